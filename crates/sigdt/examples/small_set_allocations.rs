//! What allocation costs a small set: `cargo run --release -p sigdt --example
//! small_set_allocations -- [SETS] [N] [ROUNDS]` reconstructs SETS random blobs of N points
//! (shuffled) on one thread with SIG-CONNECT2D and with the default, counts the allocations
//! and bytes of one set, and times the sets in interleaved rounds with the system allocator
//! and with an arena that never frees and is reset after every set: what reusing every
//! buffer between sets could at most save (issue 48, item 4).
use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering::Relaxed};
use std::time::Instant;

/// The arena's size: far more than one set of a few thousand points allocates.
const ARENA: usize = 1 << 28;

/// The system allocator, counting; or, while `BUMP` is set, a bump arena that frees
/// nothing (the timed loop resets it between sets). One thread allocates while it is on.
struct Switchable;

static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);
static BYTES: AtomicUsize = AtomicUsize::new(0);
static BUMP: AtomicBool = AtomicBool::new(false);
static BASE: AtomicUsize = AtomicUsize::new(0);
static USED: AtomicUsize = AtomicUsize::new(0);

fn in_arena(p: *mut u8) -> bool {
    let base = BASE.load(Relaxed);
    base != 0 && (p as usize) >= base && (p as usize) < base + ARENA
}

#[allow(unsafe_code)]
// SAFETY: the arena hands out disjoint, aligned blocks inside one live system allocation
// of ARENA bytes (or null when full); everything else goes to `System`.
unsafe impl GlobalAlloc for Switchable {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Relaxed);
        BYTES.fetch_add(layout.size(), Relaxed);
        if !BUMP.load(Relaxed) {
            return unsafe { System.alloc(layout) };
        }
        let base = BASE.load(Relaxed);
        let start = (base + USED.load(Relaxed)).next_multiple_of(layout.align());
        if start + layout.size() > base + ARENA {
            return std::ptr::null_mut();
        }
        USED.store(start + layout.size() - base, Relaxed);
        start as *mut u8
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        if !in_arena(ptr) {
            unsafe { System.dealloc(ptr, layout) };
        }
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        if !in_arena(ptr) && !BUMP.load(Relaxed) {
            ALLOCATIONS.fetch_add(1, Relaxed);
            BYTES.fetch_add(new_size, Relaxed);
            return unsafe { System.realloc(ptr, layout, new_size) };
        }
        let grown =
            unsafe { self.alloc(Layout::from_size_align_unchecked(new_size, layout.align())) };
        if !grown.is_null() {
            unsafe { std::ptr::copy_nonoverlapping(ptr, grown, layout.size().min(new_size)) };
            unsafe { self.dealloc(ptr, layout) };
        }
        grown
    }
}

#[global_allocator]
static ALLOCATOR: Switchable = Switchable;

fn main() {
    let mut args = std::env::args().skip(1);
    let sets: u64 = args.next().and_then(|s| s.parse().ok()).unwrap_or(5_000);
    let n: usize = args.next().and_then(|s| s.parse().ok()).unwrap_or(260);
    let rounds: usize = args.next().and_then(|s| s.parse().ok()).unwrap_or(5);
    let arena = arena_memory();
    BASE.store(arena as usize, Relaxed);
    let samples: Vec<_> =
        (0..sets).map(|s| sigdt::samplers::random_closed_curve(s, n).shuffled(s)).collect();
    let pool = rayon::ThreadPoolBuilder::new().num_threads(1).build().unwrap();
    let methods = [
        (
            "SIG-CONNECT2D",
            sigdt::Options { method: sigdt::Method::SigConnect2d, ..Default::default() },
        ),
        ("default", sigdt::Options::default()),
    ];
    for (name, options) in &methods {
        let run = |s: &sigdt::samplers::Sample| {
            std::hint::black_box(sigdt::reconstruct(&s.points, options).unwrap());
        };
        pool.install(|| run(&samples[0]));
        let (before, bytes) = (ALLOCATIONS.load(Relaxed), BYTES.load(Relaxed));
        pool.install(|| run(&samples[0]));
        let per_set = ALLOCATIONS.load(Relaxed) - before;
        let set_bytes = BYTES.load(Relaxed) - bytes;
        println!("{name}: {per_set} allocations, {set_bytes} bytes for one set of {n} points");
        let mut ratios = Vec::new();
        for round in 0..rounds {
            let time = |bump: bool| {
                pool.install(|| {
                    let start = Instant::now();
                    for s in &samples {
                        BUMP.store(bump, Relaxed);
                        run(s);
                        BUMP.store(false, Relaxed);
                        USED.store(0, Relaxed);
                    }
                    start.elapsed().as_secs_f64() * 1e6 / sets as f64
                })
            };
            let (malloc, arena) = (time(false), time(true));
            ratios.push(arena / malloc);
            println!("  round {round}: {malloc:.1} µs a set, {arena:.1} with the arena");
        }
        ratios.sort_by(f64::total_cmp);
        println!("  arena / system allocator: median {:.3}", ratios[ratios.len() / 2]);
    }
}

/// The arena's memory, from the system allocator (never freed: the process ends).
fn arena_memory() -> *mut u8 {
    let layout = Layout::from_size_align(ARENA, 4096).unwrap();
    #[allow(unsafe_code)]
    // SAFETY: a non-zero size and a valid alignment.
    let p = unsafe { System.alloc(layout) };
    assert!(!p.is_null(), "no memory for the arena");
    p
}
