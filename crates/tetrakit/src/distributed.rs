//! The check of a partitioned mesh (`.pvtu`) by several processes that each read only
//! their pieces: one process's side of it ([`RankCheck`]), a sequence of all-to-all
//! exchanges of byte messages that any transport carries (MPI's `alltoall` under
//! `python3 -m tetrakit.mpi`; [`check_in_ranks`] in memory). Its outcome, on rank 0, is
//! the outcome `tetrakit check X.pvtu` prints ([`crate::mesh::check_pieces`] on the merged
//! mesh), problem for problem.
//!
//! The `.pvtu`'s file `f` is read by rank `f mod K`; each `Piece` in it is a piece,
//! numbered across the files in order as `tetrakit check` numbers them. The rounds:
//! 1. every rank sends every piece's point counts, and each of its points (its global
//!    id, or its exact coordinates) to the point's *key owner* (a hash of the key);
//! 2. a key owner numbers each point as the merged reader does: the first occurrence (by
//!    piece, then index) is the vertex, numbered by its place among all the pieces'
//!    points; a later piece's point with that key is that vertex (with global ids: if its
//!    coordinates agree, else an `interface_mismatch`); a vertex that several pieces use
//!    is on an interface and is owned by the key owner's layer;
//! 3. each rank builds one part per piece (as [`crate::mesh::check_pieces`] does) and
//!    sends every tetrahedron around an interface vertex (a ghost) to the vertex's
//!    owner, and its points to the owner of their coordinates (coincident and unused
//!    vertices);
//! 4. each rank checks its parts' faces and edges (the owner's layer of ghosts is one
//!    more part) and sends what they decide to rank 0, with the count of its boundary
//!    faces, their box and their components (faces joined across edges: each one's
//!    first face, the first vertex of it and its place); the boundary faces themselves
//!    only with `convex`, for the hull test. Each boundary edge goes with its component
//!    to the edge's owner (a hash of it);
//! 5. each edge owner sends rank 0 the pairs of components that share an edge; rank 0
//!    puts the problems in the merged check's order and, where the embedding checks are
//!    due, sends every rank a grid over the boundary's box (about one cell per face,
//!    each cell owned by a rank);
//! 6. every rank runs the cone tests of the vertices it owns (to rank 0) and sends each
//!    of its boundary faces, with its corners, to the owners of the cells its box meets;
//!    rank 0 joins the components and sends every rank one vertex of each component of
//!    the whole boundary (the first vertex of its first face, as the merged check picks
//!    it);
//! 7. each rank tests the faces it received pairwise and keeps the pairs whose boxes'
//!    intersection starts in a cell it owns (so each pair is decided once, by a rank
//!    that has both faces), and looks for those vertices in its pieces' tetrahedra (the
//!    nesting test); the first 100 pairs in the merged check's order and the hits go to
//!    rank 0, which merges them and finishes.
//!
//! Memory per rank: its pieces, its parts (each piece's tetrahedra again, compacted),
//! its layer (the ghosts), the boundary faces of its cells and the boundary edges it
//! owns; rank 0 also holds each rank's components and the pairs that join them (every
//! boundary face with its corners with `convex`). A vertex number in the
//! problems is its place among all pieces' points (piece 0's first), as `tetrakit check`
//! numbers a `.pvtu`'s vertices.

use crate::geom::{Hull3, Point3, lex_cmp, point_key};
use crate::io::{self, IdMismatch, Input, InputError, Piece};
use crate::mesh::{
    self, BoundaryFace, CheckOptions, CheckOutcome, Part, PartFaces, Problem, Report,
};
use serde::{Deserialize, Serialize, de::DeserializeOwned};
use std::path::{Path, PathBuf};

/// How many exchanges a check takes (all ranks take part in each); one more with an
/// output ([`RankCheck::with_output`]).
pub(crate) const ROUNDS: usize = 7;

/// One process's side of a partitioned check: [`start`](Self::start), then
/// [`step`](Self::step) with what every rank sent it until it returns `None`; then
/// [`outcome`](Self::outcome) on rank 0.
#[derive(Default)]
pub struct RankCheck {
    rank: usize,
    size: usize,
    opts: CheckOptions,
    tets_only: bool,
    index: PathBuf,
    files: Vec<PathBuf>,
    round: usize,
    mine: Vec<Local>,
    pieces: Vec<Info>,
    failure: Option<InputError>,
    parts: Vec<Part>,
    on_boundary: Vec<Vec<bool>>,
    mismatches: Vec<Problem>,
    /// This rank's pieces' vertices (each first seen there) and tetrahedra turned.
    vertices: u32,
    reoriented: u32,
    /// Rank 0: the totals gathered, then the outcome.
    gathered: Gathered,
    hull_points: Vec<(Point3, u32)>,
    report: Report,
    /// Rank 0 with `convex`: the boundary faces with their corners.
    boundary: Vec<([u32; 3], u32, [Point3; 3])>,
    /// This rank's boundary faces (those its parts decide), with their corners.
    mine_boundary: Vec<Face>,
    /// Rank 0: the components of every rank's boundary faces (round 5), and the pairs
    /// of them that share an edge (rounds 5 and 6).
    components: Vec<Vec<Component>>,
    joined: Vec<(ComponentId, ComponentId)>,
    /// Rank 0: what the cone tests found on every rank (round 6).
    overlaps: Vec<Problem>,
    /// The cells of the self-intersection test, when it runs.
    grid: Option<Grid>,
    reps: Vec<(u32, u32, Point3)>,
    embedding: bool,
    outcome: Option<CheckOutcome>,
    /// Where the pieces are written with their problem fields (`--output P.pvtu`).
    output: Option<PathBuf>,
    /// Rank 0: the problems that mark cells and points, in the order they mark them.
    marks: Vec<Problem>,
    /// Bytes this rank sent, all rounds.
    pub bytes_sent: usize,
}

/// A piece this rank read.
struct Local {
    /// Its file and its place in it; its number among all pieces (known from round 2).
    file: u32,
    sub: u32,
    piece: u32,
    input: Input,
    /// Each point's vertex number, and whether it is on an interface and who owns it.
    labels: Vec<u32>,
    shared: Vec<bool>,
    owner: Vec<u32>,
}

