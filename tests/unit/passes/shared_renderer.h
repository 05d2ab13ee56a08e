#pragma once
// One validated Renderer per test suite: device and pipeline creation dominate on lavapipe.
// Every test must leave the validation-message count at zero.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "renderer/renderer.h"

namespace ds::test {

// "name=value" each, through the registry (a bad one throws UsageError).
inline Settings settings_of(const std::vector<std::string>& assignments) {
    Settings settings;
    for (const std::string& a : assignments) settings.apply(a);
    return settings;
}

class SharedRenderer : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        RendererOptions options;
        options.validate = true;
        renderer_ = std::make_unique<Renderer>(options);
    }
    static void TearDownTestSuite() { renderer_.reset(); }
    void TearDown() override { EXPECT_EQ(renderer_->validation_message_count(), 0u); }

    static inline std::unique_ptr<Renderer> renderer_;
};

}  // namespace ds::test
