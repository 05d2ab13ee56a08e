#include "capture/tiler_json.h"

#include <string>
#include <vector>

#include "renderer/settings/frame_knobs.h"

namespace ds::capture {
namespace {

nlohmann::json attachment_json(const graph::TilerAttachment& a) {
    nlohmann::json j = {{"resource", a.name}, {"format", a.format},      {"role", a.role},
                        {"bits", a.bits},     {"samples", a.samples},    {"load", a.load},
                        {"store", a.store},   {"transient", a.transient}};
    if (a.transient)
        j["memory"] = a.lazily_allocated
                          ? "lazily allocated"
                          : "device-local (the device has no lazily allocated memory type)";
    return j;
}

}  // namespace

nlohmann::json tiler_json(const std::optional<graph::TilerReport>& tiler,
                          const std::vector<std::string>& turned_off, const Settings& settings) {
    const std::string& path = knob_value(settings, knobs::kRenderPath);
    if (!tiler)
        return {{"render_path", path},
                {"ran", "dynamic"},
                {"note", path == "subpass" ? "render_path=subpass needs the prepass (prepass=off)"
                                           : "no subpass group: render_path=subpass plans one"}};
    const graph::TilerReport& t = *tiler;
    nlohmann::json attachments = nlohmann::json::array(), conditions = nlohmann::json::array();
    for (const graph::TilerAttachment& a : t.attachments) attachments.push_back(attachment_json(a));
    for (const graph::TilerCondition& c : t.conditions)
        conditions.push_back({{"condition", c.name}, {"ok", c.ok}, {"detail", c.detail}});
    return {{"render_path", path},
            {"ran", "subpass"},
            {"render_pass", t.group},
            {"subpasses", t.subpasses},
            {"attachments", attachments},
            {"bits_per_pixel", t.bits_per_pixel},
            {"samples", t.samples},
            {"tile_bits_per_pixel", t.tile_bits_per_pixel},
            {"fits_128_bits", t.fits_128},
            {"fits_256_bits", t.fits_256},
            {"merge_conditions", conditions},
            {"mergeable", t.mergeable},
            {"verdict", t.verdict},
            {"screen_space",
             "gtao and contact_shadows read neighbours, which tile memory cannot give: off on this "
             "path"},
            {"turned_off", turned_off}};
}

}  // namespace ds::capture
