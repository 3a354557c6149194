fn main() {
    for p in std::env::args().skip(1) {
        for _ in 0..3 {
            let t = std::time::Instant::now();
            let inp = tetrakit::io::read_input(std::path::Path::new(&p)).unwrap();
            eprintln!(
                "{p}: {:.3} s ({} pts, {} segs)",
                t.elapsed().as_secs_f64(),
                inp.points.len(),
                inp.segments.len()
            );
        }
    }
}
