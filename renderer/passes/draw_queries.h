#pragma once
// count_draws' samples_passed: one precise occlusion query around each draw of the pass that
// decides visibility (the prepass, else forward), remembered with its draw group, so a group
// the sorted prepass draws one instance at a time sums its instances' queries. Not a pass: the
// pass owns one, enables it in add(), resets it before its rendering, hands it to
// draw_groups / draw_sorted and reads it in collect(). Renderer::render waits for each frame
// before the next one is recorded (as HostReadback relies on), so one pool per pass suffices.
#include <cstdint>
#include <optional>
#include <vector>

#include <vulkan/vulkan.h>

#include "renderer/vk/query.h"

namespace ds::vk {
class Context;
}

namespace ds::passes {

class DrawQueries {
  public:
    explicit DrawQueries(vk::Context& context) : context_(context) {}

    // This frame's: off, or on with room for `max_draws` draws (the pool grows, never
    // shrinks: a pass that stops counting keeps it for the next time).
    void begin_frame(bool on, uint32_t max_draws);
    bool on() const { return on_; }
    // Outside the rendering, before the first draw.
    void reset(VkCommandBuffer cmd);
    // Around one draw of scene draw group `group`.
    void begin(VkCommandBuffer cmd, uint32_t group);
    void end(VkCommandBuffer cmd);
    // After the fence: per draw group (of `groups`), the samples its draws passed; none for a
    // group the pass did not draw. Empty when off.
    std::vector<std::optional<uint64_t>> per_group(size_t groups) const;

  private:
    vk::Context& context_;
    vk::OcclusionPool pool_;
    bool on_ = false;
    uint32_t capacity_ = 0;              // what reset() clears this frame
    std::vector<uint32_t> slot_groups_;  // per query, in recording order
};

}  // namespace ds::passes
