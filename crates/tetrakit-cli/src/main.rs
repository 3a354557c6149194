//! The `tetrakit` command-line tool: a thin layer that parses arguments, calls the
//! library, and prints results. Every command returns an [`exit::Verdict`] or an [`exit::CliError`];
//! [`main`] alone turns them into exit codes: 0 yes, 1 no, 3 undecided within the time
//! limit, 2 bad input or usage (clap's own usage errors exit 2 as well).
#![forbid(unsafe_code)]

/// `println!` that ignores write errors: output to a closed pipe (`| head`) must not panic.
macro_rules! out {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        let _ = writeln!(std::io::stdout(), $($arg)*);
    }};
}

mod constrain;
mod demo;
mod exit;
mod flips;
mod planar;
mod poly;
mod progress;
mod reduce;
mod run;
mod shell;

use clap::{Args, Parser, Subcommand, ValueEnum};
use exit::CmdResult;
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Duration;
use tetrakit::constrain::Question;

#[derive(Parser)]
#[command(
    name = "tetrakit",
    version,
    about = "Exact tetrahedralization algorithms (detection, validation, generators)"
)]
struct Cli {
    #[command(subcommand)]
    cmd: Cmd,
}

/// Each subcommand's arguments are built only when it runs or its help is shown
/// (`defer`): clap would build all of them first, 0.3 ms (cold) of a 9 ms run. A
/// deferred subcommand's argument structs must not carry doc comments: the last one
/// applied would become its help's description (`contract.rs` checks every one).
#[derive(Subcommand)]
#[command(defer = true)]
enum Cmd {
    /// Decide whether a set of segments is exactly the edge set of a tetrahedralization
    /// (or, for planar points, of a triangulation).
    Detect(DetectArgs),
    /// Validate a tetrahedral mesh (orientation, face pairing, closed boundary; with
    /// --convex, that it tetrahedralizes the convex hull of its vertices).
    Check(CheckArgs),
    /// Minimal tetrahedralization of an augmented (multi-level) BP-polyhedron by
    /// Algorithm MINTETRA (thesis §3.4), or NO with what is left.
    Mintetra(MintetraArgs),
    /// Tetrahedralize a polyhedron (faces given) or the convex hull of a point set
    /// without Steiner points, by an exact SAT solver; with --minimal, with the fewest
    /// tetrahedra. Exit 1 with a proof when impossible, 3 at the time limit.
    Tetrahedralize(TetrahedralizeArgs),
    /// Does a segment set contain the edge set of a tetrahedralization of its points
    /// (TETRAD, thesis §2.5; for planar points, of a triangulation: TRID)? Exact (SAT),
    /// with a witness or a DRAT proof for NO.
    Contains(ContainsArgs),
    /// Is there a tetrahedralization of the points with every given segment as an edge
    /// (CT, thesis §2.6; a triangulation for planar points)? Exact, with a witness or a
    /// DRAT proof for NO.
    Constrained(ConstrainedArgs),
    /// β-skeleton of planar points, exact for any rational β (circle-based by default,
    /// thesis ch. 5; --lune for the lune-based one).
    Skeleton(SkeletonArgs),
    /// Exact minimum weight triangulation of planar points, weight certified.
    Mwt(MwtArgs),
    /// The point set of thesis §5.2 against Keil's conjecture: is xy in the β-skeleton
    /// and in the MWT (both exact)? With --check-random K, β-skeleton ⊆ MWT on K random
    /// sets (β above the Cheng–Xu bound).
    Keil(KeilCliArgs),
    /// Tetrahedralize the region between two nested convex polytopes without Steiner
    /// points (thesis ch. 4), certified: every tetrahedron, the boundary on both hulls,
    /// the exact volume.
    Shell(ShellCliArgs),
    /// Every tetrahedralization of a small point set that uses every point, enumerated
    /// exactly, and the graph of the flips between them (thesis ch. 6): is it connected,
    /// is any tetrahedralization without a flip? Exit 0 connected, 1 not (with two
    /// tetrahedralizations no flips join), 3 cut by --limit or --time-limit.
    Flips(FlipsArgs),
    /// The constructions of thesis ch. 2 (reductions between the NP-complete problems).
    Reduce(ReduceArgs),
    /// Write a generated instance.
    Generate(GenerateArgs),
    /// A short tour on built-in examples.
    Demo,
}

#[derive(Args)]
pub(crate) struct DetectArgs {
    /// X.edge (with X.node beside it), X.ele (its tetrahedra's edges are used), .obj with
    /// `v`/`l` lines, or .json.
    input: PathBuf,
    /// Print one JSON object on stdout.
    #[arg(long)]
    json: bool,
    /// Write the tetrahedralization found: .ele (with .node), .vtk, .vtu or .json.
    #[arg(long)]
    output: Option<PathBuf>,
    /// How each vertex's link is freed of punctured segments (the verdict never depends
    /// on it).
    #[arg(long, value_enum, default_value_t)]
    links: tetrakit::detect::LinkMethod,
    /// Skip the Delaunay proposal and always run the thesis's per-vertex algorithm (the
    /// verdict never depends on it).
    #[arg(long)]
    links_only: bool,
    /// Give up after this many seconds (exit 3, verdict "undecided").
    #[arg(long, value_parser = seconds)]
    time_limit: Option<Duration>,
}

