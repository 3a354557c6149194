use tetrakit::detect::detect;
use tetrakit::generate::*;
use std::time::Instant;
fn main() {
    let cases: Vec<(&str, Box<dyn Fn() -> tetrakit::mesh::Tetrahedralization>)> = vec![
        ("kuhn3", Box::new(|| kuhn(3))),
        ("rand30", Box::new(|| random_tetrahedralization(30, 60, 7, None))),
        ("grid60", Box::new(|| random_tetrahedralization(60, 100, 3, Some(4)))),
        ("skew10", Box::new(|| skew_lines(10))),
        ("sphere", Box::new(|| tetrahedralize_points(cospherical_points(25), 1))),
        ("rand2000", Box::new(|| random_tetrahedralization(2000, 500, 9, None))),
        ("kuhn20", Box::new(|| kuhn(20))),
    ];
    for (name, f) in cases {
        let t = f();
        let e = t.edges();
        let s = Instant::now();
        let d = detect(&t.points, &e).unwrap();
        let r = match &d.result { Ok(_) => "YES".to_string(), Err(w) => format!("NO {:?}", w) };
        println!("{name}: n {} m {} tets {} -> {r} in {:?}", t.points.len(), e.len(), t.tets.len(), s.elapsed());
        for c in [Corruption::DropEdge, Corruption::AddCrossing, Corruption::AddOverlap] {
            if let Some(e2) = corrupt_edges(&t.points, &e, c, 5) {
                let d = detect(&t.points, &e2).unwrap();
                println!("   {c:?}: {}", match &d.result { Ok(_) => "YES".into(), Err(w) => format!("NO {} {}", w.kind, w.detail) });
            }
        }
    }
}
