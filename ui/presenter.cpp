#include "ui/presenter.h"

#include <cstring>

#include <backends/imgui_impl_vulkan.h>
#include <imgui.h>

#include "renderer/common/error.h"
#include "renderer/vk/check.h"
#include "renderer/vk/context.h"

namespace ds::ui {
namespace {

using graph::Access;

constexpr VkFormat kDisplayFormat = VK_FORMAT_R8G8B8A8_UNORM;
// The viewport's background where no image is: ImGui's dark window colour.
constexpr VkClearColorValue kBackground{{0.06f, 0.06f, 0.07f, 1.0f}};

void check_result(VkResult result) {
    if (result != VK_SUCCESS) vk::check(result, "ImGui Vulkan backend");
}

vk::RenderPass create_render_pass(vk::Context& context, VkFormat format) {
    // Only for the backend's pipeline: the graph begins a compatible render pass of its own (one
    // subpass, one colour attachment of this format) around ui_imgui.
    VkAttachmentDescription colour{};
    colour.format = format;
    colour.samples = VK_SAMPLE_COUNT_1_BIT;
    colour.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
    colour.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    colour.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    colour.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    colour.initialLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    colour.finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    const VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = 1;
    subpass.pColorAttachments = &ref;
    auto info = vk::make<VkRenderPassCreateInfo>(VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO);
    info.attachmentCount = 1;
    info.pAttachments = &colour;
    info.subpassCount = 1;
    info.pSubpasses = &subpass;
    VkRenderPass pass = VK_NULL_HANDLE;
    vk::check(vkCreateRenderPass(context.device(), &info, nullptr, &pass), "vkCreateRenderPass");
    context.set_name(VK_OBJECT_TYPE_RENDER_PASS, pass, "imgui");
    return vk::RenderPass(context.device(), pass);
}

}  // namespace

Presenter::Presenter(vk::Context& context, VkFormat target_format)
    : context_(context), format_(target_format) {
    if (!ImGui::GetCurrentContext()) throw Error("presenter: no ImGui context");
    const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4}};
    imgui_pool_ = vk::DescriptorPool(context_, 4, sizes, "imgui");
    render_pass_ = create_render_pass(context_, format_);
    frames_ = std::make_unique<vk::FrameRing>(context_);
    graph_ = std::make_unique<graph::RenderGraph>(context_);
    readback_ = std::make_unique<HostReadback>(context_);

    ImGui_ImplVulkan_InitInfo info{};
    info.Instance = context_.instance();
    info.PhysicalDevice = context_.physical_device();
    info.Device = context_.device();
    info.QueueFamily = context_.queue_family();
    info.Queue = context_.queue();
    info.DescriptorPool = imgui_pool_.handle();
    info.MinImageCount = 2;
    info.ImageCount = vk::FrameRing::kFramesInFlight;
    info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    info.CheckVkResultFn = check_result;
    if (!ImGui_ImplVulkan_Init(&info, render_pass_.handle()))
        throw Error("ImGui Vulkan backend: initialisation failed");
    backend_ = true;
    context_.submit_once([](VkCommandBuffer cmd) { ImGui_ImplVulkan_CreateFontsTexture(cmd); });
    ImGui_ImplVulkan_DestroyFontUploadObjects();
}

Presenter::~Presenter() {
    context_.drain();
    if (backend_) ImGui_ImplVulkan_Shutdown();
    frames_.reset();
    readback_.reset();
    graph_.reset();
}

void Presenter::wait_idle() {
    context_.wait_idle();
}

void Presenter::forget_targets() {
    context_.wait_idle();  // the graph's framebuffers of their views have died with their frames
}

void Presenter::ensure_display(uint32_t width, uint32_t height, vk::DestroyList& retired) {
    if (display_ && display_.width() == width && display_.height() == height) return;
    if (display_) retired.defer(std::move(display_));
    if (staging_) retired.defer(std::move(staging_));
    display_ =
        vk::Image(context_, {width, height, 1, kDisplayFormat,
                             VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                 VK_IMAGE_USAGE_SAMPLED_BIT,  // views need a view usage
                             VK_SAMPLE_COUNT_1_BIT, "viewer display"});
    staging_ =
        vk::Buffer(context_, {VkDeviceSize(width) * height * 4, VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                              vk::MemoryUsage::Upload, "viewer staging"});
}