#[derive(Args)]
struct CheckArgs {
    /// X.ele (with X.node beside it), or .json with "tets".
    input: PathBuf,
    /// More pieces of the same mesh, read with INPUT as one partitioned mesh: Gmsh's
    /// `-part_split` files (mesh_1.msh mesh_2.msh …, merged by node tag) or `.vtu` pieces.
    more: Vec<PathBuf>,
    /// Also certify that the mesh tetrahedralizes the convex hull of all its points.
    #[arg(long)]
    convex: bool,
    /// Require a manifold boundary: boundary edges of four or more boundary faces (two
    /// boxes touching along an edge) are problems (without it they are counted as
    /// "non_manifold_edges" and the mesh is valid).
    #[arg(long)]
    manifold: bool,
    /// Turn negatively oriented tetrahedra (swap their last two vertices) and count them,
    /// instead of reporting them as problems: for generators that do not orient their
    /// cells (scipy, Qhull).
    #[arg(long)]
    reorient: bool,
    /// Check the tetrahedra of a mixed mesh alone: hexahedra, prisms, pyramids and other
    /// cells are counted ("other_cells") instead of refused. The check then speaks of the
    /// tetrahedra alone (faces against a hexahedron are their boundary).
    #[arg(long)]
    tets_only: bool,
    /// Write the mesh for a viewer, .vtk or .vtu, with integer fields "problem" on cells
    /// and points (the first problem naming each, numbered as in `--json`'s
    /// "problem_codes"; 0 for none).
    #[arg(long, short)]
    output: Option<PathBuf>,
    /// Print one JSON object on stdout.
    #[arg(long)]
    json: bool,
}

#[derive(Args)]
struct MintetraArgs {
    /// A polyhedron: .off, .stl, .obj with `f` lines, .face (with .node) or .json with "faces".
    input: PathBuf,
    /// Print one JSON object on stdout.
    #[arg(long)]
    json: bool,
    /// Write the tetrahedra: .ele (with .node), .vtk, .vtu or .json.
    #[arg(long)]
    output: Option<PathBuf>,
    /// Also run the exact solver (up to 60 vertices) to confirm minimality and uniqueness.
    #[arg(long)]
    confirm: bool,
}

#[derive(Args)]
struct TetrahedralizeArgs {
    /// A polyhedron (.off, .obj with faces, .face, .json with "faces") or a point set
    /// (.node, .xyz, .obj/.json without faces; then its convex hull, every point used).
    input: PathBuf,
    /// Find a tetrahedralization with the fewest tetrahedra (otherwise any).
    #[arg(long)]
    minimal: bool,
    /// With --minimal, also decide whether the minimum one is unique.
    #[arg(long)]
    unique: bool,
    /// For a convex polytope's points: a tetrahedralization whose tetrahedra can be
    /// ordered so that each shares a triangle with the next (a Hamiltonian path of the
    /// dual graph, thesis ch. 6); --output writes them in that order. Exit 1 with a
    /// witness when no tetrahedralization has one (every one searched), 3 when undecided.
    #[arg(long, conflicts_with_all = ["minimal", "unique", "proof"])]
    hamiltonian: bool,
    /// Give up after this many seconds (exit 3 with the best bounds).
    #[arg(long, value_parser = seconds)]
    time_limit: Option<Duration>,
    /// Print one JSON object on stdout.
    #[arg(long)]
    json: bool,
    /// Write the tetrahedra: .ele (with .node), .vtk, .vtu or .json.
    #[arg(long, short)]
    output: Option<PathBuf>,
    /// On NO, write the SAT formula to P.cnf and a DRAT refutation of it to P.drat.
    #[arg(long, value_name = "P.drat")]
    proof: Option<PathBuf>,
}

// What `contains` and `constrained` share. (A plain comment: a doc comment here would
// become their help's description, set after theirs since `Cmd` is deferred.)
#[derive(Args)]
struct DecideArgs {
    /// Find a tetrahedralization with the fewest tetrahedra among the allowed ones.
    #[arg(long)]
    minimal: bool,
    /// Give up after this many seconds (exit 3, verdict "undecided").
    #[arg(long, value_parser = seconds)]
    time_limit: Option<Duration>,
    /// Print one JSON object on stdout.
    #[arg(long)]
    json: bool,
    /// Write the tetrahedra (.ele with .node, .vtk, .json) or, for planar input, the
    /// triangles (.off, .obj, .json, .edge, .svg).
    #[arg(long, short)]
    output: Option<PathBuf>,
    /// On NO, write the SAT formula to P.cnf (DIMACS, each candidate named) and a DRAT
    /// refutation of it to P.drat (check with `rate P.cnf P.drat` or drat-trim).
    #[arg(long, value_name = "P.drat")]
    proof: Option<PathBuf>,
}

#[derive(Args)]
struct ContainsArgs {
    /// The segments and their points: X.edge (with X.node), .obj with `v`/`l` lines,
    /// or .json with "points" and "segments".
    input: PathBuf,
    #[command(flatten)]
    decide: DecideArgs,
}

#[derive(Args)]
struct ConstrainedArgs {
    /// The points, with the constraint segments unless SEGMENTS is given: .node (with
    /// .edge), .obj, .json, .xyz.
    input: PathBuf,
    /// The constraints, from a file on the same points (.edge with its .node, .obj,
    /// .json).
    segments: Option<PathBuf>,
    #[command(flatten)]
    decide: DecideArgs,
}

