//! Where the NOs of convex polyhedra with triangulated facets happen (thesis ch. 6):
//! for each family of `generate convex-triangulated`, the NOs that need the SAT
//! refutation, the size of a minimal core of it (`exact::face_core`: facets to cover,
//! inner faces to pair, their vertices), and the fewest vertices any core has
//! (`exact::smallest_core`: every vertex set searched up to all of them on polyhedra of
//! at most 12 vertices, up to 6 beyond). `cargo run --release -p tetrakit --example
//! no_cores [SEEDS]`; the table is in BENCHMARKS.md.

use tetrakit::control::Control;
use tetrakit::exact::{Domain, WitnessKind, face_core, smallest_core, tetrahedralize};
use tetrakit::polyhedra::generate::{ConvexShape, convex_triangulated};

/// A smallest core's size, or "more than `most`" when none was found up to it.
fn shown_k(k: usize, most: usize) -> String {
    match k > most {
        true => format!("every core has more than {most} vertices"),
        false => format!("the smallest core has {k} vertices"),
    }
}

fn main() {
    let seeds: u64 = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(100);
    println!(
        "| shape | n | facet points | vertices | SAT NOs | minimal core vertices: min / median / max | at most 6 | core facets / faces (median) | smallest core vertices: min / median / max | a core of at most 6 | s per smallest core (max) |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|---|");
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
    let mut wide = Vec::new();
    for (shape, n, fp) in families {
        let (mut sizes, mut parts, mut worst, mut vertices) = (Vec::new(), Vec::new(), 0f64, 0);
        let mut least = Vec::new();
        for seed in 0..seeds {
            let p = convex_triangulated(shape, n, fp, seed).expect("a polyhedron");
            vertices = p.points.len();
            let o = tetrahedralize(Domain::Polyhedron(&p), Default::default(), &ctl).unwrap();
            if o.witness.map(|w| w.kind) != Some(WitnessKind::Unsatisfiable) {
                continue;
            }
            let core = face_core(&p, &ctl).unwrap().expect("a NO has a core");
            sizes.push(core.vertices.len());
            parts.push((core.facets.len(), core.faces.len()));
            let most = if vertices <= 12 { vertices } else { 6 };
            let t = std::time::Instant::now();
            let s = smallest_core(&p, most, &ctl).unwrap().expect("a NO");
            worst = worst.max(t.elapsed().as_secs_f64());
            // More than `most` when no set of at most `most` vertices is a core.
            let k = s.core.map_or(most + 1, |c| c.vertices.len());
            if k > 6 {
                wide.push(format!(
                    "{shape:?} n={n} facet-points={fp} seed={seed}: {}",
                    shown_k(k, most)
                ));
            }
            least.push(k);
        }
        sizes.sort_unstable();
        parts.sort_unstable();
        least.sort_unstable();
        let shown = |k: usize| match k > 6 && vertices > 12 {
            true => "> 6".to_string(),
            false => k.to_string(),
        };
        let small = least.iter().filter(|&&k| k <= 6).count();
        let median = |v: &[usize]| v.get(v.len() / 2).copied().unwrap_or(0);
        let local = sizes.iter().filter(|&&k| k <= 6).count();
        let (f, g) = parts.get(parts.len() / 2).copied().unwrap_or((0, 0));
        let name = format!("{shape:?}").to_lowercase();
        println!(
            "| {name} | {n} | {fp} | {vertices} | {} / {seeds} | {} / {} / {} | {local} | {f} / {g} | {} / {} / {} | {small} | {worst:.3} |",
            sizes.len(),
            sizes.first().unwrap_or(&0),
            median(&sizes),
            sizes.last().unwrap_or(&0),
            shown(least.first().copied().unwrap_or(0)),
            shown(median(&least)),
            shown(least.last().copied().unwrap_or(0)),
        );
    }
    println!();
    println!("NOs that no set of at most 6 vertices refutes:");
    for w in wide {
        println!("  {w}");
    }
}
