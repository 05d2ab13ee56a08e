#include "renderer/renderer.h"

#include <array>
#include <chrono>
#include <cmath>
#include <cstring>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/common/error.h"
#include "renderer/gpu_scene.h"
#include "renderer/passes/forward.h"
#include "renderer/shader/compiler.h"
#include "renderer/vk/barrier.h"
#include "renderer/vk/buffer.h"
#include "renderer/vk/context.h"
#include "renderer/vk/debug.h"
#include "renderer/vk/descriptors.h"
#include "renderer/vk/frame.h"
#include "renderer/vk/image.h"
#include "renderer/vk/pipeline.h"
#include "renderer/vk/query.h"

namespace ds {
namespace {

constexpr VkFormat kColorFormat = VK_FORMAT_R8G8B8A8_SRGB;
// Sky radiance behind everything, and the hemispherical ambient (scaled by `ambient`).
constexpr glm::vec3 kSkyRadiance{0.25f, 0.42f, 0.85f};
constexpr glm::vec3 kSkyAmbient{0.55f, 0.70f, 1.00f};
constexpr glm::vec3 kGroundAmbient{0.35f, 0.30f, 0.25f};

// std140 twin of FrameUniforms in shaders/common/bindings.glsl.
struct FrameUniforms {
    glm::mat4 view_projection{1.0f};
    glm::vec4 camera_position{0.0f};
    glm::vec4 sun_direction{0.0f, 1.0f, 0.0f, 0.0f};
    glm::vec4 sun_radiance{0.0f};
    glm::vec4 sky_ambient{0.0f};
    glm::vec4 ground_ambient{0.0f};
    glm::vec4 exposure{1.0f};
};
static_assert(sizeof(FrameUniforms) == 160);

enum FrameBinding : uint32_t { kFrameUniforms = 0, kInstances = 1 };

// Reverse-Z (near -> 1, far -> 0) right-handed perspective for Vulkan clip space; y is flipped
// so row 0 of the image is the top and counter-clockwise triangles stay front-facing.
glm::mat4 reverse_z_projection(float yfov, float aspect, float znear, float zfar) {
    const float f = 1.0f / std::tan(yfov * 0.5f);
    glm::mat4 p(0.0f);
    p[0][0] = f / aspect;
    p[1][1] = -f;
    p[2][2] = znear / (zfar - znear);
    p[2][3] = -1.0f;
    p[3][2] = znear * zfar / (zfar - znear);
    return p;
}

// A knob's value, or `fallback` while the registry does not have it.
float setting_or(const Settings& settings, std::string_view name, float fallback) {
    return SettingsRegistry::instance().find(name) ? settings.get_float(name) : fallback;
}

// Must match tonemap() in shaders/common/tonemap.glsl: the clear colour is the tonemapped sky.
glm::vec3 aces_fitted(glm::vec3 x) {
    const float a = 2.51f, b = 0.03f, c = 2.43f, d = 0.59f, e = 0.14f;
    return glm::clamp((x * (a * x + b)) / (x * (c * x + d) + e), 0.0f, 1.0f);
}

FrameUniforms frame_uniforms(const scene::Camera& camera, const Settings& settings,
                             const scene::DirectionalLight& sun, float aspect) {
    FrameUniforms u;
    u.view_projection =
        reverse_z_projection(camera.yfov, aspect, camera.znear, camera.zfar) * camera.view();
    u.camera_position = glm::vec4(camera.position, 1.0f);
    // Azimuth 0 puts the sun towards +Z, 90 towards +X; elevation is above the horizon.
    glm::vec3 to_sun = -glm::normalize(sun.direction);
    if (SettingsRegistry::instance().find("sun_azimuth") &&
        SettingsRegistry::instance().find("sun_elevation")) {
        const float az = glm::radians(settings.get_float("sun_azimuth"));
        const float el = glm::radians(settings.get_float("sun_elevation"));
        to_sun = {std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az)};
    }
    u.sun_direction = glm::vec4(to_sun, 0.0f);
    u.sun_radiance =
        glm::vec4(sun.color * setting_or(settings, "sun_intensity", sun.intensity), 0.0f);
    const float ambient = setting_or(settings, "ambient", 0.35f);
    u.sky_ambient = glm::vec4(kSkyAmbient * ambient, 0.0f);
    u.ground_ambient = glm::vec4(kGroundAmbient * ambient, 0.0f);
    u.exposure = glm::vec4(setting_or(settings, "exposure", 1.0f));
    return u;
}

}  // namespace

struct Renderer::Impl {
    struct Slot {  // per frame in flight
        vk::Buffer uniforms;
        VkDescriptorSet set = VK_NULL_HANDLE;
        vk::TimestampPool timestamps;
    };
    struct Targets {  // size-dependent; render() waits, so one set serves every slot
        vk::Image color;
        vk::Image depth;
        vk::Buffer readback;
    };

