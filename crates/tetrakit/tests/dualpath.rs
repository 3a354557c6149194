//! Hamiltonian dual paths (thesis ch. 6): on random spheres, cylinders and lattice
//! polytopes the cone method finds one, checked here independently; what it cannot take
//! is said.

use std::collections::HashSet;
use tetrakit::control::{Control, Verdict};
use tetrakit::dualpath::{PathError, PathOptions, hamiltonian};
use tetrakit::generate::{Distribution3, points3d};
use tetrakit::geom::{Hull3, Point3};

/// The order checked without the library's own check: every pair in a row shares three
/// corners, every tetrahedron appears once, and the verifier accepts the set.
fn check(pts: &[Point3], tets: &[[u32; 4]]) {
    for w in tets.windows(2) {
        let shared = w[1].iter().filter(|v| w[0].contains(v)).count();
        assert_eq!(shared, 3, "{:?} then {:?}", w[0], w[1]);
    }
    let distinct: HashSet<[u32; 4]> = tets
        .iter()
        .map(|t| {
            let mut s = *t;
            s.sort_unstable();
            s
        })
        .collect();
    assert_eq!(distinct.len(), tets.len());
    let report = tetrakit::mesh::verify(pts, tets, Some(&Hull3::new(pts)));
    assert!(report.problems.is_empty(), "{:?}", report.problems.first());
}

/// The convex polytopes the tests draw from.
const FAMILIES: [Distribution3; 3] = [
    Distribution3::Convex,
    Distribution3::Cylinder,
    Distribution3::LatticeHull,
];

#[test]
fn every_family_gets_a_path() {
    let mut found = 0;
    for dist in FAMILIES {
        for seed in 0..40u64 {
            let n = 6 + (seed as usize * 7) % 55;
            let pts = points3d(dist, n, seed);
            let o = hamiltonian(&pts, &PathOptions::default(), &Control::new()).unwrap();
            assert_eq!(o.verdict, Verdict::Yes, "{dist:?} n = {n} seed {seed}");
            assert!(o.certified && o.tetrahedra == o.tets.len());
            assert!(o.tetrahedra >= o.ordinary_tetrahedra.unwrap());
            check(&pts, &o.tets);
            found += 1;
        }
    }
    assert_eq!(found, 120);
}

/// Each route where the one before it is turned off or cannot go: a cone decided by
/// SAT with no depth-first budget; the enumeration with the cones off; SAT over every
/// tetrahedralization where no apex is eligible (two points inside every facet); a time
/// limit already passed leaves it UNDECIDED, with nothing claimed; a point inside the
/// hull is refused.
#[test]
fn each_route_answers_where_the_last_cannot() {
    let mut cube: Vec<Point3> = (0..8)
        .map(|i| {
            [
                (i & 1) as f64 * 2.0,
                (i >> 1 & 1) as f64 * 2.0,
                (i >> 2) as f64 * 2.0,
            ]
        })
        .collect();
    let ctl = Control::new();
    let opts = PathOptions::default();
    let no_budget = PathOptions { budget: 0, ..opts };
    let o = hamiltonian(&cube, &no_budget, &ctl).unwrap();
    assert_eq!((o.verdict, o.found_by), (Verdict::Yes, Some("cone")));
    check(&cube, &o.tets);
    // The cones off, the enumeration finds one among the cube's 74 and stops there.
    let enumerate = PathOptions {
        cones: false,
        ..opts
    };
    let o = hamiltonian(&cube, &enumerate, &ctl).unwrap();
    assert_eq!((o.verdict, o.found_by), (Verdict::Yes, Some("enumeration")));
    let e = o.enumerated.unwrap();
    assert!(
        (1..=74).contains(&e.tetrahedralizations) && !e.complete,
        "{e:?}"
    );
    check(&cube, &o.tets);
    for k in 0..3 {
        for side in [0.0, 2.0] {
            for y in [0.5, 1.5] {
                let mut p = [1.0, y, 1.0];
                p.rotate_right(k);
                p[k] = side;
                cube.push(p);
            }
        }
    }
    let o = hamiltonian(&cube, &opts, &ctl).unwrap();
    assert_eq!(
        (o.verdict, o.found_by, o.apexes, o.ordinary_tetrahedra),
        (Verdict::Yes, Some("sat"), 0, None)
    );
    check(&cube, &o.tets);
    let past = Control::new().with_time_limit(std::time::Duration::ZERO);
    let o = hamiltonian(&cube, &opts, &past).unwrap();
    assert_eq!(o.verdict, Verdict::Undecided);
    assert!(o.tets.is_empty() && !o.certified && o.witness.is_none());
    cube.push([1.0, 1.0, 1.0]);
    assert_eq!(
        hamiltonian(&cube, &opts, &ctl),
        Err(PathError::Inside { index: 20 })
    );
}