#[derive(Clone, Debug, Default, Serialize, Deserialize)]
struct Info {
    /// Its file, and its place among the file's pieces.
    file: u32,
    sub: u32,
    points: u32,
    tets: u32,
    other_cells: u32,
    ids: bool,
}

#[derive(Default, Serialize, Deserialize)]
struct Hello {
    failure: Option<(u32, InputError)>,
    pieces: Vec<Info>,
    keys: Vec<Occurrence>,
}

#[derive(Clone, Copy, Serialize, Deserialize)]
struct Occurrence {
    key: [u64; 3],
    /// The piece's file and place in it (in the order of the pieces' numbers).
    file: u32,
    sub: u32,
    index: u32,
    at: Point3,
}

#[derive(Clone, Copy, Serialize, Deserialize)]
struct Label {
    piece: u32,
    index: u32,
    label: u32,
    shared: bool,
}

#[derive(Clone, Copy, Serialize, Deserialize)]
struct Ghost {
    label: u32,
    v: [u32; 4],
    at: [Point3; 4],
    owned: u8,
}

#[derive(Default, Serialize, Deserialize)]
struct Spread {
    ghosts: Vec<Ghost>,
    /// `(place, vertex, first tetrahedron or u32::MAX)`, to the owner of the place.
    points: Vec<(Point3, u32, u32)>,
    /// To rank 0 with `convex`: points on the hull of this rank's pieces.
    hull: Vec<(Point3, u32)>,
}

#[derive(Default, Serialize, Deserialize)]
struct Gathered {
    faces: Vec<PartFaces>,
    /// How many boundary faces this rank's parts decide.
    boundary_faces: u32,
    /// The components of those faces joined across their edges (not with `convex`).
    components: Vec<Component>,
    /// The box of this rank's boundary faces.
    bbox: Option<(Point3, Point3)>,
    coincident: Vec<(Point3, Problem)>,
    unused: Vec<u32>,
    mismatches: Vec<Problem>,
    vertices: u32,
    reoriented: u32,
}

#[derive(Default, Serialize, Deserialize)]
struct Decision {
    embed: bool,
    /// The cells the boundary's self-intersection test is spread over.
    grid: Option<Grid>,
}

/// A component of one rank's boundary faces (joined across edges): its first face in
/// the merged check's order, that face's first vertex and tetrahedron, and the vertex's
/// place (a nesting test's representative, when the component is first in its
/// component of the whole boundary).
#[derive(Clone, Copy, Serialize, Deserialize)]
struct Component {
    key: [u32; 3],
    v: u32,
    tet: u32,
    at: Point3,
}

/// A rank's component: the rank, and the component's number there.
type ComponentId = (u32, u32);

/// Round 4's messages: to rank 0 what this rank's parts decided, and to the owner of
/// each boundary edge (a hash of it) the components of this rank that have it.
#[derive(Default, Serialize, Deserialize)]
struct Fourth {
    gathered: Option<Gathered>,
    edges: Vec<([u32; 2], ComponentId)>,
}

/// Round 5's messages: rank 0's decision to every rank, and to rank 0 the components
/// an edge owner found sharing an edge.
#[derive(Default, Serialize, Deserialize)]
struct Fifth {
    decision: Option<Decision>,
    joined: Vec<(ComponentId, ComponentId)>,
}

/// A boundary face: its vertices (outward), its tetrahedron, its corners.
#[derive(Clone, Copy, Serialize, Deserialize)]
struct Face {
    v: [u32; 3],
    tet: u32,
    at: [Point3; 3],
}

impl Face {
    /// Its place in the merged check's boundary order (its vertices sorted).
    fn key(&self) -> [u32; 3] {
        sorted(self.v)
    }

    fn bbox(&self) -> (Point3, Point3) {
        let [a, b, c] = &self.at;
        crate::mesh::grid::aabb(&[a, b, c])
    }
}

/// Round 6's messages: to rank 0 what the cone tests found, from rank 0 the nesting
/// test's representatives, to the owners of the cells a boundary face's box meets, the
/// face.
#[derive(Default, Serialize, Deserialize)]
struct Sixth {
    overlaps: Vec<Problem>,
    reps: Vec<(Point3, u32)>,
    faces: Vec<Face>,
}

/// Round 7's messages, to rank 0: the improper pairs this rank decides and where the
/// representatives lie in its parts.
#[derive(Default, Serialize, Deserialize)]
struct Seventh {
    pairs: Vec<(FaceId, FaceId)>,
    hits: Vec<Option<(u32, [u32; 4])>>,
}

/// A uniform grid over the boundary's box, about one cell per face: each cell is owned
/// by a rank (a hash of its index), and a pair of faces whose boxes meet is decided by
/// the owner of the cell that holds the low corner of the boxes' intersection, to whom
/// both faces were sent (the cell index is monotone in each coordinate).
#[derive(Clone, Copy, Default, Serialize, Deserialize)]
struct Grid {
    lo: Point3,
    h: f64,
    n: [u64; 3],
}

impl Grid {
    fn new((lo, hi): (Point3, Point3), faces: usize) -> Grid {
        let extent = (0..3).map(|i| hi[i] - lo[i]).fold(0.0, f64::max);
        let h = extent / (faces.max(1) as f64).cbrt().ceil();
        let h = if h.is_finite() && h > 0.0 { h } else { 1.0 };
        let n = std::array::from_fn(|i| ((hi[i] - lo[i]) / h).floor().max(0.0) as u64 + 1);
        Grid { lo, h, n }
    }

    fn index(&self, x: f64, i: usize) -> u64 {
        let k = ((x - self.lo[i]) / self.h).floor();
        match k >= 0.0 {
            true => (k as u64).min(self.n[i] - 1),
            false => 0,
        }
    }

    fn cell(&self, x: &Point3) -> [u64; 3] {
        std::array::from_fn(|i| self.index(x[i], i))
    }

    /// The ranks owning the cells `b` meets (every rank when they are many).
    fn owners(&self, b: &(Point3, Point3), size: usize) -> Vec<usize> {
        let (lo, hi) = (self.cell(&b.0), self.cell(&b.1));
        let cells: u64 = (0..3).map(|i| hi[i] - lo[i] + 1).product();
        if cells > 8 * size as u64 {
            return (0..size).collect();
        }
        let mut owners = Vec::new();
        for x in lo[0]..=hi[0] {
            for y in lo[1]..=hi[1] {
                for z in lo[2]..=hi[2] {
                    owners.push(owner_of(&[x, y, z], size));
                }
            }
        }
        owners.sort_unstable();
        owners.dedup();
        owners
    }
}

