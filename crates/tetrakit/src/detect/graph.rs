//! The segment graph in compressed adjacency form, validated.

use rayon::prelude::*;

/// A segment list that is not a simple graph on the points.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum SegmentError {
    /// Segment `segment` (0-based position in the list) names a vertex beyond the points.
    VertexOutOfRange {
        /// Position of the segment in the list.
        segment: usize,
        /// Its two ends, as given.
        ends: [u32; 2],
        /// Number of points.
        vertices: usize,
    },
    /// Segment `segment` joins `vertex` to itself.
    SelfLoop {
        /// Position of the segment in the list.
        segment: usize,
        /// The vertex.
        vertex: u32,
    },
    /// The segment `ends` is listed more than once.
    Repeated {
        /// Its two ends, the smaller first.
        ends: [u32; 2],
    },
}

impl std::fmt::Display for SegmentError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            SegmentError::VertexOutOfRange {
                segment,
                ends,
                vertices,
            } => write!(
                f,
                "segment {segment} ({}, {}) names a vertex beyond the {vertices} points",
                ends[0], ends[1]
            ),
            SegmentError::SelfLoop { segment, vertex } => {
                write!(f, "segment {segment} joins vertex {vertex} to itself")
            }
            SegmentError::Repeated { ends } => {
                write!(f, "segment ({}, {}) is listed twice", ends[0], ends[1])
            }
        }
    }
}

impl std::error::Error for SegmentError {}

/// An undirected simple graph on `n` vertices with sorted adjacency lists.
#[derive(Clone, Debug)]
pub struct Graph {
    start: Vec<usize>,
    nbrs: Vec<u32>,
}

impl Graph {
    /// Builds the graph of `segments` on `n` vertices; rejects out-of-range indices,
    /// self-loops and repeated segments with a sentence naming the segment.
    ///
    /// ```
    /// use tetrakit::detect::Graph;
    /// let g = Graph::new(3, &[[0, 1], [1, 2]]).unwrap();
    /// assert!(g.has_edge(2, 1) && !g.has_edge(0, 2));
    /// assert!(Graph::new(3, &[[0, 1], [1, 0]]).is_err());
    /// ```
    pub fn new(n: usize, segments: &[[u32; 2]]) -> Result<Graph, SegmentError> {
        if let Some((k, s)) = segments
            .par_iter()
            .enumerate()
            .find_first(|(_, s)| s[0] as usize >= n || s[1] as usize >= n || s[0] == s[1])
        {
            return Err(if s[0] as usize >= n || s[1] as usize >= n {
                SegmentError::VertexOutOfRange {
                    segment: k,
                    ends: *s,
                    vertices: n,
                }
            } else {
                SegmentError::SelfLoop {
                    segment: k,
                    vertex: s[0],
                }
            });
        }
        let (deg, mut nbrs) = crate::rows::group(n, segments.len(), |k| {
            let [a, b] = segments[k];
            [(a as usize, b), (b as usize, a)]
        });
        crate::rows::for_each_row(&mut nbrs, &deg, |_, row| row.sort_unstable());
        let g = Graph { start: deg, nbrs };
        let repeat = (0..n as u32).into_par_iter().find_map_first(|v| {
            g.nbrs(v)
                .windows(2)
                .find(|w| w[0] == w[1])
                .map(|w| (v, w[0]))
        });
        match repeat {
            Some((v, w)) => Err(SegmentError::Repeated { ends: [v, w] }),
            None => Ok(g),
        }
    }

    /// Number of vertices.
    pub fn len(&self) -> usize {
        self.start.len() - 1
    }

    /// True when the graph has no vertex.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Number of edges.
    pub fn edge_count(&self) -> usize {
        self.nbrs.len() / 2
    }

    /// Sorted neighbours of `v`.
    #[inline]
    pub fn nbrs(&self, v: u32) -> &[u32] {
        &self.nbrs[self.slots(v)]
    }

    /// Where `b` sits in the flat adjacency array (within `a`'s row), if `ab` is a segment:
    /// a dense index for per-dart flags (`0..2 × edge_count()`).
    #[inline]
    pub fn slot(&self, a: u32, b: u32) -> Option<usize> {
        let from = self.slots(a).start;
        self.nbrs(a).binary_search(&b).ok().map(|i| from + i)
    }

    /// The slots of `v`'s row, in the order of [`Self::nbrs`].
    #[inline]
    pub fn slots(&self, v: u32) -> std::ops::Range<usize> {
        self.start[v as usize]..self.start[v as usize + 1]
    }

    /// True when `ab` is a segment.
    #[inline]
    pub fn has_edge(&self, a: u32, b: u32) -> bool {
        self.nbrs(a).binary_search(&b).is_ok()
    }

    /// The connected component of each vertex (numbered from 0 in order of first vertex).
    pub fn components(&self) -> Vec<u32> {
        let n = self.len();
        let mut comp = vec![u32::MAX; n];
        let mut next = 0;
        let mut stack = Vec::new();
        for s in 0..n {
            if comp[s] != u32::MAX {
                continue;
            }
            comp[s] = next;
            stack.push(s as u32);
            while let Some(v) = stack.pop() {
                for &w in self.nbrs(v) {
                    if comp[w as usize] == u32::MAX {
                        comp[w as usize] = next;
                        stack.push(w);
                    }
                }
            }
            next += 1;
        }
        comp
    }
}

/// Calls `found(j)` for every `y[j]` that is also in `x` (both sorted, no repeats), by
/// galloping: `O(r log(len / r))` comparisons for `r` alternations between the lists.
pub(super) fn intersect_sorted(x: &[u32], y: &[u32], mut found: impl FnMut(usize)) {
    let (mut i, mut j) = (0, 0);
    while i < x.len() && j < y.len() {
        match x[i].cmp(&y[j]) {
            std::cmp::Ordering::Equal => {
                found(j);
                i += 1;
                j += 1;
            }
            std::cmp::Ordering::Less => i = gallop(x, i, y[j]),
            std::cmp::Ordering::Greater => j = gallop(y, j, x[i]),
        }
    }
}

/// The first index after `from` whose entry is at least `t` (`s[from] < t`): exponential,
/// then binary search.
fn gallop(s: &[u32], from: usize, t: u32) -> usize {
    let (mut lo, mut step) = (from, 1);
    while lo + step < s.len() && s[lo + step] < t {
        lo += step;
        step *= 2;
    }
    let hi = (lo + step).min(s.len());
    lo + 1 + s[lo + 1..hi].partition_point(|&e| e < t)
}
