#include "renderer/scene/decals.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <unordered_map>

namespace ds::scene {
namespace {

using glm::dvec3;

constexpr double kInf = std::numeric_limits<double>::infinity();
// A triangle whose area is below this fraction of its longest edge squared has no usable plane.
constexpr double kDegenerate = 1e-12;
// Grids aim at about one cell per item, at most this many cells.
constexpr double kMaxCells = double{1 << 20};
// An item whose box spans more cells than this is offered to every query instead.
constexpr int64_t kWideItem = 256;

struct Box {
    dvec3 lo{kInf};
    dvec3 hi{-kInf};
    bool empty() const { return !(lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z); }
    void extend(const dvec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    // `inner` lies inside this box grown by `margin` on every side.
    bool holds(const Box& inner, double margin) const {
        return glm::all(glm::greaterThanEqual(inner.lo, lo - margin)) &&
               glm::all(glm::lessThanEqual(inner.hi, hi + margin));
    }
    double magnitude() const {  // largest |coordinate| in the box
        const dvec3 m = glm::max(glm::abs(lo), glm::abs(hi));
        return std::max({m.x, m.y, m.z});
    }
    double diagonal() const { return glm::length(hi - lo); }
};

// A non-degenerate world-space triangle: corners, unit normal, longest edge.
struct Tri {
    std::array<dvec3, 3> p;
    dvec3 n;
    double longest = 0.0;
};

// An instance's usable triangles in world space (`scratch` holds its world vertices).
void world_triangles(const Mesh& mesh, const glm::mat4& world, std::vector<dvec3>& scratch,
                     std::vector<Tri>& out) {
    const glm::dmat4 m(world);
    scratch.resize(mesh.vertices.size());
    for (size_t i = 0; i < scratch.size(); ++i)
        scratch[i] = dvec3(m * glm::dvec4(dvec3(mesh.vertices[i].position), 1.0));
    out.clear();
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        Tri tri;
        bool in_range = true;
        for (size_t k = 0; k < 3; ++k) {
            const uint32_t index = mesh.indices[t + k];
            in_range = in_range && index < scratch.size();
            if (in_range) tri.p[k] = scratch[index];
        }
        if (!in_range) continue;
        const dvec3 cross = glm::cross(tri.p[1] - tri.p[0], tri.p[2] - tri.p[0]);
        const double twice_area = glm::length(cross);
        tri.longest = std::max({glm::length(tri.p[1] - tri.p[0]), glm::length(tri.p[2] - tri.p[1]),
                                glm::length(tri.p[0] - tri.p[2])});
        if (!std::isfinite(twice_area) || !(twice_area > kDegenerate * tri.longest * tri.longest))
            continue;
        tri.n = cross / twice_area;
        out.push_back(tri);
    }
}

// `q` lies within `eps` of the plane of `t` and inside `t` grown by `eps` in that plane.
bool on_triangle(const Tri& t, const dvec3& q, double eps) {
    if (std::abs(glm::dot(q - t.p[0], t.n)) > eps) return false;
    for (size_t k = 0; k < 3; ++k) {
        const dvec3 edge = t.p[(k + 1) % 3] - t.p[k];
        // cross(n, edge) points into the triangle; its length is the edge's.
        if (glm::dot(q - t.p[k], glm::cross(t.n, edge)) < -eps * glm::length(edge)) return false;
    }
    return true;
}

// Which of a set of boxes may hold a point: a uniform grid over their union. Items spanning
// more than kWideItem cells (floors, walls, whole-level meshes) are offered to every query.
class BoxGrid {
  public:
    BoxGrid(const std::vector<Box>& boxes, double margin);

    // Calls visit(id) for the boxes that may hold `q` (each once) until it returns true.
    template <typename Visit>
    bool find(const dvec3& q, Visit&& visit) const {
        size_t cell = 0;
        if (!cell_of(q, cell)) return false;
        for (uint32_t i = start_[cell]; i < start_[cell + 1]; ++i)
            if (visit(items_[i])) return true;
        for (uint32_t id : wide_)
            if (visit(id)) return true;
        return false;
    }