fn encode<T: Serialize>(x: &T) -> Vec<u8> {
    postcard::to_stdvec(x).expect("a message of this check encodes")
}

/// Our own ranks' messages (empty: nothing was sent). One that does not decode is a
/// bug, and a check that went on without it could miss a problem: it stops the process
/// (under `mpirun`, the whole job).
fn decode<T: DeserializeOwned + Default>(b: &[u8]) -> T {
    match b.is_empty() {
        true => T::default(),
        false => postcard::from_bytes(b).expect("a message of this check's ranks decodes"),
    }
}

/// The rank that owns a key.
fn owner_of(key: &[u64; 3], size: usize) -> usize {
    let mut h = 0x9e37_79b9_7f4a_7c15u64;
    for &k in key {
        h = (h ^ k).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        h ^= h >> 31;
    }
    (h % size as u64) as usize
}

impl Local {
    fn new(file: u32, sub: u32, input: Input) -> Self {
        let n = input.points.len();
        Local {
            file,
            sub,
            piece: u32::MAX,
            input,
            labels: vec![u32::MAX; n],
            shared: vec![false; n],
            owner: vec![0; n],
        }
    }
}

impl RankCheck {
    /// Rank `rank` of `size` checking the `.pvtu` at `index`; with `tets_only`, pieces
    /// with other cells are checked by their tetrahedra (else they are bad input).
    pub fn new(
        index: &Path,
        rank: usize,
        size: usize,
        opts: CheckOptions,
        tets_only: bool,
    ) -> Self {
        RankCheck {
            rank,
            size: size.max(1),
            opts,
            tets_only,
            index: index.to_path_buf(),
            ..Default::default()
        }
    }

    /// The check that also writes, as `tetrakit check X.pvtu --output P.pvtu` does, every
    /// piece with its problem fields: each rank writes its own pieces (`<stem>_<p>.vtu`
    /// beside `output`), rank 0 the index. One more round: rank 0 sends every rank the
    /// problems kept (at most [`Report::LIMIT`]), and the pieces as read are kept until
    /// then.
    pub fn with_output(mut self, output: &Path) -> Self {
        self.output = Some(output.to_path_buf());
        self
    }

    /// The first messages (one per rank): this rank reads its pieces.
    pub fn start(&mut self) -> Vec<Vec<u8>> {
        let mut hello = Hello::default();
        let mut keys: Vec<Vec<Occurrence>> = vec![Vec::new(); self.size];
        match io::pvtu_pieces(&self.index) {
            Err(e) => hello.failure = Some((0, e)),
            Ok(files) => self.files = files,
        }
        for f in (self.rank..self.files.len()).step_by(self.size) {
            let read = io::ReadOptions {
                mesh: true,
                tets_only: self.tets_only,
            };
            match io::read_pieces(&self.files[f], read) {
                Err(e) => {
                    hello.failure.get_or_insert((f as u32, e));
                }
                Ok(pieces) => {
                    for (sub, piece) in pieces.into_iter().enumerate() {
                        let at = (f as u32, sub as u32);
                        self.take(at, piece, &mut hello, &mut keys);
                    }
                }
            }
        }
        let out = keys
            .into_iter()
            .map(|keys| {
                let h = Hello {
                    failure: hello.failure.clone(),
                    pieces: hello.pieces.clone(),
                    keys,
                };
                encode(&h)
            })
            .collect();
        self.sent(out)
    }

    /// Piece `sub` of file `file`, read: each point to its key's owner, its facts to
    /// every rank, the piece kept.
    fn take(
        &mut self,
        (file, sub): (u32, u32),
        (input, ids): io::PieceRead,
        hello: &mut Hello,
        keys: &mut [Vec<Occurrence>],
    ) {
        for (i, at) in input.points.iter().enumerate() {
            let key = match &ids {
                Some(ids) => [ids[i] as u64, 0, 0],
                None => point_key(at),
            };
            let o = Occurrence {
                key,
                file,
                sub,
                index: i as u32,
                at: *at,
            };
            keys[owner_of(&key, self.size)].push(o);
        }
        hello.pieces.push(Info {
            file,
            sub,
            points: input.points.len() as u32,
            tets: input.tets.len() as u32,
            other_cells: (input.other_cells.as_ref()).map_or(0, |o| o.count as u32),
            ids: ids.is_some(),
        });
        self.mine.push(Local::new(file, sub, input));
    }

    fn sent(&mut self, out: Vec<Vec<u8>>) -> Vec<Vec<u8>> {
        self.bytes_sent += out.iter().map(Vec::len).sum::<usize>();
        self.round += 1;
        out
    }

    fn send_to_rank0<T: Serialize>(&mut self, x: &T) -> Vec<Vec<u8>> {
        let mut out = vec![Vec::new(); self.size];
        out[0] = encode(x);
        self.sent(out)
    }

    /// The next messages, given what every rank sent this one (`inbox[r]` from rank
    /// `r`); `None` when the check is over (on every rank in the same round).
    pub fn step(&mut self, inbox: &[&[u8]]) -> Option<Vec<Vec<u8>>> {
        if self.failure.is_some() || self.round > ROUNDS + usize::from(self.output.is_some()) {
            return None;
        }
        let out = match (self.round, &self.output) {
            (1, _) => self.number(inbox),
            (2, _) => self.spread(inbox),
            (3, _) => self.faces(inbox),
            (4, _) => self.decide(inbox),
            (5, _) => self.embed(inbox),
            (6, _) => self.pairs(inbox),
            (7, Some(_)) => {
                self.finish(inbox);
                let marks = std::mem::take(&mut self.marks);
                let out = vec![
                    if self.rank == 0 {
                        encode(&marks)
                    } else {
                        Vec::new()
                    };
                    self.size
                ];
                self.sent(out)
            }
            _ => {
                if self.round == 7 {
                    self.finish(inbox);
                } else {
                    self.write_pieces(inbox);
                }
                self.round = ROUNDS + 2;
                return None;
            }
        };
        if self.failure.is_some() {
            return None;
        }
        Some(out)
    }

