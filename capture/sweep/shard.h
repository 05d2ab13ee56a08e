#pragma once
// Which share of a sweep's jobs one process runs (docs/sweep.md "Shards"): --shard I/N (I from
// 0), or what a scheduler's environment says. Pure functions; the environment comes in as a
// lookup so that tests give their own.
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ds::capture::sweep {

struct Shard {
    int index = 0;  // 0..count-1
    int count = 1;
    std::string source;  // "--shard", "Slurm", "GitLab", "Kubernetes" (messages)
    bool operator==(const Shard& o) const { return index == o.index && count == o.count; }
};

// The most shards a sweep takes.
inline constexpr int kMaxShards = 100000;

// "I/N": decimal digits, 0 <= I < N <= kMaxShards. Throws UsageError naming --shard.
Shard parse_shard(std::string_view text);

// A variable's value, or nullopt when it is not set.
using Environment = std::function<std::optional<std::string>(const char* name)>;
Environment process_environment();  // getenv

// The shard a scheduler's environment gives, nullopt when none does:
//   Slurm       SLURM_ARRAY_TASK_ID set: I = (ID - SLURM_ARRAY_TASK_MIN) / SLURM_ARRAY_TASK_STEP
//               (STEP 1 when unset), N = SLURM_ARRAY_TASK_COUNT;
//   GitLab      CI_NODE_INDEX set: I = CI_NODE_INDEX - 1 (it counts from 1), N = CI_NODE_TOTAL;
//   Kubernetes  JOB_COMPLETION_INDEX set: I = it, N = `count` (sweep --shards N).
// A malformed value, a missing partner variable, an index outside 0..N-1, an ID off the array's
// MIN/STEP grid, `count` without JOB_COMPLETION_INDEX (or one that disagrees with the others'
// N) and two schedulers that disagree are each a UsageError naming the variables.
std::optional<Shard> shard_from_environment(const Environment& env, std::optional<int> count);

// Job i of the list sorted by ID belongs to shard i mod N. `sorted_ids` sorted ascending;
// returns the IDs of `shard`'s jobs.
std::vector<std::string> shard_ids(std::vector<std::string> ids, const Shard& shard);

}  // namespace ds::capture::sweep
