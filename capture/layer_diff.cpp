#include "capture/layer_diff.h"

#include "capture/exr_file.h"
#include "capture/layer_capture_data.h"
#include "renderer/common/error.h"

namespace ds::capture {

namespace {

using nlohmann::json;

std::string layer_pass_shape(const json& p) {
    return p.value("name", "") + " " + std::to_string(p.value("width", 0)) + "x" +
           std::to_string(p.value("height", 0)) + " " + p.value("depth_format", "") + " x" +
           std::to_string(p.value("samples", 1)) + ", " + std::to_string(p.value("draws", 0)) +
           " draws";
}

void diff_layer_draw(const json& a, const json& b, const std::string& pass, LayerDiff& out) {
    const std::string name = pass + " / " + a.value("name", "?");
    bool differs = false;
    for (const char* key : {"name", "kind", "count", "instances", "not_analysed"})
        if (a.value(key, json()) != b.value(key, json())) {
            out.differences.push_back(name + ": " + key + " " + a.value(key, json()).dump() +
                                      " -> " + b.value(key, json()).dump());
            differs = true;
        }
    for (const char* key : {"shaded", "discarded", "rasterized", "samples_passed"}) {
        const int64_t va = a.value(key, int64_t(-1)), vb = b.value(key, int64_t(-1));
        if (va == vb) continue;
        out.differences.push_back(name + ": " + key + " " + std::to_string(va) + " -> " +
                                  std::to_string(vb) + " (" + (vb > va ? "+" : "") +
                                  std::to_string(vb - va) + ")");
        differs = true;
    }
    out.differing_draws += differs;
}

void diff_layer_images(const std::filesystem::path& da, const std::filesystem::path& db,
                       const json& pa, const json& pb, LayerDiff& out) {
    if (!pa.contains("images")) return;
    // Counts, or the EQUAL check's marks.
    const auto values = [](const ExrImage& e) {
        const ExrChannel* c = e.find("count");
        return c ? c : e.find("mark");
    };
    for (const auto& [kind, image] : pa.at("images").items()) {
        ++out.images;
        if (!pb.contains("images") || !pb.at("images").contains(kind)) {
            out.differences.push_back(pa.value("name", "") + " " + kind + ": only in the first");
            ++out.differing_images;
            continue;
        }
        const ExrImage a = read_exr(da / image.at("exr").get<std::string>());
        const ExrImage b = read_exr(db / pb.at("images").at(kind).at("exr").get<std::string>());
        const ExrChannel *ca = values(a), *cb = values(b);
        if (!ca || !cb || a.width != b.width || a.height != b.height) {
            out.differences.push_back(pa.value("name", "") + " " + kind + ": not comparable");
            ++out.differing_images;
            continue;
        }
        uint64_t differing = 0;
        for (size_t i = 0; i < ca->uints.size(); ++i) differing += ca->uints[i] != cb->uints[i];
        if (differing == 0) continue;
        out.differences.push_back(pa.value("name", "") + " " + kind + ": " +
                                  std::to_string(differing) + " pixels differ");
        ++out.differing_images;
    }
}

}  // namespace

LayerDiff diff_layer_captures(const std::filesystem::path& da, const std::filesystem::path& db) {
    const json a = read_layer_report(da), b = read_layer_report(db);
    LayerDiff out;
    const json &pa = a.at("passes"), &pb = b.at("passes");
    for (size_t i = 0; i < std::max(pa.size(), pb.size()); ++i) {
        const std::string sa = i < pa.size() ? layer_pass_shape(pa[i]) : "none";
        const std::string sb = i < pb.size() ? layer_pass_shape(pb[i]) : "none";
        if (sa != sb) {
            out.comparable = false;
            out.differences.push_back("pass " + std::to_string(i) + ": " + sa + " -> " + sb);
        }
    }
    if (!out.comparable) return out;
    const json &wa = a.at("draws"), &wb = b.at("draws");
    for (size_t i = 0; i < wa.size() && i < wb.size(); ++i) {
        const std::string pass = pa.at(wa[i].at("pass").get<size_t>()).value("name", "");
        diff_layer_draw(wa[i], wb[i], pass, out);
        ++out.draws;
    }
    for (size_t i = 0; i < pa.size(); ++i) diff_layer_images(da, db, pa[i], pb[i], out);
    return out;
}

json LayerDiff::to_json() const {
    return {{"same", same()},
            {"comparable", comparable},
            {"draws", draws},
            {"differing_draws", differing_draws},
            {"images", images},
            {"differing_images", differing_images},
            {"differences", differences}};
}

std::string layer_diff_summary(const LayerDiff& d, const std::string& a, const std::string& b) {
    std::string out;
    if (!d.comparable)
        out = "not comparable: " + a + " and " + b + " have different passes\n";
    else if (d.same())
        out = "same: " + std::to_string(d.draws) + " draws and " + std::to_string(d.images) +
              " count images equal\n";
    else
        out = "differs: " + std::to_string(d.differing_draws) + " of " + std::to_string(d.draws) +
              " draws, " + std::to_string(d.differing_images) + " of " + std::to_string(d.images) +
              " count images\n";
    for (size_t i = 0; i < d.differences.size() && i < 40; ++i)
        out += "  " + d.differences[i] + "\n";
    if (d.differences.size() > 40)
        out += "  … " + std::to_string(d.differences.size() - 40) + " more\n";
    return out;
}

}  // namespace ds::capture
