#pragma once
// One validated Renderer per test suite: device and pipeline creation dominate on lavapipe.
// Every test must leave the validation-message count at zero.
#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "renderer/renderer.h"
#include "renderer/scene/loader.h"

namespace ds::test {

// "name=value" each, through the registry (a bad one throws UsageError).
inline Settings settings_of(const std::vector<std::string>& assignments) {
    Settings settings;
    for (const std::string& a : assignments) settings.apply(a);
    return settings;
}

// Names of the frame's own passes (role frame: no clear or read-back), in execution order.
inline std::vector<std::string> names(const FrameResult& f) {
    std::vector<std::string> out;
    for (const PassResult& p : f.passes)
        if (p.role == graph::PassRole::Frame) out.push_back(p.name);
    return out;
}

// Pixels where some colour channel differs by more than `tolerance`.
inline size_t differing_pixels(const FrameResult& a, const FrameResult& b, int tolerance) {
    size_t n = 0;
    for (size_t i = 0; i + 3 < a.rgba8.size(); i += 4)
        for (size_t c = 0; c < 3; ++c)
            if (std::abs(int(a.rgba8[i + c]) - int(b.rgba8[i + c])) > tolerance) {
                ++n;
                break;
            }
    return n;
}

class SharedRenderer : public ::testing::Test {
  protected:
    static void SetUpTestSuite() { guarded(create_renderer); }
    // The renderer's shutdown runs the validation layer's leak check (objects never
    // destroyed, reported at vkDestroyDevice): a message there fails the suite.
    static void TearDownTestSuite() {
        if (renderer_) {
            renderer_->shutdown();
            EXPECT_EQ(renderer_->validation_message_count(), 0u)
                << "validation messages at teardown (printed above)";
        }
        renderer_.reset();
        setup_error_.clear();
    }
    void SetUp() override {
        if (!setup_error_.empty()) GTEST_FAIL() << "the suite's set-up failed: " << setup_error_;
    }
    void TearDown() override {
        if (renderer_) {
            EXPECT_EQ(renderer_->validation_message_count(), 0u);
        }
    }

    static void create_renderer() {
        RendererOptions options;
        options.validate = true;
        renderer_ = std::make_unique<Renderer>(options);
    }
    // A throwing SetUpTestSuite makes GoogleTest report the suite's tests as skipped: a
    // fixture's set-up runs in here instead, and every test then fails with the error.
    template <typename SetUpFn>
    static void guarded(SetUpFn&& set_up) {
        try {
            set_up();
        } catch (const std::exception& e) {
            setup_error_ = e.what();
        }
    }

    static inline std::unique_ptr<Renderer> renderer_;
    static inline std::string setup_error_;
};

// SharedRenderer with one scene for the whole suite: SetUpTestSuite() of a fixture calls
// set_up_with(name); the scene is scene_.
class SharedScene : public SharedRenderer {
  protected:
    static void set_up_with(const char* name) {
        guarded([name] {
            create_renderer();
            scene_ = std::make_unique<scene::Scene>(scene::load_scene(name, Settings{}));
            renderer_->set_scene(*scene_);
        });
    }
    static void TearDownTestSuite() {
        scene_.reset();
        SharedRenderer::TearDownTestSuite();
    }

    static inline std::unique_ptr<scene::Scene> scene_;
};

// SharedRenderer whose tests pick their scene: render() loads it when it changes (scene
// settings come from the first render's settings).
class SceneSwitching : public SharedRenderer {
  protected:
    FrameResult render(const std::string& scene_name, const std::vector<std::string>& settings,
                       uint32_t width, uint32_t height, ReadBack read_back,
                       const InspectRequest& inspect = {}) {
        const Settings s = settings_of(settings);
        if (scene_name != loaded_) {
            scene_ = scene::load_scene(scene_name, s);
            renderer_->set_scene(scene_);
            loaded_ = scene_name;
        }
        return renderer_->render(
            scene_.camera, s,
            {.width = width, .height = height, .read_back = read_back, .inspect = {inspect}});
    }

    scene::Scene scene_;
    std::string loaded_;
};

}  // namespace ds::test
