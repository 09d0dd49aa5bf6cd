//! Input size limits: case and mesh file size, node count, modal and Craig–Bampton memory.
//!
//! A case that would exhaust memory is refused before anything large is allocated, with the
//! limit, the value and how to raise the limit. Defaults suit a workstation; override them for
//! one run with the environment variable `FLEXFEM_LIMITS`, e.g.
//! `FLEXFEM_LIMITS="file_mib=1024,nodes=5000000,memory_gib=64"` (any subset), or from code
//! with [`set`].

use super::error::CaseError;
use std::io::Read;
use std::path::Path;
use std::sync::RwLock;

/// The environment variable that overrides the limits.
pub const ENV: &str = "FLEXFEM_LIMITS";

/// Size limits of one run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Limits {
    /// Largest case or mesh file read, bytes.
    pub file_bytes: u64,
    /// Most nodes in a model.
    pub nodes: usize,
    /// Largest memory an analysis may plan to use (modal estimate), bytes.
    pub memory_bytes: u64,
}

const MIB: u64 = 1 << 20;
const GIB: u64 = 1 << 30;

impl Default for Limits {
    /// 256 MiB files, 2 million nodes (12 million DOFs), 8 GiB of estimated memory.
    fn default() -> Self {
        Limits {
            file_bytes: 256 * MIB,
            nodes: 2_000_000,
            memory_bytes: 8 * GIB,
        }
    }
}

static OVERRIDE: RwLock<Option<Limits>> = RwLock::new(None);

/// Sets the limits for the rest of the process (e.g. from command-line flags); `None` returns
/// to the defaults with the `FLEXFEM_LIMITS` overrides.
pub fn set(limits: Option<Limits>) {
    if let Ok(mut g) = OVERRIDE.write() {
        *g = limits;
    }
}

impl Limits {
    /// The defaults with the overrides of `FLEXFEM_LIMITS` (`key=value` pairs separated by
    /// commas; keys `file_mib`, `nodes`, `memory_gib`).
    pub fn from_env() -> Result<Limits, CaseError> {
        let mut l = Limits::default();
        let Ok(text) = std::env::var(ENV) else {
            return Ok(l);
        };
        for item in text.split(',').map(str::trim).filter(|s| !s.is_empty()) {
            let bad = || {
                CaseError::new(
                    format!("(environment {ENV})"),
                    format!("cannot read {item:?}: expected file_mib=N, nodes=N or memory_gib=N (positive numbers)"),
                )
            };
            let (k, v) = item.split_once('=').ok_or_else(bad)?;
            let v: f64 = v.trim().parse().map_err(|_| bad())?;
            if !(v.is_finite() && v > 0.0) {
                return Err(bad());
            }
            match k.trim() {
                "file_mib" => l.file_bytes = (v * MIB as f64) as u64,
                "nodes" => l.nodes = v as usize,
                "memory_gib" => l.memory_bytes = (v * GIB as f64) as u64,
                _ => return Err(bad()),
            }
        }
        Ok(l)
    }

    /// The limits in force: those [`set`] by the program, else [`Limits::from_env`].
    pub fn current() -> Result<Limits, CaseError> {
        match OVERRIDE.read().ok().and_then(|g| *g) {
            Some(l) => Ok(l),
            None => Limits::from_env(),
        }
    }
}

fn human(bytes: u64) -> String {
    if bytes >= GIB {
        format!("{:.1} GiB", bytes as f64 / GIB as f64)
    } else {
        format!("{:.1} MiB", bytes as f64 / MIB as f64)
    }
}

/// Reads a case or mesh file as bytes: a regular file no larger than the file-size limit
/// (`/dev/zero` or a FIFO would be read until memory runs out). `field` is the JSON path the
/// file name came from (errors name it), `what` the kind of file ("case file", "mesh file").
pub fn read_file(field: &str, what: &str, shown: &str, path: &Path) -> Result<Vec<u8>, CaseError> {
    let limits = Limits::current()?;
    let err = |msg: String| CaseError::value(field, shown, msg);
    let meta = std::fs::metadata(path).map_err(|e| err(format!("cannot read {what} {}: {e}", path.display())))?;
    if !meta.is_file() {
        return Err(err(format!(
            "{what} {} is not a regular file (a device, FIFO or folder); give a file",
            path.display()
        )));
    }
    let too_big = |size: String| {
        err(format!(
            "{what} {} is {size}, over the file-size limit of {} (raise it with {ENV}=file_mib=N)",
            path.display(),
            human(limits.file_bytes)
        ))
    };
    if meta.len() > limits.file_bytes {
        return Err(too_big(human(meta.len())));
    }
    let f = std::fs::File::open(path).map_err(|e| err(format!("cannot read {what} {}: {e}", path.display())))?;
    let mut bytes = Vec::with_capacity(meta.len() as usize);
    f.take(limits.file_bytes + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| err(format!("cannot read {what} {}: {e}", path.display())))?;
    if bytes.len() as u64 > limits.file_bytes {
        return Err(too_big("larger than its size on disk said".into()));
    }
    Ok(bytes)
}