#[derive(Args)]
struct ReduceArgs {
    #[command(subcommand)]
    kind: ReduceKind,
}

#[derive(Subcommand)]
enum ReduceKind {
    /// Theorem 2.9: a planar segment set (TRID) to a spatial one (TETRAD) that contains a
    /// tetrahedralization exactly when the planar one contains a triangulation; the
    /// construction's conditions are checked exactly.
    TridToTetrad {
        /// Planar points (z = 0) with segments: .json, .obj with `l` lines, .edge (with
        /// .node).
        input: PathBuf,
        /// The spatial segment set: .json, .obj or .edge (with .node).
        output: PathBuf,
        /// `apexes`: the lifted points between two apexes (proven); `sphere`: the
        /// thesis's own construction (a sphere, a twisted lower copy, regular
        /// quasi-prisms, the apex x*).
        #[arg(long, value_enum, default_value_t = reduce::Construction::Apexes)]
        construction: reduce::Construction,
        /// Print one JSON object on stdout.
        #[arg(long)]
        json: bool,
    },
    /// Lemma 2.6: tetrahedralize the gap between a polyhedron whose vertices are all
    /// vertices of its convex hull and that hull, by flipping reflex edges outward.
    HullGap {
        /// The polyhedron: .off, .obj, .face (with .node) or .json with "faces".
        input: PathBuf,
        /// Write the tetrahedra: .ele (with .node), .vtk, .vtu or .json.
        #[arg(long, short)]
        output: Option<PathBuf>,
        /// Print one JSON object on stdout.
        #[arg(long)]
        json: bool,
        /// Give up after this many seconds (exit 3).
        #[arg(long, value_parser = seconds)]
        time_limit: Option<Duration>,
    },
    /// Algorithm QUASI-PRISM-TETRAHEDRALIZATION (Lemma 2.7): cut a quasi-prism (a layer
    /// of prisms between two isomorphic triangulated surfaces) into tetrahedra keeping
    /// all its edges, three per prism when the sides' diagonals allow (regularity checked
    /// first), else by the exact solver.
    QuasiPrism {
        /// The upper surface's points, then their images in the same order, with the
        /// upper surface's triangles: .off, .obj, .json with "faces", .face (with .node).
        input: PathBuf,
        /// Write the tetrahedra: .ele (with .node), .vtk, .vtu or .json.
        #[arg(long, short)]
        output: Option<PathBuf>,
        /// Print one JSON object on stdout.
        #[arg(long)]
        json: bool,
        /// Give up after this many seconds (exit 3).
        #[arg(long, value_parser = seconds)]
        time_limit: Option<Duration>,
    },
}

#[derive(Args)]
struct FlipsArgs {
    /// The points (.xyz, .node, .obj, .off, .json, ...; faces and cells are not read).
    input: PathBuf,
    /// Stop after this many tetrahedralizations (exit 3: there are at least that many).
    #[arg(long, default_value_t = 1_000_000)]
    limit: usize,
    /// Give up after this many seconds (exit 3, with the count so far).
    #[arg(long, value_parser = seconds)]
    time_limit: Option<Duration>,
    /// Print one JSON object on stdout.
    #[arg(long)]
    json: bool,
    /// Write the graph as JSON: the points, every tetrahedralization, every flip.
    #[arg(long, short, value_name = "G.json")]
    output: Option<PathBuf>,
    /// Only count the tetrahedralizations (each certified, none kept: no graph, and
    /// memory for one at a time), as TOPCOM's points2nallfinetriangs does.
    #[arg(long, conflicts_with = "output")]
    count_only: bool,
}

#[derive(Args)]
struct ShellCliArgs {
    /// The outer polytope: a point set or polyhedron (.node, .xyz, .json, .off, .obj);
    /// its convex hull is used.
    outer: PathBuf,
    /// The inner polytope, inside the outer one (it may touch it).
    inner: PathBuf,
    /// How the outer vertices are removed: Bern's caps, minimum degree first.
    #[arg(long, value_enum, default_value_t = ShellMethod::Cap)]
    method: ShellMethod,
    /// Skip the improvement pass after the removals (3-2 flips, and Delaunay flips
    /// above 3 tetrahedra per vertex, each keeping both surfaces).
    #[arg(long)]
    no_flips: bool,
    /// Also the exact minimum over every tetrahedralization (SAT; at most 60 vertices),
    /// printed instead when proven; stopped by --time-limit, its bounds.
    #[arg(long)]
    optimum: bool,
    /// Give up after this many seconds (exit 3).
    #[arg(long, value_parser = seconds)]
    time_limit: Option<Duration>,
    /// Print one JSON object on stdout.
    #[arg(long)]
    json: bool,
    /// Write the tetrahedra: .ele (with .node), .vtk, .vtu or .json (vertices numbered from
    /// the outer ones, then the inner ones not shared).
    #[arg(long, short)]
    output: Option<PathBuf>,
}

#[derive(ValueEnum, Clone, Copy, Debug)]
enum ShellMethod {
    /// Bern's cap removal (§4.1).
    Cap,
    /// Greedy bigcaps (§4.2–4.3).
    Bigcap,
    /// BIGCAP-REMOVE: Lemma 4.1 checked exactly first (exit 1 with a witness where it
    /// fails), then Steps 1–7 (S-bigcaps over the chains of P_a, Step 3a by exact search
    /// within a budget, Step 6's chains of P_b), refused S-bigcaps repaired.
    Thesis,
}

