//! Where results go: standard output, or a file replaced atomically.
//!
//! A file is written to a temporary file in its own directory, flushed and synced, then
//! renamed over the target, so a failed run never leaves it half-written or truncated, and
//! an existing file stays untouched unless the whole run succeeds. A symbolic link is written
//! through (a dangling one creates its target, as a shell redirection does), an existing file
//! that is not a regular file (`/dev/null`, a named pipe) is written in place, and a file the
//! user could not write (read-only) is refused rather than replaced: a rename needs only the
//! folder's permission.

use std::fs;
use std::io::{self, BufWriter, ErrorKind, Write};
use std::path::{Path, PathBuf};
use std::sync::Mutex;

use anyhow::{anyhow, bail, Result};
use sigdt_io::gis::shp;

/// The destination of a command's data.
#[derive(Debug)]
pub enum Output {
    /// Standard output; a reader that goes away early (broken pipe) is not an error.
    Stdout,
    /// A regular file, replaced atomically once everything is written.
    File {
        /// The file to replace: the path as given, or the target of a symbolic link.
        path: PathBuf,
        /// The directory that holds it, where the temporary file goes.
        dir: PathBuf,
    },
    /// An existing file that is not a regular file (`/dev/null`, a named pipe): written in
    /// place, since replacing it would be wrong.
    Special {
        /// The path as given.
        path: PathBuf,
    },
}

impl Output {
    /// Checks `out` (`None` or `-` mean standard output) before any work is done: its
    /// directory must exist, it must not be a directory, and it must not be `input` (nothing
    /// the user gave may be overwritten).
    pub fn new(out: Option<&Path>, input: &Path) -> Result<Output> {
        let Some(given) = out.filter(|p| !is_dash(p)) else {
            return Ok(Output::Stdout);
        };
        let shown = given.display();
        if given.file_name().is_none() {
            bail!("{shown}: output must be a file name");
        }
        if !is_dash(input) && same_file(given, input) {
            bail!("{shown}: output is the input file; refusing to overwrite it");
        }
        if let Some(sidecar) = shp::sidecars(input).iter().find(|s| same_file(given, s)) {
            bail!(
                "{shown}: output is {}, which belongs with the input Shapefile; refusing to \
                 overwrite it",
                sidecar.display()
            );
        }
        // Write through a symbolic link rather than replace it.
        let path = link_target(given)?;
        let dir = match path.parent() {
            Some(dir) if !dir.as_os_str().is_empty() => dir.to_path_buf(),
            _ => PathBuf::from("."),
        };
        if !dir.is_dir() {
            bail!("{shown}: output directory '{}' does not exist", dir.display());
        }
        match fs::metadata(&path) {
            Ok(meta) if meta.is_dir() => bail!("{shown}: output is a directory"),
            Ok(meta) if !meta.is_file() => Ok(Output::Special { path }),
            Ok(meta) if !writable(&path, &meta) => bail!(
                "{shown}: the file is read-only; refusing to replace it (make it writable or \
                 choose another output)"
            ),
            _ => Ok(Output::File { path, dir }),
        }
    }

    /// Runs `write` on the destination. On standard output a broken pipe counts as success;
    /// a file is only replaced if `write` and every step after it succeed.
    pub fn write(&self, write: impl FnOnce(&mut dyn Write) -> io::Result<()>) -> Result<()> {
        match self {
            Output::Stdout => {
                let mut w = BufWriter::new(io::stdout().lock());
                match write(&mut w).and_then(|()| w.flush()) {
                    Err(e) if e.kind() == ErrorKind::BrokenPipe => Ok(()),
                    Err(e) => Err(anyhow!("<stdout>: {e}")),
                    Ok(()) => Ok(()),
                }
            }
            Output::File { path, dir } => write_atomically(path, dir, write),
            Output::Special { path } => {
                let shown = path.display();
                let file = fs::OpenOptions::new()
                    .write(true)
                    .open(path)
                    .map_err(|e| anyhow!("{shown}: {e}"))?;
                let mut w = BufWriter::new(file);
                write(&mut w).and_then(|()| w.flush()).map_err(|e| anyhow!("{shown}: {e}"))
            }
        }
    }
}

/// Writes `contents` to `path` through a temporary file beside it, renamed over `path` only
/// once everything is written: a full disk or a signal leaves the previous file (a report's
/// chart, a gallery picture) as it was, never a truncated one.
pub fn write_file(path: &Path, contents: &[u8]) -> Result<()> {
    let dir = match path.parent() {
        Some(parent) if !parent.as_os_str().is_empty() => parent,
        _ => Path::new("."),
    };
    write_atomically(path, dir, |w| w.write_all(contents))
}