/// Refuses a model with more nodes than the node limit (before its nodes are built).
pub fn check_nodes(field: &str, count: usize) -> Result<(), CaseError> {
    let limits = Limits::current()?;
    if count > limits.nodes {
        return Err(CaseError::value(
            field,
            format!("({count} nodes)"),
            format!(
                "the model has more nodes than the limit of {} (about {} of memory per million nodes to solve; raise it with {ENV}=nodes=N)",
                limits.nodes,
                human(3 * GIB)
            ),
        ));
    }
    Ok(())
}

/// Memory a modal analysis of `modes` modes on a model of `nodes` nodes plans to use, bytes:
/// the Lanczos basis and its mass products (2 × (2·modes + 6) vectors of 6·nodes numbers),
/// the Ritz vectors, the projected matrix and its eigenvectors ((2·modes + 6)² each) and the
/// mode shapes in the JSON result (about 56 bytes per number as a JSON value and as text).
pub fn modal_memory(modes: usize, nodes: usize) -> u64 {
    let n = 6.0 * nodes as f64;
    let k = 2.0 * modes as f64 + 6.0;
    let bytes = 8.0 * n * (2.0 * k + modes as f64) + 8.0 * 2.0 * k * k + 56.0 * n * modes as f64;
    bytes.min(u64::MAX as f64) as u64
}

/// Refuses a modal analysis whose memory estimate exceeds the memory limit.
pub fn check_modal(modes: usize, nodes: usize) -> Result<(), CaseError> {
    let limits = Limits::current()?;
    let need = modal_memory(modes, nodes);
    if need > limits.memory_bytes {
        return Err(CaseError::value(
            "modes",
            modes,
            format!(
                "{modes} modes of a model of {nodes} nodes ({} DOFs) need about {} of memory, over the limit of {} (ask for fewer modes, or raise the limit with {ENV}=memory_gib=N)",
                6 * nodes,
                human(need),
                human(limits.memory_bytes)
            ),
        ));
    }
    Ok(())
}

/// Memory a Craig–Bampton reduction plans to use, bytes, for `equations` equations of which
/// `boundary` are on the interface, and `modes` fixed-interface modes (8 bytes a number): the
/// dense K and M of the model (2 n²), their partitions, the constraint modes and the interior
/// Cholesky factor (2 i² + 4 i b + 2 b² + i² + 2 i b), the interior eigen-decomposition (5 i²,
/// with modes), the superelement's K and M and their eigen-decomposition for the frequency
/// check (8 r², r = b + modes) and its rows in the JSON result (2 r² numbers at about 56 bytes
/// each as a JSON value and as text).
pub fn craig_bampton_memory(equations: usize, boundary: usize, modes: usize) -> u64 {
    let (n, b) = (equations as f64, boundary as f64);
    let i = (n - b).max(0.0);
    let r = b + modes as f64;
    let eig = if modes > 0 { 5.0 * i * i } else { 0.0 };
    let numbers = 2.0 * n * n + 3.0 * i * i + 6.0 * i * b + 2.0 * b * b + eig + 8.0 * r * r;
    (8.0 * numbers + 112.0 * r * r).min(u64::MAX as f64) as u64
}

/// Refuses a Craig–Bampton reduction whose memory estimate exceeds the memory limit (the JSON
/// path is `interface`, whose size drives it).
pub fn check_craig_bampton(
    equations: usize,
    boundary: usize,
    modes: usize,
    interface_nodes: usize,
) -> Result<(), CaseError> {
    let limits = Limits::current()?;
    let need = craig_bampton_memory(equations, boundary, modes);
    if need > limits.memory_bytes {
        return Err(CaseError::value(
            "interface",
            format!("({interface_nodes} nodes)"),
            format!(
                "a Craig–Bampton reduction onto {boundary} boundary equations with {modes} modes, of a model of {equations} equations, needs about {} of memory (dense matrices), over the limit of {} (use fewer interface nodes or modes, or raise the limit with {ENV}=memory_gib=N)",
                human(need),
                human(limits.memory_bytes)
            ),
        ));
    }
    Ok(())
}
