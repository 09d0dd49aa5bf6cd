//! Writing output files safely: atomic replacement through an exclusively created temporary
//! file, appending without following symbolic links, lock files, "is this path the same file
//! as that one", and stdout writes that report a closed or full stdout instead of panicking.
//!
//! Temporary files live in the target's own folder (so the final rename is atomic), carry a
//! name unique to this process and call (`.NAME.PID.N.tmp`) and are created with `create_new`
//! (`O_CREAT | O_EXCL`), which fails on any existing entry — a symbolic link planted at that
//! name included — instead of writing through it. The rename then replaces the directory entry
//! `NAME` itself: if `NAME` was a symbolic link, the link is replaced, its target is untouched.

/// Exit code for a bad case file (or arguments, or a refused output path).
pub const EXIT_BAD_CASE: u8 = 2;
/// Exit code for a failed analysis (or an output that could not be written).
pub const EXIT_FAILED: u8 = 1;

use std::ffi::OsString;
use std::fs::{self, File, OpenOptions};
use std::io::{self, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

/// `path` with `suffix` appended to its file name (`a.jsonl` → `a.jsonl.partial`).
pub fn with_suffix(path: &Path, suffix: &str) -> PathBuf {
    let mut s: OsString = path.as_os_str().to_owned();
    s.push(suffix);
    PathBuf::from(s)
}

/// The folder a file named by `path` lives in (`.` for a bare name).
fn parent_dir(path: &Path) -> &Path {
    match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    }
}

/// Creates a new, uniquely named temporary file beside `path` (exclusive create: never opens
/// an existing file or follows a link). Returns the file and its path.
pub fn create_temp(path: &Path) -> io::Result<(File, PathBuf)> {
    static COUNTER: AtomicU64 = AtomicU64::new(0);
    let name = path.file_name().ok_or_else(|| {
        io::Error::new(
            io::ErrorKind::InvalidInput,
            format!("{} is not a file name", path.display()),
        )
    })?;
    let dir = parent_dir(path);
    let nanos = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.subsec_nanos());
    let mut last = None;
    for _ in 0..16 {
        let n = COUNTER.fetch_add(1, Ordering::Relaxed);
        let mut tmp_name = OsString::from(".");
        tmp_name.push(name);
        tmp_name.push(format!(".{}.{n}.{nanos:08x}.tmp", std::process::id()));
        let tmp = dir.join(tmp_name);
        match OpenOptions::new().write(true).create_new(true).open(&tmp) {
            Ok(f) => return Ok((f, tmp)),
            Err(e) if e.kind() == io::ErrorKind::AlreadyExists => last = Some(e),
            Err(e) => return Err(e),
        }
    }
    Err(last.unwrap_or_else(|| io::Error::other("no free temporary name")))
}

/// Writes `bytes` to `path` atomically: a fresh temporary file in the same folder (see the
/// module notes), flushed to disk, then renamed over `path`. On failure the temporary file is
/// removed and `path` is untouched.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> io::Result<()> {
    let (mut f, tmp) = create_temp(path)?;
    let done = f.write_all(bytes).and_then(|()| f.sync_all()).and_then(|()| {
        drop(f);
        fs::rename(&tmp, path)
    });
    if done.is_err() {
        let _ = fs::remove_file(&tmp);
    }
    done
}

/// True when `path` itself (not what it points to) is a symbolic link.
pub fn is_symlink(path: &Path) -> bool {
    fs::symlink_metadata(path).is_ok_and(|m| m.file_type().is_symlink())
}

/// Opens `path` for reading and appending, creating it if missing, without following a
/// symbolic link: a link at `path` is refused, and the opened file must be the very entry
/// found at `path` (same device and inode), so a link swapped in between is caught too.
pub fn open_append_no_follow(path: &Path) -> io::Result<File> {
    if is_symlink(path) {
        return Err(symlink_refused(path));
    }
    let f = OpenOptions::new().read(true).append(true).create(true).open(path)?;
    let opened = f.metadata()?;
    let entry = fs::symlink_metadata(path)?;
    if entry.file_type().is_symlink() || !same_inode(&opened, &entry) {
        return Err(symlink_refused(path));
    }
    if !opened.is_file() {
        return Err(io::Error::new(
            io::ErrorKind::InvalidInput,
            format!("{} is not a regular file", path.display()),
        ));
    }
    Ok(f)
}

fn symlink_refused(path: &Path) -> io::Error {
    io::Error::new(
        io::ErrorKind::InvalidInput,
        format!(
            "{} is a symbolic link; flexfem does not write through links (remove it)",
            path.display()
        ),
    )
}

#[cfg(unix)]
fn same_inode(a: &fs::Metadata, b: &fs::Metadata) -> bool {
    use std::os::unix::fs::MetadataExt;
    a.dev() == b.dev() && a.ino() == b.ino()
}

#[cfg(not(unix))]
fn same_inode(a: &fs::Metadata, b: &fs::Metadata) -> bool {
    a.len() == b.len() && a.modified().ok() == b.modified().ok()
}

/// An absolute form of `path` for comparisons: the folder resolved (links, `..`), the file name
/// kept; `None` when the folder does not exist.
fn resolved(path: &Path) -> Option<PathBuf> {
    let dir = fs::canonicalize(parent_dir(path)).ok()?;
    Some(match path.file_name() {
        Some(n) => dir.join(n),
        None => dir,
    })
}

