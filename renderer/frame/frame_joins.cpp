#include "renderer/frame/frame_joins.h"

#include "renderer/passes/draw_counts.h"
#include "renderer/passes/hiz.h"

namespace ds {
namespace {

void fill_hiz(DrawReport& d, HizResult& hiz) {
    if (d.group >= hiz.groups.size()) return;
    d.hiz = hiz.groups[d.group];
    d.hiz_occluded_instances = hiz.occluded_instances[d.group];
    d.hiz_unsafe = *d.hiz != HizVerdict::Visible && d.samples_passed && *d.samples_passed > 0;
    hiz.unsafe = hiz.unsafe.value_or(0) + (d.hiz_unsafe ? 1 : 0);
    const bool won_pixels = d.visible_pixels && *d.visible_pixels > 0;
    hiz.unsafe_visible =
        hiz.unsafe_visible.value_or(0) + (*d.hiz != HizVerdict::Visible && won_pixels ? 1 : 0);
}

}  // namespace

void join_hiz_draws(FrameResult& frame) {
    HizResult* hiz = frame.slots.find<HizResult>();
    DrawsResult* draws = frame.slots.find<DrawsResult>();
    if (!hiz || !draws) return;
    for (DrawReport& d : draws->draws) fill_hiz(d, *hiz);
}

}  // namespace ds
