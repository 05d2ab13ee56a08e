#include "capture/capture_diff.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string_view>

#include "capture/exr_file.h"
#include "renderer/common/error.h"
#include "renderer/common/quoted.h"
#include "renderer/metrics/luma.h"
#include "renderer/metrics/ssim.h"
#include "renderer/metrics/threshold.h"

namespace ds::capture {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// One rule's differences over an image: per pixel the largest (0: none over the threshold).
struct RuleAccumulator {
    DiffRule rule;
    std::vector<double> magnitude;
    double largest = 0, largest_finite = 0, largest_relative = 0;

    void add(size_t pixel, double m, double relative = 0) {
        if (!(m > 0)) return;
        magnitude[pixel] = std::max(magnitude[pixel], m);
        largest = std::max(largest, m);
        if (std::isfinite(m)) largest_finite = std::max(largest_finite, m);
        largest_relative = std::max(largest_relative, relative);
    }
};

// The rules' magnitudes folded into the image's counts, largest values and heat.
class Accumulators {
  public:
    // At most one accumulator per rule: references from of() stay valid.
    explicit Accumulators(size_t pixels) : pixels_(pixels) { rules_.reserve(3); }

    RuleAccumulator& of(DiffRule rule) {
        for (RuleAccumulator& r : rules_)
            if (r.rule == rule) return r;
        rules_.push_back({rule, std::vector<double>(pixels_, 0.0), 0, 0, 0});
        return rules_.back();
    }

    void finish(ImageDiff& out) const {
        out.heat.assign(pixels_, 0.0f);
        out.differing = 0;
        for (const RuleAccumulator& r : rules_) {
            out.rules.push_back({r.rule, r.largest, r.largest_relative});
            for (size_t p = 0; p < pixels_; ++p) {
                const double m = r.magnitude[p];
                if (!(m > 0)) continue;
                // Finite differences over the largest finite one: every differing pixel > 0.
                const double t = std::isfinite(m) ? m / r.largest_finite : 1.0;
                out.heat[p] = std::max(out.heat[p], std::max(float(t), 1e-6f));
            }
        }
        for (const float t : out.heat) out.differing += t > 0.0f ? 1 : 0;
    }

  private:
    size_t pixels_;
    std::vector<RuleAccumulator> rules_;
};

// The 8-bit code an EXR value was stored as (resource_files.h: an 8-bit colour's EXR holds
// the stored UNORM value, SRGB formats' too); -1 for NaN.
int unorm8_code(float v) {
    if (std::isnan(v)) return -1;
    return int(std::lround(std::clamp(double(v), 0.0, 1.0) * 255.0));
}

double bytes8_magnitude(int a, int b, int threshold) {
    if (a < 0 || b < 0) return a == b ? 0 : kInf;
    const int d = std::abs(a - b);
    return d >= threshold ? double(d) : 0;
}

double float_magnitude(float a, float b, double& relative) {
    relative = 0;
    if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b) ? 0 : kInf;
    if (a == b) return 0;  // equal infinities too
    const double d = std::fabs(double(a) - double(b));
    if (!std::isfinite(d)) return kInf;
    const double scale = std::max(std::fabs(double(a)), std::fabs(double(b)));
    if (d <= std::max(kFloatRelative * scale, kFloatAbsolute)) return 0;
    relative = d / scale;
    return d;
}

void compare_channel(const ExrChannel& a, const ExrChannel& b, const ResourceRef& ref,
                     int threshold, Accumulators& acc) {
    const size_t n = a.is_uint ? a.uints.size() : a.floats.size();
    if (a.is_uint) {
        RuleAccumulator& r = acc.of(DiffRule::Uint);
        for (size_t p = 0; p < n; ++p)
            if (a.uints[p] != b.uints[p])
                r.add(p, std::fabs(double(a.uints[p]) - double(b.uints[p])));
        return;
    }
    if (is_unorm8(ref.format)) {
        RuleAccumulator& r = acc.of(DiffRule::Bytes8);
        for (size_t p = 0; p < n; ++p)
            r.add(p,
                  bytes8_magnitude(unorm8_code(a.floats[p]), unorm8_code(b.floats[p]), threshold));
        return;
    }
    RuleAccumulator& r = acc.of(DiffRule::Float);
    for (size_t p = 0; p < n; ++p) {
        double relative = 0;
        const double m = float_magnitude(a.floats[p], b.floats[p], relative);
        r.add(p, m, relative);
    }
}

