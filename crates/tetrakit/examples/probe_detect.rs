fn main() {
    let p = std::env::args().nth(1).unwrap();
    let runs: usize = std::env::args()
        .nth(2)
        .map(|s| s.parse().unwrap())
        .unwrap_or(3);
    let inp = tetrakit::io::read_input(std::path::Path::new(&p)).unwrap();
    let segs: Vec<(u32, u32)> = inp.segments.iter().map(|s| (s[0], s[1])).collect();
    for _ in 0..runs {
        let t = std::time::Instant::now();
        let d = tetrakit::detect::detect(&inp.points, &segs).unwrap();
        eprintln!("total {:.3} {:?}", t.elapsed().as_secs_f64(), d.route);
    }
}
