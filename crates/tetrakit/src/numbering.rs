//! Vertex numbers and message text: a renumbering of points for locality
//! ([`Renumbering`]), vertex and cell numbers in the text of witnesses and problems,
//! input tokens quoted for messages ([`quote`]), and the contract's names of kinds
//! ([`json_name`]).
//!
//! Sentences for a person name vertices as `#12` and cells (tetrahedra, triangles) as
//! `T12`. The library numbers both from 0; a file may number from 1 (TetGen), may number
//! its tetrahedra with gaps, or the algorithm may have renumbered the points (a spatial
//! order), so texts are renamed by rewriting every `#<digits>` and every `T<digits>` that
//! starts a word. Shared by `mesh` (the verifier's problems) and `detect` (witnesses),
//! which depend on it and not on each other.
//!
//! ```
//! use tetrakit::numbering::{ids, relabel_text, renumber_text};
//! assert_eq!(ids(&[1, 2]), "[#1, #2]");
//! assert_eq!(renumber_text("vertex #0 lies on (#1, #2)", 1), "vertex #1 lies on (#2, #3)");
//! let labels = [10, 20, 30];
//! assert_eq!(
//!     relabel_text("tetrahedra T0 and T2 share #0", |v| v + 1, |t| labels[t as usize]),
//!     "tetrahedra T10 and T30 share #1"
//! );
//! ```

/// Adds `base` to every vertex number (`#<digits>`) and cell number (`T<digits>`) in
/// `text`.
pub fn renumber_text(text: &str, base: u32) -> String {
    relabel_text(text, |v| v + base, |t| t + base)
}

/// Renames every vertex number `#v` in `text` to `#f(v)`; cell numbers are kept.
pub fn map_text(text: &str, f: impl Fn(u32) -> u32) -> String {
    relabel_text(text, f, |t| t)
}

/// Renames every vertex number `#v` in `text` to `#vertex(v)` and every cell number `Tt`
/// (a `T` that starts a word, then digits) to `Tcell(t)`.
pub fn relabel_text(text: &str, vertex: impl Fn(u32) -> u32, cell: impl Fn(u32) -> u32) -> String {
    let mut out = String::with_capacity(text.len());
    let bytes = text.as_bytes();
    let (mut i, mut copied) = (0, 0);
    while i < bytes.len() {
        let b = bytes[i];
        let starts_word = i == 0 || !bytes[i - 1].is_ascii_alphanumeric();
        let f: Option<&dyn Fn(u32) -> u32> = match b {
            b'#' => Some(&vertex),
            b'T' if starts_word => Some(&cell),
            _ => None,
        };
        // `b` is ASCII, so `i + 1` is a character boundary.
        let digits = bytes[i + 1..]
            .iter()
            .take_while(|c| c.is_ascii_digit())
            .count();
        match f.map(|f| (f, text[i + 1..i + 1 + digits].parse::<u32>())) {
            Some((f, Ok(x))) => {
                out.push_str(&text[copied..=i]);
                out.push_str(&f(x).to_string());
                i += 1 + digits;
                copied = i;
            }
            _ => i += 1,
        }
    }
    out.push_str(&text[copied..]);
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

/// The name a unit enum variant has in the JSON contract (its serde name: `"no_candidate"`),
/// for the `Display` of the kinds of problems and witnesses; `fallback` if it has none.
pub fn json_name(value: &impl serde::Serialize, fallback: &'static str) -> String {
    match serde_json::to_value(value) {
        Ok(serde_json::Value::String(s)) => s,
        _ => fallback.to_string(),
    }
}
