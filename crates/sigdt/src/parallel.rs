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

/// At most this many tables in [`tally`]: each beyond the first costs a table's memory.
#[cfg(feature = "parallel")]
const MAX_TALLY_PARTS: usize = 4;

/// A table of `len` cells summed over the items `0..n`: `add_range(range, table)` adds the
/// contributions of the items in `range` to `table` (whose cells start at `zero`), for
/// passes that scatter each item's contribution to cells (half-edges to their vertices).
///
/// On a pool of several threads, from [`MIN_PARALLEL`] items, the items are split into as
/// many ranges as threads (at most [`MAX_TALLY_PARTS`]), each summed into a table of its
/// own, and the tables are then added cell by cell with `merge(cell, other)`: every extra
/// table costs `len` cells of memory while it lives. `merge` must be commutative and
/// associative with `zero` as its identity (integer sums, wrapping or saturating; minima),
/// so that the result does not depend on the split.
pub(crate) fn tally<C: Copy + Send + Sync>(
    n: usize,
    len: usize,
    zero: C,
    add_range: impl Fn(std::ops::Range<usize>, &mut [C]) + Sync + Send,
    merge: impl Fn(&mut C, C) + Sync + Send,
) -> Vec<C> {
    #[cfg(feature = "parallel")]
    if n >= MIN_PARALLEL && rayon::current_num_threads() > 1 {
        use rayon::prelude::*;
        let parts = rayon::current_num_threads().min(MAX_TALLY_PARTS);
        let chunk = n.div_ceil(parts);
        let mut tables: Vec<Vec<C>> = (0..parts)
            .into_par_iter()
            .map(|p| {
                let mut table = vec![zero; len];
                add_range(p * chunk..((p + 1) * chunk).min(n), &mut table);
                table
            })
            .collect();
        let rest = tables.split_off(1);
        let mut sum = tables.pop().unwrap_or_default();
        const BLOCK: usize = 1 << 14;
        sum.par_chunks_mut(BLOCK).enumerate().for_each(|(b, cells)| {
            for table in &rest {
                for (cell, &other) in cells.iter_mut().zip(&table[b * BLOCK..]) {
                    merge(cell, other);
                }
            }
        });
        return sum;
    }
    let _ = &merge;
    let mut table = vec![zero; len];
    add_range(0..n, &mut table);
    table
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

#[cfg(all(test, feature = "parallel"))]
mod tests {
    use super::*;

    #[test]
    fn a_tally_does_not_depend_on_the_pool_size() {
        // Items scattered over cells with wrapping byte sums and with minima, on pools of one
        // thread to past MAX_TALLY_PARTS: the sequential table every time.
        let (n, len) = (3 * MIN_PARALLEL + 17, 1001);
        let cell = |i: usize| i * 7919 % len;
        let run = |threads: usize| {
            let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
            pool.install(|| {
                let sums = tally(
                    n,
                    len,
                    0u8,
                    |range, table| {
                        range.for_each(|i| table[cell(i)] = table[cell(i)].wrapping_add(i as u8))
                    },
                    |a, b| *a = a.wrapping_add(b),
                );
                let minima = tally(
                    n,
                    len,
                    f64::INFINITY,
                    |range, table| {
                        range.for_each(|i| table[cell(i)] = table[cell(i)].min(i as f64))
                    },
                    |a, b| *a = a.min(b),
                );
                (sums, minima)
            })
        };
        let mut sums = vec![0u8; len];
        let mut minima = vec![f64::INFINITY; len];
        for i in 0..n {
            sums[cell(i)] = sums[cell(i)].wrapping_add(i as u8);
            minima[cell(i)] = minima[cell(i)].min(i as f64);
        }
        for threads in 1..=MAX_TALLY_PARTS + 1 {
            assert_eq!(run(threads), (sums.clone(), minima.clone()), "{threads} threads");
        }
    }
}
