// Descriptor layout shared by the renderer's scene passes. Must match renderer/gpu_scene.h
// (GpuMaterial, GpuInstance) and renderer/renderer.cpp (FrameUniforms).
#ifndef DS_BINDINGS_GLSL
#define DS_BINDINGS_GLSL

// Set 0: per frame.
layout(set = 0, binding = 0, std140) uniform FrameUniforms {
    mat4 view_projection;
    vec4 camera_position;  // xyz, world space
    vec4 sun_direction;    // xyz: unit vector towards the sun
    vec4 sun_radiance;     // rgb: colour * intensity
    vec4 sky_ambient;      // rgb: hemispherical ambient from above
    vec4 ground_ambient;   // rgb: hemispherical ambient from below
    vec4 exposure;         // x: linear multiplier before tonemapping
} frame;

// Model and normal matrix (transpose(inverse(mat3(model))), precomputed on the CPU so no
// vertex inverts a matrix). Indexed by gl_InstanceIndex, which already includes firstInstance.
struct InstanceData {
    mat4 model;
    mat4 normal_matrix;
};
layout(set = 0, binding = 1, std430) readonly buffer Instances {
    InstanceData instances[];
};

// Set 1: per material (no descriptor indexing on lavapipe: one small set per material).
const uint kMaterialHasNormalMap = 1u;

layout(set = 1, binding = 0, std140) uniform MaterialUniforms {
    vec4 base_color_factor;
    vec4 emissive_factor;  // rgb
    float metallic_factor;
    float roughness_factor;
    float normal_scale;
    float occlusion_strength;
    float alpha_cutoff;
    uint flags;  // kMaterial* bits
} material;

layout(set = 1, binding = 1) uniform sampler2D base_color_texture;
layout(set = 1, binding = 2) uniform sampler2D metallic_roughness_texture;  // G rough, B metal
layout(set = 1, binding = 3) uniform sampler2D normal_texture;
layout(set = 1, binding = 4) uniform sampler2D occlusion_texture;  // R
layout(set = 1, binding = 5) uniform sampler2D emissive_texture;

#endif
