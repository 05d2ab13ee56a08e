#pragma once
// Depth precision on the host: how far apart two representable depth values lie in scene
// units at a view depth, for a format's bits, the planes and the direction. What the Depth
// panel plots for the frame's configuration and its alternatives (the GPU's per-pixel view is
// the depth_precision pass).
#include <cstdint>

namespace ds::view {

struct DepthConfig {
    uint32_t bits = 32;  // 32: D32_SFLOAT; 24, 16: unorm
    bool reverse_z = true;
    double znear = 0.1, zfar = 1000.0;
};

// The depth-buffer value at view depth z (znear <= z <= zfar).
double depth_value(const DepthConfig& c, double z);
// One representable step (towards far) at view depth z, in scene units along the view axis:
// the step in depth-buffer value times dz/dd = z^2 (f - n) / (n f).
double step_at(const DepthConfig& c, double z);

}  // namespace ds::view
