#!/usr/bin/env bash
# A flexfem sweep as a Slurm job array: task K of N runs shard K/N into its own file, and a
# merge job (started when every task has ended) combines the shard files into one, checked
# against the case.
#
# Submit (on the login node; flexfem on PATH or FLEXFEM=/path/to/flexfem):
#   scripts/slurm_sweep.sh CASE.json N [OUTDIR] [TASKS]
#     CASE.json  the sweep case ("analysis": "sweep")
#     N          number of array tasks (shards)
#     OUTDIR     where shard_K.jsonl, merged.jsonl and the logs go (default: sweep_out)
#     TASKS      which tasks to (re)submit, an sbatch --array list (default 1-N); e.g. `3` reruns
#                task 3 alone after it was killed: it resumes from OUTDIR/shard_3.jsonl.partial
#   Extra sbatch options (partition, time limit, account) go in SBATCH_* variables or the
#   #SBATCH lines below, e.g. SBATCH_PARTITION=short SBATCH_TIMELIMIT=02:00:00.
#
# Or use this file directly as the array script (N from the --array range):
#   sbatch --array=1-N scripts/slurm_sweep.sh CASE.json OUTDIR
# and merge once every task has ended:
#   flexfem merge OUTDIR/merged.jsonl OUTDIR/shard_*.jsonl --case CASE.json
#
# The merge exits 0 only when every design is there exactly once; it lists missing designs
# (a task that failed or was killed: resubmit it with TASKS) and refuses lines of another base
# case. After it, `flexfem sweep CASE.json --out OUTDIR/merged.jsonl` runs no design (all are
# done) and writes the analysis' table and plot beside the merged file.
#
#SBATCH --job-name=flexfem-sweep
#SBATCH --array=1-4
#SBATCH --ntasks=1
#SBATCH --cpus-per-task=1
#SBATCH --output=flexfem-sweep-%A_%a.log
set -euo pipefail
FLEXFEM=${FLEXFEM:-flexfem}

if [[ -n "${SLURM_ARRAY_TASK_ID:-}" ]]; then
    # One array task: shard K/N (K = SLURM_ARRAY_TASK_ID, 1-based; N from --shard-count when
    # the submitter gave it, else the array's task count). One thread: the array is the
    # parallelism.
    case_file=$1
    outdir=${2:-sweep_out}
    count=${3:-}
    mkdir -p "$outdir"
    export RAYON_NUM_THREADS=${SLURM_CPUS_PER_TASK:-1}
    exec "$FLEXFEM" sweep "$case_file" --shard-from-env ${count:+--shard-count "$count"} \
        --out "$outdir/shard_${SLURM_ARRAY_TASK_ID}.jsonl"
fi

# Submitter.
if [[ $# -lt 2 ]]; then
    sed -n '2,/^#SBATCH/p' "$0" | grep -v '^#SBATCH' | sed 's/^# \{0,1\}//'
    exit 2
fi
case_file=$(realpath "$1")
n=$2
outdir=$(realpath -m "${3:-sweep_out}")
tasks=${4:-1-$n}
if ! [[ "$n" =~ ^[1-9][0-9]*$ ]]; then
    echo "error: N must be a whole number ≥ 1, got \`$n\`" >&2
    exit 2
fi
flexfem_path=$(command -v "$FLEXFEM" || true)
if [[ -z "$flexfem_path" ]]; then
    echo "error: $FLEXFEM not found; put flexfem on PATH or set FLEXFEM=/path/to/flexfem" >&2
    exit 2
fi
"$flexfem_path" check "$case_file" >/dev/null
mkdir -p "$outdir"

array_job=$(FLEXFEM=$flexfem_path sbatch --parsable --array="$tasks" --chdir="$outdir" \
    --output="$outdir/task_%a.log" --export=ALL,FLEXFEM="$flexfem_path" \
    "$0" "$case_file" "$outdir" "$n")
array_job=${array_job%%;*}
shards=()
for ((k = 1; k <= n; k++)); do shards+=("$outdir/shard_$k.jsonl"); done
# afterany: the merge runs even when a task failed, and then names the missing designs.
merge_job=$(sbatch --parsable --job-name=flexfem-merge --dependency="afterany:$array_job" \
    --chdir="$outdir" --output="$outdir/merge.log" --ntasks=1 --cpus-per-task=1 \
    --wrap="$(printf '%q ' "$flexfem_path" merge "$outdir/merged.jsonl" "${shards[@]}" --case "$case_file") && $(printf '%q ' "$flexfem_path" sweep "$case_file" --out "$outdir/merged.jsonl")")
merge_job=${merge_job%%;*}
echo "array job $array_job (tasks $tasks of $n), merge job $merge_job → $outdir/merged.jsonl (log $outdir/merge.log)"
echo "SLURM_SWEEP_JOBS=$array_job,$merge_job"
