#include "capture/capture_folder.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>

#include "renderer/common/error.h"
#include "renderer/common/quoted.h"
#include "renderer/scene/image_checks.h"

// Debian's stb_image (libstb) decodes final.png; the PNG signature is checked first, since
// stb reads other formats too.
#include <stb/stb_image.h>

namespace fs = std::filesystem;
using nlohmann::json;

namespace ds::capture {
namespace {

constexpr uint64_t kMaxReportBytes = uint64_t(64) << 20;
constexpr uint64_t kMaxPngBytes = uint64_t(1) << 30;
constexpr int kMaxSide = 16384;  // the largest --size side

[[noreturn]] void fail(const fs::path& path, const std::string& why) {
    throw Error(escaped(path.string()) + ": " + why);
}

// The whole file, after checking that it is a regular file of at most `limit` bytes.
std::string read_regular(const fs::path& path, uint64_t limit) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0)
        fail(path, errno == ENOENT ? "no such file" : std::strerror(errno));
    if (!S_ISREG(st.st_mode)) fail(path, "is not a regular file");
    if (uint64_t(st.st_size) > limit)
        fail(path, "larger than " + std::to_string(limit >> 20) + " MiB");
    std::ifstream in(path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (!in.good() && !in.eof()) fail(path, "cannot read");
    return bytes;
}

// report.json's entries, checked: each accessor throws "DIR/report.json: WHERE …".
class ReportReader {
  public:
    explicit ReportReader(fs::path path) : path_(std::move(path)) {}

    const json& member(const json& object, const char* key, const std::string& where) const {
        if (!object.is_object() || !object.contains(key))
            fail(path_, where + "." + key + " is missing");
        return object.at(key);
    }
    std::string text(const json& object, const char* key, const std::string& where) const {
        const json& v = member(object, key, where);
        if (!v.is_string()) fail(path_, where + "." + key + " is not a string");
        return v.get<std::string>();
    }
    uint64_t count(const json& object, const char* key, const std::string& where) const {
        const json& v = member(object, key, where);
        if (!v.is_number_unsigned()) fail(path_, where + "." + key + " is not a whole number");
        return v.get<uint64_t>();
    }
    double number(const json& object, const char* key, const std::string& where) const {
        const json& v = member(object, key, where);
        if (!v.is_number()) fail(path_, where + "." + key + " is not a number");
        return v.get<double>();
    }
    std::optional<uint64_t> optional_count(const json& object, const char* key,
                                           const std::string& where) const {
        if (!object.contains(key)) return std::nullopt;
        return count(object, key, where);
    }
    [[noreturn]] void fail_at(const std::string& why) const { fail(path_, why); }

  private:
    fs::path path_;
};

// A file a report names: relative, inside the capture folder, a regular file.
fs::path listed_file(const fs::path& dir, const std::string& file, const std::string& where,
                     const ReportReader& reader) {
    const fs::path relative(file);
    if (file.empty() || relative.is_absolute())
        reader.fail_at(where + " " + quote(file) + " is not a path inside the capture");
    for (const fs::path& part : relative)
        if (part == "..") reader.fail_at(where + " " + quote(file) + " leaves the capture folder");
    const fs::path path = dir / relative;
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) fail(path, "no such file (listed in report.json)");
    if (!S_ISREG(st.st_mode)) fail(path, "is not a regular file");
    return path;
}

uint32_t side(const ReportReader& reader, const json& entry, const char* key,
              const std::string& where) {
    const uint64_t v = reader.count(entry, key, where);
    if (v < 1 || v > uint64_t(kMaxSide))
        reader.fail_at(where + "." + key + " is outside 1.." + std::to_string(kMaxSide));
    return uint32_t(v);
}

