// depthscope sweep through the real executable (docs/sweep.md), every capture at 96x64: the
// acceptance cases of issue 31's sweep (4 jobs from 2 scenes x 2 settings, shards merged equal a
// one-process run, JUnit XML that a real parser reads, a baseline that passes an identical re-run
// and flags a changed setting or count, a killed sweep's jobs as failed "no result" testcases)
// and bad input (one error line, nothing written). The lint action's case waits for `lint`.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/support/run_process.h"

namespace {

namespace fs = std::filesystem;
using ds::test::ProcessResult;
using ds::test::read_file;
using nlohmann::json;

// No scheduler's shard from the environment the tests run in (a CI job may set one).
ProcessResult sweep(const std::string& args, int timeout_s = 120) {
    return ds::test::run_command(
        "env -u CI_NODE_INDEX -u SLURM_ARRAY_TASK_ID -u JOB_COMPLETION_INDEX " DS_EXECUTABLE
        " sweep " +
            args,
        timeout_s);
}

fs::path write_manifest(const fs::path& dir, const std::string& name, const std::string& text) {
    const fs::path path = dir / name;
    std::ofstream(path) << text;
    return path;
}

// 2 scenes x 2 settings of captures, counted.
std::string two_by_two(const std::string& second_setting = "\"prepass\": \"off\"") {
    return R"({"scenes": ["zfight", "decals"], "common_settings": {"count_fragments": true},
               "settings": [{"prepass": "on"}, {)" +
           second_setting + R"(}], "actions": ["capture"], "size": "96x64"})";
}

// The JUnit file read by python3's xml.etree: "TESTCASES FAILURES" and each failure's message.
std::string parse_junit(const fs::path& xml) {
    const fs::path script = xml.parent_path() / "read_junit.py";
    std::ofstream(script) << "import sys, xml.etree.ElementTree as E\n"
                             "cases = E.parse(sys.argv[1]).getroot().iter('testcase')\n"
                             "cases = list(cases)\n"
                             "fails = [c.find('failure') for c in cases]\n"
                             "fails = [f for f in fails if f is not None]\n"
                             "print(len(cases), len(fails))\n"
                             "for f in fails: print(f.get('message'))\n";
    const ProcessResult r =
        ds::test::run_command("python3 " + script.string() + " " + xml.string());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return r.out;
}

json read_json(const fs::path& path) {
    return json::parse(read_file(path), nullptr, false);
}

// Each job's result.json in A equals B's but for its wall time.
void expect_same_results(const fs::path& a, const fs::path& b) {
    const json summary = read_json(a / "sweep.json");
    ASSERT_TRUE(summary.contains("results")) << summary.dump();
    for (const json& r : summary["results"]) {
        const std::string id = r["id"];
        json ra = read_json(a / "jobs" / id / "result.json");
        json rb = read_json(b / "jobs" / id / "result.json");
        ra.erase("seconds");
        rb.erase("seconds");
        EXPECT_EQ(ra, rb) << id;
    }
    const std::regex time(" time=\"[^\"]*\"");
    EXPECT_EQ(std::regex_replace(read_file(a / "junit.xml"), time, ""),
              std::regex_replace(read_file(b / "junit.xml"), time, ""));
}

TEST(Sweep, FourJobsAndTwoShardsMergedEqualTheOneProcessRun) {
    const fs::path dir = ds::test::fresh_dir("sweep_shards");
    const fs::path manifest = write_manifest(dir, "m.json", two_by_two());
    const ProcessResult one = sweep(manifest.string() + " --out " + (dir / "one").string());
    ASSERT_EQ(one.exit_code, 0) << one.err << one.out;
    const json summary = read_json(dir / "one" / "sweep.json");
    EXPECT_EQ(summary["jobs"], 4);
    EXPECT_EQ(summary["passed"], 4);
    EXPECT_EQ(std::distance(fs::directory_iterator(dir / "one" / "jobs"), {}), 4);
    for (const json& r : summary["results"]) {
        EXPECT_TRUE(fs::is_regular_file(dir / "one/jobs" / r["id"].get<std::string>() /
                                        "capture/final.png"));
        EXPECT_TRUE(r["counts"].contains("passes")) << r.dump();
    }
    EXPECT_EQ(parse_junit(dir / "one" / "junit.xml"), "4 0\n");
    EXPECT_NE(read_file(dir / "one" / "report.md").find("](jobs/"), std::string::npos);

    for (const char* shard : {"0/2", "1/2"}) {
        const ProcessResult r = sweep(manifest.string() + " --shard " + shard + " --out " +
                                      (dir / ("shard" + std::string(1, shard[0]))).string());
        ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
        EXPECT_NE(r.out.find("2 of 4 jobs"), std::string::npos) << r.out;
        EXPECT_FALSE(fs::exists(dir / ("shard" + std::string(1, shard[0])) / "sweep.json"));
    }
    const ProcessResult merge =
        sweep("--merge " + (dir / "shard0").string() + " " + (dir / "shard1").string() + " --out " +
              (dir / "merged").string());
    ASSERT_EQ(merge.exit_code, 0) << merge.err << merge.out;
    EXPECT_EQ(read_file(dir / "merged" / "sweep.json"), read_file(dir / "one" / "sweep.json"));
    expect_same_results(dir / "merged", dir / "one");
}

TEST(Sweep, ABaselinePassesAnIdenticalRerunAndFlagsAChangedSettingOrCount) {
    const fs::path dir = ds::test::fresh_dir("sweep_baseline");
    const std::string one_scene = R"({"scenes": ["zfight"], "common_settings":
        {"count_fragments": "on", "zfight": "on"}, "settings": [{}, {"prepass": "off"}],
        "actions": ["capture"], "size": "96x64"})";
    const fs::path manifest = write_manifest(dir, "m.json", one_scene);
    ASSERT_EQ(sweep(manifest.string() + " --out " + (dir / "base").string()).exit_code, 0);
    const std::string base = " --baseline " + (dir / "base").string();
    const ProcessResult same =
        sweep(manifest.string() + " --out " + (dir / "again").string() + base);
    EXPECT_EQ(same.exit_code, 0) << same.err << same.out;
    EXPECT_NE(same.out.find("0 regressions"), std::string::npos) << same.out;