#[derive(Args)]
struct SkeletonArgs {
    /// Planar points: .xyz/.txt (x y per line), .node, .json or .obj (z = 0 unless --xy).
    input: PathBuf,
    /// Use the points' projection to the xy-plane (3D points, such as terrain samples);
    /// without it a point with z ≠ 0 is an error.
    #[arg(long)]
    xy: bool,
    /// β as a decimal (at most 15 significant digits) or a fraction a/b.
    #[arg(long)]
    beta: String,
    /// Use the lune-based region (intersection of two disks centred on the line pq).
    #[arg(long)]
    lune: bool,
    /// Print one JSON object on stdout.
    #[arg(long)]
    json: bool,
    /// Write the edges: .json, .edge (with .node) or .svg (not written when stopped).
    #[arg(long)]
    output: Option<PathBuf>,
    /// Give up after this many seconds (β < 1: exit 3, verdict "undecided", with the
    /// edges found so far counted).
    #[arg(long, value_parser = seconds)]
    time_limit: Option<Duration>,
}

#[derive(Args)]
struct MwtArgs {
    /// Planar points: .xyz/.txt (x y per line), .node, .json or .obj (z = 0 unless --xy).
    input: PathBuf,
    /// Triangulate the points' projection to the xy-plane and keep each point's z in
    /// .off/.obj output (a TIN of terrain samples); without it a point with z ≠ 0 is an
    /// error.
    #[arg(long)]
    xy: bool,
    /// Print one JSON object on stdout.
    #[arg(long)]
    json: bool,
    /// Write the triangulation: its triangles as .off or .obj, or its edges as .json,
    /// .edge (with .node) or .svg.
    #[arg(long)]
    output: Option<PathBuf>,
    /// Give up after this many seconds: exit 3 with certified bounds on the minimum
    /// weight (below: from the solver's state once the LMT-skeleton has run, else a
    /// minimum spanning tree; above: the Delaunay triangulation after flips that
    /// shorten it, which is written to --output).
    #[arg(long, value_parser = seconds)]
    time_limit: Option<Duration>,
}

#[derive(Args)]
struct KeilCliArgs {
    /// β in [2/√3, √(2√3+45)/6) as a decimal or fraction (any β above √(2√3+9)/3 with
    /// --check-random).
    #[arg(long)]
    beta: String,
    /// Sites on each arc (default: one more than Lemma 5.8's bound, where the thesis
    /// proves xy is in no MWT); with --check-random, points per random set (default 200).
    #[arg(long)]
    n: Option<usize>,
    /// Print one JSON object on stdout.
    #[arg(long)]
    json: bool,
    /// Draw the sites, the β-disks of xy, the MWT and xy.
    #[arg(long)]
    svg: Option<PathBuf>,
    /// Write the construction's sites, in the thesis's order (.xyz, .txt, .node or
    /// .json), to rerun them through `mwt`, `skeleton` or another tool; x and y are the
    /// sites the JSON output names in "xy".
    #[arg(long, short)]
    output: Option<PathBuf>,
    /// Check β-skeleton ⊆ MWT on this many random point sets instead.
    #[arg(long)]
    check_random: Option<usize>,
    /// Give up on the construction's optima after this many seconds (exit 3, verdict
    /// "undecided", with the sites and the skeleton test; no picture).
    #[arg(long, value_parser = seconds, conflicts_with = "check_random")]
    time_limit: Option<Duration>,
}

#[derive(Args)]
struct GenerateArgs {
    #[command(subcommand)]
    kind: GenKind,
}

#[derive(Args, Clone)]
struct GenCommon {
    /// Output file: .ele (writes .node, .ele and .edge), .edge (with .node), .obj, .json,
    /// .vtk, .vtu, or .pvtu (ParaView's partitioned layout: one .vtu per piece beside it).
    #[arg(long, short)]
    output: PathBuf,
    /// With a .pvtu output, the number of pieces (slabs along x).
    #[arg(long, default_value_t = 4)]
    pieces: usize,
    /// Break the instance so that it is not a tetrahedralization.
    #[arg(long, value_enum)]
    corrupt: Option<CorruptKind>,
    /// Seed for random choices.
    #[arg(long, default_value_t = 1)]
    seed: u64,
}

