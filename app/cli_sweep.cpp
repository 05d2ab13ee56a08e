// `depthscope sweep` (capture/sweep/, docs/sweep.md): its options.
#include "app/cli_options.h"
#include "capture/sweep/shard.h"

namespace ds::app {

CLI::App* add_sweep_command(CLI::App& app, Options& o) {
    auto* sweep = app.add_subcommand(
        "sweep",
        "run a manifest's scenes x cameras x settings x actions (capture, bench, lint) as jobs, "
        "each a depthscope process into DIR/jobs/ID/; without a shard also merge: sweep.json, "
        "junit.xml (one testcase per job) and report.md in DIR (docs/sweep.md)");
    CLI::Option* manifest =
        sweep->add_option("MANIFEST", o.sweep_manifest, "the manifest (JSON; docs/sweep.md)")
            ->type_name("MANIFEST.json");
    add_path_option(*sweep, "--out", o.out,
                    "the sweep folder: a new one or an earlier sweep's (its jobs are replaced "
                    "whole when they run again)")
        ->type_name("DIR")
        ->required();
    CLI::Option* shard =
        sweep
            ->add_option_function<std::string>(
                "--shard",
                [&o](const std::string& text) {
                    (void)capture::sweep::parse_shard(text);  // a bad spec fails here
                    o.sweep_shard = text;
                },
                "run only shard I of N (from 0): the jobs sorted by ID, every N-th from the "
                "I-th; no merge (default: the environment's shard under Slurm arrays, GitLab "
                "parallel: and Kubernetes indexed Jobs, else every job)")
            ->type_name("I/N");
    CLI::Option* shards = add_count_option(
        *sweep, "--shards", o.sweep_shards, 1, capture::sweep::kMaxShards,
        "the number of shards when the environment gives only the index (Kubernetes' "
        "JOB_COMPLETION_INDEX)");
    CLI::Option* merge =
        sweep
            ->add_option("--merge", o.sweep_merge,
                         "merge the shards' folders into --out: every job of their manifest, "
                         "from the first DIR that has its result (else a failed \"no result\")")
            ->type_name("DIR…")
            ->expected(1, -1);
    add_path_option(*sweep, "--baseline", o.sweep_baseline,
                    "compare with an earlier merged sweep on the same device and driver: exact "
                    "counts, final.png by diff's rule and SSIM, bench timings reported; exit 1 "
                    "on a regression")
        ->type_name("DIR");
    merge->excludes(manifest)->excludes(shard)->excludes(shards);
    shard->excludes(shards);
    return sweep;
}

}  // namespace ds::app
