//! Reading and writing meshes and segment sets: TetGen `.node/.edge/.ele/.face`, OBJ
//! (`v`, `l`, `f`), OFF, STL, Gmsh `.msh`, Medit `.mesh`, legacy VTK `.vtk` and VTK XML
//! `.vtu` (read; VTK is also written), the JSON of the README, plain `.xyz` point lists.
//!
//! Every reader validates its syntax as it goes and fails with an [`InputError`] naming the
//! file, the line (or the byte, in binary data) and the problem: indices in range, counts
//! equal to what follows. Header counts are checked against the bytes that follow but are
//! never used to size an allocation. Then every input passes one set of checks, whatever
//! read it (`validate`, run by [`read_input_with`] and [`from_arrays`]): coordinates
//! finite and within the range where the exact predicates are exact, and, unless a mesh
//! is read for its tetrahedra alone ([`ReadOptions::mesh`]), no self-loop or repeated
//! segment and no two points at the same place.

mod gmsh;
mod gmsh_binary;
mod json;
mod medit;
mod obj;
mod off;
mod planar;
mod pvtu;
mod stl;
mod stream;
mod svg;
mod tetgen;
mod vtk;
mod vtk_binary;
mod vtu;
mod vtu_data;
mod write;

pub use planar::{write_planar_edges, write_planar_triangulation, write_points2d};
pub use svg::{Figure, Svg};
pub(crate) use write::{Fields, write_piece};
pub use write::{
    piece_path, write_check_output, write_edges, write_instance, write_mesh, write_pieces,
    write_points, write_pvtu_index, write_surface, write_triangulation, write_vtk,
};

use crate::geom::{Point3, coordinate_in_range, lex_cmp};
pub(crate) use crate::numbering::quote;
use rayon::prelude::*;
use std::fmt;
use std::path::{Path, PathBuf};

/// A problem with an input file: exit code 2 in the CLI.
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct InputError {
    /// The file.
    pub file: String,
    /// 1-based line number, or 0 when the problem concerns the whole file.
    pub line: usize,
    /// What is wrong.
    pub message: String,
    /// The byte offset of the problem in a binary file (where lines mean nothing);
    /// `None` in text.
    pub byte: Option<u64>,
}

impl InputError {
    /// An error at `line` of `file`.
    pub fn new(file: &Path, line: usize, message: impl Into<String>) -> Self {
        InputError {
            file: file.display().to_string(),
            line,
            message: one_line(message.into()),
            byte: None,
        }
    }

    /// An error at byte `offset` of a binary `file`.
    pub fn at_byte(file: &Path, offset: usize, message: impl Into<String>) -> Self {
        InputError {
            byte: Some(offset as u64),
            ..InputError::new(file, 0, message)
        }
    }
}

/// A message on one line: line breaks (quoted from a file) become spaces.
fn one_line(message: String) -> String {
    if message.contains(['\n', '\r']) {
        message.replace("\r\n", " ").replace(['\n', '\r'], " ")
    } else {
        message
    }
}

impl fmt::Display for InputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (self.line, self.byte) {
            (0, Some(b)) => write!(f, "{}: byte {b}: {}", self.file, self.message),
            (0, None) => write!(f, "{}: {}", self.file, self.message),
            (l, _) => write!(f, "{}:{l}: {}", self.file, self.message),
        }
    }
}

impl std::error::Error for InputError {}

