fn main() {
    let n: usize = std::env::args().nth(1).unwrap().parse().unwrap();
    let dist = match std::env::args().nth(2).as_deref() {
        Some("clustered") => tetrakit::planar::Distribution::Clustered,
        Some("gaussian") => tetrakit::planar::Distribution::Gaussian,
        _ => tetrakit::planar::Distribution::Uniform,
    };
    let pts = tetrakit::planar::points2d(dist, n, 1);
    for _ in 0..3 {
        let t = std::time::Instant::now();
        let c = tetrakit::planar::candidate_edges(&pts).unwrap();
        eprintln!(
            "n {n}: {} candidates in {:.3} s",
            c.len(),
            t.elapsed().as_secs_f64()
        );
    }
}
