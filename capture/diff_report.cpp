#include "capture/diff_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include "capture/resource_files.h"
#include "renderer/common/quoted.h"
#include "renderer/view/heat.h"

using nlohmann::json;

namespace ds::capture {
namespace {

std::string printf_text(const char* format, double value) {
    char text[64];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

std::string size_text(uint32_t w, uint32_t h) {
    return std::to_string(w) + "x" + std::to_string(h);
}

std::string percent_text(double percent) {
    return printf_text("%.3f", percent) + " %";
}

// "37/255", "12", "2.3e-04 (rel 1.5e-02)"; "inf" where a NaN or an infinity differed.
std::string largest_text(const RuleLargest& r) {
    if (std::isinf(r.largest)) return "inf";
    switch (r.rule) {
        case DiffRule::Bytes8:
            return printf_text("%.0f", r.largest) + "/255";
        case DiffRule::Uint:
            return printf_text("%.0f", r.largest);
        case DiffRule::Float:
            if (r.largest == 0) return "0";
            return printf_text("%.2g", r.largest) + " (rel " +
                   printf_text("%.2g", r.largest_relative) + ")";
    }
    return "?";
}

std::string largest_list(const ImageDiff& d) {
    std::string out;
    for (const RuleLargest& r : d.rules) out += (out.empty() ? "" : ", ") + largest_text(r);
    return out.empty() ? "0" : out;
}

// "SSIM 0.9873", or why there is none.
std::string ssim_text(const ImageDiff& d) {
    if (!d.ssim) return "SSIM n/a (under 11 pixels on a side)";
    return printf_text("SSIM %.4f", *d.ssim);
}

// Cells in columns: the first `left` columns left-aligned, the rest right-aligned (the last
// one left-aligned too when `last_left`).
class Table {
  public:
    explicit Table(size_t left, bool last_left = false) : left_(left), last_left_(last_left) {}
    void add(std::vector<std::string> row) { rows_.push_back(std::move(row)); }
    std::string text(const std::string& indent) const {
        std::vector<size_t> width;
        for (const auto& row : rows_) {
            width.resize(std::max(width.size(), row.size()), 0);
            for (size_t c = 0; c < row.size(); ++c) width[c] = std::max(width[c], row[c].size());
        }
        std::string out;
        for (const auto& row : rows_) {
            std::string line = indent;
            for (size_t c = 0; c < row.size(); ++c) {
                const std::string pad(width[c] - row[c].size(), ' ');
                const bool left = c < left_ || (last_left_ && c + 1 == row.size());
                line += left ? row[c] + pad : pad + row[c];
                if (c + 1 < row.size()) line += "  ";
            }
            while (!line.empty() && line.back() == ' ') line.pop_back();
            out += line + "\n";
        }
        return out;
    }

  private:
    size_t left_;
    bool last_left_;
    std::vector<std::vector<std::string>> rows_;
};

// The pass table's measures: gpu_ms, then each exact counter that either capture has.
struct Measure {
    const char* name;  // as in report.json
    std::optional<double> (*get)(const PassNumbers&);
    bool is_ms;
};

std::optional<double> counter(const std::optional<uint64_t>& v) {
    return v ? std::optional<double>(double(*v)) : std::nullopt;
}

const Measure kMeasures[] = {
    {"gpu_ms", [](const PassNumbers& p) { return std::optional<double>(p.gpu_ms); }, true},
    {"rasterized_fragments", [](const PassNumbers& p) { return counter(p.rasterized); }, false},
    {"shaded_fragments", [](const PassNumbers& p) { return counter(p.shaded); }, false},
    {"discarded_fragments", [](const PassNumbers& p) { return counter(p.discarded); }, false},
};

std::optional<double> value(const std::optional<PassNumbers>& side, const Measure& m) {
    return side ? m.get(*side) : std::nullopt;
}

std::optional<double> ratio(std::optional<double> a, std::optional<double> b) {
    if (!a || !b || *a == 0) return std::nullopt;
    return *b / *a;
}

bool has(const PassRow& row, const Measure& m) {
    return value(row.a, m) || value(row.b, m);
}

std::string number_text(std::optional<double> v, bool is_ms) {
    if (!v) return "-";
    return printf_text(is_ms ? "%.3f" : "%.0f", *v);
}

// The passes that have any of `measures` (every pass for gpu_ms), a column A, B and B/A for each
// measure that some pass has.
std::string measure_table(const DiffResult& r, std::vector<const Measure*> measures) {
    std::erase_if(measures, [&](const Measure* m) {
        return std::none_of(r.passes.begin(), r.passes.end(),
                            [&](const PassRow& row) { return has(row, *m); });
    });
    if (measures.empty()) return {};
    Table table(1);
    std::vector<std::string> header{"pass"};
    for (const Measure* m : measures) {
        const std::string name =
            m->is_ms ? "gpu_ms" : std::string(m->name).substr(0, std::string(m->name).find('_'));
        header.insert(header.end(), {name + " A", name + " B", "B/A"});
    }
    table.add(header);
    for (const PassRow& row : r.passes) {
        if (std::none_of(measures.begin(), measures.end(),
                         [&](const Measure* m) { return has(row, *m); }))
            continue;
        std::vector<std::string> cells{escaped(row.name)};
        for (const Measure* m : measures) {
            const std::optional<double> a = value(row.a, *m), b = value(row.b, *m);
            const std::optional<double> q = ratio(a, b);
            cells.insert(cells.end(), {number_text(a, m->is_ms), number_text(b, m->is_ms),
                                       q ? printf_text("%.2f", *q) : "-"});
        }
        table.add(cells);
    }
    if (measures.front()->is_ms) {
        const std::optional<double> q = ratio(r.frame_ms_a, r.frame_ms_b);
        table.add({"frame (total)", number_text(r.frame_ms_a, true),
                   number_text(r.frame_ms_b, true), q ? printf_text("%.2f", *q) : "-"});
    }
    return table.text("");
}

// gpu_ms and shaded fragments for every pass; rasterized and discarded fragments in a second
// table of the passes that counted them (one table of all four would not fit a screen's width).
std::string pass_tables(const DiffResult& r) {
    return measure_table(r, {&kMeasures[0], &kMeasures[2]}) +
           measure_table(r, {&kMeasures[1], &kMeasures[3]});
}

// `lead` and the names, comma-separated, wrapped before 100 columns with a 4-space indent.
std::string name_list(const std::string& lead, const std::vector<std::string>& names) {
    std::string out, line = lead;
    size_t on_line = 0;
    for (size_t i = 0; i < names.size(); ++i) {
        const std::string item = escaped(names[i]) + (i + 1 < names.size() ? "," : "");
        if (on_line > 0 && line.size() + 1 + item.size() > 100) {
            out += line + "\n";
            line = "   ";
            on_line = 0;
        }
        line += " " + item;
        ++on_line;
    }
    return out + line + "\n";
}

std::string resources_text(const DiffResult& r) {
    if (!r.a_lists_resources && !r.b_lists_resources)
        return "resources: none listed in either report (captured with --resources none, or "
               "before resources were written)\n";
    std::string out = "resources (most differing first):\n";
    Table table(3, /*last_left=*/true);
    std::vector<std::string> same;
    for (const ImageDiff& d : r.resources) {
        if (d.differing == 0) {
            same.push_back(d.name);
            continue;
        }
        const std::string samples = d.samples > 1 ? " x" + std::to_string(d.samples) : "";
        table.add({escaped(d.name), d.format, size_text(d.width, d.height) + samples,
                   percent_text(d.percent()), std::to_string(d.differing) + " px",
                   "largest " + largest_list(d)});
    }
    out += table.text("  ");
    if (r.resources.empty()) out += "  (none compared)\n";
    if (!same.empty())
        out += name_list("  no pixel differs (" + std::to_string(same.size()) + "):", same);
    for (const NotComparable& n : r.not_comparable)
        out += "  not comparable: " + escaped(n.name) + ": " + n.why + "\n";
    const auto only = [&](const char* side, const std::vector<std::string>& names, bool lists) {
        if (!lists) return std::string("  ") + side + " lists no resources\n";
        if (names.empty()) return std::string();
        return name_list(
            std::string("  only in ") + side + " (" + std::to_string(names.size()) + "):", names);
    };
    out += only("A", r.only_in_a, r.a_lists_resources);
    out += only("B", r.only_in_b, r.b_lists_resources);
    return out;
}

std::string threshold_text(const DiffOptions& o) {
    return std::to_string(o.threshold) + "/255";
}

std::string verdict_text(const DiffResult& r) {
    const std::string limit = printf_text("%g", r.options.max_percent) + " %";
    if (!r.final_image)
        return "verdict: differs (final.png not comparable: " + r.final_not_comparable + ")\n";
    const std::string what = percent_text(r.final_image->percent()) +
                             " of final.png's pixels differ by >= " + threshold_text(r.options);
    return r.passed() ? "verdict: same (" + what + "; at most " + limit + " allowed)\n"
                      : "verdict: differs (" + what + "; more than " + limit + ")\n";
}

json number_or_inf(double v) {
    return std::isinf(v) ? json("inf") : json(v);
}

json image_json(const ImageDiff& d, bool with_heat_map) {
    json rules = json::array();
    for (const RuleLargest& r : d.rules) {
        json entry = {{"rule", diff_rule_name(r.rule)}, {"largest", number_or_inf(r.largest)}};
        if (r.rule == DiffRule::Float) entry["largest_relative"] = r.largest_relative;
        rules.push_back(std::move(entry));
    }
    json out = {{"name", d.name},       {"format", d.format},       {"semantic", d.semantic},
                {"width", d.width},     {"height", d.height},       {"samples", d.samples},
                {"pixels", d.pixels()}, {"differing", d.differing}, {"percent", d.percent()},
                {"largest", rules}};
    if (with_heat_map) out["heat_map"] = heat_map_file(d);
    return out;
}

json side_json(const std::optional<PassNumbers>& p) {
    if (!p) return nullptr;
    json out = {{"kind", p->kind}, {"gpu_ms", p->gpu_ms}};
    if (p->rasterized) out["rasterized_fragments"] = *p->rasterized;
    if (p->shaded) out["shaded_fragments"] = *p->shaded;
    if (p->discarded) out["discarded_fragments"] = *p->discarded;
    return out;
}

json passes_json(const DiffResult& r) {
    json passes = json::array();
    for (const PassRow& row : r.passes) {
        json ratios = json::object();
        for (const Measure& m : kMeasures) {
            const std::optional<double> a = value(row.a, m), b = value(row.b, m);
            if (!a && !b) continue;
            const std::optional<double> q = ratio(a, b);
            ratios[m.name] = q ? json(*q) : json(nullptr);
        }
        passes.push_back({{"name", row.name},
                          {"a", side_json(row.a)},
                          {"b", side_json(row.b)},
                          {"b_over_a", ratios}});
    }
    return passes;
}

json optional_json(std::optional<double> v) {
    return v ? json(*v) : json(nullptr);
}

}  // namespace

std::vector<uint8_t> heat_map_rgba(const ImageDiff& image) {
    std::vector<uint8_t> rgba(image.heat.size() * 4, 0);
    for (size_t p = 0; p < image.heat.size(); ++p) {
        const std::array<uint8_t, 3> rgb =
            image.heat[p] > 0.0f ? view::heat_color(image.heat[p]) : std::array<uint8_t, 3>{};
        std::copy(rgb.begin(), rgb.end(), rgba.begin() + std::ptrdiff_t(p * 4));
        rgba[p * 4 + 3] = 255;
    }
    return rgba;
}

std::string heat_map_file(const ImageDiff& image) {
    return image.name == "final.png" ? "final.png" : "resources/" + file_stem(image.name) + ".png";
}

std::string diff_summary(const DiffResult& r, const DiffNames& names) {
    std::string out = "depthscope diff A " + quote(names.a) + " B " + quote(names.b) + "\n";
    out += "a pixel differs when a channel of any sample differs: 8-bit data by >= " +
           threshold_text(r.options) + ", uint by anything, float by more than " +
           printf_text("%g", kFloatRelative * 100) + " % of the larger (and " +
           printf_text("%g", kFloatAbsolute) + ")\n";
    if (r.final_image) {
        const ImageDiff& f = *r.final_image;
        out += "final.png " + size_text(f.width, f.height) + ": " + percent_text(f.percent()) +
               " (" + std::to_string(f.differing) + " of " + std::to_string(f.pixels()) +
               " pixels), largest " + largest_list(f) + ", " + ssim_text(f) + "\n";
    } else {
        out += "final.png: not comparable: " + r.final_not_comparable + "\n";
    }
    out += resources_text(r);
    out += pass_tables(r);
    if (!names.out.empty()) out += "heat maps and diff.json: " + escaped(names.out) + "\n";
    out += verdict_text(r);
    return out;
}

json diff_json(const DiffResult& r, const DiffNames& names) {
    const bool maps = !names.out.empty();
    json resources = json::array(), not_comparable = json::array();
    for (const ImageDiff& d : r.resources) resources.push_back(image_json(d, maps));
    for (const NotComparable& n : r.not_comparable)
        not_comparable.push_back({{"name", n.name}, {"why", n.why}});
    json final_json = r.final_image
                          ? image_json(*r.final_image, maps)
                          : json{{"name", "final.png"}, {"not_comparable", r.final_not_comparable}};
    if (r.final_image) final_json["ssim"] = optional_json(r.final_image->ssim);
    return {
        {"tool", "depthscope"},
        {"command", "diff"},
        {"a", names.a},
        {"b", names.b},
        {"threshold", r.options.threshold},
        {"max_percent", r.options.max_percent},
        {"rules",
         {{"8-bit", "stored 8-bit codes differ by >= threshold (of 255)"},
          {"uint", "any difference"},
          {"float", "|a - b| > max(" + printf_text("%g", kFloatRelative) + " * max(|a|, |b|), " +
                        printf_text("%g", kFloatAbsolute) + "); NaN against a number differs"},
          {"ssim",
           "final.ssim: mean SSIM (Wang et al. 2004, Gaussian window sigma 1.5) of the "
           "luma 0.2126 R + 0.7152 G + 0.0722 B; null under 11 pixels on a side"}}},
        {"final", final_json},
        {"resources", resources},
        {"not_comparable", not_comparable},
        {"only_in_a", r.only_in_a},
        {"only_in_b", r.only_in_b},
        {"a_lists_resources", r.a_lists_resources},
        {"b_lists_resources", r.b_lists_resources},
        {"passes", passes_json(r)},
        {"frame",
         {{"gpu_ms",
           {{"a", optional_json(r.frame_ms_a)},
            {"b", optional_json(r.frame_ms_b)},
            {"b_over_a", optional_json(ratio(r.frame_ms_a, r.frame_ms_b))}}}}},
        {"verdict",
         {{"same", r.passed()},
          {"final_percent", r.final_image ? json(r.final_image->percent()) : json(nullptr)},
          {"exit_code", diff_exit_code(r)}}},
    };
}

int diff_exit_code(const DiffResult& result) {
    return result.passed() ? 0 : 1;
}

}  // namespace ds::capture
