// triangle_size=on through the Renderer facade, validation on. A scene of known triangles —
// large ones partly off screen, sub-pixel ones (two instances of one mesh), one with two
// corners behind the eye and one with a corner between the eye and the near plane — rendered
// at msaa 1 and 4 and with prepass_mode=depth: every covered pixel's area against the area of
// the triangle surface_id names there, computed here in double precision from the same
// inputs (float positions, model matrices, view and projection); the histogram against the
// image, bin by bin, and against the pixels surface_id covers.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "renderer/frame/frame_uniforms.h"
#include "renderer/passes/triangle_size.h"
#include "renderer/renderer.h"
#include "renderer/scene/loader.h"
#include "tests/gpu/passes/shared_renderer.h"

namespace {

using namespace ds;

constexpr uint32_t kWidth = 256, kHeight = 160;
constexpr double kTinyDepth = 4.0;  // view-space distance of the sub-pixel triangles

// Float rounds each step to 2^-24 (6e-8) of its value; the shader keeps the triangle relative
// to one corner, so its few dozen operations leave errors of about 1e-6 of the area (measured
// here: the test prints the largest). 1e-4 is far above that and far below what a wrong area
// gives: no near-plane clip (checked below to be off by more than 10%), a wrong corner, the
// wrong instance's matrix, half or twice the shoelace sum.
constexpr double kMaxRelativeError = 1e-4;

scene::Camera test_camera() {
    scene::Camera c;
    c.position = {30.0f, 4.0f, 40.0f};
    c.forward = glm::normalize(glm::vec3(-0.3f, -0.05f, -1.0f));
    c.up = glm::normalize(glm::cross(glm::cross(c.forward, glm::vec3(0, 1, 0)), c.forward));
    c.yfov = 0.9f;
    c.znear = 0.25f;
    c.zfar = 200.0f;
    return c;
}

// The frame's matrices as the renderer builds them (float), widened.
glm::dmat4 view_of(const scene::Camera& c) {
    return glm::dmat4(c.view());
}
glm::dmat4 projection_of(const scene::Camera& c, bool reverse_z) {
    return glm::dmat4(
        perspective(c.yfov, float(kWidth) / float(kHeight), c.znear, c.zfar, reverse_z));
}

// View space of the point at pixel (x, y) (top-left origin), `depth` in front of the eye.
glm::dvec3 view_at_pixel(const scene::Camera& c, double x, double y, double depth) {
    const double t = std::tan(double(c.yfov) * 0.5);
    const double aspect = double(float(kWidth) / float(kHeight));
    return {(x / kWidth * 2.0 - 1.0) * aspect * depth * t, -(y / kHeight * 2.0 - 1.0) * depth * t,
            -depth};
}

// A mesh placed by `world` whose triangles are the view-space `corners` (three per triangle).
scene::Mesh mesh_from_view(const std::string& name, const scene::Camera& c, const glm::mat4& world,
                           const std::vector<glm::dvec3>& corners) {
    const glm::dmat4 to_local = glm::inverse(view_of(c) * glm::dmat4(world));
    scene::Mesh m;
    m.name = name;
    for (const glm::dvec3& v : corners) {
        const glm::vec3 p(to_local * glm::dvec4(v, 1.0));
        m.vertices.push_back({p, {0, 0, 1}, {0, 0}, {1, 0, 0, 1}});
        m.bounds.extend(p);
    }
    // Each triangle's corners in a rotated order, so that index order matters.
    for (uint32_t t = 0; t < corners.size() / 3; ++t)
        for (uint32_t k : {1u, 2u, 0u}) m.indices.push_back(3 * t + k);
    return m;
}

// Sub-pixel and small triangles centred on pixel centres of a 12 x 6 grid, half-sizes from
// 0.3 px (0.18 px²) growing by 3.5% each (up to 24 px²); corners at pixel offsets (-a, -a),
// (a, -a), (0, a), so each covers its centre with a margin of at least 0.13 px.
std::vector<glm::dvec3> tiny_corners(const scene::Camera& c) {
    std::vector<glm::dvec3> out;
    for (int k = 0; k < 72; ++k) {
        const double cx = 20.5 + 8 * (k % 12), cy = 20.5 + 8 * (k / 12);
        const double a = 0.3 * std::pow(1.035, k);
        for (const glm::dvec2 o : {glm::dvec2(-a, -a), glm::dvec2(a, -a), glm::dvec2(0, a)})
            out.push_back(view_at_pixel(c, cx + o.x, cy + o.y, kTinyDepth));
    }
    return out;
}

// The instances, in scene order.
enum Instance : uint32_t { kBackdrop, kTiny, kTinyShifted, kFloor, kSlant, kInstances };

glm::mat4 tiny_world() {
    return glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(20.0f, 1.0f, 30.0f)), 0.4f,
                       glm::vec3(0.2f, 1.0f, 0.1f));
}

