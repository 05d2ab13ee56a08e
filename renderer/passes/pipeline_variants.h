#pragma once
// A pass's pipelines by variant: a small value type per pass (its defines and state, with ==
// and hash()), compiled once, each pipeline built on first use for the target it draws in
// (graph::RenderTarget: the formats its rendering declared, or the render pass's subpass), so a
// variant no frame asks for (the counting ones, invariant=off, another sample count or depth
// format) costs nothing, and switching back costs nothing after the first frame of each. rebuild()
// is fail-safe: every stage of every built variant compiles first (a shader::ShaderError leaves the
// current pipelines in place), then the pipelines are created, and only then are the old ones
// retired. Geometry passes also describe each variant once, when it is built (PipelineInfo: its
// name and early-Z verdict from the SPIR-V it compiled), so a frame reports them without looking.
#include <concepts>
#include <cstddef>
#include <functional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/graph/rendering.h"
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
    std::string early_z;         // spirv::early_z_verdict
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

template <typename Key>
concept PipelineKey = requires(const Key& k) {
    { k == k } -> std::convertible_to<bool>;
    { k.hash() } -> std::convertible_to<size_t>;
};

template <PipelineKey Key>
class PipelineVariants {
  public:
    using Compile = std::function<ShaderStages(const Key&)>;
    // `target`: what the pass renders into (graph::PassContext::target()); empty for compute
    // and for pipelines a pass makes without a rendering of its own.
    using Create =
        std::function<vk::Pipeline(const Key&, const ShaderStages&, const graph::RenderTarget&)>;
    using Describe = std::function<PipelineInfo(const Key&, const ShaderStages&)>;

    // `describe` (geometry passes) runs once per variant, on the stages it compiled.
    PipelineVariants(Compile compile, Create create, Describe describe = {})
        : compile_(std::move(compile)),
          create_(std::move(create)),
          describe_(std::move(describe)) {}

    // The variant's pipeline for `target`, built on first use. Throws shader::ShaderError /
    // ds::Error on the first build of a variant.
    VkPipeline get(const Key& key, const graph::RenderTarget& target = {}) {
        Variant& v = variant(key);
        auto it = v.pipelines.find(target);
        if (it == v.pipelines.end())
            it = v.pipelines.emplace(target, create_(key, v.stages, target)).first;
        return it->second.handle();
    }
    // The variant's description (empty without `describe`): its shaders compile, no pipeline
    // is made.
    const PipelineInfo& info(const Key& key) { return variant(key).info; }

    void rebuild(vk::DestroyList& retired) {
        std::vector<std::pair<Key, ShaderStages>> stages;
        for (const auto& entry : variants_) stages.emplace_back(entry.first, compile_(entry.first));
        Map fresh;
        for (auto& [key, s] : stages) {
            Variant v = describe(key, std::move(s));
            for (const auto& entry : variants_.at(key).pipelines)
                v.pipelines.emplace(entry.first, create_(key, v.stages, entry.first));
            fresh.emplace(key, std::move(v));
        }
        // An in-flight frame may still use the old pipelines.
        for (auto& entry : variants_)
            for (auto& pipeline : entry.second.pipelines) retired.defer(std::move(pipeline.second));
        variants_ = std::move(fresh);
    }

  private:
    struct Hash {
        size_t operator()(const Key& key) const { return key.hash(); }
    };
    struct TargetHash {
        size_t operator()(const graph::RenderTarget& t) const { return t.hash(); }
    };
    struct Variant {
        ShaderStages stages;
        PipelineInfo info;
        std::unordered_map<graph::RenderTarget, vk::Pipeline, TargetHash> pipelines;
    };
    using Map = std::unordered_map<Key, Variant, Hash>;

    Variant describe(const Key& key, ShaderStages stages) const {
        Variant v;
        v.stages = std::move(stages);
        if (describe_) v.info = describe_(key, v.stages);
        return v;
    }
    Variant& variant(const Key& key) {
        auto it = variants_.find(key);
        if (it == variants_.end()) it = variants_.emplace(key, describe(key, compile_(key))).first;
        return it->second;
    }

    Compile compile_;
    Create create_;
    Describe describe_;
    Map variants_;
};

}  // namespace ds::passes
