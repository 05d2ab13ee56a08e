// The in-plane broadphase of find_surface_pairs (surface_pairs.h): boxes that are flat along z
// (triangles of one direction bin, in its frame) go into a 2-D grid over x and y with one level
// per factor kSpLevelRatio of size, and each cell's boxes are swept in order of their lowest z.
#include <algorithm>
#include <cmath>
#include <limits>

#include "renderer/scene/surface_pairs_detail.h"

namespace ds::scene::detail {
namespace {

// Cell sizes grow by this factor per level; a box goes to the first level whose cells are at
// least its larger extent in x and y, so it covers at most 2 x 2 cells there.
constexpr double kSpLevelRatio = 4.0;
// Cells per axis stay below this at the finest level (a key packs two 32-bit coordinates).
constexpr double kSpMaxCells = double{1u << 30};

struct SpRecord {
    uint64_t key = 0;
    double lo_z = 0.0;
    uint32_t entry = 0;
    uint32_t instance = 0;  // the entry's, to skip pairs of one instance without reading it
};

struct SpLevel {
    double size = 0.0;
    std::vector<SpRecord> records;  // one per cell a box covers, sorted by (key, lo_z)
};

// Overlap with positive extents in x and y (touching is not enough); in z, touching is.
bool sp_overlap_xy(const PlaneEntry& a, const PlaneEntry& b) {
    return a.lo.x < b.hi.x && b.lo.x < a.hi.x && a.lo.y < b.hi.y && b.lo.y < a.hi.y;
}

class SpGrid {
  public:
    explicit SpGrid(const std::vector<PlaneEntry>& entries);
    // Pairs of boxes of one level, found in the cell that holds their overlap's lowest corner.
    void same_level_pairs(const std::function<void(uint32_t, uint32_t)>& visit) const;
    // Every box against the coarser levels' boxes, found likewise in the coarser level.
    void cross_level_pairs(const std::function<void(uint32_t, uint32_t)>& visit) const;

  private:
    int64_t coordinate(double v, double origin, double size) const {
        return static_cast<int64_t>(std::floor((v - origin) / size));
    }
    uint64_t key(double x, double y, double size) const {
        return static_cast<uint64_t>(coordinate(x, origin_.x, size)) << 32 |
               static_cast<uint64_t>(coordinate(y, origin_.y, size));
    }
    // `a` and `b` overlap in x and y: whether cell `key` holds their overlap's lowest corner.
    bool owns(const PlaneEntry& a, const PlaneEntry& b, uint64_t cell, double size) const {
        return key(std::max(a.lo.x, b.lo.x), std::max(a.lo.y, b.lo.y), size) == cell;
    }
    void record(uint32_t entry, SpLevel& level);
    void query(uint32_t entry, const SpLevel& level,
               const std::function<void(uint32_t, uint32_t)>& visit) const;