    /// The error that stopped the check (every rank has it), as `file:line: problem`.
    pub fn failure(&self) -> Option<&InputError> {
        self.failure.as_ref()
    }

    /// Round 2: the pieces' table, and the vertex numbers of the keys this rank owns.
    fn number(&mut self, inbox: &[&[u8]]) -> Vec<Vec<u8>> {
        let hellos: Vec<Hello> = inbox.iter().map(|b| decode(b)).collect();
        let mut failures: Vec<(u32, InputError)> =
            hellos.iter().filter_map(|h| h.failure.clone()).collect();
        failures.sort_by_key(|f| f.0);
        let mut pieces: Vec<Info> = hellos.iter().flat_map(|h| h.pieces.clone()).collect();
        pieces.sort_by_key(|i| (i.file, i.sub));
        if failures.is_empty() {
            let with = pieces.iter().position(|i| i.ids);
            let without = pieces.iter().position(|i| !i.ids && i.points > 0);
            if let (Some(a), Some(b)) = (with, without) {
                let file = |k: usize| self.files[pieces[k].file as usize].display();
                let why = format!(
                    "piece {a} ({}) has global point ids but piece {b} ({}) has none: the pieces disagree in layout",
                    file(a),
                    file(b)
                );
                failures.push((0, InputError::new(&self.index, 0, why)));
            }
        }
        if let Some((_, why)) = failures.into_iter().next() {
            self.failure = Some(why);
            return Vec::new();
        }
        self.pieces = pieces;
        for m in &mut self.mine {
            m.piece = piece_of(&self.pieces, m.file, m.sub);
        }
        let offsets = self.point_offsets();
        let mut occ: Vec<Occurrence> = hellos.into_iter().flat_map(|h| h.keys).collect();
        occ.sort_by_key(|o| (o.key, o.file, o.sub, o.index));
        let ids = self.pieces.iter().any(|i| i.ids);
        let mut out: Vec<Vec<Label>> = vec![Vec::new(); self.size];
        let mut mismatches = Vec::new();
        for group in occ.chunk_by(|a, b| a.key == b.key) {
            let c = group[0];
            let piece = |o: &Occurrence| piece_of(&self.pieces, o.file, o.sub);
            let concat = |o: &Occurrence| offsets[piece(o) as usize] + o.index;
            let same_piece = |o: &Occurrence| (o.file, o.sub) == (c.file, c.sub);
            let new = |o: &Occurrence| same_piece(o) || (ids && o.at != c.at);
            let merged = group.iter().any(|o| !new(o));
            for o in group {
                let label = match new(o) {
                    true => concat(o),
                    false => concat(&c),
                };
                let shared = !new(o) || (concat(o) == concat(&c) && merged);
                if ids && new(o) && !same_piece(o) {
                    let m = IdMismatch {
                        id: c.key[0] as i64,
                        first: concat(&c),
                        second: concat(o),
                        piece: piece(o),
                    };
                    mismatches.push(m.problem(c.at, o.at));
                }
                let l = Label {
                    piece: piece(o),
                    index: o.index,
                    label,
                    shared,
                };
                out[o.file as usize % self.size].push(l);
            }
        }
        self.mismatches = mismatches;
        let out = out.iter().map(encode).collect();
        self.sent(out)
    }

    fn point_offsets(&self) -> Vec<u32> {
        let mut offsets = vec![0u32; self.pieces.len() + 1];
        for (k, i) in self.pieces.iter().enumerate() {
            offsets[k + 1] = offsets[k] + i.points;
        }
        offsets
    }

    fn tet_offsets(&self) -> Vec<u32> {
        let mut offsets = vec![0u32; self.pieces.len() + 1];
        for (k, i) in self.pieces.iter().enumerate() {
            offsets[k + 1] = offsets[k] + i.tets;
        }
        offsets
    }

    /// Round 3: this rank's parts; ghosts to the owners of interface vertices, points to
    /// the owners of their places, the hull's candidates to rank 0.
    fn spread(&mut self, inbox: &[&[u8]]) -> Vec<Vec<u8>> {
        for (from, b) in inbox.iter().enumerate() {
            let labels: Vec<Label> = decode(b);
            for l in labels {
                let at = self.mine.binary_search_by_key(&l.piece, |m| m.piece);
                if let Some(m) = at.ok().map(|k| &mut self.mine[k]) {
                    let k = l.index as usize;
                    (m.labels[k], m.shared[k], m.owner[k]) = (l.label, l.shared, from as u32);
                }
            }
        }
        let tet_offsets = self.tet_offsets();
        let mut out: Vec<Spread> = (0..self.size).map(|_| Spread::default()).collect();
        let mut reoriented = 0;
        for m in &mut self.mine {
            if self.opts.reorient {
                reoriented += mesh::reorient(&m.input.points, &mut m.input.tets);
            }
            let first = tet_offsets[m.piece as usize];
            spread_piece(m, first, self.opts.convex, &mut out, self.size);
            let tet_labels = (first..first + m.input.tets.len() as u32).collect();
            let labels = &m.labels;
            let part = Part::new(
                &m.input.points,
                |k| labels[k as usize],
                &m.input.tets,
                tet_labels,
                |k| !m.shared[k as usize],
                true,
            );
            self.parts.push(part);
        }
        self.reoriented = reoriented as u32;
        let offsets = self.point_offsets();
        self.vertices = (self.mine.iter())
            .map(|m| {
                let base = offsets[m.piece as usize];
                (m.labels.iter().enumerate())
                    .filter(|&(k, &l)| l == base + k as u32)
                    .count() as u32
            })
            .sum();
        // The parts hold what the checks need: the pieces as read go (unless written).
        if self.output.is_none() {
            for m in &mut self.mine {
                m.input = Input::default();
            }
        }
        let out = out.iter().map(encode).collect();
        self.sent(out)
    }

