//! Vertex numbers and message text: sentences that name vertices and cells as data
//! ([`Sentence`]); inside the crate, a renumbering of points for locality, input tokens
//! quoted for messages, and the contract's names of kinds.
//!
//! Sentences for a person name vertices as `#12` and cells (tetrahedra, triangles) as
//! `T12`. The library numbers both from 0; a file may number from 1 (TetGen), may number
//! its tetrahedra with gaps, or the algorithm may have renumbered the points (a spatial
//! order). So a witness's or problem's sentence is a [`Sentence`]: text with the numbers
//! kept apart, built once from the library's own format string where it is made,
//! renamed by mapping the numbers ([`Sentence::map`]), and formatted only when shown.
//! Shared by `mesh` (the verifier's problems) and `detect` (witnesses), which depend on
//! it and not on each other.
//!
//! ```
//! use tetrakit::numbering::{Sentence, ids};
//! assert_eq!(ids(&[1, 2]), "[#1, #2]");
//! let s = Sentence::from("tetrahedra T0 and T2 share #0");
//! let labels = [10, 20, 30];
//! let s = s.map(|v| v + 1, |t| labels[t as usize]);
//! assert_eq!(s.to_string(), "tetrahedra T10 and T30 share #1");
//! ```

use std::fmt;

/// A sentence for a person whose vertex numbers (`#12`) and cell numbers (`T12`) are
/// data: [`map`](Sentence::map) renames them, [`Display`](fmt::Display) and the JSON
/// (a string) format them.
///
/// Made from the library's own text (`Sentence::from(format!("vertex #{v} …"))`): each
/// `#` followed by digits is a vertex, each `T` that starts a word followed by digits a
/// cell, read once where the sentence is made; no text taken from an input is ever part
/// of one.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Sentence(Vec<Part>);

/// A piece of a [`Sentence`].
#[derive(Clone, Debug, PartialEq, Eq)]
enum Part {
    Text(String),
    Vertex(u32),
    Cell(u32),
}

impl From<&str> for Sentence {
    fn from(text: &str) -> Self {
        let mut parts = Vec::new();
        let bytes = text.as_bytes();
        let (mut i, mut copied) = (0, 0);
        while i < bytes.len() {
            let starts_word = i == 0 || !bytes[i - 1].is_ascii_alphanumeric();
            let make: Option<fn(u32) -> Part> = match bytes[i] {
                b'#' => Some(Part::Vertex),
                b'T' if starts_word => Some(Part::Cell),
                _ => None,
            };
            // `bytes[i]` is ASCII here, so `i + 1` is a character boundary.
            let digits = bytes[i + 1..]
                .iter()
                .take_while(|c| c.is_ascii_digit())
                .count();
            match make.map(|m| (m, text[i + 1..i + 1 + digits].parse::<u32>())) {
                Some((make, Ok(x))) => {
                    if copied < i {
                        parts.push(Part::Text(text[copied..i].to_string()));
                    }
                    parts.push(make(x));
                    i += 1 + digits;
                    copied = i;
                }
                _ => i += 1,
            }
        }
        if copied < text.len() {
            parts.push(Part::Text(text[copied..].to_string()));
        }
        Sentence(parts)
    }
}

impl From<String> for Sentence {
    fn from(text: String) -> Self {
        Sentence::from(text.as_str())
    }
}

impl Sentence {
    /// Every vertex `v` renamed `vertex(v)` and every cell `t` renamed `cell(t)`.
    pub fn map(mut self, vertex: impl Fn(u32) -> u32, cell: impl Fn(u32) -> u32) -> Self {
        for p in &mut self.0 {
            match p {
                Part::Vertex(v) => *v = vertex(*v),
                Part::Cell(t) => *t = cell(*t),
                Part::Text(_) => {}
            }
        }
        self
    }

    /// Every vertex and cell number shifted by `base` (a file numbering from 1).
    pub fn shifted(self, base: u32) -> Self {
        self.map(|v| v + base, |t| t + base)
    }

    /// Every `from` in its text (not in its numbers) replaced by `to`.
    pub fn replace(mut self, from: &str, to: &str) -> Self {
        for p in &mut self.0 {
            if let Part::Text(t) = p {
                *t = t.replace(from, to);
            }
        }
        self
    }

    /// True when the sentence as shown contains `pattern`.
    pub fn contains(&self, pattern: &str) -> bool {
        self.to_string().contains(pattern)
    }

    /// True when it says nothing.
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }
}