/// Everything read from an input: points and whichever of segments, faces and tetrahedra
/// the format carried. Indices are 0-based internally.
#[derive(Clone, Debug, Default)]
pub struct Input {
    /// The points (a 2D input has `z = 0`).
    pub points: Vec<Point3>,
    /// 2 for planar input files, 3 otherwise.
    pub dim: usize,
    /// Segments as pairs of point indices.
    pub segments: Vec<[u32; 2]>,
    /// Triangles.
    pub faces: Vec<[u32; 3]>,
    /// Tetrahedra.
    pub tets: Vec<[u32; 4]>,
    /// The numbering of the input file (0 or 1), used to report vertices as the user
    /// numbered them.
    pub index_base: u32,
    /// The source line of each point, for messages (empty where the format has none).
    pub point_lines: Vec<usize>,
    /// The file's own number of each point where it is not `k + index_base` (Gmsh node
    /// tags with gaps); empty otherwise. See [`Input::point_label`].
    pub point_labels: Vec<u32>,
    /// The file the segments came from (a TetGen `.edge` beside its `.node`), and the
    /// source line of each (0 where the format has none).
    pub segment_file: PathBuf,
    /// See [`Input::segment_file`].
    pub segment_lines: Vec<u32>,
    /// The file the points came from.
    pub point_file: PathBuf,
    /// The file the tetrahedra came from, and the source line of each (empty where the
    /// format has no lines, as JSON).
    pub tet_file: PathBuf,
    /// See [`Input::tet_file`].
    pub tet_lines: Vec<u32>,
    /// Cells the format carried besides tetrahedra, triangles, lines and points
    /// (hexahedra, prisms, pyramids, quadrilaterals, higher orders): [`read_input`] refuses
    /// them with this error, [`read_input_with`] and [`ReadOptions::tets_only`] keep it
    /// here and read the rest.
    pub other_cells: Option<OtherCells>,
    /// The region of each tetrahedron where the format has them (Gmsh's physical or
    /// entity tags); empty otherwise.
    pub regions: Vec<i64>,
    /// The file's own number of each tetrahedron where it is not `k + index_base` (a
    /// `.ele` numbered with gaps, or from another base than its `.node`); empty otherwise.
    /// See [`Input::tet_label`].
    pub tet_labels: Vec<u32>,
    /// The pieces of a partitioned mesh (a `.pvtu`'s files, or the `Piece`s of a
    /// `.vtu`), in order, each with its first tetrahedron; empty for other formats.
    pub pieces: Vec<Piece>,
    /// Points of a partitioned mesh that share a global id with a point of an earlier
    /// piece but not its coordinates (an interface written differently by two pieces).
    pub id_mismatches: Vec<IdMismatch>,
}

/// Two points of a partitioned mesh with one global id (`GlobalNodeIds`) at different
/// coordinates: kept apart, and a problem for `check`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct IdMismatch {
    /// The global id.
    pub id: i64,
    /// The point of the earlier piece.
    pub first: u32,
    /// The point of the later piece.
    pub second: u32,
    /// The later piece.
    pub piece: u32,
}

impl IdMismatch {
    /// The problem it is, its points at `first` and `second`.
    pub fn problem(&self, first: Point3, second: Point3) -> crate::mesh::Problem {
        let at = |[x, y, z]: Point3| format!("[{x:?}, {y:?}, {z:?}]");
        let detail = format!(
            "global id {} names #{} at {} and #{} (piece {}) at {}: the pieces disagree on an interface vertex",
            self.id,
            self.first,
            at(first),
            self.second,
            self.piece,
            at(second)
        );
        let kind = crate::mesh::ProblemKind::InterfaceMismatch;
        crate::mesh::Problem::new(kind, Vec::new(), vec![self.first, self.second], detail)
    }
}

/// One piece of a partitioned mesh: its file, and where its tetrahedra start among
/// [`Input::tets`].
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Piece {
    /// The file the piece was read from.
    pub file: PathBuf,
    /// Its first tetrahedron's index in [`Input::tets`].
    pub first_tet: u32,
    /// Gmsh's tag of the partition, for a partitioned `.msh` (its pieces are in one file).
    pub partition: Option<i64>,
}

/// Cells a reader found but does not keep: how many, and where the first is.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct OtherCells {
    /// How many cells in all.
    pub count: usize,
    /// The line of the first (0 where the format has none).
    pub line: usize,
    /// What they are, with their counts by kind, as the error says it.
    pub message: String,
}

/// How [`read_input_with`] treats what it cannot keep.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ReadOptions {
    /// Read a mixed mesh's tetrahedra (and triangles and lines) alone, the other cells
    /// counted in [`Input::other_cells`] instead of refused.
    pub tets_only: bool,
    /// The input is a tetrahedral mesh to be checked: where it has tetrahedra, only they
    /// matter. Points no tetrahedron uses may coincide with others, and coincident
    /// tetrahedron vertices are left to [`crate::mesh::verify`], which names them (a
    /// non-conforming assembly is a NO, not a bad file); segments and triangles, which
    /// Gmsh lists once per physical group and writes degenerate for closed curves, are
    /// kept as read, unchecked.
    pub mesh: bool,
}

impl Input {
    /// The number the file gives point `k` (`k + index_base` unless the file numbers its
    /// points otherwise).
    pub fn point_label(&self, k: usize) -> u32 {
        match self.point_labels.get(k) {
            Some(&l) => l,
            None => k as u32 + self.index_base,
        }
    }