    /// Round 4: the layer of this rank's interface vertices; every part's faces, the
    /// coincident and unused vertices of the places this rank owns, to rank 0.
    fn faces(&mut self, inbox: &[&[u8]]) -> Vec<Vec<u8>> {
        let mut ghosts = Vec::new();
        let mut points = Vec::new();
        for b in inbox {
            let s: Spread = decode(b);
            ghosts.extend(s.ghosts);
            points.extend(s.points);
            self.hull_points.extend(s.hull);
        }
        ghosts.sort_by_key(|g| g.label);
        ghosts.dedup_by_key(|g| g.label);
        let at: Vec<Point3> = ghosts.iter().flat_map(|g| g.at).collect();
        let tets: Vec<[u32; 4]> = (0..ghosts.len() as u32)
            .map(|g| std::array::from_fn(|i| 4 * g + i as u32))
            .collect();
        let owned = |k: u32| ghosts[k as usize / 4].owned >> (k % 4) & 1 == 1;
        let labels = |k: u32| ghosts[k as usize / 4].v[k as usize % 4];
        let tet_labels = ghosts.iter().map(|g| g.label).collect();
        self.parts
            .push(Part::new(&at, labels, &tets, tet_labels, owned, false));
        let mut faces: Vec<PartFaces> = self.parts.iter().map(Part::faces).collect();
        self.on_boundary = (faces.iter_mut())
            .map(|f| std::mem::take(&mut f.on_boundary))
            .collect();
        let boundary_faces = faces.iter().map(|f| f.boundary.len() as u32).sum();
        self.keep_boundary(&mut faces);
        let bbox = (self.mine_boundary.iter().map(Face::bbox)).reduce(box_union);
        let (components, edges) = match self.opts.convex {
            true => (Vec::new(), Vec::new()),
            false => self.components_and_edges(),
        };
        let (coincident, unused) = places(points);
        let g = Gathered {
            faces,
            boundary_faces,
            components,
            bbox,
            coincident,
            unused: if self.opts.convex { unused } else { Vec::new() },
            mismatches: std::mem::take(&mut self.mismatches),
            vertices: self.vertices,
            reoriented: self.reoriented,
        };
        let mut out: Vec<Fourth> = (0..self.size).map(|_| Fourth::default()).collect();
        for (e, c) in edges {
            out[owner_of(&[e[0] as u64, e[1] as u64, 0], self.size)]
                .edges
                .push((e, c));
        }
        out[0].gathered = Some(g);
        let out = out.iter().map(encode).collect();
        self.sent(out)
    }

    /// The components of this rank's boundary faces joined across edges (the faces put
    /// in the merged check's order first), and each face's edges with its component,
    /// each pair once.
    fn components_and_edges(&mut self) -> (Vec<Component>, Vec<([u32; 2], ComponentId)>) {
        self.mine_boundary.sort_by_key(Face::key);
        let keys: Vec<[u32; 3]> = self.mine_boundary.iter().map(Face::key).collect();
        let (of, firsts) = mesh::face_components(&keys);
        let components = (firsts.iter())
            .map(|&i| {
                let f = &self.mine_boundary[i];
                let (v, tet, at) = (f.v[0], f.tet, f.at[0]);
                Component {
                    key: keys[i],
                    v,
                    tet,
                    at,
                }
            })
            .collect();
        let rank = self.rank as u32;
        let mut edges: Vec<([u32; 2], ComponentId)> = (keys.iter().zip(&of))
            .flat_map(|(k, &c)| [[k[0], k[1]], [k[0], k[2]], [k[1], k[2]]].map(|e| (e, (rank, c))))
            .collect();
        edges.sort_unstable();
        edges.dedup();
        (components, edges)
    }

    /// This rank's boundary faces kept with their corners; rank 0 gets them only with
    /// `convex` (the hull test needs them all).
    fn keep_boundary(&mut self, faces: &mut [PartFaces]) {
        for f in faces.iter_mut() {
            let at = |v: u32| {
                let k = f.places.binary_search_by_key(&v, |p| p.0);
                f.places[k.expect("a boundary vertex has its place")].1
            };
            let kept = f.boundary.iter().map(|&(v, tet)| Face {
                v,
                tet,
                at: v.map(at),
            });
            self.mine_boundary.extend(kept);
            if !self.opts.convex {
                f.boundary = Vec::new();
                f.places = Vec::new();
            }
        }
    }

    /// Round 5: the components sharing the edges this rank owns, to rank 0; rank 0:
    /// the report so far in the merged check's order, and whether (and where) the
    /// embedding checks run.
    fn decide(&mut self, inbox: &[&[u8]]) -> Vec<Vec<u8>> {
        let (mut edges, mut gathered) = (Vec::new(), Vec::new());
        for (r, b) in inbox.iter().enumerate() {
            let f: Fourth = decode(b);
            edges.extend(f.edges);
            gathered.extend(f.gathered.map(|g| (r, g)));
        }
        let joined = joined(edges);
        if self.rank != 0 {
            let mut out = vec![Vec::new(); self.size];
            out[0] = encode(&Fifth {
                decision: None,
                joined,
            });
            return self.sent(out);
        }
        self.joined = joined;
        let mut all = Gathered::default();
        self.components = vec![Vec::new(); self.size];
        for (r, g) in gathered {
            all.faces.extend(g.faces);
            all.boundary_faces += g.boundary_faces;
            self.components[r] = g.components;
            all.coincident.extend(g.coincident);
            all.unused.extend(g.unused);
            all.mismatches.extend(g.mismatches);
            all.bbox = match (all.bbox, g.bbox) {
                (Some(a), Some(b)) => Some(box_union(a, b)),
                (a, b) => a.or(b),
            };
            all.vertices += g.vertices;
            all.reoriented += g.reoriented;
        }
        let corners: std::collections::HashMap<u32, Point3> = (all.faces.iter())
            .flat_map(|f| f.places.iter().copied())
            .collect();
        let (mut report, boundary) = mesh::assemble_faces(std::mem::take(&mut all.faces));
        report.boundary_faces = all.boundary_faces as usize;
        all.coincident
            .sort_by(|a, b| lex_cmp(&a.0, &b.0).then(a.1.vertices[1].cmp(&b.1.vertices[1])));
        for (_, p) in std::mem::take(&mut all.coincident) {
            report.push(p);
        }
        let mut decision = Decision::default();
        if self.opts.convex {
            self.boundary = (boundary.iter())
                .map(|f| (f.v, f.tet, f.v.map(|v| corners[&v])))
                .collect();
            all.unused.sort_unstable();
            for &v in &all.unused {
                report.push(mesh::unused_vertex(v));
            }
            for p in self.hull_faces(!all.unused.is_empty()) {
                report.push(p);
            }
        } else if report.is_valid() {
            self.embedding = true;
            decision = Decision {
                embed: true,
                grid: (all.bbox).map(|b| Grid::new(b, all.boundary_faces as usize)),
            };
        }
        self.report = report;
        self.gathered = all;
        let fifth = Fifth {
            decision: Some(decision),
            joined: Vec::new(),
        };
        let out = vec![encode(&fifth); self.size];
        self.sent(out)
    }

