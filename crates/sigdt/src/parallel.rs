//! Data-parallel loops on the current rayon pool, or sequential without the `parallel`
//! feature. Every loop here computes each element from the input alone (no reduction whose
//! result depends on how the work is split), so results are the same bit for bit at every
//! thread count and with the feature off. Callers that want a given number of threads run
//! sigdt inside `rayon::ThreadPoolBuilder::new().num_threads(n).build()?.install(...)`;
//! otherwise rayon's global pool is used (`RAYON_NUM_THREADS`, else one thread per core).

/// Below this many elements a loop runs sequentially (splitting costs more than it gains).
#[cfg(feature = "parallel")]
const MIN_PARALLEL: usize = 1 << 14;

/// Whether loops here may use more than one thread (the current pool has several). Passes
/// with a cheaper sequential form use it only then; both forms give the same result.
pub(crate) fn is_parallel() -> bool {
    #[cfg(feature = "parallel")]
    return rayon::current_num_threads() > 1;
    #[cfg(not(feature = "parallel"))]
    false
}

/// `(0..n).map(f).collect()`.
pub(crate) fn map_range<T: Send>(n: usize, f: impl Fn(usize) -> T + Sync + Send) -> Vec<T> {
    #[cfg(feature = "parallel")]
    if n >= MIN_PARALLEL {
        use rayon::prelude::*;
        return (0..n).into_par_iter().with_min_len(4096).map(f).collect();
    }
    (0..n).map(f).collect()
}

/// `items.iter().map(f).collect()`.
pub(crate) fn map_slice<S: Sync, T: Send>(
    items: &[S],
    f: impl Fn(&S) -> T + Sync + Send,
) -> Vec<T> {
    #[cfg(feature = "parallel")]
    if items.len() >= MIN_PARALLEL {
        use rayon::prelude::*;
        return items.par_iter().with_min_len(4096).map(f).collect();
    }
    items.iter().map(f).collect()
}

/// `items.iter_mut().for_each(f)`.
pub(crate) fn update_slice<T: Send>(items: &mut [T], f: impl Fn(&mut T) + Sync + Send) {
    #[cfg(feature = "parallel")]
    if items.len() >= MIN_PARALLEL {
        use rayon::prelude::*;
        return items.par_iter_mut().with_min_len(4096).for_each(f);
    }
    items.iter_mut().for_each(f)
}

/// Sorts distinct values (so that stability cannot matter).
pub(crate) fn sort_unstable<T: Ord + Send>(items: &mut [T]) {
    #[cfg(feature = "parallel")]
    if items.len() >= MIN_PARALLEL {
        use rayon::prelude::*;
        return items.par_sort_unstable();
    }
    items.sort_unstable()
}

/// `f` on every run of consecutive items that `same` joins (as `chunk_by_mut`), in
/// parallel from [`MIN_PARALLEL`] items on. Runs are disjoint, so the order does not matter.
pub(crate) fn for_each_run<T: Send>(
    items: &mut [T],
    same: impl Fn(&T, &T) -> bool + Sync + Send,
    f: impl Fn(&mut [T]) + Sync + Send,
) {
    #[cfg(feature = "parallel")]
    if items.len() >= MIN_PARALLEL {
        use rayon::prelude::*;
        return items.par_chunk_by_mut(same).for_each(f);
    }
    items.chunk_by_mut(same).for_each(f)
}

/// `(a(), b())`, on two threads when the pool has them.
pub(crate) fn join<A: Send, B: Send>(
    a: impl FnOnce() -> A + Send,
    b: impl FnOnce() -> B + Send,
) -> (A, B) {
    #[cfg(feature = "parallel")]
    return rayon::join(a, b);
    #[cfg(not(feature = "parallel"))]
    (a(), b())
}

/// `f` on the ranges `0..chunk`, `chunk..2·chunk`, ... covering `0..n`, in order: for loops
/// that carry a little state from one element to the next within a range.
pub(crate) fn map_chunks<T: Send>(
    n: usize,
    chunk: usize,
    f: impl Fn(std::ops::Range<usize>) -> T + Sync + Send,
) -> Vec<T> {
    let chunk = chunk.max(1);
    let range = |c: usize| c * chunk..((c + 1) * chunk).min(n);
    #[cfg(feature = "parallel")]
    if n >= MIN_PARALLEL {
        use rayon::prelude::*;
        return (0..n.div_ceil(chunk)).into_par_iter().map(|c| f(range(c))).collect();
    }
    (0..n.div_ceil(chunk)).map(|c| f(range(c))).collect()
}

/// How many times to halve `n` points for the divide-and-conquer triangulation
/// (`delaunay::divide`): until every thread of the current pool has a part (at most 16
/// parts), from 2^16 points on; 0 (insert them one by one) on one thread or fewer points.
pub(crate) fn halvings(n: usize) -> u32 {
    #[cfg(feature = "parallel")]
    if n >= 1 << 16 {
        return rayon::current_num_threads().min(16).next_power_of_two().trailing_zeros();
    }
    let _ = n;
    0
}