    std::string changed_text = one_scene;
    changed_text.replace(changed_text.find("\"prepass\": \"off\""), 16,
                         "\"depth_format\": \"d16\"");
    const fs::path changed = write_manifest(dir, "changed.json", changed_text);
    const ProcessResult c = sweep(changed.string() + " --out " + (dir / "changed").string() + base);
    EXPECT_EQ(c.exit_code, 1) << c.err << c.out;
    EXPECT_NE(c.out.find("regression: baseline job not in this sweep: zfight · scene camera · "
                         "count_fragments=on prepass=off zfight=on · capture"),
              std::string::npos)
        << c.out;
    EXPECT_NE(c.out.find("new job, not in the baseline: zfight · scene camera · "
                         "count_fragments=on depth_format=d16 zfight=on · capture"),
              std::string::npos)
        << c.out;

    // The same jobs with a count that differs: a baseline whose sweep.json says one more shaded
    // fragment in the prepass-on job's forward pass.
    json edited = read_json(dir / "base" / "sweep.json");
    json& forward = edited["results"][0]["counts"]["passes"]["forward"];
    forward["shaded_fragments"] = forward["shaded_fragments"].get<uint64_t>() + 1;
    std::ofstream(dir / "base" / "sweep.json") << edited.dump(2);
    const ProcessResult counts =
        sweep("--merge " + (dir / "again").string() + " --out " + (dir / "again").string() + base);
    EXPECT_EQ(counts.exit_code, 1) << counts.err << counts.out;
    EXPECT_NE(counts.out.find("counts.passes.forward.shaded_fragments: "), std::string::npos)
        << counts.out;
    EXPECT_NE(parse_junit(dir / "again" / "junit.xml").find("2 1\nbaseline: counts.passes."),
              std::string::npos);
}