// The tiny mesh again, moved 130 px right in the view at kTinyDepth.
glm::mat4 tiny_shifted_world(const scene::Camera& c) {
    const glm::dvec3 shift =
        view_at_pixel(c, 130.0, 0.0, kTinyDepth) - view_at_pixel(c, 0.0, 0.0, kTinyDepth);
    const glm::dmat4 v = view_of(c);
    return glm::mat4(glm::inverse(v) * glm::translate(glm::dmat4(1.0), shift) * v *
                     glm::dmat4(tiny_world()));
}

scene::Scene triangle_scene() {
    const scene::Camera c = test_camera();
    scene::Scene s;
    s.name = "triangles";
    scene::Material m;
    m.name = "grey";
    m.double_sided = true;
    s.materials = {m};
    s.samplers = {scene::Sampler{}};
    const glm::mat4 backdrop_world =
        glm::scale(glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(5.0f, -2.0f, 3.0f)), 0.3f,
                               glm::vec3(0, 1, 0)),
                   glm::vec3(1.5f));
    const glm::mat4 floor_world = glm::translate(glm::mat4(1.0f), glm::vec3(-3.0f, 0.5f, 2.0f));
    const glm::mat4 slant_world = glm::rotate(glm::mat4(1.0f), -0.7f, glm::vec3(1, 0, 0));
    // Two tilted triangles well off screen on several sides, far away.
    const std::vector<glm::dvec3> backdrop = {
        view_at_pixel(c, -40, -30, 60), view_at_pixel(c, 180, -20, 55),
        view_at_pixel(c, -30, 170, 65), view_at_pixel(c, 200, 10, 50),
        view_at_pixel(c, 300, 150, 52), view_at_pixel(c, 140, 150, 48)};
    // A floor triangle with two corners behind the eye; a slanted one with a corner between
    // the eye and the near plane (z = -0.1 > -znear).
    const std::vector<glm::dvec3> floor = {{-4.0, -1.5, 2.0}, {4.0, -1.5, 2.0}, {0.5, -1.5, -40.0}};
    const std::vector<glm::dvec3> slant = {{0.1, 0.6, -0.1}, {3.0, 0.2, -6.0}, {2.5, 2.5, -8.0}};
    s.meshes = {mesh_from_view("backdrop", c, backdrop_world, backdrop),
                mesh_from_view("tiny", c, tiny_world(), tiny_corners(c)),
                mesh_from_view("floor", c, floor_world, floor),
                mesh_from_view("slant", c, slant_world, slant)};
    s.instances = {{0, backdrop_world, "backdrop"},
                   {1, tiny_world(), "tiny"},
                   {1, tiny_shifted_world(c), "tiny_shifted"},
                   {2, floor_world, "floor"},
                   {3, slant_world, "slant"}};
    s.draw_groups = {{0, scene::AlphaMode::Opaque, true, 0, 1},
                     {1, scene::AlphaMode::Opaque, true, 1, 2},
                     {2, scene::AlphaMode::Opaque, true, 3, 1},
                     {3, scene::AlphaMode::Opaque, true, 4, 1}};
    for (const scene::Instance& inst : s.instances) {
        const scene::Bounds& b = s.meshes[inst.mesh].bounds;
        s.bounds.extend(glm::vec3(inst.world * glm::vec4(b.min, 1.0f)));
        s.bounds.extend(glm::vec3(inst.world * glm::vec4(b.max, 1.0f)));
    }
    s.camera = c;
    return s;
}