    explicit Impl(const RendererOptions& options);
    ~Impl();
    void ensure_targets(uint32_t width, uint32_t height, vk::DestroyList& retired);
    void record(vk::Frame& frame, Slot& slot, const FrameUniforms& uniforms, ReadBack read_back);
    void read_back(Slot& slot, FrameResult& result, ReadBack read_back);

    // Declared in creation order; ~Impl tears down explicitly in reverse.
    std::unique_ptr<vk::Context> context;
    std::unique_ptr<shader::Compiler> compiler;
    vk::DescriptorSetLayout frame_layout;
    vk::DescriptorSetLayout material_layout;
    vk::PipelineLayout pipeline_layout;
    vk::DescriptorPool frame_pool;
    std::array<Slot, vk::FrameRing::kFramesInFlight> slots;
    std::unique_ptr<vk::FrameRing> frames;
    std::unique_ptr<passes::ForwardPass> forward;
    std::unique_ptr<GpuScene> scene;
    scene::DirectionalLight sun;
    Targets targets;
};

Renderer::Impl::Impl(const RendererOptions& options) {
    context = std::make_unique<vk::Context>(
        vk::ContextOptions{.validate = options.validate, .device = options.device});
    compiler = std::make_unique<shader::Compiler>();
    const VkShaderStageFlags graphics = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    const VkDescriptorSetLayoutBinding frame_bindings[] = {
        vk::layout_binding(kFrameUniforms, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, graphics),
        vk::layout_binding(kInstances, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                           VK_SHADER_STAGE_VERTEX_BIT)};
    frame_layout = vk::DescriptorSetLayout(*context, frame_bindings, "frame set layout");
    material_layout = create_material_set_layout(*context);
    const VkDescriptorSetLayout sets[] = {frame_layout.handle(), material_layout.handle()};
    pipeline_layout = vk::PipelineLayout(*context, sets, {}, "scene pipeline layout");

    const uint32_t n = vk::FrameRing::kFramesInFlight;
    const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, n},
                                          {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, n}};
    frame_pool = vk::DescriptorPool(*context, n, sizes, "frame sets");
    const bool timestamps = context->report().timestamps && context->report().timestamp_valid_bits;
    for (Slot& slot : slots) {
        slot.uniforms =
            vk::Buffer(*context, {sizeof(FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                  vk::MemoryUsage::Upload, "frame uniforms"});
        slot.set = frame_pool.allocate(frame_layout.handle());
        if (timestamps) slot.timestamps = vk::TimestampPool(*context, 2);
    }
    frames = std::make_unique<vk::FrameRing>(*context);
    forward = std::make_unique<passes::ForwardPass>(*context, *compiler, pipeline_layout.handle(),
                                                    kColorFormat, context->report().depth_format);
}

Renderer::Impl::~Impl() {
    if (!context) return;
    vkDeviceWaitIdle(context->device());  // teardown: an error here has nowhere to go
    targets = Targets{};
    scene.reset();
    forward.reset();
    frames.reset();  // flushes every destroy list
    for (Slot& slot : slots) slot = Slot{};
    frame_pool = vk::DescriptorPool{};
    pipeline_layout.reset();
    material_layout.reset();
    frame_layout.reset();
    compiler.reset();
    context.reset();  // device, messenger, instance last
}

void Renderer::Impl::ensure_targets(uint32_t width, uint32_t height, vk::DestroyList& retired) {
    if (targets.color && targets.color.width() == width && targets.color.height() == height) return;
    // An earlier frame may still read the old images: they die after this frame's fence.
    if (targets.color) retired.defer(std::move(targets));
    targets = Targets{};
    targets.color =
        vk::Image(*context, {width, height, 1, kColorFormat,
                             VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                 VK_IMAGE_USAGE_SAMPLED_BIT,
                             VK_SAMPLE_COUNT_1_BIT, "forward colour"});
    targets.depth =
        vk::Image(*context, {width, height, 1, context->report().depth_format,
                             VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT |
                                 VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                             VK_SAMPLE_COUNT_1_BIT, "depth (reverse-Z)"});
    targets.readback =
        vk::Buffer(*context, {VkDeviceSize(width) * height * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                              vk::MemoryUsage::Readback, "colour readback"});
}

