#include "capture/resource_files.h"

#include <cmath>

#include "capture/image_writer.h"
#include "renderer/common/error.h"
#include "renderer/format/format.h"
#include "renderer/graph/names.h"
#include "renderer/view/decode.h"

namespace ds::capture {
namespace {

using graph::Semantic;

// Texel component `c` of every texel, transformed by `f`.
template <typename F>
std::vector<float> component(const InspectedImage& image, int c, F f) {
    const size_t texels = size_t(image.width) * image.height;
    std::vector<float> out(texels);
    for (size_t i = 0; i < texels; ++i) out[i] = f(image.texels[i * 4 + size_t(c)]);
    return out;
}

ExrChannel float_channel(const InspectedImage& image, std::string name, int c) {
    return {std::move(name), false, component(image, c, [](float v) { return v; }), {}};
}

ExrChannel uint_channel(const InspectedImage& image, std::string name, int c) {
    ExrChannel out{std::move(name), true, {}, {}};
    const std::vector<float> values = component(image, c, [](float v) { return v; });
    out.uints.reserve(values.size());
    for (const float v : values) out.uints.push_back(v > 0.0f ? uint32_t(std::lround(v)) : 0u);
    return out;
}

// R, G, B, A over the format's meaningful channels ("Y" for one when `grey`).
std::vector<ExrChannel> by_format(const InspectedImage& image, const std::string& layer,
                                  bool grey) {
    const uint32_t n = view::format_channels(image.format);
    const bool integer = format::is_integer(image.format);
    if (n == 1 && grey) return {float_channel(image, layer + "Y", 0)};
    static const char* kNames[4] = {"R", "G", "B", "A"};
    std::vector<ExrChannel> out;
    for (uint32_t c = 0; c < n; ++c)
        out.push_back(integer ? uint_channel(image, layer + kNames[c], int(c))
                              : float_channel(image, layer + kNames[c], int(c)));
    return out;
}

// A Scalar image's one channel, named and typed by its Display ("" names it "Y").
ExrChannel scalar_channel(const InspectedImage& image, const std::string& layer) {
    const graph::Display& d = image.display;
    const std::string name = layer + (d.exr_channel.empty() ? "Y" : d.exr_channel);
    return d.exr_type == graph::ExrType::Uint ? uint_channel(image, name, 0)
                                              : float_channel(image, name, 0);
}

// report.json's "display" of a Scalar image: its graph::Display, field by field.
nlohmann::json display_json(const graph::Display& d) {
    nlohmann::json range = {{"rule", graph::range_rule_name(d.range.rule)}};
    if (d.range.rule == graph::DisplayRange::Rule::Fixed) {
        range["black"] = d.range.black;
        range["white"] = d.range.white;
    }
    return {{"scale", graph::value_scale_name(d.scale)},
            {"range", range},
            {"palette", graph::palette_name(d.palette)},
            {"unit", d.unit},
            {"legend", d.legend},
            {"hover", d.hover},
            {"exr", {{"channel", d.exr_channel}, {"type", graph::exr_type_name(d.exr_type)}}}};
}

}  // namespace

std::vector<ExrChannel> exr_channels(const InspectedImage& image, const std::string& layer) {
    switch (image.semantic) {
        case Semantic::ReverseZDepth:
        case Semantic::ForwardZDepth:
        case Semantic::ShadowDepth:
            return {float_channel(image, layer + "Z", 0)};
        case Semantic::EncodedNormal: {
            std::vector<ExrChannel> out;
            const char* names[3] = {"X", "Y", "Z"};
            for (int c = 0; c < 3; ++c)
                out.push_back({layer + names[c],
                               false,
                               component(image, c, [](float v) { return v * 2.0f - 1.0f; }),
                               {}});
            return out;
        }
        case Semantic::UnormScalar:
        case Semantic::AO:
            return by_format(image, layer, /*grey=*/true);
        case Semantic::HdrColor:
        case Semantic::LdrColor: {
            std::vector<ExrChannel> out = by_format(image, layer, false);
            if (out.size() == 3) out.push_back(float_channel(image, layer + "A", 3));
            return out;
        }
        case Semantic::Count:
            return {uint_channel(image, layer + "count", 0)};
        case Semantic::SurfaceId:
            return {uint_channel(image, layer + "id", 0)};
        case Semantic::DepthStep:
            return {float_channel(image, layer + "step", 0),
                    float_channel(image, layer + "distance", 1)};
        case Semantic::Scalar:
            return {scalar_channel(image, layer)};
        case Semantic::Other:
            break;
    }
    return by_format(image, layer, false);
}

ExrImage exr_image(std::span<const InspectedImage> samples) {
    ExrImage out;
    if (samples.empty()) return out;
    out.width = samples[0].width;
    out.height = samples[0].height;
    for (size_t s = 0; s < samples.size(); ++s) {
        const std::string layer =
            samples.size() == 1 ? std::string() : "sample" + std::to_string(s) + ".";
        for (ExrChannel& c : exr_channels(samples[s], layer)) out.channels.push_back(std::move(c));
    }
    return out;
}

std::string file_stem(const std::string& resource_name) {
    std::string out = resource_name;
    for (char& c : out) {
        const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                          (c >= '0' && c <= '9') || c == '_' || c == '-' || c == '.';
        if (!keep) c = '_';
    }
    if (out.empty() || out[0] == '.') out.insert(out.begin(), '_');
    return out;
}

nlohmann::json write_resource_files(const std::filesystem::path& dir, const ResourceSummary& image,
                                    std::span<const InspectedImage> samples) {
    if (samples.empty()) throw Error("capture: a resource without samples");
    const InspectedImage& first = samples[0];
    const std::string stem = file_stem(first.name);
    const view::DecodedView shown = view::decode(first, view::ViewParams{});
    if (shown.width == 0) throw Error("capture: " + first.name + ": texels do not fill the image");
    write_png_rgba8(dir / (stem + ".png"), shown.width, shown.height, shown.rgba8);
    const ExrImage exr = exr_image(samples);
    write_exr(dir / (stem + ".exr"), exr);

    nlohmann::json channels = nlohmann::json::array();
    for (const ExrChannel& c : exr.channels)
        channels.push_back({{"name", c.name}, {"type", c.is_uint ? "UINT" : "FLOAT"}});
    nlohmann::json entry = {
        {"name", image.name},
        {"format", format::name(image.format)},
        {"width", image.width},
        {"height", image.height},
        {"samples", image.samples},
        {"semantic", graph::semantic_name(image.semantic)},
        {"png",
         {{"file", "resources/" + stem + ".png"},
          {"sample", first.sample},
          {"black", shown.black},
          {"white", shown.white},
          {"unit", shown.unit},
          {"depth_view", view::is_perspective_depth(first.semantic) ? "linear" : ""}}},
        {"exr", {{"file", "resources/" + stem + ".exr"}, {"channels", channels}}},
    };
    // Only Scalar images have one, so the other entries stay as they were. From the read
    // image, which carries what the graph declared, as the PNG and the EXR do.
    if (first.semantic == Semantic::Scalar) entry["display"] = display_json(first.display);
    return entry;
}

}  // namespace ds::capture
