//! Differential tests: `detect` against the brute-force oracle (Theorem 2.1's L-empty
//! tetrahedra) on thousands of small random and degenerate instances, valid and corrupted.
//! Every crossing witness is checked independently, and every YES pins Euler's count
//! t = |L| − n − n_b + 3 (Theorem 2.3, condition 3, with n_b the points on the hull).

use tetrakit::control::Control;
use tetrakit::detect::{
    Answer, Cells, LinkMethod, Options, WitnessKind, detect, oracle::forms_tetrahedralization,
};
use tetrakit::generate::{cospherical_points, random_flips, random_points, tetrahedralize_points};
use tetrakit::geom::{Hull3, Point3, orient2d, point_in_segment_interior, segments_meet};
use tetrakit::mesh::Tetrahedralization;
use tetrakit::rng::Rng;

#[derive(Default)]
struct Tally {
    yes: usize,
    no: usize,
}

/// Runs `detect` with both link methods (the sign table and the sphere sweep), with and
/// without the Delaunay proposal first, against the oracle.
fn check(points: &[Point3], edges: &[[u32; 2]], tally: &mut Tally, what: &str) {
    let expected = forms_tetrahedralization(points, edges);
    for (delaunay_first, links) in [
        (false, LinkMethod::SignTable),
        (false, LinkMethod::Sweep),
        (true, LinkMethod::Sweep),
    ] {
        let opts = Options {
            delaunay_first,
            links,
        };
        check_method(points, edges, expected, opts, &format!("{what} ({opts:?})"));
    }
    if expected {
        tally.yes += 1;
    } else {
        tally.no += 1;
    }
}

fn check_method(points: &[Point3], edges: &[[u32; 2]], expected: bool, opts: Options, what: &str) {
    let d = detect(points, edges, &opts, &Control::new()).expect("well-formed input");
    assert_eq!(
        d.is_yes(),
        expected,
        "{what}: detect says {:?}\npoints {points:?}\nedges {edges:?}",
        d.answer.witness()
    );
    match &d.answer {
        Answer::Yes(Cells::Tetrahedra(t)) => {
            let hull = Hull3::new(points);
            let nb = (0..points.len()).filter(|&i| hull.on_boundary(i)).count();
            assert_eq!(
                t.len() as i64,
                edges.len() as i64 - points.len() as i64 - nb as i64 + 3,
                "{what}: Euler count"
            );
        }
        Answer::Yes(Cells::Triangles(t)) => {
            assert_eq!(
                t.len(),
                edges.len() + 1 - points.len(),
                "{what}: planar Euler count"
            );
        }
        Answer::Undecided => panic!("{what}: undecided without a limit"),
        Answer::No(w) => {
            let p = |i: u32| &points[i as usize];
            match w.kind {
                WitnessKind::CrossingSegments => {
                    let [s, t] = [w.segments[0], w.segments[1]];
                    assert!(
                        segments_meet(p(s[0]), p(s[1]), p(t[0]), p(t[1])).is_some(),
                        "{what}: bogus crossing {w:?}"
                    );
                }
                WitnessKind::VertexOnSegment => {
                    let s = w.segments[0];
                    assert!(
                        point_in_segment_interior(p(w.vertices[0]), p(s[0]), p(s[1])),
                        "{what}: bogus {w:?}"
                    );
                }
                _ => assert!(!w.detail.is_empty()),
            }
        }
    }
}

fn sorted_edges(e: &[[u32; 2]]) -> Vec<[u32; 2]> {
    let mut e: Vec<[u32; 2]> = e.iter().map(|&[a, b]| [a.min(b), a.max(b)]).collect();
    e.sort_unstable();
    e.dedup();
    e
}

/// The valid instance, then one with a random edge removed and one with a random non-edge
/// added (the oracle decides whether those are still valid: an added edge may be a flip).
fn check_with_variants(
    points: &[Point3],
    edges: &[[u32; 2]],
    rng: &mut Rng,
    tally: &mut Tally,
    what: &str,
) {
    check(points, edges, tally, what);
    if edges.len() > 1 {
        let mut e = edges.to_vec();
        e.remove(rng.below(e.len()));
        check(points, &e, tally, &format!("{what} minus an edge"));
    }
    let n = points.len() as u32;
    let non: Vec<[u32; 2]> = (0..n)
        .flat_map(|a| (a + 1..n).map(move |b| [a, b]))
        .filter(|x| !edges.contains(x))
        .collect();
    if !non.is_empty() {
        let mut e = edges.to_vec();
        e.push(non[rng.below(non.len())]);
        check(
            points,
            &sorted_edges(&e),
            tally,
            &format!("{what} plus an edge"),
        );
    }
}

