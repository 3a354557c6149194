//! The constructions of thesis ch. 2 §2.5: Lemma 2.6's flips on polyhedra peeled from
//! tetrahedralizations of points in convex position.

use tetrakit::generate::tetrahedralize_points;
use tetrakit::geom::{Point3, orient3d};
use tetrakit::mesh::{Polyhedron, certify_hull};
use tetrakit::reduce::{HullGapError, hull_gap};
use tetrakit::rng::Rng;

/// The faces of `tets` that only one of them has, oriented outward (the fourth vertex
/// behind).
fn boundary(pts: &[Point3], tets: &[[u32; 4]]) -> Vec<[u32; 3]> {
    let mut count = std::collections::HashMap::new();
    for t in tets {
        for k in 0..4 {
            let mut f: Vec<u32> = (0..4).filter(|&j| j != k).map(|j| t[j]).collect();
            f.sort_unstable();
            count.entry([f[0], f[1], f[2]]).or_insert((0, t[k])).0 += 1;
        }
    }
    count
        .into_iter()
        .filter(|(_, (k, _))| *k == 1)
        .map(|([a, b, c], (_, x))| {
            let p = |v: u32| &pts[v as usize];
            if orient3d(p(a), p(b), p(c), p(x)) > 0 {
                [a, c, b]
            } else {
                [a, b, c]
            }
        })
        .collect()
}

/// Points on a sphere, a tetrahedralization of their hull, some tetrahedra on the
/// boundary peeled off while the rest stays a simple polyhedron on every point: Lemma
/// 2.6's flips fill the gap, and with the rest it tetrahedralizes the hull.
#[test]
fn hull_gap_fills_peeled_hulls() {
    let mut rng = Rng::new(26);
    let mut flipped = 0;
    for k in 0..120 {
        let n = 8 + rng.below(10);
        let pts: Vec<Point3> = (0..n)
            .map(|_| {
                let (z, a) = (2.0 * rng.unit() - 1.0, std::f64::consts::TAU * rng.unit());
                let r = (1.0 - z * z).sqrt();
                [r * a.cos(), r * a.sin(), z]
            })
            .collect();
        let mut tets = tetrahedralize_points(pts.clone(), k).tets;
        for _ in 0..1 + rng.below(tets.len()) {
            let i = rng.below(tets.len());
            let mut rest = tets.clone();
            rest.swap_remove(i);
            let used: std::collections::HashSet<u32> = rest.iter().flatten().copied().collect();
            if used.len() == n && Polyhedron::new(pts.clone(), boundary(&pts, &rest)).is_ok() {
                tets = rest;
            }
        }
        let q = Polyhedron::new(pts.clone(), boundary(&pts, &tets)).unwrap();
        let gap = hull_gap(&q, &tetrakit::control::Control::new())
            .unwrap_or_else(|e| panic!("#{k}: {e}"));
        flipped += gap.len();
        let mut all = tets;
        all.extend(gap);
        assert!(certify_hull(&pts, &all).is_ok(), "#{k}");
    }
    assert!(
        flipped > 200,
        "the peeling left too little to flip: {flipped}"
    );
}

/// A vertex inside the hull is refused (the lemma's condition), naming it.
#[test]
fn hull_gap_needs_every_vertex_on_the_hull() {
    let pts = vec![
        [0.0, 0.0, 0.0],
        [4.0, 0.0, 0.0],
        [0.0, 4.0, 0.0],
        [0.0, 0.0, 4.0],
        [0.5, 0.5, 0.5],
    ];
    // The tetrahedron 0-1-2-3 with its face 1-2-3 dented to the inner point 4.
    let faces = vec![
        [0, 2, 1],
        [0, 1, 3],
        [0, 3, 2],
        [1, 2, 4],
        [2, 3, 4],
        [3, 1, 4],
    ];
    let q = Polyhedron::new(pts, faces).unwrap();
    assert_eq!(
        hull_gap(&q, &tetrakit::control::Control::new()),
        Err(HullGapError::NotHullVertex(4))
    );
}

/// Three points, and four on a circle (whose lifts lie in one plane), are TRID instances
/// the reduction takes (it used to refuse them as "not an upper-hull vertex"), and their
/// triangulations lift to certified tetrahedralizations.
#[test]
fn trid_to_tetrad_takes_tiny_and_cocircular_sets() {
    use tetrakit::reduce::trid_to_tetrad;
    let tri = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
    let r = trid_to_tetrad(&tri, &[[0, 1], [1, 2], [0, 2]]).unwrap();
    assert!(certify_hull(&r.points, &r.lift(&[[0, 1, 2]])).is_ok());
    let square = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]];
    let r = trid_to_tetrad(&square, &[[0, 1], [1, 2], [2, 3], [3, 0], [0, 2]]).unwrap();
    assert!(certify_hull(&r.points, &r.lift(&[[0, 1, 2], [0, 2, 3]])).is_ok());
}