  private:
    glm::i64vec3 coords(const dvec3& p) const {
        const glm::i64vec3 c(glm::floor((p - domain_.lo) / size_));
        return glm::clamp(c, glm::i64vec3(0), dims_ - int64_t{1});
    }
    size_t index(const glm::i64vec3& c) const {
        return static_cast<size_t>((c.z * dims_.y + c.y) * dims_.x + c.x);
    }
    bool cell_of(const dvec3& q, size_t& cell) const {
        Box point;
        point.extend(q);
        if (start_.empty() || !domain_.holds(point, 0.0)) return false;
        cell = index(coords(q));
        return true;
    }
    void size_cells(size_t items);

    Box domain_;
    double size_ = 1.0;
    glm::i64vec3 dims_{1};
    std::vector<uint32_t> start_;  // per cell, into items_ (one more entry than cells)
    std::vector<uint32_t> items_;
    std::vector<uint32_t> wide_;
};

// Halves the cell size from the whole domain while the cell count stays within about one per
// item; a flat or thin domain keeps one cell across its thin axes.
void BoxGrid::size_cells(size_t items) {
    const dvec3 extent = domain_.hi - domain_.lo;
    const double target = std::clamp(static_cast<double>(items), 1.0, kMaxCells);
    auto cells = [&](double h) {
        const dvec3 n = glm::max(glm::ceil(extent / h), dvec3(1.0));
        return n.x * n.y * n.z;
    };
    size_ = std::max({extent.x, extent.y, extent.z, std::numeric_limits<double>::min()});
    for (int step = 0; step < 64 && cells(size_ * 0.5) <= target; ++step) size_ *= 0.5;
    dims_ = glm::i64vec3(glm::max(glm::ceil(extent / size_), dvec3(1.0)));
}

BoxGrid::BoxGrid(const std::vector<Box>& boxes, double margin) {
    for (const Box& b : boxes) {
        if (b.empty()) continue;
        domain_.extend(b.lo - margin);
        domain_.extend(b.hi + margin);
    }
    if (domain_.empty()) return;
    size_cells(boxes.size());
    const size_t cells = static_cast<size_t>(dims_.x * dims_.y * dims_.z);
    // Two passes over the boxes' cell ranges: count per cell, then fill.
    std::vector<uint32_t> fill(cells + 1, 0);
    auto for_cells = [&](uint32_t id, auto&& per_cell) {
        const Box& b = boxes[id];
        if (b.empty()) return;
        const glm::i64vec3 lo = coords(b.lo - margin), hi = coords(b.hi + margin);
        const glm::i64vec3 span = hi - lo + int64_t{1};
        if (span.x * span.y * span.z > kWideItem) return;
        for (int64_t z = lo.z; z <= hi.z; ++z)
            for (int64_t y = lo.y; y <= hi.y; ++y)
                for (int64_t x = lo.x; x <= hi.x; ++x) per_cell(index({x, y, z}));
    };
    const auto count = static_cast<uint32_t>(boxes.size());
    for (uint32_t id = 0; id < count; ++id) for_cells(id, [&](size_t c) { ++fill[c + 1]; });
    for (size_t c = 0; c < cells; ++c) fill[c + 1] += fill[c];
    start_ = fill;
    items_.resize(fill[cells]);
    for (uint32_t id = 0; id < count; ++id) {
        bool narrow = false;
        for_cells(id, [&](size_t c) {
            items_[fill[c]++] = id;
            narrow = true;
        });
        if (!narrow && !boxes[id].empty()) wide_.push_back(id);
    }
}

// Barycentric weights of the points tested per triangle (see decals.h), vertices first: they
// reject fastest.
std::array<dvec3, 16> sample_weights() {
    const dvec3 centre(1.0 / 3.0);
    const std::array<dvec3, 3> vertices = {dvec3(1, 0, 0), dvec3(0, 1, 0), dvec3(0, 0, 1)};
    const std::array<dvec3, 3> midpoints = {dvec3(0.5, 0.5, 0), dvec3(0, 0.5, 0.5),
                                            dvec3(0.5, 0, 0.5)};
    std::array<dvec3, 16> w{};
    for (size_t k = 0; k < 3; ++k) {
        w[k] = vertices[k];
        w[3 + k] = midpoints[k];
        w[7 + k] = glm::mix(vertices[k], centre, 0.01);
        w[10 + k] = glm::mix(midpoints[k], centre, 0.01);
        w[13 + k] = glm::mix(vertices[k], centre, 0.5);
    }
    w[6] = centre;
    return w;
}

// What the first pass keeps of every instance.
struct Summary {
    Box box;  // of its usable triangles
    double area = 0.0;
    double max_eps = 0.0;  // the largest eps any of its sample points gets
    size_t triangles = 0;
};

}  // namespace

double overlay_epsilon(const glm::dvec3& p, double longest_edge) {
    const dvec3 a = glm::abs(p);
    return kOverlayTolerance * (std::max({a.x, a.y, a.z}) + longest_edge);
}

namespace {

// The classification of one set of instances; world triangles and their grids are built only
// for instances that take part in a candidate pair, once each.
class Overlays {
  public:
    Overlays(const std::vector<Mesh>& meshes, const std::vector<Instance>& instances);
    std::vector<int32_t> bases();
    std::vector<Box> instance_boxes(Box& all) const;
    std::vector<BuriedOverlay> buried(const std::vector<int32_t>& decal_base);