// The reference: view-space corners clipped against z = -znear (Sutherland-Hodgman), each
// remaining corner projected on its own to pixels, the shoelace sum. `clip` false skips the
// clipping (what a wrong shader might do).
double reference_area(const std::vector<glm::dvec3>& view, const glm::dmat4& projection,
                      double znear, bool clip = true) {
    std::vector<glm::dvec3> poly;
    for (size_t k = 0; k < view.size(); ++k) {
        const glm::dvec3 a = view[k], b = view[(k + 1) % view.size()];
        const bool in_a = !clip || a.z <= -znear, in_b = !clip || b.z <= -znear;
        if (in_a) poly.push_back(a);
        if (in_a != in_b) poly.push_back(a + (b - a) * ((-znear - a.z) / (b.z - a.z)));
    }
    std::vector<glm::dvec2> px;
    for (const glm::dvec3& v : poly) {
        const glm::dvec4 c = projection * glm::dvec4(v, 1.0);
        px.push_back((glm::dvec2(c) / c.w * 0.5 + 0.5) * glm::dvec2(kWidth, kHeight));
    }
    double twice = 0.0;
    for (size_t k = 0; k < px.size(); ++k) {
        const glm::dvec2 a = px[k], b = px[(k + 1) % px.size()];
        twice += a.x * b.y - b.x * a.y;
    }
    return 0.5 * std::abs(twice);
}

// Triangle `triangle` of instance `instance` in view space, from the scene's float data.
std::vector<glm::dvec3> view_triangle(const scene::Scene& s, uint32_t instance, uint32_t triangle) {
    const scene::Instance& inst = s.instances.at(instance);
    const scene::Mesh& mesh = s.meshes.at(inst.mesh);
    const glm::dmat4 model_view = view_of(s.camera) * glm::dmat4(inst.world);
    std::vector<glm::dvec3> out;
    for (uint32_t k = 0; k < 3; ++k) {
        const glm::vec3 p = mesh.vertices.at(mesh.indices.at(3 * triangle + k)).position;
        out.emplace_back(model_view * glm::dvec4(glm::dvec3(p), 1.0));
    }
    return out;
}

// floor(log2(area)) clamped to the result's exponents, as the shader bins.
size_t bin_of(float area) {
    int exponent = TriangleSizeResult::kMinExponent;
    if (area > 0.0f) {
        std::frexp(area, &exponent);  // area = m * 2^exponent, m in [0.5, 1)
        exponent -= 1;
    }
    exponent =
        std::clamp(exponent, TriangleSizeResult::kMinExponent, TriangleSizeResult::kMaxExponent);
    return size_t(exponent - TriangleSizeResult::kMinExponent);
}

const InspectedImage* image(const FrameResult& f, const std::string& name) {
    if (f.inspected && f.inspected->name == name) return &*f.inspected;
    for (const InspectedImage& i : f.overlays)
        if (i.name == name) return &i;
    return nullptr;
}

class TriangleSize : public test::SharedRenderer {
  protected:
    static void SetUpTestSuite() {
        guarded([] {
            create_renderer();
            scene_ = std::make_unique<scene::Scene>(triangle_scene());
            renderer_->set_scene(*scene_);
        });
    }
    static void TearDownTestSuite() {
        scene_.reset();
        SharedRenderer::TearDownTestSuite();
    }

    FrameResult render(std::vector<std::string> settings) {
        settings.push_back("triangle_size=on");
        const InspectRequest asks[] = {{"triangle_size"}, {"surface_id"}};
        return renderer_->render(scene_->camera, test::settings_of(settings),
                                 {.width = kWidth,
                                  .height = kHeight,
                                  .read_back = ReadBack::Yes,
                                  .inspect = {std::begin(asks), std::end(asks)}});
    }

    // Every pixel against the reference and the histogram against the image.
    void check(const std::vector<std::string>& settings);

    static inline std::unique_ptr<scene::Scene> scene_;
};

// What the images say, pixel by pixel, against the reference.
struct Tally {
    std::array<uint64_t, TriangleSizeResult::kBins> bins{};
    std::map<uint32_t, uint64_t> pixels_of;  // per instance
    uint64_t covered = 0, under_1 = 0, under_4 = 0, wrong = 0;
    double worst = 0.0;  // relative error
};