impl fmt::Display for Sentence {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for p in &self.0 {
            match p {
                Part::Text(t) => f.write_str(t)?,
                Part::Vertex(v) => write!(f, "#{v}")?,
                Part::Cell(t) => write!(f, "T{t}")?,
            }
        }
        Ok(())
    }
}

impl serde::Serialize for Sentence {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_str(self)
    }
}

/// Read back from its text, as it travels between ranks (`distributed`).
impl<'de> serde::Deserialize<'de> for Sentence {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        String::deserialize(d).map(Sentence::from)
    }
}

/// Adds `base` to every vertex number (`#<digits>`) and cell number (`T<digits>`) in a
/// library message: for the errors the command line names in a file's numbering.
pub fn renumber_text(text: &str, base: u32) -> String {
    Sentence::from(text).shifted(base).to_string()
}

/// Formats vertex numbers as `[#1, #2, #3]`.
pub fn ids(v: &[u32]) -> String {
    let parts: Vec<String> = v.iter().map(|x| format!("#{x}")).collect();
    format!("[{}]", parts.join(", "))
}

/// A renumbering of points, `new → old` and `old → new`: algorithms that read points at
/// random work in an order where neighbours in space are neighbours in memory (a
/// space-filling curve, grid cells), then give their answer in the caller's numbering.
#[derive(Clone, Debug)]
pub(crate) struct Renumbering {
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
pub(crate) fn quote(tok: &str) -> String {
    let mut q: String = tok.chars().take(40).flat_map(char::escape_debug).collect();
    if tok.chars().nth(40).is_some() {
        q.push('…');
    }
    format!("'{q}'")
}

/// The name a unit enum variant has in the JSON contract (its serde name: `"no_candidate"`),
/// for the `Display` of the kinds of problems and witnesses; `fallback` if it has none.
pub(crate) fn json_name(value: &impl serde::Serialize, fallback: &'static str) -> String {
    match serde_json::to_value(value) {
        Ok(serde_json::Value::String(s)) => s,
        _ => fallback.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn renumbering_maps_both_ways() {
        let r = Renumbering::from_order(vec![2, 0, 1]); // new 0 is old 2, ...
        assert_eq!(r.reorder(&['a', 'b', 'c']), ['c', 'a', 'b']);
        assert_eq!(r.to_new(&[[2, 1]]), [[0, 2]]);
        assert_eq!(r.to_old(&[[0, 2]]), [[2, 1]]);
    }

    #[test]
    fn quote_escapes_and_cuts() {
        assert_eq!(quote("1.5"), "'1.5'");
        assert_eq!(quote("\u{1b}[31m"), "'\\u{1b}[31m'");
        assert_eq!(quote(&"7".repeat(100)).chars().count(), 43);
    }

    /// Shown unchanged, a sentence is its text; only `#<digits>` and a word's
    /// `T<digits>` are numbers, and mapping them leaves every other character alone.
    #[test]
    fn sentences_keep_their_text_and_map_only_numbers() {
        let texts = [
            "vertex #4 lies inside segment (#1, #2)",
            "tetrahedra T0 and T12 share #0#1",
            "T-junction at #x, Type T3a, AT7, #, T, ##9, #99999999999",
            "",
            "ünïcode #3 — T4",
        ];
        for t in texts {
            assert_eq!(Sentence::from(t).to_string(), t);
        }
        let s = Sentence::from(texts[2]).map(|v| v + 100, |c| c + 1000);
        assert_eq!(
            s.to_string(),
            "T-junction at #x, Type T1003a, AT7, #, T, ##109, #99999999999"
        );
        let s = Sentence::from(texts[1]).shifted(1);
        assert_eq!(s.to_string(), "tetrahedra T1 and T13 share #1#2");
        let s = Sentence::from(texts[4]).replace("T", "cell ");
        assert_eq!(s.to_string(), "ünïcode #3 — T4");
    }

    /// In JSON a sentence is its text, and read back it is the same sentence.
    #[test]
    fn sentences_travel_as_text() {
        let s = Sentence::from("face [#1, #2, #3] of T7");
        let json = serde_json::to_string(&s).unwrap();
        assert_eq!(json, "\"face [#1, #2, #3] of T7\"");
        let back: Sentence = serde_json::from_str(&json).unwrap();
        assert_eq!(back, s);
        assert_eq!(
            back.map(|v| v * 2, |t| t).to_string(),
            "face [#2, #4, #6] of T7"
        );
    }
}
