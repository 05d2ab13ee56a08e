// export_model: OUT.gltf + OUT.bin + one PNG per image, written into a hidden temporary folder
// beside OUT and renamed into place only when everything was written and checked (DESIGN
// decision 8: no half-written output).
//
// tinygltf 2.7.0 notes that shaped this file:
// - WriteGltfSceneToFile writes images through the image-writer callback, but its default
//   callback gets a null FsCallbacks and silently writes nothing; and a failed image write just
//   falls back to the old uri. So we install our own callback that records failures.
// - Its .gltf and .bin writers do not check stream errors, so the results are checked here.
// - PNG encoding uses tinygltf::WriteImageData (stb_image_write inside libtinygltf/libstb), so
//   this library needs no stb implementation of its own.
#include <unistd.h>

#include <atomic>
#include <cctype>
#include <fstream>
#include <set>
#include <string>
#include <system_error>
#include <vector>

#include <nlohmann/json.hpp>

#include "renderer/common/error.h"
#include "renderer/scene/builtin/builtin.h"

namespace ds::scene::builtin {

namespace fs = std::filesystem;

namespace {

struct ImageSink {
    tinygltf::FsCallbacks fs{&tinygltf::FileExists, &tinygltf::ExpandFilePath,
                             &tinygltf::ReadWholeFile, &tinygltf::WriteWholeFile, nullptr};
    std::vector<std::string> failed;
};

bool write_png(const std::string* basepath, const std::string* filename,
               const tinygltf::Image* image, bool /*embed*/, std::string* out_uri, void* user) {
    auto* sink = static_cast<ImageSink*>(user);
    if (!tinygltf::WriteImageData(basepath, filename, image, false, out_uri, &sink->fs)) {
        sink->failed.push_back(*filename);
        return false;
    }
    return true;
}

std::string file_safe(const std::string& name) {
    std::string out;
    for (char c : name) {
        const auto u = static_cast<unsigned char>(c);
        out += (std::isalnum(u) || c == '_' || c == '-') ? c : '_';
    }
    return out;
}

// A copy whose buffers and images carry file names derived from OUT's stem, so exports of two
// scenes into one folder never overwrite each other's files. Returns the files to expect.
std::vector<std::string> name_files(tinygltf::Model& m, const std::string& stem,
                                    const std::string& what) {
    std::vector<std::string> files;
    for (size_t i = 0; i < m.buffers.size(); ++i) {
        m.buffers[i].uri = stem + (m.buffers.size() > 1 ? "_" + std::to_string(i) : "") + ".bin";
        files.push_back(m.buffers[i].uri);
    }
    std::set<std::string> used;
    for (size_t i = 0; i < m.images.size(); ++i) {
        tinygltf::Image& img = m.images[i];
        if (img.bufferView >= 0) continue;  // stays inside the .bin
        if (img.image.empty() || img.bits != 8 ||
            img.pixel_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) {
            throw Error(what + ": cannot write image " + std::to_string(i) +
                        ": no 8-bit pixel data");
        }
        std::string base = file_safe(img.name.empty() ? std::to_string(i) : img.name);
        if (!used.insert(base).second) base += "_" + std::to_string(i);
        // "atrium_brick" exported as atrium.gltf stays atrium_brick.png, not atrium_atrium_...
        const bool prefixed = base.rfind(stem + "_", 0) == 0;
        img.uri = (prefixed ? base : stem + "_" + base) + ".png";
        img.mimeType = "image/png";
        files.push_back(img.uri);
    }
    return files;
}

void check_written(const fs::path& dir, const tinygltf::Model& m, const std::string& gltf_name,
                   const std::vector<std::string>& files, const std::string& what) {
    for (const std::string& f : files) {
        std::error_code ec;
        if (!fs::is_regular_file(dir / f, ec)) throw Error(what + ": cannot write " + f);
    }
    for (const tinygltf::Buffer& b : m.buffers) {
        std::error_code ec;
        if (fs::file_size(dir / b.uri, ec) != b.data.size() || ec) {
            throw Error(what + ": cannot write " + b.uri + " (short write)");
        }
    }
    std::ifstream in(dir / gltf_name);
    if (!in || !nlohmann::json::accept(in)) {
        throw Error(what + ": cannot write " + gltf_name + " (incomplete JSON)");
    }
}

fs::path make_temp_dir(const fs::path& parent, const std::string& stem, const std::string& what) {
    static std::atomic<unsigned> counter{0};
    for (int attempt = 0; attempt < 100; ++attempt) {
        const fs::path dir = parent / ("." + stem + ".export-" + std::to_string(::getpid()) + "-" +
                                       std::to_string(counter++));
        std::error_code ec;
        if (fs::create_directory(dir, ec)) return dir;
        if (ec) throw Error(what + ": cannot write into " + parent.string() + ": " + ec.message());
    }
    throw Error(what + ": cannot write: no free temporary name in " + parent.string());
}

// Moves every file into `parent`, the .gltf last so it never points at missing files. On
// failure, removes what was already moved.
void publish(const fs::path& tmp, const fs::path& parent, std::vector<std::string> files,
             const std::string& what) {
    std::vector<fs::path> moved;
    for (const std::string& f : files) {
        std::error_code ec;
        fs::rename(tmp / f, parent / f, ec);
        if (ec) {
            for (const fs::path& p : moved) fs::remove(p, ec);
            throw Error(what + ": cannot write " + (parent / f).string() + ": " + ec.message());
        }
        moved.push_back(parent / f);
    }
}

}  // namespace

void export_model(const tinygltf::Model& model, const fs::path& out_gltf) {
    const std::string what = out_gltf.string();
    const fs::path parent = out_gltf.has_parent_path() ? out_gltf.parent_path() : fs::path(".");
    std::error_code ec;
    if (!fs::is_directory(parent, ec)) {
        throw Error(what + ": cannot write: folder " + parent.string() + " does not exist");
    }
    if (out_gltf.filename().empty()) throw Error(what + ": cannot write: no file name");
    const std::string stem = out_gltf.stem().string();
    const std::string gltf_name = out_gltf.filename().string();

    tinygltf::Model copy = model;
    std::vector<std::string> files = name_files(copy, stem, what);
    const fs::path tmp = make_temp_dir(parent, stem, what);
    try {
        ImageSink sink;
        tinygltf::TinyGLTF writer;
        writer.SetImageWriter(&write_png, &sink);
        const bool ok = writer.WriteGltfSceneToFile(&copy, (tmp / gltf_name).string(),
                                                    /*embedImages=*/false, /*embedBuffers=*/false,
                                                    /*prettyPrint=*/true, /*writeBinary=*/false);
        if (!ok) throw Error(what + ": cannot write (glTF writer failed)");
        if (!sink.failed.empty()) throw Error(what + ": cannot write image " + sink.failed[0]);
        check_written(tmp, copy, gltf_name, files, what);
        files.push_back(gltf_name);
        publish(tmp, parent, files, what);
    } catch (...) {
        fs::remove_all(tmp, ec);
        throw;
    }
    fs::remove_all(tmp, ec);
}

}  // namespace ds::scene::builtin