    /// Where point `k` was read, for messages: `line L` or `point P` (the file's
    /// number).
    fn point_origin(&self, k: usize) -> (usize, String) {
        match self.point_lines.get(k) {
            Some(&l) if l > 0 => (l, format!("point {}", self.point_label(k))),
            _ => (0, format!("point {}", self.point_label(k))),
        }
    }

    /// The number the file gives tetrahedron `k` (`k + index_base` unless the file
    /// numbers its tetrahedra otherwise).
    pub fn tet_label(&self, k: usize) -> u32 {
        match self.tet_labels.get(k) {
            Some(&l) => l,
            None => k as u32 + self.index_base,
        }
    }

    /// Where tetrahedron `k` was read, for messages: `file:line` or `file` (`tets[k]`);
    /// in a partitioned mesh, the piece's file.
    pub fn tet_origin(&self, k: usize) -> String {
        let file = match self.tet_piece(k) {
            Some((p, _)) => self.pieces[p].file.display(),
            None => self.tet_file.display(),
        };
        match self.tet_lines.get(k) {
            Some(&line) if line > 0 => format!("{file}:{line}"),
            _ => format!("{file}: tets[{k}]"),
        }
    }

    /// The problems of [`Input::id_mismatches`], for [`crate::mesh::CheckOutcome::with_problems`].
    pub fn interface_problems(&self) -> Vec<crate::mesh::Problem> {
        let at = |k: u32| self.points[k as usize];
        (self.id_mismatches.iter())
            .map(|m| m.problem(at(m.first), at(m.second)))
            .collect()
    }

    /// In a partitioned mesh, the piece of tetrahedron `k` and its 0-based index among
    /// that piece's tetrahedra.
    pub fn tet_piece(&self, k: usize) -> Option<(usize, u32)> {
        let p = self
            .pieces
            .partition_point(|p| p.first_tet as usize <= k)
            .checked_sub(1)?;
        Some((p, k as u32 - self.pieces[p].first_tet))
    }
}

/// The piece files of the `.pvtu` at `path`, in order, each a file inside its folder
/// (an index naming another is an error at its line).
pub(crate) fn pvtu_pieces(path: &Path) -> Result<Vec<PathBuf>, InputError> {
    pvtu::piece_files(path)
}

/// Reads several files as the pieces of one partitioned mesh, as a `.pvtu`'s are read:
/// `.vtu` pieces, or Gmsh's `-part_split` files (`mesh_1.msh`, …; nodes merged by tag,
/// vertices and tetrahedra named by their node and element tags), or other meshes
/// (merged by exact coordinates).
pub fn read_files(files: &[PathBuf], opts: ReadOptions) -> Result<Input, InputError> {
    match files {
        [] => Err(InputError::new(Path::new(""), 0, "no input file")),
        [one] => read_input_with(one, opts),
        _ => accepted(&files[0], vtu::read_files(files, opts)?, opts),
    }
}

/// A piece of a partitioned mesh as read: its mesh, and its points' global ids where it
/// has them.
pub(crate) type PieceRead = (Input, Option<Vec<i64>>);

/// Reads the pieces of one piece file of a partitioned mesh (a `.vtu`), each `Piece`
/// apart, and accepts each as [`read_input_with`] does: its mesh, and each point's
/// global id (`GlobalNodeIds` or `GlobalPointIds`) where every point has one. A `.pvtu`
/// whose files hold several `Piece`s has that many pieces, numbered across its files
/// in order, as [`read_input`] numbers them.
pub(crate) fn read_pieces(path: &Path, opts: ReadOptions) -> Result<Vec<PieceRead>, InputError> {
    let pieces = vtu::read_pieces(path)?;
    for (input, _) in &pieces {
        // A piece alone may hold no tetrahedron (an empty partition): its points are
        // only required to be ones the predicates take.
        check_coordinates(input)?;
        only_tets(path, input, opts)?;
    }
    Ok(pieces)
}