    /// The boundary faces (gathered) not on the hull of all points, or overlapping on it.
    fn hull_faces(&self, wrong: bool) -> Vec<Problem> {
        let mut points: Vec<(Point3, u32)> = self.hull_points.clone();
        for (v, _, at) in &self.boundary {
            points.extend((0..3).map(|i| (at[i], v[i])));
        }
        points.sort_by_key(|p| p.1);
        points.dedup_by_key(|p| p.1);
        let place: Vec<Point3> = points.iter().map(|p| p.0).collect();
        let local = |v: u32| points.binary_search_by_key(&v, |p| p.1).unwrap_or(0) as u32;
        let faces: Vec<BoundaryFace> = (self.boundary.iter())
            .map(|(v, tet, _)| BoundaryFace {
                v: v.map(local),
                tet: *tet,
            })
            .collect();
        let hull = Hull3::new(&place);
        let found = mesh::hull_faces(&place, &faces, &hull, wrong);
        relabeled(found, |k| points[k as usize].1)
    }

    /// Round 6: the cone tests of this rank's vertices (to rank 0), its boundary faces
    /// to the owners of their cells; rank 0 also sends every rank the nesting test's
    /// representatives.
    fn embed(&mut self, inbox: &[&[u8]]) -> Vec<Vec<u8>> {
        let mut decision = Decision::default();
        for b in inbox {
            let f: Fifth = decode(b);
            decision = f.decision.unwrap_or(decision);
            self.joined.extend(f.joined);
        }
        let mut out: Vec<Sixth> = (0..self.size).map(|_| Sixth::default()).collect();
        if decision.embed {
            for (part, on) in self.parts.iter().zip(&self.on_boundary) {
                out[0].overlaps.extend(part.vertex_overlaps(on));
            }
            if self.rank == 0 {
                let reps = self.representatives();
                out.iter_mut().for_each(|o| o.reps.clone_from(&reps));
            }
            if let Some(grid) = decision.grid {
                for f in std::mem::take(&mut self.mine_boundary) {
                    for r in grid.owners(&f.bbox(), self.size) {
                        out[r].faces.push(f);
                    }
                }
            }
        }
        self.grid = decision.grid;
        let out = out.iter().map(encode).collect();
        self.sent(out)
    }

    /// Rank 0: one vertex of each component of the whole boundary (the first vertex of
    /// its first face in the merged check's order), in the order of those faces, as
    /// `mesh::boundary_components` picks them; none when the boundary is one component.
    /// The components are the ranks' own, joined where an edge owner found two sharing
    /// an edge.
    fn representatives(&mut self) -> Vec<(Point3, u32)> {
        let all: Vec<&Component> = self.components.iter().flatten().collect();
        let mut offsets = vec![0u32];
        for c in &self.components {
            offsets.push(offsets.last().copied().unwrap_or(0) + c.len() as u32);
        }
        let id = |(r, c): ComponentId| offsets[r as usize] + c;
        let mut parent = crate::partition::singletons(all.len());
        for &(a, b) in &self.joined {
            crate::partition::union(&mut parent, id(a), id(b));
        }
        let mut first: Vec<Option<usize>> = vec![None; all.len()];
        for i in 0..all.len() {
            let root = crate::partition::find(&mut parent, i as u32) as usize;
            if first[root].is_none_or(|j| all[i].key < all[j].key) {
                first[root] = Some(i);
            }
        }
        let mut reps: Vec<&Component> = first.iter().flatten().map(|&i| all[i]).collect();
        reps.sort_by_key(|c| c.key);
        if reps.len() > 1 {
            self.reps = reps.iter().map(|c| (c.v, c.tet, c.at)).collect();
        }
        self.reps.iter().map(|&(v, _, x)| (x, v)).collect()
    }

    /// Round 7: the boundary faces of the cells this rank owns, tested pairwise (each
    /// pair where its boxes' intersection starts), the first pairs in the merged check's
    /// order; and where the representatives lie in this rank's parts; to rank 0.
    fn pairs(&mut self, inbox: &[&[u8]]) -> Vec<Vec<u8>> {
        let (mut faces, mut reps) = (Vec::new(), Vec::new());
        for (r, b) in inbox.iter().enumerate() {
            let sixth: Sixth = decode(b);
            self.overlaps.extend(sixth.overlaps);
            if r == 0 {
                reps = sixth.reps;
            }
            faces.extend(sixth.faces);
        }
        let pairs = match self.grid {
            Some(grid) => self.pairs_in(grid, faces),
            None => Vec::new(),
        };
        let mut hits = vec![None; reps.len()];
        if !reps.is_empty() {
            for part in self.parts.iter().filter(|p| p.reports_tets) {
                mesh::first_hits(&mut hits, part.containing(&reps));
            }
        }
        self.send_to_rank0(&Seventh { pairs, hits })
    }

