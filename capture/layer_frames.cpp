#include "capture/layer_frames.h"

#include <fstream>

#include <vulkan/vulkan.h>

#include <nlohmann/json.hpp>

#include "renderer/common/error.h"
#include "renderer/format/format.h"

namespace ds::capture {

namespace {

LayerFrame parse_layer_frame(const nlohmann::json& j) {
    LayerFrame f;
    f.number = j.at("frame").get<uint64_t>();
    f.by_present = j.at("delimiter").get<std::string>() == "present";
    f.presented = j.at("presented").get<bool>();
    f.submissions = j.at("submissions").get<uint32_t>();
    for (const auto& p : j.at("passes"))
        f.passes.push_back({p.at("dynamic").get<bool>(), p.at("subpass").get<uint32_t>(),
                            p.at("label").get<std::string>(), p.at("width").get<uint32_t>(),
                            p.at("height").get<uint32_t>(), p.at("depth_format").get<int>(),
                            p.at("samples").get<uint32_t>(), p.at("draws").get<uint32_t>()});
    return f;
}

std::string layer_plural(uint64_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

std::string layer_pass_line(const LayerPass& p) {
    std::string line = "  " + std::string(p.dynamic ? "dynamic rendering" : "render pass");
    if (!p.dynamic && p.subpass > 0) line += " subpass " + std::to_string(p.subpass);
    if (!p.label.empty()) line += " \"" + p.label + "\"";
    line += " " + std::to_string(p.width) + "x" + std::to_string(p.height);
    line += p.depth_format ? " depth " + format::name(VkFormat(p.depth_format)) : " no depth";
    if (p.samples > 1) line += " x" + std::to_string(p.samples);
    return line + ": " + layer_plural(p.draws, "draw", "draws");
}

std::string layer_frame_head(const LayerFrame& first, const LayerFrame& last) {
    const char* unit = first.by_present ? "frame" : "submission";
    std::string head = std::string(unit) + " " + std::to_string(first.number);
    if (last.number != first.number)
        head = std::string(unit) + "s " + std::to_string(first.number) + "-" +
               std::to_string(last.number) + " (each)";
    uint32_t draws = 0;
    for (const LayerPass& p : first.passes) draws += p.draws;
    head += ": " + layer_plural(first.passes.size(), "pass", "passes") + ", " +
            layer_plural(draws, "draw", "draws");
    if (first.by_present)
        head += ", " + layer_plural(first.submissions, "submission", "submissions");
    if (first.by_present && !last.presented) head += " (not presented: the application ended)";
    return head;
}

}  // namespace

std::vector<LayerFrame> read_layer_frames(const std::filesystem::path& file) {
    std::vector<LayerFrame> frames;
    std::ifstream in(file);
    std::string line;
    for (size_t n = 1; std::getline(in, line); ++n) {
        try {
            frames.push_back(parse_layer_frame(nlohmann::json::parse(line)));
        } catch (const nlohmann::json::exception& e) {
            throw Error(file.string() + ":" + std::to_string(n) + ": " + e.what());
        }
    }
    return frames;
}

std::vector<std::string> list_lines(const std::vector<LayerFrame>& frames) {
    std::vector<std::string> lines;
    for (size_t i = 0; i < frames.size();) {
        size_t j = i;
        while (j + 1 < frames.size() && frames[j + 1].passes == frames[i].passes &&
               frames[j + 1].submissions == frames[i].submissions &&
               frames[j + 1].presented == frames[i].presented)
            ++j;
        lines.push_back(layer_frame_head(frames[i], frames[j]));
        for (const LayerPass& p : frames[i].passes) lines.push_back(layer_pass_line(p));
        i = j + 1;
    }
    return lines;
}

}  // namespace ds::capture
