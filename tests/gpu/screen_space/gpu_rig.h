#pragma once
// A real device (the first suitable one: lavapipe here) with validation on, the shader
// compiler, a frame set shaped like the renderer's (set 0, FrameUniforms at binding 0, visible
// to compute) and the synthetic prepass output as imported images: what the screen-space
// passes need to run through a real render graph, frame after frame, and be read back.
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "renderer/graph/graph.h"
#include "renderer/passes/frame.h"
#include "renderer/readback/host_readback.h"
#include "renderer/shader/compiler.h"
#include "renderer/vk/buffer.h"
#include "renderer/vk/context.h"
#include "renderer/vk/descriptors.h"
#include "renderer/vk/destroy_list.h"
#include "renderer/vk/image.h"
#include "tests/gpu/screen_space/synthetic_scene.h"

namespace ds::test {

// The first channel (and the second, for formats with two or more) of a read-back image.
struct HostImage {
    uint32_t width = 0, height = 0;
    std::vector<float> r, g;
    float at(uint32_t x, uint32_t y) const { return r[size_t(y) * width + x]; }
    float g_at(uint32_t x, uint32_t y) const { return g[size_t(y) * width + x]; }
};

// The full-resolution pixel a reduced-resolution AO texel stands for (ao_source_pixel in
// screen_space.glsl) and the octahedral encoding of a unit vector (oct_encode there).
glm::ivec2 ao_source_pixel(glm::ivec2 q, glm::ivec2 size, glm::ivec2 full);
glm::vec2 oct_encode(glm::vec3 n);

// 8-bit grayscale PNG of the first channel (to look at).
void write_png(const std::string& path, const HostImage& image);

struct FrameOutput {
    std::map<std::string, HostImage> images;  // by graph resource name
    std::vector<graph::PassResult> passes;    // GPU time per pass
};

class GpuRig {
  public:
    using Declare = std::function<void(graph::RenderGraph&, const passes::FrameInputs&,
                                       passes::FrameResources&)>;

    static GpuRig& get();  // one device per test process

    vk::Context& context() { return *context_; }
    passes::PassServices services();

    // The prepass images and uniforms the next frames read.
    void upload(const SyntheticFrame& frame);
    void set_uniforms(const passes::FrameUniforms& uniforms);
    // For feeding a pass a known input in place of the previous pass's output: a sampled
    // R16G16B16A16_SFLOAT image packed as gtao writes ao_raw (and ao_spatial ao_filtered): `values`
    // (row-major, width x height) as AO, with the view distance and the octahedral view normal of
    // the pixel of `frame` each texel stands for (sky: 1, 0, 0, 0).
    vk::Image make_packed_ao(const SyntheticFrame& frame, uint32_t width, uint32_t height,
                             const std::vector<float>& values);
    // Such an image imported into `graph` as `name` (semantic AO), ready to sample.
    graph::ImageHandle import_input(graph::RenderGraph& graph, const std::string& name,
                                    const vk::Image& image) const;

    // One frame: imports the inputs, runs `declare` (the passes under test), copies every
    // image named in `read_back` to the host, submits and waits.
    FrameOutput run_frame(graph::RenderGraph& graph, const Declare& declare,
                          const std::vector<std::string>& read_back,
                          const passes::FrameOptions& options = {});

  private:
    GpuRig();
    void write_uniforms();
    std::vector<graph::ImageHandle> add_read_back(graph::RenderGraph& graph,
                                                  const std::vector<std::string>& names);

    std::unique_ptr<vk::Context> context_;
    std::unique_ptr<shader::Compiler> compiler_;
    std::unique_ptr<HostReadback> readback_;  // run_frame's read-back (and PassServices')
    vk::DescriptorSetLayout frame_layout_;
    vk::DescriptorPool frame_pool_;
    VkDescriptorSet frame_set_ = VK_NULL_HANDLE;
    vk::Buffer uniform_buffer_;
    passes::FrameUniforms uniforms_;
    vk::Image depth_, normals_;
    bool reverse_z_ = true;
    uint64_t frame_number_ = 0;
    vk::DestroyList retired_;
};

}  // namespace ds::test