/// Reads `path`, choosing the format by extension: `.node` (with sibling `.edge`, `.ele`
/// and `.face` when present), `.edge`/`.ele`/`.face` (with the sibling `.node`), `.obj`,
/// `.off`, `.stl` (ASCII or binary, corners merged by exact coordinates), `.mesh` (Medit), `.msh` (Gmsh 2.2 and 4.1 ASCII, 4.1 binary), `.vtk` (legacy, ASCII or binary), `.vtu` (VTK XML: ASCII, base64, appended raw or base64, zlib),
/// `.json`, `.xyz`/`.txt`.
///
/// ```
/// let dir = std::env::temp_dir().join("tetrakit-doc-read");
/// std::fs::create_dir_all(&dir).unwrap();
/// std::fs::write(dir.join("t.node"), "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n").unwrap();
/// std::fs::write(dir.join("t.edge"), "1 0\n1 1 2\n").unwrap();
/// let input = tetrakit::io::read_input(&dir.join("t.edge")).unwrap();
/// assert_eq!((input.points.len(), input.segments[0], input.index_base), (4, [0, 1], 1));
/// std::fs::write(dir.join("bad.xyz"), "0 0 0\n1 x 0\n").unwrap();
/// let err = tetrakit::io::read_input(&dir.join("bad.xyz")).unwrap_err();
/// assert_eq!(err.line, 2);
/// ```
pub fn read_input(path: &Path) -> Result<Input, InputError> {
    read_input_with(path, ReadOptions::default())
}

/// [`read_input`], with a mixed mesh read for its tetrahedra alone when
/// `opts.tets_only` (the other cells in [`Input::other_cells`]).
///
/// ```
/// use tetrakit::io::{ReadOptions, read_input, read_input_with};
/// let dir = std::env::temp_dir().join("tetrakit-doc-mixed");
/// std::fs::create_dir_all(&dir).unwrap();
/// let mesh = "MeshVersionFormatted 2\nDimension 3\nVertices\n5\n0 0 0 1\n1 0 0 1\n0 1 0 1\n0 0 1 1\n1 1 1 1\nTetrahedra\n1\n1 2 3 4 0\nPyramids\n1\n1 2 3 4 5 0\nEnd\n";
/// std::fs::write(dir.join("m.mesh"), mesh).unwrap();
/// let e = read_input(&dir.join("m.mesh")).unwrap_err();
/// assert!(e.message.starts_with("1 pyramids besides tetrahedra"), "{e}");
/// let opts = ReadOptions { tets_only: true, ..Default::default() };
/// let m = read_input_with(&dir.join("m.mesh"), opts).unwrap();
/// assert_eq!((m.tets.len(), m.other_cells.unwrap().count), (1, 1));
/// ```
pub fn read_input_with(path: &Path, opts: ReadOptions) -> Result<Input, InputError> {
    accepted(path, read_any(path)?, opts)
}

/// `input` read from `path`, once its coordinates are ones the predicates take and
/// (unless `tets_only`) it holds no other cells.
fn accepted(path: &Path, input: Input, opts: ReadOptions) -> Result<Input, InputError> {
    validate(&input, opts)?;
    only_tets(path, &input, opts)?;
    Ok(input)
}

/// Other cells than tetrahedra are an error unless `tets_only`.
fn only_tets(path: &Path, input: &Input, opts: ReadOptions) -> Result<(), InputError> {
    match (&input.other_cells, opts.tets_only) {
        (Some(o), false) => {
            let why = format!("{} (--tets-only reads the tetrahedra alone)", o.message);
            Err(InputError::new(path, o.line, why))
        }
        _ => Ok(()),
    }
}

/// The size from which the checks of [`validate`] run on every core: below it, waking
/// the other threads costs more than they save (reading 10^3 points took twice as long).
const PARALLEL_FROM: usize = 1 << 14;

/// The checks every input passes, whatever read it, so that no reader can skip them:
/// every coordinate finite and in the range where the predicates are exact, then
/// (unless a mesh is read for its tetrahedra alone, see [`ReadOptions::mesh`]) no
/// segment repeated or a loop, and no two points equal.
fn validate(input: &Input, opts: ReadOptions) -> Result<(), InputError> {
    check_coordinates(input)?;
    if opts.mesh && !input.tets.is_empty() {
        return Ok(());
    }
    let file = match input.segment_file.as_os_str().is_empty() {
        true => &input.point_file,
        false => &input.segment_file,
    };
    check_segments(
        &input.segments,
        &input.segment_lines,
        &|v| input.point_label(v as usize),
        file,
    )?;
    check_distinct_points(input)
}

/// Every coordinate finite and within [`coordinate_in_range`]; the error names the first
/// point outside by the file's number and line.
fn check_coordinates(input: &Input) -> Result<(), InputError> {
    let bad = (input.points.par_iter().with_min_len(PARALLEL_FROM))
        .position_first(|p| !p.iter().all(|&x| coordinate_in_range(x)));
    let Some(k) = bad else { return Ok(()) };
    let x = input.points[k]
        .into_iter()
        .find(|&x| !coordinate_in_range(x))
        .unwrap_or(f64::NAN);
    let (line, name) = input.point_origin(k);
    Err(InputError::new(
        &input.point_file,
        line,
        format!(
            "{name} has coordinate {x:e}, which is not finite or outside the exactly supported magnitude range [2^-142, 2^201]"
        ),
    ))
}