    /// Among `faces` (some twice), the improper pairs this rank decides, ordered by
    /// their faces' sorted vertices, at most [`mesh::SELF_INTERSECTIONS`].
    fn pairs_in(&self, grid: Grid, mut faces: Vec<Face>) -> Vec<(FaceId, FaceId)> {
        faces.sort_by_key(Face::key);
        faces.dedup_by_key(|f| f.key());
        let mut labels: Vec<(u32, Point3)> = (faces.iter())
            .flat_map(|f| (0..3).map(|i| (f.v[i], f.at[i])))
            .collect();
        labels.sort_by_key(|p| p.0);
        labels.dedup_by_key(|p| p.0);
        let local = |v: u32| labels.binary_search_by_key(&v, |p| p.0).unwrap_or(0) as u32;
        let place: Vec<Point3> = labels.iter().map(|p| p.1).collect();
        let plain: Vec<[u32; 3]> = faces.iter().map(|f| f.v.map(local)).collect();
        let mut found: Vec<(FaceId, FaceId)> =
            crate::mesh::grid::improper_pairs(&place, &plain, usize::MAX)
                .into_iter()
                .filter(|&(i, j)| {
                    let (a, b) = (faces[i].bbox(), faces[j].bbox());
                    let low: Point3 = std::array::from_fn(|k| a.0[k].max(b.0[k]));
                    owner_of(&grid.cell(&low), self.size) == self.rank
                })
                .map(|(i, j)| ((faces[i].v, faces[i].tet), (faces[j].v, faces[j].tet)))
                .collect();
        found.sort_by_key(|(a, b)| (sorted(a.0), sorted(b.0)));
        found.truncate(mesh::SELF_INTERSECTIONS);
        found
    }

    /// Rank 0: the last problems and the outcome.
    fn finish(&mut self, inbox: &[&[u8]]) {
        if self.rank != 0 {
            return;
        }
        let mut report = std::mem::take(&mut self.report);
        let mut overlaps = std::mem::take(&mut self.overlaps);
        overlaps.sort_by_key(|p| p.vertices[0]);
        for p in overlaps {
            report.push(p);
        }
        let (mut pairs, mut hits) = (Vec::new(), vec![None; self.reps.len()]);
        for b in inbox {
            let s: Seventh = decode(b);
            pairs.extend(s.pairs);
            mesh::first_hits(&mut hits, s.hits);
        }
        if self.embedding {
            pairs.sort_by_key(|(a, b)| (sorted(a.0), sorted(b.0)));
            pairs.truncate(mesh::SELF_INTERSECTIONS);
            for (a, b) in pairs {
                report.push(mesh::self_intersection(a, b));
            }
        }
        for (&(v, own, _), hit) in self.reps.iter().zip(hits) {
            if let Some((t, corners)) = hit {
                report.push(mesh::nested_problem(v, own, t, &corners));
            }
        }
        if self.opts.manifold {
            report = report.require_manifold();
        }
        if self.output.is_some() {
            // As `mesh::outcome` marks: the problems, the non-manifold edges, then what
            // the reading found.
            self.marks = (report.problems.iter().chain(&report.non_manifold))
                .chain(&self.gathered.mismatches)
                .cloned()
                .collect();
        }
        let g = &self.gathered;
        let reoriented = self.opts.reorient.then_some(g.reoriented as usize);
        let tets: usize = self.pieces.iter().map(|i| i.tets as usize).sum();
        let mut o = mesh::outcome(
            report,
            Vec::new(),
            g.vertices as usize,
            self.opts,
            reoriented,
        );
        o.tetrahedra = tets;
        self.outcome = Some(o.with_problems(std::mem::take(&mut self.gathered.mismatches)));
    }

    /// The last round with an output: this rank's pieces with the problem codes of the
    /// problems rank 0 sent (each cell and point the first problem naming it marks),
    /// vertices numbered as the check names them; rank 0 writes the index too. A file
    /// that cannot be written is this rank's failure.
    fn write_pieces(&mut self, inbox: &[&[u8]]) {
        let Some(out) = self.output.clone() else {
            return;
        };
        let marks: Vec<Problem> = decode(inbox[0]);
        let mut at_vertex: std::collections::HashMap<u32, i32> = Default::default();
        for p in &marks {
            for &v in &p.vertices {
                at_vertex.entry(v).or_insert(p.kind.code());
            }
        }
        let offsets = self.tet_offsets();
        let written = |m: &Local| {
            let first = offsets[m.piece as usize];
            let mut cells = vec![0; m.input.tets.len()];
            for p in &marks {
                for &t in &p.cells {
                    let local = t.checked_sub(first).map(|k| k as usize);
                    if let Some(c) = local.and_then(|k| cells.get_mut(k)).filter(|c| **c == 0) {
                        *c = p.kind.code();
                    }
                }
            }
            let points: Vec<i32> = (m.labels.iter())
                .map(|l| at_vertex.get(l).copied().unwrap_or(0))
                .collect();
            let ids: Vec<i32> = m.labels.iter().map(|&l| l as i32).collect();
            let fields = io::Fields {
                cells: vec![("problem", &cells)],
                points: vec![("problem", &points)],
            };
            let name = io::piece_path(&out, m.piece as usize);
            io::write_piece(&name, &m.input.points, &m.input.tets, Some(&ids), &fields)
                .map_err(|e| InputError::new(&name, 0, e.to_string()))
        };
        let mut result: Result<(), InputError> = self.mine.iter().try_for_each(written);
        if self.rank == 0 && result.is_ok() {
            let names: Vec<PathBuf> = (0..self.pieces.len())
                .map(|k| io::piece_path(&out, k))
                .collect();
            result = io::write_pvtu_index(&out, &names)
                .map_err(|e| InputError::new(&out, 0, e.to_string()));
        }
        self.failure = result.err();
    }

    /// Rank 0, when the check is over: its outcome.
    pub fn outcome(&self) -> Option<&CheckOutcome> {
        self.outcome.as_ref()
    }

    /// Rank 0, when the check is over: the mesh's reading facts for the report layer
    /// (its pieces, where each starts, and the other cells), without points or tetrahedra.
    pub fn input(&self) -> Input {
        let offsets = self.tet_offsets();
        let other: usize = self.pieces.iter().map(|i| i.other_cells as usize).sum();
        Input {
            dim: 3,
            point_file: self.index.clone(),
            tet_file: self.index.clone(),
            pieces: (self.pieces.iter().zip(&offsets))
                .map(|(info, &first_tet)| Piece {
                    file: self.files[info.file as usize].clone(),
                    first_tet,
                    partition: None,
                })
                .collect(),
            other_cells: (other > 0).then(|| io::OtherCells {
                count: other,
                line: 0,
                message: format!("{other} cells that are not tetrahedra"),
            }),
            ..Default::default()
        }
    }
}

/// The smallest box holding boxes `a` and `b`.
fn box_union(a: (Point3, Point3), b: (Point3, Point3)) -> (Point3, Point3) {
    let lo = std::array::from_fn(|i| a.0[i].min(b.0[i]));
    (lo, std::array::from_fn(|i| a.1[i].max(b.1[i])))
}

