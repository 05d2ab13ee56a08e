#include "renderer/passes/geometry_instrument.h"

#include "renderer/gpu_scene/gpu_scene.h"
#include "renderer/vk/context.h"

namespace ds::passes {

GeometryInstrument::GeometryInstrument(const PassServices& services, const char* pass,
                                       VkDescriptorSetLayout set2)
    : services_(services),
      set2_(set2),
      count_layout_(create_count_set_layout(services.context)),
      count_sets_(services.context, 1, kCountPoolSizes,
                  (std::string(pass) + " count sets").c_str()),
      rasterized_(services, pass),
      queries_(services.context),
      history_(services, pass,
               {services.frame_layout, services.material_layout, set2, count_layout_.handle()}) {}

std::vector<VkDescriptorSetLayout> GeometryInstrument::sets() const {
    return {services_.frame_layout, services_.material_layout, set2_, count_layout_.handle()};
}

void GeometryInstrument::begin_frame(const CountImages& counts, bool queries, uint32_t max_draws) {
    counts_ = counts;
    uses_.clear();
    history_.clear();
    history_pipelines_.clear();
    queries_.begin_frame(queries, max_draws);
}

void GeometryInstrument::declare(graph::PassBuilder& b) {
    if (counts_.valid()) declare_counts(b, counts_);
    if (queries_.on()) b.outside_rendering([this](VkCommandBuffer cmd) { queries_.reset(cmd); });
}

void GeometryInstrument::bind_counts(graph::PassContext& ctx, uint64_t frame_number,
                                     VkPipelineLayout layout) {
    if (!counts_.valid()) return;
    const VkDescriptorSet set = count_sets_.allocate(frame_number, count_layout_.handle());
    write_count_set(ctx, services_.context.device(), set, counts_);
    vkCmdBindDescriptorSets(ctx.cmd(), VK_PIPELINE_BIND_POINT_GRAPHICS, layout, kCountSet, 1, &set,
                            0, nullptr);
}

void GeometryInstrument::add_history(graph::RenderGraph& graph, const FrameInputs& in,
                                     const PixelHistoryReplay::Reads& reads,
                                     PixelHistoryReplay::Declare declare,
                                     PixelHistoryReplay::Draw draw,
                                     std::vector<HistoryPipeline> pipelines) {
    history_pipelines_ = std::move(pipelines);
    history_.add(graph, in, reads, std::move(declare), std::move(draw));
}

void GeometryInstrument::add_measure(graph::RenderGraph& graph, const FrameInputs& in,
                                     const FrameResources& res,
                                     RasterizedCount::Selection selection) {
    rasterized_.add(graph, in, res, counts_, std::move(selection));
}

bool GeometryInstrument::collect(const FrameCollect& c, std::span<PassResult> own,
                                 FrameResult& frame, const HistoryRules& rules) {
    PassResult* const own_pass = frame_result(own);
    if (!own_pass) return false;
    collect_counts(c.readback, counts_, *own_pass);
    own_pass->pipelines = uses_.list();
    own_pass->draw_samples_passed = queries_.per_group(c.in.scene->draw_groups().size());
    history_.collect(c, history_pipelines_, rules, frame);
    return true;
}

}  // namespace ds::passes
