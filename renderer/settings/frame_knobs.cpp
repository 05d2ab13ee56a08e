#include "renderer/settings/frame_knobs.h"

namespace ds::knobs {
namespace {

using I = Invalidates;

// A depth plane: "scene" (the scene camera's) or a distance; never a pipeline or resource
// change (the projection is a uniform). 0 passes the registry so that znear=0 meets the
// planes' own check (0 < znear < zfar, checked against the scene camera's when rendering).
SettingDef plane_knob(Knob<OptionalFloat> k, std::string help) {
    return optional_float_knob(k, "prepass and depth", "scene", "scene", 0, 1000000,
                               std::move(help), I::Nothing);
}

std::vector<SettingDef> depth_knobs() {
    return {
        bool_knob(kPrepass, "prepass and depth", true,
                  "depth prepass; off: forward writes depth with GREATER (gtao and "
                  "contact_shadows need the prepass and are skipped)",
                  I::Nothing),
        // Which pipelines the prepass has; forward, GTAO and contact shadows adapt.
        enum_knob(kPrepassMode, "prepass and depth", {"gbuffer", "depth"},
                  "prepass on: gbuffer writes depth, normals and roughness (forward reads them); "
                  "depth is Z only (opaque: no fragment stage, masked: the alpha test), forward "
                  "computes normals and roughness itself and gtao / contact_shadows read normals "
                  "reconstructed from depth (normals_from_depth)",
                  I::Nothing),
        // Seed 002's tiler path.
        enum_knob(kRenderPath, "prepass and depth", {"dynamic", "subpass"},
                  "dynamic: every pass on its own (dynamic rendering); subpass: depth prepass, "
                  "forward and sky as two subpasses of one render pass, forward reading normals "
                  "and roughness as input attachments (tile memory on a tiler); needs the prepass; "
                  "gtao, contact_shadows and the per-pass diagnostics do not run on it",
                  I::Nothing),
        enum_knob(kDepthCompare, "prepass and depth", {"equal", "greater_or_equal"},
                  "forward pass depth test against the prepass depth (prepass on)", I::Nothing),
        bool_knob(kReverseZ, "prepass and depth", true,
                  "reverse-Z depth (clear 0, GREATER); off: clear 1, LESS", I::Nothing),
        // Which of these the device offers is checked per frame (the registry cannot know).
        enum_knob(kDepthFormat, "prepass and depth", {"d32f", "d24", "d16"},
                  "scene depth format, as the device supports it: d32f D32_SFLOAT (else "
                  "D32_SFLOAT_S8_UINT), d24 D24_UNORM_S8_UINT (else X8_D24_UNORM_PACK32), d16 "
                  "D16_UNORM; the shadow map keeps its own",
                  I::Resources),
        plane_knob(kZnear,
                   "near plane in scene units; scene: the scene camera's own (must stay below "
                   "the far plane)"),
        plane_knob(kZfar,
                   "far plane in scene units; scene: the scene camera's own (must stay above "
                   "the near plane)"),
    };
}

std::vector<SettingDef> msaa_and_alpha_knobs() {
    return {
        // A sample count Vulkan has (1, 2, 4, 8: anything else is a usage error); whether the
        // device supports it for colour and depth is checked per frame: lavapipe offers 1, 4.
        int_knob(kMsaa, "msaa", 1, 1, 8,
                 "samples per pixel (1, 2, 4 or 8, as the device allows); > 1: depth, normals, "
                 "roughness and HDR colour are multisampled and resolved inline (depth keeps "
                 "the nearest sample)",
                 I::Pipelines, {"1", "2", "4", "8"}),
        bool_knob(kSampleShading, "msaa", false,
                  "msaa > 1: forward shades every sample (minSampleShading 1), so specular "
                  "and texture detail inside a pixel is antialiased too, at up to msaa times "
                  "the shading cost",
                  I::Pipelines),
        optional_float_knob(kAlphaCutoff, "alpha", "material", "material", 0, 1,
                            "alpha test cutoff for MASK materials; material: each material's own "
                            "(material_alpha_cutoff wins over it)",
                            I::Nothing),
        // Checked against the scene when rendering: every NAME must be a MASK material.
        map_knob(kMaterialAlphaCutoff, "alpha", 0, 1,
                 "per-material alpha test cutoff, NAME=V[,NAME=V...]: NAME a MASK material of "
                 "the scene by its glTF name (unnamed: 'material N', N its glTF index; a name "
                 "sets every material so named); wins over alpha_cutoff, which wins over the "
                 "material's own alphaCutoff",
                 I::Nothing),
        bool_knob(kAlphaToCoverage, "alpha", false,
                  "msaa > 1: MASK materials turn alpha (sharpened around the cutoff) into "
                  "sample coverage instead of discarding, so cut-out edges are antialiased",
                  I::Pipelines),
        // The textures are made again by the renderer (GpuScene), not the scene reloaded.
        enum_knob(kAlphaMipCoverage, "alpha", {"box", "preserve"},
                  "mips of MASK materials' base colour: box, the 2x2 box filter (vkCmdBlitImage), "
                  "whose averaged alpha thins cut-outs with distance; preserve, mips made on the "
                  "CPU whose alpha is scaled so that each level passes the alpha test on as many "
                  "texels as level 0 (Castaño 2010), per texture and effective cutoff (report "
                  "alpha_coverage)",
                  I::Resources),
        bool_knob(kAlphaLevel0, "alpha", false,
                  "the MASK alpha test (prepass, forward, shadow, decals, transparent, zfight) "
                  "samples the base colour's alpha at mip level 0 (textureLod 0), as "
                  "alpha-tested materials sample the texture's full-resolution level in a "
                  "supersampled reference frame; colour keeps its mips",
                  I::Nothing),
    };
}

std::vector<SettingDef> lighting_and_camera_knobs() {
    return {
        float_knob(kSunAzimuth, "lighting", "35", -360, 360,
                   "sun direction around the vertical axis, degrees", I::Nothing),
        float_knob(kSunElevation, "lighting", "55", 1, 90, "sun height above the horizon, degrees",
                   I::Nothing),
        float_knob(kSunIntensity, "lighting", "3", 0, 100, "sun illuminance (linear scale)",
                   I::Nothing),
        float_knob(kAmbient, "lighting", "0.35", 0, 10, "hemispherical sky/ground ambient strength",
                   I::Nothing),
        float_knob(kExposure, "lighting", "1", 0.01, 64,
                   "exposure multiplier applied before tonemapping", I::Nothing),
        optional_float_knob(kFov, "camera", "scene", "scene", 10, 120,
                            "vertical field of view in degrees; scene: the scene camera's own",
                            I::Nothing),
    };
}

}  // namespace

std::vector<SettingDef> frame_knobs() {
    std::vector<SettingDef> out = depth_knobs();
    for (auto part : {msaa_and_alpha_knobs(), lighting_and_camera_knobs()})
        out.insert(out.end(), part.begin(), part.end());
    return out;
}

}  // namespace ds::knobs