/// Pairs of components that share an edge, among `edges` (an edge owner's): enough of
/// them to join every set that shares edges (a spanning forest: fewer pairs than
/// components).
fn joined(mut edges: Vec<([u32; 2], ComponentId)>) -> Vec<(ComponentId, ComponentId)> {
    edges.sort_unstable();
    let mut ids: Vec<ComponentId> = edges.iter().map(|e| e.1).collect();
    ids.sort_unstable();
    ids.dedup();
    let index = |c: &ComponentId| ids.binary_search(c).unwrap_or(0) as u32;
    let mut parent = crate::partition::singletons(ids.len());
    let mut out = Vec::new();
    for run in edges.chunk_by(|a, b| a.0 == b.0) {
        for e in &run[1..] {
            if crate::partition::union(&mut parent, index(&run[0].1), index(&e.1)) {
                out.push((run[0].1, e.1));
            }
        }
    }
    out
}

/// A boundary face as a problem names it: its vertices (outward) and its tetrahedron.
type FaceId = ([u32; 3], u32);

fn sorted(mut v: [u32; 3]) -> [u32; 3] {
    v.sort_unstable();
    v
}

/// The number of the piece `sub` of file `file` in the pieces' table.
fn piece_of(pieces: &[Info], file: u32, sub: u32) -> u32 {
    let at = pieces.binary_search_by_key(&(file, sub), |i| (i.file, i.sub));
    at.expect("every piece read is in the table") as u32
}

fn relabeled(found: Vec<Problem>, label: impl Fn(u32) -> u32) -> Vec<Problem> {
    let mut found = found;
    for p in &mut found {
        p.relabel(&label, &|t| t);
    }
    found
}

/// A piece's ghosts (every tetrahedron around an interface vertex, to the vertex's
/// owner), its points (to the owner of their place) and, with `convex`, its hull's.
fn spread_piece(m: &Local, first: u32, convex: bool, out: &mut [Spread], size: usize) {
    let mut first_tet = vec![u32::MAX; m.input.points.len()];
    for (t, tet) in m.input.tets.iter().enumerate().rev() {
        tet.iter()
            .for_each(|&k| first_tet[k as usize] = first + t as u32);
        let mut owners: Vec<u32> = (tet.iter())
            .filter(|&&k| m.shared[k as usize])
            .map(|&k| m.owner[k as usize])
            .collect();
        owners.sort_unstable();
        owners.dedup();
        for r in owners {
            let mut owned = 0u8;
            for (i, &k) in tet.iter().enumerate() {
                if m.shared[k as usize] && m.owner[k as usize] == r {
                    owned |= 1 << i;
                }
            }
            out[r as usize].ghosts.push(Ghost {
                label: first + t as u32,
                v: tet.map(|k| m.labels[k as usize]),
                at: tet.map(|k| m.input.points[k as usize]),
                owned,
            });
        }
    }
    for (k, at) in m.input.points.iter().enumerate() {
        let r = owner_of(&point_key(at), size);
        out[r].points.push((*at, m.labels[k], first_tet[k]));
    }
    if convex {
        let hull = Hull3::new(&m.input.points);
        let on = (0..m.input.points.len()).filter(|&k| hull.on_boundary(k));
        out[0]
            .hull
            .extend(on.map(|k| (m.input.points[k], m.labels[k])));
    }
}

/// The coincident vertices among `points` (`(place, vertex, first tetrahedron)`, a
/// vertex possibly many times) with the place of each problem, and the unused vertices.
fn places(mut points: Vec<(Point3, u32, u32)>) -> (Vec<(Point3, Problem)>, Vec<u32>) {
    points.sort_by_key(|p| (p.1, p.2));
    points.dedup_by_key(|p| p.1);
    let unused = (points.iter())
        .filter(|p| p.2 == u32::MAX)
        .map(|p| p.1)
        .collect();
    let mut used: Vec<(Point3, u32, u32)> =
        points.into_iter().filter(|p| p.2 != u32::MAX).collect();
    let found = mesh::coincident_runs(&mut used);
    let at: std::collections::HashMap<u32, Point3> = used.iter().map(|u| (u.1, u.0)).collect();
    let found = found.into_iter().map(|p| (at[&p.vertices[1]], p)).collect();
    (found, unused)
}

/// Runs the ranks of a partitioned check of `index` in this process, exchanging their
/// messages in memory: rank 0's outcome (or the failure), and the bytes each rank sent.
pub fn check_in_ranks(
    index: &Path,
    size: usize,
    opts: CheckOptions,
) -> (Result<CheckOutcome, InputError>, Vec<usize>) {
    check_in_ranks_writing(index, size, opts, None)
}

/// [`check_in_ranks`], each rank writing its pieces with their problem fields to
/// `output` as [`RankCheck::with_output`] says.
pub fn check_in_ranks_writing(
    index: &Path,
    size: usize,
    opts: CheckOptions,
    output: Option<&Path>,
) -> (Result<CheckOutcome, InputError>, Vec<usize>) {
    let mut ranks: Vec<RankCheck> = (0..size)
        .map(|r| RankCheck::new(index, r, size, opts, false))
        .map(|r| match output {
            Some(out) => r.with_output(out),
            None => r,
        })
        .collect();
    let mut outs: Vec<Vec<Vec<u8>>> = ranks.iter_mut().map(RankCheck::start).collect();
    loop {
        let mut next = Vec::new();
        for (r, rank) in ranks.iter_mut().enumerate() {
            let inbox: Vec<&[u8]> = outs.iter().map(|o| &o[r][..]).collect();
            next.push(rank.step(&inbox));
        }
        if next.iter().any(Option::is_none) {
            break;
        }
        outs = next.into_iter().map(Option::unwrap_or_default).collect();
    }
    let sent = ranks.iter().map(|r| r.bytes_sent).collect();
    let result = match ranks.iter().find_map(RankCheck::failure) {
        Some(f) => Err(f.clone()),
        None => (ranks.first().and_then(|r| r.outcome.clone()))
            .ok_or_else(|| InputError::new(index, 0, "no rank took part (size 0)")),
    };
    (result, sent)
}