TEST(Sweep, BenchTimingsAreReportedAgainstABaselineNeverCompared) {
    const fs::path dir = ds::test::fresh_dir("sweep_bench");
    const fs::path manifest = write_manifest(dir, "m.json", R"({"scenes": ["overdraw"],
        "actions": [{"action": "bench", "frames": 2, "warmup": 0}], "size": "96x64"})");
    ASSERT_EQ(sweep(manifest.string() + " --out " + (dir / "a").string()).exit_code, 0);
    const ProcessResult b = sweep(manifest.string() + " --out " + (dir / "b").string() +
                                  " --baseline " + (dir / "a").string());
    EXPECT_EQ(b.exit_code, 0) << b.err << b.out;
    EXPECT_NE(b.out.find("note: overdraw · scene camera · defaults · bench: frame ms (median) "),
              std::string::npos)
        << b.out;
    const json summary = read_json(dir / "b" / "sweep.json");
    EXPECT_FALSE(summary["results"][0].contains("timings")) << "sweep.json holds no times";
}

// lint jobs: zfight's coplanar pairs fail at --fail-on error (the reason is lint's counts),
// atrium passes; the JUnit has both, one failed; the counts are in sweep.json.
TEST(Sweep, LintJobsFailByTheirFindingsInTheJunit) {
    const fs::path dir = ds::test::fresh_dir("sweep_lint");
    const fs::path manifest = write_manifest(dir, "m.json", R"({"scenes": ["zfight", "atrium"],
        "actions": [{"action": "lint", "fail_on": "error"}]})");
    const ProcessResult r = sweep(manifest.string() + " --out " + (dir / "out").string());
    EXPECT_EQ(r.exit_code, 1) << r.err << r.out;
    EXPECT_EQ(parse_junit(dir / "out" / "junit.xml"),
              "2 1\nlint: 6 errors, 0 warnings, 5 infos at --fail-on error (lint.json)\n");
    const json summary = read_json(dir / "out" / "sweep.json");
    ASSERT_EQ(summary["results"].size(), 2u) << summary.dump();
    for (const json& job : summary["results"])
        EXPECT_EQ(job["lint"]["numErrors"], job["scene"] == "zfight" ? 6 : 0) << job.dump();
}

// The sweep (and with it its running job) is killed with SIGKILL while a job runs: that job has
// no folder, and the merge makes it a failed testcase "no result". Run again, every job passes.
TEST(Sweep, AJobKilledMidRunIsAFailedTestcaseAfterTheMerge) {
    const fs::path dir = ds::test::fresh_dir("sweep_killed");
    const fs::path manifest = write_manifest(dir, "m.json", R"({"scenes": ["atrium"],
        "settings": [{"prepass": "on"}, {"prepass": "off"}], "actions": ["capture"],
        "size": "96x64"})");
    const fs::path out = dir / "out";
    // Once the first job's folder is in place and the second's staging folder exists, the
    // sweep's process group is killed (set -m: the background job is a group of its own).
    const std::string script =
        "set -m; " DS_EXECUTABLE " sweep " + manifest.string() + " --out " + out.string() +
        " & pid=$!; for i in $(seq 2000); do finished=$(ls " + (out / "jobs").string() +
        " 2>/dev/null | grep -c -v tmp-); staging=$(ls " + (out / "jobs").string() +
        " 2>/dev/null | grep -c tmp-); [ \"$finished\" = 1 ] && [ \"$staging\" = 1 ] && break; "
        "sleep 0.01; done; kill -KILL -- -$pid; wait $pid; echo status=$?";
    std::ofstream(dir / "kill.sh") << script << "\n";
    const ProcessResult killed = ds::test::run_command(
        "env -u CI_NODE_INDEX -u SLURM_ARRAY_TASK_ID -u JOB_COMPLETION_INDEX bash " +
        (dir / "kill.sh").string());
    ASSERT_NE(killed.out.find("status=137"), std::string::npos) << killed.out << killed.err;
    EXPECT_FALSE(fs::exists(out / "sweep.json"));

    const ProcessResult merge = sweep("--merge " + out.string() + " --out " + (dir / "m").string());
    EXPECT_EQ(merge.exit_code, 1) << merge.err << merge.out;
    EXPECT_EQ(read_json(dir / "m" / "sweep.json")["no_result"], 1);
    const std::string junit = parse_junit(dir / "m" / "junit.xml");
    EXPECT_EQ(junit.rfind("2 1\nno result: ", 0), 0u) << junit;

    const ProcessResult again = sweep(manifest.string() + " --out " + out.string());
    EXPECT_EQ(again.exit_code, 0) << again.err << again.out;
    EXPECT_EQ(parse_junit(out / "junit.xml"), "2 0\n");
}