    const std::vector<PlaneEntry>& entries_;
    glm::dvec2 origin_{std::numeric_limits<double>::infinity()};
    std::vector<uint8_t> level_of_;
    std::vector<SpLevel> levels_;
};

SpGrid::SpGrid(const std::vector<PlaneEntry>& entries)
    : entries_(entries), level_of_(entries.size(), 0) {
    glm::dvec2 far(-std::numeric_limits<double>::infinity());
    double smallest = std::numeric_limits<double>::infinity();
    for (const PlaneEntry& e : entries) {
        origin_ = glm::min(origin_, glm::dvec2(e.lo));
        far = glm::max(far, glm::dvec2(e.hi));
        smallest = std::min(smallest, std::max(e.hi.x - e.lo.x, e.hi.y - e.lo.y));
    }
    if (entries.empty()) return;
    const double span = std::max(far.x - origin_.x, far.y - origin_.y);
    const double base =
        std::max({smallest, span / kSpMaxCells, std::numeric_limits<double>::min()});
    for (uint32_t i = 0; i < entries.size(); ++i) {
        const PlaneEntry& e = entries[i];
        const double extent = std::max(e.hi.x - e.lo.x, e.hi.y - e.lo.y);
        size_t level = 0;
        for (double size = base; size < extent; size *= kSpLevelRatio) ++level;
        if (levels_.size() <= level) levels_.resize(level + 1);
        level_of_[i] = static_cast<uint8_t>(level);
    }
    std::vector<size_t> counts(levels_.size(), 0);
    for (const uint8_t level : level_of_) ++counts[level];
    double size = base;
    for (size_t level = 0; level < levels_.size(); ++level) {
        levels_[level].size = size;
        levels_[level].records.reserve(4 * counts[level]);  // at most 2 x 2 cells each
        size *= kSpLevelRatio;
    }
    for (uint32_t i = 0; i < entries.size(); ++i) record(i, levels_[level_of_[i]]);
    for (SpLevel& level : levels_)
        std::sort(level.records.begin(), level.records.end(),
                  [](const SpRecord& a, const SpRecord& b) {
                      return a.key != b.key ? a.key < b.key : a.lo_z < b.lo_z;
                  });
}

void SpGrid::record(uint32_t entry, SpLevel& level) {
    const PlaneEntry& e = entries_[entry];
    const int64_t x0 = coordinate(e.lo.x, origin_.x, level.size);
    const int64_t x1 = coordinate(e.hi.x, origin_.x, level.size);
    const int64_t y0 = coordinate(e.lo.y, origin_.y, level.size);
    const int64_t y1 = coordinate(e.hi.y, origin_.y, level.size);
    for (int64_t x = x0; x <= x1; ++x)
        for (int64_t y = y0; y <= y1; ++y)
            level.records.push_back({static_cast<uint64_t>(x) << 32 | static_cast<uint64_t>(y),
                                     e.lo.z, entry, e.instance});
}

void SpGrid::same_level_pairs(const std::function<void(uint32_t, uint32_t)>& visit) const {
    for (const SpLevel& level : levels_) {
        const std::vector<SpRecord>& r = level.records;
        for (size_t begin = 0, end = 0; begin < r.size(); begin = end) {
            while (end < r.size() && r[end].key == r[begin].key) ++end;
            for (size_t i = begin; i < end; ++i) {
                const PlaneEntry& a = entries_[r[i].entry];
                for (size_t j = i + 1; j < end && r[j].lo_z <= a.hi.z; ++j) {
                    if (r[j].instance == a.instance) continue;
                    const PlaneEntry& b = entries_[r[j].entry];
                    if (sp_overlap_xy(a, b) && owns(a, b, r[i].key, level.size))
                        visit(r[i].entry, r[j].entry);
                }
            }
        }
    }
}

// `entry`'s box against the boxes of the cells of (coarser) `level` that it covers.
void SpGrid::query(uint32_t entry, const SpLevel& level,
                   const std::function<void(uint32_t, uint32_t)>& visit) const {
    const PlaneEntry& a = entries_[entry];
    const int64_t x0 = coordinate(a.lo.x, origin_.x, level.size);
    const int64_t x1 = coordinate(a.hi.x, origin_.x, level.size);
    const int64_t y0 = coordinate(a.lo.y, origin_.y, level.size);
    const int64_t y1 = coordinate(a.hi.y, origin_.y, level.size);
    const std::vector<SpRecord>& r = level.records;
    for (int64_t x = x0; x <= x1; ++x) {
        for (int64_t y = y0; y <= y1; ++y) {
            const uint64_t cell = static_cast<uint64_t>(x) << 32 | static_cast<uint64_t>(y);
            auto it = std::lower_bound(r.begin(), r.end(), cell,
                                       [](const SpRecord& s, uint64_t k) { return s.key < k; });
            for (; it != r.end() && it->key == cell && it->lo_z <= a.hi.z; ++it) {
                if (it->instance == a.instance) continue;
                const PlaneEntry& b = entries_[it->entry];
                if (b.hi.z >= a.lo.z && sp_overlap_xy(a, b) && owns(a, b, cell, level.size))
                    visit(entry, it->entry);
            }
        }
    }
}

void SpGrid::cross_level_pairs(const std::function<void(uint32_t, uint32_t)>& visit) const {
    for (uint32_t i = 0; i < entries_.size(); ++i)
        for (size_t level = level_of_[i] + size_t{1}; level < levels_.size(); ++level)
            if (!levels_[level].records.empty()) query(i, levels_[level], visit);
}

}  // namespace

void overlapping_entries(const std::vector<PlaneEntry>& entries,
                         const std::function<void(uint32_t, uint32_t)>& visit) {
    const SpGrid grid(entries);
    grid.same_level_pairs(visit);
    grid.cross_level_pairs(visit);
}

}  // namespace ds::scene::detail
