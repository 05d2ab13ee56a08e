#pragma once
// Joins: steps after every pass has collected its result that combine two passes' results
// (passes never include each other). The pass list names them (frame_passes.cpp).
#include "renderer/passes/frame_result.h"

namespace ds {

// hiz=on with count_draws=on: each draw's Hi-Z verdict next to its samples_passed, and the
// unsafe disagreements: a draw Hi-Z calls not visible (occluded or outside) whose samples
// passed (HizResult::unsafe) or that won pixels in the final depth (unsafe_visible).
void join_hiz_draws(FrameResult& frame);

}  // namespace ds