// ui_upload: the viewer's decoded pixels from the staging buffer into the display image; no
// pass when they are the version already there (the UI redraws at display rate, the pixels
// change with a scene frame or the view).
graph::ImageHandle Presenter::add_upload(const ViewerBlit& viewer, vk::DestroyList& retired) {
    graph::RenderGraph& g = *graph_;
    const bool same_size =
        display_ && display_.width() == viewer.width && display_.height() == viewer.height;
    const bool current = same_size && viewer.version != 0 && viewer.version == uploaded_version_;
    ensure_display(viewer.width, viewer.height, retired);
    graph::ExternalImage d;
    d.image = display_.handle();
    d.view = display_.view();
    d.desc = {.format = kDisplayFormat,
              .size = graph::ImageSize::fixed(viewer.width, viewer.height),
              .semantic = graph::Semantic::LdrColor};
    if (current) {  // as the last frame's blit left it (each UI frame waits for its fence)
        d.initial = {VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_BLIT_BIT,
                     VK_ACCESS_2_NONE};
        return g.import_image("viewer_display", d);
    }
    d.initial = {};  // rewritten
    staging_.write(viewer.rgba8->data(), viewer.rgba8->size());
    uploaded_version_ = viewer.version;
    const graph::ImageHandle display = g.import_image("viewer_display", d);
    graph::ExternalBuffer s;
    s.buffer = staging_.handle();
    s.size = staging_.size();
    s.initial = {VK_IMAGE_LAYOUT_UNDEFINED, VK_PIPELINE_STAGE_2_HOST_BIT,
                 VK_ACCESS_2_HOST_WRITE_BIT};
    const graph::BufferHandle staging = g.import_buffer("viewer_staging", s);
    struct Data {};
    g.add_pass<Data>(
        {"ui_upload", graph::PassKind::Transfer},
        [&](graph::PassBuilder& b, Data&) {
            b.read(staging, Access::TransferSrc);
            b.write(display, Access::TransferDst);
        },
        [=, w = viewer.width, h = viewer.height](graph::PassContext& ctx, const Data&) {
            VkBufferImageCopy copy{};
            copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            copy.imageExtent = {w, h, 1};
            vkCmdCopyBufferToImage(ctx.cmd(), ctx.buffer(staging), ctx.image(display),
                                   ctx.layout(display), 1, &copy);
        });
    return display;
}

// ui_viewer: clears the target and blits the display image (when there is one) into the
// viewer's rectangle.
void Presenter::add_viewer(graph::ImageHandle ui, graph::ImageHandle display,
                           const BlitRegion& region, bool nearest) {
    struct Data {};
    graph_->add_pass<Data>(
        {"ui_viewer", graph::PassKind::Transfer},
        [&](graph::PassBuilder& b, Data&) {
            if (display.valid()) b.read(display, Access::TransferSrc);
            b.write(ui, Access::TransferDst);
        },
        [=](graph::PassContext& ctx, const Data&) {
            const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
            vkCmdClearColorImage(ctx.cmd(), ctx.image(ui), ctx.layout(ui), &kBackground, 1, &range);
            if (!display.valid()) return;
            // The clear and the blit both write the target: order them.
            ctx.dependency(ui, Access::TransferDst, Access::TransferDst);
            VkImageBlit b{};
            b.srcSubresource = b.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            b.srcOffsets[0] = {region.sx0, region.sy0, 0};
            b.srcOffsets[1] = {region.sx1, region.sy1, 1};
            b.dstOffsets[0] = {region.dx0, region.dy0, 0};
            b.dstOffsets[1] = {region.dx1, region.dy1, 1};
            vkCmdBlitImage(ctx.cmd(), ctx.image(display), ctx.layout(display), ctx.image(ui),
                           ctx.layout(ui), 1, &b, nearest ? VK_FILTER_NEAREST : VK_FILTER_LINEAR);
        });
}

// ui_imgui: ImGui's draw data over the target, through the backend's render pass.
void Presenter::add_imgui(graph::ImageHandle ui, ImDrawData* draw) {
    struct Data {};
    graph_->add_pass<Data>(
        "ui_imgui",
        [&](graph::PassBuilder& b, Data&) {
            // The backend's pipeline is made for render_pass_, which the graph's one-subpass
            // render pass over the same attachment is compatible with.
            b.render_pass();
            b.color(ui);
        },
        [draw](graph::PassContext& ctx, const Data&) {
            if (draw) ImGui_ImplVulkan_RenderDrawData(draw, ctx.cmd());
        });
}

