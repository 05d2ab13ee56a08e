#include "capture/layer_capture.h"

#include <algorithm>
#include <fstream>
#include <map>

#include <vulkan/vulkan.h>

#include "capture/exr_file.h"
#include "capture/file_output.h"
#include "capture/image_writer.h"
#include "capture/layer_capture_data.h"
#include "capture/layer_depth_report.h"
#include "capture/resource_files.h"
#include "renderer/common/error.h"
#include "renderer/common/version.h"
#include "renderer/format/format.h"

namespace ds::capture {

namespace {

using nlohmann::json;

std::vector<uint32_t> read_layer_pixels(const std::filesystem::path& file, size_t words) {
    std::vector<uint32_t> out(words);
    std::ifstream in(file, std::ios::binary);
    in.read(reinterpret_cast<char*>(out.data()), std::streamsize(words * 4));
    if (size_t(in.gcount()) != words * 4) throw Error(file.string() + ": truncated");
    return out;
}

// One count image of a pass (component of 4-word pixels).
json write_layer_count_image(const std::filesystem::path& dir, const std::string& stem,
                             uint32_t width, uint32_t height, const std::vector<uint32_t>& px,
                             uint32_t component) {
    std::vector<uint32_t> counts(size_t(width) * height);
    for (size_t i = 0; i < counts.size(); ++i) counts[i] = px[i * 4 + component];
    return write_layer_image(dir, stem, width, height, counts);
}

std::string layer_pass_name(const json& pass) {
    const std::string label = pass.value("label", "");
    if (!label.empty()) return label;
    return "pass" + std::to_string(pass.at("index").get<int>());
}

json layer_pass_entry(const std::filesystem::path& layer_dir, const std::filesystem::path& out_dir,
                      const json& pass, std::map<std::string, int>& stems) {
    json entry = pass;
    entry["name"] = layer_pass_name(pass);
    const int fmt = pass.at("depth_format").get<int>();
    entry["depth_format"] = fmt ? format::name(VkFormat(fmt)) : "none";
    entry.erase("pixels");
    if (!pass.contains("pixels")) return entry;
    std::string stem = file_stem(entry["name"].get<std::string>());
    if (stems[stem]++ > 0) stem += "_" + std::to_string(pass.at("index").get<int>());
    const json& px = pass.at("pixels");
    const uint32_t w = px.at("width"), h = px.at("height");
    const auto pixels =
        read_layer_pixels(layer_dir / px.at("file").get<std::string>(), size_t(w) * h * 4);
    const std::filesystem::path dir = out_dir / "resources";
    std::filesystem::create_directories(dir);
    entry["images"] = {
        {"shaded", write_layer_count_image(dir, stem + "_shaded", w, h, pixels, 0)},
        {"discarded", write_layer_count_image(dir, stem + "_discarded", w, h, pixels, 1)},
        {"rasterized", write_layer_count_image(dir, stem + "_rasterized", w, h, pixels, 2)}};
    // The Z-fight competitors and the EQUAL check's marks (zfight, equal_check).
    for (const auto& [key, marks] : {std::pair{"zfight", false}, std::pair{"equal_check", true}}) {
        if (!pass.contains(key)) continue;
        const std::string file = pass.at(key).at("file");
        entry[key].erase("file");
        entry["images"][key] = write_layer_image(
            dir, stem + "_" + key, w, h, read_layer_pixels(layer_dir / file, size_t(w) * h), marks);
    }
    return entry;
}

}  // namespace

json write_layer_image(const std::filesystem::path& dir, const std::string& stem, uint32_t width,
                       uint32_t height, const std::vector<uint32_t>& values, bool marks) {
    const uint32_t max = values.empty() ? 0 : *std::max_element(values.begin(), values.end());
    uint64_t total = 0;
    for (uint32_t v : values) total += v;
    write_png_rgba8(dir / (stem + ".png"), width, height,
                    marks ? marks_rgba(values) : count_heat_rgba(values, max));
    ExrImage exr{width, height, {}};
    exr.channels.push_back({marks ? "mark" : "count", true, {}, values});
    write_exr(dir / (stem + ".exr"), exr);
    return {{"png", "resources/" + stem + ".png"},
            {"exr", "resources/" + stem + ".exr"},
            {"max", max},
            {"total", total}};
}

std::string layer_draw_name(const json& draw, const std::string& pass,
                            const std::string& pipeline) {
    const auto& labels = draw.at("labels");
    if (!labels.empty() && labels.back().get<std::string>() != pass)
        return labels.back().get<std::string>();
    return pass + " draw " + std::to_string(draw.at("index_in_pass").get<int>()) + " (" + pipeline +
           ")";
}

json write_layer_capture(const std::filesystem::path& layer_dir,
                         const std::filesystem::path& out_dir,
                         const std::vector<std::string>& command) {
    const json raw = read_json_file(layer_dir / "capture.json");
    json report = {{"tool", "depthscope"}, {"version", ds::version()}, {"source", "layer"}};
    for (const char* key : {"device", "application", "frame", "delimiter", "submissions",
                            "counter_set", "cost", "pipelines", "not_analysed"})
        report[key] = raw.at(key);
    report["command"] = command;
    std::map<std::string, int> stems;  // pass name -> how many passes had it
    json passes = json::array();
    for (const json& p : raw.at("passes"))
        passes.push_back(layer_pass_entry(layer_dir, out_dir, p, stems));
    json draws = json::array();
    std::map<std::string, int> ordinals;
    for (json d : raw.at("draws")) {
        // Unnamed pipelines by their order of first use: handles differ from run to run.
        const std::string handle = d.at("pipeline");
        if (!ordinals.count(handle)) ordinals[handle] = int(ordinals.size()) + 1;
        std::string pipeline = "pipeline " + std::to_string(ordinals[handle]);
        for (const json& p : raw.at("pipelines"))
            if (p.at("handle") == handle && !p.at("name").get<std::string>().empty())
                pipeline = p.at("name");
        d["name"] = layer_draw_name(d, passes.at(d.at("pass").get<size_t>()).at("name"), pipeline);
        draws.push_back(std::move(d));
    }
    report["passes"] = passes;
    report["draws"] = draws;
    report["settings"] = raw.at("settings");
    add_layer_depth_sections(report);
    // The instrumented fragment shaders, as the device ran them (spirv-val, spirv-dis).
    if (std::filesystem::exists(layer_dir / "shaders"))
        std::filesystem::copy(layer_dir / "shaders", out_dir / "shaders",
                              std::filesystem::copy_options::recursive);
    write_new_file(out_dir / "report.json", report.dump(2) + "\n");
    return report;
}

}  // namespace ds::capture
