// The host's depth-precision model (view/precision.h) against the exact distance between
// neighbouring depth values and the textbook facts it should reproduce.
#include <gtest/gtest.h>

#include <cmath>

#include "renderer/view/precision.h"

namespace {

using ds::view::depth_value;
using ds::view::DepthConfig;
using ds::view::step_at;

// View depth of a depth-buffer value (the inverse of depth_value).
double linear(const DepthConfig& c, double d) {
    const double n = c.znear, f = c.zfar;
    return c.reverse_z ? n * f / (n + d * (f - n)) : n * f / (f - d * (f - n));
}

TEST(DepthPrecision, ValuesMapThePlanesForEitherDirection) {
    const DepthConfig reverse{32, true, 0.1, 1000.0}, forward{32, false, 0.1, 1000.0};
    EXPECT_NEAR(depth_value(reverse, 0.1), 1.0, 1e-12);
    EXPECT_NEAR(depth_value(reverse, 1000.0), 0.0, 1e-12);
    EXPECT_NEAR(depth_value(forward, 0.1), 0.0, 1e-12);
    EXPECT_NEAR(depth_value(forward, 1000.0), 1.0, 1e-12);
    EXPECT_NEAR(linear(forward, depth_value(forward, 12.5)), 12.5, 1e-9);
}

// The derivative times one step matches the exact distance to the next value to 1 %, plus the
// curvature the derivative misses where one step is a sizeable part of the distance (D16 far
// away: about step / z).
TEST(DepthPrecision, StepMatchesTheNextRepresentableValue) {
    for (const uint32_t bits : {32u, 24u, 16u}) {
        for (const bool reverse : {true, false}) {
            const DepthConfig c{bits, reverse, 0.1, 1000.0};
            for (const double z : {0.5, 2.0, 30.0, 400.0}) {
                const double d = depth_value(c, z);
                double next = 0;  // the next representable value towards far
                if (bits == 32) {
                    next = std::nextafter(float(d), reverse ? 0.0f : 1.0f);
                    const double exact = std::abs(linear(c, next) - linear(c, float(d)));
                    EXPECT_NEAR(step_at(c, z) / exact, 1.0, 0.01 + exact / z) << reverse << z;
                } else {
                    const double levels = std::ldexp(1.0, int(bits)) - 1.0;
                    const double q = std::round(d * levels) / levels;
                    next = q + (reverse ? -1.0 : 1.0) / levels;
                    const double exact = std::abs(linear(c, next) - linear(c, q));
                    EXPECT_NEAR(step_at(c, z) / exact, 1.0, 0.01 + exact / z)
                        << bits << reverse << z;
                }
            }
        }
    }
}

// Reverse-Z float: relative precision about constant (2^-24 .. 2^-23 of the distance);
// forward-Z float: no better than 24-bit unorm once the value passes 0.5.
TEST(DepthPrecision, ReverseFloatIsRelativeAndForwardFloatIsLikeD24) {
    const DepthConfig reverse{32, true, 0.01, 10000.0};
    for (const double z : {1.0, 10.0, 100.0}) {
        const double relative = step_at(reverse, z) / z;
        EXPECT_GT(relative, std::ldexp(1.0, -24) * 0.99) << z;
        EXPECT_LT(relative, std::ldexp(1.0, -23) * 1.01) << z;
    }
    const DepthConfig forward32{32, false, 0.01, 10000.0}, forward24{24, false, 0.01, 10000.0};
    for (const double z : {1.0, 100.0, 5000.0}) {
        const double ratio = step_at(forward32, z) / step_at(forward24, z);
        EXPECT_GT(ratio, 0.49) << z;
        EXPECT_LT(ratio, 1.01) << z;
    }
}

}  // namespace