  private:
    struct Geometry {
        std::vector<Tri> tris;
        std::optional<BoxGrid> grid;   // built when it is first a candidate base
        std::optional<BoxGrid> loose;  // the same, grown by kBuriedTolerance (buried())
    };
    Geometry& geometry(uint32_t i);
    bool covers(uint32_t base, uint32_t top);
    bool covers_uncached(uint32_t base, uint32_t top);
    bool strictly_on(uint32_t top, uint32_t base);
    std::optional<double> buried_gap(uint32_t base, uint32_t top);
    const BoxGrid& triangle_grid(uint32_t base, double tolerance, std::optional<BoxGrid>& grid);

    const std::vector<Mesh>& meshes_;
    const std::vector<Instance>& instances_;
    std::vector<Summary> summary_;
    std::vector<std::unique_ptr<Geometry>> geometry_;
    std::unordered_map<uint64_t, bool> covers_;  // (base << 32 | top) -> result
    std::vector<dvec3> scratch_;
};

Overlays::Overlays(const std::vector<Mesh>& meshes, const std::vector<Instance>& instances)
    : meshes_(meshes),
      instances_(instances),
      summary_(instances.size()),
      geometry_(instances.size()) {
    std::vector<Tri> tris;
    for (size_t i = 0; i < instances.size(); ++i) {
        if (instances[i].mesh >= meshes.size()) continue;
        world_triangles(meshes[instances[i].mesh], instances[i].world, scratch_, tris);
        Summary& s = summary_[i];
        double longest = 0.0;
        for (const Tri& t : tris) {
            for (const dvec3& p : t.p) s.box.extend(p);
            s.area += 0.5 * glm::length(glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]));
            longest = std::max(longest, t.longest);
        }
        s.triangles = tris.size();
        s.max_eps = s.box.empty() ? 0.0 : kOverlayTolerance * (s.box.magnitude() + longest);
    }
}

Overlays::Geometry& Overlays::geometry(uint32_t i) {
    if (!geometry_[i]) {
        geometry_[i] = std::make_unique<Geometry>();
        world_triangles(meshes_[instances_[i].mesh], instances_[i].world, scratch_,
                        geometry_[i]->tris);
    }
    return *geometry_[i];
}

bool Overlays::covers(uint32_t base, uint32_t top) {
    const uint64_t key = uint64_t{base} << 32 | top;
    const auto found = covers_.find(key);
    if (found != covers_.end()) return found->second;
    const bool result = covers_uncached(base, top);
    covers_.emplace(key, result);
    return result;
}

