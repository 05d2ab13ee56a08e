#include "renderer/scene/alpha_coverage.h"

#include "renderer/settings/frame_knobs.h"

namespace ds::scene {

const char* to_string(AlphaMipMode mode) {
    return mode == AlphaMipMode::Preserve ? "preserve" : "box";
}

AlphaMipMode alpha_mip_mode(const Settings& settings) {
    return knob_value(settings, knobs::kAlphaMipCoverage) == "preserve" ? AlphaMipMode::Preserve
                                                                        : AlphaMipMode::Box;
}

float effective_alpha_cutoff(const Material& material, std::optional<float> override_cutoff,
                             std::optional<float> global) {
    if (override_cutoff) return *override_cutoff;
    return global ? *global : material.alpha_cutoff;
}

std::vector<float> effective_alpha_cutoffs(const Scene& scene, const Settings& settings) {
    const std::optional<float> global = knob_value(settings, knobs::kAlphaCutoff);
    const auto by_name = knob_value(settings, knobs::kMaterialAlphaCutoff);
    std::vector<float> out;
    out.reserve(scene.materials.size());
    for (const Material& m : scene.materials) {
        std::optional<float> own;
        if (m.alpha_mode == AlphaMode::Mask)
            if (auto it = by_name.find(m.name); it != by_name.end()) own = it->second;
        out.push_back(effective_alpha_cutoff(m, own, global));
    }
    return out;
}

std::optional<uint32_t> masked_base_color_image(const Scene& scene, uint32_t material) {
    if (material >= scene.materials.size()) return std::nullopt;
    const Material& m = scene.materials[material];
    if (m.alpha_mode != AlphaMode::Mask || !m.base_color.present()) return std::nullopt;
    const size_t texture = size_t(m.base_color.texture);
    if (texture >= scene.textures.size()) return std::nullopt;
    const uint32_t image = scene.textures[texture].image;
    if (image >= scene.images.size()) return std::nullopt;
    return image;
}

std::vector<MipImage> preserved_mip_chain(const Image& image, float cutoff, float factor) {
    std::vector<MipImage> chain = box_mip_chain(image.width, image.height, image.rgba8, image.srgb);
    preserve_alpha_coverage(chain, cutoff, factor);
    return chain;
}

std::vector<MaterialAlphaCoverage> scene_alpha_coverage(const Scene& scene,
                                                        const Settings& settings) {
    const std::vector<float> cutoffs = effective_alpha_cutoffs(scene, settings);
    const AlphaMipMode mode = alpha_mip_mode(settings);
    std::vector<MaterialAlphaCoverage> out;
    for (uint32_t i = 0; i < scene.materials.size(); ++i) {
        const std::optional<uint32_t> image = masked_base_color_image(scene, i);
        if (!image) continue;
        const Material& m = scene.materials[i];
        const Image& img = scene.images[*image];
        MaterialAlphaCoverage c{.material = i,
                                .material_name = m.name,
                                .image = *image,
                                .image_name = img.name,
                                .cutoff = cutoffs[i],
                                .factor = m.base_color_factor.a,
                                .mode = mode,
                                .box = {},
                                .uploaded = {}};
        std::vector<MipImage> chain = box_mip_chain(img.width, img.height, img.rgba8, img.srgb);
        c.box = chain_coverage(chain, c.cutoff, c.factor);
        if (mode == AlphaMipMode::Preserve) {
            preserve_alpha_coverage(chain, c.cutoff, c.factor);
            c.uploaded = chain_coverage(chain, c.cutoff, c.factor);
        }
        out.push_back(std::move(c));
    }
    return out;
}

std::optional<CoverageDrop> worst_coverage_drop(const std::vector<LevelCoverage>& levels,
                                                uint32_t min_size) {
    std::optional<CoverageDrop> worst;
    for (const LevelCoverage& l : levels) {
        if (l.level == 0 || l.width < min_size || l.height < min_size) continue;
        const double drop = 1.0 - l.relative;
        if (drop > 0.0 && (!worst || drop > worst->drop)) worst = CoverageDrop{l.level, drop};
    }
    return worst;
}

}  // namespace ds::scene
