// Inputs kept from fuzzing the importer (tests/data/fuzz/importer/, container format of
// fuzz/container.h) run through load_gltf_memory as the fuzz target does: each must load or
// throw one-line InputError "NAME: ...". Each file's reason is in tests/data/fuzz/README.md.
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "fuzz/container.h"
#include "renderer/common/error.h"
#include "renderer/scene/importer.h"

namespace ds::scene {
namespace {

namespace fs = std::filesystem;
const fs::path kInputs = fs::path(DS_SOURCE_DIR) / "tests/data/fuzz/importer";

std::string slurp(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

TEST(FuzzRegressions, EveryKeptInputLoadsOrFailsWithOneLine) {
    size_t inputs = 0;
    for (const auto& entry : fs::directory_iterator(kInputs)) {
        if (!entry.is_regular_file()) continue;
        ++inputs;
        SCOPED_TRACE(entry.path().filename().string());
        const std::string bytes = slurp(entry.path());
        const fuzz::Container c =
            fuzz::unpack(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
        try {
            load_gltf_memory(c.document, c.files, c.name);
        } catch (const InputError& e) {
            const std::string message = e.what();
            EXPECT_EQ(message.rfind(c.name + ": ", 0), 0u) << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        }
    }
    EXPECT_GT(inputs, 0u);
}

// The in-memory entry point serves uris from the given files only.
TEST(FuzzRegressions, MemoryLoadReadsNamedFilesOnly) {
    const std::string doc =
        R"({"asset":{"version":"2.0"},"buffers":[{"uri":"a.bin","byteLength":4}]})";
    try {
        load_gltf_memory(doc, {}, "mem.gltf");
        FAIL() << "loaded";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "mem.gltf: buffers[0].uri \"a.bin\": no such file");
    }
    try {
        load_gltf_memory(doc, {{"a.bin", "12345"}}, "mem.gltf");
        FAIL() << "loaded";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(),
                     "mem.gltf: buffers[0].uri \"a.bin\": the file is 5 bytes, the buffer's "
                     "byteLength 4");
    }
}

// A name (a path) with control characters stays one line: they are escaped like every echoed
// value (found by the fuzzer as a NUL that cut the message short; a newline would split it).
TEST(FuzzRegressions, ControlCharactersInTheNameAreEscaped) {
    try {
        load_gltf_memory("{", {}, "a\nb\tc.gltf");
        FAIL() << "loaded";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("a\\nb\\tc.gltf: byte ", 0), 0u) << e.what();
    }
    try {
        load_gltf(std::string("/nonexistent/x\ny.gltf"));
        FAIL() << "loaded";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "/nonexistent/x\\ny.gltf: no such file");
    }
}

}  // namespace
}  // namespace ds::scene
