// The zfight detector against the scene's own geometry: the test rasterises every triangle of
// the zfight scene on the host (the GPU's vertex transform in float, pixel-centre coverage and
// screen-space depth interpolation in double), derives for each pair of overlapping surfaces
// the smallest gap in representable steps of each depth configuration, and decides whether
// the pair must fight. zfight.pairs must hold exactly those pairs; for exactly coplanar pairs
// their `pixels` must equal the overlap area the projection gives, edge pixels aside.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "renderer/frame/frame_uniforms.h"
#include "renderer/passes/zfight.h"
#include "renderer/renderer.h"
#include "renderer/scene/loader.h"
#include "tests/gpu/passes/shared_renderer.h"

namespace {

using namespace ds;

constexpr uint32_t kDerivedWidth = 1280, kDerivedHeight = 720;
constexpr uint32_t kSteps = 4;  // zfight_steps' default

struct Config {
    const char* format;
    bool reverse;
};
constexpr std::array<Config, 4> kConfigs = {
    {{"d32f", true}, {"d32f", false}, {"d24", false}, {"d16", false}}};

// Representable steps between two depths in [0, 1], as the shader counts them.
double steps_between(double a, double b, const std::string& format) {
    if (format == "d32f") {
        const auto bits = [](double d) { return double(std::bit_cast<uint32_t>(float(d))); };
        return std::abs(bits(a) - bits(b));
    }
    const double levels = format == "d24" ? 16777215.0 : 65535.0;
    return std::abs(std::round(a * levels) - std::round(b * levels));
}

// One triangle of one instance in screen space: x, y in pixels, z the depth.
struct ScreenTriangle {
    uint32_t instance;
    std::array<glm::dvec3, 3> v;
};

std::vector<ScreenTriangle> project(const scene::Scene& s, bool reverse) {
    const float aspect = float(kDerivedWidth) / float(kDerivedHeight);
    const glm::mat4 vp =
        perspective(s.camera.yfov, aspect, s.camera.znear, s.camera.zfar, reverse) *
        s.camera.view();
    std::vector<ScreenTriangle> out;
    for (uint32_t i = 0; i < s.instances.size(); ++i) {
        const scene::Mesh& mesh = s.meshes[s.instances[i].mesh];
        for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            ScreenTriangle tri{i, {}};
            for (int k = 0; k < 3; ++k) {
                const glm::vec3 p = mesh.vertices[mesh.indices[t + k]].position;
                const glm::vec4 clip = vp * (s.instances[i].world * glm::vec4(p, 1.0f));
                const glm::vec3 ndc = glm::vec3(clip) / clip.w;
                tri.v[k] = {(ndc.x * 0.5 + 0.5) * kDerivedWidth,
                            (ndc.y * 0.5 + 0.5) * kDerivedHeight, ndc.z};
            }
            out.push_back(tri);
        }
    }
    return out;
}

double edge(const glm::dvec3& a, const glm::dvec3& b, double x, double y) {
    return (b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x);
}

// Depth of `t` at the pixel centre (x, y) when the centre is inside it.
std::optional<double> depth_at(const ScreenTriangle& t, double x, double y) {
    const double area = edge(t.v[0], t.v[1], t.v[2].x, t.v[2].y);
    if (area == 0.0) return std::nullopt;
    const double w0 = edge(t.v[1], t.v[2], x, y) / area;
    const double w1 = edge(t.v[2], t.v[0], x, y) / area;
    const double w2 = edge(t.v[0], t.v[1], x, y) / area;
    if (w0 < 0.0 || w1 < 0.0 || w2 < 0.0) return std::nullopt;
    return w0 * t.v[0].z + w1 * t.v[1].z + w2 * t.v[2].z;
}

struct Hit {
    uint32_t instance;
    double depth;
};

// Whether the prepass keeps a fragment at `depth`: the strict nearer-than test against the
// cleared far value, after the format's quantisation (D16 loses surfaces near the far plane).
bool survives(double depth, const Config& c) {
    if (std::string(c.format) == "d32f")
        return c.reverse ? float(depth) > 0.0f : float(depth) < 1.0f;
    const double levels = std::string(c.format) == "d24" ? 16777215.0 : 65535.0;
    const double q = std::round(depth * levels);
    return c.reverse ? q > 0.0 : q < levels;
}

// Every surface the prepass keeps at every pixel centre.
std::vector<std::vector<Hit>> rasterise(const std::vector<ScreenTriangle>& triangles,
                                        const Config& c) {
    std::vector<std::vector<Hit>> hits(size_t(kDerivedWidth) * kDerivedHeight);
    for (const ScreenTriangle& t : triangles) {
        const auto lo = glm::min(glm::min(t.v[0], t.v[1]), t.v[2]);
        const auto hi = glm::max(glm::max(t.v[0], t.v[1]), t.v[2]);
        const int x0 = std::max(0, int(std::floor(lo.x)));
        const int x1 = std::min(int(kDerivedWidth), int(hi.x) + 1);
        const int y0 = std::max(0, int(std::floor(lo.y)));
        const int y1 = std::min(int(kDerivedHeight), int(hi.y) + 1);
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x)
                if (const auto d = depth_at(t, x + 0.5, y + 0.5); d && survives(*d, c))
                    hits[size_t(y) * kDerivedWidth + x].push_back({t.instance, *d});
    }
    return hits;
}

