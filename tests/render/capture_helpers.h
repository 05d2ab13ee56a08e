#pragma once
// Capture a scene through the real executable and read back final.png + report.json.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/run_process.h"

namespace ds::test {

struct Capture {
    Png image;
    nlohmann::json report;
    std::filesystem::path dir;
};

// Renders `scene` at WxH with --validate and extra args into a fresh folder named `tag`;
// without the graph's images (run_depthscope's --resources none) unless `extra` asks for them.
inline Capture capture(const std::string& tag, const std::string& scene, const std::string& size,
                       const std::string& extra = "") {
    Capture c;
    c.dir = fresh_dir(tag) / "cap";
    auto r = run_depthscope("capture --validate --scene " + scene + " --size " + size + " --out " +
                            c.dir.string() + " " + extra);
    EXPECT_EQ(r.exit_code, 0) << scene << "\n" << r.err;
    if (r.exit_code != 0) return c;
    c.image = read_png(c.dir / "final.png");
    c.report = nlohmann::json::parse(read_file(c.dir / "report.json"), nullptr, false);
    return c;
}

}  // namespace ds::test