TEST(Sweep, BadInputIsOneErrorLineAndWritesNothing) {
    const fs::path dir = ds::test::fresh_dir("sweep_bad");
    const fs::path good = write_manifest(dir, "good.json", two_by_two());
    std::ofstream(dir / "a_file") << "x";
    const std::string out = " --out " + (dir / "out").string();
    const auto manifest = [&](const std::string& name, const std::string& text) {
        return write_manifest(dir, name, text).string();
    };
    struct Case {
        std::string args;
        int code;
        std::string mention;
    };
    const Case cases[] = {
        {manifest("a.json", "{\"scenes\": [") + out, 1, "a.json: not valid JSON"},
        {manifest("b.json", R"({"scenes": ["nosuch.gltf"], "actions": ["capture"]})") + out, 1,
         "b.json: scenes[0]: 'nosuch.gltf' is neither a built-in scene"},
        {manifest("c.json", R"({"scenes": ["atrium"], "actions": ["capture"], "sise": "8x8"})") +
             out,
         1, "c.json: sise: unknown key"},
        {manifest("d.json", R"({"scenes": ["atrium"], "actions": ["capture"],
            "settings": [{}, {"msaa": 3}]})") +
             out,
         1, "d.json: settings[1].msaa: "},
        {manifest("e.json", R"({"scenes": ["atrium"], "actions": ["paint"]})") + out, 1,
         "e.json: actions[0]: expects capture, bench or lint"},
        {manifest("f.json", R"({"scenes": ["atrium"], "actions": ["capture"], "size": "0x9"})") +
             out,
         1, "f.json: size: "},
        {(dir / "missing.json").string() + out, 1, "missing.json: no such file"},
        {good.string() + " --out " + (dir / "a_file" / "out").string(), 1, "cannot create"},
        {good.string() + " --out " + (dir / "a_file").string(), 1, "exists and is not a folder"},
        {good.string() + out + " --shard 2/2", 2, "--shard expects I/N"},
        {good.string() + out + " --shard 1", 2, "--shard expects I/N"},
        {good.string() + out + " --shard 0/2 --baseline " + dir.string(), 2, "--baseline"},
        {"--merge " + (dir / "nothing").string() + out, 1, "no folder holds a sweep"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.args);
        ds::test::expect_one_error_line(sweep(c.args), c.code, c.mention);
        EXPECT_FALSE(fs::exists(dir / "out"));
    }
    // A scheduler's environment that makes no sense.
    const ProcessResult gitlab = ds::test::run_command(
        "env CI_NODE_INDEX=0 CI_NODE_TOTAL=2 " DS_EXECUTABLE " sweep " + good.string() + out);
    ds::test::expect_one_error_line(gitlab, 2, "CI_NODE_INDEX=0 (it counts from 1)");
    EXPECT_FALSE(fs::exists(dir / "out"));
}

}  // namespace
