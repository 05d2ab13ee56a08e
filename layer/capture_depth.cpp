#include "layer/capture_depth.h"

namespace ds::layer {

namespace {

// The submission's records by the pass of the draw that made them, draws as frame indices.
std::map<uint32_t, std::vector<DepthRecord>> records_by_pass(const CaptureResources& res,
                                                             CountingRecorder& recorder,
                                                             uint32_t draw_base) {
    std::map<uint32_t, std::vector<DepthRecord>> out;
    const uint32_t n = std::min(res.record_count(), res.record_capacity());
    const uint32_t* words = res.records();
    const std::vector<CapturedDraw>& draws = recorder.draws();
    for (uint32_t i = 0; i < n; ++i) {
        const uint32_t* w = words + 4 * size_t(i);
        if (w[1] >= draws.size()) continue;
        out[draws[w[1]].pass].push_back({w[0], draw_base + w[1], w[2], w[3]});
    }
    return out;
}

void read_zfight(FrameCapture& fc, const CaptureResources& res, CountingRecorder& recorder,
                 const SubmissionPlan& plan, CountingRecorder::Bases bases) {
    auto records = records_by_pass(res, recorder, bases.draw);
    std::map<uint32_t, DepthUse> uses;
    for (const CapturedDraw& d : recorder.draws())
        if (d.depth_recorded) uses[bases.draw + d.slot] = d.depth;
    const uint32_t count = res.record_count(), capacity = res.record_capacity();
    for (const auto& [pass, reverse] : recorder.recorded_passes()) {
        const PassSummary& s = plan.passes[pass];
        const uint32_t w = s.x + s.width, h = s.y + s.height;
        CapturedPass& out = fc.passes[bases.pass + pass];
        out.zfight = analyse_depth_pass(records[pass], w, h, depth_bits_of(s.depth_format),
                                        config().settings.zfight_steps, uses);
        out.zfight->records = records[pass].size();
        out.zfight->dropped = count > capacity ? count - capacity : 0;
        fc.winners[bases.pass + pass] = {bases.pass + pass, w, h, out.zfight->winners};
    }
}

void read_equal(FrameCapture& fc, const CaptureResources& res, CountingRecorder& recorder,
                const SubmissionPlan& plan, CountingRecorder::Bases bases) {
    for (const auto& [pass, matched] : recorder.equal_matches()) {
        int32_t prepass = -1;
        for (const CapturedDraw& d : recorder.draws())
            if (d.pass == pass && d.equal_counted) prepass = d.equal_prepass;
        const auto winners = fc.winners.find(uint32_t(prepass));
        if (winners == fc.winners.end()) {
            fc.not_analysed.push_back("pass " + std::to_string(bases.pass + pass) +
                                      ": the EQUAL check: its prepass has no depth records");
            continue;
        }
        const PassSummary& s = plan.passes[pass];
        fc.passes[bases.pass + pass].equal =
            equal_check(res.depth_words(pass), s.x + s.width, s.y + s.height, winners->second,
                        matched);
    }
}

}  // namespace

void read_depth_records(FrameCapture& fc, const CaptureResources& res,
                        CountingRecorder& recorder, const SubmissionPlan& plan,
                        CountingRecorder::Bases bases) {
    fc.depth_passes = recorder.depth_passes();
    if (!config().settings.depth_records()) return;
    read_zfight(fc, res, recorder, plan, bases);
    if (config().settings.equal_check) read_equal(fc, res, recorder, plan, bases);
}

}  // namespace ds::layer
