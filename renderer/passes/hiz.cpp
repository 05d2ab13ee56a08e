#include "renderer/passes/hiz.h"

#include <algorithm>
#include <cstring>

#include <nlohmann/json.hpp>

#include "renderer/common/error.h"
#include "renderer/gpu_scene/gpu_scene.h"
#include "renderer/readback/host_readback.h"
#include "renderer/vk/context.h"

namespace ds::passes {

using graph::Access;

namespace {

constexpr uint32_t kHizTestGroup = 64;  // hiz_test.comp's local_size_x
constexpr uint32_t kFirstLevelBinding = 2;
constexpr const char* kVerdictBuffer = "hiz_verdicts";  // its HostReadback buffer

// hiz_test.comp's push constants.
struct HizTestPush {
    uint32_t instances, levels;
    float margin;
};

// hiz_test.comp's output per instance.
struct HizVerdictRecord {
    uint32_t verdict, level, nearest_bits, farthest_bits;
};
static_assert(sizeof(HizVerdictRecord) == 16);

ComputeKernel hiz_kernel(const PassServices& services, uint32_t dispatches) {
    return ComputeKernel(services, "hiz.comp", {KernelBinding::Sampled, KernelBinding::Storage},
                         sizeof(int32_t), dispatches);
}

HizInstance hiz_instance(const HizVerdictRecord& r) {
    HizInstance out;
    out.verdict = r.verdict == 1   ? HizVerdict::Occluded
                  : r.verdict == 2 ? HizVerdict::Outside
                                   : HizVerdict::Visible;
    out.level = r.level;
    std::memcpy(&out.nearest, &r.nearest_bits, sizeof out.nearest);
    std::memcpy(&out.farthest, &r.farthest_bits, sizeof out.farthest);
    return out;
}

// A group is visible when any instance is, else occluded when any instance is, else outside.
void group_verdicts(const GpuScene& scene, HizResult& r) {
    const std::vector<scene::DrawGroup>& groups = scene.draw_groups();
    r.groups.assign(groups.size(), HizVerdict::Outside);
    r.occluded_instances.assign(groups.size(), 0);
    for (size_t g = 0; g < groups.size(); ++g) {
        bool visible = false, occluded = false;
        for (uint32_t i = 0; i < groups[g].instance_count; ++i) {
            const HizVerdict v = r.instances.at(groups[g].first_instance + i).verdict;
            visible = visible || v == HizVerdict::Visible;
            occluded = occluded || v == HizVerdict::Occluded;
            r.occluded_instances[g] += v == HizVerdict::Occluded;
        }
        if (visible || groups[g].instance_count == 0)
            r.groups[g] = HizVerdict::Visible;
        else if (occluded)
            r.groups[g] = HizVerdict::Occluded;
    }
}

}  // namespace

std::vector<VkExtent2D> hiz_level_extents(VkExtent2D base) {
    std::vector<VkExtent2D> out{{std::max(base.width, 1u), std::max(base.height, 1u)}};
    while (out.back().width > 1 || out.back().height > 1) {
        const VkExtent2D p = out.back();
        out.push_back({std::max(p.width / 2, 1u), std::max(p.height / 2, 1u)});
    }
    return out;
}

std::string hiz_level_name(uint32_t level) {
    return "hiz." + std::to_string(level);
}

HizPass::HizPass(const PassServices& services)
    : services_(services),
      copy_(hiz_kernel(services, 1)),
      copy_samples_(hiz_kernel(services, 1)),
      reduce_(hiz_kernel(services, kMaxLevels - 1)),
      nearest_(vk::nearest_clamp_sampler(services.context, "hiz nearest")),
      test_pipeline_(services, "hiz_test.comp", "hiz test") {
    vk::Context& context = services.context;
    std::vector<VkDescriptorSetLayoutBinding> bindings = {
        vk::layout_binding(0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT),
        vk::layout_binding(1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT)};
    for (uint32_t k = 0; k < kMaxLevels; ++k)
        bindings.push_back(vk::layout_binding(kFirstLevelBinding + k,
                                              VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                                              VK_SHADER_STAGE_COMPUTE_BIT));
    test_set_layout_ = vk::DescriptorSetLayout(context, bindings, "hiz test set");
    const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2},
                                          {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kMaxLevels}};
    test_pool_ = vk::DescriptorPool(context, 1, sizes, "hiz test");
    test_set_ = test_pool_.allocate(test_set_layout_.handle());
    const VkDescriptorSetLayout sets[] = {services.frame_layout, test_set_layout_.handle()};
    const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(HizTestPush)};
    test_layout_ = vk::PipelineLayout(context, sets, {&push, 1}, "hiz test layout");
}

void HizPass::build_kernels() {
    vk::DestroyList nothing_in_flight;  // first build: no frame has used them
    install_kernels(nothing_in_flight);
    built_ = true;
}