fn read_any(path: &Path) -> Result<Input, InputError> {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .unwrap_or("")
        .to_ascii_lowercase();
    let mut input = match ext.as_str() {
        "node" | "edge" | "ele" | "face" => tetgen::read(path, &ext)?,
        "obj" => obj::read(path)?,
        "off" => off::read(path)?,
        "stl" => stl::read(path)?,
        "mesh" => medit::read(path)?,
        "vtk" => {
            let bytes = read_bytes(path)?;
            if vtk::is_binary(&bytes) {
                vtk_binary::read(path, &bytes)?
            } else {
                vtk::read(path, bytes)?
            }
        }
        "vtu" => vtu::read(path)?,
        "pvtu" => pvtu::read(path)?,
        "msh" if gmsh::is_binary(path) => gmsh_binary::read(path)?,
        "msh" => gmsh::read(path)?,
        "json" => json::read(path)?,
        "xyz" | "txt" => read_xyz(path)?,
        _ => {
            return Err(InputError::new(
                path,
                0,
                format!(
                    "unknown input format '.{ext}' (expected .node, .edge, .ele, .face, .obj, .off, .stl, .mesh, .msh, .vtk, .vtu, .pvtu, .json, .xyz or .txt)"
                ),
            ));
        }
    };
    if input.point_file.as_os_str().is_empty() {
        input.point_file = path.to_path_buf();
    }
    Ok(input)
}

/// Reads a polyhedron (`.off`, `.obj` with `f` lines, `.face` with its `.node`, or
/// `.json` with `"faces"`) and checks that it is a simple polyhedron; the error names the
/// faces and vertices in the file's numbering.
///
/// ```
/// let dir = std::env::temp_dir().join("tetrakit-doc-poly");
/// std::fs::create_dir_all(&dir).unwrap();
/// let off = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
/// std::fs::write(dir.join("t.off"), off).unwrap();
/// let (_, p) = tetrakit::io::read_polyhedron(&dir.join("t.off")).unwrap();
/// assert_eq!(p.faces.len(), 4);
/// std::fs::write(dir.join("open.off"), "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n").unwrap();
/// assert!(tetrakit::io::read_polyhedron(&dir.join("open.off")).is_err());
/// ```
pub fn read_polyhedron(path: &Path) -> Result<(Input, crate::mesh::Polyhedron), InputError> {
    let input = read_input(path)?;
    if input.faces.is_empty() {
        return Err(InputError::new(
            path,
            0,
            "no faces: a polyhedron needs triangles (.off, .obj 'f' lines, .face, or JSON \"faces\")",
        ));
    }
    let poly =
        crate::mesh::Polyhedron::new(input.points.clone(), input.faces.clone()).map_err(|e| {
            InputError::new(
                path,
                0,
                format!("not a simple polyhedron: {}", e.describe(input.index_base)),
            )
        })?;
    Ok((input, poly))
}

/// The largest input file read (bytes): 4 GiB, about 40 million points as text.
pub const MAX_INPUT_BYTES: u64 = 4 << 30;

/// The bytes of a regular file of at most [`MAX_INPUT_BYTES`].
pub(crate) fn read_bytes(path: &Path) -> Result<Vec<u8>, InputError> {
    let cannot = |e: std::io::Error| InputError::new(path, 0, format!("cannot read: {e}"));
    let meta = std::fs::metadata(path).map_err(cannot)?;
    if !meta.is_file() {
        return Err(InputError::new(path, 0, "not a regular file"));
    }
    if meta.len() > MAX_INPUT_BYTES {
        return Err(InputError::new(
            path,
            0,
            format!(
                "{} bytes: larger than the {} GiB input limit",
                meta.len(),
                MAX_INPUT_BYTES >> 30
            ),
        ));
    }
    std::fs::read(path).map_err(cannot)
}

/// Reads a text input: a regular file (not a FIFO or a device, which could be read
/// forever) of at most [`MAX_INPUT_BYTES`], UTF-8, a leading byte-order mark dropped.
/// Line ends may be LF or CR LF; a file whose only line ends are CR is refused by name.
pub(crate) fn read_text(path: &Path) -> Result<String, InputError> {
    text_of(path, read_bytes(path)?)
}

