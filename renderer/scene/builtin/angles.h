#pragma once
// Angles the built-in scene generators share: one definition, as the generators are compiled
// together (a unity build) and each used to carry its own.
#include <numbers>

namespace ds::scene::builtin {

inline constexpr float kPi = std::numbers::pi_v<float>;
inline constexpr float kHalfPi = kPi * 0.5f;

}  // namespace ds::scene::builtin
