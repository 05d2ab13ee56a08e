#pragma once
// The view library's image decode: turns an InspectedImage (the floats a shader sampling a
// graph image sees) into 8-bit pixels to show (the inspector's viewer; captures later).
// readout.h reads one texel, heat.h holds the count heat map. Pure functions: no Vulkan
// calls, no ImGui; only the data types (renderer/view/image.h) and the format table.
//
// How each semantic is shown (decode):
// - ReverseZDepth / ForwardZDepth: DepthView::Linear shows the linear view distance, near dark
//   and far bright (like distance); DepthView::Raw shows the stored value (so reverse-Z is near
//   bright). Sky texels (stored depth at the far value: 0 reverse-Z, 1 forward-Z) are kSkyColor
//   in both views and never take part in auto-fit. The convention comes from the semantic
//   (InspectedImage::reverse_z is the camera's and agrees with it).
// - ShadowDepth: orthographic, always the raw stored value.
// - EncodedNormal: rgb as stored (n * 0.5 + 0.5); the range is not applied.
// - UnormScalar, AO: r as grey over the range.
// - HdrColor: rgb * 2^exposure, clamped to 0..1, sRGB-encoded; the range is not applied.
// - LdrColor: as stored (already sRGB-encoded); an *_SRGB format samples as linear, so it is
//   encoded again to show what is stored.
// - Count: heat map (count_color) over black..white; a count <= black is black. Auto-fit uses
//   0..max, so zero is always black.
// - Other: the format's first channels as rgb (one channel as grey) over the range.
// - Scalar: r as the image's graph::Display says (graph/display.h: log or linear, its range
//   rule for auto-fit, grey or the heat map); the range is in the value's unit (Log too), the
//   unit is the Display's.
// `channel` 0..3 shows that channel as grey, through the same transform (range, exposure...),
// for the multi-channel semantics (normals, colours, Other); depth, scalars (Scalar too), AO and
// counts have one quantity in r and ignore it. A texel whose shown quantity is NaN or infinite is
// kNonFiniteColor (magenta), and auto-fit skips it.
// Auto-fit: black/white = the finite min/max of the shown quantity over the image (depth:
// excluding sky; counts: black 0, white max; Scalar: its Display's rule). A flat image (min == max)
// shows mid grey; an image with nothing to fit (all sky, all NaN, no count above 0) uses the
// default range: znear..zfar for linear depth, 0..1 otherwise. A manual range with black == white
// is a threshold: at or below black shows 0, above 1; black > white inverts. A colour's alpha
// (channel 3 of HdrColor, LdrColor) shows as stored, clamped to 0..1: no exposure, no encode.
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "renderer/graph/semantic.h"
#include "renderer/view/image.h"

namespace ds::view {

enum class DepthView : uint8_t { Linear, Raw };

struct ViewParams {
    DepthView depth = DepthView::Linear;  // depth semantics (not ShadowDepth: always raw)
    bool auto_fit = true;                 // black/white from the image (see above)
    // Range when !auto_fit, in the shown quantity's units (linear depth: scene units; raw
    // depth, scalars, Other: stored value; counts: count; Scalar: the value, log scale too).
    float black = 0.0f, white = 1.0f;
    int channel = -1;       // -1 all, 0..3 isolate r/g/b/a as grey
    float exposure = 0.0f;  // HdrColor: EV stops, before the clamp and sRGB encode
};

struct DecodedView {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> rgba8;        // tightly packed, row 0 = top, alpha 255
    float black = 0.0f, white = 1.0f;  // the range actually used (after auto-fit); 0..1 where
                                       // the semantic ignores the range
    std::string unit;  // "scene units", "raw depth", "count", a Scalar's, "" (stored values)
};

// Colours with a meaning of their own.
inline constexpr std::array<uint8_t, 3> kSkyColor{24, 32, 96};         // depth: nothing drawn
inline constexpr std::array<uint8_t, 3> kNonFiniteColor{255, 0, 255};  // NaN / infinity

// Decodes the whole image. decode_into reuses `out`'s buffer (call it every frame with the
// same DecodedView to avoid reallocating). An image whose texels do not hold width * height * 4
// floats decodes to an empty view (width = height = 0).
DecodedView decode(const InspectedImage& image, const ViewParams& params);
void decode_into(const InspectedImage& image, const ViewParams& params, DecodedView& out);

// A count image (zfight) over the frame: texels whose count is 0 (or, with `keep`, whose keep
// byte is 0) show the final image (`final_rgba8`, same size, tightly packed) scaled by `dim`;
// the others keep the heat colour `view` decoded. Nothing happens when the sizes differ.
// A selection over whatever the view shows: texels whose `keep` byte is 0 are scaled by `dim`,
// the others stay as decoded (the Draws panel's selected draw). Nothing happens when `keep`
// is not one byte per texel.
void highlight(DecodedView& view, std::span<const uint8_t> keep, float dim);
void overlay_counts(DecodedView& view, const InspectedImage& counts,
                    std::span<const uint8_t> final_rgba8, float dim = 0.3f,
                    std::span<const uint8_t> keep = {});

// The colour a surface id shows as (not 0): a hash, bright enough to read, stable across
// frames, so one surface keeps its colour.
std::array<uint8_t, 3> surface_color(uint32_t id);

// Linear view distance of a stored depth (finite far plane):
// reverse-Z d = n f / (depth (f - n) + n), forward-Z d = n f / (f - depth (f - n)).
float linear_depth(float stored, bool reverse_z, float znear, float zfar);
// A stored depth at (or beyond) the far value: nothing was drawn there.
bool is_sky_depth(float stored, bool reverse_z);
// ReverseZDepth or ForwardZDepth (perspective depth that linearises; not ShadowDepth).
bool is_perspective_depth(graph::Semantic semantic);

// Meaningful channels of a format, from the format table (renderer/format): 1 for depth,
// stencil and R formats, 2 for RG, 3 for RGB and B10G11R11, 4 otherwise (A2B10G10R10 and
// formats the table does not know included).
uint32_t format_channels(VkFormat format);

}  // namespace ds::view
