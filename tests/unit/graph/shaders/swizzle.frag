#version 450
// Reads the source texel under this pixel and swaps red and blue: proof that the pixels went
// through this pass, not only the clear before it.
layout(set = 0, binding = 0) uniform sampler2D source;
layout(location = 0) out vec4 colour;

void main() {
    const vec4 c = texelFetch(source, ivec2(gl_FragCoord.xy), 0);
    colour = vec4(c.b, c.g, c.r, 1.0);
}
