#include "capture/resource_capture.h"

#include <algorithm>
#include <map>

#include "capture/resource_files.h"
#include "renderer/common/error.h"
#include "renderer/common/quoted.h"
#include "renderer/passes/inspect.h"

namespace ds::capture {
namespace {

bool is_inspect_target(const std::string& name) {
    return name.rfind("inspect_texels", 0) == 0;
}

// The frame's images that the selection names, in the frame's order.
std::vector<const ResourceSummary*> selected_images(const FrameResult& frame,
                                                    const ResourceSelection& selection) {
    std::vector<const ResourceSummary*> images;
    for (const ResourceSummary& r : frame.resources)
        if (r.is_image && !is_inspect_target(r.name)) images.push_back(&r);
    if (selection.all) return images;
    std::vector<const ResourceSummary*> chosen;
    for (const std::string& name : selection.names) {
        const auto it = std::find_if(images.begin(), images.end(),
                                     [&](const ResourceSummary* r) { return r->name == name; });
        if (it == images.end()) {
            std::string names;
            for (const ResourceSummary* r : images) names += (names.empty() ? "" : ", ") + r->name;
            throw UsageError("--resources " + quote(name) + ": this frame has no such image (" +
                             names + ")");
        }
        if (std::find(chosen.begin(), chosen.end(), *it) == chosen.end()) chosen.push_back(*it);
    }
    std::sort(chosen.begin(), chosen.end());  // frame order: pointers into frame.resources
    return chosen;
}

}  // namespace

ResourceSelection parse_resource_selection(const std::string& text) {
    if (text == "all") return {};
    if (text == "none") return {false, {}};
    ResourceSelection selection{false, {}};
    size_t start = 0;
    for (;;) {
        const size_t comma = text.find(',', start);
        const std::string name = text.substr(start, comma - start);
        if (name.empty())
            throw UsageError("--resources " + quote(text) +
                             ": expected all, none or NAME,NAME,… without empty names");
        selection.names.push_back(name);
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return selection;
}

nlohmann::json capture_resources(const FrameResult& frame, const ResourceSelection& selection,
                                 const RenderInspected& render,
                                 const std::filesystem::path& resources_dir) {
    const std::vector<const ResourceSummary*> images = selected_images(frame, selection);
    nlohmann::json entries = nlohmann::json::array();
    if (images.empty()) return entries;
    std::error_code ec;
    std::filesystem::create_directory(resources_dir, ec);
    if (ec) throw Error(escaped(resources_dir.string()) + ": cannot create: " + ec.message());

    // Every sample of every image, in order; batches of what one frame reads.
    std::vector<InspectRequest> requests;
    for (const ResourceSummary* r : images)
        for (uint32_t s = 0; s < std::max(r->samples, 1u); ++s) requests.push_back({r->name, s});
    // "final" is read back only as a frame's first request (Renderer::render).
    std::stable_partition(requests.begin(), requests.end(),
                          [](const InspectRequest& q) { return q.resource == "final"; });
    // Read images wait here until their last sample comes, then are written and let go.
    std::map<std::string, std::vector<InspectedImage>> read;
    size_t written = 0;
    const size_t batch = passes::InspectPass::kMaxImages;
    for (size_t first = 0; first < requests.size(); first += batch) {
        const size_t count = std::min(batch, requests.size() - first);
        FrameResult again = render(std::span(requests).subspan(first, count));
        if (again.rgba8 != frame.rgba8)
            throw Error(
                "capture: the frame rendered again to read its images differs from "
                "final.png: this device does not render the same frame twice");
        if (again.inspected) read[again.inspected->name].push_back(std::move(*again.inspected));
        for (InspectedImage& image : again.overlays) read[image.name].push_back(std::move(image));
        const bool last = first + count == requests.size();
        for (; written < images.size(); ++written) {
            const ResourceSummary& r = *images[written];
            std::vector<InspectedImage>& samples = read[r.name];
            if (samples.size() < std::max(r.samples, 1u) && !last) break;
            if (samples.size() != std::max(r.samples, 1u))
                throw Error("capture: " + r.name + ": read " + std::to_string(samples.size()) +
                            " of its " + std::to_string(r.samples) + " samples");
            entries.push_back(write_resource_files(resources_dir, r, samples));
            read.erase(r.name);
        }
    }
    return entries;
}

}  // namespace ds::capture
