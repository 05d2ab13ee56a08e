#pragma once
// A sweep job's process: this executable again (/proc/self/exe) with a subcommand's arguments,
// its stdout and stderr into a log file, stdin from /dev/null, killed (SIGKILL) when the sweep
// dies first so that no job outlives the process that would move its folder into place.
#include <filesystem>
#include <string>
#include <vector>

#include "capture/sweep/job_result.h"

namespace ds::app {

// Runs `depthscope ARGS…` and waits for it. Throws ds::Error when it cannot start.
capture::sweep::ChildExit run_child(const std::vector<std::string>& args,
                                    const std::filesystem::path& log);

}  // namespace ds::app
