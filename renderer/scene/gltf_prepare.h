#pragma once
// Compressed glTF made readable by tinygltf (Debian's 2.7 has no Draco, and refuses a meshopt
// fallback buffer without `uri` and an accessor that only a Draco stream fills, before any
// extension code could run). The document is rewritten before tinygltf parses it:
// - EXT_meshopt_compression: a fallback buffer without `uri` gets a placeholder uri;
// - KHR_draco_mesh_compression: each accessor a Draco stream fills that has no bufferView gets
//   one in a new placeholder buffer, sized from its count and type.
// Placeholders read as zeros (PlaceholderSource); gltf_decode.h then fills them by decoding.
// Where the file also holds an uncompressed copy, that copy is used and nothing is decoded.
// Internal to renderer/scene; errors are InputError with a WHAT only.
#include <cstdint>
#include <map>
#include <string>
#include <string_view>

#include "renderer/scene/gltf_source.h"

namespace ds::scene::detail {

struct Prepared {
    std::string bytes;                             // the rewritten document; empty: unchanged
    std::map<std::string, uint64_t> placeholders;  // uri -> size in bytes (zeros)
};

// `bytes` is the whole (prechecked) file, `binary` a GLB container.
Prepared prepare_compressed(std::string_view bytes, bool binary);

// A FileSource that answers the placeholders itself and asks `inner` for every other uri.
class PlaceholderSource : public FileSource {
  public:
    PlaceholderSource(const FileSource& inner, const std::map<std::string, uint64_t>& sizes)
        : inner_(inner), sizes_(sizes) {}
    uint64_t check(const std::string& uri) const override;
    std::string read(const std::string& uri) const override;

  private:
    const FileSource& inner_;
    const std::map<std::string, uint64_t>& sizes_;
};

}  // namespace ds::scene::detail
