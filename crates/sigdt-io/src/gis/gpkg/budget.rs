//! A GeoPackage is an SQLite database, and its layer list, its systems and its layers may be
//! views: queries of any cost, an endless recursive one included (issue 47, M1 and M2: a
//! 20 KB file sorting into a temporary file at 80 MB/s until the disk was full). Every
//! query sigdt runs on a GeoPackage is therefore on a budget, enforced by SQLite's progress
//! handler, which SQLite calls every [`STEP`] virtual-machine instructions:
//!
//! - **time**: at most [`STEPS_PER_ROW`] instructions between two rows (about 10 to 60 s
//!   on today's machines); an ordinary table gives a row every few dozen;
//! - **temporary storage**: temporary tables and sorts are kept in memory
//!   (`temp_store = MEMORY`, so nothing is written beside the input or in `/tmp`), and
//!   SQLite may hold at most [`MEMORY`] bytes (its hard heap limit);
//! - **rows**: the reader counts every row against `--max-points`, a row without a point as
//!   one;
//! - **cancel**: a reading cancelled from another thread ([`crate::cancel`]) stops.
//!
//! Opening never writes beside the input either (M4): a database in write-ahead-log mode
//! with no log beside it (as QGIS leaves a closed GeoPackage), or in a folder sigdt may not
//! write to, is opened immutable, so SQLite creates no `-wal` or `-shm` file.

use std::path::Path;
use std::sync::atomic::{AtomicU64, AtomicU8, Ordering};
use std::sync::Arc;

use rusqlite::{Connection, OpenFlags};

/// How many virtual-machine instructions SQLite runs between two calls of the handler.
pub const STEP: i32 = 10_000;

/// The most instructions a query may run without giving a row.
pub const STEPS_PER_ROW: u64 = 1_000_000_000;

/// The most memory SQLite may hold while a query runs (sorts, temporary tables, caches).
pub const MEMORY: i64 = 512 << 20;

/// The budget of one query (module docs).
#[derive(Debug, Clone, Copy)]
pub struct Limits {
    /// The most instructions between two rows.
    pub steps_per_row: u64,
    /// The most memory SQLite may hold, in bytes.
    pub memory: i64,
}

impl Default for Limits {
    fn default() -> Limits {
        Limits { steps_per_row: STEPS_PER_ROW, memory: MEMORY }
    }
}

/// Why a query was stopped.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stop {
    /// It ran [`STEPS_PER_ROW`] instructions without a row.
    Time,
    /// SQLite held more than [`MEMORY`] bytes.
    Memory,
    /// The reading was cancelled.
    Cancelled,
}

impl Stop {
    /// What a user reads: which budget of `limits`, and what to do.
    pub fn explain(self, limits: &Limits) -> String {
        match self {
            Stop::Time => format!(
                "stopped after {} SQLite steps without a row (an endless or very costly \
                 view?); read a table, or write the view's rows to one",
                limits.steps_per_row
            ),
            Stop::Memory => format!(
                "stopped when SQLite held more than {} MiB (sorting or a temporary table of an \
                 endless or very large view?); read a table, or write the view's rows to one",
                limits.memory >> 20
            ),
            Stop::Cancelled => "reading cancelled".to_string(),
        }
    }
}

/// An open GeoPackage whose every query is on the budget; [`Budgeted::row`] marks progress.
pub struct Budgeted {
    /// The connection.
    pub db: Connection,
    ticks: Arc<AtomicU64>,
    /// 0 while running, else 1 + the index of the [`Stop`] in [`STOPS`].
    stopped: Arc<AtomicU8>,
    /// SQLite's heap limit before this reading, restored when it ends.
    heap_limit: i64,
    /// The budget.
    pub limits: Limits,
}

const STOPS: [Stop; 3] = [Stop::Time, Stop::Memory, Stop::Cancelled];

impl Budgeted {
    /// Opens `path` read-only on the default budget (module docs).
    pub fn open(path: &Path) -> rusqlite::Result<Budgeted> {
        Budgeted::open_with(path, Limits::default())
    }

    /// Opens `path` read-only on the budget `limits`. The memory budget is SQLite's hard
    /// heap limit, which is the process's (the bundled SQLite is sigdt's own): set while
    /// the reading lasts and restored after, so two GeoPackages read at once share it.
    pub fn open_with(path: &Path, limits: Limits) -> rusqlite::Result<Budgeted> {
        let mut db = open_read_only(path)?;
        db.pragma_update(None, "temp_store", "MEMORY")?;
        let heap_limit: i64 = db.query_row("PRAGMA hard_heap_limit", [], |row| row.get(0))?;
        if heap_limit == 0 || heap_limit > limits.memory {
            db.pragma_update(None, "hard_heap_limit", limits.memory)?;
        }
        let ticks = Arc::new(AtomicU64::new(0));
        let stopped = Arc::new(AtomicU8::new(0));
        let (t, s) = (Arc::clone(&ticks), Arc::clone(&stopped));
        db.progress_handler(
            STEP,
            Some(move || {
                let ticks = t.fetch_add(STEP as u64, Ordering::Relaxed) + STEP as u64;
                let stop = if crate::cancel::cancelled() {
                    Some(Stop::Cancelled)
                } else if ticks > limits.steps_per_row {
                    Some(Stop::Time)
                } else {
                    None
                };
                if let Some(stop) = stop {
                    let code = 1 + STOPS.iter().position(|&x| x == stop).unwrap_or(0);
                    s.store(code as u8, Ordering::Relaxed);
                }
                stop.is_some() // true interrupts the query
            }),
        )?;
        Ok(Budgeted { db, ticks, stopped, heap_limit, limits })
    }

