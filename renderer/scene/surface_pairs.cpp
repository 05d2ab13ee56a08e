#include "renderer/scene/surface_pairs.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "renderer/scene/decals.h"
#include "renderer/scene/surface_pairs_detail.h"

namespace ds::scene {

const char* to_string(PairKind kind) {
    switch (kind) {
        case PairKind::Coplanar:
            return "coplanar";
        case PairKind::Duplicate:
            return "duplicate";
        case PairKind::Near:
            return "near";
    }
    return "?";
}

namespace {

using detail::PairInstance;
using detail::PlaneEntry;
using detail::WorldTriangle;
using glm::dvec3;

// Direction bins: a grid over unit normals, kDirCell wide and centred on the axes (coordinates
// -kDirHalf .. kDirHalf). A triangle goes into every bin that its normal's ball of radius
// sin(facing / 2) touches, so two normals within the facing angle share the bin of their
// midpoint, where alone the pair is tested. n and -n share bins: a normal is folded onto the
// side of kDirFold (a direction off the axes, their diagonals and the cube's), and one within
// the facing angle of the fold's plane goes in on both sides.
constexpr double kDirCell = 0.2;
constexpr int kDirHalf = 5;
constexpr int kDirSide = 2 * kDirHalf + 1;
// Room for rounding in the bins' reach.
constexpr double kDirSlack = 1.01;

dvec3 dir_fold() {
    return glm::normalize(dvec3(1.0, 2.0, 4.0));
}

int dir_coordinate(double v) {
    return std::clamp(static_cast<int>(std::floor(v / kDirCell + 0.5)), -kDirHalf, kDirHalf);
}

size_t dir_bin(const glm::ivec3& c) {
    return static_cast<size_t>(((c.z + kDirHalf) * kDirSide + c.y + kDirHalf) * kDirSide + c.x +
                               kDirHalf);
}

// The side of the fold a midpoint of two folded normals lies on (ties broken by its first
// non-zero coordinate), so a pair folded both ways is tested once.
bool dir_positive(const dvec3& m) {
    const double side = glm::dot(m, dir_fold());
    if (side != 0.0) return side > 0.0;
    for (int k = 0; k < 3; ++k)
        if (m[k] != 0.0) return m[k] > 0.0;
    return true;
}

struct DirRef {
    uint32_t instance = 0;
    uint32_t triangle = 0;
};

// What one instance pair and kind has gathered (surface_pairs.h's aggregation).
struct PairTally {
    uint32_t count = 0;
    double area = 0.0;
    double min_gap = std::numeric_limits<double>::infinity();
    double max_gap = 0.0;
    double best = -1.0;  // the largest overlap's area
    dvec3 normal{0.0}, point{0.0};
    uint32_t triangle_a = 0, triangle_b = 0;

    void add(const detail::TriangleContact& c, const WorldTriangle& a, const DirRef& ra,
             const DirRef& rb) {
        ++count;
        area += c.area;
        min_gap = std::min(min_gap, c.min_gap);
        max_gap = std::max(max_gap, c.max_gap);
        if (c.area <= best) return;
        best = c.area;
        normal = a.n;
        point = c.point;
        triangle_a = ra.triangle;
        triangle_b = rb.triangle;
    }
    SurfacePair pair(uint32_t a, uint32_t b, PairKind kind) const {
        return {a, b, kind, area, min_gap, max_gap, count, normal, point, triangle_a, triangle_b};
    }
};

struct PairTallies {
    PairTally coplanar, near;
};

class SurfacePairSearch {
  public:
    SurfacePairSearch(const std::vector<Mesh>& meshes, const std::vector<Material>& materials,
                      const std::vector<Instance>& instances, const SurfacePairOptions& options);
    std::vector<SurfacePair> run();

  private:
    void bin_triangles();
    void bin(const dvec3& normal, const DirRef& ref);
    // Fills entries_ (kept across bins, as its memory is).
    void bin_entries(size_t bin, const dvec3& w);
    void search_bin(size_t bin);
    void consider(size_t bin, const dvec3& centre, const PlaneEntry& x, const PlaneEntry& y);
    bool duplicate(uint32_t a, uint32_t b) const;