using PairKey = std::pair<uint32_t, uint32_t>;  // instances, lower first

struct Derived {
    double min_steps = 1e30;  // over the pixels both cover
    double min_alone = 1e30;  // ... where no third surface is near either (one of the two won)
    uint64_t overlap = 0;     // pixels both cover
    uint64_t interior = 0;    // ... whose four neighbours both cover too
};

bool covers_both(const std::vector<std::vector<Hit>>& hits, int x, int y, PairKey key) {
    if (x < 0 || y < 0 || x >= int(kDerivedWidth) || y >= int(kDerivedHeight)) return false;
    bool a = false, b = false;
    for (const Hit& h : hits[size_t(y) * kDerivedWidth + x]) {
        a |= h.instance == key.first;
        b |= h.instance == key.second;
    }
    return a && b;
}

// Each pair of surfaces that overlap somewhere: their smallest gap and their overlap.
std::map<PairKey, Derived> derive(const std::vector<std::vector<Hit>>& hits,
                                  const std::string& format) {
    std::map<PairKey, Derived> pairs;
    for (int y = 0; y < int(kDerivedHeight); ++y) {
        for (int x = 0; x < int(kDerivedWidth); ++x) {
            const std::vector<Hit>& here = hits[size_t(y) * kDerivedWidth + x];
            std::set<PairKey> seen;
            for (size_t i = 0; i < here.size(); ++i) {
                for (size_t j = i + 1; j < here.size(); ++j) {
                    if (here[i].instance == here[j].instance) continue;  // a shared edge
                    const PairKey key = std::minmax(here[i].instance, here[j].instance);
                    Derived& d = pairs[key];
                    const double steps = steps_between(here[i].depth, here[j].depth, format);
                    d.min_steps = std::min(d.min_steps, steps);
                    bool alone = true;
                    for (size_t k = 0; k < here.size(); ++k)
                        if (k != i && k != j && here[k].instance != here[i].instance &&
                            here[k].instance != here[j].instance)
                            alone &=
                                steps_between(here[k].depth, here[i].depth, format) > 2 * kSteps &&
                                steps_between(here[k].depth, here[j].depth, format) > 2 * kSteps;
                    if (alone) d.min_alone = std::min(d.min_alone, steps);
                    if (!seen.insert(key).second) continue;
                    ++d.overlap;
                    d.interior +=
                        covers_both(hits, x - 1, y, key) && covers_both(hits, x + 1, y, key) &&
                        covers_both(hits, x, y - 1, key) && covers_both(hits, x, y + 1, key);
                }
            }
        }
    }
    return pairs;
}

// Every vertex of b on the plane of a's first triangle (world space, relative tolerance).
bool coplanar(const scene::Scene& s, uint32_t a, uint32_t b) {
    auto world = [&](uint32_t i, uint32_t v) {
        const scene::Mesh& m = s.meshes[s.instances[i].mesh];
        return glm::dvec3(s.instances[i].world * glm::vec4(m.vertices[v].position, 1.0f));
    };
    const scene::Mesh& ma = s.meshes[s.instances[a].mesh];
    const glm::dvec3 p0 = world(a, ma.indices[0]);
    const glm::dvec3 n =
        glm::normalize(glm::cross(world(a, ma.indices[1]) - p0, world(a, ma.indices[2]) - p0));
    for (uint32_t v = 0; v < s.meshes[s.instances[b].mesh].vertices.size(); ++v)
        if (std::abs(glm::dot(n, world(b, v) - p0)) > 1e-6 * glm::length(p0)) return false;
    return true;
}

// One representable step of the format at depth d, as a depth difference.
double one_step(double d, const std::string& format) {
    if (format == "d32f") return std::abs(double(std::nextafter(float(d), 2.0f)) - float(d));
    return 1.0 / (format == "d24" ? 16777215.0 : 65535.0);
}