void HizPass::install_kernels(vk::DestroyList& retired) {
    // Compile all three before replacing any, so a failure leaves a matching set.
    ComputeKernel::Prepared copy = copy_.prepare({{"HIZ_MODE", "0"}});
    ComputeKernel::Prepared samples = copy_samples_.prepare({{"HIZ_MODE", "1"}});
    ComputeKernel::Prepared reduce = reduce_.prepare({{"HIZ_MODE", "2"}});
    copy_.install(std::move(copy), retired);
    copy_samples_.install(std::move(samples), retired);
    reduce_.install(std::move(reduce), retired);
}

void HizPass::rebuild_pipelines(vk::DestroyList& retired) {
    if (built_) install_kernels(retired);
    test_pipeline_.rebuild(retired);
}

std::vector<SettingDef> HizPass::knobs() {
    return {bool_knob(kKnob, "diagnostics", false,
                      "prepass on: the hiz pass builds a Hi-Z pyramid from the prepass depth "
                      "(images hiz.0 ... hiz.N, each texel the farthest of its children; at msaa "
                      "> 1 level 0 is the farthest sample); with count_draws each draw's screen "
                      "bounds are tested against it (report draws[].hiz next to samples_passed)",
                      Invalidates::Nothing)};
}

void HizPass::configure(const FrameSetup& setup, FrameOptions& o) {
    const bool knob = knob_value(setup.settings, kKnob);
    on_ = knob && o.prepass && !o.subpass;  // built from the prepass's depth
    if (knob && !o.prepass) set_skipped("prepass off");
    if (knob && o.subpass) {
        set_skipped("render_path=subpass: the depth is in tile memory until lighting has drawn");
        set_turned_off(kKnob.name);
    }
}

void HizPass::add(graph::RenderGraph& graph, const FrameInputs& in, FrameResources& res) {
    result_.reset();
    verdicts_ = {};
    if (!on_) return;
    if (!built_) build_kernels();  // on first use: most sessions never look at it
    const std::vector<graph::ImageHandle> levels = add_pyramid(graph, in, res);
    HizResult r;
    for (graph::ImageHandle h : levels) {
        const VkExtent2D e = graph.resources()[h.index].extent;
        r.levels.emplace_back(e.width, e.height);
    }
    r.source = in.options.msaa() ? "msaa_depth" : "depth";
    r.samples = uint32_t(in.options.samples);
    r.reverse_z = in.options.reverse_z;
    result_ = std::move(r);
    if (in.options.count_draws && in.scene && !in.scene->instance_bounds().empty())
        add_test(graph, in, res, levels);
}

std::vector<graph::ImageHandle> HizPass::add_pyramid(graph::RenderGraph& graph,
                                                     const FrameInputs& in,
                                                     const FrameResources& res) {
    const bool msaa = in.options.msaa();
    const graph::ImageHandle source = msaa ? res.msaa_depth : res.depth;
    const std::vector<VkExtent2D> extents =
        hiz_level_extents(graph.resources()[source.index].extent);
    if (extents.size() > kMaxLevels)
        throw UsageError("hiz: a frame of " + std::to_string(extents.front().width) + "x" +
                         std::to_string(extents.front().height) + " needs " +
                         std::to_string(extents.size()) + " levels, more than " +
                         std::to_string(kMaxLevels));
    const graph::Semantic semantic =
        in.options.reverse_z ? graph::Semantic::ReverseZDepth : graph::Semantic::ForwardZDepth;
    struct Data {
        graph::ImageHandle source;
        std::vector<graph::ImageHandle> levels;
    };
    const Data& data = graph.add_pass<Data>(
        {name(), graph::PassKind::Compute},
        [&](graph::PassBuilder& b, Data& d) {
            b.read(res.frame_uniforms, Access::UniformRead);
            d.source = b.read(source, Access::Sampled);
            for (uint32_t k = 0; k < extents.size(); ++k) {
                const graph::ImageHandle level = b.create_image(
                    hiz_level_name(k),
                    {.format = kFormat,
                     .size = graph::ImageSize::fixed(extents[k].width, extents[k].height),
                     .semantic = semantic});
                b.write(level, Access::StorageWrite);
                if (k + 1 < extents.size()) b.read(level, Access::Sampled);  // the next level's
                d.levels.push_back(level);
            }
        },
        [this, msaa, samples = int32_t(in.options.samples), frame_set = in.frame_set,
         frame = in.frame_number](graph::PassContext& ctx, const Data& d) {
            auto bound = [&](graph::ImageHandle h) {
                return BoundImage{ctx.view(h), ctx.layout(h)};
            };
            const BoundImage first[] = {bound(d.source), bound(d.levels[0])};
            (msaa ? copy_samples_ : copy_)
                .dispatch(ctx.cmd(), frame_set, frame, first, &samples, ctx.extent(d.levels[0]));
            for (size_t k = 1; k < d.levels.size(); ++k) {
                // The graph orders passes; inside this one, each level reads the one before.
                ctx.dependency(d.levels[k - 1], Access::StorageWrite, Access::Sampled);
                const BoundImage images[] = {bound(d.levels[k - 1]), bound(d.levels[k])};
                reduce_.dispatch(ctx.cmd(), frame_set, frame, images, &samples,
                                 ctx.extent(d.levels[k]), uint32_t(k - 1));
            }
        });
    return data.levels;
}