Tally tally(const scene::Scene& s, const Renderer& renderer, const InspectedImage& sizes,
            const InspectedImage& ids) {
    const glm::dmat4 projection = projection_of(s.camera, true);
    Tally t;
    for (size_t i = 0; i < size_t(kWidth) * kHeight; ++i) {
        const uint32_t id = uint32_t(ids.texels[i * 4]);
        const float area = sizes.texels[i * 4];
        if (id == 0) {
            EXPECT_EQ(area, 0.0f) << "pixel " << i << ": nothing drawn";
            continue;
        }
        const std::optional<SurfaceInfo> info = renderer.describe_surface(id);
        if (!info) {
            ADD_FAILURE() << "pixel " << i << ": id " << id << " names no surface";
            continue;
        }
        const double expected = reference_area(view_triangle(s, info->instance, info->triangle),
                                               projection, s.camera.znear);
        const double error = std::abs(double(area) - expected) / expected;
        t.worst = std::max(t.worst, error);
        if (error >= kMaxRelativeError && t.wrong++ < 5)
            ADD_FAILURE() << "pixel " << i % kWidth << "," << i / kWidth << ": " << area
                          << " px², expected " << expected << " (" << info->name.node
                          << " triangle " << info->triangle << ")";
        ++t.covered;
        ++t.pixels_of[info->instance];
        t.under_1 += area < 1.0f;
        t.under_4 += area < 4.0f;
        ++t.bins[bin_of(area)];
    }
    return t;
}

void TriangleSize::check(const std::vector<std::string>& settings) {
    std::string what;
    for (const std::string& s : settings) what += s + " ";
    if (what.empty()) what = "defaults ";
    SCOPED_TRACE(what);
    const FrameResult f = render(settings);
    ASSERT_TRUE(f.find<TriangleSizeResult>());
    const InspectedImage* sizes = image(f, "triangle_size");
    const InspectedImage* ids = image(f, "surface_id");
    ASSERT_TRUE(sizes && ids);
    ASSERT_EQ(sizes->width * sizes->height, kWidth * kHeight);
    Tally t = tally(*scene_, *renderer_, *sizes, *ids);
    EXPECT_EQ(t.wrong, 0u) << "pixels off by " << kMaxRelativeError << " or more";
    std::cout << "[          ] " << what << ": " << t.covered
              << " covered pixels checked, largest relative error " << t.worst << "\n";
    for (uint32_t instance = 0; instance < kInstances; ++instance)
        EXPECT_GT(t.pixels_of[instance], 0u) << scene_->instances[instance].node << " wins none";
    // The sub-pixel triangles are there: 42 pixels under 1 px² at 1x on lavapipe (the H200 meets
    // the same bound); at 4x sample 0 lies off the pixel centre and which sub-pixel triangles
    // it meets depends on the device's rasteriser (30 on lavapipe, 8 on the H200).
    EXPECT_GE(t.under_1, settings == std::vector<std::string>{"msaa=4"} ? 5u : 20u);
    EXPECT_GE(t.under_4 - t.under_1, 50u);
    const TriangleSizeResult& r = *f.find<TriangleSizeResult>();
    EXPECT_EQ(r.covered, t.covered);
    EXPECT_EQ(r.under_1, t.under_1);
    EXPECT_EQ(r.under_4, t.under_4);
    for (size_t b = 0; b < TriangleSizeResult::kBins; ++b)
        EXPECT_EQ(r.bins[b], t.bins[b]) << "bin " << b;
}

TEST_F(TriangleSize, EveryPixelHoldsItsTrianglesArea) {
    check({});
}

TEST_F(TriangleSize, MultisampledSampleZerosWinner) {
    check({"msaa=4"});
}

TEST_F(TriangleSize, DepthOnlyPrepass) {
    check({"prepass_mode=depth"});
}

// The check above can fail: without the near-plane clip the floor (corners behind the eye)
// and the slanted triangle (a corner inside the near plane) would be off by far more than
// the tolerance.
TEST_F(TriangleSize, NearPlaneClipMatters) {
    const glm::dmat4 projection = projection_of(scene_->camera, true);
    const double znear = scene_->camera.znear;
    for (uint32_t instance : {kFloor, kSlant}) {
        const std::vector<glm::dvec3> v = view_triangle(*scene_, instance, 0);
        const double clipped = reference_area(v, projection, znear);
        const double unclipped = reference_area(v, projection, znear, /*clip=*/false);
        EXPECT_GT(std::abs(unclipped - clipped) / clipped, 0.1) << instance;
    }
}