/// [`read_text`] on bytes already read.
pub(crate) fn text_of(path: &Path, bytes: Vec<u8>) -> Result<String, InputError> {
    let mut text = String::from_utf8(bytes).map_err(|e| {
        let at = e.utf8_error().valid_up_to();
        let line = 1 + e.as_bytes()[..at].iter().filter(|&&b| b == b'\n').count();
        InputError::new(
            path,
            line,
            "not UTF-8 text (a binary file, or another encoding)",
        )
    })?;
    if text.starts_with('\u{feff}') {
        text.drain(..3);
    }
    if !text.contains('\n') && text.trim_end_matches('\r').contains('\r') {
        return Err(InputError::new(
            path,
            0,
            "lines end in CR alone (classic Mac line ends): convert them to LF or CR LF",
        ));
    }
    Ok(text)
}

/// Parses a coordinate, rejecting decimals that round to 0 although their digits are not
/// all 0 (`1e-400`), which the range check on the points ([`validate`]) can no longer
/// see.
pub(crate) fn parse_coord(tok: &str, path: &Path, line: usize) -> Result<f64, InputError> {
    let x: f64 = tok
        .parse()
        .map_err(|_| InputError::new(path, line, format!("{} is not a number", quote(tok))))?;
    if x == 0.0 && has_nonzero_digits(tok) {
        return Err(InputError::new(
            path,
            line,
            format!(
                "coordinate {} is below the exactly supported magnitude range [2^-142, 2^201] (it would round to 0)",
                quote(tok)
            ),
        ));
    }
    Ok(x)
}

/// True when the decimal `tok` has a nonzero digit before its exponent: a number that is
/// not 0, whatever it rounds to.
fn has_nonzero_digits(tok: &str) -> bool {
    let mantissa = tok.split(['e', 'E']).next().unwrap_or("");
    mantissa.bytes().any(|b| (b'1'..=b'9').contains(&b))
}

/// Parses a coordinate of an array declared single precision (VTK `Float32`, legacy
/// `float`): the number every other reader of the file (VTK, ParaView, meshio) holds is
/// the decimal rounded to `f32`, so that is the point; a decimal whose digits are not all
/// 0 but that rounds to 0 or past the `f32` range is refused (as [`parse_coord`] refuses
/// it in double precision).
pub(crate) fn parse_coord32(tok: &str) -> Result<f64, String> {
    let x: f32 = tok
        .parse()
        .map_err(|_| format!("{} is not a number", quote(tok)))?;
    let word = tok.trim_start_matches(['+', '-']).to_ascii_lowercase();
    let named = word.starts_with("inf") || word.starts_with("nan");
    if (x == 0.0 && has_nonzero_digits(tok)) || (x.is_infinite() && !named) {
        return Err(format!(
            "coordinate {} is outside the single-precision range of its Float32 array",
            quote(tok)
        ));
    }
    Ok(f64::from(x))
}

/// Parses an index token as an integer.
pub(crate) fn parse_int(
    tok: &str,
    path: &Path,
    line: usize,
    what: &str,
) -> Result<i64, InputError> {
    tok.parse().map_err(|_| {
        InputError::new(
            path,
            line,
            format!("{what} {} is not an integer", quote(tok)),
        )
    })
}

/// Converts a file's vertex reference to a 0-based index, checking the range.
pub(crate) fn vertex_ref(
    raw: i64,
    base: u32,
    n: usize,
    path: &Path,
    line: usize,
) -> Result<u32, InputError> {
    let i = raw - base as i64;
    if i < 0 || i as usize >= n {
        let hi = n as i64 - 1 + base as i64;
        return Err(InputError::new(
            path,
            line,
            format!("vertex {raw} is out of range (points are numbered {base}..={hi})"),
        ));
    }
    Ok(i as u32)
}

