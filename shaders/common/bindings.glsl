// Descriptor layout shared by the passes that draw scene meshes: set 0 is the frame
// (common/frame.glsl) plus the instance buffer, set 1 one material. Must match
// renderer/gpu_scene.h (GpuMaterial, GpuInstance) and renderer/passes/frame.h (FrameUniforms).
#ifndef DS_BINDINGS_GLSL
#define DS_BINDINGS_GLSL

#include "frame.glsl"

// Model and normal matrix (transpose(inverse(mat3(model))), precomputed on the CPU so no
// vertex inverts a matrix). Indexed by gl_InstanceIndex, which already includes firstInstance.
struct InstanceData {
    mat4 model;
    mat4 normal_matrix;
    uint surface_base;  // surface id of triangle 0, minus 1 (renderer/gpu_scene SurfaceTable)
    uint draw_group;    // its scene draw group (count_draws: common/count.glsl)
    uint pad1, pad2;
};
layout(set = 0, binding = 1, std430) readonly buffer Instances {
    InstanceData instances[];
};

// Set 1: per material (no descriptor indexing on lavapipe: one small set per material).
const uint kMaterialHasNormalMap = 1u;
const uint kMaterialAlphaMask = 2u;  // glTF alphaMode MASK

layout(set = 1, binding = 0, std140) uniform MaterialUniforms {
    vec4 base_color_factor;
    vec4 emissive_factor;  // rgb
    float metallic_factor;
    float roughness_factor;
    float normal_scale;
    float occlusion_strength;
    float alpha_cutoff;           // the glTF material's own
    uint flags;                   // kMaterial* bits
    float alpha_cutoff_override;  // material_alpha_cutoff for this material, < 0: none
    // KHR_texture_transform per texture (kTexture*): rows (a, b, tx) and (c, d, ty).
    vec4 uv_rows[10];
} material;

const uint kTextureBaseColor = 0u;
const uint kTextureMetallicRoughness = 1u;
const uint kTextureNormal = 2u;
const uint kTextureOcclusion = 3u;
const uint kTextureEmissive = 4u;

// The UV a material texture is sampled at: TEXCOORD_0 through its KHR_texture_transform.
vec2 texture_uv(uint texture_index, vec2 uv) {
    const vec3 p = vec3(uv, 1.0);
    return vec2(dot(material.uv_rows[2u * texture_index].xyz, p),
                dot(material.uv_rows[2u * texture_index + 1u].xyz, p));
}

layout(set = 1, binding = 1) uniform sampler2D base_color_texture;
layout(set = 1, binding = 2) uniform sampler2D metallic_roughness_texture;  // G rough, B metal
layout(set = 1, binding = 3) uniform sampler2D normal_texture;
layout(set = 1, binding = 4) uniform sampler2D occlusion_texture;  // R
layout(set = 1, binding = 5) uniform sampler2D emissive_texture;

// Precedence: the material_alpha_cutoff setting for this material, then the alpha_cutoff
// setting (every material) when it is a number, then the material's own cutoff.
float alpha_cutoff() {
    if (material.alpha_cutoff_override >= 0.0) return material.alpha_cutoff_override;
    return frame.alpha.x >= 0.0 ? frame.alpha.x : material.alpha_cutoff;
}

// The alpha a MASK test compares with alpha_cutoff(): `sampled` (the base colour's alpha x
// factor as the shader sampled it, through the mips), or with alpha_level0 (frame.alpha.y, a
// uniform, so the branch is uniform) the base colour's alpha at mip level 0 x factor.
bool alpha_level0() {
    return frame.alpha.y > 0.5;
}
float mask_alpha(vec2 uv0, float sampled) {
    if (!alpha_level0()) return sampled;
    return textureLod(base_color_texture, texture_uv(kTextureBaseColor, uv0), 0.0).a *
           material.base_color_factor.a;
}

#endif
