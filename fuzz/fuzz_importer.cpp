// libFuzzer target: the glTF importer on a document and its files, all in memory
// (container.h). Every input must load or throw ds::InputError whose message is one line
// starting with the document's name; anything else (a crash, a sanitizer report, another
// exception, a hang, more than the memory limit) is a finding.
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "container.h"
#include "renderer/common/error.h"
#include "renderer/scene/importer.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const ds::fuzz::Container input = ds::fuzz::unpack(data, size);
    try {
        (void)ds::scene::load_gltf_memory(input.document, input.files, input.name);
    } catch (const ds::InputError& e) {
        const std::string message = e.what();
        if (message.find('\n') != std::string::npos || message.rfind(input.name + ": ", 0) != 0) {
            std::fprintf(stderr, "bad error message: %s\n", message.c_str());
            std::abort();
        }
    }
    return 0;
}
