//! Cancelling a reading from another thread: Python's `read_points` runs the reader on a
//! thread of its own and sets the flag when Ctrl-C arrives (issue 47, P3). The flag is the
//! reading thread's, so that readers deep down (SQLite's progress handler, the block loop
//! of plain point files) can ask without a parameter through every layer.

use std::cell::RefCell;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

thread_local! {
    static FLAG: RefCell<Option<Arc<AtomicBool>>> = const { RefCell::new(None) };
}

/// Runs `read` on this thread with `flag` as its cancel flag: readers stop with an error
/// ("reading cancelled") soon after it is set.
pub fn cancellable<T>(flag: Arc<AtomicBool>, read: impl FnOnce() -> T) -> T {
    FLAG.with(|f| *f.borrow_mut() = Some(flag));
    let out = read();
    FLAG.with(|f| *f.borrow_mut() = None);
    out
}

/// Whether this thread's reading was cancelled.
pub fn cancelled() -> bool {
    FLAG.with(|f| f.borrow().as_ref().is_some_and(|flag| flag.load(Ordering::Relaxed)))
}
