// The MSAA sample view (issue 15) through the inspector, offscreen on lavapipe with validation:
// zoomed in on `edges` at msaa=4, a silhouette pixel's sample list holds samples of two
// surfaces with their depths (the backdrop's where the scene's plane puts it, the nearer
// surface's in front), the viewer draws every sample in its surface's colour, and a pick
// lists the pixel's samples and each prepass triangle's coverage.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "capture/image_writer.h"
#include "renderer/passes/msaa_samples.h"
#include "renderer/passes/pixel_history.h"
#include "renderer/view/decode.h"
#include "tests/unit/ui/inspector_ui.h"

namespace ds::test {
namespace {

using ui::HeadlessInput;
using ui::PixelSampleList;

class SampleView : public InspectorUi {};

constexpr float kBackdropZ = -8.0f;  // edges.cpp: the backdrop quad's plane

// The view-space depth at which the ray through frame point (fx, fy) (pixels, y down) meets the
// plane z = plane_z, for the frame's projection (frame_uniforms.cpp: Vulkan's y down).
float depth_on_plane(const scene::Camera& cam, VkExtent2D size, float fx, float fy, float plane_z) {
    const float f = 1.0f / std::tan(cam.yfov * 0.5f);
    const float aspect = float(size.width) / float(size.height);
    const float nx = 2.0f * fx / float(size.width) - 1.0f;
    const float ny = 2.0f * fy / float(size.height) - 1.0f;
    const glm::vec3 fwd = glm::normalize(cam.forward);
    const glm::vec3 right = glm::normalize(glm::cross(fwd, cam.up));
    const glm::vec3 up = glm::cross(right, fwd);
    const glm::vec3 dir = fwd + (nx * aspect / f) * right - (ny / f) * up;  // per unit of depth
    return (plane_z - cam.position.z) / dir.z;
}

struct Silhouette {
    PixelSampleList list;
    uint32_t backdrop = 0, other = 0;  // surface ids
};

// A pixel of the read rectangle whose samples hold the backdrop and one other instance: found
// in the frame's own samples, never a fixed position.
// Only texels the viewer shows, above the panels stacked over its lower part (the rectangle
// read has a margin around them).
std::optional<Silhouette> find_silhouette(ui::HeadlessUi& ui) {
    const ui::Inspector& in = ui.inspector();
    const MsaaSamples* s = in.shown_samples();
    if (!s) return std::nullopt;
    const ui::ViewerState& v = in.viewer();
    const ui::ViewerBlit b = in.viewer_blit();
    const float zoom = b.dst_w / b.src_w;
    auto shown = [&](uint32_t x, uint32_t y) {
        const glm::vec2 at{b.dst_x + (float(x) + 0.5f - b.src_x) * zoom,
                           b.dst_y + (float(y) + 0.5f - b.src_y) * zoom};
        return at.x > v.x + 8 && at.x < v.x + v.w - 8 && at.y > v.y + 8 &&
               at.y < 0.5f * float(ui.size().height);
    };
    for (uint32_t y = s->rect.y; y < s->rect.y + s->rect.height; ++y)
        for (uint32_t x = s->rect.x; x < s->rect.x + s->rect.width; ++x) {
            if (!shown(x, y)) continue;
            std::optional<PixelSampleList> list = in.sample_list_at(x, y);
            if (!list) continue;
            Silhouette found{*list, 0, 0};
            for (const ui::SurfaceSamples& c : list->surfaces) {
                if (!c.info) continue;
                if (c.info->name.mesh == "backdrop")
                    found.backdrop = c.surface;
                else
                    found.other = c.surface;
            }
            if (found.backdrop && found.other) return found;
        }
    return std::nullopt;
}

// Zoomed in at a few places of the frame until the rectangle holds a silhouette against the
// backdrop (the grating and the rods stand in front of it).
std::optional<Silhouette> zoom_to_silhouette(ui::HeadlessUi& ui) {
    ui::Inspector& in = ui.inspector();
    for (const glm::vec2 centre : {glm::vec2(0.5f, 0.45f), glm::vec2(0.3f, 0.3f),
                                   glm::vec2(0.7f, 0.3f), glm::vec2(0.5f, 0.2f)}) {
        in.viewer().zoom = 16.0f;
        in.viewer().centre = centre;
        ui.frame();
        if (std::optional<Silhouette> found = find_silhouette(ui)) return found;
    }
    return std::nullopt;
}

TEST_F(SampleView, ASilhouettePixelListsTwoSurfacesWithTheirDepths) {
    Settings settings;
    settings.set("msaa", "4");
    auto ui = open("edges", settings, {960, 540});
    ui::Inspector& in = ui->inspector();
    EXPECT_FALSE(in.frame().find<MsaaSamples>()) << "zoomed out: no samples asked";
    const std::optional<Silhouette> found = zoom_to_silhouette(*ui);
    ASSERT_TRUE(in.frame().find<MsaaSamples>()) << in.message();
    ASSERT_TRUE(found) << "no backdrop silhouette in the zoomed views";
    const PixelSampleList& list = found->list;
    EXPECT_EQ(list.samples, 4u);
    ASSERT_EQ(list.rows.size(), 4u);
    EXPECT_TRUE(list.surface_ids);
    EXPECT_TRUE(list.standard_positions);  // lavapipe: standardSampleLocations
    const VkExtent2D size{in.frame().width, in.frame().height};
    const DepthResult& depth = *in.frame().depth;
    float backdrop_depth = 0, other_depth = 0;
    for (const ui::SampleRow& row : list.rows) {
        ASSERT_TRUE(row.surface == found->backdrop || row.surface == found->other ||
                    row.surface == 0)
            << row.surface;
        ASSERT_TRUE(row.surface == 0 || row.info) << row.surface;
        EXPECT_EQ(row.linear_depth,
                  view::linear_depth(row.depth, depth.reverse_z, depth.znear, depth.zfar));
        if (row.surface == found->backdrop) {
            // Where the backdrop's plane is along this sample's ray (its own position).
            const float want = depth_on_plane(in.camera(), size, float(list.x) + row.position.x,
                                              float(list.y) + row.position.y, kBackdropZ);
            EXPECT_NEAR(row.linear_depth, want, want * 0.005f) << "sample " << row.index;
            backdrop_depth = row.linear_depth;
        } else if (row.surface == found->other) {
            other_depth = row.linear_depth;
        }
    }
    std::printf("silhouette pixel (%u, %u): backdrop at %.3f, %s at %.3f\n", list.x, list.y,
                backdrop_depth, in.describe_surface(found->other)->name.mesh.c_str(), other_depth);
    // Everything else in edges stands well in front of the backdrop (4.5 m at least).
    EXPECT_GT(other_depth, 0.0f);
    EXPECT_LT(other_depth, backdrop_depth - 2.0f);
    // Raw depth orders them the other way round with reverse-Z (nearer: greater).
    for (const ui::SampleRow& a : list.rows)
        for (const ui::SampleRow& b : list.rows)
            if (a.surface == found->other && b.surface == found->backdrop) {
                EXPECT_GT(a.depth, b.depth);
            }
    // The two surfaces' masks split the four samples between them.
    uint32_t masks = 0;
    for (const ui::SurfaceSamples& c : list.surfaces) {
        EXPECT_EQ(masks & c.mask, 0u);
        masks |= c.mask;
    }
    EXPECT_EQ(masks, 0xfu);
    // Samples read only where asked: the frame's settings stay as they were.
    EXPECT_EQ(in.settings().get("surface_id"), "off");
}

// The composite: each sample of the silhouette pixel is a square in its surface's colour (the
// surface_id view's) at its standard position inside the pixel; hovering lists the samples;
// zoomed out the frame asks for none (no msaa_samples pass).
TEST_F(SampleView, TheViewerDrawsEachSampleInItsSurfacesColour) {
    Settings settings;
    settings.set("msaa", "4");
    auto ui = open("edges", settings, {960, 540});
    ui::Inspector& in = ui->inspector();
    const std::optional<Silhouette> found = zoom_to_silhouette(*ui);
    ASSERT_TRUE(found);
    bool pass = false;
    for (const PassResult& p : in.frame().passes)
        pass = pass || (p.name == "msaa_samples" && p.role == graph::PassRole::ReadBack);
    EXPECT_TRUE(pass);
    const std::vector<uint8_t> pixels = ui->frame();  // the cursor outside: no tooltip
    const VkExtent2D target = ui->size();
    ui::BlitRegion r{};
    ASSERT_TRUE(ui::clip_blit(in.viewer_blit(), {target.width, target.height}, r));
    const float side = float(r.dx1 - r.dx0) / float(r.sx1 - r.sx0);
    EXPECT_FLOAT_EQ(side, 16.0f);
    const PixelSampleList& list = found->list;
    for (const ui::SampleRow& row : list.rows) {
        const float cx = float(r.dx0) + (float(list.x) - float(r.sx0) + row.position.x) * side;
        const float cy = float(r.dy0) + (float(list.y) - float(r.sy0) + row.position.y) * side;
        const size_t at = (size_t(std::floor(cy)) * target.width + size_t(std::floor(cx))) * 4;
        const std::array<uint8_t, 3> want =
            row.surface ? view::surface_color(row.surface) : view::kSkyColor;
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(int(pixels[at + c]), int(want[c]), 1) << "sample " << row.index;
    }
    // Hovering the pixel: the tooltip lists its samples (drawn; the PNG shows it).
    HeadlessInput hover;
    hover.mouse = screen_of(*ui, list.x, list.y);
    ui->frame(hover);
    const std::vector<uint8_t> hovered = ui->frame(hover);
    ASSERT_TRUE(in.viewer().hover);
    EXPECT_EQ(in.viewer().hover->x, list.x);
    EXPECT_EQ(in.viewer().hover->y, list.y);
    if (const char* png = std::getenv("DS_SAMPLES_PNG")) {  // with the tooltip, and without
        capture::write_png_rgba8(png, target.width, target.height, hovered);
        capture::write_png_rgba8(std::string(png) + ".plain.png", target.width, target.height,
                                 pixels);
    }
    // Zoomed out: no samples asked, none shown.
    in.viewer().zoom = 1.0f;
    ui->frame();
    EXPECT_FALSE(in.frame().find<MsaaSamples>());
    EXPECT_EQ(in.shown_samples(), nullptr);
    for (const PassResult& p : in.frame().passes) EXPECT_NE(p.name, "msaa_samples");
}

// A pick reads the picked pixel's samples with its history: the same samples the view showed,
// and per prepass triangle the samples it was rasterized to and those it kept.
TEST_F(SampleView, APickListsThePixelsSamplesAndCoverage) {
    Settings settings;
    settings.set("msaa", "4");
    auto ui = open("edges", settings, {960, 540});
    ui::Inspector& in = ui->inspector();
    const std::optional<Silhouette> found = zoom_to_silhouette(*ui);
    ASSERT_TRUE(found);
    const PixelSampleList& list = found->list;
    in.queue(ui::PickPixel{list.x, list.y});
    ui->frame();
    ASSERT_TRUE(in.pixel_samples()) << in.pixel_error();
    const std::span<const PixelSample> picked = in.pixel_samples()->pixel(list.x, list.y);
    ASSERT_EQ(picked.size(), 4u);
    for (uint32_t i = 0; i < 4; ++i) {
        EXPECT_EQ(picked[i].surface, list.rows[i].surface) << i;
        EXPECT_EQ(picked[i].depth, list.rows[i].depth) << i;
    }
    const std::vector<ui::CoverageRow> rows = in.pixel_coverage();
    ASSERT_FALSE(rows.empty());
    uint32_t kept = 0;
    bool other_row = false;
    const SurfaceInfo other = *in.describe_surface(found->other);
    for (const ui::CoverageRow& row : rows) {
        EXPECT_EQ(row.kept & ~row.rasterized, 0u) << "kept outside the rasterized coverage";
        EXPECT_EQ(kept & row.kept, 0u);
        kept |= row.kept;
        if (row.instance == other.instance && row.primitive == other.triangle) {
            other_row = true;
            for (const ui::SurfaceSamples& c : list.surfaces)
                if (c.surface == found->other) {
                    EXPECT_EQ(row.kept, c.mask);
                }
        }
    }
    EXPECT_TRUE(other_row);
    EXPECT_EQ(kept, 0xfu);  // every sample is some surface's (the backdrop is behind all)
}

// Alpha to coverage (foliage, msaa=4): a masked card's triangle rasterized to samples it does
// not keep although what holds them at the end is farther than the card there: its alpha cut
// them (the mask before alpha vs after). Candidate pixels come from the sample view: a masked
// surface holding some of the samples, not all.
TEST_F(SampleView, AlphaToCoverageCutsRasterizedSamples) {
    Settings settings;
    settings.set("msaa", "4");
    settings.set("alpha_to_coverage", "on");
    auto ui = open("foliage", settings, {960, 540});
    ui::Inspector& in = ui->inspector();
    constexpr size_t kMaxCandidates = 32;
    std::vector<std::array<uint32_t, 2>> candidates;
    for (const glm::vec2 centre : {glm::vec2(0.5f, 0.5f), glm::vec2(0.35f, 0.45f),
                                   glm::vec2(0.65f, 0.4f), glm::vec2(0.45f, 0.6f)}) {
        in.viewer().zoom = 16.0f;
        in.viewer().centre = centre;
        ui->frame();
        const MsaaSamples* s = in.shown_samples();
        ASSERT_TRUE(s) << in.message();
        for (uint32_t y = s->rect.y;
             y < s->rect.y + s->rect.height && candidates.size() < kMaxCandidates; ++y)
            for (uint32_t x = s->rect.x; x < s->rect.x + s->rect.width; ++x) {
                const std::optional<PixelSampleList> list = in.sample_list_at(x, y);
                if (!list || list->surfaces.size() < 2) continue;
                for (const ui::SurfaceSamples& c : list->surfaces)
                    if (c.info && c.info->name.material.rfind("alpha_ramp", 0) == 0) {
                        candidates.push_back({x, y});
                        break;
                    }
                if (candidates.size() >= kMaxCandidates) break;
            }
        if (candidates.size() >= kMaxCandidates) break;
    }
    ASSERT_FALSE(candidates.empty()) << "no partly covered card pixel in view";
    int cut_by_alpha = 0;
    size_t picked = 0;
    // Until one is found: a device's alpha-to-coverage pattern decides which candidates show
    // it (lavapipe in the first, the H200's dither further on).
    for (const auto& [x, y] : candidates) {
        if (cut_by_alpha > 0) break;
        ++picked;
        in.queue(ui::PickPixel{x, y});
        ui->frame();
        ASSERT_TRUE(in.pixel_history() && in.pixel_samples()) << in.pixel_error();
        const std::span<const PixelSample> end = in.pixel_samples()->pixel(x, y);
        ASSERT_EQ(end.size(), 4u);
        for (const ui::CoverageRow& row : in.pixel_coverage()) {
            EXPECT_EQ(row.kept & ~row.rasterized, 0u);
            if (!row.alpha) continue;  // opaque: the ground, the backdrop
            for (const PixelFragment& f : in.pixel_history()->fragments) {
                const bool mine = f.pass == "depth_prepass" && f.instance == row.instance &&
                                  f.primitive == row.primitive;
                if (!mine || (row.kept >> f.sample) & 1u) continue;
                // Not kept, and what holds the sample is farther (reverse-Z: smaller).
                if (f.depth > end[f.sample].depth) ++cut_by_alpha;
            }
        }
    }
    std::printf("%zu card pixels picked, %d samples cut by alpha to coverage\n", picked,
                cut_by_alpha);
    EXPECT_GT(cut_by_alpha, 0);
}

}  // namespace
}  // namespace ds::test
