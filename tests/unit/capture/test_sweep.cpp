// sweep's pure parts (capture/sweep/): the shard formulas of each scheduler's environment, the
// shares of the ID-sorted jobs, job IDs that do not depend on the manifest's order, the
// manifest's errors naming their key, and JUnit's escaping. No device, no process.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

#include "capture/sweep/jobs.h"
#include "capture/sweep/manifest.h"
#include "capture/sweep/shard.h"
#include "capture/sweep/sweep_summary.h"
#include "renderer/common/error.h"

namespace {

using namespace ds::capture::sweep;

Environment env_of(std::map<std::string, std::string> vars) {
    return [vars](const char* name) -> std::optional<std::string> {
        const auto it = vars.find(name);
        if (it == vars.end()) return std::nullopt;
        return it->second;
    };
}

Shard from_env(std::map<std::string, std::string> vars, std::optional<int> count = {}) {
    const std::optional<Shard> s = shard_from_environment(env_of(std::move(vars)), count);
    EXPECT_TRUE(s.has_value());
    return s.value_or(Shard{-1, -1, ""});
}

void expect_usage_error(std::map<std::string, std::string> vars, const std::string& mention,
                        std::optional<int> count = {}) {
    try {
        (void)shard_from_environment(env_of(vars), count);
        ADD_FAILURE() << "no error; expected " << mention;
    } catch (const ds::UsageError& e) {
        EXPECT_NE(std::string(e.what()).find(mention), std::string::npos) << e.what();
    }
}

TEST(SweepShard, ExplicitSpecCountsFromZero) {
    EXPECT_EQ(parse_shard("0/2"), (Shard{0, 2, ""}));
    EXPECT_EQ(parse_shard("1/2"), (Shard{1, 2, ""}));
    for (const char* bad :
         {"2/2", "1", "/2", "0/0", "-1/2", "0x1/2", " 0/2", "0/2 ", "a/b", "0/1/2"})
        EXPECT_THROW(parse_shard(bad), ds::UsageError) << bad;
}

TEST(SweepShard, NoSchedulerNoShard) {
    EXPECT_FALSE(shard_from_environment(env_of({}), std::nullopt));
    // GitLab sets CI_NODE_TOTAL=1 in every job; without parallel: there is no CI_NODE_INDEX.
    EXPECT_FALSE(shard_from_environment(env_of({{"CI_NODE_TOTAL", "1"}}), std::nullopt));
}

TEST(SweepShard, GitLabCountsFromOne) {
    for (int i = 1; i <= 3; ++i)
        EXPECT_EQ(from_env({{"CI_NODE_INDEX", std::to_string(i)}, {"CI_NODE_TOTAL", "3"}}),
                  (Shard{i - 1, 3, ""}));
    expect_usage_error({{"CI_NODE_INDEX", "0"}, {"CI_NODE_TOTAL", "3"}}, "counts from 1");
    expect_usage_error({{"CI_NODE_INDEX", "4"}, {"CI_NODE_TOTAL", "3"}}, "not in 0..2");
    expect_usage_error({{"CI_NODE_INDEX", "1"}}, "CI_NODE_TOTAL is not");
    expect_usage_error({{"CI_NODE_INDEX", "one"}, {"CI_NODE_TOTAL", "3"}}, "not a whole number");
}

TEST(SweepShard, SlurmArrayWithAStep) {
    // sbatch --array=0-6:2: tasks 0, 2, 4, 6.
    const std::map<std::string, std::string> base = {{"SLURM_ARRAY_TASK_MIN", "0"},
                                                     {"SLURM_ARRAY_TASK_STEP", "2"},
                                                     {"SLURM_ARRAY_TASK_COUNT", "4"},
                                                     {"SLURM_ARRAY_TASK_MAX", "6"}};
    for (int id = 0; id <= 6; id += 2) {
        auto vars = base;
        vars["SLURM_ARRAY_TASK_ID"] = std::to_string(id);
        EXPECT_EQ(from_env(vars), (Shard{id / 2, 4, ""}));
    }
    auto off_grid = base;
    off_grid["SLURM_ARRAY_TASK_ID"] = "3";
    expect_usage_error(off_grid, "is not MIN + k * STEP");
}

TEST(SweepShard, SlurmArrayFromThree) {
    // sbatch --array=3-6: STEP 1 (also when Slurm leaves it unset).
    for (int id = 3; id <= 6; ++id) {
        EXPECT_EQ(from_env({{"SLURM_ARRAY_TASK_ID", std::to_string(id)},
                            {"SLURM_ARRAY_TASK_MIN", "3"},
                            {"SLURM_ARRAY_TASK_STEP", "1"},
                            {"SLURM_ARRAY_TASK_COUNT", "4"}}),
                  (Shard{id - 3, 4, ""}));
        EXPECT_EQ(from_env({{"SLURM_ARRAY_TASK_ID", std::to_string(id)},
                            {"SLURM_ARRAY_TASK_MIN", "3"},
                            {"SLURM_ARRAY_TASK_COUNT", "4"}}),
                  (Shard{id - 3, 4, ""}));
    }
    expect_usage_error({{"SLURM_ARRAY_TASK_ID", "2"},
                        {"SLURM_ARRAY_TASK_MIN", "3"},
                        {"SLURM_ARRAY_TASK_COUNT", "4"}},
                       "is not MIN + k * STEP");
    expect_usage_error({{"SLURM_ARRAY_TASK_ID", "3"}, {"SLURM_ARRAY_TASK_COUNT", "4"}},
                       "SLURM_ARRAY_TASK_MIN is not");
    expect_usage_error({{"SLURM_ARRAY_TASK_ID", "9"},
                        {"SLURM_ARRAY_TASK_MIN", "3"},
                        {"SLURM_ARRAY_TASK_COUNT", "4"}},
                       "not in 0..3");
}

TEST(SweepShard, KubernetesIndexWithTheCountGiven) {
    EXPECT_EQ(from_env({{"JOB_COMPLETION_INDEX", "2"}}, 4), (Shard{2, 4, ""}));
    expect_usage_error({{"JOB_COMPLETION_INDEX", "2"}}, "--shards N");
    expect_usage_error({{"JOB_COMPLETION_INDEX", "4"}}, "not in 0..3", 4);
    expect_usage_error({}, "needs JOB_COMPLETION_INDEX", 4);
}

TEST(SweepShard, SchedulersThatDisagreeAreAnError) {
    const std::map<std::string, std::string> both = {{"CI_NODE_INDEX", "1"},
                                                     {"CI_NODE_TOTAL", "2"},  // GitLab 0/2
                                                     {"SLURM_ARRAY_TASK_ID", "1"},
                                                     {"SLURM_ARRAY_TASK_MIN", "0"},
                                                     {"SLURM_ARRAY_TASK_COUNT", "2"}};  // Slurm 1/2
    expect_usage_error(both, "disagree");
    auto agree = both;
    agree["CI_NODE_INDEX"] = "2";
    EXPECT_EQ(from_env(agree), (Shard{1, 2, ""}));
    expect_usage_error(agree, "--shards 3", 3);
}

TEST(SweepShard, SharesCoverEveryJobOnceWhateverTheOrder) {
    std::vector<std::string> ids = {"f0", "0a", "77", "3c", "b1", "19", "e4"};
    std::vector<std::string> reversed(ids.rbegin(), ids.rend());
    std::multiset<std::string> all;
    for (int i = 0; i < 3; ++i) {
        const std::vector<std::string> share = shard_ids(ids, Shard{i, 3, ""});
        EXPECT_EQ(share, shard_ids(reversed, Shard{i, 3, ""}));
        all.insert(share.begin(), share.end());
    }
    EXPECT_EQ(all, std::multiset<std::string>(ids.begin(), ids.end()));
    // Sorted: 0a 19 3c 77 b1 e4 f0; shard 0 of 3 takes the 1st, 4th and 7th.
    EXPECT_EQ(shard_ids(ids, Shard{0, 3, ""}), (std::vector<std::string>{"0a", "77", "f0"}));
}

std::set<std::string> ids_of(const std::string& manifest) {
    std::set<std::string> ids;
    for (const Job& job : expand_jobs(parse_manifest(manifest, "m.json"))) ids.insert(job.id);
    return ids;
}

TEST(SweepJobs, IdsHashTheJobNotItsPlaceInTheManifest) {
    const std::set<std::string> a = ids_of(R"({"scenes": ["atrium", "zfight"],
        "settings": [{"prepass": "off", "msaa": 4}, {}], "actions": ["capture", "bench"]})");
    const std::set<std::string> b = ids_of(R"({"actions": ["bench", "capture"],
        "settings": [{}, {"msaa": "4", "prepass": false}], "scenes": ["zfight", "atrium"]})");
    EXPECT_EQ(a.size(), 8u);
    EXPECT_EQ(a, b);
    const std::set<std::string> c = ids_of(R"({"scenes": ["atrium", "zfight"],
        "settings": [{"prepass": "off", "msaa": 2}, {}], "actions": ["capture", "bench"]})");
    std::vector<std::string> common;
    std::set_intersection(a.begin(), a.end(), c.begin(), c.end(), std::back_inserter(common));
    EXPECT_EQ(common.size(), 4u) << "the msaa=4 jobs change, the default ones do not";
}