/// Rejects self-loops and repeated segments. `lines[k]` is the source line of segment `k`,
/// or 0 (or missing) for formats without lines (then segments are named by their position). Repeats are
/// found per vertex (small sorts), not by sorting all segments.
fn check_segments(
    segs: &[[u32; 2]],
    lines: &[u32],
    label: &(dyn Fn(u32) -> u32 + Sync),
    path: &Path,
) -> Result<(), InputError> {
    let at = |k: usize| -> (usize, String) {
        match lines.get(k).copied().unwrap_or(0) {
            0 => (0, format!("segments[{k}]")),
            l => (l as usize, format!("line {l}")),
        }
    };
    let segments = || segs.par_iter().with_min_len(PARALLEL_FROM);
    if let Some(k) = segments().position_first(|s| s[0] == s[1]) {
        let (line, name) = at(k);
        return Err(InputError::new(
            path,
            line,
            format!(
                "segment {name} joins vertex {} to itself",
                label(segs[k][0])
            ),
        ));
    }
    let n = segments()
        .map(|s| s[0].max(s[1]) as usize + 1)
        .max()
        .unwrap_or(0);
    // Each segment as (larger end, position) in the row of its smaller end.
    let (start, mut rows) = crate::rows::group(n, segs.len(), |k| {
        let s = segs[k];
        [(s[0].min(s[1]) as usize, (s[0].max(s[1]), k as u32))]
    });
    crate::rows::for_each_row(&mut rows, &start, |_, bucket| bucket.sort_unstable());
    // The repeat whose second listing comes first.
    let first = (0..n)
        .into_par_iter()
        .with_min_len(PARALLEL_FROM)
        .filter_map(|lo| {
            rows[start[lo]..start[lo + 1]]
                .windows(2)
                .filter(|w| w[0].0 == w[1].0)
                .map(|w| (w[1].1, w[0].1, lo as u32))
                .min()
        })
        .min()
        .map(|(k2, k1, lo)| (lo, k1, k2));
    if let Some((lo, k1, k2)) = first {
        let (s, (line, name2)) = (segs[k2 as usize], at(k2 as usize));
        let hi = s[0].max(s[1]);
        return Err(InputError::new(
            path,
            line,
            format!(
                "segment ({}, {}) is listed twice ({} and {name2})",
                label(lo),
                label(hi),
                at(k1 as usize).1
            ),
        ));
    }
    Ok(())
}

/// Points and 0-based index rows as an array library holds them (numpy, JSON), before
/// any check: see [`from_arrays`].
#[derive(Clone, Debug, Default)]
pub struct Arrays<'a> {
    /// The points (`z = 0` for planar ones).
    pub points: Vec<Point3>,
    /// 2 for planar points, 3 otherwise.
    pub dim: usize,
    /// Segments: two point indices each.
    pub segments: &'a [[i64; 2]],
    /// Triangles.
    pub faces: &'a [[i64; 3]],
    /// Tetrahedra.
    pub tets: &'a [[i64; 4]],
    /// A mesh to check: see [`ReadOptions::mesh`].
    pub mesh: bool,
}

/// An [`Input`] from arrays, with the checks every reader makes: at least one point,
/// every coordinate in the exactly supported range, every index naming a point, no
/// segment listed twice, no two points equal. `source` names the arrays in errors, whose
/// `line` is 0 and whose message names the row (`tets[3] names vertex 12, ...`).
///
/// ```
/// use std::path::Path;
/// use tetrakit::io::{Arrays, from_arrays};
/// let points = vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let tets = [[0, 1, 2, 3]];
/// let a = Arrays { points: points.clone(), dim: 3, tets: &tets, ..Default::default() };
/// assert_eq!(from_arrays(Path::new("mesh"), a).unwrap().tets, vec![[0, 1, 2, 3]]);
/// let bad = [[0, 1, 2, 4]];
/// let a = Arrays { points, dim: 3, tets: &bad, ..Default::default() };
/// let e = from_arrays(Path::new("mesh"), a).unwrap_err();
/// assert_eq!(e.message, "tets[0] names vertex 4, but points are numbered 0..=3");
/// ```
pub fn from_arrays(source: &Path, a: Arrays<'_>) -> Result<Input, InputError> {
    let opts = ReadOptions {
        mesh: a.mesh,
        ..Default::default()
    };
    let input = arrays_input(source, a)?;
    validate(&input, opts)?;
    Ok(input)
}

/// The [`Input`] of arrays, every index checked, nothing else (see [`validate`]).
pub(super) fn arrays_input(source: &Path, a: Arrays<'_>) -> Result<Input, InputError> {
    if a.points.is_empty() {
        return Err(InputError::new(source, 0, "no points"));
    }
    let n = a.points.len();
    Ok(Input {
        segments: index_rows(a.segments, n, "segments", source)?,
        faces: index_rows(a.faces, n, "faces", source)?,
        tets: index_rows(a.tets, n, "tets", source)?,
        points: a.points,
        dim: a.dim,
        point_file: source.to_path_buf(),
        tet_file: source.to_path_buf(),
        ..Default::default()
    })
}