void check_exr_size(const ExrImage& exr, const ResourceRef& ref) {
    if (exr.width != ref.width || exr.height != ref.height)
        throw Error(escaped(ref.exr.string()) + ": " + std::to_string(exr.width) + "x" +
                    std::to_string(exr.height) + ", report.json says " + std::to_string(ref.width) +
                    "x" + std::to_string(ref.height));
}

std::string channel_list(const ExrImage& exr) {
    std::string out;
    for (const ExrChannel& c : exr.channels)
        out += (out.empty() ? "" : ",") + c.name + (c.is_uint ? ":uint" : "");
    return out;
}

// Both EXRs, channel by channel; nullopt (and `why`) when their channels differ.
std::optional<ImageDiff> diff_resource(const ResourceRef& a, const ResourceRef& b, int threshold,
                                       std::string& why) {
    const ExrImage ea = read_exr(a.exr);
    const ExrImage eb = read_exr(b.exr);
    check_exr_size(ea, a);
    check_exr_size(eb, b);
    const std::string ca = channel_list(ea), cb = channel_list(eb);
    if (ca != cb) {
        why = "EXR channels " + ca + " vs " + cb;
        return std::nullopt;
    }
    ImageDiff d{a.name, a.format, a.semantic, a.width, a.height, a.samples, 0, {}, {}, {}};
    Accumulators acc(d.pixels());
    for (size_t c = 0; c < ea.channels.size(); ++c)
        compare_channel(ea.channels[c], eb.channels[c], a, threshold, acc);
    acc.finish(d);
    return d;
}

const ResourceRef* find_resource(const CaptureFolder& c, const std::string& name) {
    for (const ResourceRef& r : c.resources)
        if (r.name == name) return &r;
    return nullptr;
}

void diff_resources(const CaptureFolder& a, const CaptureFolder& b, const DiffOptions& options,
                    const std::function<void(const ImageDiff&)>& on_image, DiffResult& out) {
    for (const ResourceRef& ra : a.resources) {
        const ResourceRef* rb = find_resource(b, ra.name);
        if (!rb) {
            out.only_in_a.push_back(ra.name);
            continue;
        }
        std::string why = why_not_comparable(ra, *rb);
        std::optional<ImageDiff> d;
        if (why.empty()) d = diff_resource(ra, *rb, options.threshold, why);
        if (!d) {
            out.not_comparable.push_back({ra.name, why});
            continue;
        }
        if (on_image) on_image(*d);
        d->heat = {};
        out.resources.push_back(std::move(*d));
    }
    for (const ResourceRef& rb : b.resources)
        if (!find_resource(a, rb.name)) out.only_in_b.push_back(rb.name);
    std::stable_sort(
        out.resources.begin(), out.resources.end(),
        [](const ImageDiff& x, const ImageDiff& y) { return x.percent() > y.percent(); });
}

}  // namespace

const char* diff_rule_name(DiffRule rule) {
    switch (rule) {
        case DiffRule::Bytes8:
            return "8-bit";
        case DiffRule::Uint:
            return "uint";
        case DiffRule::Float:
            return "float";
    }
    return "?";
}

bool is_unorm8(const std::string& format_name) {
    // The channel part of the name: letter + "8" per channel ("R8G8B8A8", "B8G8R8A8", "R8").
    const size_t underscore = format_name.find('_');
    if (underscore == std::string::npos || underscore == 0 || underscore % 2 != 0) return false;
    for (size_t i = 0; i < underscore; i += 2) {
        if (std::string_view("RGBA").find(format_name[i]) == std::string_view::npos ||
            format_name[i + 1] != '8')
            return false;
    }
    const std::string numeric = format_name.substr(underscore + 1);
    return numeric == "UNORM" || numeric == "SRGB";
}

bool DiffResult::passed() const {
    return final_image && final_image->percent() <= options.max_percent;
}

