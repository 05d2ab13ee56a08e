#include "renderer/view/precision.h"

#include <cmath>

namespace ds::view {

double depth_value(const DepthConfig& c, double z) {
    const double n = c.znear, f = c.zfar;
    return c.reverse_z ? n * (f - z) / (z * (f - n)) : f * (z - n) / (z * (f - n));
}

double step_at(const DepthConfig& c, double z) {
    const double d = depth_value(c, z);
    double step = 0.0;
    if (c.bits == 32) {
        const float stored = float(d);
        step = std::abs(double(std::nextafter(stored, c.reverse_z ? 0.0f : 1.0f)) - stored);
    } else {
        step = 1.0 / (std::ldexp(1.0, int(c.bits)) - 1.0);
    }
    return step * z * z * (c.zfar - c.znear) / (c.znear * c.zfar);
}

}  // namespace ds::view
