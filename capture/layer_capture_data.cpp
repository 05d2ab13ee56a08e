#include "capture/layer_capture_data.h"

#include <algorithm>
#include <fstream>

#include "capture/exr_file.h"
#include "renderer/common/error.h"

namespace ds::capture {

LayerCaptureData load_layer_capture(const std::filesystem::path& dir) {
    LayerCaptureData data;
    data.dir = dir;
    std::ifstream in(dir / "report.json");
    if (!in) throw Error((dir / "report.json").string() + ": cannot be read");
    data.report = nlohmann::json::parse(in, nullptr, false);
    if (!data.report.is_object() || data.report.value("source", "") != "layer")
        throw Error((dir / "report.json").string() + ": not a layer capture (depthscope layer)");
    try {
        for (const auto& pass : data.report.at("passes")) {
            if (!pass.contains("images")) continue;
            LayerPassImages images;
            images.pass = pass.at("index").get<uint32_t>();
            images.name = pass.at("name").get<std::string>();
            for (size_t k = 0; k < kLayerCountKinds.size(); ++k) {
                const auto& entry = pass.at("images").at(kLayerCountKinds[k]);
                const ExrImage exr = read_exr(dir / entry.at("exr").get<std::string>());
                const ExrChannel* count = exr.find("count");
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
