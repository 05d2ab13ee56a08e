// load_gltf: a .gltf / .glb file -> Scene. Kept apart from loader.cpp so that tools linking only
// the importer (the ASan check binary, the fuzzer) need no built-in scenes.
#include "renderer/scene/gltf_image.h"
#include "renderer/scene/gltf_precheck.h"
#include "renderer/scene/gltf_source.h"
#include "renderer/scene/import_limits.h"
#include "renderer/scene/import_util.h"
#include "renderer/scene/importer.h"

namespace ds::scene {
namespace {

namespace fs = std::filesystem;
using detail::fail;
using detail::one_line;

// tinygltf reports problems in `err` even when it returns true (e.g. a texture info without
// its required index), and puts undecodable or missing images in `warn`: all are errors here.
// The file and image checks' own messages come first: they name the JSON path.
tinygltf::Model parse(const std::string& bytes, bool binary, const detail::FileSource& source) {
    tinygltf::TinyGLTF loader;
    detail::FsBridge bridge{&source, {}};
    loader.SetFsCallbacks(bridge.callbacks());
    detail::ImageBudget images;
    loader.SetImageLoader(&detail::load_image_checked, &images);
    tinygltf::Model model;
    std::string err;
    std::string warn;
    bool ok = false;
    try {
        // tinygltf takes an unsigned int length (kMaxFileBytes keeps within it) and an empty
        // base dir: the FileSource resolves uris.
        const auto length = static_cast<unsigned int>(bytes.size());
        ok = binary ? loader.LoadBinaryFromMemory(
                          &model, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()),
                          length, "")
                    : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), length, "");
    } catch (const std::exception& e) {
        fail(std::string("tinygltf: ") + e.what());
    }
    std::string message = one_line(bridge.error);
    if (message.empty()) message = one_line(images.error);
    if (message.empty()) message = one_line(err);
    if (message.empty()) message = one_line(warn);
    if (!ok && message.empty()) message = "tinygltf could not parse the file";
    if (message.size() > 400) message = message.substr(0, 400) + "...";  // tinygltf may quote data
    if (!message.empty()) fail(message);
    return model;
}

// Every file the document names is checked (exists, regular file, size bound) before tinygltf
// reads any; the reads themselves go through the same source.
tinygltf::Model parse_checked(const std::string& bytes, const detail::FileSource& source) {
    if (bytes.empty()) fail("empty file");
    static_assert(limits::kMaxFileBytes <= 0xffffffffu);
    if (bytes.size() > limits::kMaxFileBytes) fail("file larger than the limit");
    const bool binary = bytes.starts_with("glTF");
    for (const detail::FileRef& ref : detail::precheck_gltf(bytes, binary)) {
        const std::string what = ref.json_path + " " + detail::quote_value(ref.uri) + ": ";
        uint64_t size = 0;
        try {
            size = source.check(ref.decoded);
        } catch (const InputError& e) {
            fail(what + e.what());
        }
        if (size == 0) fail(what + "empty file");
        if (ref.is_buffer && size != ref.byte_length)
            fail(what + "the file is " + std::to_string(size) + " bytes, the buffer's byteLength " +
                 std::to_string(ref.byte_length));
    }
    return parse(bytes, binary, source);
}

}  // namespace

Scene load_gltf(const fs::path& path) {
    const std::string shown = detail::printable(path.string());
    tinygltf::Model model;
    try {
        const std::string bytes = detail::read_regular_file(path);
        model = parse_checked(bytes, detail::DiskSource(path.parent_path()));
    } catch (const InputError& e) {
        throw InputError(shown + ": " + one_line(e.what()));
    }
    return import_model(model, detail::printable(path.stem().string()), shown);
}

Scene load_gltf_memory(const std::string& bytes, const std::map<std::string, std::string>& files,
                       const std::string& name) {
    tinygltf::Model model;
    try {
        model = parse_checked(bytes, detail::MemorySource(files));
    } catch (const InputError& e) {
        throw InputError(detail::printable(name) + ": " + one_line(e.what()));
    }
    return import_model(model, detail::printable(fs::path(name).stem().string()),
                        detail::printable(name));
}

}  // namespace ds::scene