#[derive(Subcommand)]
enum GenKind {
    /// Kuhn subdivision of a K×K×K grid of cubes ((K+1)^3 points, 6K^3 tetrahedra).
    Kuhn {
        /// Cubes along each side.
        #[arg(long)]
        size: usize,
        #[command(flatten)]
        common: GenCommon,
    },
    /// A random valid, non-Delaunay tetrahedralization (random insertion plus flips).
    RandomTetrahedralization {
        /// Number of points.
        #[arg(long)]
        points: usize,
        /// Number of random 2-3/3-2 flips.
        #[arg(long, default_value_t = 0)]
        flips: usize,
        /// Integer coordinates in [0, G)^3 instead of uniform reals (degenerate input).
        #[arg(long)]
        grid: Option<u32>,
        #[command(flatten)]
        common: GenCommon,
    },
    /// A stacked polyhedron (tetrahedra glued face to face; no diagonal needed).
    Stacked {
        /// Number of vertices.
        #[arg(long)]
        n: usize,
        #[command(flatten)]
        out: PolyOut,
    },
    /// A convex bipyramid over an m-gon.
    Bipyramid {
        /// Vertices of the middle polygon.
        #[arg(long)]
        m: usize,
        #[command(flatten)]
        out: PolyOut,
    },
    /// An augmented BP-polyhedron (thesis §3.3.2).
    BpPolyhedron(BpArgs),
    /// An augmented two-level BP-polyhedron of Theorem 3.6's kind.
    TwoLevel(BpArgs),
    /// An augmented h-level BP-polyhedron (§3.5's conjecture).
    HLevel {
        /// Levels h.
        #[arg(long, default_value_t = 3)]
        levels: usize,
        #[command(flatten)]
        bp: BpArgs,
    },
    /// Schönhardt's twisted prism: no tetrahedralization. With --twist, the prism
    /// twisted by that many degrees (positive: Schönhardt's, negative: convex).
    Schonhardt {
        /// Twist of the top triangle in degrees, in (-120, 120).
        #[arg(long, allow_negative_numbers = true)]
        twist: Option<f64>,
        #[command(flatten)]
        out: PolyOut,
    },
    /// Schönhardt's prism stacked LAYERS high, each layer turned TWIST degrees further
    /// (a hard family for `tetrahedralize`; one layer is Schönhardt's polyhedron).
    SchonhardtTower {
        /// Layers (prisms stacked).
        #[arg(long, default_value_t = 2)]
        layers: usize,
        /// Turn per layer in degrees, in (-60, 60).
        #[arg(long, default_value_t = 30.0, allow_negative_numbers = true)]
        twist: f64,
        #[command(flatten)]
        out: PolyOut,
    },
    /// Chazelle's polyhedron: a box with GROOVES grooves in its top and as many across
    /// its bottom, their floors passing close on a saddle (12·GROOVES + 8 vertices).
    Chazelle {
        /// Grooves on each side.
        #[arg(long, default_value_t = 2)]
        grooves: usize,
        #[command(flatten)]
        out: PolyOut,
    },
    /// A dented convex polyhedron: N random points on a sphere, their hull's surface,
    /// half the vertices pushed inward by up to DENT.
    Perturbed {
        /// Vertices.
        #[arg(long)]
        n: usize,
        /// The largest inward push, as a fraction of the radius, in [0, 1).
        #[arg(long, default_value_t = 0.5)]
        dent: f64,
        #[command(flatten)]
        out: PolyOut,
    },
    /// A CT instance for `constrained`: ROWS × COLS towers of LAYERS Schönhardt gadgets
    /// (all their edges as constraints) side by side, and no other point.
    GadgetGrid {
        /// Rows of gadgets.
        #[arg(long, default_value_t = 2)]
        rows: usize,
        /// Columns of gadgets.
        #[arg(long, default_value_t = 2)]
        cols: usize,
        /// Gadgets stacked in each tower (a chain).
        #[arg(long, default_value_t = 1)]
        layers: usize,
        /// Twist of each prism in degrees, in (0, 60).
        #[arg(long, default_value_t = 30.0)]
        twist: f64,
        /// Distance between neighbouring axes (at least 2.5).
        #[arg(long, default_value_t = 3.0)]
        spacing: f64,
        /// Output: .json, .edge (with .node) or .obj.
        #[arg(long, short)]
        output: PathBuf,
    },
    /// A convex polyhedron with its polygon facets triangulated at random (thesis ch. 6:
    /// can it be tetrahedralized without Steiner points, the surface fixed?).
    ConvexTriangulated {
        /// The polytope: a prism over an N-gon, the cube, or the hull of N lattice points.
        #[arg(long, value_enum, default_value_t = tetrakit::polyhedra::generate::ConvexShape::Prism)]
        shape: tetrakit::polyhedra::generate::ConvexShape,
        /// The prism's N-gon, or the number of lattice points.
        #[arg(long, default_value_t = 3)]
        n: usize,
        /// Points added strictly inside random facets.
        #[arg(long, default_value_t = 0)]
        facet_points: usize,
        #[command(flatten)]
        out: PolyOut,
    },
    /// Schönhardt's polyhedron with three BP-nets, convex (Figure 3.21).
    SchonhardtBp {
        #[command(flatten)]
        out: PolyOut,
    },
    /// Points in space for `flips`.
    Points3d {
        /// The distribution.
        #[arg(long, value_enum, default_value_t = tetrakit::generate::Distribution3::Uniform)]
        dist: tetrakit::generate::Distribution3,
        /// Number of points.
        #[arg(long)]
        n: usize,
        /// Seed.
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// Output file: .xyz, .txt, .node or .json.
        #[arg(long, short)]
        output: PathBuf,
    },
    /// Planar points for `skeleton` and `mwt`.
    Points2d {
        /// The distribution.
        #[arg(long, value_enum, default_value_t = tetrakit::planar::Distribution::Uniform)]
        dist: tetrakit::planar::Distribution,
        /// Number of points.
        #[arg(long)]
        n: usize,
        /// Seed.
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// Output file: .xyz, .txt, .node or .json.
        #[arg(long, short)]
        output: PathBuf,
    },
    /// Two nested convex point sets for `shell`: the outer shape of radius 1 and the
    /// inner one of radius 1 − gap (shrunk by 0.9 until it fits, reported).
    Nested(NestedArgs),
    /// A shell on which Bern's minimum-degree cap removal is superlinear: an antiprism
    /// over two RING-gons around a flat bicone with RIDGE points on its rim.
    BernDisk {
        /// Points on the inner bicone's rim (it has two apexes besides).
        #[arg(long)]
        ridge: usize,
        /// Vertices of each of the outer antiprism's two polygons.
        #[arg(long)]
        ring: usize,
        /// Seed (jitters the ring heights).
        #[arg(long, default_value_t = 1)]
        seed: u64,
        #[command(flatten)]
        out: PairOutput,
    },
    /// A shell whose inner polytope touches the outer one at a vertex, along an edge,
    /// along a facet, or with a vertex inside a facet (the cube), and nowhere else.
    Contact {
        /// How the two polytopes touch.
        #[arg(long, value_enum)]
        kind: tetrakit::shell::generate::Contact,
        /// Points on the outer sphere (ignored for facet-point: the cube's corners).
        #[arg(long, default_value_t = 40)]
        n_outer: usize,
        /// Inner points: the shared ones, then points strictly inside.
        #[arg(long, default_value_t = 20)]
        n_inner: usize,
        /// Seed.
        #[arg(long, default_value_t = 1)]
        seed: u64,
        #[command(flatten)]
        out: PairOutput,
    },
    /// The smallest counterexample to the thesis's Lemma 4.1 we found (10 points, no four
    /// coplanar): a tip whose bigcap is simple but not star-shaped from it.
    Lemma41 {
        #[command(flatten)]
        out: PairOutput,
        /// Print the check's outcome as JSON (that of `shell --method thesis --json`).
        #[arg(long = "json")]
        as_json: bool,
    },
    /// A CT instance for `constrained`: Schönhardt's polyhedron's twelve edges as
    /// constraints, among random points outside its niche's view (Theorem 2.10: NO).
    Niche {
        /// Twist in degrees, in (0, 60).
        #[arg(long, default_value_t = 30.0)]
        twist: f64,
        /// Random points around the prism, outside the view.
        #[arg(long, default_value_t = 8)]
        extra: usize,
        /// Add the prism's centre, which sees both niches' bases (then YES).
        #[arg(long)]
        in_view: bool,
        /// Seed.
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// Output: .json, .edge (with .node) or .obj.
        #[arg(long, short)]
        output: PathBuf,
    },
    /// A quasi-prism for `reduce quasi-prism`: RING points on the unit circle and INNER
    /// random ones inside, Delaunay-triangulated, on two caps of a lens, the lower one
    /// turned by TWIST degrees. Writes the upper points, then their images, with the
    /// upper triangles.
    QuasiPrism {
        /// Points on the rim.
        #[arg(long, default_value_t = 8)]
        ring: usize,
        /// Random points inside the rim.
        #[arg(long, default_value_t = 8)]
        inner: usize,
        /// Turn of the lower cap in degrees, in (-90, 90).
        #[arg(long, default_value_t = 3.0, allow_negative_numbers = true)]
        twist: f64,
        #[command(flatten)]
        out: PolyOut,
    },
    /// Points on two skew lines: Θ(n²) tetrahedra, the thesis's worst case for m.
    SkewLines {
        /// Number of points (half on each line).
        #[arg(long)]
        points: usize,
        #[command(flatten)]
        common: GenCommon,
    },
}

