//! A failed allocation ends the run with exit 1 and one line, not an abort (issue 47, S3).
//!
//! When an allocation fails, Rust's default handler prints `memory allocation of N bytes
//! failed` and aborts (SIGABRT, a core file, sometimes a backtrace); stable Rust offers no
//! hook to change that (`set_alloc_error_hook` is unstable). [`memory::check`] refuses the
//! runs that cannot fit before they start, but its bound is low on purpose, so a run near
//! the limit still reached the abort. The binary's global allocator is therefore
//! [`ExitOnAllocationFailure`]: the system allocator, except that a request it cannot serve
//! removes the temporary output files being written and exits with status 1 and the line
//! `sigdt: out of memory: ...`, naming the size that failed and the address-space limit.
//!
//! Implementing [`GlobalAlloc`] is unsafe by definition; besides the speed benchmark's
//! counting allocator and the one call of [`large_blocks`], this is the workspace's only
//! `unsafe`. Every method forwards to [`System`] unchanged; the failure path allocates
//! nothing (the message is formatted on the stack, the temporary files are removed with
//! the lock taken only if it is free) and never unwinds.
//!
//! [`memory::check`]: crate::memory
//! [`large_blocks`]: crate::large_blocks

use std::alloc::{GlobalAlloc, Layout, System};
use std::fmt::Write as _;
use std::io::Write as _;
use std::sync::atomic::{AtomicUsize, Ordering::SeqCst};

/// The system allocator, with a failed request ending the process with exit 1 (module
/// docs). The `sigdt` binary installs it as its `#[global_allocator]`.
#[derive(Debug, Default, Clone, Copy)]
pub struct ExitOnAllocationFailure;

#[allow(unsafe_code)]
// SAFETY: every method calls `System`'s with the caller's arguments and returns its result;
// where that result is null, the process exits instead of returning.
unsafe impl GlobalAlloc for ExitOnAllocationFailure {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        served(System.alloc(layout), layout.size())
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        served(System.alloc_zeroed(layout), layout.size())
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        served(System.realloc(ptr, layout, new_size), new_size)
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        System.dealloc(ptr, layout)
    }
}

/// The thread of the first failed allocation (its [`THREAD_MARK`]'s address), 0 before.
static EXITING: AtomicUsize = AtomicUsize::new(0);

thread_local! {
    /// A per-thread address that names the thread without allocating.
    static THREAD_MARK: u8 = const { 0 };
}

/// `block`, unless it is null: then the run ends (module docs).
#[inline]
fn served(block: *mut u8, size: usize) -> *mut u8 {
    if block.is_null() {
        out_of_memory(size);
    }
    block
}

#[cold]
#[inline(never)]
fn out_of_memory(size: usize) -> ! {
    // Only the first failure reports and exits: calling `exit` twice is undefined in C.
    // Another thread failing meanwhile waits for the process to end; the same thread
    // failing again (in what `exit` runs) cannot report, and aborts.
    let me = THREAD_MARK.with(|mark| mark as *const u8 as usize);
    if let Err(first) = EXITING.compare_exchange(0, me, SeqCst, SeqCst) {
        if first == me {
            std::process::abort();
        }
        loop {
            std::thread::sleep(std::time::Duration::from_secs(1));
        }
    }
    crate::output::remove_pending_now();
    let mut line = StackLine::default();
    let _ = write!(line, "sigdt: out of memory: an allocation of {} failed", Size(size as u64));
    let _ = match address_space_limit() {
        Some(limit) => write!(
            line,
            " under the address-space limit of {} (ulimit -v): raise the limit, or give \
             fewer points",
            Size(limit)
        ),
        None => write!(line, ": free memory, or give fewer points"),
    };
    let _ = line.write_str("\n");
    let _ = std::io::stderr().write_all(line.text());
    std::process::exit(1);
}

/// RLIMIT_AS in bytes, when there is one.
#[cfg(target_os = "linux")]
fn address_space_limit() -> Option<u64> {
    rustix::process::getrlimit(rustix::process::Resource::As).current
}

#[cfg(not(target_os = "linux"))]
fn address_space_limit() -> Option<u64> {
    None
}

/// A byte count as people read it: `N bytes` below a mebibyte, `N MB` above.
struct Size(u64);

impl std::fmt::Display for Size {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.0 {
            n if n < 1 << 20 => write!(f, "{n} bytes"),
            n => write!(f, "{} MB", n.div_ceil(1 << 20)),
        }
    }
}

/// One line of text in a fixed buffer: formatting into it never allocates. What does not
/// fit is cut (the line is written whole in practice: it is under 200 bytes).
struct StackLine {
    bytes: [u8; 256],
    len: usize,
}

impl Default for StackLine {
    fn default() -> Self {
        StackLine { bytes: [0; 256], len: 0 }
    }
}

impl StackLine {
    fn text(&self) -> &[u8] {
        &self.bytes[..self.len]
    }
}

impl std::fmt::Write for StackLine {
    fn write_str(&mut self, s: &str) -> std::fmt::Result {
        let room = self.bytes.len() - self.len;
        let taken = s.len().min(room);
        self.bytes[self.len..self.len + taken].copy_from_slice(&s.as_bytes()[..taken]);
        self.len += taken;
        match taken == s.len() {
            true => Ok(()),
            false => Err(std::fmt::Error),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_read_as_bytes_then_megabytes() {
        let mut line = StackLine::default();
        write!(line, "{} {} {}", Size(512), Size(1u64 << 20), Size(3u64 << 29)).unwrap();
        assert_eq!(line.text(), b"512 bytes 1 MB 1536 MB");
    }

    #[test]
    fn a_line_too_long_is_cut_not_overrun() {
        let mut line = StackLine::default();
        assert!(line.write_str(&"x".repeat(300)).is_err());
        assert_eq!(line.text().len(), 256);
    }
}
