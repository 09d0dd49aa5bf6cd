//! `flexfem sweep --shard-from-env`: the shard `K/N` of a Slurm job-array task, read from the
//! variables Slurm sets in each array task.
//!
//! The rule, exactly:
//! - `SLURM_ARRAY_TASK_ID` (required) is the task id. The ids are 1-based (`--array=1-N`,
//!   K = id) unless `SLURM_ARRAY_TASK_MIN` is `0`, when they are 0-based (`--array=0-(N-1)`,
//!   K = id + 1).
//! - N is `--shard-count N` when given, else `SLURM_ARRAY_TASK_COUNT`. Without `--shard-count`
//!   the array must be the whole range with step 1: `SLURM_ARRAY_TASK_STEP` (when set) is 1,
//!   and `SLURM_ARRAY_TASK_MAX − SLURM_ARRAY_TASK_MIN + 1` (when both are set) equals the count.
//!   Otherwise (e.g. `--array=1,3` or `--array=1-8:2`) the shards would not cover the sweep, and
//!   flexfem refuses.
//! - K must lie in 1..=N.
//!
//! Rerunning one task of an array (`sbatch --array=3 …`) makes Slurm report a count of 1, so
//! such a resubmission passes the full N: `--shard-from-env --shard-count 4` (K = 3 as before,
//! for 1-based ids). A single task of a 0-based array cannot be told from a 1-based one (its
//! minimum is its own id): rerun it with `--shard K/N` (K = id + 1).
//!
//! Every problem is a message naming the variable and its value (exit 2 at the command line).

use crate::design::sweep::Shard;

/// The variables read, in the order the messages name them.
pub const TASK_ID: &str = "SLURM_ARRAY_TASK_ID";
const TASK_COUNT: &str = "SLURM_ARRAY_TASK_COUNT";
const TASK_MIN: &str = "SLURM_ARRAY_TASK_MIN";
const TASK_MAX: &str = "SLURM_ARRAY_TASK_MAX";
const TASK_STEP: &str = "SLURM_ARRAY_TASK_STEP";

/// The shard of this array task, from the variables `var` returns (`std::env::var` at the
/// command line) and the explicit `--shard-count`, if any.
pub fn shard_from(var: impl Fn(&str) -> Option<String>, count: Option<usize>) -> Result<Shard, String> {
    let number =
        |name: &str| -> Result<Option<usize>, String> {
            match var(name) {
                None => Ok(None),
                Some(text) => text.trim().parse::<usize>().map(Some).map_err(|_| {
                    format!("{name}=`{text}` is not a whole number ≥ 0 (is this a Slurm job-array task?)")
                }),
            }
        };
    let id = number(TASK_ID)?.ok_or_else(|| {
        format!(
            "--shard-from-env: {TASK_ID} is not set; run inside a Slurm job array \
             (sbatch --array=1-N) or give --shard K/N"
        )
    })?;
    let min = number(TASK_MIN)?;
    let n = match count {
        Some(n) => n,
        None => {
            let n = number(TASK_COUNT)?.ok_or_else(|| {
                format!("--shard-from-env: {TASK_COUNT} is not set; give the number of shards with --shard-count N")
            })?;
            if let Some(step) = number(TASK_STEP)?.filter(|&s| s != 1) {
                return Err(format!(
                    "--shard-from-env: {TASK_STEP}={step}: the array's ids must run with step 1 \
                     (--array=1-N) so that the shards cover every design; or give --shard-count N"
                ));
            }
            if let (Some(lo), Some(hi)) = (min, number(TASK_MAX)?) {
                if hi < lo || hi - lo + 1 != n {
                    return Err(format!(
                        "--shard-from-env: the array {lo}-{hi} ({TASK_MIN}, {TASK_MAX}) is not one \
                         contiguous range of {TASK_COUNT}={n} ids, so its tasks would not cover every \
                         design; submit --array=1-N, or give --shard-count N"
                    ));
                }
            }
            n
        }
    };
    let k = if min == Some(0) { id + 1 } else { id };
    let base = if min == Some(0) {
        format!("0-based ids ({TASK_MIN}=0): K = {TASK_ID} + 1 = {k}")
    } else {
        format!("1-based ids: K = {TASK_ID} = {k}")
    };
    Shard::new(k, n).map_err(|msg| format!("--shard-from-env: {base}, N = {n}: {msg}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn env<'a>(pairs: &'a [(&'a str, &'a str)]) -> impl Fn(&str) -> Option<String> + 'a {
        move |name| pairs.iter().find(|(k, _)| *k == name).map(|(_, v)| v.to_string())
    }

    /// Slurm's job-array variables as `sbatch --array` sets them (Slurm manual, sbatch(1),
    /// "OUTPUT ENVIRONMENT VARIABLES").
    #[test]
    fn one_based_and_zero_based_arrays() {
        let one = [
            (TASK_ID, "3"),
            (TASK_COUNT, "4"),
            (TASK_MIN, "1"),
            (TASK_MAX, "4"),
            (TASK_STEP, "1"),
        ];
        assert_eq!(shard_from(env(&one), None), Ok(Shard::new(3, 4).unwrap()));
        let zero = [(TASK_ID, "3"), (TASK_COUNT, "4"), (TASK_MIN, "0"), (TASK_MAX, "3")];
        assert_eq!(shard_from(env(&zero), None), Ok(Shard::new(4, 4).unwrap()));
        // A resubmitted single task of a 1-based array, with the full N given.
        let rerun = [(TASK_ID, "3"), (TASK_COUNT, "1"), (TASK_MIN, "3"), (TASK_MAX, "3")];
        assert_eq!(shard_from(env(&rerun), Some(4)), Ok(Shard::new(3, 4).unwrap()));
        assert!(shard_from(env(&rerun), None)
            .unwrap_err()
            .contains("K must lie in 1..=1"));
    }

    #[test]
    fn missing_or_invalid_variables_are_named() {
        let e = shard_from(env(&[]), None).unwrap_err();
        assert!(e.contains("SLURM_ARRAY_TASK_ID is not set"), "{e}");
        let e = shard_from(env(&[(TASK_ID, "2")]), None).unwrap_err();
        assert!(e.contains("SLURM_ARRAY_TASK_COUNT is not set"), "{e}");
        let e = shard_from(env(&[(TASK_ID, "x"), (TASK_COUNT, "4")]), None).unwrap_err();
        assert!(e.contains("SLURM_ARRAY_TASK_ID=`x`"), "{e}");
        let e = shard_from(env(&[(TASK_ID, "0"), (TASK_COUNT, "4"), (TASK_MIN, "1")]), None).unwrap_err();
        assert!(e.contains("K must lie in 1..=4"), "{e}");
        let e = shard_from(env(&[(TASK_ID, "5"), (TASK_COUNT, "4")]), None).unwrap_err();
        assert!(e.contains("K must lie in 1..=4"), "{e}");
        let gaps = [(TASK_ID, "3"), (TASK_COUNT, "2"), (TASK_MIN, "1"), (TASK_MAX, "3")];
        assert!(shard_from(env(&gaps), None).unwrap_err().contains("contiguous"));
        let step = [(TASK_ID, "3"), (TASK_COUNT, "4"), (TASK_STEP, "2")];
        assert!(shard_from(env(&step), None).unwrap_err().contains("step 1"));
        assert!(shard_from(env(&[(TASK_ID, "1"), (TASK_COUNT, "0")]), None)
            .unwrap_err()
            .contains("N must be at least 1"));
    }
}
