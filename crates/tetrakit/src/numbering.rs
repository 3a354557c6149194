//! Vertex numbers and message text: a renumbering of points for locality
//! ([`Renumbering`]), vertex numbers in the text of witnesses and problems, and input
//! tokens quoted for messages ([`quote`]).
//!
//! Sentences for a person name vertices as `#12`. The library numbers from 0; a file may
//! number from 1 (TetGen) or the algorithm may have renumbered the points (a spatial
//! order), so texts are renumbered by rewriting every `#<digits>`. Shared by `mesh` (the
//! verifier's problems) and `detect` (witnesses), which depend on it and not on each
//! other.
//!
//! ```
//! use tetrakit::numbering::{ids, renumber_text};
//! assert_eq!(ids(&[1, 2]), "[#1, #2]");
//! assert_eq!(renumber_text("vertex #0 lies on (#1, #2)", 1), "vertex #1 lies on (#2, #3)");
//! ```

/// Adds `base` to every `#<digits>` vertex number in `text`.
pub fn renumber_text(text: &str, base: u32) -> String {
    map_text(text, |v| v + base)
}

/// Renames every `#<digits>` vertex number `v` in `text` to `f(v)`.
pub fn map_text(text: &str, f: impl Fn(u32) -> u32) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(i) = rest.find('#') {
        out.push_str(&rest[..=i]);
        rest = &rest[i + 1..];
        let digits = rest.bytes().take_while(u8::is_ascii_digit).count();
        if let Ok(x) = rest[..digits].parse::<u32>() {
            out.push_str(&f(x).to_string());
        } else {
            out.push_str(&rest[..digits]);
        }
        rest = &rest[digits..];
    }
    out.push_str(rest);
    out
}

/// Formats vertex numbers as `[#1, #2, #3]`.
pub fn ids(v: &[u32]) -> String {
    let parts: Vec<String> = v.iter().map(|x| format!("#{x}")).collect();
    format!("[{}]", parts.join(", "))
}

/// A renumbering of points, `new → old` and `old → new`: algorithms that read points at
/// random work in an order where neighbours in space are neighbours in memory (a
/// space-filling curve, grid cells), then give their answer in the caller's numbering.
///
/// ```
/// use tetrakit::numbering::Renumbering;
/// let r = Renumbering::from_order(vec![2, 0, 1]); // new 0 is old 2, ...
/// assert_eq!(r.reorder(&['a', 'b', 'c']), ['c', 'a', 'b']);
/// assert_eq!(r.to_new(&[[2, 1]]), [[0, 2]]);
/// assert_eq!(r.to_old(&[[0, 2]]), [[2, 1]]);
/// ```
#[derive(Clone, Debug)]
pub struct Renumbering {
    order: Vec<u32>,
    rank: Vec<u32>,
}

impl Renumbering {
    /// The renumbering in which new point `i` is old point `order[i]` (`order` a
    /// permutation of `0..order.len()`).
    pub fn from_order(order: Vec<u32>) -> Self {
        let mut rank = vec![0u32; order.len()];
        for (new, &old) in order.iter().enumerate() {
            rank[old as usize] = new as u32;
        }
        Renumbering { order, rank }
    }

    /// The old number of new point `v`.
    #[inline]
    pub fn old(&self, v: u32) -> u32 {
        self.order[v as usize]
    }

    /// The new number of old point `v`.
    #[inline]
    pub fn new_of(&self, v: u32) -> u32 {
        self.rank[v as usize]
    }

    /// `items` (one per old point) in the new order.
    pub fn reorder<T: Copy + Send + Sync>(&self, items: &[T]) -> Vec<T> {
        use rayon::prelude::*;
        self.order.par_iter().map(|&o| items[o as usize]).collect()
    }

    /// Cells (edges, triangles, tetrahedra) of old points in the new numbering.
    pub fn to_new<const N: usize>(&self, cells: &[[u32; N]]) -> Vec<[u32; N]> {
        use rayon::prelude::*;
        cells
            .par_iter()
            .map(|c| c.map(|v| self.new_of(v)))
            .collect()
    }

    /// Cells of new points in the old numbering.
    pub fn to_old<const N: usize>(&self, cells: &[[u32; N]]) -> Vec<[u32; N]> {
        use rayon::prelude::*;
        cells.par_iter().map(|c| c.map(|v| self.old(v))).collect()
    }
}

/// An input token for a message, in single quotes: escaped (no control character from
/// a file reaches the terminal) and cut to 40 characters.
///
/// ```
/// use tetrakit::numbering::quote;
/// assert_eq!(quote("1.5"), "'1.5'");
/// assert_eq!(quote("\u{1b}[31m"), "'\\u{1b}[31m'");
/// assert_eq!(quote(&"7".repeat(100)).chars().count(), 43);
/// ```
pub fn quote(tok: &str) -> String {
    let mut q: String = tok.chars().take(40).flat_map(char::escape_debug).collect();
    if tok.chars().nth(40).is_some() {
        q.push('…');
    }
    format!("'{q}'")
}