/// Writes to a temporary file in `dir`, then renames it over `path`.
fn write_atomically(
    path: &Path,
    dir: &Path,
    write: impl FnOnce(&mut dyn Write) -> io::Result<()>,
) -> Result<()> {
    let shown = path.display();
    // The file is created and listed as pending under one lock, which the signal handler
    // holds until the process exits: a signal never falls between the two.
    let create = |candidate: &Path| {
        let mut pending = lock_pending();
        let mut options = fs::OpenOptions::new();
        options.write(true).create_new(true);
        #[cfg(unix)]
        {
            // What a plain create would give (0o666 less the umask).
            use std::os::unix::fs::OpenOptionsExt;
            options.mode(0o666);
        }
        let file = options.open(candidate)?;
        pending.push(candidate.to_path_buf());
        Ok(file)
    };
    let mut tmp =
        tempfile::Builder::new().prefix(".sigdt-").suffix(".tmp").make_in(dir, create).map_err(
            |e| anyhow!("{shown}: cannot create a temporary file in '{}': {e}", dir.display()),
        )?;
    let _pending = Pending(tmp.path().to_path_buf());
    if let Ok(meta) = fs::metadata(path) {
        // Replacing an existing file keeps its permissions.
        let _ = tmp.as_file().set_permissions(meta.permissions());
    }
    let mut w = BufWriter::new(tmp.as_file_mut());
    write(&mut w).and_then(|()| w.flush()).map_err(|e| anyhow!("{shown}: cannot write: {e}"))?;
    drop(w);
    tmp.as_file().sync_all().map_err(|e| anyhow!("{shown}: cannot write: {e}"))?;
    // The temporary file is removed when `persist` fails.
    tmp.persist(path).map_err(|e| anyhow!("{shown}: cannot replace: {}", e.error))?;
    Ok(())
}

/// Where writing to `given` lands: `given` itself, or, for a symbolic link, the end of its
/// chain of links, which need not exist yet (it is then created).
fn link_target(given: &Path) -> Result<PathBuf> {
    let mut path = given.to_path_buf();
    // As the kernel does, give up after 40 links (a loop).
    for _ in 0..40 {
        match fs::symlink_metadata(&path) {
            Ok(meta) if meta.file_type().is_symlink() => {
                let target = fs::read_link(&path)
                    .map_err(|e| anyhow!("{}: cannot read the link: {e}", given.display()))?;
                path = match path.parent() {
                    Some(dir) if target.is_relative() => dir.join(target),
                    _ => target,
                };
            }
            _ => return Ok(path),
        }
    }
    bail!("{}: too many levels of symbolic links", given.display())
}

/// Whether the user may write the existing regular file `path`: it has a write permission
/// bit (root included: a read-only file is protected on purpose) and opens for writing.
fn writable(path: &Path, meta: &fs::Metadata) -> bool {
    !meta.permissions().readonly() && fs::OpenOptions::new().write(true).open(path).is_ok()
}

/// Temporary files being written, removed by [`remove_pending_on_signals`] when the
/// process is told to stop midway.
static PENDING: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// A temporary file listed in [`PENDING`] (when it was created), unlisted when dropped.
struct Pending(PathBuf);

impl Drop for Pending {
    fn drop(&mut self) {
        lock_pending().retain(|p| p != &self.0);
    }
}

fn lock_pending() -> std::sync::MutexGuard<'static, Vec<PathBuf>> {
    PENDING.lock().unwrap_or_else(|poisoned| poisoned.into_inner())
}

/// On SIGINT, SIGTERM or SIGHUP, removes the temporary files being written and exits with
/// status 130: the targets are untouched (they are only ever replaced whole) and nothing is
/// left behind. Without a handler, the process would die with its `.sigdt-*.tmp` in place.
pub fn remove_pending_on_signals() {
    // Installing fails only if a handler exists already; the default behaviour then stays.
    let _ = ctrlc::set_handler(|| {
        // Held until the exit, so that no new temporary file appears after the removal.
        let pending = lock_pending();
        for path in pending.iter() {
            let _ = fs::remove_file(path);
        }
        std::process::exit(130);
    });
}

/// Removes the temporary files being written, from a path that must not block or panic
/// (a failed allocation, `allocation_failure`): the list is read only if its lock is free.
pub fn remove_pending_now() {
    if let Ok(pending) = PENDING.try_lock() {
        for path in pending.iter() {
            let _ = fs::remove_file(path);
        }
    }
}

/// Whether `p` is `-`, meaning standard input or output.
pub fn is_dash(p: &Path) -> bool {
    p.as_os_str() == "-"
}

/// Whether `a` and `b` name the same existing file (through `..`, symlinks and the like).
fn same_file(a: &Path, b: &Path) -> bool {
    match (fs::canonicalize(a), fs::canonicalize(b)) {
        (Ok(a), Ok(b)) => a == b,
        _ => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_failed_write_leaves_the_previous_file_whole() {
        // Issue 30, G24: on a full disk `bench` replaced a chart with a truncated file.
        let dir = tempfile::tempdir().unwrap();
        let chart = dir.path().join("accuracy.svg");
        write_file(&chart, b"<svg>old</svg>").unwrap();
        let full_disk = |w: &mut dyn Write| {
            w.write_all(b"<svg>ne")?;
            Err(io::Error::new(ErrorKind::StorageFull, "No space left on device"))
        };
        let err = write_atomically(&chart, dir.path(), full_disk).unwrap_err();
        assert!(err.to_string().contains("No space left on device"), "{err}");
        assert_eq!(fs::read(&chart).unwrap(), b"<svg>old</svg>");
        let left: Vec<_> =
            fs::read_dir(dir.path()).unwrap().map(|e| e.unwrap().file_name()).collect();
        assert_eq!(left, ["accuracy.svg"], "no temporary file is left behind");
        write_file(&chart, b"<svg>new</svg>").unwrap();
        assert_eq!(fs::read(&chart).unwrap(), b"<svg>new</svg>");
    }
}
