#include "layer/frames.h"

#include <nlohmann/json.hpp>

namespace ds::layer {

bool has_depth_pass(const std::vector<PassSummary>& passes) {
    for (const PassSummary& p : passes)
        if (p.depth_format != VK_FORMAT_UNDEFINED) return true;
    return false;
}

bool FrameTracker::open_list(const std::string& out, std::string& error) {
    std::lock_guard lock(mutex_);
    if (list_) return true;  // a second device of the process
    const std::string path = out + "/frames.jsonl";
    list_ = std::fopen(path.c_str(), "a");
    if (!list_) error = "cannot write " + path;
    return list_ != nullptr;
}

uint64_t FrameTracker::submitted(const std::vector<PassSummary>& passes, bool presenting) {
    std::lock_guard lock(mutex_);
    presenting_ = presenting;
    const bool depth = has_depth_pass(passes);
    if (depth) ++depth_submissions_;
    if (!presenting) {
        if (!depth) return depth_submissions_ + 1;
        pending_ = passes;
        pending_submissions_ = 1;
        frame_ = depth_submissions_;
        write(false);
        return depth_submissions_;
    }
    pending_.insert(pending_.end(), passes.begin(), passes.end());
    ++pending_submissions_;
    return frame_;
}

void FrameTracker::presented() {
    std::lock_guard lock(mutex_);
    presenting_ = true;
    write(true);
    ++frame_;
}

void FrameTracker::finish() {
    std::lock_guard lock(mutex_);
    if (presenting_ && pending_submissions_ > 0) write(false);
    if (list_) std::fclose(list_);
    list_ = nullptr;
}

void FrameTracker::write(bool presented) {
    if (list_) {
        nlohmann::json passes = nlohmann::json::array();
        for (const PassSummary& p : pending_)
            passes.push_back({{"dynamic", p.dynamic},
                              {"subpass", p.subpass},
                              {"label", p.label},
                              {"width", p.width},
                              {"height", p.height},
                              {"depth_format", int(p.depth_format)},
                              {"samples", p.samples},
                              {"draws", p.draws}});
        const nlohmann::json line = {{"frame", frame_},
                                     {"delimiter", presenting_ ? "present" : "submission"},
                                     {"presented", presented},
                                     {"submissions", pending_submissions_},
                                     {"passes", passes}};
        std::fprintf(list_, "%s\n", line.dump().c_str());
        std::fflush(list_);
    }
    pending_.clear();
    pending_submissions_ = 0;
}

}  // namespace ds::layer