// A grid over `base`'s triangles for query points whose eps is `tolerance` relative (made once).
const BoxGrid& Overlays::triangle_grid(uint32_t base, double tolerance,
                                       std::optional<BoxGrid>& grid) {
    if (!grid) {
        const Geometry& under = geometry(base);
        std::vector<Box> boxes(under.tris.size());
        for (size_t t = 0; t < boxes.size(); ++t)
            for (const dvec3& p : under.tris[t].p) boxes[t].extend(p);
        // Any eps a query point gets: its magnitude and its triangle's edge are bounded by
        // the base's bounds (the candidate test saw to it).
        const Box& b = summary_[base].box;
        grid.emplace(boxes, 2.0 * tolerance * (b.magnitude() + b.diagonal()));
    }
    return *grid;
}

// Every sample point of every triangle of `top` lies on a triangle of `base`.
bool Overlays::covers_uncached(uint32_t base, uint32_t top) {
    Geometry& under = geometry(base);
    const BoxGrid& grid = triangle_grid(base, kOverlayTolerance, under.grid);
    static const std::array<dvec3, 16> kWeights = sample_weights();
    uint32_t hint = 0;  // the last triangle that matched: neighbouring points usually share it
    for (const Tri& t : geometry(top).tris) {
        for (const dvec3& w : kWeights) {
            const dvec3 q = t.p[0] * w.x + t.p[1] * w.y + t.p[2] * w.z;
            const double eps = overlay_epsilon(q, t.longest);
            if (hint < under.tris.size() && on_triangle(under.tris[hint], q, eps)) continue;
            const bool found = grid.find(q, [&](uint32_t id) {
                if (!on_triangle(under.tris[id], q, eps)) return false;
                hint = id;
                return true;
            });
            if (!found) return false;
        }
    }
    return true;
}

// `top` lies on `base` and not the other way round.
bool Overlays::strictly_on(uint32_t top, uint32_t base) {
    const Summary& t = summary_[top];
    const Summary& b = summary_[base];
    if (top == base || b.triangles == 0 || !b.box.holds(t.box, t.max_eps)) return false;
    if (!covers(base, top)) return false;
    return !(t.box.holds(b.box, b.max_eps) && covers(top, base));
}

// How far behind `base` the farthest sample point of `top` lies, when `top` lies buried under
// it (decals.h); none otherwise.
std::optional<double> Overlays::buried_gap(uint32_t base, uint32_t top) {
    const BoxGrid& grid = triangle_grid(base, kBuriedTolerance, geometry(base).loose);
    const std::vector<Tri>& under = geometry(base).tris;
    static const std::array<dvec3, 16> kWeights = sample_weights();
    const double facing = std::cos(glm::radians(5.0));
    double gap = 0.0;
    for (const Tri& t : geometry(top).tris) {
        for (const dvec3& w : kWeights) {
            const dvec3 q = t.p[0] * w.x + t.p[1] * w.y + t.p[2] * w.z;
            const double strict = overlay_epsilon(q, t.longest);
            const double loose = strict * (kBuriedTolerance / kOverlayTolerance);
            double behind = -1.0;
            grid.find(q, [&](uint32_t id) {
                const Tri& b = under[id];
                const double d = glm::dot(q - b.p[0], b.n);  // > 0: in front of b
                if (glm::dot(b.n, t.n) < facing || d >= -strict || d < -loose) return false;
                if (!on_triangle(b, q - d * b.n, loose)) return false;  // its foot, inside b
                behind = -d;
                return true;
            });
            if (behind < 0.0) return std::nullopt;
            gap = std::max(gap, behind);
        }
    }
    return gap;
}

