// libFuzzer target: the settings parser on arbitrary bytes taken as one `--set` assignment.
// It must either accept the assignment or throw ds::UsageError; a value it accepted must
// re-apply to the same canonical value (so report.json and reproductions round-trip).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "renderer/common/error.h"
#include "renderer/settings/settings.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    ds::Settings settings;
    try {
        settings.apply(text);
    } catch (const ds::UsageError&) {
        return 0;
    }
    const std::string name = text.substr(0, text.find('='));
    const std::string canonical = settings.get(name);
    ds::Settings again;
    try {
        again.set(name, canonical);
    } catch (const ds::UsageError& e) {
        std::fprintf(stderr, "canonical value \"%s\" of %s refused: %s\n", canonical.c_str(),
                     name.c_str(), e.what());
        std::abort();
    }
    if (again.get(name) != canonical) {
        std::fprintf(stderr, "%s: canonical \"%s\" re-applies as \"%s\"\n", name.c_str(),
                     canonical.c_str(), again.get(name).c_str());
        std::abort();
    }
    return 0;
}