std::vector<ResourceRef> read_resources(const fs::path& dir, const json& list,
                                        const ReportReader& reader) {
    if (!list.is_array()) reader.fail_at("\"resources\" is not an array");
    std::vector<ResourceRef> out;
    for (size_t i = 0; i < list.size(); ++i) {
        const std::string where = "resources[" + std::to_string(i) + "]";
        const json& e = list[i];
        ResourceRef r;
        r.name = reader.text(e, "name", where);
        r.format = reader.text(e, "format", where);
        r.semantic = reader.text(e, "semantic", where);
        r.width = side(reader, e, "width", where);
        r.height = side(reader, e, "height", where);
        const uint64_t samples = reader.count(e, "samples", where);
        if (samples < 1 || samples > 64) reader.fail_at(where + ".samples is outside 1..64");
        r.samples = uint32_t(samples);
        const json& exr = reader.member(e, "exr", where);
        r.exr =
            listed_file(dir, reader.text(exr, "file", where + ".exr"), where + ".exr.file", reader);
        for (const ResourceRef& earlier : out)
            if (earlier.name == r.name) reader.fail_at(where + " repeats " + quote(r.name));
        out.push_back(std::move(r));
    }
    return out;
}

std::vector<PassNumbers> read_passes(const json& list, const ReportReader& reader) {
    if (!list.is_array()) reader.fail_at("\"passes\" is not an array");
    std::vector<PassNumbers> out;
    for (size_t i = 0; i < list.size(); ++i) {
        const std::string where = "passes[" + std::to_string(i) + "]";
        const json& e = list[i];
        PassNumbers p;
        p.name = reader.text(e, "name", where);
        if (e.is_object() && e.contains("kind")) p.kind = reader.text(e, "kind", where);
        p.gpu_ms = reader.number(e, "gpu_ms", where);
        p.rasterized = reader.optional_count(e, "rasterized_fragments", where);
        p.shaded = reader.optional_count(e, "shaded_fragments", where);
        p.discarded = reader.optional_count(e, "discarded_fragments", where);
        out.push_back(std::move(p));
    }
    return out;
}

json read_report(const fs::path& dir) {
    const fs::path path = dir / "report.json";
    const std::string text = read_regular(path, kMaxReportBytes);
    json report = json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (report.is_discarded()) fail(path, "is not JSON");
    if (!report.is_object() || !report.contains("tool") || report["tool"] != "depthscope")
        fail(path, "is not a depthscope report (no \"tool\": \"depthscope\")");
    return report;
}

}  // namespace

Rgba8Image read_png_rgba8(const fs::path& path) {
    const std::string bytes = read_regular(path, kMaxPngBytes);
    const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
    const int size = int(bytes.size());
    int w = 0, h = 0, comp = 0;
    if (!scene::is_png(data, size) || !stbi_info_from_memory(data, size, &w, &h, &comp))
        fail(path, "is not a PNG");
    if (w < 1 || h < 1 || w > kMaxSide || h > kMaxSide)
        fail(path, "PNG of " + std::to_string(w) + "x" + std::to_string(h) + ": outside 1x1.." +
                       std::to_string(kMaxSide) + "x" + std::to_string(kMaxSide));
    std::string cleaned;  // without empty IDAT chunks, which stb mishandles (image_checks.h)
    try {
        scene::check_png_chunks(data, size, cleaned);
    } catch (const Error& e) {
        fail(path, e.what());
    }
    const std::string& png = cleaned.empty() ? bytes : cleaned;
    const std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
        stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(png.data()), int(png.size()), &w, &h,
                              &comp, 4),
        stbi_image_free);
    if (!pixels) fail(path, std::string("cannot decode PNG: ") + stbi_failure_reason());
    Rgba8Image image{uint32_t(w), uint32_t(h), {}};
    image.rgba.assign(pixels.get(), pixels.get() + size_t(w) * size_t(h) * 4);
    return image;
}

CaptureFolder load_capture(const fs::path& dir) {
    struct stat st {};
    if (::stat(dir.c_str(), &st) != 0)
        fail(dir, errno == ENOENT ? "no such capture folder" : std::strerror(errno));
    if (!S_ISDIR(st.st_mode)) fail(dir, "is not a folder");
    CaptureFolder c;
    c.dir = dir;
    c.report = read_report(dir);
    const ReportReader reader(dir / "report.json");
    if (c.report.contains("passes")) c.passes = read_passes(c.report["passes"], reader);
    if (c.report.contains("frame") && c.report["frame"].is_object() &&
        c.report["frame"].contains("gpu_ms"))
        c.frame_gpu_ms = reader.number(c.report["frame"], "gpu_ms", "frame");
    c.lists_resources = c.report.contains("resources");
    if (c.lists_resources) c.resources = read_resources(dir, c.report["resources"], reader);
    c.final_image = read_png_rgba8(dir / "final.png");
    return c;
}

}  // namespace ds::capture