/// 0-based index rows checked against `n` points.
fn index_rows<const K: usize>(
    rows: &[[i64; K]],
    n: usize,
    field: &str,
    source: &Path,
) -> Result<Vec<[u32; K]>, InputError> {
    let check = |k: usize, v: i64| {
        u32::try_from(v)
            .ok()
            .filter(|&v| (v as usize) < n)
            .ok_or_else(|| {
                let msg = format!(
                    "{field}[{k}] names vertex {v}, but points are numbered 0..={}",
                    n - 1
                );
                InputError::new(source, 0, msg)
            })
    };
    rows.iter()
        .enumerate()
        .map(|(k, r)| {
            let mut out = [0u32; K];
            for (o, &v) in out.iter_mut().zip(r) {
                *o = check(k, v)?;
            }
            Ok(out)
        })
        .collect()
}

fn check_distinct_points(input: &Input) -> Result<(), InputError> {
    match coincident_pair(&input.points) {
        None => Ok(()),
        Some((a, b)) => {
            let (line, _) = input.point_origin(b);
            let first = match input.point_origin(a).0 {
                0 => String::new(),
                l => format!(" (line {l})"),
            };
            Err(InputError::new(
                &input.point_file,
                line,
                format!(
                    "points {} and {} coincide at {:?}{first}",
                    input.point_label(a),
                    input.point_label(b),
                    input.points[a],
                ),
            ))
        }
    }
}

/// Two equal points `(a, b)`, `a < b`, if any (the first pair in lexicographic order).
fn coincident_pair(pts: &[Point3]) -> Option<(usize, usize)> {
    let mut order: Vec<u32> = (0..pts.len() as u32).collect();
    let lex = |&a: &u32, &b: &u32| lex_cmp(&pts[a as usize], &pts[b as usize]);
    match pts.len() < PARALLEL_FROM {
        true => order.sort_unstable_by(lex),
        false => order.par_sort_unstable_by(lex),
    }
    order.windows(2).find_map(|w| {
        let (a, b) = (w[0].min(w[1]) as usize, w[0].max(w[1]) as usize);
        (pts[a] == pts[b]).then_some((a, b))
    })
}

/// Meaningful lines of a text file: (1-based line number, tokens), comments after `#`
/// and blank lines skipped.
pub(crate) fn token_lines(text: &str) -> impl Iterator<Item = (usize, Tokens<'_>)> {
    text.lines().enumerate().filter_map(|(i, l)| {
        let l = l.split('#').next().unwrap_or("");
        let toks = Tokens::new(l);
        (!toks.is_empty()).then_some((i + 1, toks))
    })
}

/// The tokens of one line, separated by ASCII whitespace (as TetGen and the other
/// formats' readers separate them), kept inline (no allocation) up to 24 of them.
pub(crate) struct Tokens<'a> {
    inline: [&'a str; 24],
    len: usize,
    heap: Vec<&'a str>,
}

impl<'a> Tokens<'a> {
    fn new(line: &'a str) -> Self {
        let mut t = Tokens {
            inline: [""; 24],
            len: 0,
            heap: Vec::new(),
        };
        for tok in line.split_ascii_whitespace() {
            if t.len < 24 {
                t.inline[t.len] = tok;
            } else {
                if t.heap.is_empty() {
                    t.heap.extend_from_slice(&t.inline);
                }
                t.heap.push(tok);
            }
            t.len += 1;
        }
        t
    }
}

impl<'a> std::ops::Deref for Tokens<'a> {
    type Target = [&'a str];
    fn deref(&self) -> &[&'a str] {
        if self.heap.is_empty() {
            &self.inline[..self.len]
        } else {
            &self.heap
        }
    }
}

fn read_xyz(path: &Path) -> Result<Input, InputError> {
    let text = read_text(path)?;
    let mut input = Input {
        dim: 3,
        point_file: path.to_path_buf(),
        ..Default::default()
    };
    let mut dim = None;
    for (line, toks) in token_lines(&text) {
        let d = *dim.get_or_insert(toks.len());
        if !(2..=3).contains(&toks.len()) || toks.len() != d {
            return Err(InputError::new(
                path,
                line,
                format!(
                    "expected {} coordinates, found {}",
                    if (2..=3).contains(&d) { d } else { 3 },
                    toks.len()
                ),
            ));
        }
        let mut p = [0.0; 3];
        for (k, t) in toks.iter().enumerate() {
            p[k] = parse_coord(t, path, line)?;
        }
        input.points.push(p);
        input.point_lines.push(line);
    }
    if input.points.is_empty() {
        return Err(InputError::new(path, 0, "no points"));
    }
    input.dim = dim.unwrap_or(3);
    Ok(input)
}

#[cfg(test)]
mod tests;