ImageDiff diff_final(const Rgba8Image& a, const Rgba8Image& b, int threshold) {
    ImageDiff d{"final.png", "RGBA8", "LdrColor", a.width, a.height, 1, 0, {}, {}, {}};
    const metrics::Rgba8View va{a.width, a.height, a.rgba}, vb{b.width, b.height, b.rgba};
    Accumulators acc(d.pixels());
    RuleAccumulator& r = acc.of(DiffRule::Bytes8);
    const std::vector<uint8_t> largest = metrics::largest_channel_differences(va, vb);
    for (size_t p = 0; p < largest.size(); ++p)
        r.add(p, metrics::over_threshold(largest[p], threshold) ? double(largest[p]) : 0.0);
    acc.finish(d);
    return d;
}

std::optional<double> final_ssim(const Rgba8Image& a, const Rgba8Image& b) {
    if (a.width < metrics::kSsimWindow || a.height < metrics::kSsimWindow) return std::nullopt;
    const metrics::Rgba8View va{a.width, a.height, a.rgba}, vb{b.width, b.height, b.rgba};
    return metrics::ssim(metrics::luma(va), metrics::luma(vb)).mean;
}

std::string why_not_comparable(const ResourceRef& a, const ResourceRef& b) {
    const auto size = [](const ResourceRef& r) {
        return std::to_string(r.width) + "x" + std::to_string(r.height);
    };
    if (a.width != b.width || a.height != b.height) return "size " + size(a) + " vs " + size(b);
    if (a.format != b.format) return "format " + a.format + " vs " + b.format;
    if (a.samples != b.samples)
        return "samples " + std::to_string(a.samples) + " vs " + std::to_string(b.samples);
    if (a.semantic != b.semantic) return "semantic " + a.semantic + " vs " + b.semantic;
    return {};
}

std::vector<PassRow> match_passes(const std::vector<PassNumbers>& a,
                                  const std::vector<PassNumbers>& b) {
    // The n-th pass of a name in A meets the n-th of that name in B.
    const auto nth = [](const std::vector<PassNumbers>& list, size_t index) {
        size_t n = 0;
        for (size_t i = 0; i < index; ++i) n += list[i].name == list[index].name ? 1 : 0;
        return n;
    };
    const auto find = [](const std::vector<PassNumbers>& list, const std::string& name,
                         size_t n) -> const PassNumbers* {
        for (const PassNumbers& p : list)
            if (p.name == name && n-- == 0) return &p;
        return nullptr;
    };
    std::vector<PassRow> rows;
    for (size_t i = 0; i < a.size(); ++i) {
        PassRow row{a[i].name, a[i], std::nullopt};
        if (const PassNumbers* match = find(b, a[i].name, nth(a, i))) row.b = *match;
        rows.push_back(std::move(row));
    }
    for (size_t i = 0; i < b.size(); ++i)
        if (!find(a, b[i].name, nth(b, i))) rows.push_back({b[i].name, std::nullopt, b[i]});
    return rows;
}

DiffResult diff_captures(const CaptureFolder& a, const CaptureFolder& b, const DiffOptions& options,
                         const std::function<void(const ImageDiff&)>& on_image) {
    DiffResult out;
    out.options = options;
    const Rgba8Image& fa = a.final_image;
    const Rgba8Image& fb = b.final_image;
    if (fa.width == fb.width && fa.height == fb.height) {
        ImageDiff d = diff_final(fa, fb, options.threshold);
        d.ssim = final_ssim(fa, fb);
        if (on_image) on_image(d);
        d.heat = {};
        out.final_image = std::move(d);
    } else {
        out.final_not_comparable = "size " + std::to_string(fa.width) + "x" +
                                   std::to_string(fa.height) + " vs " + std::to_string(fb.width) +
                                   "x" + std::to_string(fb.height);
    }
    out.a_lists_resources = a.lists_resources;
    out.b_lists_resources = b.lists_resources;
    diff_resources(a, b, options, on_image, out);
    out.passes = match_passes(a.passes, b.passes);
    out.frame_ms_a = a.frame_gpu_ms;
    out.frame_ms_b = b.frame_gpu_ms;
    return out;
}

}  // namespace ds::capture
