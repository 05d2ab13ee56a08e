#include "renderer/passes/pixel_history.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <tuple>

#include <glm/gtc/packing.hpp>

#include "renderer/common/error.h"
#include "renderer/readback/host_readback.h"
#include "renderer/vk/context.h"
#include "renderer/vk/functions.h"
#include "renderer/vk/upload.h"

namespace ds::passes {

using graph::Access;

namespace {

// The stand-in for output 0 (lavapipe crashes drawing without any attachment).
constexpr VkFormat kTargetFormat = VK_FORMAT_R8G8B8A8_UNORM;
constexpr VkDeviceSize kHistoryHeaderBytes = 16;  // count and padding, zeroed by the host
constexpr VkDeviceSize kBufferBytes =
    kHistoryHeaderBytes + PixelHistoryReplay::kCapacity * sizeof(HistoryRecord);
const VkDescriptorPoolSize kPixelHistoryPoolSizes[] = {
    {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1}, {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 2}};

// The value the depth image holds for `z`: unorm formats round to their steps (as the
// rasterizer converts before the test), floats keep it.
float stored_depth(float z, VkFormat format) {
    double steps = 0;
    if (format == VK_FORMAT_D16_UNORM) steps = 65535.0;
    if (format == VK_FORMAT_D24_UNORM_S8_UINT || format == VK_FORMAT_X8_D24_UNORM_PACK32)
        steps = 16777215.0;
    if (steps == 0) return z;
    return float(std::round(double(std::clamp(z, 0.0f, 1.0f)) * steps) / steps);
}

bool compare(VkCompareOp op, float fragment, float stored) {
    switch (op) {
        case VK_COMPARE_OP_NEVER:
            return false;
        case VK_COMPARE_OP_LESS:
            return fragment < stored;
        case VK_COMPARE_OP_EQUAL:
            return fragment == stored;
        case VK_COMPARE_OP_LESS_OR_EQUAL:
            return fragment <= stored;
        case VK_COMPARE_OP_GREATER:
            return fragment > stored;
        case VK_COMPARE_OP_NOT_EQUAL:
            return fragment != stored;
        case VK_COMPARE_OP_GREATER_OR_EQUAL:
            return fragment >= stored;
        default:
            return true;
    }
}

// What an R16G16B16A16_SFLOAT attachment keeps of `v`.
float to_half(float v) {
    return glm::unpackHalf1x16(glm::packHalf1x16(v));
}

// SRC_ALPHA / ONE_MINUS_SRC_ALPHA for colour, ONE / ONE_MINUS_SRC_ALPHA for alpha (vk::Blend).
std::array<float, 4> blend(const std::array<float, 4>& src, const std::array<float, 4>& dst) {
    const float a = src[3];
    std::array<float, 4> out{};
    for (int c = 0; c < 3; ++c) out[c] = to_half(src[c] * a + dst[c] * (1.0f - a));
    out[3] = to_half(a + dst[3] * (1.0f - a));
    return out;
}

// Submission order: the draw holding the instance, then the instance, then the primitive.
struct Ordered {
    uint32_t draw = 0;
    const HistoryRecord* record = nullptr;
};
std::vector<Ordered> in_submission_order(std::span<const HistoryRecord> records,
                                         const DrawLog& log) {
    std::vector<Ordered> out;
    for (const HistoryRecord& r : records) {
        for (uint32_t d = 0; d < log.draws.size(); ++d) {
            const DrawLog::Draw& draw = log.draws[d];
            if (r.instance >= draw.first_instance &&
                r.instance < draw.first_instance + draw.instance_count) {
                out.push_back({d, &r});
                break;
            }
        }
    }
    const auto key = [](const Ordered& o) {
        return std::tuple(o.draw, o.record->instance, o.record->primitive, o.record->sample);
    };
    std::sort(out.begin(), out.end(),
              [&](const Ordered& a, const Ordered& b) { return key(a) < key(b); });
    // One sample of one primitive of one instance is one fragment: lavapipe at msaa > 1 runs
    // the per-sample invocations' stores more than once for some samples, identically.
    out.erase(std::unique(out.begin(), out.end(),
                          [&](const Ordered& a, const Ordered& b) { return key(a) == key(b); }),
              out.end());
    return out;
}

}  // namespace

HistoryPipeline history_pipeline(const PipelineInfo& info, bool blend) {
    return {info.name, info.early_z == "guaranteed", blend};
}

std::vector<PixelFragment> simulate(const char* pass, std::span<const HistoryRecord> records,
                                    const DrawLog& log, std::span<const HistoryPipeline> pipelines,
                                    const HistoryRules& rules) {
    std::map<uint32_t, float> depth;                 // per sample: the depth buffer now
    std::map<uint32_t, std::array<float, 4>> color;  // per sample: the HDR colour now
    std::vector<PixelFragment> out;
    for (const Ordered& o : in_submission_order(records, log)) {
        const HistoryRecord& r = *o.record;
        const HistoryPipeline& pipeline = pipelines[log.draws[o.draw].pipeline];
        if (!depth.count(r.sample)) depth[r.sample] = rules.clear_depth.value_or(r.start_depth);
        if (!color.count(r.sample)) color[r.sample] = r.dst;
        PixelFragment f;
        f.pass = pass;
        f.pipeline = pipeline.name;
        f.draw = o.draw;
        f.instance = r.instance;
        f.primitive = r.primitive;
        f.sample = r.sample;
        f.depth = stored_depth(r.depth, rules.depth_format);
        f.against = depth[r.sample];
        f.depth_passed = compare(rules.compare, f.depth, f.against);
        const bool discarded = (r.flags & kHistoryDiscarded) != 0;
        if (r.flags & kHistoryAlphaTested)
            f.alpha_test = PixelAlphaTest{r.alpha, r.cutoff, !discarded};
        // Early-Z: the test ran first and only what passed ran the shader; otherwise the
        // shader ran for every rasterized fragment and the (late) test came after it.
        f.shaded = pipeline.early_z ? f.depth_passed : true;
        if ((r.flags & kHistoryColor) && !discarded) f.color = r.color;
        const bool kept = f.depth_passed && !discarded;
        if (kept && rules.depth_write) depth[r.sample] = f.depth;
        if (kept && f.color && pipeline.blend) {
            color[r.sample] = blend(*f.color, color[r.sample]);
            f.blended = color[r.sample];
        } else if (kept && f.color) {
            color[r.sample] = *f.color;
        }
        out.push_back(std::move(f));
    }
    return out;
}

PixelHistoryReplay::PixelHistoryReplay(const PassServices& services, std::string pass,
                                       std::vector<VkDescriptorSetLayout> pass_sets)
    : services_(services), pass_(std::move(pass)), pass_sets_(std::move(pass_sets)) {}

VkPipelineLayout PixelHistoryReplay::layout() const {
    if (layout_.handle()) return layout_.handle();
    const VkDescriptorSetLayoutBinding bindings[] = {
        vk::layout_binding(0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_FRAGMENT_BIT),
        vk::layout_binding(1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                           VK_SHADER_STAGE_FRAGMENT_BIT),
        vk::layout_binding(2, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                           VK_SHADER_STAGE_FRAGMENT_BIT)};
    const std::string name = pass_ + " history";
    set_layout_ =
        vk::DescriptorSetLayout(services_.context, bindings, (name + " set layout").c_str());
    // The pass's sets 0..3 exactly (compatible layouts), then the history set.
    if (pass_sets_.size() != kSet) throw Error(pass_ + ": pixel history needs 4 pass sets");
    std::vector<VkDescriptorSetLayout> sets = pass_sets_;
    sets.push_back(set_layout_.handle());
    layout_ = vk::PipelineLayout(services_.context, sets, {}, (name + " layout").c_str());
    sets_.emplace(services_.context, 1, kPixelHistoryPoolSizes, (name + " sets").c_str());
    sampler_ = vk::nearest_clamp_sampler(services_.context, (name + " sampler").c_str());
    // Lavapipe reads every descriptor of a bound set: what the variant does not read gets this.
    const VkImageUsageFlags usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    unused_ = vk::Image(services_.context, {1, 1, 1, VK_FORMAT_R8G8B8A8_UNORM, usage,
                                            VK_SAMPLE_COUNT_1_BIT, (name + " unused").c_str()});
    vk::clear_image_once(services_.context, unused_, VkClearValue{});
    return layout_.handle();
}

vk::Pipeline PixelHistoryReplay::create(const ShaderStages& stages, VkSampleCountFlagBits samples,
                                        const std::string& name, VertexInputs inputs) const {
    // Output 0 goes to the stand-in attachment, the rest is recorded. gl_SampleID in the MSAA
    // variant runs it once per sample.
    return scene_pipeline_builder(layout(), stages.vert, stages.frag, inputs)
        .color_attachment(kTargetFormat)
        .samples(samples)
        .build(services_.context, name.c_str());
}

std::vector<shader::Define> PixelHistoryReplay::defines(bool reads_depth, bool reads_dst,
                                                        bool msaa) {
    std::vector<shader::Define> d = {{"PIXEL_HISTORY", "1"}};
    if (reads_depth) d.push_back({"PIXEL_HISTORY_DEPTH", "1"});
    if (reads_dst) d.push_back({"PIXEL_HISTORY_DST", "1"});
    if (msaa) d.push_back({"PIXEL_HISTORY_MSAA", "1"});
    return d;
}

void PixelHistoryReplay::clear() {
    buffer_ = {};
    log_ = {};
}

void PixelHistoryReplay::add(graph::RenderGraph& graph, const FrameInputs& in, const Reads& reads,
                             const Declare& declare, Draw draw) {
    const graph::BufferHandle buffer = services_.readback.import_storage(
        graph, pass_ + "_history", kBufferBytes, kHistoryHeaderBytes);
    buffer_ = buffer;
    struct Data {
        FrameInputs in;
        Reads reads;
        graph::BufferHandle buffer;
        Draw draw;
    };
    graph.add_pass<Data>(
        {pass_ + "_history", graph::PassKind::Graphics, graph::PassRole::History},
        [&](graph::PassBuilder& b, Data& d) {
            const graph::ImageHandle target =
                b.create_image(pass_ + "_history_target", {.format = kTargetFormat,
                                                           .size = graph::ImageSize::relative(1.0f),
                                                           .samples = in.options.samples,
                                                           .semantic = graph::Semantic::Other});
            b.color(target, {.load = graph::Load::DontCare});
            b.write(buffer, Access::StorageReadWrite, graph::Shader::Fragment);
            for (graph::ImageHandle h : {reads.depth, reads.dst})
                if (h.valid()) b.read(h, Access::Sampled, graph::Shader::Fragment);
            declare(b);
            d = {in, reads, buffer, std::move(draw)};
        },
        [this](graph::PassContext& ctx, const Data& d) {
            record(ctx, d.in, d.reads, d.buffer, d.draw);
        });
}

// Inside the rendering the graph began on the stand-in target: the viewport is the frame's, so
// every fragment lands where the real pass puts it; the scissor keeps the one pixel.
void PixelHistoryReplay::record(graph::PassContext& ctx, const FrameInputs& in, const Reads& reads,
                                graph::BufferHandle buffer, const Draw& draw) {
    VkCommandBuffer cmd = ctx.cmd();
    const VkDescriptorSet set = sets_->allocate(in.frame_number, set_layout_.handle());
    vk::DescriptorWriter writer;
    writer.buffer(0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, ctx.buffer(buffer));
    uint32_t binding = 1;
    for (graph::ImageHandle h : {reads.depth, reads.dst}) {
        if (h.valid())
            writer.image(binding++, ctx.view(h), sampler_.handle(), ctx.layout(h));
        else
            writer.image(binding++, unused_.view(), sampler_.handle());
    }
    writer.update(services_.context.device(), set);
    const VkRect2D pixel{{int32_t(in.pixel->x), int32_t(in.pixel->y)}, {1, 1}};
    vkCmdSetScissor(cmd, 0, 1, &pixel);
    set_depth_state(cmd, /*test=*/false, /*write=*/false, VK_COMPARE_OP_ALWAYS);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_.handle(), kSet, 1, &set,
                            0, nullptr);
    draw(ctx, log_);
}

void PixelHistoryReplay::collect(const FrameCollect& c, std::span<const HistoryPipeline> pipelines,
                                 const HistoryRules& rules, FrameResult& frame) const {
    const std::span<const std::byte> bytes = c.readback.buffer_bytes(buffer_);
    if (bytes.size() < kBufferBytes || !c.in.pixel) return;
    uint32_t count = 0;
    std::memcpy(&count, bytes.data(), sizeof count);
    std::vector<HistoryRecord> records(std::min(count, kCapacity));
    if (!records.empty())  // data() may be null then: memcpy(null, …, 0) is undefined
        std::memcpy(records.data(), bytes.data() + kHistoryHeaderBytes,
                    records.size() * sizeof(HistoryRecord));
    PixelHistory* history = frame.slots.find<PixelHistory>();
    if (!history) history = &frame.slots.put(PixelHistory{c.in.pixel->x, c.in.pixel->y});
    history->dropped += count - records.size();
    for (PixelFragment& f : simulate(pass_.c_str(), records, log_, pipelines, rules))
        history->fragments.push_back(std::move(f));
}

}  // namespace ds::passes
