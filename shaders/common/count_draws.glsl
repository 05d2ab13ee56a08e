// count_draws=on, the vertex side: hands the instance's draw group to the fragment shader,
// whose count_fragment() (common/count.glsl) adds one to that group's counter. A flat
// varying because a fragment shader cannot see gl_InstanceIndex. Include it after
// bindings.glsl from a vertex shader, and write PASS_DRAW_GROUP(instance); in main. A macro,
// not a function: off, it leaves nothing behind, so the default SPIR-V is what it was.
#ifndef DS_COUNT_DRAWS_GLSL
#define DS_COUNT_DRAWS_GLSL

#ifndef COUNT_DRAWS
#define COUNT_DRAWS 0
#endif

#if COUNT_DRAWS
layout(location = 5) flat out uint out_draw_group;
#define PASS_DRAW_GROUP(instance) out_draw_group = (instance).draw_group
#else
#define PASS_DRAW_GROUP(instance)
#endif

#endif
