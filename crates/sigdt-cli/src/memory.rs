//! Refusing a run that cannot fit under the address-space limit, before it starts (issue
//! 47, S3). Under `ulimit -v` (RLIMIT_AS) every command aborted where an allocation failed.
//! Here each command that knows its cost per point compares a *lower bound* of what it will
//! need with what the limit leaves, and refuses with exit 1 and one line when even that
//! cannot fit, before reading further. The bound is low on purpose, so that no run that
//! fits is refused; a run that passes and still fails an allocation ends with exit 1 too
//! ([`crate::allocation_failure`]).

use anyhow::{bail, Result};

/// The least memory a command needs a point, in bytes, as docs/speed.md and
/// docs/reliability.md measure them (each rounded down).
#[derive(Debug, Clone, Copy)]
pub enum Cost {
    /// `reconstruct`: the triangulation and the method, about 100 bytes a point at least.
    Reconstruct,
    /// `view`: building the page, about 780 bytes a point.
    View,
    /// `render`: the picture, about 570 bytes a point.
    Render,
}

impl Cost {
    fn bytes_per_point(self) -> u64 {
        match self {
            Cost::Reconstruct => 100,
            Cost::View => 780,
            Cost::Render => 570,
        }
    }
}

/// Refuses `n` points for a command of `cost` when their lower bound does not fit in what
/// the address-space limit leaves beside the memory the process already maps.
pub fn check(name: &str, n: usize, cost: Cost) -> Result<()> {
    let Some(left) = address_space_left() else { return Ok(()) };
    let need = (n as u64).saturating_mul(cost.bytes_per_point());
    if need > left {
        bail!(
            "{name}: {n} points need at least {} MB of memory, and the address-space limit \
             (ulimit -v) leaves {} MB: raise the limit, or give fewer points",
            need.div_ceil(1 << 20),
            left >> 20
        );
    }
    Ok(())
}

/// What RLIMIT_AS leaves beside the memory the process has in use now; `None` without a
/// limit (or where it cannot be read).
///
/// In use means resident, not mapped: the mapped size counts address space the allocator
/// only reserved (glibc reserves 64 MB for each thread's arena, and gives it up when the
/// limit leaves no room), so subtracting it refused 10⁶ points under a 200 MB limit that
/// the run fits in. Resident memory is part of what the run holds, so the bound stays low.
#[cfg(target_os = "linux")]
fn address_space_left() -> Option<u64> {
    let limit = rustix::process::getrlimit(rustix::process::Resource::As).current?;
    // /proc/self/statm: the second field is the resident size in pages.
    let statm = std::fs::read_to_string("/proc/self/statm").ok()?;
    let pages: u64 = statm.split_whitespace().nth(1)?.parse().ok()?;
    let resident = pages.saturating_mul(rustix::param::page_size() as u64);
    Some(limit.saturating_sub(resident))
}

#[cfg(not(target_os = "linux"))]
fn address_space_left() -> Option<u64> {
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_lower_bound_past_the_limit_is_refused_in_one_line() {
        // This process has no RLIMIT_AS in the test harness, unless the tester set one:
        // either way a run of no points fits.
        assert!(check("a.xy", 0, Cost::View).is_ok());
        if let Some(left) = address_space_left() {
            let n = (left / 780 + 1) as usize;
            let err = check("a.xy", n, Cost::View).unwrap_err().to_string();
            assert!(err.contains("ulimit -v") && !err.contains('\n'), "{err}");
        }
    }
}
