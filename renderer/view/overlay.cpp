#include "renderer/view/overlay.h"

#include <algorithm>
#include <cmath>

namespace ds::view {

std::optional<CountImageName> count_image_name(std::string_view image) {
    const size_t cut = image.rfind('_');
    if (cut == std::string_view::npos || cut == 0) return std::nullopt;
    const std::string_view kind = image.substr(cut + 1);
    if (std::find(kCountKinds.begin(), kCountKinds.end(), kind) == kCountKinds.end())
        return std::nullopt;
    return CountImageName{std::string(image.substr(0, cut)), std::string(kind)};
}

std::optional<InspectedImage> wasted_image(const InspectedImage& shaded,
                                           const InspectedImage& depth) {
    const auto name = count_image_name(shaded.name);
    const size_t texels = size_t(shaded.width) * shaded.height;
    if (!name || name->kind != kShadedKind || shaded.semantic != graph::Semantic::Count ||
        !is_perspective_depth(depth.semantic) || shaded.width != depth.width ||
        shaded.height != depth.height || shaded.texels.size() != texels * 4 ||
        depth.texels.size() != texels * 4)
        return std::nullopt;
    InspectedImage out;
    out.name = count_image(name->pass, kWastedKind);
    out.format = shaded.format;
    out.semantic = graph::Semantic::Count;
    out.width = shaded.width;
    out.height = shaded.height;
    out.znear = depth.znear;
    out.zfar = depth.zfar;
    out.reverse_z = depth.reverse_z;
    out.texels.assign(texels * 4, 0.0f);
    const bool reverse = depth.semantic == graph::Semantic::ReverseZDepth;
    for (size_t i = 0; i < texels; ++i) {
        const float covered = is_sky_depth(depth.texels[i * 4], reverse) ? 0.0f : 1.0f;
        out.texels[i * 4] = std::max(shaded.texels[i * 4] - covered, 0.0f);
    }
    return out;
}

float count_max(std::span<const InspectedImage* const> images) {
    float hi = 0.0f;
    for (const InspectedImage* image : images) {
        if (!image) continue;
        for (size_t i = 0; i < image->texels.size(); i += 4)
            if (std::isfinite(image->texels[i])) hi = std::max(hi, image->texels[i]);
    }
    return hi;
}

bool blend_overlay(DecodedView& base, const DecodedView& colours, const InspectedImage& values,
                   float opacity) {
    const size_t texels = size_t(base.width) * base.height;
    if (colours.width != base.width || colours.height != base.height ||
        values.width != base.width || values.height != base.height ||
        base.rgba8.size() != texels * 4 || colours.rgba8.size() != texels * 4 ||
        values.texels.size() != texels * 4)
        return false;
    const float a = std::clamp(opacity, 0.0f, 1.0f);
    for (size_t i = 0; i < texels; ++i) {
        if (values.texels[i * 4] == 0.0f) continue;  // nothing there: transparent
        for (size_t c = 0; c < 3; ++c)
            base.rgba8[i * 4 + c] = blend8(base.rgba8[i * 4 + c], colours.rgba8[i * 4 + c], a);
    }
    return true;
}

}  // namespace ds::view
