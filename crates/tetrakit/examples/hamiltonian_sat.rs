//! How far SAT over every tetrahedralization reaches (BENCHMARKS.md, "Hamiltonian dual
//! paths"): `tetrakit::dualpath::hamiltonian` with the cones and the enumeration off, on
//! spheres, cylinders and lattice hulls of 10 to 60 points, 3 seeds each, 60 s a set.
//!
//! `cargo run --release -p tetrakit --example hamiltonian_sat [SEEDS]`

use std::time::{Duration, Instant};
use tetrakit::control::{Control, Verdict};
use tetrakit::dualpath::{PathOptions, hamiltonian};
use tetrakit::generate::{Distribution3, points3d};

fn main() {
    let seeds: u64 = std::env::args()
        .nth(1)
        .map_or(3, |s| s.parse().expect("SEEDS"));
    let only_sat = PathOptions {
        cones: false,
        enumerate_up_to: 0,
        sat_up_to: usize::MAX,
        ..PathOptions::default()
    };
    println!("| family | n | path found | tetrahedra (median) | cuts (max) | median s | max s |");
    println!("|---|---|---|---|---|---|---|");
    for (name, dist) in [
        ("convex", Distribution3::Convex),
        ("cylinder", Distribution3::Cylinder),
        ("lattice-hull", Distribution3::LatticeHull),
    ] {
        for n in [10, 20, 30, 40, 50, 60] {
            let (mut found, mut tets, mut cuts, mut secs) = (0, Vec::new(), 0, Vec::new());
            for seed in 1..=seeds {
                let pts = points3d(dist, n, seed);
                let ctl = Control::new().with_time_limit(Duration::from_secs(60));
                let start = Instant::now();
                let o = hamiltonian(&pts, &only_sat, &ctl).expect("a convex polytope");
                secs.push(start.elapsed().as_secs_f64());
                cuts = cuts.max(o.cuts);
                if o.verdict == Verdict::Yes {
                    found += 1;
                    tets.push(o.tetrahedra);
                }
                assert_ne!(o.verdict, Verdict::No, "{name} n = {n} seed {seed}: a NO");
            }
            tets.sort_unstable();
            secs.sort_by(f64::total_cmp);
            let median = tets
                .get(tets.len() / 2)
                .map_or("-".into(), |t| t.to_string());
            println!(
                "| {name} | {n} | {found} / {seeds} | {median} | {cuts} | {:.2} | {:.2} |",
                secs[secs.len() / 2],
                secs[secs.len() - 1]
            );
        }
    }
}
