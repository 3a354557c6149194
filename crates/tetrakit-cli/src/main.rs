//! The `tetrakit` command-line tool: a thin layer that parses arguments, calls the
//! library, and prints results. Exit codes: 0 yes, 1 no, 2 bad input or usage.
#![forbid(unsafe_code)]

/// `println!` that ignores write errors: output to a closed pipe (`| head`) must not panic.
macro_rules! out {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        let _ = writeln!(std::io::stdout(), $($arg)*);
    }};
}

mod demo;
mod run;

use clap::{Args, Parser, Subcommand, ValueEnum};
use std::path::PathBuf;
use std::process::ExitCode;

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

#[derive(Subcommand)]
enum Cmd {
    /// Decide whether a set of segments is exactly the edge set of a tetrahedralization
    /// (or, for planar points, of a triangulation).
    Detect(DetectArgs),
    /// Validate a tetrahedral mesh (orientation, face pairing, closed boundary; with
    /// --convex, that it tetrahedralizes the convex hull of its vertices).
    Check(CheckArgs),
    /// Write a generated instance.
    Generate(GenerateArgs),
    /// A short tour on built-in examples.
    Demo,
}

#[derive(Args)]
struct DetectArgs {
    /// X.edge (with X.node beside it), X.ele (its tetrahedra's edges are used), .obj with
    /// `v`/`l` lines, or .json.
    input: PathBuf,
    /// Print one JSON object on stdout.
    #[arg(long)]
    json: bool,
    /// Write the tetrahedralization found: .ele (with .node), .vtk or .json.
    #[arg(long)]
    output: Option<PathBuf>,
}

#[derive(Args)]
struct CheckArgs {
    /// X.ele (with X.node beside it), or .json with "tets".
    input: PathBuf,
    /// Also certify that the mesh tetrahedralizes the convex hull of all its points.
    #[arg(long)]
    convex: bool,
    /// Print one JSON object on stdout.
    #[arg(long)]
    json: bool,
}

#[derive(Args)]
struct GenerateArgs {
    #[command(subcommand)]
    kind: GenKind,
}

#[derive(Args, Clone)]
struct GenCommon {
    /// Output file: .ele (writes .node, .ele and .edge), .edge (with .node), .obj, .json or .vtk.
    #[arg(long, short)]
    output: PathBuf,
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
    /// Points on two skew lines: Θ(n²) tetrahedra, the thesis's worst case for m.
    SkewLines {
        /// Number of points (half on each line).
        #[arg(long)]
        points: usize,
        #[command(flatten)]
        common: GenCommon,
    },
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

fn main() -> ExitCode {
    let cli = Cli::parse();
    let code = match cli.cmd {
        Cmd::Detect(a) => run::detect(&a.input, a.json, a.output.as_deref()),
        Cmd::Check(a) => run::check(&a.input, a.convex, a.json),
        Cmd::Generate(a) => run::generate(a.kind),
        Cmd::Demo => demo::run(),
    };
    ExitCode::from(code)
}
