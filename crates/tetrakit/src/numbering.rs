//! Vertex numbers in the text of witnesses and problems.
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
