//! Long calls that Ctrl-C interrupts: the work runs on a thread of its own while the calling
//! thread, GIL released, wakes every [`POLL`] to let Python handle signals.
//!
//! Python runs signal handlers only on the main thread and only between bytecodes, so a
//! call that keeps the GIL released for seconds would deliver `KeyboardInterrupt` only when
//! it returns. Here the caller gets it within [`POLL`]: a cancellation flag tells the
//! workers to stop at their next check (between point sets), and a computation that cannot
//! stop (one large set) finishes on its thread and is dropped. Small calls, expected to
//! take less than [`POLL`], run directly, without a thread.
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{channel, RecvTimeoutError};
use std::sync::Arc;
use std::time::Duration;

use pyo3::prelude::*;

use crate::convert::InternalError;

/// How often a waiting call lets Python handle signals.
pub const POLL: Duration = Duration::from_millis(50);

/// Points below which a call runs directly: at about a microsecond per point, such a call
/// ends well within [`POLL`].
pub const DIRECT_POINTS: usize = 20_000;

/// Runs `work` with the GIL released and returns its value, or raises what Python's signal
/// handlers raise (`KeyboardInterrupt` for Ctrl-C) within [`POLL`] of the signal, after
/// setting the flag given to `work`. With `points` below [`DIRECT_POINTS`] it runs on the
/// calling thread.
pub fn interruptible<T: Send + 'static>(
    py: Python<'_>,
    points: usize,
    work: impl FnOnce(&Arc<AtomicBool>) -> T + Send + 'static,
) -> PyResult<T> {
    let cancel = Arc::new(AtomicBool::new(false));
    if points < DIRECT_POINTS {
        return Ok(py.detach(|| work(&cancel)));
    }
    let (sender, receiver) = channel();
    let flag = Arc::clone(&cancel);
    std::thread::Builder::new()
        .name("sigdt".into())
        .spawn(move || {
            // The receiver is gone when the call was interrupted: nothing to report then.
            let _ = sender.send(work(&flag));
        })
        .map_err(|e| InternalError::new_err(format!("cannot start a thread: {e}")))?;
    let mut receiver = receiver;
    loop {
        // The receiver moves into the GIL-free closure and back: it is Send, not Sync.
        let (answer, back) = py.detach(move || (receiver.recv_timeout(POLL), receiver));
        receiver = back;
        match answer {
            Ok(value) => return Ok(value),
            Err(RecvTimeoutError::Timeout) => {
                if let Err(signal) = py.check_signals() {
                    cancel.store(true, Ordering::Relaxed);
                    return Err(signal);
                }
            }
            Err(RecvTimeoutError::Disconnected) => {
                return Err(InternalError::new_err("internal error in sigdt: a worker died"));
            }
        }
    }
}