TEST(SweepJobs, ManifestErrorsNameTheirKey) {
    const std::pair<const char*, const char*> cases[] = {
        {R"([1])", "m.json: expects a JSON object"},
        {R"({"actions": ["capture"]})", "m.json: scenes: missing"},
        {R"({"scenes": [], "actions": ["capture"]})", "m.json: scenes: expects a non-empty array"},
        {R"({"scenes": ["atrium"], "actions": ["capture"], "cameras": [{"camera": "a",
            "look_at": "0,0,1:0,0,0"}]})",
         "m.json: cameras[0]: camera and look_at exclude each other"},
        {R"({"scenes": ["atrium"], "actions": [{"action": "bench", "frames": 0}]})",
         "m.json: actions[0].frames: expects a whole number in 1..100000"},
        {R"({"scenes": ["atrium"], "actions": [{"action": "capture", "frames": 2}]})",
         "m.json: actions[0].frames: unknown key"},
        {R"({"scenes": ["atrium"], "actions": [{"action": "lint", "fail_on": "hint"}]})",
         "m.json: actions[0].fail_on: expects error, warning or info"},
        {R"({"scenes": ["atrium"], "actions": ["capture"], "common_settings": {"nope": 1}})",
         "m.json: common_settings.nope: "},
        {R"({"scenes": ["atrium", "atrium"], "actions": ["capture"]})", "are the same job"},
    };
    for (const auto& [text, mention] : cases) {
        try {
            (void)expand_jobs(parse_manifest(text, "m.json"));
            ADD_FAILURE() << "no error for " << text;
        } catch (const ds::InputError& e) {
            EXPECT_NE(std::string(e.what()).find(mention), std::string::npos) << e.what();
        }
    }
}

TEST(SweepJunit, EscapesWhatXmlCannotHoldAsIs) {
    EXPECT_EQ(xml_escaped("a<b>&\"c\"'d'"), "a&lt;b&gt;&amp;&quot;c&quot;&apos;d&apos;");
    EXPECT_EQ(xml_escaped(std::string("x\x01y\tz\n")), "x?y\tz\n");
    EXPECT_EQ(xml_escaped("prepass=off · capture"), "prepass=off · capture");
}

}  // namespace
