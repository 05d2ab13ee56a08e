#include "renderer/capture/tiler_json.h"

#include <string>
#include <vector>

namespace ds::capture {
namespace {

// The knobs that are on but do not run on the subpass path (passes/frame.cpp).
std::vector<std::string> turned_off(const Settings& s) {
    std::vector<std::string> out;
    for (const char* knob :
         {"gtao", "contact_shadows", "count_fragments", "count_draws", "count_discards",
          "equal_check", "surface_id", "zfight", "depth_precision", "hiz"})
        if (s.get_bool(knob)) out.push_back(knob);
    return out;
}

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
                          const Settings& settings) {
    const std::string path = settings.get("render_path");
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
            {"turned_off", turned_off(settings)}};
}

}  // namespace ds::capture
