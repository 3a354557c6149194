//! A token stream over a text file that remembers the line of each token, for the
//! readers whose entries may span lines (Medit, legacy VTK).

use super::{InputError, parse_coord, parse_coord32, parse_int};
use crate::geom::Point3;
use std::path::Path;

/// A stream of `(line, token)`.
pub(super) struct Stream<'a> {
    toks: Box<dyn Iterator<Item = (usize, &'a str)> + 'a>,
    pub(super) path: &'a Path,
    pub(super) line: usize,
}

impl<'a> Stream<'a> {
    /// The tokens of `text` (whose first line is line `skipped + 1` of the file), with
    /// everything from `comment` to the end of a line left out.
    pub(super) fn new(
        text: &'a str,
        skipped: usize,
        comment: Option<char>,
        path: &'a Path,
    ) -> Self {
        let toks = text.lines().enumerate().flat_map(move |(i, l)| {
            let l = match comment {
                Some(c) => l.split(c).next().unwrap_or(""),
                None => l,
            };
            l.split_ascii_whitespace()
                .map(move |x| (skipped + i + 1, x))
        });
        Stream {
            toks: Box::new(toks),
            path,
            line: skipped,
        }
    }

    pub(super) fn next(&mut self) -> Option<(usize, &'a str)> {
        let t = self.toks.next();
        if let Some((l, _)) = t {
            self.line = l;
        }
        t
    }

    /// The next token, or an error saying what was expected.
    pub(super) fn want(&mut self, what: &str) -> Result<(usize, &'a str), InputError> {
        let line = self.line;
        self.next().ok_or_else(|| {
            InputError::new(
                self.path,
                line,
                format!("the file ends where {what} was expected"),
            )
        })
    }

    /// A section's count: a non-negative integer.
    pub(super) fn count(&mut self, section: &str) -> Result<usize, InputError> {
        let (line, tok) = self.want(&format!("the number of {section}"))?;
        let k = parse_int(tok, self.path, line, &format!("the number of {section}"))?;
        usize::try_from(k)
            .map_err(|_| InputError::new(self.path, line, format!("negative number of {section}")))
    }

    /// `dim` coordinates (the rest 0) and the line of the last one.
    pub(super) fn point(&mut self, dim: usize) -> Result<(usize, Point3), InputError> {
        self.point_in(dim, false)
    }

    /// [`Stream::point`], in single precision when `single` (see [`parse_coord32`]).
    pub(super) fn point_in(
        &mut self,
        dim: usize,
        single: bool,
    ) -> Result<(usize, Point3), InputError> {
        let mut p = [0.0; 3];
        let mut at = self.line;
        for c in p.iter_mut().take(dim) {
            let (l, tok) = self.want("a coordinate")?;
            at = l;
            *c = match single {
                true => parse_coord32(tok).map_err(|e| InputError::new(self.path, l, e))?,
                false => parse_coord(tok, self.path, l)?,
            };
        }
        Ok((at, p))
    }
}
