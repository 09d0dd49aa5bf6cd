#!/usr/bin/env bash
# A real Slurm test of `flexfem sweep --shard-from-env` and `flexfem merge` (not part of
# `cargo test`; `.ci/run` runs it last).
#
# It installs Debian's slurm-wlm and munge (apt-get, as root) when they are missing, starts a
# single-node cluster on localhost (munged, slurmctld, slurmd as background processes, no
# systemd, no cgroups, no accounting) in a temporary folder, and then through
# scripts/slurm_sweep.sh:
#   1. submits the bundled stage sweep as a 4-task job array plus its merge job, waits, and
#      checks the merged file equals the single-machine run (`flexfem sweep CASE --out`) line
#      for line;
#   2. simulates a killed task (task 3's file replaced by a partial file holding its first
#      lines and a torn one), checks the merge reports shard 3/4's designs missing, resubmits
#      task 3 alone, checks that it resumed (ran only the designs not in the partial file) and
#      that the new merge again equals the single-machine run.
# It always stops the daemons it started and removes its folder.
#
# Exit status: 0 when the test passed, or was SKIPPED because Slurm could not be set up here
# (no root, no apt-get, install failed, a daemon did not start, jobs never started) — the
# reason is printed; 1 when Slurm ran and the result is wrong. Bounded: 240 s once the
# daemons run (SLURM_TEST_TIMEOUT), plus the package install.
set -uo pipefail
cd "$(dirname "$0")/.."
ROOT=$(pwd)
START=$SECONDS
CASE=$ROOT/cases/ruiz2019_stage_sweep.json
FLEXFEM=${FLEXFEM:-$ROOT/target/release/flexfem}
TIMEOUT=${SLURM_TEST_TIMEOUT:-240}
PORT_CTLD=${SLURM_TEST_PORT:-16817}

say() { echo "slurm_test: $*"; }
skip() {
    say "SKIPPED (could not set up Slurm here): $*"
    exit 0
}
fail() {
    say "FAILED (Slurm ran and the result is wrong): $*"
    exit 1
}

[[ -x "$FLEXFEM" ]] || skip "no flexfem binary at $FLEXFEM (cargo build --release first)"

# --- Slurm and munge installed? ---------------------------------------------------------
if ! command -v slurmctld >/dev/null || ! command -v slurmd >/dev/null || ! command -v munged >/dev/null; then
    [[ $(id -u) -eq 0 ]] || skip "slurm-wlm/munge are not installed and this is not root (apt-get needs root)"
    command -v apt-get >/dev/null || skip "slurm-wlm/munge are not installed and there is no apt-get"
    say "installing slurm-wlm and munge with apt-get …"
    export DEBIAN_FRONTEND=noninteractive
    timeout 150 apt-get update -qq >/tmp/slurm_test_apt.log 2>&1 ||
        skip "apt-get update failed (see /tmp/slurm_test_apt.log)"
    timeout 200 apt-get install -y -qq --no-install-recommends slurm-wlm munge >>/tmp/slurm_test_apt.log 2>&1 ||
        skip "apt-get install slurm-wlm munge failed (see /tmp/slurm_test_apt.log)"
fi
[[ $(id -u) -eq 0 ]] || skip "the daemons need root here (munge key, SlurmdUser=root)"
say "$(slurmctld -V), munge $(munged -V 2>&1 | awk '{print $1}'), setup took $((SECONDS - START)) s"

