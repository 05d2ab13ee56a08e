#pragma once
// The frame-wide knobs: what shapes the whole frame rather than one pass (the prepass and its
// mode, the render path, depth conventions and planes, MSAA, alpha, lighting, the field of
// view). Every other knob is declared by what owns it (knob.h).
#include <vector>

#include "renderer/settings/knob.h"

namespace ds::knobs {

inline constexpr Knob<bool> kPrepass{"prepass"};
inline constexpr Knob<KnobEnum> kPrepassMode{"prepass_mode"};  // gbuffer | depth
inline constexpr Knob<KnobEnum> kRenderPath{"render_path"};    // dynamic | subpass
inline constexpr Knob<KnobEnum> kDepthCompare{"depth_compare"};
inline constexpr Knob<bool> kReverseZ{"reverse_z"};
inline constexpr Knob<KnobEnum> kDepthFormat{"depth_format"};
inline constexpr Knob<OptionalFloat> kZnear{"znear"};  // none: the scene camera's
inline constexpr Knob<OptionalFloat> kZfar{"zfar"};
inline constexpr Knob<int> kMsaa{"msaa"};
inline constexpr Knob<bool> kSampleShading{"sample_shading"};
inline constexpr Knob<OptionalFloat> kAlphaCutoff{"alpha_cutoff"};  // none: each material's
inline constexpr Knob<KnobMap> kMaterialAlphaCutoff{"material_alpha_cutoff"};
inline constexpr Knob<bool> kAlphaToCoverage{"alpha_to_coverage"};
inline constexpr Knob<KnobEnum> kAlphaMipCoverage{"alpha_mip_coverage"};  // box | preserve
inline constexpr Knob<bool> kAlphaLevel0{"alpha_level0"};
inline constexpr Knob<float> kSunAzimuth{"sun_azimuth"};
inline constexpr Knob<float> kSunElevation{"sun_elevation"};
inline constexpr Knob<float> kSunIntensity{"sun_intensity"};
inline constexpr Knob<float> kAmbient{"ambient"};
inline constexpr Knob<float> kExposure{"exposure"};
inline constexpr Knob<OptionalFloat> kFov{"fov"};  // none: the scene camera's

// Their declarations, in listing order (the registry puts them first).
std::vector<SettingDef> frame_knobs();

}  // namespace ds::knobs