/// Algorithm QUASI-PRISM-TETRAHEDRALIZATION (Lemma 2.7) on 280 lens-shaped quasi-prisms
/// (3–7 ring points, 0–3 inside, twists from −10° to 30°): every staircase is certified
/// (inside `tetrahedralize`), straight prisms take the thesis's vertex order, twisted
/// ones need the SAT orientation, and where no staircase exists or the prism is not
/// regular the exact solver (every edge of the quasi-prism required) decides. On these
/// seeds every quasi-prism without a staircase still has a tetrahedralization (with an
/// interior diagonal), and two irregular ones have none.
#[test]
fn quasi_prisms_by_staircases_and_the_exact_solver() {
    use tetrakit::control::Control;
    use tetrakit::exact::{Domain, Edges, Options, Outcome, solve};
    use tetrakit::reduce::{QuasiPrism, QuasiPrismError};
    let exact = |q: &QuasiPrism| {
        let poly = q.boundary().ok()?;
        let req = q.edges();
        let edges = Edges {
            allowed: None,
            required: &req,
        };
        let opts = Options {
            any: true,
            ..Options::default()
        };
        let (out, _) = solve(Domain::Polyhedron(&poly), edges, &opts, &Control::new()).unwrap();
        Some(!matches!(out, Outcome::Infeasible))
    };
    let (mut by_order, mut by_sat, mut no_staircase, mut irregular_no) = (0, 0, 0, 0);
    for seed in 0..40u64 {
        for &twist in &[0.0, 2.0, 5.0, 10.0, 20.0, 30.0, -10.0] {
            let q = QuasiPrism::lens(
                3 + (seed % 5) as usize,
                (seed / 5 % 4) as usize,
                twist,
                seed,
            );
            match q.tetrahedralize(&Control::new()) {
                Ok(s) => {
                    assert_eq!(s.tets.len(), 3 * q.triangles.len());
                    assert_eq!(s.by_order, twist == 0.0, "seed {seed}, twist {twist}");
                    if s.by_order {
                        by_order += 1
                    } else {
                        by_sat += 1
                    }
                }
                Err(QuasiPrismError::NoStaircase) => {
                    assert_eq!(exact(&q), Some(true), "seed {seed}, twist {twist}");
                    no_staircase += 1;
                }
                Err(QuasiPrismError::Irregular { .. }) => {
                    assert_ne!(twist, 0.0);
                    irregular_no += usize::from(exact(&q) == Some(false));
                }
                Err(QuasiPrismError::NoConvexDiagonal(_)) => assert!(twist >= 20.0),
                Err(e) => panic!("seed {seed}, twist {twist}: {e}"),
            }
        }
    }
    assert_eq!(
        (by_order, by_sat, no_staircase, irregular_no),
        (40, 87, 62, 2)
    );
}

/// Each way an input fails to be a quasi-prism is its own typed error, and a stopped
/// control is reached through `source()`.
#[test]
fn quasi_prism_inputs_are_refused_by_kind() {
    use tetrakit::reduce::{NotQuasiPrism as E, QuasiPrism, QuasiPrismError};
    let up =
        |n: usize| -> Vec<Point3> { (0..n).map(|i| [i as f64, (i * i) as f64, 1.0]).collect() };
    let down =
        |n: usize| -> Vec<Point3> { (0..n).map(|i| [i as f64, (i * i) as f64, 0.0]).collect() };
    let refused = |n: usize, m: usize, t: Vec<[u32; 3]>| match QuasiPrism::new(up(n), down(m), t) {
        Err(QuasiPrismError::Input(e)) => e,
        other => panic!("{:?}", other.map(|q| q.n())),
    };
    assert_eq!(
        refused(3, 2, vec![[0, 1, 2]]),
        E::Sizes { upper: 3, lower: 2 }
    );
    assert_eq!(refused(3, 3, vec![]), E::NoTriangles);
    assert_eq!(
        refused(3, 3, vec![[0, 1, 5]]),
        E::NotUpper {
            triangle: 0,
            vertex: 5
        }
    );
    assert_eq!(refused(3, 3, vec![[0, 0, 1]]), E::RepeatedVertex(0));
    assert_eq!(
        refused(3, 3, vec![[0, 1, 2], [2, 1, 0]]),
        E::RepeatedTriangle(1)
    );
    assert_eq!(refused(4, 4, vec![[0, 1, 2]]), E::Unused(3));
    let fan = vec![[0, 1, 2], [0, 1, 3], [0, 1, 4]];
    assert_eq!(refused(5, 5, fan), E::NonManifoldEdge([0, 1]));
    assert_eq!(refused(6, 6, vec![[0, 1, 2], [3, 4, 5]]), E::NotDisk);
    // The sentence names the vertex in the library's numbering.
    let e = QuasiPrismError::Input(E::Unused(3));
    assert_eq!(
        e.to_string(),
        "not a quasi-prism: vertex #3 is on no triangle"
    );
    assert!(std::error::Error::source(&e).is_some());
}
