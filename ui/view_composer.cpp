#include "ui/view_composer.h"

#include <algorithm>
#include <cstdio>

#include "renderer/view/overlay.h"
#include "renderer/view/readout.h"
#include "ui/inspector.h"

namespace ds::ui {
namespace {

using view::count_image;
using view::count_image_name;

constexpr const char* kFinal = "final";
constexpr const char* kDepth = "depth";  // the resolved scene depth: what covered_pixels counts

const ResourceSummary* resource(std::span<const ResourceSummary> resources, std::string_view name) {
    for (const ResourceSummary& r : resources)
        if (r.is_image && r.name == name) return &r;
    return nullptr;
}

// A pass gets a wasted view when it counts shaded fragments (a Count image) at the scene
// depth's size (a shadow map's counts have no scene pixel to be visible in).
bool wastable(std::span<const ResourceSummary> resources, const std::string& pass) {
    const ResourceSummary* shaded = resource(resources, count_image(pass, view::kShadedKind));
    const ResourceSummary* depth = resource(resources, kDepth);
    return shaded && depth && shaded->semantic == graph::Semantic::Count &&
           shaded->width == depth->width && shaded->height == depth->height;
}

bool same_pass(std::string_view image, const std::string& pass) {
    const auto name = count_image_name(image);
    return name && name->pass == pass;
}

}  // namespace

bool ViewComposer::derived(std::string_view name) {
    const auto c = count_image_name(name);
    return c && c->kind == view::kWastedKind;
}

std::vector<std::string> ViewComposer::viewable(std::span<const ResourceSummary> resources) {
    std::vector<std::string> out;
    for (size_t i = 0; i < resources.size(); ++i) {
        if (!resources[i].is_image) continue;
        out.push_back(resources[i].name);
        const auto c = count_image_name(resources[i].name);
        if (!c || !wastable(resources, c->pass)) continue;
        // After the pass's last count image.
        const bool last = std::none_of(
            resources.begin() + long(i) + 1, resources.end(),
            [&](const ResourceSummary& r) { return r.is_image && same_pass(r.name, c->pass); });
        if (last) out.push_back(count_image(c->pass, view::kWastedKind));
    }
    return out;
}

std::vector<InspectRequest> ViewComposer::request(const ViewerState& viewer,
                                                  std::span<const ResourceSummary> resources) {
    std::vector<std::string> names;
    auto push = [&](const std::string& name) {
        if (!name.empty() && std::find(names.begin(), names.end(), name) == names.end())
            names.push_back(name);
    };
    auto expand = [&](const std::string& name) {
        const auto c = count_image_name(name);
        if (derived(name)) {
            push(count_image(c->pass, view::kShadedKind));
            push(kDepth);
        } else {
            push(name);
        }
        if (!c || !viewer.shared_count_scale) return;
        for (const ResourceSummary& r : resources)  // the rest of the pass's scale
            if (r.is_image && same_pass(r.name, c->pass)) push(r.name);
    };
    expand(viewer.resource);
    for (const Overlay& o : viewer.overlays)
        if (o.visible) expand(o.resource);

    std::vector<InspectRequest> request;
    for (const std::string& name : names)  // "final" is read back only as the first
        if (request.empty() || name != kFinal)
            request.push_back({name, name == viewer.resource ? viewer.sample : 0});
    return request;
}

const InspectedImage* ViewComposer::find(const FrameResult& frame, std::string_view name) const {
    if (const InspectedImage* image = frame.image(name)) return image;
    for (const InspectedImage& image : derived_)
        if (image.name == name) return &image;
    return nullptr;
}

void ViewComposer::derive(const FrameResult& frame, const ViewerState& viewer) {
    derived_.clear();
    std::vector<std::string> wanted{viewer.resource};
    for (const Overlay& o : viewer.overlays)
        if (o.visible) wanted.push_back(o.resource);
    for (const std::string& name : wanted) {
        if (!derived(name) || find(frame, name)) continue;
        const InspectedImage* shaded =
            find(frame, count_image(count_image_name(name)->pass, view::kShadedKind));
        const InspectedImage* depth = find(frame, kDepth);
        if (!shaded || !depth) continue;
        if (auto wasted = view::wasted_image(*shaded, *depth))
            derived_.push_back(std::move(*wasted));
    }
}

view::ViewParams ViewComposer::count_params(const FrameResult& frame, const ViewerState& viewer,
                                            const std::string& pass) const {
    view::ViewParams p;
    p.auto_fit = false;
    if (shown_pass_ == pass && !viewer.params.auto_fit) {  // the user's range, for all of them
        p.black = viewer.params.black;
        p.white = viewer.params.white;
        return p;
    }
    std::vector<const InspectedImage*> images;
    auto add = [&](const InspectedImage& image) {
        if (image.semantic == graph::Semantic::Count && same_pass(image.name, pass))
            images.push_back(&image);
    };
    if (frame.inspected) add(*frame.inspected);
    for (const InspectedImage& image : frame.overlays) add(image);
    for (const InspectedImage& image : derived_) add(image);
    const float top = view::count_max(images);
    p.black = 0.0f;
    p.white = top > 0.0f ? top : 1.0f;  // as decode's auto-fit: nothing counted shows black
    return p;
}

const InspectedImage* ViewComposer::decode_shown(const FrameResult& frame,
                                                 const ViewerState& viewer,
                                                 view::DecodedView& out) {
    derive(frame, viewer);
    legends_.clear();
    legend_keys_.clear();
    shown_pass_.reset();
    const InspectedImage* shown = find(frame, viewer.resource);
    if (!shown) {
        out = view::DecodedView{};
        return nullptr;
    }
    const auto c = count_image_name(shown->name);
    if (c && shown->semantic == graph::Semantic::Count) shown_pass_ = c->pass;
    view::ViewParams params = viewer.params;
    if (shown_pass_ && viewer.params.auto_fit && viewer.shared_count_scale)
        params = count_params(frame, viewer, *shown_pass_);
    view::decode_into(*shown, params, out);
    add_legend(*shown, viewer, out);
    return shown;
}

void ViewComposer::stack_overlays(const FrameResult& frame, const ViewerState& viewer,
                                  view::DecodedView& out) {
    status_.assign(viewer.overlays.size(), "");
    for (size_t i = 0; i < viewer.overlays.size(); ++i) {
        const Overlay& o = viewer.overlays[i];
        const InspectedImage* image = o.visible ? find(frame, o.resource) : nullptr;
        if (!image) {
            status_[i] = o.visible ? "not in this frame" : "hidden";
            continue;
        }
        // Counts on their pass's shared scale (or their own); anything else as the viewer
        // would show it at first: auto-fit.
        view::ViewParams params;
        const auto c = count_image_name(image->name);
        if (c && image->semantic == graph::Semantic::Count && viewer.shared_count_scale)
            params = count_params(frame, viewer, c->pass);
        view::decode_into(*image, params, scratch_);
        if (!view::blend_overlay(out, scratch_, *image, o.opacity)) {
            status_[i] = out.width ? "size differs" : "nothing shown under it";
            continue;
        }
        add_legend(*image, viewer, scratch_);
    }
}

// One legend per scale: a pass's count images share one when the scale is shared; a Scalar
// image has one (a colour bar) when its Display asks for the heat map.
void ViewComposer::add_legend(const InspectedImage& image, const ViewerState& viewer,
                              const view::DecodedView& decoded) {
    if (image.semantic == graph::Semantic::Scalar) {
        if (image.display.palette != graph::Palette::Heat) return;
        if (std::find(legend_keys_.begin(), legend_keys_.end(), image.name) != legend_keys_.end())
            return;
        legend_keys_.push_back(image.name);
        const std::string& title = image.display.legend;
        legends_.push_back({title.empty() ? image.name : title, decoded.black, decoded.white, false,
                            image.display});
        return;
    }
    const bool log = image.semantic == graph::Semantic::DepthStep;
    if (image.semantic != graph::Semantic::Count && !log) return;
    const auto c = count_image_name(image.name);
    const bool shared = c && !log && viewer.shared_count_scale;
    const std::string key = shared ? c->pass : image.name;
    const std::string what = shared ? c->kind : image.name;
    for (size_t i = 0; i < legend_keys_.size(); ++i) {
        if (legend_keys_[i] != key) continue;
        legends_[i].label += ", " + what;
        return;
    }
    legend_keys_.push_back(key);
    legends_.push_back({shared ? c->pass + ": " + what : what, decoded.black, decoded.white, log});
}

std::string ViewComposer::text_at(const FrameResult& frame, std::string_view name, uint32_t x,
                                  uint32_t y) const {
    const InspectedImage* image = find(frame, name);
    const auto r = image ? view::readout(*image, x, y) : std::nullopt;
    if (!r) return {};
    if (!derived(name)) return r->decoded_text;
    // A wasted view says what it was made of.
    const InspectedImage* shaded =
        find(frame, count_image(count_image_name(name)->pass, view::kShadedKind));
    const InspectedImage* depth = find(frame, kDepth);
    const auto s = shaded ? view::readout(*shaded, x, y) : std::nullopt;
    const auto d = depth ? view::readout(*depth, x, y) : std::nullopt;
    if (!s || !d) return r->decoded_text;
    char text[96];
    std::snprintf(text, sizeof text, "shaded %.0f, covered %d, wasted %.0f", double(s->raw[0]),
                  d->sky ? 0 : 1, double(r->raw[0]));
    return text;
}

}  // namespace ds::ui
