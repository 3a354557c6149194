//! The text of a `check` outcome.

use crate::io::Input;
use crate::mesh::{CheckOutcome, Report};
use std::fmt::Write;

/// What `tetrakit check` prints for `outcome`, the check of the mesh read as `input`
/// (`parsed` seconds to read, `seconds` in all): the JSON object (`json`) or the text,
/// numbered as the file numbers its points and cells, partitioned meshes' pieces placed.
pub fn check_printed(
    outcome: CheckOutcome,
    input: &Input,
    seconds: f64,
    parsed: f64,
    json: bool,
) -> String {
    // Where each problem lies in its piece, placed before relabeling.
    let partitioned = !input.pieces.is_empty();
    let placed = (partitioned && json).then(|| problem_pieces(&outcome, input));
    let pieces = (partitioned && !json).then(|| pieces_text(&outcome, input));
    let outcome = outcome.relabeled(
        |v| input.point_label(v as usize),
        |t| input.tet_label(t as usize),
    );
    let other = input.other_cells.as_ref();
    if json {
        let mut extra = vec![
            ("other_cells", other.map_or(0, |o| o.count).into()),
            ("seconds", seconds.into()),
            ("parse_seconds", parsed.into()),
        ];
        if let Some(placed) = placed {
            extra.push(("pieces", input.pieces.len().into()));
            let placed = serde_json::to_value(placed).unwrap_or_default();
            extra.push(("problem_pieces", placed));
        }
        return super::json(&outcome, extra).to_string();
    }
    let other = other.map(|o| (o.count, o.message.as_str()));
    let mut text = check_text(&outcome, seconds, other).trim_end().to_string();
    if let Some(p) = pieces {
        text.push('\n');
        text.push_str(p.trim_end());
    }
    text
}

/// How many problems the text lists (the JSON keeps up to [`Report::LIMIT`]).
const LISTED: usize = 20;

/// The lines a person reads for `outcome`, checked in `seconds`; `other_cells` is the
/// count and the description of the cells a mixed mesh had besides its tetrahedra.
pub fn check_text(
    outcome: &CheckOutcome,
    seconds: f64,
    other_cells: Option<(usize, &str)>,
) -> String {
    let o = outcome;
    let mut s = String::new();
    if o.is_valid() {
        let scope = if o.convex {
            "a tetrahedralization of the convex hull of its points"
        } else {
            "oriented, face-paired, no overlap near any vertex, boundary closed and embedded (add --convex to certify it tetrahedralizes the convex hull)"
        };
        let _ = writeln!(
            s,
            "VALID: {} tetrahedra on {} points: {scope}. [{seconds:.3} s]",
            o.tetrahedra, o.vertices
        );
        if let Some(p) = &o.first_non_manifold {
            let _ = writeln!(
                s,
                "  {} non-manifold boundary edge(s), valid for a non-manifold domain (--manifold refuses them); first: {}",
                o.non_manifold_edges, p.detail
            );
        }
    } else {
        let _ = writeln!(
            s,
            "INVALID: {} problem(s) in {} tetrahedra:",
            o.problem_count, o.tetrahedra
        );
        for p in o.problems.iter().take(LISTED) {
            let _ = writeln!(s, "  {}: {}", p.kind, p.detail);
        }
        if o.problem_count > LISTED {
            let _ = writeln!(
                s,
                "  ... ({} more; --json lists up to {})",
                o.problem_count - LISTED,
                Report::LIMIT
            );
        }
    }
    if let Some(k) = o.reoriented {
        let _ = writeln!(
            s,
            "  {k} negatively oriented tetrahedra turned (--reorient)"
        );
    }
    if let Some((count, what)) = other_cells {
        let _ = writeln!(s, "  {count} other cells not checked (--tets-only): {what}");
    }
    s
}

/// Where the tetrahedra of each problem of `o` lie in a partitioned mesh `input` (its
/// pieces, [`crate::io::Input::pieces`]): for each problem, `[piece, cell]` per
/// tetrahedron, both 0-based. `o` must not be relabeled yet.
pub fn problem_pieces(o: &CheckOutcome, input: &crate::io::Input) -> Vec<Vec<[u32; 2]>> {
    o.problems
        .iter()
        .map(|p| {
            p.cells
                .iter()
                .filter_map(|&t| input.tet_piece(t as usize))
                .map(|(piece, cell)| [piece as u32, cell])
                .collect()
        })
        .collect()
}

/// The lines that place the first problems' tetrahedra in their pieces, after
/// [`check_text`]: `T900 is cell 17 of piece 2 (k_2.vtu)`.
pub fn pieces_text(o: &CheckOutcome, input: &crate::io::Input) -> String {
    let mut s = format!(
        "  read from {} pieces, interface vertices merged by global id where the pieces have one, else by exact coordinates\n",
        input.pieces.len()
    );
    let mut named: Vec<u32> = o
        .problems
        .iter()
        .take(10)
        .flat_map(|p| p.cells.iter().copied())
        .collect();
    named.sort_unstable();
    named.dedup();
    for t in named {
        if let Some((piece, cell)) = input.tet_piece(t as usize) {
            let p = &input.pieces[piece];
            let file = match p.partition {
                Some(tag) => format!("{}, partition {tag}", p.file.display()),
                None => p.file.display().to_string(),
            };
            let _ = writeln!(
                s,
                "  T{} is cell {cell} of piece {piece} ({file})",
                input.tet_label(t as usize)
            );
        }
    }
    s
}

/// What a mesh reader found besides the arrays (Python's `tetrakit.read`): the numbering,
/// regions, other cells, and the pieces of a partitioned mesh.
#[derive(Clone, Debug, serde::Serialize)]
pub struct MeshFacts {
    /// 2 or 3.
    pub dimension: usize,
    /// The file's numbering, 0 or 1.
    pub index_base: u32,
    /// The file's number of each point.
    pub point_labels: Vec<u32>,
    /// The file's number of each tetrahedron.
    pub tet_labels: Vec<u32>,
    /// Each tetrahedron's region, where the format has them.
    pub regions: Vec<i64>,
    /// Cells of other kinds, counted.
    pub other_cells: usize,
    /// A partitioned mesh's pieces: `[file, first tetrahedron]`; empty otherwise.
    pub pieces: Vec<(String, u32)>,
    /// Global ids at two coordinates: `[id, first point, second point, piece]`.
    pub id_mismatches: Vec<[i64; 4]>,
}

/// The facts of `input` for [`MeshFacts`].
pub fn mesh_facts(input: &crate::io::Input) -> MeshFacts {
    MeshFacts {
        dimension: input.dim,
        index_base: input.index_base,
        point_labels: (0..input.points.len())
            .map(|k| input.point_label(k))
            .collect(),
        tet_labels: (0..input.tets.len()).map(|k| input.tet_label(k)).collect(),
        regions: input.regions.clone(),
        other_cells: input.other_cells.as_ref().map_or(0, |o| o.count),
        pieces: input
            .pieces
            .iter()
            .map(|p| (p.file.display().to_string(), p.first_tet))
            .collect(),
        id_mismatches: (input.id_mismatches.iter())
            .map(|m| [m.id, m.first.into(), m.second.into(), m.piece.into()])
            .collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_text_of_an_inverted_tetrahedron() {
        use crate::mesh::{CheckOptions, check};
        let pts = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
        ];
        let o = check(&pts, vec![[0, 2, 1, 3]], CheckOptions::default());
        let text = check_text(&o, 0.0, None);
        assert!(text.starts_with("INVALID: 1 problem(s) in 1 tetrahedra:\n  inverted: "));
    }
}
