// Helpers of the screen-space compute passes (gtao, ao_spatial, ao_temporal, contact_shadows):
// view-space reconstruction from the prepass depth, normal decoding, deterministic noise.
// Include after common/frame.glsl (it reads `frame`).
#ifndef DS_SCREEN_SPACE_GLSL
#define DS_SCREEN_SPACE_GLSL

const float kPi = 3.14159265358979;
const float kHalfPi = 1.57079632679490;

// The depth buffer's clear value: no surface here (sky). Reverse-Z clears to 0, forward-Z to 1.
bool is_background(float d) {
    return frame.depth_params.z > 0.5 ? d <= 0.0 : d >= 1.0;
}

// View-space direction through `uv` (0..1, origin top-left as Vulkan's NDC) scaled to z = -1,
// so that ray * linear_depth(d) is the view-space position. Through inverse_projection, so
// any perspective projection (jittered, off-centre, y-flipped) reconstructs consistently;
// the distance comes from linear_depth(), which is exact for both depth conventions.
vec3 view_ray(vec2 uv) {
    vec4 p = frame.inverse_projection * vec4(uv * 2.0 - 1.0, 0.5, 1.0);
    return p.xyz / -p.z;  // (p.xyz / p.w) / (-p.z / p.w)
}

// linear_depth() with the depth convention's branch and constants taken out of a loop: a
// shader that converts many depth samples makes one of these, then each sample is one
// multiply-add and one divide (the ternary in linear_depth() makes the compiler evaluate both
// conventions' divides per sample). The same arithmetic as linear_depth() for either.
struct LinearDepth {
    float nf;     // znear * zfar
    float a, b;   // distance = nf / (a + d * b)
};

LinearDepth linear_depth_consts() {
    float n = frame.depth_params.x, f = frame.depth_params.y;
    return frame.depth_params.z > 0.5 ? LinearDepth(n * f, n, f - n)   // reverse-Z
                                      : LinearDepth(n * f, f, n - f);  // forward-Z
}

float linear_depth(LinearDepth c, float d) {
    return c.nf / (c.a + d * c.b);
}

vec3 view_position(vec2 uv, float d) {
    return view_ray(uv) * linear_depth(d);
}

// The position of pixel `px` (its centre) of an image of size 1 / inv_size.
vec3 view_position_at(ivec2 px, vec2 inv_size, float d) {
    return view_position((vec2(px) + 0.5) * inv_size, d);
}

// View rays are affine in the pixel position: a perspective projection's z and w rows do not
// involve x and y, so neither does the inverse's. A shader that needs the positions of many
// pixels around one computes the ray there and its change per pixel once; each position is
// then two multiply-adds and linear_depth(), not a matrix product.
struct RayBasis {
    vec3 ray;  // through the centre of the pixel the basis was made for (z = -1)
    vec3 dx;   // change per pixel to the right
    vec3 dy;   // change per pixel down
};

RayBasis ray_basis(ivec2 px, vec2 inv_size) {
    vec2 centre = (vec2(px) + 0.5) * inv_size;
    vec3 ray = view_ray(centre);
    return RayBasis(ray, view_ray(centre + vec2(inv_size.x, 0.0)) - ray,
                    view_ray(centre + vec2(0.0, inv_size.y)) - ray);
}

// The ray `offset` pixels away from the basis pixel's centre.
vec3 basis_ray(RayBasis b, vec2 offset) {
    return b.ray + offset.x * b.dx + offset.y * b.dy;
}

// Screen uv of a view-space position.
vec2 project_to_uv(vec3 view_pos) {
    vec4 clip = frame.projection * vec4(view_pos, 1.0);
    return clip.xy / clip.w * 0.5 + 0.5;
}

// The prepass stores world-space normals as n * 0.5 + 0.5 (A2B10G10R10). A zero texel (no
// surface) decodes to an arbitrary unit vector instead of NaN.
vec3 decode_normal(vec3 encoded) {
    vec3 n = encoded * 2.0 - 1.0;
    float len2 = dot(n, n);
    return len2 > 1e-8 ? n * inversesqrt(len2) : vec3(0.0, 1.0, 0.0);
}

// acos(x), x in [-1, 1], to within 7e-5 rad (Abramowitz & Stegun 4.4.45): one square root
// and three multiply-adds, where a library acos costs several times that per lane on a CPU
// device. GTAO's horizon angles need far less precision than that.
float fast_acos(float x) {
    float a = abs(x);
    float r = sqrt(1.0 - a) * (1.5707288 + a * (-0.2121144 + a * (0.0742610 + a * -0.0187293)));
    return x >= 0.0 ? r : kPi - r;
}

// Octahedral encoding of a unit vector in two numbers in [-1, 1] (Cigolle et al. 2014): the
// reduced-resolution AO images carry a view-space normal per texel in two channels, so a
// filter tap is one fetch. Error well below 1e-3 in 16-bit floats.
vec2 oct_encode(vec3 n) {
    n /= abs(n.x) + abs(n.y) + abs(n.z);
    vec2 p = n.xy;
    if (n.z < 0.0) p = (1.0 - abs(p.yx)) * vec2(p.x >= 0.0 ? 1.0 : -1.0, p.y >= 0.0 ? 1.0 : -1.0);
    return p;
}

vec3 oct_decode(vec2 e) {
    vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
    float t = max(-n.z, 0.0);
    n.xy += vec2(n.x >= 0.0 ? -t : t, n.y >= 0.0 ? -t : t);
    return normalize(n);
}

// frame.view is rigid (rotation + translation), so its upper 3x3 transforms normals too.
vec3 world_to_view_dir(vec3 dir) {
    return normalize(mat3(frame.view) * dir);
}

// The full-resolution pixel a reduced-resolution AO texel stands for (gtao reads its depth
// there; ao_spatial compares against the same pixel when it upsamples). Identity at scale 1.
ivec2 ao_source_pixel(ivec2 ao_px, ivec2 ao_size, ivec2 full_size) {
    ivec2 p = ivec2((vec2(ao_px) + 0.5) * vec2(full_size) / vec2(ao_size));
    return min(p, full_size - 1);
}

// 4x4 ordered-dither index 0..15. A 4x4 tile holds every value once, so a filter whose
// weights are equal per residue mod 4 (ao_spatial's 1 2 2 2 1 tent) averages the pattern away
// exactly on flat areas: the rotation noise costs no detail.
uint bayer4(ivec2 p) {
    const uint m[16] = uint[16](0u, 8u, 2u, 10u, 12u, 4u, 14u, 6u, 3u, 11u, 1u, 9u, 15u, 7u,
                                13u, 5u);
    return m[(p.y & 3) * 4 + (p.x & 3)];
}

// Jimenez 2014 interleaved gradient noise in [0, 1): deterministic per pixel.
float interleaved_gradient_noise(vec2 px) {
    return fract(52.9829189 * fract(dot(px, vec2(0.06711056, 0.00583715))));
}

#endif
