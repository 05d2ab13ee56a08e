#pragma once
// A pass's pipelines by variant: a small value type per pass (its defines and state, with ==
// and hash()), each pipeline built on first use, so a variant no frame asks for (the counting
// ones, invariant=off, another sample count or depth format) costs nothing, and switching back
// costs nothing after the first frame of each. rebuild() is fail-safe: every stage of every
// built variant compiles first (a shader::ShaderError leaves the current pipelines in place),
// then the pipelines are created, and only then are the old ones retired.
// Geometry passes also describe each variant once, when it is built (PipelineInfo: its name
// and early-Z verdict from the SPIR-V it compiled), so a frame reports them without looking.
#include <concepts>
#include <cstddef>
#include <functional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/vk/destroy_list.h"
#include "renderer/vk/pipeline.h"

namespace ds::passes {

// SPIR-V of one pipeline's stages; an empty fragment stage means depth only.
struct ShaderStages {
    std::vector<uint32_t> vert;
    std::vector<uint32_t> frag;
};

// What a pass reports about one pipeline variant (PipelineReport without the frame's draws).
struct PipelineInfo {
    std::string name;
    std::string early_z;         // shader::early_z_verdict
    bool fragment_stage = true;  // false: built without one (depth only)
};

// Mixes the fields of a variant into one hash (boost's hash_combine).
template <typename... Fields>
size_t hash_fields(const Fields&... fields) {
    size_t seed = 0;
    ((seed ^= std::hash<Fields>{}(fields) + 0x9e3779b9u + (seed << 6) + (seed >> 2)), ...);
    return seed;
}

// The variant of a pass with one pipeline (fullscreen passes at 1x).
struct NoVariant {
    bool operator==(const NoVariant&) const = default;
    size_t hash() const { return 0; }
};

// Pipelines that differ only by the depth format they attach (the frame's depth_format).
struct DepthFormatVariant {
    VkFormat depth = VK_FORMAT_UNDEFINED;
    bool operator==(const DepthFormatVariant&) const = default;
    size_t hash() const { return size_t(depth); }
};

template <typename Key>
concept PipelineKey = requires(const Key& k) {
    { k == k } -> std::convertible_to<bool>;
    { k.hash() } -> std::convertible_to<size_t>;
};

template <PipelineKey Key>
class PipelineVariants {
  public:
    using Compile = std::function<ShaderStages(const Key&)>;
    using Create = std::function<vk::Pipeline(const Key&, const ShaderStages&)>;
    using Describe = std::function<PipelineInfo(const Key&, const ShaderStages&)>;

    // `describe` (geometry passes) runs once per built variant, on the stages it was built from.
    PipelineVariants(Compile compile, Create create, Describe describe = {})
        : compile_(std::move(compile)),
          create_(std::move(create)),
          describe_(std::move(describe)) {}

    // Throws shader::ShaderError / ds::Error on the first build of a variant.
    VkPipeline get(const Key& key) { return entry(key).pipeline.handle(); }
    // The variant's description (empty without `describe`); builds it like get().
    const PipelineInfo& info(const Key& key) { return entry(key).info; }

    void rebuild(vk::DestroyList& retired) {
        std::vector<std::pair<Key, ShaderStages>> stages;
        for (const auto& entry : pipelines_)
            stages.emplace_back(entry.first, compile_(entry.first));
        Map fresh;
        for (const auto& [key, s] : stages) fresh.emplace(key, build(key, s));
        // An in-flight frame may still use the old pipelines.
        for (auto& entry : pipelines_) retired.defer(std::move(entry.second.pipeline));
        pipelines_ = std::move(fresh);
    }

  private:
    struct Hash {
        size_t operator()(const Key& key) const { return key.hash(); }
    };
    struct Built {
        vk::Pipeline pipeline;
        PipelineInfo info;
    };
    using Map = std::unordered_map<Key, Built, Hash>;

    Built build(const Key& key, const ShaderStages& stages) const {
        Built b{create_(key, stages), {}};
        if (describe_) b.info = describe_(key, stages);
        return b;
    }
    Built& entry(const Key& key) {
        auto it = pipelines_.find(key);
        if (it == pipelines_.end()) it = pipelines_.emplace(key, build(key, compile_(key))).first;
        return it->second;
    }

    Compile compile_;
    Create create_;
    Describe describe_;
    Map pipelines_;
};

}  // namespace ds::passes