    std::vector<PairInstance> instances_;
    double near_gap_max_ = 0.0;
    double reach_ = 0.0;  // of a normal's ball
    std::vector<std::vector<DirRef>> bins_;
    std::vector<PlaneEntry> entries_;                    // of the bin being searched
    std::vector<double> eps_;                            // each entry's largest eps
    std::unordered_map<uint64_t, PairTallies> tallies_;  // key: a << 32 | b
};

SurfacePairSearch::SurfacePairSearch(const std::vector<Mesh>& meshes,
                                     const std::vector<Material>& materials,
                                     const std::vector<Instance>& instances,
                                     const SurfacePairOptions& options)
    : instances_(instances.size()),
      near_gap_max_(std::max(0.0, options.near_gap_max)),
      reach_(kDirSlack * std::sin(glm::radians(0.5 * kPairFacingDegrees))),
      bins_(size_t{kDirSide} * kDirSide * kDirSide) {
    for (size_t i = 0; i < instances.size(); ++i) {
        if (instances[i].mesh >= meshes.size()) continue;
        const Mesh& mesh = meshes[instances[i].mesh];
        PairInstance& p = instances_[i];
        p.mesh = &mesh;
        p.world = glm::dmat4(instances[i].world);
        p.facing = glm::determinant(glm::dmat3(p.world)) < 0.0 ? -1.0 : 1.0;
        p.double_sided = mesh.material < materials.size() && materials[mesh.material].double_sided;
    }
}

// Into every bin that the ball around `normal` (folded) touches.
void SurfacePairSearch::bin(const dvec3& normal, const DirRef& ref) {
    const glm::ivec3 lo(dir_coordinate(normal.x - reach_), dir_coordinate(normal.y - reach_),
                        dir_coordinate(normal.z - reach_));
    const glm::ivec3 hi(dir_coordinate(normal.x + reach_), dir_coordinate(normal.y + reach_),
                        dir_coordinate(normal.z + reach_));
    for (int z = lo.z; z <= hi.z; ++z)
        for (int y = lo.y; y <= hi.y; ++y)
            for (int x = lo.x; x <= hi.x; ++x) bins_[dir_bin({x, y, z})].push_back(ref);
}

void SurfacePairSearch::bin_triangles() {
    const dvec3 fold = dir_fold();
    const double near_fold = kDirSlack * std::sin(glm::radians(kPairFacingDegrees));
    WorldTriangle t;
    for (uint32_t i = 0; i < instances_.size(); ++i) {
        if (instances_[i].mesh == nullptr) continue;
        const auto count = static_cast<uint32_t>(instances_[i].mesh->indices.size() / 3);
        for (uint32_t tri = 0; tri < count; ++tri) {
            if (!detail::world_triangle(instances_[i], tri, t)) continue;
            const double side = glm::dot(t.n, fold);
            const dvec3 folded = side >= 0.0 ? t.n : -t.n;
            bin(folded, {i, tri});
            if (std::abs(side) <= near_fold) bin(-folded, {i, tri});
        }
    }
}

// The bin's triangles as boxes in its frame (x, y in the plane, z along `w`), grown so that
// two triangles of a pair overlap: the points of b lie within the pair's gap g of a's along
// a's normal (|g| <= eps_a + eps_b coplanar; <= near_gap_max somewhere, near), which moves them
// by at most |g| along z and |g| times the bin's largest tilt (the sine between a normal of
// the bin and `w`) in the plane. Each box takes half. A pair's overlap has a positive area,
// so its boxes overlap with positive extents in x and y: boxes that merely touch there (tiles
// side by side) never pair (overlapping_entries).
void SurfacePairSearch::bin_entries(size_t bin, const dvec3& w) {
    const dvec3 u =
        glm::normalize(glm::cross(w, std::abs(w.x) < 0.9 ? dvec3(1, 0, 0) : dvec3(0, 1, 0)));
    const dvec3 v = glm::cross(w, u);
    std::vector<PlaneEntry>& entries = entries_;
    std::vector<double>& eps = eps_;
    entries.clear();
    eps.clear();
    double lateral = 0.0;
    WorldTriangle t;
    for (const DirRef& ref : bins_[bin]) {
        detail::world_triangle(instances_[ref.instance], ref.triangle, t);
        PlaneEntry e{dvec3(std::numeric_limits<double>::infinity()),
                     dvec3(-std::numeric_limits<double>::infinity()), ref.instance, ref.triangle};
        double own = 0.0;
        for (const dvec3& p : t.p) {
            own = std::max(own, overlay_epsilon(p, t.longest));
            const dvec3 q(glm::dot(p, u), glm::dot(p, v), glm::dot(p, w));
            e.lo = glm::min(e.lo, q);
            e.hi = glm::max(e.hi, q);
        }
        lateral = std::max(lateral, glm::length(t.n - glm::dot(t.n, w) * w));
        entries.push_back(e);
        eps.push_back(own);
    }
    for (size_t i = 0; i < entries.size(); ++i) {
        const double gap = eps[i] + 0.5 * near_gap_max_ * kDirSlack;
        const dvec3 grow(gap * lateral, gap * lateral, gap);
        entries[i].lo -= grow;
        entries[i].hi += grow;
    }
}

void SurfacePairSearch::search_bin(size_t bin) {
    const std::vector<DirRef>& refs = bins_[bin];
    if (refs.size() < 2 || refs.front().instance == refs.back().instance) return;
    const auto index = static_cast<int>(bin);
    const dvec3 centre = dvec3(index % kDirSide - kDirHalf, index / kDirSide % kDirSide - kDirHalf,
                               index / (kDirSide * kDirSide) - kDirHalf) *
                         kDirCell;
    const dvec3 w = glm::normalize(centre);
    bin_entries(bin, w);
    const std::vector<PlaneEntry>& entries = entries_;
    detail::overlapping_entries(
        entries, [&](uint32_t i, uint32_t j) { consider(bin, w, entries[i], entries[j]); });
}

void SurfacePairSearch::consider(size_t bin, const dvec3& centre, const PlaneEntry& x,
                                 const PlaneEntry& y) {
    const bool swap = x.instance > y.instance;
    const DirRef ra = swap ? DirRef{y.instance, y.triangle} : DirRef{x.instance, x.triangle};
    const DirRef rb = swap ? DirRef{x.instance, x.triangle} : DirRef{y.instance, y.triangle};
    WorldTriangle a, b;
    detail::world_triangle(instances_[ra.instance], ra.triangle, a);
    detail::world_triangle(instances_[rb.instance], rb.triangle, b);
    // The pair is tested in the bin of its folded normals' midpoint only.
    const dvec3 fa = glm::dot(a.n, centre) >= 0.0 ? a.n : -a.n;
    const dvec3 fb = glm::dot(b.n, centre) >= 0.0 ? b.n : -b.n;
    const dvec3 mid = 0.5 * (fa + fb);
    const glm::ivec3 cell(dir_coordinate(mid.x), dir_coordinate(mid.y), dir_coordinate(mid.z));
    if (dir_bin(cell) != bin || !dir_positive(mid)) return;
    const bool two_sided =
        instances_[ra.instance].double_sided || instances_[rb.instance].double_sided;
    const detail::TriangleContact c = detail::triangle_contact(a, b, two_sided, near_gap_max_);
    if (c.kind == detail::Contact::None) return;
    PairTallies& tally = tallies_[uint64_t{ra.instance} << 32 | rb.instance];
    (c.kind == detail::Contact::Coplanar ? tally.coplanar : tally.near).add(c, a, ra, rb);
}

// The two instances' world triangles match corner for corner within eps (surface_pairs.h).
bool SurfacePairSearch::duplicate(uint32_t a, uint32_t b) const {
    const PairInstance& ia = instances_[a];
    const PairInstance& ib = instances_[b];
    if (ia.mesh->indices.size() != ib.mesh->indices.size()) return false;
    const size_t va = ia.mesh->vertices.size(), vb = ib.mesh->vertices.size();
    for (size_t t = 0; t + 2 < ia.mesh->indices.size(); t += 3) {
        std::array<dvec3, 3> pa, pb;
        for (size_t k = 0; k < 3; ++k) {
            const uint32_t ja = ia.mesh->indices[t + k], jb = ib.mesh->indices[t + k];
            if (ja >= va || jb >= vb) return false;
            pa[k] = detail::world_position(ia, ja);
            pb[k] = detail::world_position(ib, jb);
        }
        const double longest = std::max(
            {glm::length(pa[1] - pa[0]), glm::length(pa[2] - pa[1]), glm::length(pa[0] - pa[2])});
        for (size_t k = 0; k < 3; ++k)
            if (!(glm::length(pa[k] - pb[k]) <= overlay_epsilon(pa[k], longest))) return false;
    }
    return true;
}

std::vector<SurfacePair> SurfacePairSearch::run() {
    bin_triangles();
    for (size_t bin = 0; bin < bins_.size(); ++bin) search_bin(bin);
    std::vector<SurfacePair> out;
    for (const auto& [key, tally] : tallies_) {
        const auto a = static_cast<uint32_t>(key >> 32), b = static_cast<uint32_t>(key);
        const bool twin = tally.coplanar.count > 0 && duplicate(a, b);
        if (tally.coplanar.count > 0)
            out.push_back(
                tally.coplanar.pair(a, b, twin ? PairKind::Duplicate : PairKind::Coplanar));
        if (tally.near.count > 0 && !twin) out.push_back(tally.near.pair(a, b, PairKind::Near));
    }
    std::sort(out.begin(), out.end(), [](const SurfacePair& x, const SurfacePair& y) {
        return std::tie(x.a, x.b, x.kind) < std::tie(y.a, y.b, y.kind);
    });
    return out;
}

}  // namespace

std::vector<SurfacePair> find_surface_pairs(const std::vector<Mesh>& meshes,
                                            const std::vector<Material>& materials,
                                            const std::vector<Instance>& instances,
                                            const SurfacePairOptions& options) {
    return SurfacePairSearch(meshes, materials, instances, options).run();
}

std::vector<DegenerateTriangles> find_degenerate_triangles(const std::vector<Mesh>& meshes) {
    std::vector<DegenerateTriangles> out;
    for (uint32_t m = 0; m < meshes.size(); ++m) {
        const Mesh& mesh = meshes[m];
        DegenerateTriangles found{m, 0, 0};
        for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            std::array<dvec3, 3> p;
            bool in_range = true;
            for (size_t k = 0; k < 3; ++k) {
                const uint32_t index = mesh.indices[t + k];
                in_range = in_range && index < mesh.vertices.size();
                if (in_range) p[k] = dvec3(mesh.vertices[index].position);
            }
            if (in_range && !degenerate_triangle(p[0], p[1], p[2])) continue;
            if (found.count++ == 0) found.first = static_cast<uint32_t>(t / 3);
        }
        if (found.count > 0) out.push_back(found);
    }
    return out;
}

}  // namespace ds::scene
