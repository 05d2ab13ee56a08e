#include "capture/layer_capture_data.h"

#include <algorithm>
#include <fstream>

#include "capture/exr_file.h"
#include "renderer/common/error.h"
#include "renderer/view/heat.h"

namespace ds::capture {

nlohmann::json read_json_file(const std::filesystem::path& file) {
    std::error_code ec;
    if (std::filesystem::is_directory(file, ec)) throw Error(file.string() + ": is a folder");
    std::ifstream in(file);
    if (!in) throw Error(file.string() + ": cannot be read");
    try {
        return nlohmann::json::parse(in);
    } catch (const nlohmann::json::exception& e) {
        throw Error(file.string() + ": " + e.what());
    }
}

nlohmann::json read_layer_report(const std::filesystem::path& dir) {
    nlohmann::json report = read_json_file(dir / "report.json");
    if (!report.is_object() || report.value("source", "") != "layer")
        throw Error((dir / "report.json").string() + ": not a layer capture (depthscope layer)");
    return report;
}

bool is_layer_capture(const std::filesystem::path& dir) {
    try {
        read_layer_report(dir);
        return true;
    } catch (const Error&) {
        return false;
    }
}

std::vector<uint8_t> count_heat_rgba(const std::vector<uint32_t>& counts, uint32_t max) {
    const float white = float(std::max<uint32_t>(max, 1));
    std::vector<uint8_t> rgba(counts.size() * 4, 255);
    for (size_t i = 0; i < counts.size(); ++i) {
        const auto c = view::count_color(float(counts[i]), 0.0f, white);
        std::copy(c.begin(), c.end(), rgba.begin() + long(i * 4));
    }
    return rgba;
}

std::vector<uint8_t> marks_rgba(const std::vector<uint32_t>& marks) {
    std::vector<uint8_t> rgba(marks.size() * 4, 0);
    for (size_t i = 0; i < marks.size(); ++i) {
        if (marks[i] == 0) continue;
        const bool hole = marks[i] == 1;
        const uint8_t c[4] = {255, uint8_t(hole ? 0 : 230), uint8_t(hole ? 255 : 0), 255};
        std::copy(c, c + 4, rgba.begin() + long(i * 4));
    }
    return rgba;
}

LayerCaptureData load_layer_capture(const std::filesystem::path& dir) {
    LayerCaptureData data;
    data.dir = dir;
    data.report = read_layer_report(dir);
    try {
        for (const auto& pass : data.report.at("passes")) {
            if (!pass.contains("images")) continue;
            LayerPassImages images;
            images.pass = pass.at("index").get<uint32_t>();
            images.name = pass.at("name").get<std::string>();
            for (size_t k = 0; k < kLayerImageKinds.size(); ++k) {
                if (k >= kLayerCountKinds.size() &&
                    !pass.at("images").contains(kLayerImageKinds[k]))
                    continue;
                const auto& entry = pass.at("images").at(kLayerImageKinds[k]);
                const ExrImage exr = read_exr(dir / entry.at("exr").get<std::string>());
                const ExrChannel* count = exr.find("count") ? exr.find("count") : exr.find("mark");
                if (!count || !count->is_uint)
                    throw Error(entry.at("exr").get<std::string>() + ": no UINT count channel");
                images.width = exr.width;
                images.height = exr.height;
                images.counts[k] = count->uints;
                images.max[k] = count->uints.empty()
                                    ? 0
                                    : *std::max_element(count->uints.begin(), count->uints.end());
            }
            data.images.push_back(std::move(images));
        }
    } catch (const nlohmann::json::exception& e) {
        throw Error((dir / "report.json").string() + ": " + e.what());
    }
    return data;
}

}  // namespace ds::capture
