// GpuScene's MASK base colours across their mips (alpha_mip_coverage; gpu_scene.h
// set_alpha_mips): the box chain's coverage per material, and with preserve an image per
// (image, effective cutoff, baseColorFactor.a) whose mips keep level 0's coverage.
#include "renderer/gpu_scene/gpu_scene.h"

#include <algorithm>
#include <string>

#include "renderer/scene/alpha_mips.h"
#include "renderer/vk/context.h"

namespace ds {

void GpuScene::remember_masked(const scene::Scene& scene, uint32_t material, VkImageView view,
                               VkSampler sampler) {
    const uint32_t image = *scene::masked_base_color_image(scene, material);
    masked_.push_back({material, image, scene.materials[material], view, sampler});
    bound_.emplace_back();
    masked_images_.try_emplace(image, scene.images[image]);
}

const std::vector<scene::LevelCoverage>& GpuScene::box_coverage(const AlphaKey& key) {
    auto it = box_coverage_.find(key);
    if (it != box_coverage_.end()) return it->second;
    const scene::Image& img = masked_images_.at(key.image);
    const std::vector<scene::MipImage> chain =
        scene::box_mip_chain(img.width, img.height, img.rgba8, img.srgb);
    return box_coverage_[key] = scene::chain_coverage(chain, key.cutoff, key.factor);
}

GpuScene::PreservedImage& GpuScene::preserved(const AlphaKey& key, vk::UploadBatch& batch) {
    auto it = preserved_.find(key);
    if (it != preserved_.end()) return it->second;
    const scene::Image& img = masked_images_.at(key.image);
    const std::vector<scene::MipImage> chain =
        scene::preserved_mip_chain(img, key.cutoff, key.factor);
    const std::string name =
        img.name + " (alpha_mip_coverage=preserve, cutoff " + std::to_string(key.cutoff) + ")";
    PreservedImage& p = preserved_[key];
    p.image = vk::Image(context_,
                        vk::ImageDesc{img.width, img.height, uint32_t(chain.size()),
                                      img.srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM,
                                      VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                      VK_SAMPLE_COUNT_1_BIT, name.c_str()});
    std::vector<const uint8_t*> levels;
    for (const scene::MipImage& level : chain) levels.push_back(level.rgba8.data());
    batch.texture(p.image, levels);  // copies the levels into its staging buffer
    p.coverage = scene::chain_coverage(chain, key.cutoff, key.factor);
    return p;
}

// Rewrites the base colour binding of every material whose image changes: after the device
// is idle, as set_alpha_cutoff_overrides rewrites the uniforms (a set a submitted frame uses
// must not change).
void GpuScene::bind_base_colors(const std::vector<std::optional<AlphaKey>>& want) {
    if (want == bound_) return;
    context_.wait_idle();
    for (size_t i = 0; i < masked_.size(); ++i) {
        if (want[i] == bound_[i]) continue;
        const MaskedBase& m = masked_[i];
        const VkImageView view = want[i] ? preserved_.at(*want[i]).image.view() : m.view;
        vk::DescriptorWriter writer;
        writer.image(kBaseColorTexture, view, m.sampler);
        writer.update(context_.device(), material_sets_.at(m.material));
    }
    bound_ = want;
}

void GpuScene::set_alpha_mips(scene::AlphaMipMode mode, std::optional<float> global_cutoff,
                              vk::DestroyList& retired) {
    std::vector<float> cutoffs;
    for (const MaskedBase& m : masked_) {
        const float own = cutoff_overrides_.at(m.material);
        cutoffs.push_back(scene::effective_alpha_cutoff(
            m.source, own >= 0.0f ? std::optional<float>(own) : std::nullopt, global_cutoff));
    }
    if (alpha_state_ && alpha_state_->first == mode && alpha_state_->second == cutoffs) return;
    alpha_state_ = {mode, cutoffs};

    const bool preserve = mode == scene::AlphaMipMode::Preserve;
    std::vector<std::optional<AlphaKey>> want(masked_.size());
    std::vector<scene::MaterialAlphaCoverage> coverage;
    vk::UploadBatch batch(context_);
    for (size_t i = 0; i < masked_.size(); ++i) {
        const MaskedBase& m = masked_[i];
        const AlphaKey key{m.image, cutoffs[i], m.source.base_color_factor.a};
        scene::MaterialAlphaCoverage c{.material = m.material,
                                       .material_name = m.source.name,
                                       .image = m.image,
                                       .image_name = masked_images_.at(m.image).name,
                                       .cutoff = key.cutoff,
                                       .factor = key.factor,
                                       .mode = mode,
                                       .box = box_coverage(key),
                                       .uploaded = {}};
        if (preserve) {
            want[i] = key;
            c.uploaded = preserved(key, batch).coverage;
        }
        coverage.push_back(std::move(c));
    }
    batch.submit();  // the new images are complete before any set names them
    bind_base_colors(want);
    // Images no material binds any more: destroyed once the frames that may use them are done.
    for (auto it = preserved_.begin(); it != preserved_.end();) {
        if (std::count(bound_.begin(), bound_.end(), std::optional<AlphaKey>(it->first))) {
            ++it;
            continue;
        }
        retired.defer(std::move(it->second.image));
        it = preserved_.erase(it);
    }
    alpha_coverage_ = std::move(coverage);
}

}  // namespace ds
