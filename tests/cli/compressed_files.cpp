#include "tests/cli/compressed_files.h"

#include <gtest/gtest.h>

#include "tests/support/run_process.h"

namespace ds::test {

namespace fs = std::filesystem;

fs::path compressed_folder() {
    static const fs::path dir = [] {
        const fs::path data = fs::path(DS_SOURCE_DIR) / "tests/data/compressed";
        const fs::path d =
            fresh_dir(std::string("compressed-") +
                      ::testing::UnitTest::GetInstance()->current_test_info()->name());
        EXPECT_EQ(run_depthscope("export-scene atrium " + (d / "atrium.gltf").string()).exit_code,
                  0);
        for (const auto& entry : fs::directory_iterator(data))
            if (entry.path().extension() != ".md")
                fs::copy_file(entry.path(), d / entry.path().filename());
        return d;
    }();
    return dir;
}

}  // namespace ds::test
