//! The exact Delaunay tetrahedralization (`geom::Delaunay3`) against brute force: every
//! result is certified a tetrahedralization of the hull with every point a vertex
//! (`mesh::certify_hull`, which owes nothing to the builder), no point is strictly inside
//! any tetrahedron's sphere (checked against every point), and the neighbour lists are
//! the faces' other tetrahedra. The sets are chosen degenerate: small integer grids
//! (coplanar, collinear, cospherical points everywhere), integer points on spheres,
//! cubes of lattice points, points on cylinders, and random floats.

use tetrakit::geom::{Delaunay3, DelaunayError, Point3, insphere};
use tetrakit::mesh::certify_hull;
use tetrakit::rng::Rng;

/// Checks `d` on `pts` as the module docs say, `brute` deciding the all-pairs sphere test.
fn check(pts: &[Point3], d: &Delaunay3, brute: bool) {
    assert_eq!(certify_hull(pts, &d.tets), Ok(()), "{pts:?}");
    assert_eq!(d.tets.len(), d.neighbours.len());
    for (t, (c, n)) in d.tets.iter().zip(&d.neighbours).enumerate() {
        for (k, &across) in n.iter().enumerate() {
            let mut face: Vec<u32> = (0..4).filter(|&i| i != k).map(|i| c[i]).collect();
            face.sort_unstable();
            if across == u32::MAX {
                continue;
            }
            let other = d.tets[across as usize];
            let back = d.neighbours[across as usize];
            let j = back
                .iter()
                .position(|&x| x == t as u32)
                .expect("neighbours agree");
            let mut theirs: Vec<u32> = (0..4).filter(|&i| i != j).map(|i| other[i]).collect();
            theirs.sort_unstable();
            assert_eq!(face, theirs);
            // Locally Delaunay, unperturbed: the apex across is not strictly inside.
            let p = |v: u32| &pts[v as usize];
            assert!(insphere(p(c[0]), p(c[1]), p(c[2]), p(c[3]), p(other[j])) <= 0);
        }
        if brute {
            let p = |v: u32| &pts[v as usize];
            for x in pts {
                assert!(insphere(p(c[0]), p(c[1]), p(c[2]), p(c[3]), x) <= 0);
            }
        }
    }
    // The faces with no neighbour are exactly those of one tetrahedron (the hull).
    let hull = d
        .neighbours
        .iter()
        .flatten()
        .filter(|&&n| n == u32::MAX)
        .count();
    let mut faces: Vec<[u32; 3]> = Vec::new();
    for t in &d.tets {
        for k in 0..4 {
            let mut f = [t[(k + 1) % 4], t[(k + 2) % 4], t[(k + 3) % 4]];
            f.sort_unstable();
            faces.push(f);
        }
    }
    faces.sort_unstable();
    let once = faces
        .chunk_by(|a, b| a == b)
        .filter(|run| run.len() == 1)
        .count();
    assert_eq!(hull, once);
}

/// Distinct points of `pts`, in their first order.
fn distinct(pts: Vec<Point3>) -> Vec<Point3> {
    let mut seen = std::collections::HashSet::new();
    pts.into_iter()
        .filter(|p| seen.insert(p.map(f64::to_bits)))
        .collect()
}

fn solid(pts: &[Point3]) -> bool {
    tetrakit::geom::affine_dimension(pts) == 3
}

#[test]
fn small_integer_grids() {
    let mut rng = Rng::new(7);
    let mut done = 0;
    for _ in 0..1500 {
        let side = 2 + rng.below(3) as i32;
        let n = 5 + rng.below(30);
        let pts = distinct(
            (0..n)
                .map(|_| [0, 1, 2].map(|_| rng.below(side as usize + 1) as f64))
                .collect(),
        );
        if !solid(&pts) {
            assert_eq!(Delaunay3::new(&pts), Err(DelaunayError::Flat));
            continue;
        }
        check(&pts, &Delaunay3::new(&pts).unwrap(), true);
        done += 1;
    }
    assert!(done > 1200);
}

#[test]
fn integer_points_on_spheres() {
    for r2 in [3, 9, 11, 25, 50, 75, 99, 147] {
        let r = (r2 as f64).sqrt() as i32 + 1;
        let mut pts: Vec<Point3> = Vec::new();
        for x in -r..=r {
            for y in -r..=r {
                for z in -r..=r {
                    if x * x + y * y + z * z == r2 {
                        pts.push([x as f64, y as f64, z as f64]);
                    }
                }
            }
        }
        let with_centre: Vec<Point3> = pts.iter().copied().chain([[0.0; 3]]).collect();
        for set in [pts.clone(), with_centre] {
            if solid(&set) {
                check(&set, &Delaunay3::new(&set).unwrap(), true);
            }
        }
    }
}

#[test]
fn cubes_of_lattice_points_and_cylinders() {
    for m in 2..7 {
        let cube: Vec<Point3> = (0..m * m * m)
            .map(|i| [i % m, (i / m) % m, i / (m * m)].map(|c| c as f64))
            .collect();
        check(&cube, &Delaunay3::new(&cube).unwrap(), m < 6);
    }
    // Regular polygons stacked: cocircular and coplanar rings, not exactly cospherical.
    for (sides, rings) in [(6, 3), (8, 5), (12, 4), (20, 6)] {
        let pts: Vec<Point3> = (0..sides * rings)
            .map(|i| {
                let a = std::f64::consts::TAU * (i % sides) as f64 / sides as f64;
                [a.cos(), a.sin(), (i / sides) as f64]
            })
            .collect();
        check(&pts, &Delaunay3::new(&pts).unwrap(), true);
    }
}

#[test]
fn random_floats_and_their_scaled_grids() {
    let mut rng = Rng::new(11);
    for round in 0..60 {
        let n = 4 + rng.below(300);
        let pts: Vec<Point3> = (0..n)
            .map(|_| match round % 2 {
                0 => [0, 1, 2].map(|_| rng.unit() * 2.0 - 1.0),
                _ => [0, 1, 2].map(|_| (rng.below(9) as f64) * 0.125 - 0.5),
            })
            .collect();
        let pts = distinct(pts);
        if solid(&pts) {
            check(&pts, &Delaunay3::new(&pts).unwrap(), true);
        }
    }
    let big: Vec<Point3> = (0..20_000).map(|_| [0, 1, 2].map(|_| rng.unit())).collect();
    check(&big, &Delaunay3::new(&big).unwrap(), false);
}

#[test]
fn repeats_and_flat_sets_are_named() {
    let pts = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
        [1.0, 0.0, 0.0],
    ];
    let e = Delaunay3::new(&pts).unwrap_err();
    assert!(
        matches!(e, DelaunayError::Repeated { first, second } if pts[first as usize] == pts[second as usize] && first != second)
    );
    assert_eq!(Delaunay3::new(&pts[..3]), Err(DelaunayError::Flat));
    assert_eq!(Delaunay3::new(&[]), Err(DelaunayError::Flat));
}
