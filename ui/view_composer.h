#pragma once
// The viewer's image built from several read-backs: the shown resource (or a view derived
// from graph images, such as "<pass>_wasted"), decoded, with the visible overlays blended
// over it in list order, count images of one pass on one shared heat scale, and the legends
// that explain the colours. Vulkan-free: it asks the renderer for images through an
// InspectRequest list and works on the FrameResult that comes back.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "renderer/passes/frame_result.h"
#include "renderer/view/decode.h"

namespace ds::ui {

struct ViewerState;

// One legend the viewer draws: a heat scale and what shares it ("forward: counts,
// discarded, wasted"), a log scale (depth steps), or a Scalar image's colour bar (its
// Display's Heat palette: label = the Display's legend, else the image's name).
struct ViewLegend {
    std::string label;
    float black = 0, white = 1;  // the value's unit
    bool log = false;
    std::optional<graph::Display> display{};  // a colour bar (view::display_legend)
};

class ViewComposer {
  public:
    // Every image the viewer can show or overlay this frame, in list order: the frame's image
    // resources, each counting pass's derived "<pass>_wasted" after its last count image.
    static std::vector<std::string> viewable(std::span<const ResourceSummary> resources);
    // Whether `name` is a view derived here rather than a graph image.
    static bool derived(std::string_view name);
    // What the frame must read back: the shown resource, the visible overlays, what derived
    // views are made of and (shared scale) the other count images of their passes, each once.
    // `resources`: the last frame's (the names the next one will have).
    // The first is the shown image (or the first it is derived from).
    static std::vector<InspectRequest> request(const ViewerState& viewer,
                                               std::span<const ResourceSummary> resources);

    // After the frame: derives the views asked for and decodes the shown image into `out`
    // (on its pass's shared scale). Returns the shown image (none: not in this frame).
    const InspectedImage* decode_shown(const FrameResult& frame, const ViewerState& viewer,
                                       view::DecodedView& out);
    // Then blends the visible overlays over `out`, in order, and makes the legends.
    void stack_overlays(const FrameResult& frame, const ViewerState& viewer,
                        view::DecodedView& out);

    // An image of this frame by name: read back or derived; none when the frame lacks it.
    const InspectedImage* find(const FrameResult& frame, std::string_view name) const;
    const std::vector<ViewLegend>& legends() const { return legends_; }
    // Per overlay of the viewer's list: "" when drawn, else why not ("not in this frame",
    // "hidden", "size differs", "nothing shown under it").
    const std::vector<std::string>& overlay_status() const { return status_; }
    // The hover text of image `name` at (x, y): its decoded readout, and for a wasted view
    // the shaded and covered counts it came from. "" outside it.
    std::string text_at(const FrameResult& frame, std::string_view name, uint32_t x,
                        uint32_t y) const;

  private:
    // The shared count scale of `pass`: 0..max over its count images (or the viewer's manual
    // range when the shown image is the pass's and auto-fit is off).
    view::ViewParams count_params(const FrameResult& frame, const ViewerState& viewer,
                                  const std::string& pass) const;
    void derive(const FrameResult& frame, const ViewerState& viewer);
    void add_legend(const InspectedImage& image, const ViewerState& viewer,
                    const view::DecodedView& decoded);

    std::vector<InspectedImage> derived_;  // this frame's wasted views
    std::vector<ViewLegend> legends_;
    std::vector<std::string> legend_keys_;  // per legend: its pass (shared) or image name
    std::vector<std::string> status_;
    view::DecodedView scratch_;              // an overlay's colours, reused frame to frame
    std::optional<std::string> shown_pass_;  // the shown image's pass, when it is a count image
};

}  // namespace ds::ui