// ui_readback (read-back role): the target into a host buffer (render_offscreen).
void Presenter::add_readback(graph::ImageHandle ui) {
    readback_->add_copy_pass(*graph_, "ui_readback", {ui});
}

void Presenter::record(VkCommandBuffer cmd, const Target& target, const graph::ExternalState& final,
                       const ViewerBlit& viewer, ImDrawData* draw, vk::DestroyList& retired,
                       bool read_back) {
    BlitRegion region{};
    const bool blit = clip_blit(viewer, {target.extent.width, target.extent.height}, region);
    graph::RenderGraph& g = *graph_;
    g.begin_frame(target.extent, retired);
    readback_->begin_frame(retired);

    graph::ExternalImage out;
    out.image = target.image;
    out.view = target.view;
    out.desc = {.format = format_,
                .size = graph::ImageSize::fixed(target.extent.width, target.extent.height),
                .semantic = graph::Semantic::LdrColor};
    out.initial = {};  // UNDEFINED: every UI frame draws the whole target
    out.final = final;
    const graph::ImageHandle ui = g.import_image("ui_target", out);
    target_ = ui;

    const graph::ImageHandle display = blit ? add_upload(viewer, retired) : graph::ImageHandle{};
    add_viewer(ui, display, region, viewer.nearest);
    add_imgui(ui, draw);
    if (read_back) add_readback(ui);
    g.compile();
    last_graph_frame_ = g.execute(cmd);
}

// The UI composite's cost: its passes, not the offscreen read-back (a window has none).
UiFrameStats Presenter::collect(uint64_t id) const {
    UiFrameStats stats;
    const std::vector<graph::PassResult> passes = graph_->collect(id);
    for (size_t i = 0; i < passes.size(); ++i)
        if (graph_->passes()[i].role != graph::PassRole::ReadBack) stats.gpu_ms += passes[i].gpu_ms;
    return stats;
}

UiFrameStats Presenter::present(const Target& target, const ViewerBlit& viewer, ImDrawData* draw,
                                VkSemaphore acquired, VkSemaphore rendered) {
    vk::Frame& frame = frames_->begin();
    record(frame.cmd, target, graph::ExternalState::present(), viewer, draw, frame.retired);
    frames_->submit(frame, {.wait = acquired,
                            .wait_stages = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                            .signal = rendered});
    frames_->wait(frame);
    return collect(last_graph_frame_);
}

std::vector<uint8_t> Presenter::render_offscreen(VkExtent2D extent, const ViewerBlit& viewer,
                                                 ImDrawData* draw, UiFrameStats* stats) {
    vk::Frame& frame = frames_->begin();
    if (!offscreen_ || offscreen_.width() != extent.width || offscreen_.height() != extent.height) {
        if (offscreen_) frame.retired.defer(std::move(offscreen_));
        offscreen_ = vk::Image(
            context_, {extent.width, extent.height, 1, kOffscreenFormat,
                       VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                           VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                       VK_SAMPLE_COUNT_1_BIT, "ui offscreen"});
    }
    const Target target{offscreen_.handle(), offscreen_.view(), extent};
    record(frame.cmd, target, graph::ExternalState::transfer_src(), viewer, draw, frame.retired,
           /*read_back=*/true);
    frames_->submit(frame);
    frames_->wait(frame);
    if (stats) *stats = collect(last_graph_frame_);
    const std::span<const std::byte> bgra = readback_->image_bytes(target_);
    std::vector<uint8_t> rgba(size_t(extent.width) * extent.height * 4);
    if (bgra.size() < rgba.size()) throw Error("ui: the offscreen read-back is incomplete");
    for (size_t i = 0; i < rgba.size(); i += 4) {  // B8G8R8A8 -> RGBA
        rgba[i + 0] = uint8_t(bgra[i + 2]);
        rgba[i + 1] = uint8_t(bgra[i + 1]);
        rgba[i + 2] = uint8_t(bgra[i + 0]);
        rgba[i + 3] = 255;
    }
    return rgba;
}

}  // namespace ds::ui
