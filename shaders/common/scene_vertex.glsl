// The vertex shader of every pass whose depth must match another's bit for bit: depth
// prepass, forward and transparent (seed 000). One source, one expression
//     gl_Position = view_projection * (model * position)
// and `invariant gl_Position`, so the EQUAL test of the forward pass keeps exactly the
// fragments the prepass kept.
//
// NON_INVARIANT=1 (forward with invariant=off) drops `invariant` and evaluates the
// mathematically equal (view_projection * model) * position, which rounds differently: the
// EQUAL test then rejects visible fragments, which is the point of the setting.
// Include it from a .vert that enables GL_GOOGLE_include_directive.

#ifndef NON_INVARIANT
#define NON_INVARIANT 0
#endif
// SURFACE_ID=1 (prepass with surface_id, the zfight pass): hands the instance's surface base
// to the fragment shader, which adds gl_PrimitiveID (renderer/gpu_scene SurfaceTable).
#ifndef SURFACE_ID
#define SURFACE_ID 0
#endif

// PIXEL_HISTORY=1 (the pixel history replays): hands gl_InstanceIndex on, flat; gl_Position's
// expression and `invariant` are untouched, so the replay's depths are the real pass's.
#ifndef PIXEL_HISTORY
#define PIXEL_HISTORY 0
#endif

// SCENE_VARYINGS (prepass_mode=depth): what is handed to the fragment stage besides the flat
// extras above. 2 (default) world position, normal, uv, tangent; 1 uv only (the masked
// depth-only prepass: its alpha test); 0 nothing (the opaque depth-only prepass, which has
// no fragment stage, or one that only counts or writes surface_id). The pipeline then
// fetches only the attributes read (VertexInputs). gl_Position is the same expression and
// `invariant` either way, which GLSL guarantees bit-identical across shaders.
#ifndef SCENE_VARYINGS
#define SCENE_VARYINGS 2
#endif

#include "bindings.glsl"
#include "count_draws.glsl"

layout(location = 0) in vec3 in_position;
#if SCENE_VARYINGS >= 1
layout(location = 2) in vec2 in_uv0;
layout(location = 2) out vec2 out_uv0;
#endif
#if SCENE_VARYINGS >= 2
layout(location = 1) in vec3 in_normal;
layout(location = 3) in vec4 in_tangent;

layout(location = 0) out vec3 out_world_position;
layout(location = 1) out vec3 out_normal;
layout(location = 3) out vec4 out_tangent;
#endif
#if SURFACE_ID
layout(location = 4) flat out uint out_surface_base;
#endif
#if PIXEL_HISTORY
layout(location = 5) flat out uint out_history_instance;
#endif

#if !NON_INVARIANT
invariant gl_Position;
#endif

void main() {
    InstanceData instance = instances[gl_InstanceIndex];
    vec4 world = instance.model * vec4(in_position, 1.0);
#if NON_INVARIANT
    gl_Position = (frame.view_projection * instance.model) * vec4(in_position, 1.0);
#else
    gl_Position = frame.view_projection * world;
#endif
#if SCENE_VARYINGS >= 2
    out_world_position = world.xyz;
    out_normal = mat3(instance.normal_matrix) * in_normal;
    out_tangent = vec4(mat3(instance.model) * in_tangent.xyz, in_tangent.w);
#endif
#if SCENE_VARYINGS >= 1
    out_uv0 = in_uv0;
#endif
#if SURFACE_ID
    out_surface_base = instance.surface_base;
#endif
    PASS_DRAW_GROUP(instance);
#if PIXEL_HISTORY
    out_history_instance = uint(gl_InstanceIndex);
#endif
}
