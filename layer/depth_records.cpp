#include "layer/depth_records.h"

#include <algorithm>
#include <bit>
#include <set>
#include <tuple>

namespace ds::layer {

bool same_geometry(const DrawGeometry& a, const DrawGeometry& b) {
    const DrawArgs &x = a.args, &y = b.args;
    // Instances may be drawn in other groupings (a prepass sorted per instance, a forward pass
    // by mesh): the index or vertex range decides.
    if (x.indexed() != y.indexed() || x.count != y.count || x.first != y.first ||
        x.vertex_offset != y.vertex_offset || x.indirect != y.indirect ||
        x.indirect_offset != y.indirect_offset)
        return false;
    if (a.indexed != b.indexed) return false;
    if (a.indexed && (a.index_buffer != b.index_buffer || a.index_offset != b.index_offset ||
                      a.index_type != b.index_type))
        return false;
    for (const auto& [binding, buffer] : a.vertex) {
        const auto it = b.vertex.find(binding);
        if (it != b.vertex.end() && it->second != buffer) return false;
    }
    return true;
}

bool DepthUse::equal_like() const {
    if (!test) return false;
    if (op == VK_COMPARE_OP_EQUAL) return true;
    return !write && (op == VK_COMPARE_OP_LESS_OR_EQUAL || op == VK_COMPARE_OP_GREATER_OR_EQUAL);
}

uint32_t depth_bits_of(VkFormat format) {
    switch (format) {
        case VK_FORMAT_D32_SFLOAT:
        case VK_FORMAT_D32_SFLOAT_S8_UINT: return 32;
        case VK_FORMAT_X8_D24_UNORM_PACK32:
        case VK_FORMAT_D24_UNORM_S8_UINT: return 24;
        case VK_FORMAT_D16_UNORM:
        case VK_FORMAT_D16_UNORM_S8_UINT: return 16;
        default: return 0;
    }
}

uint32_t depth_steps_value(uint32_t depth_bits, uint32_t float_bits) {
    if (depth_bits == 32) return float_bits;
    const float levels = depth_bits == 24 ? 16777215.0f : 65535.0f;
    const float z = std::bit_cast<float>(float_bits);
    if (!(z >= 0.0f)) return 0;
    return uint32_t(std::min(z, 1.0f) * levels + 0.5f);  // as the survival shader rounds
}

namespace {

// Whether a fragment at `now` replaces the stored `stored` under `op` (values in steps).
bool replaces(VkCompareOp op, uint32_t now, uint32_t stored) {
    switch (op) {
        case VK_COMPARE_OP_NEVER: return false;
        case VK_COMPARE_OP_LESS: return now < stored;
        case VK_COMPARE_OP_EQUAL: return now == stored;
        case VK_COMPARE_OP_LESS_OR_EQUAL: return now <= stored;
        case VK_COMPARE_OP_GREATER: return now > stored;
        case VK_COMPARE_OP_NOT_EQUAL: return now != stored;
        case VK_COMPARE_OP_GREATER_OR_EQUAL: return now >= stored;
        default: return true;
    }
}

struct PairAcc {
    uint64_t pixels = 0;
    uint32_t min_steps = UINT32_MAX;
};

// One pixel's records (sorted by draw, instance): its winner, and each competitor once.
void analyse_pixel(std::span<const DepthRecord> px, uint32_t depth_bits, uint32_t max_steps,
                   const std::vector<VkCompareOp>& ops, DepthPassAnalysis& out,
                   std::map<std::pair<DrawInstance, DrawInstance>, PairAcc>& pairs) {
    const DepthRecord* winner = nullptr;
    for (const DepthRecord& r : px) {
        const VkCompareOp op = r.draw < ops.size() ? ops[r.draw] : VK_COMPARE_OP_LESS;
        if (!winner || replaces(op, depth_steps_value(depth_bits, r.depth),
                                depth_steps_value(depth_bits, winner->depth)))
            winner = &r;
    }
    const uint32_t pixel = px.front().pixel;
    const DrawInstance w{winner->draw, winner->instance};
    out.winners[pixel] = w;
    const int64_t wv = depth_steps_value(depth_bits, winner->depth);
    std::map<DrawInstance, uint32_t> competing;  // least steps per competitor
    for (const DepthRecord& r : px) {
        const DrawInstance c{r.draw, r.instance};
        if (c == w) continue;
        const int64_t gap = std::abs(int64_t(depth_steps_value(depth_bits, r.depth)) - wv);
        if (gap > int64_t(max_steps)) continue;
        auto [it, added] = competing.try_emplace(c, uint32_t(gap));
        if (!added) it->second = std::min(it->second, uint32_t(gap));
    }
    out.competitors[pixel] = uint32_t(competing.size());
    if (!competing.empty()) ++out.pixels;
    for (const auto& [c, steps] : competing) {
        PairAcc& acc = pairs[std::minmax(w, c)];
        ++acc.pixels;
        acc.min_steps = std::min(acc.min_steps, steps);
    }
}

}  // namespace

DepthPassAnalysis analyse_depth_pass(std::span<const DepthRecord> records, uint32_t width,
                                     uint32_t height, uint32_t depth_bits, uint32_t max_steps,
                                     const std::map<uint32_t, DepthUse>& uses) {
    DepthPassAnalysis out;
    out.width = width;
    out.height = height;
    const size_t n = size_t(width) * height;
    out.competitors.assign(n, 0);
    out.winners.assign(n, DrawInstance{UINT32_MAX, 0});
    // Records by pixel (a counting sort: millions of records for a shadow map), then each
    // pixel's few by draw and instance.
    std::vector<uint32_t> start(n + 1, 0);
    for (const DepthRecord& r : records)
        if (r.pixel < n) ++start[r.pixel + 1];
    for (size_t p = 0; p < n; ++p) start[p + 1] += start[p];
    std::vector<DepthRecord> sorted(start[n]);
    std::vector<uint32_t> next(start.begin(), start.end() - 1);
    for (const DepthRecord& r : records)
        if (r.pixel < n) sorted[next[r.pixel]++] = r;
    // Each draw's compare op by its index.
    std::vector<VkCompareOp> ops(uses.empty() ? 0 : uses.rbegin()->first + 1, VK_COMPARE_OP_LESS);
    for (const auto& [draw, use] : uses) ops[draw] = use.op;
    std::map<std::pair<DrawInstance, DrawInstance>, PairAcc> pairs;
    for (size_t p = 0; p < n; ++p) {
        if (start[p] == start[p + 1]) continue;
        const auto px = std::span(sorted).subspan(start[p], start[p + 1] - start[p]);
        std::sort(px.begin(), px.end(), [](const DepthRecord& a, const DepthRecord& b) {
            return std::tie(a.draw, a.instance) < std::tie(b.draw, b.instance);
        });
        analyse_pixel(px, depth_bits, max_steps, ops, out, pairs);
    }
    for (const auto& [key, acc] : pairs)
        out.pairs.push_back({key.first, key.second, acc.pixels, acc.min_steps});
    std::stable_sort(out.pairs.begin(), out.pairs.end(),
                     [](const DepthPair& a, const DepthPair& b) { return a.pixels > b.pixels; });
    return out;
}

EqualCheckResult equal_check(const uint32_t* words, uint32_t width, uint32_t height,
                             const PrepassWinners& prepass, const std::set<uint32_t>& matched) {
    EqualCheckResult out;
    out.prepass = prepass.pass;
    out.marks.assign(size_t(width) * height, 0);
    for (uint32_t y = 0; y < height; ++y) {
        for (uint32_t x = 0; x < width; ++x) {
            const size_t i = size_t(y) * width + x;
            const uint32_t survivors = words[2 * i + 1];
            DrawInstance w{UINT32_MAX, 0};
            if (x < prepass.width && y < prepass.height)
                w = prepass.winners[size_t(y) * prepass.width + x];
            const bool covered = w.draw != UINT32_MAX && matched.contains(w.draw);
            if (covered && survivors == 0) {
                out.marks[i] = 1;
                ++out.holes;
                ++out.by_winner[w].first;
            } else if (survivors > 1) {
                out.marks[i] = 2;
                ++out.multiple;
                if (w.draw != UINT32_MAX) ++out.by_winner[w].second;
            }
        }
    }
    return out;
}

}  // namespace ds::layer