fn tet_instance(points: Vec<Point3>, flips: usize, seed: u64) -> Option<Tetrahedralization> {
    let mut t = tetrahedralize_points(points, seed);
    if t.tets.is_empty() {
        return None;
    }
    random_flips(&mut t, flips, seed);
    Some(t)
}

#[test]
fn random_float_tetrahedralizations() {
    let mut rng = Rng::new(1);
    let mut tally = Tally::default();
    for seed in 0..200 {
        let n = 5 + rng.below(6);
        let t = tet_instance(random_points(n, seed, None), rng.below(3 * n), seed).unwrap();
        check_with_variants(
            &t.points,
            &t.edges(),
            &mut rng,
            &mut tally,
            &format!("float seed {seed}"),
        );
    }
    assert!(
        tally.yes >= 200 && tally.no >= 150,
        "yes {} no {}",
        tally.yes,
        tally.no
    );
}

#[test]
fn random_grid_tetrahedralizations_degenerate() {
    let mut rng = Rng::new(2);
    let mut tally = Tally::default();
    for seed in 0..250 {
        let n = 5 + rng.below(6);
        let pts = random_points(n, 1000 + seed, Some(3));
        if let Some(t) = tet_instance(pts, rng.below(3 * n), seed) {
            check_with_variants(
                &t.points,
                &t.edges(),
                &mut rng,
                &mut tally,
                &format!("grid seed {seed}"),
            );
        }
    }
    assert!(
        tally.yes >= 200 && tally.no >= 200,
        "yes {} no {}",
        tally.yes,
        tally.no
    );
}

#[test]
fn cospherical_subsets() {
    let mut rng = Rng::new(3);
    let mut tally = Tally::default();
    for (k, r2) in [9i64, 25].into_iter().cycle().take(200).enumerate() {
        let mut pool = cospherical_points(r2);
        rng.shuffle(&mut pool);
        pool.truncate(5 + rng.below(6));
        if let Some(t) = tet_instance(pool, rng.below(20), k as u64) {
            check_with_variants(
                &t.points,
                &t.edges(),
                &mut rng,
                &mut tally,
                &format!("cospherical {k}"),
            );
        }
    }
    assert!(tally.yes >= 150, "yes {} no {}", tally.yes, tally.no);
}

#[test]
fn random_segment_sets() {
    let mut rng = Rng::new(4);
    let mut tally = Tally::default();
    for seed in 0..400 {
        let n = 4 + rng.below(4);
        let grid = if seed % 2 == 0 { Some(3) } else { None };
        let pts = random_points(n, 5000 + seed, grid);
        let density = 0.5 + rng.unit() * 0.5;
        let mut e = Vec::new();
        for a in 0..n as u32 {
            for b in a + 1..n as u32 {
                if rng.unit() < density {
                    e.push([a, b]);
                }
            }
        }
        if !e.is_empty() {
            check(&pts, &e, &mut tally, &format!("random graph {seed}"));
        }
    }
    assert!(
        tally.yes >= 20 && tally.no >= 200,
        "yes {} no {}",
        tally.yes,
        tally.no
    );
}

#[test]
fn kuhn_cube_single_edge_edits() {
    let t = tetrakit::generate::kuhn(1);
    let e = t.edges();
    let mut tally = Tally::default();
    check(&t.points, &e, &mut tally, "kuhn");
    for i in 0..e.len() {
        let mut f = e.clone();
        f.remove(i);
        check(
            &t.points,
            &f,
            &mut tally,
            &format!("kuhn without {:?}", e[i]),
        );
    }
    for a in 0..8u32 {
        for b in a + 1..8 {
            if !e.contains(&[a, b]) {
                let mut f = e.clone();
                f.push([a, b]);
                check(
                    &t.points,
                    &sorted_edges(&f),
                    &mut tally,
                    &format!("kuhn with {a}-{b}"),
                );
            }
        }
    }
    assert_eq!(
        tally.yes, 1,
        "only the cube itself; flips of Kuhn cubes are planar-blocked"
    );
}