    /// A row arrived (or a new query starts): the time budget starts again.
    pub fn row(&self) {
        self.ticks.store(0, Ordering::Relaxed);
    }

    /// Why `error` ended a query, if a budget did.
    pub fn stopped(&self, error: &rusqlite::Error) -> Option<Stop> {
        if error.sqlite_error_code() == Some(rusqlite::ErrorCode::OutOfMemory) {
            return Some(Stop::Memory);
        }
        match self.stopped.load(Ordering::Relaxed) {
            0 => None,
            code => STOPS.get(usize::from(code) - 1).copied(),
        }
    }
}

impl Drop for Budgeted {
    fn drop(&mut self) {
        // Nothing to report if it fails: the limit only guards readings.
        let _ = self.db.pragma_update(None, "hard_heap_limit", self.heap_limit);
    }
}

/// `path` opened read-only, immutable where SQLite would otherwise create files beside it.
pub fn open_read_only(path: &Path) -> rusqlite::Result<Connection> {
    let flags = OpenFlags::SQLITE_OPEN_READ_ONLY | OpenFlags::SQLITE_OPEN_NO_MUTEX;
    if !needs_immutable(path) {
        return Connection::open_with_flags(path, flags);
    }
    let uri = format!("file:{}?immutable=1", uri_path(path));
    Connection::open_with_flags(uri, flags | OpenFlags::SQLITE_OPEN_URI)
}

/// Whether opening `path` normally could write beside it: its folder is not writable, or it
/// is in write-ahead-log mode (header bytes 18 and 19 are 2) with no log beside it, which a
/// reader would create. With a log beside it, the log may hold committed rows, which only a
/// normal open reads.
fn needs_immutable(path: &Path) -> bool {
    let folder = path.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
    let writable = std::fs::metadata(folder).map(|m| !m.permissions().readonly()).unwrap_or(false)
        && is_writable(folder);
    let mut header = [0u8; 20];
    let wal = std::fs::File::open(path)
        .and_then(|mut f| std::io::Read::read_exact(&mut f, &mut header))
        .map(|()| header[18] == 2 && header[19] == 2)
        .unwrap_or(false);
    let mut log = path.as_os_str().to_owned();
    log.push("-wal");
    !writable || (wal && !Path::new(&log).exists())
}

/// Whether this process may create files in `folder` (access(2), which knows about
/// read-only mounts and permissions).
#[cfg(unix)]
fn is_writable(folder: &Path) -> bool {
    rustix::fs::access(folder, rustix::fs::Access::WRITE_OK).is_ok()
}

#[cfg(not(unix))]
fn is_writable(_folder: &Path) -> bool {
    true // the permissions' read-only flag, checked beside it, is what there is
}

/// `path` as the path part of an SQLite URI: percent-encoded where URIs need it.
fn uri_path(path: &Path) -> String {
    let absolute = std::path::absolute(path).unwrap_or_else(|_| path.to_path_buf());
    let mut out = String::new();
    for byte in absolute.to_string_lossy().bytes() {
        match byte {
            b'%' | b'?' | b'#' | b' ' | 0x80..=0xff => out.push_str(&format!("%{byte:02X}")),
            _ => out.push(byte as char),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_endless_view_is_stopped_by_its_budget() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("endless.sqlite");
        let db = Connection::open(&path).unwrap();
        db.execute_batch(
            "CREATE VIEW endless AS WITH RECURSIVE n(i) AS (SELECT 1 UNION ALL SELECT i + 1 \
             FROM n) SELECT i FROM n ORDER BY i DESC;",
        )
        .unwrap();
        drop(db);
        // A small budget, so that the test is quick; the default stops it the same way.
        let limits = Limits { steps_per_row: 50_000_000, memory: 64 << 20 };
        let budgeted = Budgeted::open_with(&path, limits).unwrap();
        let started = std::time::Instant::now();
        let first = budgeted.db.query_row("SELECT i FROM endless", [], |r| r.get::<_, i64>(0));
        let error = first.unwrap_err();
        assert!(matches!(budgeted.stopped(&error), Some(Stop::Memory | Stop::Time)), "{error}");
        assert!(started.elapsed().as_secs() < 300);
    }

    #[test]
    fn a_path_becomes_a_uri_path() {
        let p = uri_path(Path::new("/data/a b?c#d%e.gpkg"));
        assert_eq!(p, "/data/a%20b%3Fc%23d%25e.gpkg");
    }
}