/// SAT over every tetrahedralization at once (the cones and the enumeration off): on
/// spheres, cylinders and lattice hulls of 5 to 30 points, a path, certified and checked
/// here. A NO here would answer the thesis's open question for that set.
#[test]
fn sat_over_every_tetrahedralization_finds_a_path() {
    let only = PathOptions {
        cones: false,
        enumerate_up_to: 0,
        sat_up_to: 30,
        ..PathOptions::default()
    };
    let ctl = Control::new();
    for dist in FAMILIES {
        for seed in 0..10u64 {
            let n = 5 + (seed as usize * 11) % 26;
            let pts = points3d(dist, n, seed);
            let o = hamiltonian(&pts, &only, &ctl).unwrap();
            assert_eq!(
                (o.verdict, o.found_by),
                (Verdict::Yes, Some("sat")),
                "{dist:?} n = {n} seed {seed}: {:?}",
                o.witness
            );
            check(&pts, &o.tets);
        }
    }
}

/// Every tetrahedralization enumerated, each one's dual searched completely (the cones
/// off): on small spheres, cylinders, lattice hulls and prisms with points on their
/// facets, a path is found, certified and checked here, the enumeration stopping there;
/// streamed, the count is the flip graph's.
/// A NO here would answer the thesis's open question for that set: the test says so.
#[test]
fn the_enumeration_finds_a_path_where_the_cones_are_not_asked() {
    let only = PathOptions {
        cones: false,
        ..PathOptions::default()
    };
    let ctl = Control::new();
    let mut sets: Vec<Vec<Point3>> = Vec::new();
    for dist in FAMILIES {
        for seed in 0..12u64 {
            sets.push(points3d(dist, 5 + (seed as usize % 5), seed));
        }
    }
    // A triangular prism with a point inside each square facet.
    let mut prism: Vec<Point3> = (0..6)
        .map(|i| {
            let a = [[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]][i % 3];
            [a[0], a[1], 4.0 * (i / 3) as f64]
        })
        .collect();
    prism.extend([[2.0, 0.0, 2.0], [0.0, 2.0, 2.0], [2.0, 2.0, 2.0]]);
    sets.push(prism);
    for pts in &sets {
        let o = hamiltonian(pts, &only, &ctl).unwrap();
        assert_eq!(
            o.verdict,
            Verdict::Yes,
            "no path among all of {pts:?}: {:?}",
            o.witness
        );
        assert_eq!(o.found_by, Some("enumeration"));
        check(pts, &o.tets);
        let all = tetrakit::flipgraph::tetrahedralizations(pts, usize::MAX, &ctl).unwrap();
        let e = o.enumerated.unwrap();
        assert!((1..=all.len()).contains(&e.tetrahedralizations) && !e.complete);
        // Streamed, nothing kept: the same count as the enumeration that keeps them.
        let count =
            tetrakit::flipgraph::for_each_tetrahedralization(pts, usize::MAX, &ctl, |_| true);
        assert_eq!(count.unwrap(), (None, all.len()));
    }
}

/// The octahedron's Kleetope (a pyramid on each facet): each octahedron vertex has
/// three neighbours of degree 3, so its cone's base has three leaves and no path; SAT
/// proves it for all six, and a cone from a pyramid's apex has one.
#[test]
fn a_kleetope_refutes_the_cones_of_its_original_vertices() {
    let mut klee: Vec<Point3> = (0..6)
        .map(|i| {
            let mut p = [0.0; 3];
            p[i % 3] = if i < 3 { 1.0 } else { -1.0 };
            p
        })
        .collect();
    klee.extend((0..8).map(|s| [0, 1, 2].map(|k| if s >> k & 1 == 1 { 0.4 } else { -0.4 })));
    let o = hamiltonian(&klee, &PathOptions::default(), &Control::new()).unwrap();
    assert_eq!(
        (o.verdict, o.found_by, o.cones_refuted),
        (Verdict::Yes, Some("cone"), 6)
    );
    assert!(o.apex.is_some_and(|v| v >= 6), "{:?}", o.apex);
    check(&klee, &o.tets);
}

/// Four points: one tetrahedron, a path of one, by every route.
#[test]
fn one_tetrahedron_is_a_path_by_every_route() {
    let tet: Vec<Point3> = vec![
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
    ];
    let defaults = PathOptions::default();
    let routes = [
        defaults,
        PathOptions {
            cones: false,
            ..defaults
        },
        PathOptions {
            cones: false,
            enumerate_up_to: 0,
            ..defaults
        },
    ];
    for opts in routes {
        let o = hamiltonian(&tet, &opts, &Control::new()).unwrap();
        assert_eq!((o.verdict, o.tets.len()), (Verdict::Yes, 1), "{opts:?}");
    }
}
