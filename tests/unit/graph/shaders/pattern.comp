#version 450
// Writes a pattern every pixel can be checked against: red = x / 255, green = y / 255.
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0, rgba8) uniform writeonly image2D target;

void main() {
    const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(target)))) return;
    imageStore(target, p, vec4(float(p.x) / 255.0, float(p.y) / 255.0, 1.0, 1.0));
}
