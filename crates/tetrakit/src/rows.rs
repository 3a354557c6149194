//! Compressed rows (one flat array cut at nondecreasing offsets): the counting sort of
//! the planar grids, adjacency and edge lists ([`buckets`]), and its parallel form for the
//! readers' segment check, the segment graph and the verifier's face pairing ([`group`]).

use rayon::prelude::*;

/// `v` cut into the pieces `offsets[i]..offsets[i + 1]` (`offsets` runs from 0 to the
/// length, nondecreasing).
pub(crate) fn split_at_offsets<'a, T>(v: &'a mut [T], offsets: &[usize]) -> Vec<&'a mut [T]> {
    let mut pieces = Vec::with_capacity(offsets.len().saturating_sub(1));
    let mut rest = v;
    for w in offsets.windows(2) {
        let (head, tail) = rest.split_at_mut(w[1] - w[0]);
        pieces.push(head);
        rest = tail;
    }
    pieces
}

/// Calls `f(i, row)` for every row `start[i]..start[i + 1]` of `v`, rows in parallel (in
/// runs of consecutive rows, so that a million small rows do not make a million tasks).
pub(crate) fn for_each_row<T: Send>(
    v: &mut [T],
    start: &[usize],
    f: impl Fn(usize, &mut [T]) + Sync,
) {
    let rows = start.len().saturating_sub(1);
    let runs = (rayon::current_num_threads() * 16).clamp(1, rows.max(1));
    let cuts: Vec<usize> = (0..=runs).map(|r| rows * r / runs).collect();
    let offsets: Vec<usize> = cuts.iter().map(|&c| start[c]).collect();
    split_at_offsets(v, &offsets)
        .into_par_iter()
        .zip(cuts.par_windows(2))
        .for_each(|(run, w)| {
            let mut rest = run;
            for i in w[0]..w[1] {
                let (row, tail) = rest.split_at_mut(start[i + 1] - start[i]);
                f(i, row);
                rest = tail;
            }
        });
}

/// Compressed rows: `entries` `(bucket, item)` with buckets below `n`, grouped by bucket
/// (a counting sort, stable within a bucket; sequential: [`group`] is the parallel form
/// for indexed items). Returns the row starts (`n + 1` of them)
/// and the items. Used for the point and edge grids, adjacency lists and edge lists.
pub(crate) fn buckets<T: Copy + Default>(
    n: usize,
    entries: impl Iterator<Item = (usize, T)> + Clone,
) -> (Vec<u32>, Vec<T>) {
    let mut start = vec![0u32; n + 1];
    for (b, _) in entries.clone() {
        start[b + 1] += 1;
    }
    for i in 0..n {
        start[i + 1] += start[i];
    }
    let mut fill = start.clone();
    let mut items = vec![T::default(); start[n] as usize];
    for (b, x) in entries {
        items[fill[b] as usize] = x;
        fill[b] += 1;
    }
    (start, items)
}

/// Groups the pairs `(key, value)` that `emit(i)` yields for every item `i < items` into
/// rows by key: `start` (`keys + 1` offsets) and the values, each row in item order. Keys
/// at or beyond `keys` are skipped. Each thread counts and fills the rows of its own range
/// of keys while reading every item: reads are sequential and cheap, the scattered writes
/// are what costs, and they are split between the threads without contention.
pub(crate) fn group<V: Copy + Default + Send + Sync, I: IntoIterator<Item = (usize, V)>>(
    keys: usize,
    items: usize,
    emit: impl Fn(usize) -> I + Sync,
) -> (Vec<usize>, Vec<V>) {
    let parts = rayon::current_num_threads().clamp(1, keys.max(1));
    let bounds: Vec<usize> = (0..=parts).map(|p| keys * p / parts).collect();
    let scan = |lo: usize, hi: usize, put: &mut dyn FnMut(usize, V)| {
        for i in 0..items {
            for (key, value) in emit(i) {
                if (lo..hi).contains(&key) {
                    put(key - lo, value);
                }
            }
        }
    };
    let mut count = vec![0usize; keys];
    split_at_offsets(&mut count, &bounds)
        .into_par_iter()
        .zip(bounds.par_windows(2))
        .for_each(|(c, w)| scan(w[0], w[1], &mut |k, _| c[k] += 1));
    let mut start = Vec::with_capacity(keys + 1);
    start.push(0usize);
    for c in &count {
        start.push(start[start.len() - 1] + c);
    }
    let mut values = vec![V::default(); start[keys]];
    let offsets: Vec<usize> = bounds.iter().map(|&b| start[b]).collect();
    split_at_offsets(&mut values, &offsets)
        .into_par_iter()
        .zip(bounds.par_windows(2))
        .for_each(|(out, w)| {
            let mut fill: Vec<usize> = start[w[0]..w[1]].iter().map(|&s| s - start[w[0]]).collect();
            scan(w[0], w[1], &mut |k, v| {
                out[fill[k]] = v;
                fill[k] += 1;
            });
        });
    (start, values)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_are_visited_once_in_place() {
        let start = [0, 2, 2, 5, 6];
        let mut v = vec![9, 1, 7, 3, 5, 4];
        for_each_row(&mut v, &start, |i, row| {
            row.sort_unstable();
            row.iter_mut().for_each(|x| *x += 10 * i as i32);
        });
        assert_eq!(v, [1, 9, 23, 25, 27, 34]);
        let mut w = [1, 2, 3];
        let pieces = split_at_offsets(&mut w, &[0, 1, 1, 3]);
        assert_eq!(
            pieces.iter().map(|p| p.len()).collect::<Vec<_>>(),
            [1, 0, 2]
        );
    }
}