// Each hit's gap in scene units is its gap in steps times one step along the pixel's view ray
// (distance^2 (f - n) / (n f) per unit of depth, stretched off the axis), give or take the
// rounding of the two depths (1.5 steps).
void expect_gaps_in_scene_units(const ZfightResult& z, const std::vector<std::vector<Hit>>& hits,
                                const scene::Scene& s, const Config& c) {
    const double n = s.camera.znear, f = s.camera.zfar;
    const double half_tan = std::tan(double(s.camera.yfov) * 0.5);
    const double aspect = double(kDerivedWidth) / kDerivedHeight;
    for (const ZfightHit& h : z.hits) {
        const std::vector<Hit>& here = hits[h.pixel];
        ASSERT_FALSE(here.empty()) << "a hit where the host sees no surface";
        const double d = here.front().depth;
        const double zview = c.reverse ? n * f / (n + d * (f - n)) : n * f / (f - d * (f - n));
        const double x = ((h.pixel % kDerivedWidth) + 0.5) / kDerivedWidth * 2.0 - 1.0;
        const double y = ((h.pixel / kDerivedWidth) + 0.5) / kDerivedHeight * 2.0 - 1.0;
        const double stretch =
            std::sqrt(1.0 + std::pow(x * half_tan * aspect, 2) + std::pow(y * half_tan, 2));
        const double step = one_step(d, c.format) * zview * zview * (f - n) / (n * f) * stretch;
        EXPECT_NEAR(h.gap / step, double(h.steps), 1.5) << "pixel " << h.pixel;
    }
}

class ZfightDerived : public test::SharedScene {
  protected:
    static void SetUpTestSuite() { set_up_with("zfight"); }
};

// A pair must fight when its smallest gap is well inside zfight_steps at a pixel where no
// third surface is near (so one of the two won the prepass), and must not when it is well
// outside everywhere; the scene is built so that no pair lies in between (the test says if
// one does). A pair close only where a third surface is close too may be found or not: the
// detector pairs each competitor with the pixel's winner, and draw order picks the winner.
TEST_F(ZfightDerived, PairsAreExactlyThoseTheGeometryPredicts) {
    for (const Config& c : kConfigs) {
        const std::string config =
            std::string(c.format) + (c.reverse ? " reverse-Z" : " forward-Z");
        SCOPED_TRACE(config);
        const auto hits = rasterise(project(*scene_, c.reverse), c);
        const auto derived = derive(hits, c.format);
        const FrameResult f = renderer_->render(
            scene_->camera,
            test::settings_of({"zfight=on", std::string("depth_format=") + c.format,
                               c.reverse ? "reverse_z=on" : "reverse_z=off"}),
            {.width = kDerivedWidth, .height = kDerivedHeight, .read_back = ReadBack::No});
        ASSERT_TRUE(f.find<ZfightResult>());
        std::map<std::string, const ZfightPair*> found;
        for (const ZfightPair& p : f.find<ZfightResult>()->pairs)
            found[p.a.node + "|" + p.b.node] = &p;
        size_t required = 0;
        for (const auto& [key, d] : derived) {
            const std::string name =
                scene_->instances[key.first].node + "|" + scene_->instances[key.second].node;
            for (const double steps : {d.min_steps, d.min_alone})
                ASSERT_TRUE(steps <= kSteps / 2 || steps > 2 * kSteps)
                    << name << " is " << steps << " steps apart: too close to call";
            if (d.min_steps > 2 * kSteps) {
                EXPECT_FALSE(found.contains(name)) << name << " lies " << d.min_steps << " apart";
                continue;
            }
            if (d.min_alone > kSteps / 2) continue;  // close only beside a third surface
            ++required;
            ASSERT_TRUE(found.contains(name)) << name << " lies " << d.min_alone << " apart";
            EXPECT_LE(found[name]->min_steps, kSteps);
            if (!coplanar(*scene_, key.first, key.second)) continue;
            // Exactly coplanar: every pixel both cover fights, edge pixels aside.
            EXPECT_GE(found[name]->pixels, d.interior) << name << " overlap " << d.overlap;
            EXPECT_LE(found[name]->pixels, 2 * d.overlap - d.interior) << name;
        }
        for (const auto& [name, p] : found)
            EXPECT_TRUE(std::any_of(derived.begin(), derived.end(),
                                    [&](const auto& entry) {
                                        return scene_->instances[entry.first.first].node + "|" +
                                                   scene_->instances[entry.first.second].node ==
                                               name;
                                    }))
                << name << " never overlap";
        EXPECT_GE(required, 6u) << "the six coplanar pairs at least";
        expect_gaps_in_scene_units(*f.find<ZfightResult>(), hits, *scene_, c);
        // With the widest window forward-Z's nearly coplanar pairs compete too, 64 steps apart
        // (reverse-Z keeps them thousands of ULPs apart).
        const FrameResult wide = renderer_->render(
            scene_->camera,
            test::settings_of({"zfight=on", "zfight_steps=1024",
                               std::string("depth_format=") + c.format,
                               c.reverse ? "reverse_z=on" : "reverse_z=off"}),
            {.width = kDerivedWidth, .height = kDerivedHeight, .read_back = ReadBack::No});
        ASSERT_TRUE(wide.find<ZfightResult>());
        if (!c.reverse) {
            EXPECT_GT(wide.find<ZfightResult>()->hits.size(), f.find<ZfightResult>()->hits.size());
        }
        expect_gaps_in_scene_units(*wide.find<ZfightResult>(), hits, *scene_, c);
        printf("[ %-16s ] %zu pairs must fight, %zu found, %lu pixels\n", config.c_str(), required,
               found.size(), (unsigned long)f.find<ZfightResult>()->pixels);
    }
}

}  // namespace
