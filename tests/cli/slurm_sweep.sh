#!/bin/bash
# depthscope sweep on a real distributed engine: a single-node Slurm cluster on this machine
# (munged, slurmctld and slurmd as root, no systemd: a munge key and a slurm.conf written into a
# temporary folder, every daemon in the foreground of a background job whose PID is kept), the
# sweep submitted as a 4-task job array (each task takes its shard from SLURM_ARRAY_TASK_*),
# merged, and compared with a one-process run of the same manifest. The daemons are stopped by
# their PIDs whatever happens (trap EXIT). Exits 77 (ctest's SKIP_RETURN_CODE) with the reason
# where Slurm or munge is missing or the test does not run as root.
# Usage: slurm_sweep.sh DEPTHSCOPE WORKDIR
set -euo pipefail

DS=$(readlink -f "$1")
WORK=$(readlink -m "$2")
SKIP=77

skip() {
    echo "SKIP: $*"
    exit "$SKIP"
}
for tool in munged slurmctld slurmd sbatch sinfo squeue scancel python3; do
    command -v "$tool" >/dev/null || PATH=$PATH:/usr/sbin command -v "$tool" >/dev/null ||
        skip "$tool is not installed (./dev installs slurm-wlm and munge)"
done
export PATH=$PATH:/usr/sbin
[[ $(id -u) -eq 0 ]] || skip "slurmd runs jobs as root here: run as root"

# The shard comes from Slurm alone, even where this test runs inside a CI job that sets its own.
unset CI_NODE_INDEX CI_NODE_TOTAL JOB_COMPLETION_INDEX SLURM_ARRAY_TASK_ID SLURM_ARRAY_TASK_MIN \
    SLURM_ARRAY_TASK_STEP SLURM_ARRAY_TASK_COUNT SLURM_CONF
mkdir -p "$WORK"
TMP=$(mktemp -d "$WORK/slurm.XXXXXX")
chmod 0700 "$TMP"
PIDS=()

stop_daemons() {
    local status=$?
    # Jobs first (their slurmstepd would outlive slurmd), then the daemons, newest first.
    if [[ -f $TMP/slurm.conf ]]; then
        SLURM_CONF=$TMP/slurm.conf timeout 10 scancel --full --quiet --user=root 2>/dev/null || true
    fi
    for ((i = ${#PIDS[@]} - 1; i >= 0; i--)); do kill -TERM "${PIDS[i]}" 2>/dev/null || true; done
    for _ in $(seq 50); do
        local alive=0
        for pid in "${PIDS[@]}"; do kill -0 "$pid" 2>/dev/null && alive=1; done
        ((alive)) || break
        sleep 0.1
    done
    for pid in "${PIDS[@]}"; do kill -KILL "$pid" 2>/dev/null || true; done
    if ((status != 0)); then
        for log in "$TMP"/*.log "$TMP"/*.out "$TMP"/out/*; do
            [[ -f $log ]] && { echo "--- $log"; tail -n 20 "$log"; }
        done
    else
        rm -rf "$TMP"
    fi
    return "$status"
}
trap stop_daemons EXIT

HOST=$(hostname -s)
CPUS=$(nproc)
PORT=$((20000 + RANDOM % 20000))
mkdir -p "$TMP/state" "$TMP/spool" "$TMP/out" "$TMP/munge"
chmod 0700 "$TMP/munge"

# munge: its own key and socket, so that a system munged (if any) is neither used nor disturbed.
dd if=/dev/urandom of="$TMP/munge/munge.key" bs=1024 count=1 status=none
chmod 0400 "$TMP/munge/munge.key"
SOCKET=$TMP/munge/munge.socket
munged --foreground --force --key-file="$TMP/munge/munge.key" --socket="$SOCKET" \
    --pid-file="$TMP/munge/munged.pid" --log-file="$TMP/munged.log" \
    --seed-file="$TMP/munge/munge.seed" >"$TMP/munged.out" 2>&1 &
PIDS+=($!)

cat >"$TMP/slurm.conf" <<EOF
ClusterName=dssweep
SlurmctldHost=$HOST(127.0.0.1)
SlurmUser=root
SlurmdUser=root
SlurmctldPort=$PORT
SlurmdPort=$((PORT + 1))
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$SOCKET
StateSaveLocation=$TMP/state
SlurmdSpoolDir=$TMP/spool
SlurmctldPidFile=$TMP/slurmctld.pid
SlurmdPidFile=$TMP/slurmd.pid
SlurmctldLogFile=$TMP/slurmctld.log
SlurmdLogFile=$TMP/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MpiDefault=none
SwitchType=switch/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
ReturnToService=2
SchedulerType=sched/builtin
NodeName=$HOST NodeAddr=127.0.0.1 CPUs=$CPUS State=UNKNOWN
PartitionName=sweep Nodes=$HOST Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF=$TMP/slurm.conf

for _ in $(seq 50); do [[ -S $SOCKET ]] && break; sleep 0.1; done
[[ -S $SOCKET ]] || { echo "munged did not start"; exit 1; }
slurmctld -D -i >"$TMP/slurmctld.out" 2>&1 &
PIDS+=($!)
slurmd -D -N "$HOST" >"$TMP/slurmd.out" 2>&1 &
PIDS+=($!)

state=""
for _ in $(seq 150); do
    state=$(sinfo -h -n "$HOST" -o %T 2>/dev/null || true)
    [[ $state == idle ]] && break
    sleep 0.2
done
[[ $state == idle ]] || { echo "the node is not idle after 30 s: '$state'"; exit 1; }

cat >"$TMP/manifest.json" <<'EOF'
{
  "scenes": ["zfight", "decals"],
  "common_settings": {"count_fragments": "on"},
  "settings": [{"prepass": "on"}, {"prepass": "off"}],
  "actions": ["capture"],
  "size": "96x64"
}
EOF

# The array: each task its own folder, its shard from the environment (no --shard).
cat >"$TMP/sweep.sbatch" <<EOF
#!/bin/bash
#SBATCH --array=0-3
#SBATCH --cpus-per-task=1
#SBATCH --output=$TMP/out/slurm-%A_%a.out
exec "$DS" sweep "$TMP/manifest.json" --out "$TMP/shards/\$SLURM_ARRAY_TASK_ID"
EOF
start=$(date +%s)
sbatch --wait --chdir="$TMP" "$TMP/sweep.sbatch"
echo "the array ran in $(($(date +%s) - start)) s"
grep -h "^sweep: shard" "$TMP"/out/*.out

"$DS" sweep --merge "$TMP"/shards/* --out "$TMP/merged"
"$DS" sweep "$TMP/manifest.json" --out "$TMP/one"

cmp "$TMP/merged/sweep.json" "$TMP/one/sweep.json"
python3 - "$TMP/merged" "$TMP/one" <<'EOF'
import json, pathlib, re, sys
merged, one = map(pathlib.Path, sys.argv[1:])
ids = [r["id"] for r in json.loads((one / "sweep.json").read_text())["results"]]
assert len(ids) == 4, ids
for i in ids:
    a = json.loads((merged / "jobs" / i / "result.json").read_text())
    b = json.loads((one / "jobs" / i / "result.json").read_text())
    a.pop("seconds"); b.pop("seconds")
    assert a == b, (i, a, b)
    assert a["status"] == "passed", a
untimed = lambda p: re.sub(r' time="[^"]*"', "", p.read_text())
assert untimed(merged / "junit.xml") == untimed(one / "junit.xml")
print("merged == one-process:", len(ids), "jobs")
EOF