#[derive(Args, Clone)]
struct NestedArgs {
    /// The outer shape.
    #[arg(long, value_enum, default_value_t = tetrakit::shell::generate::Shape::Sphere)]
    outer: tetrakit::shell::generate::Shape,
    /// The inner shape.
    #[arg(long, value_enum, default_value_t = tetrakit::shell::generate::Shape::Sphere)]
    inner: tetrakit::shell::generate::Shape,
    /// Points of the outer shape.
    #[arg(long, default_value_t = 100)]
    n_outer: usize,
    /// Points of the inner shape.
    #[arg(long, default_value_t = 50)]
    n_inner: usize,
    /// The gap between the shapes, in (0, 1).
    #[arg(long, default_value_t = 0.3)]
    gap: f64,
    /// Seed.
    #[arg(long, default_value_t = 1)]
    seed: u64,
    #[command(flatten)]
    out: PairOutput,
}

/// Where a generated shell's two point sets go.
#[derive(Args, Clone)]
struct PairOutput {
    /// The outer points: .xyz, .txt, .node or .json.
    #[arg(long)]
    outer_output: PathBuf,
    /// The inner points: .xyz, .txt, .node or .json.
    #[arg(long)]
    inner_output: PathBuf,
}

impl NestedArgs {
    fn params(&self) -> tetrakit::shell::generate::NestedParams {
        tetrakit::shell::generate::NestedParams {
            outer: self.outer,
            inner: self.inner,
            n_outer: self.n_outer,
            n_inner: self.n_inner,
            gap: self.gap,
            seed: self.seed,
        }
    }
}

#[derive(Args, Clone)]
struct PolyOut {
    /// Output file: .off, .obj, .face (with .node) or .json.
    #[arg(long, short)]
    output: PathBuf,
    /// Seed for random choices.
    #[arg(long, default_value_t = 1)]
    seed: u64,
}

