//! Where the NOs of convex polyhedra with triangulated facets happen (thesis ch. 6):
//! for each family of `generate convex-triangulated`, the NOs that need the SAT
//! refutation and the size of a minimal core of it (`exact::face_core`: facets to
//! cover, inner faces to pair, their vertices). `cargo run --release -p tetrakit
//! --example no_cores [SEEDS]`; the table is in BENCHMARKS.md.

use tetrakit::control::Control;
use tetrakit::exact::{Domain, WitnessKind, face_core, tetrahedralize};
use tetrakit::polyhedra::generate::{ConvexShape, convex_triangulated};

fn main() {
    let seeds: u64 = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(100);
    println!(
        "| shape | n | facet points | vertices | SAT NOs | core vertices: min / median / max | at most 6 | core facets / faces (median) | s per core (max) |"
    );
    println!("|---|---|---|---|---|---|---|---|---|");
    let families = [
        (ConvexShape::Prism, 4, 0),
        (ConvexShape::Prism, 6, 0),
        (ConvexShape::Prism, 8, 0),
        (ConvexShape::Prism, 12, 0),
        (ConvexShape::Prism, 12, 2),
        (ConvexShape::Cube, 0, 0),
        (ConvexShape::Cube, 0, 2),
        (ConvexShape::Cube, 0, 4),
    ];
    let ctl = Control::new();
    for (shape, n, fp) in families {
        let (mut sizes, mut parts, mut worst, mut vertices) = (Vec::new(), Vec::new(), 0f64, 0);
        for seed in 0..seeds {
            let p = convex_triangulated(shape, n, fp, seed).expect("a polyhedron");
            vertices = p.points.len();
            let o = tetrahedralize(Domain::Polyhedron(&p), Default::default(), &ctl).unwrap();
            if o.witness.map(|w| w.kind) != Some(WitnessKind::Unsatisfiable) {
                continue;
            }
            let t = std::time::Instant::now();
            let core = face_core(&p, &ctl).unwrap().expect("a NO has a core");
            worst = worst.max(t.elapsed().as_secs_f64());
            sizes.push(core.vertices.len());
            parts.push((core.facets.len(), core.faces.len()));
        }
        sizes.sort_unstable();
        parts.sort_unstable();
        let median = |v: &[usize]| v.get(v.len() / 2).copied().unwrap_or(0);
        let local = sizes.iter().filter(|&&k| k <= 6).count();
        let (f, g) = parts.get(parts.len() / 2).copied().unwrap_or((0, 0));
        let name = format!("{shape:?}").to_lowercase();
        println!(
            "| {name} | {n} | {fp} | {vertices} | {} / {seeds} | {} / {} / {} | {local} | {f} / {g} | {worst:.3} |",
            sizes.len(),
            sizes.first().unwrap_or(&0),
            median(&sizes),
            sizes.last().unwrap_or(&0),
        );
    }
}
