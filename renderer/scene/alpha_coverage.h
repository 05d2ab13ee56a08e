#pragma once
// The alpha coverage of a scene's MASK materials across their base colour's mips (alpha_mips.h
// does the image work): which cutoff each material's alpha test uses under the settings, which
// chain the renderer uploads (alpha_mip_coverage), and each level's coverage. GpuScene uploads
// and reports these; diagnose's alpha_coverage check computes them from the scene.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "renderer/scene/alpha_mips.h"
#include "renderer/scene/scene.h"
#include "renderer/settings/settings.h"

namespace ds::scene {

// alpha_mip_coverage: box (GPU blits, the box filter), preserve (alpha_mips.h, Castaño).
enum class AlphaMipMode : uint8_t { Box, Preserve };
const char* to_string(AlphaMipMode mode);
AlphaMipMode alpha_mip_mode(const Settings& settings);

// The cutoff a material's alpha test compares with (common/bindings.glsl's alpha_cutoff()):
// its material_alpha_cutoff, else alpha_cutoff, else its own alphaCutoff.
float effective_alpha_cutoff(const Material& material, std::optional<float> override_cutoff,
                             std::optional<float> global);
// Per material of `scene`, that cutoff under `settings` (material_alpha_cutoff applies to MASK
// materials by name).
std::vector<float> effective_alpha_cutoffs(const Scene& scene, const Settings& settings);

// The image a MASK material's base colour texture samples; none for any other material or a
// missing texture.
std::optional<uint32_t> masked_base_color_image(const Scene& scene, uint32_t material);

// The chain alpha_mip_coverage=preserve uploads: the box chain with every level's alpha scaled
// to level 0's coverage at `cutoff` x `factor`.
std::vector<MipImage> preserved_mip_chain(const Image& image, float cutoff, float factor);

// One MASK material with a base colour texture: report.json `alpha_coverage`'s entry.
struct MaterialAlphaCoverage {
    uint32_t material = 0;
    std::string material_name;
    uint32_t image = 0;
    std::string image_name;
    float cutoff = 0.5f;  // effective
    float factor = 1.0f;  // baseColorFactor.a
    AlphaMipMode mode = AlphaMipMode::Box;
    std::vector<LevelCoverage> box;       // the box chain's levels
    std::vector<LevelCoverage> uploaded;  // preserve: the chain uploaded instead; box: empty
};

// Every MASK material's entry under `settings`, computed here (the chains made anew).
std::vector<MaterialAlphaCoverage> scene_alpha_coverage(const Scene& scene,
                                                        const Settings& settings);

// The largest fall of coverage below level 0's among the levels at least `min_size` texels on
// both sides: 1 - relative at its level; none when no such level falls.
struct CoverageDrop {
    uint32_t level = 0;
    double drop = 0.0;  // 0..1
};
std::optional<CoverageDrop> worst_coverage_drop(const std::vector<LevelCoverage>& levels,
                                                uint32_t min_size);

}  // namespace ds::scene
