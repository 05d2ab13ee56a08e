// load_gltf: a .gltf / .glb file -> Scene. Kept apart from loader.cpp so that tools linking only
// the importer (the ASan check binary, the fuzzer) need no built-in scenes.
#include "renderer/scene/gltf_decode.h"
#include "renderer/scene/gltf_image.h"
#include "renderer/scene/gltf_precheck.h"
#include "renderer/scene/gltf_prepare.h"
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
// The model, and (lenient) the images that could not be used, by index.
struct Parsed {
    tinygltf::Model model;
    std::map<size_t, std::string> image_problems;
};

tinygltf::Model parse(const std::string& bytes, bool binary, const detail::FileSource& source,
                      detail::ImageBudget& images) {
    tinygltf::TinyGLTF loader;
    detail::FsBridge bridge{&source, {}};
    loader.SetFsCallbacks(bridge.callbacks());
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
// reads any; the reads themselves go through the same source. Lenient, an image file that is
// not there is read as a one-byte placeholder that the image loader records as its problem.
Parsed parse_checked(const std::string& bytes, const detail::FileSource& source, bool strict) {
    if (bytes.empty()) fail("empty file");
    static_assert(limits::kMaxFileBytes <= 0xffffffffu);
    if (bytes.size() > limits::kMaxFileBytes) fail("file larger than the limit");
    const bool binary = bytes.starts_with("glTF");
    detail::ImageBudget images;
    images.lenient = !strict;
    for (const detail::FileRef& ref : detail::precheck_gltf(bytes, binary)) {
        const std::string what = ref.json_path + " " + detail::quote_value(ref.uri) + ": ";
        uint64_t size = 0;
        try {
            size = source.check(ref.decoded);
            if (size == 0) fail("empty file");
        } catch (const InputError& e) {
            if (strict || ref.is_buffer) fail(what + e.what());
            images.missing[ref.decoded] = e.what();
            continue;
        }
        if (ref.is_buffer && size != ref.byte_length)
            fail(what + "the file is " + std::to_string(size) + " bytes, the buffer's byteLength " +
                 std::to_string(ref.byte_length));
    }
    // Compressed data: placeholders tinygltf reads as zeros, filled by decoding.
    const detail::Prepared prepared = detail::prepare_compressed(bytes, binary);
    std::map<std::string, uint64_t> served = prepared.placeholders;
    for (const auto& [uri, why] : images.missing) served.emplace(uri, 1);
    const detail::PlaceholderSource with_placeholders(source, served);
    Parsed out;
    out.model =
        parse(prepared.bytes.empty() ? bytes : prepared.bytes, binary, with_placeholders, images);
    detail::decode_meshopt(out.model, prepared.placeholders);
    detail::decode_draco(out.model, prepared.placeholders);
    out.image_problems = std::move(images.problems);
    return out;
}

}  // namespace

Scene load_gltf(const fs::path& path, const ImportOptions& options) {
    const std::string shown = detail::printable(path.string());
    Parsed parsed;
    try {
        const std::string bytes = detail::read_regular_file(path);
        parsed = parse_checked(bytes, detail::DiskSource(path.parent_path()), options.strict);
    } catch (const InputError& e) {
        throw InputError(shown + ": " + one_line(e.what()));
    }
    return detail::import_parsed(parsed.model, detail::printable(path.stem().string()), shown,
                                 options, parsed.image_problems);
}

Scene load_gltf_memory(const std::string& bytes, const std::map<std::string, std::string>& files,
                       const std::string& name, const ImportOptions& options) {
    Parsed parsed;
    try {
        parsed = parse_checked(bytes, detail::MemorySource(files), options.strict);
    } catch (const InputError& e) {
        throw InputError(detail::printable(name) + ": " + one_line(e.what()));
    }
    return detail::import_parsed(parsed.model, detail::printable(fs::path(name).stem().string()),
                                 detail::printable(name), options, parsed.image_problems);
}

}  // namespace ds::scene
