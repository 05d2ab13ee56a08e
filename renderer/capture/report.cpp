#include "renderer/capture/report.h"

#include <unistd.h>

#include <fstream>

#include "renderer/common/error.h"

namespace ds::capture {

nlohmann::json scene_summary(const scene::Scene& s) {
    size_t by_mode[3] = {0, 0, 0};
    for (const auto& m : s.materials) ++by_mode[size_t(m.alpha_mode)];
    return {
        {"name", s.name},
        {"source", s.source},
        {"gltf_meshes", s.gltf_mesh_count},
        {"meshes", s.meshes.size()},
        {"materials",
         {{"total", s.materials.size()},
          {"opaque", by_mode[0]},
          {"mask", by_mode[1]},
          {"blend", by_mode[2]}}},
        {"textures", s.textures.size()},
        {"instances", s.instances.size()},
        {"draw_groups", s.draw_groups.size()},
        {"triangles", s.triangle_count()},
        {"warnings", s.warnings},
    };
}

nlohmann::json make_report(const ReportInput& in) {
    nlohmann::json settings = nlohmann::json::object();
    for (const auto& [name, value] : in.settings->values()) settings[name] = value;
    return {
        {"tool", "depthscope"},
        {"device", {{"name", in.device_name}, {"driver", in.driver}, {"api", in.api_version}}},
        {"scene", scene_summary(*in.scene)},
        {"size", {{"width", in.width}, {"height", in.height}}},
        {"settings", settings},
        {"frame", {{"gpu_ms", in.gpu_ms}, {"cpu_ms", in.cpu_ms}}},
        {"validation_messages", in.validation_messages},
    };
}

void write_json(const std::filesystem::path& path, const nlohmann::json& json) {
    std::ofstream out(path, std::ios::binary);
    out << json.dump(2) << '\n';
    out.close();
    if (!out) throw Error(path.string() + ": cannot write");
}

void write_json_atomically(const std::filesystem::path& path, const nlohmann::json& json) {
    const std::filesystem::path temp = path.string() + ".tmp-" + std::to_string(::getpid());
    try {
        write_json(temp, json);
    } catch (...) {
        std::error_code ignored;
        std::filesystem::remove(temp, ignored);
        throw Error(path.string() + ": cannot write");
    }
    std::error_code ec;
    std::filesystem::rename(temp, path, ec);
    if (ec) {
        std::filesystem::remove(temp, ec);
        throw Error(path.string() + ": cannot write: " + ec.message());
    }
}

}  // namespace ds::capture