void Renderer::Impl::record(vk::Frame& frame, Slot& slot, const FrameUniforms& uniforms,
                            ReadBack read_back) {
    VkCommandBuffer cmd = frame.cmd;
    const VkImage color = targets.color.handle();
    const VkImage depth = targets.depth.handle();
    if (slot.timestamps.count()) slot.timestamps.reset(cmd);

    // Contents are discarded (UNDEFINED); the previous frame's copy-out read and depth writes
    // must still finish before the clears overwrite them.
    const vk::ImageBarrier to_attachment[] = {
        {.image = color,
         .old_layout = VK_IMAGE_LAYOUT_UNDEFINED,
         .new_layout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
         .src_stage = VK_PIPELINE_STAGE_2_COPY_BIT,
         .dst_stage = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
         .dst_access = VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT},
        {.image = depth,
         .aspect = targets.depth.aspect(),
         .old_layout = VK_IMAGE_LAYOUT_UNDEFINED,
         .new_layout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
         .src_stage = VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
         .src_access = VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
         .dst_stage = VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT |
                      VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
         .dst_access = VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                       VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT}};
    vk::image_barriers(cmd, to_attachment);

    if (slot.timestamps.count()) slot.timestamps.write(cmd, VK_PIPELINE_STAGE_2_TOP_OF_PIPE_BIT, 0);
    {
        vk::ScopedLabel label(context->debug(), cmd, "forward");
        const glm::vec3 sky = aces_fitted(kSkyRadiance * uniforms.exposure.x);
        forward->record({.cmd = cmd,
                         .scene = scene.get(),
                         .frame_set = slot.set,
                         .color = &targets.color,
                         .depth = &targets.depth,
                         .clear_color = {sky.r, sky.g, sky.b, 1.0f},
                         .camera_position = glm::vec3(uniforms.camera_position)});
    }
    if (slot.timestamps.count())
        slot.timestamps.write(cmd, VK_PIPELINE_STAGE_2_BOTTOM_OF_PIPE_BIT, 1);
    if (read_back == ReadBack::No) return;

    vk::image_barrier(cmd, {.image = color,
                            .old_layout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                            .new_layout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                            .src_stage = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                            .src_access = VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                            .dst_stage = VK_PIPELINE_STAGE_2_COPY_BIT,
                            .dst_access = VK_ACCESS_2_TRANSFER_READ_BIT});
    VkBufferImageCopy region{};  // bufferRowLength 0: tightly packed, row 0 = top
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {targets.color.width(), targets.color.height(), 1};
    vkCmdCopyImageToBuffer(cmd, color, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           targets.readback.handle(), 1, &region);
    vk::memory_barrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                       VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
}

void Renderer::Impl::read_back(Slot& slot, FrameResult& result, ReadBack read_back) {
    if (slot.timestamps.count()) {
        if (auto ticks = slot.timestamps.results()) {
            result.gpu_ms = slot.timestamps.ticks_to_ms((*ticks)[0], (*ticks)[1]);
            result.passes.push_back({"forward", result.gpu_ms});
        }
    }
    if (read_back == ReadBack::No) return;
    targets.readback.invalidate();
    const size_t bytes = size_t(result.width) * result.height * 4;
    result.rgba8.resize(bytes);
    std::memcpy(result.rgba8.data(), targets.readback.mapped(), bytes);
}

Renderer::Renderer(const RendererOptions& options) : impl_(std::make_unique<Impl>(options)) {}

Renderer::~Renderer() = default;

const vk::DeviceReport& Renderer::device_report() const {
    return impl_->context->report();
}

uint64_t Renderer::validation_message_count() const {
    return impl_->context->validation_message_count();
}

VkInstance Renderer::instance() const {
    return impl_->context->instance();
}

void Renderer::set_scene(const scene::Scene& scene) {
    Impl& r = *impl_;
    // Descriptor sets that in-flight frames use are rewritten below: let them finish first.
    r.context->wait_idle();
    r.scene.reset();
    r.scene = std::make_unique<GpuScene>(*r.context, scene, r.material_layout.handle());
    r.sun = scene.sun;
    for (Impl::Slot& slot : r.slots) {
        vk::DescriptorWriter writer;
        writer.buffer(kFrameUniforms, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, slot.uniforms.handle())
            .buffer(kInstances, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, r.scene->instance_buffer());
        writer.update(r.context->device(), slot.set);
    }
}

FrameResult Renderer::render(const scene::Camera& camera, const Settings& settings, uint32_t width,
                             uint32_t height, ReadBack read_back) {
    Impl& r = *impl_;
    if (!r.scene) throw Error("render: no scene (call set_scene first)");
    if (width == 0 || height == 0)
        throw Error("render: size " + std::to_string(width) + "x" + std::to_string(height) +
                    " is empty");
    const auto start = std::chrono::steady_clock::now();
    vk::Frame& frame = r.frames->begin();
    Impl::Slot& slot = r.slots[frame.number % vk::FrameRing::kFramesInFlight];
    r.ensure_targets(width, height, frame.retired);

    const FrameUniforms uniforms =
        frame_uniforms(camera, settings, r.sun, float(width) / float(height));
    slot.uniforms.write(&uniforms, sizeof uniforms);
    r.record(frame, slot, uniforms, read_back);
    r.frames->submit(frame);

    FrameResult result;
    result.width = width;
    result.height = height;
    result.cpu_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    r.frames->wait(frame);
    r.read_back(slot, result, read_back);
    return result;
}

}  // namespace ds
