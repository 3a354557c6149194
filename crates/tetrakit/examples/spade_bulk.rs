//! The peer measurement of BENCHMARKS.md: `spade`'s bulk Delaunay triangulation of a
//! planar point file, timed alone (median of `RUNS`, default 3), printed in seconds.

use spade::{DelaunayTriangulation, Point2, Triangulation};
use std::time::Instant;

fn main() {
    let path = std::env::args()
        .nth(1)
        .expect("usage: spade_bulk POINTS.xyz");
    let runs: usize = std::env::var("RUNS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(3);
    let input = tetrakit::io::read_input(std::path::Path::new(&path)).expect("readable points");
    let pts: Vec<Point2<f64>> = input
        .points
        .iter()
        .map(|p| Point2::new(p[0], p[1]))
        .collect();
    let mut times: Vec<f64> = (0..runs)
        .map(|_| {
            let t = Instant::now();
            let dt =
                DelaunayTriangulation::<Point2<f64>>::bulk_load(pts.clone()).expect("valid points");
            let s = t.elapsed().as_secs_f64();
            assert_eq!(dt.num_vertices(), pts.len());
            s
        })
        .collect();
    times.sort_by(f64::total_cmp);
    println!("{:.4}", times[times.len() / 2]);
}
