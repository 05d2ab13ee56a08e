#pragma once
// The Hi-Z test's verdict on a draw: what HizResult (hiz.h) holds per group and the join puts
// into each DrawReport (draw_counts.h), so that neither pass includes the other.
#include <cstdint>

namespace ds {

// hiz=on with count_draws=on: what the Hi-Z test says of a draw group's instances, from their
// world bounds' screen rectangle and nearest depth against the pyramid. Visible: it may be seen
// (or the box crosses the near plane, where the test says nothing); Occluded: every sample it
// could cover is farther than the pyramid's farthest depth there; Outside: off screen or
// beyond the far plane (frustum culled). A group is Visible when any instance is, else
// Occluded when any instance is, else Outside.
enum class HizVerdict : uint8_t { Visible, Occluded, Outside };
inline const char* hiz_verdict_name(HizVerdict verdict) {
    return verdict == HizVerdict::Occluded  ? "occluded"
           : verdict == HizVerdict::Outside ? "outside"
                                            : "visible";
}

}  // namespace ds
