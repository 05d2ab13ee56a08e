#include "capture/sweep/shard.h"

#include <algorithm>
#include <charconv>
#include <cstdlib>

#include "renderer/common/error.h"
#include "renderer/common/quoted.h"

namespace ds::capture::sweep {
namespace {

// Decimal digits only (no sign, space or exponent), at most 10^9.
std::optional<long> whole_number(std::string_view text) {
    long value = 0;
    if (text.empty() || text.find_first_not_of("0123456789") != std::string_view::npos)
        return std::nullopt;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || ptr != text.data() + text.size() || value > 1000000000)
        return std::nullopt;
    return value;
}

[[noreturn]] void bad_environment(const std::string& what) {
    throw UsageError("the environment's shard: " + what);
}

// A variable that must be set and hold a whole number.
long number_variable(const Environment& env, const char* name, const char* needed_by) {
    const std::optional<std::string> value = env(name);
    if (!value) bad_environment(std::string(needed_by) + " is set but " + name + " is not");
    const std::optional<long> n = whole_number(*value);
    if (!n) bad_environment(std::string(name) + "=" + quote(*value) + " is not a whole number");
    return *n;
}

Shard checked(long index, long count, const std::string& source, const std::string& vars) {
    if (count < 1 || count > kMaxShards)
        bad_environment(vars + ": the count " + std::to_string(count) + " is not in 1.." +
                        std::to_string(kMaxShards));
    if (index < 0 || index >= count)
        bad_environment(vars + ": shard " + std::to_string(index) + " is not in 0.." +
                        std::to_string(count - 1));
    return {int(index), int(count), source};
}

std::optional<Shard> slurm_shard(const Environment& env) {
    if (!env("SLURM_ARRAY_TASK_ID")) return std::nullopt;
    const char* by = "SLURM_ARRAY_TASK_ID";
    const long id = number_variable(env, "SLURM_ARRAY_TASK_ID", by);
    const long min = number_variable(env, "SLURM_ARRAY_TASK_MIN", by);
    const long step =
        env("SLURM_ARRAY_TASK_STEP") ? number_variable(env, "SLURM_ARRAY_TASK_STEP", by) : 1;
    const long count = number_variable(env, "SLURM_ARRAY_TASK_COUNT", by);
    if (step < 1) bad_environment("SLURM_ARRAY_TASK_STEP=" + std::to_string(step) + " is below 1");
    if (id < min || (id - min) % step != 0)
        bad_environment("SLURM_ARRAY_TASK_ID=" + std::to_string(id) + " is not MIN + k * STEP (" +
                        std::to_string(min) + " + k * " + std::to_string(step) +
                        "): give sbatch --array a range START-END[:STEP]");
    return checked((id - min) / step, count, "Slurm",
                   "(SLURM_ARRAY_TASK_ID - SLURM_ARRAY_TASK_MIN) / SLURM_ARRAY_TASK_STEP of "
                   "SLURM_ARRAY_TASK_COUNT");
}

std::optional<Shard> gitlab_shard(const Environment& env) {
    if (!env("CI_NODE_INDEX")) return std::nullopt;
    const long index = number_variable(env, "CI_NODE_INDEX", "CI_NODE_INDEX");
    const long total = number_variable(env, "CI_NODE_TOTAL", "CI_NODE_INDEX");
    if (index < 1)
        bad_environment("CI_NODE_INDEX=" + std::to_string(index) + " (it counts from 1)");
    return checked(index - 1, total, "GitLab", "CI_NODE_INDEX - 1 of CI_NODE_TOTAL");
}

std::optional<Shard> kubernetes_shard(const Environment& env, std::optional<int> count) {
    if (!env("JOB_COMPLETION_INDEX")) return std::nullopt;
    const long index = number_variable(env, "JOB_COMPLETION_INDEX", "JOB_COMPLETION_INDEX");
    if (!count)
        bad_environment(
            "JOB_COMPLETION_INDEX is set: give the number of shards with --shards N "
            "(the Job's completions)");
    return checked(index, *count, "Kubernetes", "JOB_COMPLETION_INDEX of --shards");
}

std::string describe(const Shard& s) {
    return s.source + " " + std::to_string(s.index) + "/" + std::to_string(s.count);
}

}  // namespace

Shard parse_shard(std::string_view text) {
    const size_t slash = text.find('/');
    const auto fail = [&]() -> Shard {
        throw UsageError("--shard expects I/N with 0 <= I < N <= " + std::to_string(kMaxShards) +
                         " (shards count from 0), got " + quote(text));
    };
    if (slash == std::string_view::npos) return fail();
    const std::optional<long> index = whole_number(text.substr(0, slash));
    const std::optional<long> count = whole_number(text.substr(slash + 1));
    if (!index || !count || *count < 1 || *count > kMaxShards || *index >= *count) return fail();
    return {int(*index), int(*count), "--shard"};
}

Environment process_environment() {
    return [](const char* name) -> std::optional<std::string> {
        const char* value = std::getenv(name);
        if (!value) return std::nullopt;
        return std::string(value);
    };
}

std::optional<Shard> shard_from_environment(const Environment& env, std::optional<int> count) {
    std::vector<Shard> found;
    for (const std::optional<Shard>& s :
         {slurm_shard(env), gitlab_shard(env), kubernetes_shard(env, count)})
        if (s) found.push_back(*s);
    if (found.empty()) {
        if (count) throw UsageError("--shards N needs JOB_COMPLETION_INDEX (Kubernetes) set");
        return std::nullopt;
    }
    for (const Shard& s : found) {
        if (!(s == found.front()))
            bad_environment(describe(found.front()) + " and " + describe(s) + " disagree");
        if (count && s.count != *count)
            bad_environment(describe(s) + " but --shards " + std::to_string(*count));
    }
    return found.front();
}

std::vector<std::string> shard_ids(std::vector<std::string> ids, const Shard& shard) {
    std::sort(ids.begin(), ids.end());
    std::vector<std::string> out;
    for (size_t i = 0; i < ids.size(); ++i)
        if (int(i % size_t(shard.count)) == shard.index) out.push_back(ids[i]);
    return out;
}

}  // namespace ds::capture::sweep
