// load_gltf: a .gltf / .glb file -> Scene. Kept apart from loader.cpp so that tools linking only
// the importer (the ASan check binary) need no built-in scenes.
#include <climits>
#include <fstream>

#include "renderer/scene/gltf_precheck.h"
#include "renderer/scene/import_util.h"
#include "renderer/scene/importer.h"

namespace ds::scene {
namespace {

namespace fs = std::filesystem;
using detail::fail;
using detail::one_line;

std::string read_file(const fs::path& path) {
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (ec || !fs::exists(status)) fail("no such file");
    if (fs::is_directory(status)) fail("is a directory, not a .gltf or .glb file");
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) fail("cannot open the file");
    const std::streamoff size = in.tellg();
    // tinygltf takes an unsigned int length.
    if (size < 0 || static_cast<unsigned long long>(size) > UINT_MAX) fail("file too large");
    std::string bytes(static_cast<size_t>(size), '\0');
    in.seekg(0);
    if (!in.read(bytes.data(), size)) fail("cannot read the file");
    if (bytes.empty()) fail("empty file");
    return bytes;
}

// tinygltf reports problems in `err` even when it returns true (e.g. a texture info without
// its required index), and puts undecodable or missing images in `warn`: all are errors here.
tinygltf::Model parse(const std::string& bytes, bool binary, const std::string& base_dir) {
    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string err;
    std::string warn;
    bool ok = false;
    try {
        const auto length = static_cast<unsigned int>(bytes.size());
        ok = binary
                 ? loader.LoadBinaryFromMemory(&model, &err, &warn,
                                               reinterpret_cast<const unsigned char*>(bytes.data()),
                                               length, base_dir)
                 : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), length, base_dir);
    } catch (const std::exception& e) {
        fail(std::string("tinygltf: ") + e.what());
    }
    std::string message = one_line(err);
    if (message.empty()) message = one_line(warn);
    if (!ok && message.empty()) message = "tinygltf could not parse the file";
    if (!message.empty()) fail(message);
    return model;
}

}  // namespace

Scene load_gltf(const fs::path& path) {
    const std::string shown = path.string();
    tinygltf::Model model;
    try {
        const std::string bytes = read_file(path);
        const bool binary = bytes.starts_with("glTF");
        detail::precheck_gltf(bytes, binary);
        model = parse(bytes, binary, path.parent_path().string());
    } catch (const InputError& e) {
        throw InputError(shown + ": " + one_line(e.what()));
    }
    return import_model(model, path.stem().string(), shown);
}

}  // namespace ds::scene
