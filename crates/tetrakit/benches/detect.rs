//! Criterion micro-benchmarks of the library paths (no external tools needed):
//! `cargo bench -p tetrakit`. The comparison with TetGen meshes and CGAL lives in
//! `benches/run.sh` (BENCHMARKS.md).

use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use tetrakit::control::Control;
use tetrakit::detect::Options;
use tetrakit::detect::detect;
use tetrakit::generate;
use tetrakit::geom::Hull3;
use tetrakit::mesh::verify;

fn benches(c: &mut Criterion) {
    let grid = generate::kuhn(12);
    let grid_edges = grid.edges();
    let random = generate::random_tetrahedralization(3000, 3000, 1, None);
    let random_edges = random.edges();
    let skew = generate::skew_lines(200);
    let skew_edges = skew.edges();
    let mut g = c.benchmark_group("detect");
    g.sample_size(10);
    g.bench_function("kuhn 12 (2197 points)", |b| {
        b.iter(|| {
            detect(
                black_box(&grid.points),
                black_box(&grid_edges),
                &Options::default(),
                &Control::new(),
            )
        })
    });
    g.bench_function("random 3000 points", |b| {
        b.iter(|| {
            detect(
                black_box(&random.points),
                black_box(&random_edges),
                &Options::default(),
                &Control::new(),
            )
        })
    });
    g.bench_function("skew lines 200 points", |b| {
        b.iter(|| {
            detect(
                black_box(&skew.points),
                black_box(&skew_edges),
                &Options::default(),
                &Control::new(),
            )
        })
    });
    g.finish();
    let mut g = c.benchmark_group("verify");
    g.sample_size(10);
    g.bench_function("random 3000 points, with hull", |b| {
        b.iter(|| {
            verify(
                black_box(&random.points),
                black_box(&random.tets),
                Some(&Hull3::new(&random.points)),
            )
        })
    });
    g.bench_function("random 3000 points, no hull", |b| {
        b.iter(|| verify(black_box(&random.points), black_box(&random.tets), None))
    });
    g.finish();
}

criterion_group!(detect_benches, benches);
criterion_main!(detect_benches);
