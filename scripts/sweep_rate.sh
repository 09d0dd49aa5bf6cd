#!/usr/bin/env bash
# Whole-process `flexfem sweep` throughput: 10,000 stage designs (with --out) and 10,000
# circular-notch hinge designs (with --out), each run REPS times (default 3); prints designs per
# second of wall time and per CPU-second (user + sys), and the load average before each run.
#
#   scripts/sweep_rate.sh [FLEXFEM_BINARY] [REPS]
#
# The binary defaults to target/release/flexfem (build it with `cargo build --release`). The two
# sweep cases are written to a temporary directory: the stage case is the bundled
# cases/ruiz2019_stage_sweep.json with 10 values on each of its four axes, the hinge case
# cases/ruiz2019_hinge_sweep.json with 100 × 100 values of t and R.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
bin="${1:-$here/target/release/flexfem}"
reps="${2:-3}"
[ -x "$bin" ] || { echo "no flexfem binary at $bin (cargo build --release)" >&2; exit 2; }
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT

cat >"$dir/stage_10000.json" <<'JSON'
{
  "analysis": "sweep",
  "base": {
    "analysis": "stage",
    "material": "Al7075",
    "stage": {
      "L": 109.215, "b": 47.91, "alpha0_deg": 45, "gamma_deg": 0,
      "leg": {"w": 10, "h": 10},
      "revolute": {"type": "circular_notch", "R": 8, "t": 2},
      "spherical": {"type": "spherical_neck", "l": 5, "t": 3, "R": 4}
    },
    "load_cases": [{"name": "F20", "actuator_forces": [20, 20, 20]}]
  },
  "vary": {
    "stage.revolute.t": {"from": 1.5, "to": 3, "steps": 10},
    "stage.revolute.R": {"from": 6, "to": 12, "steps": 10},
    "stage.spherical.t": {"from": 2.5, "to": 4, "steps": 10},
    "stage.spherical.l": {"from": 3, "to": 9, "steps": 10}
  }
}
JSON
cat >"$dir/notch_10000.json" <<'JSON'
{
  "analysis": "sweep",
  "base": {
    "analysis": "hinge",
    "material": "Al7075",
    "hinge": {"type": "circular_notch", "R": 8, "t": 2, "w": 10, "h": 10, "blank_length": 20}
  },
  "vary": {
    "hinge.t": {"from": 1, "to": 3, "steps": 100},
    "hinge.R": {"from": 2, "to": 12, "steps": 100}
  }
}
JSON

run() { # name case
    local name="$1" case="$2"
    for _ in $(seq "$reps"); do
        rm -f "$dir/out.jsonl" "$dir/out.jsonl.notes.json" "$dir/out.csv" "$dir/out.svg"
        local load
        load="$(cut -d' ' -f1 /proc/loadavg)"
        /usr/bin/time -f '%e %U %S' -o "$dir/time" "$bin" sweep "$case" --out "$dir/out.jsonl" 2>/dev/null
        read -r wall user sys <"$dir/time"
        awk -v n=10000 -v w="$wall" -v u="$user" -v s="$sys" -v l="$load" -v name="$name" 'BEGIN {
            printf "%-22s wall %6.2f s  cpu %6.2f s (user %.2f + sys %.2f)  %8.0f designs/s  %8.0f designs/CPU-s  load %s\n",
                name, w, u + s, u, s, n / w, n / (u + s), l }'
    done
}
run "stage, 10,000, --out" "$dir/stage_10000.json"
run "notch, 10,000, --out" "$dir/notch_10000.json"