// Every non-decal with triangles against the instances whose bounds, grown by the loose
// tolerance, hold its centre.
std::vector<BuriedOverlay> Overlays::buried(const std::vector<int32_t>& decal_base) {
    Box all;
    const std::vector<Box> boxes = instance_boxes(all);
    std::vector<BuriedOverlay> out;
    if (all.empty()) return out;
    const double margin = 2.0 * kBuriedTolerance * (all.magnitude() + all.diagonal());
    const BoxGrid grid(boxes, margin);
    for (uint32_t top = 0; top < summary_.size(); ++top) {
        if (summary_[top].triangles == 0 || decal_base[top] >= 0) continue;
        std::optional<BuriedOverlay> best;
        grid.find(0.5 * (boxes[top].lo + boxes[top].hi), [&](uint32_t base) {
            if (base == top || summary_[base].triangles == 0 ||
                !boxes[base].holds(boxes[top], margin))
                return false;
            const std::optional<double> gap = buried_gap(base, top);
            if (gap && (!best || *gap < best->gap || (*gap == best->gap && base < best->base)))
                best = BuriedOverlay{top, base, *gap};
            return false;
        });
        if (best) out.push_back(*best);
    }
    return out;
}

// One base per decal: the best non-decal reached through "lies on" links (see decals.h).
std::vector<int32_t> resolve_bases(const std::vector<std::vector<uint32_t>>& on,
                                   const std::vector<Summary>& summary) {
    std::vector<int32_t> base(on.size(), -1);
    std::vector<size_t> seen(on.size(), on.size());  // the search that last visited it
    std::vector<uint32_t> stack;
    for (size_t top = 0; top < on.size(); ++top) {
        if (on[top].empty()) continue;
        seen[top] = top;
        stack.assign(on[top].begin(), on[top].end());
        for (uint32_t b : stack) seen[b] = top;
        int32_t best = -1;
        while (!stack.empty()) {
            const uint32_t b = stack.back();
            stack.pop_back();
            if (on[b].empty()) {
                const double area = summary[b].area;
                if (best < 0 || area > summary[static_cast<size_t>(best)].area ||
                    (area == summary[static_cast<size_t>(best)].area && b < uint32_t(best)))
                    best = static_cast<int32_t>(b);
                continue;
            }
            for (uint32_t next : on[b]) {
                if (seen[next] == top) continue;
                seen[next] = top;
                stack.push_back(next);
            }
        }
        base[top] = best;
    }
    return base;
}

// Every instance's box (what a BoxGrid over the instances takes) and, in `all`, their union.
std::vector<Box> Overlays::instance_boxes(Box& all) const {
    std::vector<Box> boxes(summary_.size());
    for (size_t i = 0; i < boxes.size(); ++i) {
        boxes[i] = summary_[i].box;
        if (!boxes[i].empty()) {
            all.extend(boxes[i].lo);
            all.extend(boxes[i].hi);
        }
    }
    return boxes;
}

std::vector<int32_t> Overlays::bases() {
    Box all;
    const std::vector<Box> boxes = instance_boxes(all);
    if (all.empty()) return std::vector<int32_t>(summary_.size(), -1);
    // A base must hold the centre of its overlay's box, give or take any overlay's eps.
    const BoxGrid grid(boxes, 2.0 * kOverlayTolerance * (all.magnitude() + all.diagonal()));
    std::vector<std::vector<uint32_t>> on(summary_.size());
    for (uint32_t top = 0; top < summary_.size(); ++top) {
        if (summary_[top].triangles == 0) continue;
        const dvec3 centre = 0.5 * (boxes[top].lo + boxes[top].hi);
        grid.find(centre, [&](uint32_t base) {
            if (strictly_on(top, base)) on[top].push_back(base);
            return false;
        });
        std::sort(on[top].begin(), on[top].end());
    }
    return resolve_bases(on, summary_);
}

}  // namespace

std::vector<int32_t> find_decal_bases(const std::vector<Mesh>& meshes,
                                      const std::vector<Instance>& instances) {
    return Overlays(meshes, instances).bases();
}

OverlayClasses classify_overlays(const std::vector<Mesh>& meshes,
                                 const std::vector<Instance>& instances) {
    Overlays overlays(meshes, instances);
    OverlayClasses out;
    out.decal_base = overlays.bases();
    out.buried = overlays.buried(out.decal_base);
    return out;
}

}  // namespace ds::scene