void HizPass::add_test(graph::RenderGraph& graph, const FrameInputs& in, const FrameResources& res,
                       const std::vector<graph::ImageHandle>& levels) {
    const uint32_t instances = uint32_t(in.scene->instance_bounds().size());
    const graph::BufferHandle out = services_.readback.import_storage(
        graph, kVerdictBuffer, VkDeviceSize(instances) * sizeof(HizVerdictRecord));
    verdicts_ = out;
    test_pipeline_.get(test_layout_.handle());  // built now, not while the frame records
    struct Data {};
    graph.add_pass<Data>(
        {"hiz_test", graph::PassKind::Compute},
        [&](graph::PassBuilder& b, Data&) {
            b.read(res.frame_uniforms, Access::UniformRead);
            for (graph::ImageHandle level : levels) b.read(level, Access::Sampled);
            b.write(out, Access::StorageWrite);
        },
        [this, levels, out, scene = in.scene, frame_set = in.frame_set, instances](
            graph::PassContext& ctx, const Data&) {
            vk::DescriptorWriter writer;
            writer.buffer(0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, scene->instance_bounds_buffer())
                .buffer(1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, ctx.buffer(out));
            for (uint32_t k = 0; k < kMaxLevels; ++k) {
                const graph::ImageHandle level = levels[std::min<size_t>(k, levels.size() - 1)];
                writer.image(kFirstLevelBinding + k, ctx.view(level), nearest_.handle(),
                             ctx.layout(level));
            }
            writer.update(services_.context.device(), test_set_);
            record_test(ctx, frame_set, instances, uint32_t(levels.size()));
        });
}

void HizPass::record_test(graph::PassContext& ctx, VkDescriptorSet frame_set, uint32_t instances,
                          uint32_t levels) {
    VkCommandBuffer cmd = ctx.cmd();
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE,
                      test_pipeline_.get(test_layout_.handle()));
    const VkDescriptorSet sets[] = {frame_set, test_set_};
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, test_layout_.handle(), 0, 2, sets,
                            0, nullptr);
    const HizTestPush push{instances, levels, kMargin};
    vkCmdPushConstants(cmd, test_layout_.handle(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push,
                       &push);
    vkCmdDispatch(cmd, (instances + kHizTestGroup - 1) / kHizTestGroup, 1, 1);
}

void HizPass::collect(const FrameCollect& c, std::span<PassResult>, FrameResult& frame) {
    if (!result_) return;
    HizResult r = std::move(*result_);
    result_.reset();
    const std::span<const std::byte> bytes =
        verdicts_.valid() ? c.readback.buffer_bytes(verdicts_) : std::span<const std::byte>{};
    const size_t instances = c.in.scene ? c.in.scene->instance_bounds().size() : 0;
    if (!bytes.empty() && bytes.size() >= instances * sizeof(HizVerdictRecord)) {
        for (size_t i = 0; i < instances; ++i) {
            HizVerdictRecord record;
            std::memcpy(&record, bytes.data() + i * sizeof record, sizeof record);
            r.instances.push_back(hiz_instance(record));
        }
        group_verdicts(*c.in.scene, r);
    }
    frame.slots.put(std::move(r), &hiz_report);
}

// hiz=on: the pyramid's levels and, with count_draws, the verdicts' tally and the unsafe
// disagreements (per draw in draws[]).
void hiz_report(const HizResult& h, const FrameResult&, nlohmann::json& report) {
    nlohmann::json levels = nlohmann::json::array();
    for (const auto& [w, ht] : h.levels) levels.push_back({w, ht});
    nlohmann::json json = {{"levels", levels},
                           {"source", h.source},
                           {"samples", h.samples},
                           {"farthest", h.reverse_z ? "min (reverse-Z)" : "max (forward-Z)"}};
    if (!h.groups.empty()) {
        nlohmann::json tally = {{"visible", 0}, {"occluded", 0}, {"outside", 0}};
        for (HizVerdict v : h.groups)
            tally[hiz_verdict_name(v)] = tally[hiz_verdict_name(v)].get<int>() + 1;
        json["draws"] = tally;
    }
    json["unsafe_draws"] = h.unsafe ? nlohmann::json(*h.unsafe) : nullptr;
    json["unsafe_visible_draws"] = h.unsafe_visible ? nlohmann::json(*h.unsafe_visible) : nullptr;
    report["hiz"] = std::move(json);
}

}  // namespace ds::passes