TEST_F(TriangleSize, OffAddsNothingAndSkipsSay) {
    const FrameResult off =
        renderer_->render(scene_->camera, Settings{},
                          {.width = kWidth, .height = kHeight, .read_back = ReadBack::Yes});
    EXPECT_FALSE(off.find<TriangleSizeResult>());
    for (const ResourceSummary& res : off.resources) EXPECT_NE(res.name, "triangle_size");
    const FrameResult no_prepass = render({"prepass=off"});
    EXPECT_FALSE(no_prepass.find<TriangleSizeResult>());
    ASSERT_FALSE(no_prepass.skipped.empty());
    EXPECT_NE(std::find(no_prepass.skipped.begin(), no_prepass.skipped.end(),
                        "triangle_size: skipped (prepass off)"),
              no_prepass.skipped.end());
    const FrameResult subpass = render({"render_path=subpass"});
    EXPECT_FALSE(subpass.find<TriangleSizeResult>());
    EXPECT_NE(std::find_if(subpass.skipped.begin(), subpass.skipped.end(),
                           [](const std::string& s) {
                               return s.starts_with("triangle_size: skipped (render_path=subpass");
                           }),
              subpass.skipped.end());
}

// On the atrium (masked foliage, many instances): the histogram covers exactly the pixels the
// depth says are covered, and the image's pixels under 1 and 4 px² are the report's.
TEST_F(TriangleSize, AtriumHistogramCoversTheDepthsPixels) {
    const scene::Scene atrium = scene::load_scene("atrium", Settings{});
    renderer_->set_scene(atrium);
    const InspectRequest asks[] = {{"triangle_size"}, {"surface_id"}};
    const FrameResult f = renderer_->render(atrium.camera, test::settings_of({"triangle_size=on"}),
                                            {.width = 320,
                                             .height = 180,
                                             .read_back = ReadBack::Yes,
                                             .inspect = {std::begin(asks), std::end(asks)}});
    renderer_->set_scene(*scene_);
    const InspectedImage* sizes = image(f, "triangle_size");
    const InspectedImage* ids = image(f, "surface_id");
    ASSERT_TRUE(f.find<TriangleSizeResult>() && f.covered_pixels && sizes && ids);
    EXPECT_EQ(f.find<TriangleSizeResult>()->covered, *f.covered_pixels);
    uint64_t under_1 = 0, under_4 = 0;
    for (size_t i = 0; i < sizes->texels.size(); i += 4) {
        if (ids->texels[i] == 0.0f) continue;
        under_1 += sizes->texels[i] < 1.0f;
        under_4 += sizes->texels[i] < 4.0f;
    }
    EXPECT_EQ(f.find<TriangleSizeResult>()->under_1, under_1);
    EXPECT_EQ(f.find<TriangleSizeResult>()->under_4, under_4);
}

// The report section: bounds of the first (from 0) and last (to null) bins, only non-empty
// bins, the counts under 1 and 4 px² exact sums of the bins below.
TEST(TriangleSizeJson, BinsAndCounts) {
    std::array<uint32_t, TriangleSizeResult::kBins> counts{};
    counts[0] = 3;                                              // [0, 2^-9)
    counts[size_t(-1 - TriangleSizeResult::kMinExponent)] = 5;  // [0.5, 1)
    counts[size_t(1 - TriangleSizeResult::kMinExponent)] = 7;   // [2, 4)
    counts[size_t(2 - TriangleSizeResult::kMinExponent)] = 11;  // [4, 8)
    counts.back() = 13;                                         // [2^30, inf)
    const TriangleSizeResult r = TriangleSizeResult::from_counts(counts);
    EXPECT_EQ(r.covered, 39u);
    EXPECT_EQ(r.under_1, 8u);
    EXPECT_EQ(r.under_4, 15u);
    const nlohmann::json j = passes::triangle_size_json(r);
    EXPECT_EQ(j["covered_pixels"], 39);
    EXPECT_EQ(j["pixels_under_1px2"], 8);
    EXPECT_EQ(j["pixels_under_4px2"], 15);
    ASSERT_EQ(j["bins"].size(), 5u);
    EXPECT_EQ(j["bins"][0], (nlohmann::json{{"from", 0.0}, {"to", 1.0 / 512}, {"pixels", 3}}));
    EXPECT_EQ(j["bins"][1], (nlohmann::json{{"from", 0.5}, {"to", 1.0}, {"pixels", 5}}));
    EXPECT_EQ(j["bins"][3], (nlohmann::json{{"from", 4.0}, {"to", 8.0}, {"pixels", 11}}));
    EXPECT_EQ(j["bins"][4],
              (nlohmann::json{{"from", 1073741824.0}, {"to", nullptr}, {"pixels", 13}}));
}

}  // namespace