/// True when `a` and `b` name the same file: the same inode when both exist (hard links and
/// symbolic links included), else the same resolved path.
pub fn same_file(a: &Path, b: &Path) -> bool {
    if let (Ok(x), Ok(y)) = (fs::metadata(a), fs::metadata(b)) {
        return same_inode(&x, &y);
    }
    match (resolved(a), resolved(b)) {
        (Some(x), Some(y)) => x == y,
        _ => a == b,
    }
}

/// An exclusive lock on an output file: `FILE.lock`, created with `create_new` and holding
/// `pid=P host=H`; removed when dropped.
///
/// A lock left by a killed process is stale: when its host is this host and process `P` no
/// longer exists (`/proc/P` is absent, Linux), it is taken over; otherwise the lock is
/// refused with a message naming the lock file and its holder.
#[derive(Debug)]
pub struct Lock {
    path: PathBuf,
}

/// What a failed [`Lock::acquire`] found.
#[derive(Debug)]
pub enum LockError {
    /// Another live process (or one on another host) holds the lock.
    Held(String),
    /// The lock file could not be created or read.
    Io(io::Error),
}

impl std::fmt::Display for LockError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            LockError::Held(m) => f.write_str(m),
            LockError::Io(e) => write!(f, "{e}"),
        }
    }
}

fn host_name() -> Option<String> {
    let h = fs::read_to_string("/proc/sys/kernel/hostname")
        .or_else(|_| fs::read_to_string("/etc/hostname"))
        .ok()?;
    let h = h.trim();
    (!h.is_empty()).then(|| h.to_string())
}

/// `Some(true)` when process `pid` on this host is alive, `Some(false)` when it is gone, `None`
/// when that cannot be told (no `/proc`).
fn process_alive(pid: u32) -> Option<bool> {
    if !Path::new("/proc/self").exists() {
        return None;
    }
    Some(Path::new(&format!("/proc/{pid}")).exists())
}

/// Parses `pid=P host=H`.
fn holder(text: &str) -> Option<(u32, String)> {
    let mut pid = None;
    let mut host = None;
    for word in text.split_whitespace() {
        if let Some(p) = word.strip_prefix("pid=") {
            pid = p.parse().ok();
        } else if let Some(h) = word.strip_prefix("host=") {
            host = Some(h.to_string());
        }
    }
    Some((pid?, host?))
}

impl Lock {
    /// Takes the lock `FILE.lock` of `file`.
    pub fn acquire(file: &Path) -> Result<Lock, LockError> {
        let path = with_suffix(file, ".lock");
        let me = format!(
            "pid={} host={}\n",
            std::process::id(),
            host_name().unwrap_or_else(|| "unknown".into())
        );
        // Two rounds: the second after taking over a stale lock.
        for _ in 0..2 {
            match OpenOptions::new().write(true).create_new(true).open(&path) {
                Ok(mut f) => {
                    let lock = Lock { path: path.clone() };
                    f.write_all(me.as_bytes()).map_err(LockError::Io)?;
                    return Ok(lock);
                }
                Err(e) if e.kind() == io::ErrorKind::AlreadyExists => {}
                Err(e) => {
                    return Err(LockError::Io(io::Error::new(
                        e.kind(),
                        format!("cannot create lock file {}: {e}", path.display()),
                    )))
                }
            }
            if is_symlink(&path) {
                return Err(LockError::Io(symlink_refused(&path)));
            }
            let text = fs::read_to_string(&path).unwrap_or_default();
            let held = || {
                LockError::Held(format!(
                    "{} is locked by another flexfem sweep ({}, lock file {}); run one sweep per output \
                     file at a time (shards: one after another, or each with its own --out), or delete the lock \
                     file if no sweep is running",
                    file.display(),
                    if text.trim().is_empty() {
                        "holder unknown"
                    } else {
                        text.trim()
                    },
                    path.display()
                ))
            };
            let stale = match (holder(&text), host_name()) {
                (Some((pid, host)), Some(here)) if host == here => process_alive(pid) == Some(false),
                _ => false,
            };
            if !stale {
                return Err(held());
            }
            // Move the stale lock aside under a unique name, then check it is still the one we
            // judged stale (another process may have replaced it meanwhile).
            let aside = with_suffix(&path, &format!(".stale.{}", std::process::id()));
            if fs::rename(&path, &aside).is_err() {
                continue;
            }
            let moved = fs::read_to_string(&aside).unwrap_or_default();
            if moved != text {
                // Not ours to break: put it back if nothing took its place.
                let _ = fs::hard_link(&aside, &path);
                let _ = fs::remove_file(&aside);
                return Err(held());
            }
            let _ = fs::remove_file(&aside);
            eprintln!(
                "note: removed the stale lock {} ({}: no such process)",
                path.display(),
                text.trim()
            );
        }
        Err(LockError::Held(format!(
            "cannot take the lock {} for {}",
            path.display(),
            file.display()
        )))
    }
}

impl Drop for Lock {
    fn drop(&mut self) {
        let _ = fs::remove_file(&self.path);
    }
}

/// Writes `text` to stdout and flushes; a closed pipe or a full disk is an error naming stdout
/// (not a panic, as `print!` would give).
pub fn stdout_write(text: &str) -> io::Result<()> {
    let mut out = io::stdout().lock();
    out.write_all(text.as_bytes())
        .and_then(|()| out.flush())
        .map_err(|e| io::Error::new(e.kind(), format!("cannot write to stdout: {e}")))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn holder_parses_pid_and_host() {
        assert_eq!(holder("pid=42 host=box\n"), Some((42, "box".into())));
        assert_eq!(holder("pid=x host=box"), None);
        assert_eq!(holder(""), None);
    }
}