# --- A private single-node cluster ------------------------------------------------------
W=$(mktemp -d /tmp/flexfem-slurm-test.XXXXXX)
PIDS=()
cleanup() {
    local p
    for ((i = ${#PIDS[@]} - 1; i >= 0; i--)); do
        p=${PIDS[i]}
        kill "$p" 2>/dev/null && for _ in $(seq 50); do kill -0 "$p" 2>/dev/null || break; sleep 0.1; done
        kill -9 "$p" 2>/dev/null
    done
    rm -rf "$W"
}
trap cleanup EXIT
trap 'exit 1' INT TERM

# munge: use a running munged, else start one as the munge user.
if ! munge -n 2>/dev/null | unmunge >/dev/null 2>&1; then
    [[ -r /etc/munge/munge.key ]] || mungekey -c >/dev/null 2>&1 ||
        skip "no munge key and mungekey -c failed"
    mkdir -p /run/munge && chown munge:munge /run/munge
    setpriv --reuid=munge --regid=munge --init-groups munged -F >"$W/munged.log" 2>&1 &
    PIDS+=($!)
    for _ in $(seq 50); do munge -n 2>/dev/null | unmunge >/dev/null 2>&1 && break; sleep 0.1; done
    munge -n 2>/dev/null | unmunge >/dev/null 2>&1 || skip "munged did not start: $(tail -3 "$W/munged.log")"
fi

HOST=$(hostname -s)
mkdir -p "$W/state" "$W/spool" "$W/out"
cat >"$W/slurm.conf" <<EOF
ClusterName=flexfemtest
SlurmctldHost=$HOST(127.0.0.1)
SlurmctldPort=$PORT_CTLD
SlurmdPort=$((PORT_CTLD + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
StateSaveLocation=$W/state
SlurmdSpoolDir=$W/spool
SlurmctldPidFile=$W/slurmctld.pid
SlurmdPidFile=$W/slurmd.pid
SlurmctldLogFile=$W/slurmctld.log
SlurmdLogFile=$W/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/backfill
MpiDefault=none
ReturnToService=2
NodeName=$HOST NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=flexfemtest Nodes=ALL Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF=$W/slurm.conf
unset SLURM_JOB_ID SLURM_ARRAY_TASK_ID SLURM_ARRAY_TASK_COUNT SLURM_ARRAY_TASK_MIN SLURM_ARRAY_TASK_MAX
slurmctld -D -c -f "$SLURM_CONF" >"$W/slurmctld.out" 2>&1 &
PIDS+=($!)
slurmd -D -f "$SLURM_CONF" >"$W/slurmd.out" 2>&1 &
PIDS+=($!)
T0=$SECONDS
DEADLINE=$((SECONDS + TIMEOUT))
until [[ $(sinfo -h -o %T 2>/dev/null) == idle* ]]; do
    ((SECONDS < T0 + 30)) || skip "the node did not come up in 30 s: $(tail -2 "$W/slurmctld.log" "$W/slurmd.log" 2>&1 | tr '\n' ' ')"
    for p in "${PIDS[@]}"; do kill -0 "$p" 2>/dev/null || skip "a daemon exited: $(tail -3 "$W"/*.out 2>&1 | tr '\n' ' ')"; done
    sleep 0.5
done
say "slurmctld + slurmd up on $HOST ($(nproc) CPUs) in $((SECONDS - T0)) s"

# Waits until the jobs (comma-separated ids) have left the queue; a job never started by the
# deadline means the cluster does not work here (skip), not a wrong result.
wait_jobs() {
    local ids=$1 state
    while :; do
        state=$(squeue -h -j "$ids" -o %T 2>/dev/null | sort -u | tr '\n' ' ')
        [[ -z "$state" ]] && return 0
        if ((SECONDS > DEADLINE)); then
            [[ "$state" == *RUNNING* || "$state" == *COMPLETING* ]] &&
                fail "jobs $ids still $state after ${TIMEOUT} s"
            skip "jobs $ids never started in ${TIMEOUT} s (state: $state; $(squeue -h -j "$ids" -o %R | sort -u | tr '\n' ' '))"
        fi
        sleep 0.5
    done
}
# A job that left no log never ran flexfem: Slurm could not start it here (skip); a log with
# the wrong content is a wrong result (fail).
need_log() {
    [[ -s "$1" ]] || skip "job $2 left no log $1 (Slurm could not run it here): \
$(scontrol -o show job "$2" 2>&1 | grep -o 'JobState=[^ ]*\|Reason=[^ ]*' | sort -u | tr '\n' ' ')"
}
# Submits through the bundled script; prints "ARRAY,MERGE" job ids.
submit() {
    local out
    out=$(FLEXFEM=$FLEXFEM "$ROOT/scripts/slurm_sweep.sh" "$CASE" 4 "$W/out" "$@" 2>&1) ||
        skip "scripts/slurm_sweep.sh could not submit: $out"
    echo "$out" | sed -n 's/^SLURM_SWEEP_JOBS=//p'
}
# Checks the merged file against the single-machine run, line for line.
compare() {
    [[ -s "$W/out/merged.jsonl" ]] || fail "$1: no merged file; merge log: $(cat "$W/out/merge.log" 2>&1)"
    if ! cmp -s "$W/out/merged.jsonl" "$W/single.jsonl"; then
        diff <(cut -c1-200 "$W/single.jsonl") <(cut -c1-200 "$W/out/merged.jsonl") | head -5
        fail "$1: the merged file differs from the single-machine run"
    fi
    say "$1: merged file = single-machine run, $(wc -l <"$W/single.jsonl") lines identical"
}

# --- 1. A 4-task array sweep, merged -----------------------------------------------------
"$FLEXFEM" sweep "$CASE" --out "$W/single.jsonl" 2>"$W/single.log" ||
    fail "the single-machine sweep failed: $(cat "$W/single.log")"
T1=$SECONDS
jobs=$(submit)
say "submitted array + merge jobs $jobs"
wait_jobs "$jobs"
for k in 1 2 3 4; do
    need_log "$W/out/task_$k.log" "${jobs%,*}_$k"
    grep -q "^sweep: 64 designs (shard $k/4 of 256), 0 already done, 64 run, 0 failed" "$W/out/task_$k.log" ||
        fail "array task $k did not run shard $k/4: $(cat "$W/out/task_$k.log" 2>&1)"
done
need_log "$W/out/merge.log" "${jobs#*,}"
grep -q "^merge: 256 of 256 designs from 4 files" "$W/out/merge.log" ||
    fail "merge job: $(cat "$W/out/merge.log" 2>&1)"
compare "4-task array (took $((SECONDS - T1)) s)"
# The merge job's second step writes the stage sweep's table and plot without running a design.
grep -q "^sweep: 256 designs, 256 already done, 0 run, 0 failed" "$W/out/merge.log" &&
    [[ -s "$W/out/merged.csv" && -s "$W/out/merged.svg" ]] ||
    fail "the merge job's table/plot step: $(cat "$W/out/merge.log")"

# --- 2. A killed task, resubmitted, resumes ----------------------------------------------
# A task killed mid-run leaves FILE.partial (lines appended as designs finish, the last torn)
# and no FILE: keep task 3's first 20 lines and half of the 21st.
s3=$W/out/shard_3.jsonl
{
    head -n 20 "$s3"
    sed -n 21p "$s3" | head -c 100
} >"$s3.partial"
rm -f "$s3" "$W/out/merged.jsonl" "$W/out/task_3.log" "$W/out/merge.log"
if "$FLEXFEM" merge "$W/out/merged.jsonl" "$W"/out/shard_{1,2,4}.jsonl --case "$CASE" 2>"$W/merge_missing.log"; then
    fail "merge without shard 3 exited 0"
fi
grep -q "64 of 256 designs missing: 2, 6, 10" "$W/merge_missing.log" && grep -q "all of shard 3/4" "$W/merge_missing.log" ||
    fail "merge without shard 3 did not name its designs: $(cat "$W/merge_missing.log")"
say "killed task simulated: merge reports $(grep -o '64 of 256 designs missing' "$W/merge_missing.log") (shard 3/4)"
T2=$SECONDS
jobs=$(submit 3)
say "resubmitted task 3 alone + merge: jobs $jobs"
wait_jobs "$jobs"
need_log "$W/out/task_3.log" "${jobs%,*}_3"
grep -q "^sweep: 64 designs (shard 3/4 of 256), 20 already done, 44 run, 0 failed" "$W/out/task_3.log" ||
    fail "the resubmitted task 3 did not resume from its partial file: $(cat "$W/out/task_3.log" 2>&1)"
say "task 3 resumed: $(grep '^sweep:' "$W/out/task_3.log" | cut -d, -f1-4)"
compare "after resubmitting task 3 (took $((SECONDS - T2)) s)"

# --- 3. A shard of another base case is refused -------------------------------------------
sed 's/"w": 10, "h": 10/"w": 11, "h": 10/' "$CASE" >"$W/other.json"
"$FLEXFEM" sweep "$W/other.json" --shard 2/4 --out "$W/other_2.jsonl" 2>/dev/null || fail "sweep of the other case failed"
"$FLEXFEM" merge "$W/m.jsonl" "$W"/out/shard_{1,3,4}.jsonl "$W/other_2.jsonl" --case "$CASE" 2>"$W/merge_other.log"
rc=$?
[[ $rc -eq 2 ]] && grep -q "other_2.jsonl line 1 (index 1) has design_hash" "$W/merge_other.log" ||
    fail "merge did not refuse a shard of another base case (exit $rc): $(cat "$W/merge_other.log")"
say "a shard of another base case is refused (exit 2): $(cut -c1-120 "$W/merge_other.log")…"

say "PASSED in $((SECONDS - START)) s"
