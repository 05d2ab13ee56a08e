#include "layer/capture_output.h"

#include <cinttypes>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

namespace ds::layer {

namespace {

using nlohmann::json;

std::string hex(uint64_t v) {
    char text[24];
    std::snprintf(text, sizeof text, "0x%" PRIx64, v);
    return text;
}

const char* draw_kind(DrawKind k) {
    switch (k) {
        case DrawKind::Draw: return "draw";
        case DrawKind::Indexed: return "indexed";
        case DrawKind::Indirect: return "indirect";
        case DrawKind::IndexedIndirect: return "indexed_indirect";
        case DrawKind::IndirectCount: return "indirect_count";
        case DrawKind::IndexedIndirectCount: return "indexed_indirect_count";
    }
    return "draw";
}

// A per-pixel image of a pass: 4-byte words, row-major.
std::string write_words(const std::filesystem::path& out, const std::string& file,
                        const std::vector<uint32_t>& words) {
    std::ofstream(out / file, std::ios::binary)
        .write(reinterpret_cast<const char*>(words.data()), std::streamsize(words.size() * 4));
    return file;
}

json draw_instance_json(const DrawInstance& d) {
    json j = {{"draw", d.draw}};
    if (d.instance != UINT32_MAX) j["instance"] = d.instance;
    return j;
}

json zfight_json(const DepthPassAnalysis& z, const std::filesystem::path& out, size_t pass) {
    json pairs = json::array();
    for (const DepthPair& p : z.pairs)
        pairs.push_back({{"a", draw_instance_json(p.a)},
                         {"b", draw_instance_json(p.b)},
                         {"pixels", p.pixels},
                         {"min_steps", p.min_steps}});
    return {{"pixels", z.pixels},
            {"pairs", pairs},
            {"records", z.records},
            {"dropped_records", z.dropped},
            {"file", write_words(out, "passes/" + std::to_string(pass) + ".zfight.bin",
                                 z.competitors)}};
}

json equal_json(const EqualCheckResult& e, const std::filesystem::path& out, size_t pass) {
    json surfaces = json::array();
    for (const auto& [who, counts] : e.by_winner) {
        json j = draw_instance_json(who);
        j["holes"] = counts.first;
        j["multiple"] = counts.second;
        surfaces.push_back(j);
    }
    return {{"prepass", e.prepass},
            {"holes", e.holes},
            {"multiple", e.multiple},
            {"surfaces", surfaces},
            {"file", write_words(out, "passes/" + std::to_string(pass) + ".equal.bin", e.marks)}};
}

json passes_json(const FrameCapture& fc, const std::filesystem::path& out) {
    json passes = json::array();
    std::filesystem::create_directories(out / "passes");
    for (size_t i = 0; i < fc.passes.size(); ++i) {
        const CapturedPass& p = fc.passes[i];
        const PassSummary& s = p.summary;
        json j = {{"index", i},           {"submission", p.submission}, {"dynamic", s.dynamic},
                  {"subpass", s.subpass}, {"label", s.label},           {"x", s.x},
                  {"y", s.y},             {"width", s.width},           {"height", s.height},
                  {"depth_format", int(s.depth_format)}, {"samples", s.samples},
                  {"draws", s.draws},     {"counted", p.counted}};
        if (p.counted) {
            const std::string file = "passes/" + std::to_string(i) + ".bin";
            std::ofstream(out / file, std::ios::binary)
                .write(reinterpret_cast<const char*>(p.pixels.data()),
                       std::streamsize(p.pixels.size() * 4));
            j["pixels"] = {{"file", file}, {"width", p.pixel_width}, {"height", p.pixel_height}};
        }
        if (p.zfight) j["zfight"] = zfight_json(*p.zfight, out, i);
        if (p.equal) j["equal_check"] = equal_json(*p.equal, out, i);
        passes.push_back(j);
    }
    return passes;
}

json draws_json(const FrameCapture& fc) {
    json draws = json::array();
    for (const CapturedDrawResult& r : fc.draws) {
        const CapturedDraw& d = r.draw;
        json j = {{"pass", d.pass},
                  {"index_in_pass", d.index_in_pass},
                  {"labels", d.labels},
                  {"pipeline", hex(uint64_t(d.pipeline))},
                  {"kind", draw_kind(d.args.kind)},
                  {"count", d.args.count},
                  {"instances", d.args.instances}};
        j["depth"] = {{"test", d.depth.test},
                      {"write", d.depth.write},
                      {"compare_op", int(d.depth.op)}};
        if (d.depth_recorded) j["depth_recorded"] = true;
        if (d.equal_counted) j["equal_prepass"] = d.equal_prepass;
        if (!d.depth_why.empty()) j["depth_not_analysed"] = d.depth_why;
        if (d.not_analysed.empty()) {
            j["shaded"] = r.counts.shaded;
            j["discarded"] = r.counts.discarded;
            j["rasterized"] = r.counts.rasterized;
            j["samples_passed"] = r.samples_passed;
        } else {
            j["not_analysed"] = d.not_analysed;
        }
        draws.push_back(j);
    }
    return draws;
}

json pipelines_json(const FrameCapture& fc, const std::filesystem::path& out) {
    json pipelines = json::array();
    std::filesystem::create_directories(out / "shaders");
    for (const auto& [app, p] : fc.pipelines.all()) {
        json j = {{"handle", hex(uint64_t(app))},
                  {"name", p.name},
                  {"fragment_shader", p.has_fragment},
                  {"early_z", p.early_z},
                  {"early_fragment_tests_added", p.early_tests_added},
                  {"discard_sites", p.discard_sites}};
        if (!p.why.empty()) j["not_analysed"] = p.why;
        if (!p.depth_record_why.empty()) j["depth_record_not_analysed"] = p.depth_record_why;
        if (!p.equal_why.empty()) j["equal_not_analysed"] = p.equal_why;
        if (p.depth_record) j["instance_known"] = p.instance_known;
        if (!p.survival_spirv.empty())
            j["survival_spirv"] = write_words(out, "shaders/" + hex(uint64_t(app)) + ".survival.spv",
                                              p.survival_spirv);
        if (!p.instrumented.empty()) {
            const std::string file = "shaders/" + hex(uint64_t(app)) + ".spv";
            std::ofstream(out / file, std::ios::binary)
                .write(reinterpret_cast<const char*>(p.instrumented.data()),
                       std::streamsize(p.instrumented.size() * 4));
            j["instrumented_spirv"] = file;
        }
        if (!p.measure_spirv.empty()) {
            const std::string file = "shaders/" + hex(uint64_t(app)) + ".measure.spv";
            std::ofstream(out / file, std::ios::binary)
                .write(reinterpret_cast<const char*>(p.measure_spirv.data()),
                       std::streamsize(p.measure_spirv.size() * 4));
            j["measurement_spirv"] = file;
        }
        pipelines.push_back(j);
    }
    return pipelines;
}

}  // namespace

void write_capture(DeviceData& d, const FrameCapture& fc, const std::string& out_dir) {
    const std::filesystem::path out = out_dir;
    const VkPhysicalDeviceProperties& p = d.properties;
    json report = {
        {"device",
         {{"name", p.deviceName},
          {"vendor_id", p.vendorID},
          {"device_id", p.deviceID},
          {"driver_version", p.driverVersion},
          {"api_version", std::to_string(VK_API_VERSION_MAJOR(p.apiVersion)) + "." +
                              std::to_string(VK_API_VERSION_MINOR(p.apiVersion)) + "." +
                              std::to_string(VK_API_VERSION_PATCH(p.apiVersion))}}},
        {"application", d.instance ? d.instance->application : ""},
        {"frame", config().frame},
        {"delimiter", process().presenting ? "present" : "submission"},
        {"submissions", fc.submissions},
        {"counter_set", d.counter_set},
        {"settings",
         {{"zfight", config().settings.zfight},
          {"zfight_steps", config().settings.zfight_steps},
          {"equal_check", config().settings.equal_check}}},
        {"cost",
         {{"capture_ms", fc.capture_ms},
          {"pipeline_build_ms", fc.pipelines.build_ms()},
          {"pipelines_built", fc.pipelines.all().size()},
          {"counter_bytes", fc.counter_bytes},
          {"depth_record_bytes", fc.depth_record_bytes},
          // The application's pipeline and shader module creation so far: in the layers
          // below, and with this layer's copies of their recipes (not armed: no counting copy).
          {"creation_ms_below", double(d.creation_next_ns) / 1e6},
          {"creation_ms_with_layer", double(d.creation_total_ns) / 1e6}}},
        {"passes", passes_json(fc, out)},
        {"draws", draws_json(fc)},
        {"pipelines", pipelines_json(fc, out)},
        {"not_analysed", fc.not_analysed}};
    // capture.json last: its presence says the rest is complete.
    const auto tmp = out / "capture.json.partial";
    std::ofstream(tmp) << report.dump(1) << "\n";
    std::filesystem::rename(tmp, out / "capture.json");
}

}  // namespace ds::layer