/// A 2D placing triangulation (lexicographic insertion, exact) on points of a plane.
fn planar_triangulation(p2: &[[f64; 2]]) -> Option<Vec<[u32; 2]>> {
    let mut idx: Vec<u32> = (0..p2.len() as u32).collect();
    let q = |i: u32| &p2[i as usize];
    idx.sort_by(|&a, &b| {
        q(a)[0]
            .total_cmp(&q(b)[0])
            .then(q(a)[1].total_cmp(&q(b)[1]))
    });
    let k = (2..idx.len()).find(|&k| orient2d(q(idx[0]), q(idx[1]), q(idx[k])) != 0)?;
    let mut tris: Vec<[u32; 3]> = Vec::new();
    for w in idx[..k].windows(2) {
        let (a, b, c) = (w[0], w[1], idx[k]);
        tris.push(if orient2d(q(a), q(b), q(c)) > 0 {
            [a, b, c]
        } else {
            [a, c, b]
        });
    }
    for &x in &idx[k + 1..] {
        let mut dir: Vec<[u32; 2]> = tris
            .iter()
            .flat_map(|t| [[t[0], t[1]], [t[1], t[2]], [t[2], t[0]]])
            .collect();
        dir.sort_unstable();
        let boundary: Vec<[u32; 2]> = dir
            .iter()
            .copied()
            .filter(|&[a, b]| dir.binary_search(&[b, a]).is_err())
            .collect();
        for [a, b] in boundary {
            if orient2d(q(a), q(b), q(x)) < 0 {
                tris.push([b, a, x]);
            }
        }
    }
    let e: Vec<[u32; 2]> = tris
        .iter()
        .flat_map(|t| [[t[0], t[1]], [t[1], t[2]], [t[2], t[0]]])
        .collect();
    Some(sorted_edges(&e))
}

#[test]
fn planar_triangulations() {
    let mut rng = Rng::new(5);
    let mut tally = Tally::default();
    for seed in 0..300 {
        let n = 3 + rng.below(7);
        let mut p2: Vec<[f64; 2]> = Vec::new();
        while p2.len() < n {
            let c = [rng.below(4) as f64, rng.below(4) as f64];
            if !p2.contains(&c) {
                p2.push(c);
            }
        }
        let Some(edges) = planar_triangulation(&p2) else {
            continue;
        };
        // Half on z = 0, half on the tilted plane z = x + 2y (projection must be exact).
        let pts: Vec<Point3> = p2
            .iter()
            .map(|c| {
                if seed % 2 == 0 {
                    [c[0], c[1], 0.0]
                } else {
                    [c[0], c[1], c[0] + 2.0 * c[1]]
                }
            })
            .collect();
        check_with_variants(
            &pts,
            &edges,
            &mut rng,
            &mut tally,
            &format!("planar {seed}"),
        );
    }
    assert!(
        tally.yes >= 250 && tally.no >= 250,
        "yes {} no {}",
        tally.yes,
        tally.no
    );
}

/// The Delaunay route: on Delaunay edge sets in general position it answers (with exactly
/// the brute-force Delaunay tetrahedra), and every variant gets the oracle's verdict from
/// all routes (`check`).
#[test]
fn delaunay_route_on_delaunay_edge_sets() {
    use tetrakit::detect::{Route, oracle::delaunay_tetrahedra};
    let mut rng = Rng::new(7);
    let mut tally = Tally::default();
    let mut by_delaunay = 0;
    for case in 0..300 {
        let n = 5 + case % 14;
        let points = random_points(n, case as u64 + 1, None);
        let Some(mut tets) = delaunay_tetrahedra(&points) else {
            continue;
        };
        let edges = tetrakit::mesh::edges_of(&tets);
        let d = detect(&points, &edges, &Options::default(), &Control::new()).unwrap();
        let Answer::Yes(Cells::Tetrahedra(mut found)) = d.answer else {
            panic!("case {case}: the Delaunay edge set is rejected");
        };
        assert_eq!(d.route, Route::Delaunay, "case {case}");
        by_delaunay += 1;
        for t in tets.iter_mut().chain(found.iter_mut()) {
            t.sort_unstable();
        }
        tets.sort_unstable();
        found.sort_unstable();
        assert_eq!(found, tets, "case {case}");
        check_with_variants(
            &points,
            &edges,
            &mut rng,
            &mut tally,
            &format!("Delaunay {case}"),
        );
    }
    assert!(
        by_delaunay >= 290 && tally.no > 100,
        "{by_delaunay} {}",
        tally.no
    );
}

/// The Delaunay proposal withdraws on cospherical and coplanar input and fails
/// certification on valid non-Delaunay tetrahedralizations; the thesis's algorithm then
/// answers YES.
#[test]
fn delaunay_route_falls_back_to_links() {
    use tetrakit::detect::Route;
    let mut links = 0;
    let mut instances = vec![tetrakit::generate::kuhn(3)];
    for seed in 0..40 {
        instances.extend(tet_instance(random_points(12, seed, None), 30, seed));
    }
    for t in &instances {
        let d = detect(&t.points, &t.edges(), &Options::default(), &Control::new()).unwrap();
        assert!(d.is_yes());
        links += usize::from(d.route == Route::Links);
    }
    assert!(links >= 20, "{links} of {}", instances.len());
}