#[derive(Args, Clone)]
struct BpArgs {
    /// Vertices of the stacked core (the default is the smallest with which the default
    /// `two-level` hides its second level: with 6 every seed gives one level).
    #[arg(long, default_value_t = 8)]
    core: usize,
    /// BP-nets glued (on the first level).
    #[arg(long, default_value_t = 2)]
    nets: usize,
    /// Path length m of each BP-net is drawn from 3..=MAX_M.
    #[arg(long, default_value_t = 4)]
    max_m: usize,
    /// Tetrahedra stacked on the result (an augmented BP-polyhedron).
    #[arg(long, default_value_t = 2)]
    augment: usize,
    #[command(flatten)]
    out: PolyOut,
}

#[derive(ValueEnum, Clone, Copy, Debug)]
enum CorruptKind {
    /// Remove one segment.
    DropEdge,
    /// Add a segment that crosses a segment or passes through a point.
    AddCrossing,
    /// Add a segment overlapping a collinear one (and, in .ele output, a tetrahedron
    /// overlapping two others).
    AddOverlap,
}

/// A time limit: a finite, non-negative number of seconds (a usage error otherwise,
/// never a panic).
fn seconds(text: &str) -> Result<Duration, String> {
    let x: f64 = text
        .parse()
        .map_err(|_| format!("'{text}' is not a number of seconds"))?;
    Duration::try_from_secs_f64(x)
        .map_err(|_| format!("'{text}' is not a finite, non-negative number of seconds"))
}

fn main() -> ExitCode {
    let cmd = Cli::parse().cmd;
    match in_threads(|| run(cmd)) {
        Ok(verdict) => ExitCode::from(exit::code(verdict)),
        Err(e) => {
            eprintln!("tetrakit: {e}");
            ExitCode::from(2)
        }
    }
}

/// Runs `work` with the parallel passes on their worker threads; where the system refuses
/// a thread (a tight memory or process limit, as batch schedulers set), on this thread
/// alone. rayon would otherwise panic at its first parallel pass, and a panic whose
/// backtrace cannot be allocated deadlocks in the standard library. The pool is the
/// command's own, not rayon's global one, whose builder waits until every worker has
/// started (0.1–0.2 ms of a 9 ms run): work installed here starts on the first one up.
fn in_threads(work: impl FnOnce() -> CmdResult + Send) -> CmdResult {
    if let Ok(pool) = rayon::ThreadPoolBuilder::new().build() {
        return pool.install(work);
    }
    let one = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .use_current_thread()
        .build();
    match one {
        Ok(pool) => pool.install(work),
        Err(e) => Err(exit::CliError::new(format!(
            "cannot start a worker thread: {e}"
        ))),
    }
}

