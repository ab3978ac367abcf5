//! Freed large blocks go back to the system at once (glibc's malloc only).
//!
//! glibc serves a request of at least `M_MMAP_THRESHOLD` bytes from a mapping of its own and
//! unmaps it when it is freed, but by default it raises that threshold to the size of every
//! such block freed (up to 32 MiB). After the first large array is freed, arrays of that size
//! come from an arena instead and stay resident once freed; and each thread of the pool has
//! an arena of its own. So with the triangulation divided among threads, the parts' arrays
//! stayed resident beside the merged ones: the peak resident memory of a run on two threads
//! was far above the one-thread run's (`docs/algorithms.md` §7.6 has the figures).
//!
//! Setting the threshold fixes it (glibc then stops raising it): every block of a mebibyte
//! or more is mapped on its own and returned when freed. Blocks that large are few (the
//! arrays of a point set), so the extra mappings cost no measurable time. The Python module
//! leaves the interpreter's allocator alone: that process is the caller's.

/// Blocks at least this large (bytes) are mapped on their own.
const MAP_AT_LEAST: i32 = 1 << 20;

/// Sets glibc's mmap threshold (module docs); elsewhere nothing to do.
pub fn return_large_blocks_to_the_system() {
    #[cfg(all(target_os = "linux", target_env = "gnu"))]
    #[allow(unsafe_code)]
    // SAFETY: `mallopt` only changes a parameter of the allocator; any value is accepted
    // (an invalid one returns 0 and changes nothing), and it is called before any thread of
    // ours starts.
    unsafe {
        libc::mallopt(libc::M_MMAP_THRESHOLD, MAP_AT_LEAST);
    }
}