/// Runs one command.
fn run(cmd: Cmd) -> CmdResult {
    match cmd {
        Cmd::Detect(a) => run::detect(&a),
        Cmd::Check(a) => run::check(&a),
        Cmd::Mintetra(a) => poly::mintetra(&a.input, a.json, a.output.as_deref(), a.confirm),
        Cmd::Tetrahedralize(a) if a.hamiltonian => {
            poly::hamiltonian(&a.input, a.time_limit, a.json, a.output.as_deref())
        }
        Cmd::Tetrahedralize(a) => poly::tetrahedralize(poly::TetraArgs {
            input: &a.input,
            minimal: a.minimal,
            unique: a.unique,
            time_limit: a.time_limit,
            as_json: a.json,
            output: a.output.as_deref(),
            proof: a.proof.as_deref(),
        }),
        Cmd::Contains(a) => decide(Question::Contains, &a.input, None, &a.decide),
        Cmd::Constrained(a) => decide(
            Question::Constrained,
            &a.input,
            a.segments.as_deref(),
            &a.decide,
        ),
        Cmd::Skeleton(a) => {
            let output = a.output.as_deref();
            planar::skeleton(
                &a.input,
                a.xy,
                &a.beta,
                a.lune,
                a.json,
                output,
                a.time_limit,
            )
        }
        Cmd::Mwt(a) => planar::mwt(planar::MwtArgs {
            input: &a.input,
            xy: a.xy,
            as_json: a.json,
            output: a.output.as_deref(),
            time_limit: a.time_limit,
        }),
        Cmd::Keil(a) => planar::keil(planar::KeilArgs {
            beta: &a.beta,
            n: a.n,
            as_json: a.json,
            svg: a.svg.as_deref(),
            output: a.output.as_deref(),
            check_random: a.check_random,
            time_limit: a.time_limit,
        }),
        Cmd::Flips(a) => flips::flips(flips::FlipsArgs {
            input: &a.input,
            limit: a.limit,
            time_limit: a.time_limit,
            as_json: a.json,
            output: a.output.as_deref(),
            count_only: a.count_only,
        }),
        Cmd::Shell(a) => shell::shell(shell::ShellArgs {
            outer: &a.outer,
            inner: &a.inner,
            method: match a.method {
                ShellMethod::Cap => tetrakit::shell::Method::Cap,
                ShellMethod::Bigcap => tetrakit::shell::Method::Bigcap,
                ShellMethod::Thesis => tetrakit::shell::Method::Thesis,
            },
            flips: !a.no_flips,
            optimum: a.optimum,
            time_limit: a.time_limit,
            as_json: a.json,
            output: a.output.as_deref(),
        }),
        Cmd::Reduce(ReduceArgs {
            kind:
                ReduceKind::TridToTetrad {
                    input,
                    output,
                    construction,
                    json,
                },
        }) => reduce::trid_to_tetrad(&input, &output, construction, json),
        Cmd::Reduce(ReduceArgs {
            kind:
                ReduceKind::HullGap {
                    input,
                    output,
                    json,
                    time_limit,
                },
        }) => reduce::hull_gap(&input, output.as_deref(), json, time_limit),
        Cmd::Reduce(ReduceArgs {
            kind:
                ReduceKind::QuasiPrism {
                    input,
                    output,
                    json,
                    time_limit,
                },
        }) => reduce::quasi_prism(&input, output.as_deref(), json, time_limit),
        Cmd::Generate(GenerateArgs {
            kind:
                GenKind::QuasiPrism {
                    ring,
                    inner,
                    twist,
                    out,
                },
        }) => reduce::generate_quasi_prism(ring, inner, twist, out.seed, &out.output),
        Cmd::Generate(GenerateArgs {
            kind:
                GenKind::GadgetGrid {
                    rows,
                    cols,
                    layers,
                    twist,
                    spacing,
                    output,
                },
        }) => constrain::generate_gadget_grid(rows, cols, layers, twist, spacing, &output),
        Cmd::Generate(GenerateArgs {
            kind:
                GenKind::Niche {
                    twist,
                    extra,
                    in_view,
                    seed,
                    output,
                },
        }) => constrain::generate_niche(twist, extra, in_view, seed, &output),
        Cmd::Generate(GenerateArgs {
            kind: GenKind::Nested(a),
        }) => shell::generate_nested(&a.params(), &a.out.outer_output, &a.out.inner_output),
        Cmd::Generate(GenerateArgs {
            kind:
                GenKind::Contact {
                    kind,
                    n_outer,
                    n_inner,
                    seed,
                    out,
                },
        }) => shell::generate_contact(
            kind,
            [n_outer, n_inner],
            seed,
            &out.outer_output,
            &out.inner_output,
        ),
        Cmd::Generate(GenerateArgs {
            kind:
                GenKind::BernDisk {
                    ridge,
                    ring,
                    seed,
                    out,
                },
        }) => shell::generate_bern_disk(ridge, ring, seed, &out.outer_output, &out.inner_output),
        Cmd::Generate(GenerateArgs {
            kind: GenKind::Lemma41 { out, as_json },
        }) => shell::generate_lemma41(&out.outer_output, &out.inner_output, as_json),
        Cmd::Generate(GenerateArgs {
            kind:
                GenKind::Points2d {
                    dist,
                    n,
                    seed,
                    output,
                },
        }) => planar::generate_points(dist, n, seed, &output),
        Cmd::Generate(GenerateArgs {
            kind:
                GenKind::Points3d {
                    dist,
                    n,
                    seed,
                    output,
                },
        }) => flips::generate_points(dist, n, seed, &output),
        Cmd::Generate(a) => match polyhedron_kind(a.kind) {
            Ok((kind, out)) => poly::generate(kind, out.seed, &out.output),
            Err(kind) => run::generate(kind),
        },
        Cmd::Demo => demo::run(),
    }
}

fn decide(
    question: Question,
    input: &std::path::Path,
    segments: Option<&std::path::Path>,
    a: &DecideArgs,
) -> CmdResult {
    constrain::run(constrain::Args {
        question,
        input,
        segments,
        minimal: a.minimal,
        time_limit: a.time_limit,
        as_json: a.json,
        output: a.output.as_deref(),
        proof: a.proof.as_deref(),
    })
}

/// Splits the polyhedron generators from the mesh generators.
fn polyhedron_kind(kind: GenKind) -> Result<(poly::PolyGen, PolyOut), GenKind> {
    use tetrakit::polyhedra::generate::BpParams;
    let bp = |a: BpArgs, levels: usize, hide_all: bool| {
        let params = BpParams {
            core: a.core,
            nets: a.nets,
            levels,
            max_m: a.max_m,
            augment: a.augment,
            hide_all,
            seed: a.out.seed,
        };
        (poly::PolyGen::Bp(params), a.out)
    };
    Ok(match kind {
        GenKind::Stacked { n, out } => (poly::PolyGen::Stacked { n }, out),
        GenKind::Bipyramid { m, out } => (poly::PolyGen::Bipyramid { m }, out),
        GenKind::BpPolyhedron(a) => bp(a, 1, false),
        GenKind::TwoLevel(a) => bp(a, 2, false),
        GenKind::HLevel { levels, bp: a } => bp(a, levels, true),
        GenKind::Schonhardt { twist, out } => (poly::PolyGen::Schonhardt { twist }, out),
        GenKind::SchonhardtBp { out } => (poly::PolyGen::SchonhardtBp, out),
        GenKind::ConvexTriangulated {
            shape,
            n,
            facet_points,
            out,
        } => (
            poly::PolyGen::ConvexTriangulated {
                shape,
                n,
                facet_points,
            },
            out,
        ),
        GenKind::SchonhardtTower { layers, twist, out } => {
            (poly::PolyGen::Tower { layers, twist }, out)
        }
        GenKind::Chazelle { grooves, out } => (poly::PolyGen::Chazelle { grooves }, out),
        GenKind::Perturbed { n, dent, out } => (poly::PolyGen::Perturbed { n, dent }, out),
        other => return Err(other),
    })
}
