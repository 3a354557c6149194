//! The shell between nested convex polytopes (thesis ch. 4): every output certified by
//! `certify_shell`, never above 9n − 6, Lemma 4.9's count where it applies, and the
//! degenerate contacts (shared vertices, edges and facets, coplanar polygon facets).

use tetrakit::control::Control;
use tetrakit::exact::Outcome;
use tetrakit::geom::{Expansion, Hull3, Point3, orient3d_value};
use tetrakit::mesh::certify_shell;
use tetrakit::shell::generate::{Contact, NestedParams, Shape, bern_disk, contact, nested};
use tetrakit::shell::{
    Finish, Method, Shell, ShellError, ShellMesh, ShellOptions, improve, optimum, tetrahedralize,
};

/// Both methods, each certified and within 9n − 6; the cap removal's mesh is returned.
fn solve(outer: &[Point3], inner: &[Point3]) -> (Shell, ShellMesh) {
    solve_by(outer, inner, &[Method::Thesis, Method::Bigcap, Method::Cap])
}

/// The given methods (the last one's mesh is returned).
fn solve_by(outer: &[Point3], inner: &[Point3], methods: &[Method]) -> (Shell, ShellMesh) {
    let shell = Shell::new(outer, inner).expect("a shell");
    let run = |m: Method| {
        let mesh = tetrahedralize(&shell, m, &Control::new()).unwrap_or_else(|e| {
            panic!(
                "{m:?}: {e} ({} outer, {} inner)",
                shell.outer.len(),
                shell.inner.len()
            )
        });
        let cert = certify_shell(&shell.points, &mesh.tets, &shell.inner);
        assert_eq!(cert, Ok(()), "{m:?}");
        assert!(fills_the_shell(&shell, &mesh.tets), "{m:?}");
        assert!(mesh.tets.len() <= 9 * shell.n() - 6, "{m:?}");
        assert!(ledger_is_exact(&mesh), "{m:?}");
        improved(&shell, mesh.clone());
        mesh
    };
    let meshes: Vec<ShellMesh> = methods.iter().map(|&m| run(m)).collect();
    (shell, meshes.into_iter().last().expect("a method"))
}

/// The weights of §4.4 charge every interior edge of a removal's mesh exactly once (true
/// too for a placed mesh, which has no ledger).
fn ledger_is_exact(mesh: &ShellMesh) -> bool {
    match (&mesh.ledger, mesh.finished_by) {
        (Some(l), Finish::Removal) => l.edges() == mesh.interior_edges(),
        (None, Finish::Placing) => true,
        _ => false,
    }
}

/// The improvement pass on `mesh`: certified, never more tetrahedra; returns the count.
fn improved(shell: &Shell, mut mesh: ShellMesh) -> usize {
    let before = mesh.tets.len();
    let done = improve(&shell.points, &mut mesh, &Control::new()).expect("flips");
    assert_eq!(done.before, before);
    let cert = certify_shell(&shell.points, &mesh.tets, &shell.inner);
    assert_eq!(cert, Ok(()), "after {done:?}");
    assert!(mesh.tets.len() <= before);
    mesh.tets.len()
}

/// Six times a volume, exactly: the tetrahedra's, or a hull's as cones from a point.
fn six_volume(points: &[Point3], tets: impl Iterator<Item = [u32; 4]>) -> Expansion {
    tets.fold(Expansion::default(), |acc, t| {
        let p = t.map(|v| &points[v as usize]);
        acc.add(&orient3d_value(p[0], p[1], p[2], p[3]))
    })
}

fn hull_six_volume(points: &[Point3]) -> Expansion {
    let h = Hull3::new(points);
    six_volume(points, h.triangles.iter().map(|t| [t[0], t[2], t[1], 0]))
}

/// The exact volume test `certify_shell` implies: `Σ vol(t) = vol(P) − vol(Q)`.
fn fills_the_shell(shell: &Shell, tets: &[[u32; 4]]) -> bool {
    let inner: Vec<Point3> = shell
        .inner
        .iter()
        .map(|&v| shell.points[v as usize])
        .collect();
    let expected = hull_six_volume(&shell.points).sub(&hull_six_volume(&inner));
    six_volume(&shell.points, tets.iter().copied())
        .sub(&expected)
        .sign()
        == 0
}

fn simplicial(points: &[Point3]) -> bool {
    let h = Hull3::new(points);
    h.facet_count() == h.triangles.len()
}

fn cube(lo: Point3, side: f64) -> Vec<Point3> {
    (0..8)
        .map(|i| [0, 1, 2].map(|k| lo[k] + if (i >> k) & 1 == 1 { side } else { 0.0 }))
        .collect()
}

/// Random nested spheres, cubes, prisms and random polytopes, every pair: both methods
/// certified (never a dead end), within the bound, and
/// `t = e_i + n − 6` (Lemma 4.9) whenever both hulls are simplicial and apart.
#[test]
fn random_nested_shells_are_certified_and_obey_lemma_4_9() {
    let shapes = [Shape::Sphere, Shape::Random, Shape::Cube, Shape::Cylinder];
    let mut lemma = 0;
    for seed in 0..240u64 {
        let (o, i) = (shapes[seed as usize % 4], shapes[(seed / 4) as usize % 4]);
        let p = NestedParams {
            outer: o,
            inner: i,
            n_outer: 8 + (seed as usize * 7) % 40,
            n_inner: 8 + (seed as usize * 5) % 30,
            gap: 0.1 + 0.8 * ((seed % 10) as f64 / 10.0),
            seed,
        };
        let Ok((outer, inner, _)) = nested(&p) else {
            continue; // an outer random polytope that misses the origin
        };
        let (shell, mesh) = solve(&outer, &inner);
        let shared = shell
            .inner
            .iter()
            .any(|&v| (v as usize) < shell.outer.len());
        let outer_pts: Vec<Point3> = shell
            .outer
            .iter()
            .map(|&v| shell.points[v as usize])
            .collect();
        let inner_pts: Vec<Point3> = shell
            .inner
            .iter()
            .map(|&v| shell.points[v as usize])
            .collect();
        if !shared && simplicial(&outer_pts) && simplicial(&inner_pts) {
            assert_eq!(
                mesh.tets.len(),
                mesh.interior_edges() + shell.n() - 6,
                "seed {seed}"
            );
            lemma += 1;
        }
    }
    // Seed 126 (a cube around a square prism) once left the greedy bigcaps a last
    // piece with no tetrahedralization; the exact solver now finishes the region left
    // (Q's facets free), and coaxial prisms (cylinder in cylinder) finish too.
    assert!(lemma > 50, "Lemma 4.9 checked on {lemma} shells only");
}

/// Contacts: a shared corner with three coplanar facet pairs, a shared edge, an inner
/// vertex inside an outer facet, a shared facet, and coplanar polygon facets.
#[test]
fn touching_and_coplanar_shells() {
    let big = cube([0.0; 3], 4.0);
    solve(&big, &cube([0.0; 3], 2.0)); // a shared corner, three facets in common planes
    solve(&big, &cube([0.0, 0.0, 1.0], 4.0 - 1.0)); // a shared edge segment
    solve(&big, &cube([1.0, 1.0, 1.0], 2.0)); // apart, all facets squares
    let tip = [
        [2.0, 2.0, 0.0],
        [1.0, 1.0, 1.0],
        [3.0, 1.0, 1.0],
        [2.0, 3.0, 1.0],
    ];
    solve(&big, &tip); // an inner vertex in the interior of an outer facet
    let slab = [
        [0.0, 0.0, 0.0],
        [4.0, 0.0, 0.0],
        [0.0, 4.0, 0.0],
        [4.0, 4.0, 0.0],
        [1.0, 1.0, 1.0],
        [3.0, 1.0, 1.0],
        [1.0, 3.0, 1.0],
        [3.0, 3.0, 1.0],
    ];
    solve(&big, &slab); // the whole bottom facet shared
}

/// Points that are not corners are not vertices, and are reported.
/// `generate contact`: `Q` touching `P` at a vertex, along an edge, along a facet, and
/// with a vertex inside a facet, 15 seeds each at sizes 5–40, both methods certified
/// within 9n − 6; the contact is what the generator says (shared vertices, or one inner
/// vertex on `P`'s boundary).
#[test]
fn contact_families_are_certified() {
    let kinds = [
        (Contact::Vertex, 1),
        (Contact::Edge, 2),
        (Contact::Facet, 3),
        (Contact::FacetPoint, 0),
    ];
    for (kind, shared) in kinds {
        for seed in 0..15u64 {
            let (n_outer, n_inner) = (5 + 2 * seed as usize, 4 + seed as usize);
            let (outer, inner) = contact(kind, n_outer, n_inner, seed).unwrap();
            let (shell, _) = solve(&outer, &inner);
            let common = shell
                .inner
                .iter()
                .filter(|&&v| (v as usize) < shell.outer.len())
                .count();
            assert_eq!(common, shared, "{kind:?} seed {seed}");
            let touching = usize::from(kind == Contact::FacetPoint);
            assert_eq!(shell.touching.len(), touching, "{kind:?} seed {seed}");
        }
    }
}

#[test]
fn non_corner_points_are_reported() {
    let mut outer = cube([0.0; 3], 4.0);
    outer.extend([
        [2.0, 2.0, 2.0],
        [2.0, 2.0, 0.0],
        [2.0, 0.0, 0.0],
        [4.0, 4.0, 4.0],
    ]);
    let shell = Shell::new(&outer, &cube([1.0; 3], 2.0)).unwrap();
    assert_eq!(shell.outer_ignored, [8, 9, 10, 11]);
    assert_eq!(shell.n(), 16);
}

#[test]
fn bad_shells_are_refused_with_a_reason() {
    let big = cube([0.0; 3], 4.0);
    let mut out = cube([1.0; 3], 2.0);
    out[5] = [1.0, 1.0, 5.0];
    assert!(matches!(
        Shell::new(&big, &out),
        Err(ShellError::InnerOutside { index: 5, .. })
    ));
    let flat = [
        [1.0, 1.0, 1.0],
        [2.0, 1.0, 1.0],
        [1.0, 2.0, 1.0],
        [2.0, 2.0, 1.0],
    ];
    assert_eq!(
        Shell::new(&big, &flat).unwrap_err(),
        ShellError::InnerFlat { dimension: 2 }
    );
    assert_eq!(
        Shell::new(&flat, &big).unwrap_err(),
        ShellError::OuterFlat { dimension: 2 }
    );
}

/// Coaxial prisms: facets of the current hull inside `P` through several vertices, where
/// a tip that is not an ear of every such facet's triangulation is refused; pairs, and
/// then the placing, finish them.
#[test]
fn coaxial_prisms() {
    let mut cases: Vec<(Vec<Point3>, Vec<Point3>)> = Vec::new();
    for seed in 0..60 {
        let p = NestedParams {
            outer: Shape::Cylinder,
            inner: Shape::Cylinder,
            n_outer: 6 + seed as usize % 30,
            n_inner: 6 + (seed as usize * 7) % 30,
            gap: 0.1 + 0.8 * ((seed % 10) as f64 / 10.0),
            seed,
        };
        cases.push(nested(&p).map(|(o, i, _)| (o, i)).unwrap());
    }
    for (outer, inner) in cases {
        solve(&outer, &inner);
    }
}

/// A cube sharing two facet planes with the outer cube (and, for bigcaps, a corner): the
/// removal can leave every piece refused; the placing finishes it.
#[test]
fn shared_facet_planes_are_solved() {
    let big = cube([0.0; 3], 4.0);
    for inner in [cube([1.0, 0.0, 0.0], 2.0), cube([0.0; 3], 2.0)] {
        solve(&big, &inner);
    }
}

/// A stopped control stops the removal (the CLI's `--time-limit`, exit 3).
#[test]
fn a_stopped_control_stops() {
    let shell = Shell::new(&cube([0.0; 3], 4.0), &cube([1.0; 3], 2.0)).unwrap();
    let ctl = Control::new();
    ctl.stop();
    for m in [Method::Cap, Method::Bigcap] {
        let e = tetrahedralize(&shell, m, &ctl).unwrap_err();
        assert_eq!(e, ShellError::Stopped(tetrakit::control::Stopped));
        // The one stop type is reached through `source()`, as from every error.
        let source = std::error::Error::source(&e).expect("a stop has its source");
        assert!(source.is::<tetrakit::control::Stopped>());
    }
}

/// The certified mesh of one method, without the bound (see the Bern disks).
fn certified(shell: &Shell, m: Method) -> ShellMesh {
    let mesh = tetrahedralize(shell, m, &Control::new()).expect("a mesh");
    let cert = certify_shell(&shell.points, &mesh.tets, &shell.inner);
    assert_eq!(cert, Ok(()), "{m:?}");
    mesh
}

/// Bern's worst case for minimum-degree cap removal: on Bern disks the tetrahedra per
/// vertex grow with the size (each ridge vertex is handed from ring vertex to ring
/// vertex about log₂ ring times), while every mesh stays certified.
#[test]
fn cap_removal_is_superlinear_on_bern_disks() {
    let per_vertex = |ridge: usize, ring: usize| {
        let (outer, inner) = bern_disk(ridge, ring, 1).unwrap();
        let shell = Shell::new(&outer, &inner).unwrap();
        assert_eq!(
            (shell.outer.len(), shell.inner.len()),
            (2 * ring, ridge + 2)
        );
        certified(&shell, Method::Cap).tets.len() as f64 / shell.n() as f64
    };
    let (small, large) = (per_vertex(64, 16), per_vertex(1024, 256));
    assert!(
        large > small + 2.0,
        "{small:.2} → {large:.2} tetrahedra per vertex"
    );
}

/// The input on which both methods' removals exceed 9n − 6 (n = 3002: 27 782
/// tetrahedra, the bound 27 012): the improvement pass's Delaunay flips bring both down
/// to 3 per vertex (8996, TetGen's count on the same surfaces). The capability does not
/// finish such a removal: past 5 tetrahedra per vertex it takes the Delaunay
/// tetrahedralization outside `Q`, which has that count.
#[test]
fn bern_disks_within_the_bound_after_flips() {
    let (outer, inner) = bern_disk(2500, 250, 1).unwrap();
    let shell = Shell::new(&outer, &inner).unwrap();
    let mut flipped = Vec::new();
    for m in [Method::Bigcap, Method::Cap] {
        let mesh = certified(&shell, m);
        assert!(
            mesh.tets.len() > 9 * shell.n() - 6,
            "{m:?}: the removals alone"
        );
        // Lemma 4.9 with the ledger's sum: above 9n − 6, so some weight is above 8, and
        // the ledger names it.
        let ledger = mesh.ledger.as_ref().expect("finished by removal");
        assert_eq!(mesh.tets.len(), ledger.edges() + shell.n() - 6);
        let (heaviest, v) = ledger.heaviest();
        assert!(heaviest > 8 && ledger.weights[v as usize] == heaviest);
        assert_eq!(ledger.histogram().iter().sum::<usize>(), shell.n());
        let t = improved(&shell, mesh);
        assert!(t <= 3 * shell.n(), "{m:?}: {t} after flips");
        flipped.push(t);
    }
    // The capability says how it ended: without flips every route is above the bound,
    // and the smaller mesh is printed with `within_bound: false`; with them, within.
    for flips in [false, true] {
        let opts = ShellOptions {
            flips,
            ..ShellOptions::new(Method::Cap)
        };
        let o = tetrakit::shell::shell(&shell, opts, &Control::new()).unwrap();
        let t = o.tetrahedra.unwrap();
        // The interior edges reported from the ledger's sum and the flips, recounted.
        let recount = ShellMesh {
            tets: o.tets.clone(),
            pieces: 0,
            finished_by: Finish::Removal,
            ledger: None,
            thesis: None,
        };
        assert_eq!(o.interior_edges, Some(recount.interior_edges()));
        assert_eq!(o.within_bound, Some(flips), "{t} against {}", o.bound);
        assert_eq!(o.within_bound, Some(t <= o.bound));
        let ended = o.finished_by.unwrap();
        assert_eq!(ended == Finish::Delaunay, flips, "{ended:?}");
        if flips {
            let cert = certify_shell(&shell.points, &o.tets, &shell.inner);
            assert_eq!(cert, Ok(()));
            assert!(flipped.iter().all(|&f| t <= f), "{t} against {flipped:?}");
            assert_eq!((o.pieces, o.weights.is_none()), (Some(0), true));
            // The Delaunay route runs beside the removal on a spare core, after it on
            // one: the same mesh either way.
            let one = rayon::ThreadPoolBuilder::new()
                .num_threads(1)
                .build()
                .unwrap();
            let alone = one.install(|| tetrakit::shell::shell(&shell, opts, &Control::new()));
            assert_eq!(alone.unwrap().tets, o.tets);
        }
    }
}

/// The exact optimum of 200 small random simplicial shells (n ≤ 18, 5 s each) against
/// both methods, before and after the flips: never below it, and the worst ratios
/// pinned a little above those measured (cap 1.30, cap with flips 1.19, bigcap 1.42,
/// bigcap with flips 1.30, BIGCAP-REMOVE's steps 1.42, with flips 1.30).
#[test]
fn small_shells_against_the_exact_optimum() {
    let shapes = [Shape::Sphere, Shape::Random];
    let mut worst = [1.0f64; 6];
    let (mut solved, mut tried) = (0, 0);
    for seed in 0..200u64 {
        let p = NestedParams {
            outer: shapes[seed as usize % 2],
            inner: shapes[(seed / 2) as usize % 2],
            n_outer: 6 + (seed as usize * 7) % 5,
            n_inner: 5 + (seed as usize * 5) % 4,
            gap: 0.1 + 0.8 * ((seed % 9) as f64 / 9.0),
            seed,
        };
        let Ok((o, i, _)) = nested(&p) else { continue };
        let shell = Shell::new(&o, &i).unwrap();
        let own = |v: &[u32]| {
            v.iter()
                .map(|&k| shell.points[k as usize])
                .collect::<Vec<_>>()
        };
        if !simplicial(&own(&shell.outer)) || !simplicial(&own(&shell.inner)) {
            continue;
        }
        let meshes: Vec<ShellMesh> = [Method::Cap, Method::Bigcap, Method::Thesis]
            .iter()
            .map(|&m| tetrahedralize(&shell, m, &Control::new()).expect("a mesh"))
            .collect();
        let counts: Vec<usize> = meshes
            .iter()
            .flat_map(|m| [m.tets.len(), improved(&shell, m.clone())])
            .collect();
        tried += 1;
        let ctl = Control::new().with_time_limit(std::time::Duration::from_secs(5));
        let (best, _) = optimum(&shell, &ctl).expect("small");
        let tets = match best {
            Outcome::Optimal { tets, .. } => tets,
            Outcome::Undecided { .. } => continue,
            other => panic!("seed {seed}: {other:?}"),
        };
        let cert = certify_shell(&shell.points, &tets, &shell.inner);
        assert_eq!(cert, Ok(()), "seed {seed}: the optimum");
        solved += 1;
        for (w, &c) in worst.iter_mut().zip(&counts) {
            assert!(
                c >= tets.len(),
                "seed {seed}: {c} below the optimum {}",
                tets.len()
            );
            *w = w.max(c as f64 / tets.len() as f64);
        }
    }
    eprintln!(
        "{solved} of {tried} shells solved; worst ratios cap, cap+flips, bigcap, bigcap+flips, thesis, thesis+flips: {worst:.3?}"
    );
    assert!(
        solved * 10 >= tried * 9 && tried >= 150,
        "{solved} of {tried}"
    );
    let pinned = [1.35, 1.25, 1.45, 1.35, 1.45, 1.35];
    assert!(worst.iter().zip(pinned).all(|(w, p)| *w <= p), "{worst:?}");
}

/// A cube inside a cube with points on the facets (axis-parallel planes everywhere): the
/// removals get stuck once the current hull has facets through a tip in planes inside
/// `P`, and the exact solver finishes the region left (the surface fixed, `Q`'s facets
/// free). These 60 seeds include the 10 that ended in an internal error before.
#[test]
fn cubes_in_cubes_finish() {
    for seed in 1..=60u64 {
        let p = NestedParams {
            outer: Shape::Cube,
            inner: Shape::Cube,
            n_outer: 8 + seed as usize % 12,
            n_inner: 8 + seed as usize % 7,
            gap: 0.1 * (seed % 9 + 1) as f64,
            seed,
        };
        let (o, i, _) = nested(&p).unwrap();
        solve(&o, &i);
    }
}

/// A mutated certified mesh: one tetrahedron removed, repeated, inverted, given another
/// vertex or replaced; a face flipped 2-3 whether or not that is legal; or two of these.
fn mutant(points: &[Point3], tets: &[[u32; 4]], rng: &mut tetrakit::rng::Rng) -> Vec<[u32; 4]> {
    let mut t = tets.to_vec();
    let n = points.len();
    let i = rng.below(t.len());
    match rng.below(7) {
        0 => {
            t.swap_remove(i);
        }
        1 => t.push(t[i]),
        2 => t[i].swap(0, 1),
        3 => t[i][rng.below(4)] = rng.below(n) as u32,
        4 => t[i] = [0; 4].map(|_| rng.below(n) as u32),
        5 => flip_2_3(points, &mut t, i, rng.below(4)),
        _ => {
            t = mutant(points, &t, rng);
            t = mutant(points, &t, rng);
        }
    }
    t
}

/// Replaces tetrahedron `i` and its neighbour across the face opposite corner `k` by the
/// three tetrahedra around the edge joining their far corners, each oriented positively
/// where it is not flat.
fn flip_2_3(points: &[Point3], t: &mut Vec<[u32; 4]>, i: usize, k: usize) {
    let face: Vec<u32> = (0..4).filter(|&j| j != k).map(|j| t[i][j]).collect();
    let Some(j) = (0..t.len()).find(|&j| j != i && face.iter().all(|v| t[j].contains(v))) else {
        return;
    };
    let (d, e) = (
        t[i][k],
        *t[j]
            .iter()
            .find(|v| !face.contains(v))
            .expect("a far corner"),
    );
    let (hi, lo) = (i.max(j), i.min(j));
    t.swap_remove(hi);
    t.swap_remove(lo);
    for m in 0..3 {
        let mut new = [d, e, face[m], face[(m + 1) % 3]];
        let p = new.map(|v| &points[v as usize]);
        if tetrakit::geom::orient3d(p[0], p[1], p[2], p[3]) < 0 {
            new.swap(0, 1);
        }
        t.push(new);
    }
}

/// `certify_shell` pins the covering degree from one corner per component of `∂P − Q`
/// instead of testing overlaps around every vertex and summing volumes: on thousands of
/// mutated meshes of shells with one and with several components, whatever it accepts
/// the full vertex-by-vertex check of `verify` accepts too, with the exact shell volume.
#[test]
fn shell_certificates_agree_with_the_full_check_on_mutants() {
    let mut shells = Vec::new();
    let big = cube([0.0; 3], 2.0);
    let corners: Vec<Point3> = big
        .iter()
        .copied()
        .filter(|p| (p[0] + p[1] + p[2]) % 4.0 == 0.0)
        .collect();
    shells.push((big.clone(), corners));
    shells.push((big, cube([0.5; 3], 1.0)));
    for seed in 0..4u64 {
        for kind in [
            Contact::Vertex,
            Contact::Edge,
            Contact::Facet,
            Contact::FacetPoint,
        ] {
            shells.push(contact(kind, 8, 5, seed).unwrap());
        }
        let p = NestedParams {
            outer: Shape::Sphere,
            inner: Shape::Random,
            n_outer: 12,
            n_inner: 6,
            gap: 0.3,
            seed,
        };
        let (o, i, _) = nested(&p).unwrap();
        shells.push((o, i));
    }
    let mut rng = tetrakit::rng::Rng::new(7);
    let (mut accepted, mut faces_ok) = (0, 0);
    for (outer, inner) in &shells {
        let shell = Shell::new(outer, inner).expect("a shell");
        for m in [Method::Cap, Method::Bigcap] {
            let mesh = tetrahedralize(&shell, m, &Control::new()).expect("a mesh");
            assert!(tetrakit::mesh::verify(&shell.points, &mesh.tets, None).is_valid());
            for _ in 0..150 {
                let t = mutant(&shell.points, &mesh.tets, &mut rng);
                if tetrakit::mesh::verify(&shell.points, &t, None).is_valid() {
                    faces_ok += 1;
                }
                if certify_shell(&shell.points, &t, &shell.inner).is_ok() {
                    accepted += 1;
                    let full = tetrakit::mesh::verify(&shell.points, &t, None);
                    assert!(full.is_valid(), "{m:?}: accepted {:?}", full.problems);
                    assert!(
                        fills_the_shell(&shell, &t),
                        "{m:?}: accepted a wrong volume"
                    );
                }
            }
        }
    }
    // Legal flips are accepted by both; the rest are refused.
    assert!(
        accepted > 0 && accepted <= faces_ok,
        "{accepted} accepted, {faces_ok} valid"
    );
}

mod property {
    use super::*;
    use proptest::prelude::*;

    /// Points of a `k × k × k` grid on the box `[lo, lo + side]³`: cospherical corners,
    /// coplanar facets full of points that are not vertices.
    fn grid(k: usize, lo: f64, side: f64) -> Vec<Point3> {
        let step = side / (k - 1) as f64;
        let mut pts = Vec::new();
        for x in 0..k {
            for y in 0..k {
                for z in 0..k {
                    pts.push([x, y, z].map(|i| lo + step * i as f64));
                }
            }
        }
        pts
    }

    fn shape() -> impl Strategy<Value = (u8, usize, u64)> {
        (0u8..3, 2usize..5, any::<u64>())
    }

    /// `kind` 0: a grid box; 1: random points on a sphere; 2: a random polytope.
    fn points((kind, k, seed): (u8, usize, u64), centre: f64, radius: f64) -> Vec<Point3> {
        let mut rng = tetrakit::rng::Rng::new(seed);
        match kind {
            0 => grid(k, centre - radius / 3f64.sqrt(), 2.0 * radius / 3f64.sqrt()),
            1 => {
                tetrakit::shell::generate::shape_points(Shape::Sphere, 4 + 3 * k, radius, &mut rng)
                    .into_iter()
                    .map(|p| p.map(|x| x + centre))
                    .collect()
            }
            _ => {
                tetrakit::shell::generate::shape_points(Shape::Random, 4 + 4 * k, radius, &mut rng)
                    .into_iter()
                    .map(|p| p.map(|x| x + centre))
                    .collect()
            }
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        /// Nested grids, spheres and random polytopes (the inner one scaled into the outer
        /// one, sometimes touching a grid's facets): every method's mesh and its flipped
        /// mesh certified and within 9n − 6 (inputs that are not nested are rejected, not
        /// counted); never an internal error.
        #[test]
        fn nested_point_sets(outer in shape(), inner in shape(), shrink in 0.05f64..0.9) {
            let o = points(outer, 0.0, 1.0);
            // Well inside: a coarse outer hull (few random points) may still cut into
            // the inner shape; those draws are rejected.
            let i = points(inner, 0.0, shrink * 0.3);
            let shell = match Shell::new(&o, &i) {
                Ok(s) => s,
                Err(ShellError::InnerOutside { .. } | ShellError::OuterFlat { .. } | ShellError::InnerFlat { .. }) => {
                    return Err(TestCaseError::reject("not nested"));
                }
                Err(e) => return Err(TestCaseError::fail(format!("{e}"))),
            };
            for m in [Method::Cap, Method::Bigcap] {
                let mesh = tetrahedralize(&shell, m, &Control::new())
                    .map_err(|e| TestCaseError::fail(format!("{m:?}: {e}")))?;
                prop_assert_eq!(certify_shell(&shell.points, &mesh.tets, &shell.inner), Ok(()));
                prop_assert!(mesh.tets.len() <= 9 * shell.n() - 6);
                improved(&shell, mesh);
            }
        }
    }
}

/// `Q` a box with integer corners anywhere in `P = [0, 4]³`: on the floor, in a corner,
/// along an edge, across, sharing facets, edges and vertices with `P` (999 boxes), each
/// in its order and reversed, both methods certified within 9n − 6. Q's facets inside
/// P's facets are recovered in the surface (`shell::recover`); before, 156 of 366 such
/// contact runs failed.
#[test]
fn boxes_touching_a_box_anywhere() {
    let big = cube([0.0; 3], 4.0);
    let mut failed = Vec::new();
    for mut inner in boxes_in_the_cube() {
        for reversed in [false, true] {
            if reversed {
                inner.reverse();
            }
            let shell = Shell::new(&big, &inner).unwrap();
            for m in [Method::Cap, Method::Bigcap, Method::Thesis] {
                match tetrahedralize(&shell, m, &Control::new()) {
                    Ok(mesh) => {
                        let cert = certify_shell(&shell.points, &mesh.tets, &shell.inner);
                        assert_eq!(cert, Ok(()), "{m:?} {inner:?}");
                        assert!(mesh.tets.len() <= 9 * shell.n() - 6);
                    }
                    Err(e) => failed.push(format!("{m:?} {inner:?}: {e}")),
                }
            }
        }
    }
    assert!(
        failed.is_empty(),
        "{} failed:\n{}",
        failed.len(),
        failed.join("\n")
    );
}

/// `Q` filling a corner of `P` (sharing the corner and three facet planes): the shared
/// corner is in no tetrahedron, since the region is empty around it. The exact solver
/// once called such a shell infeasible (it asked every vertex to be used); in this order
/// the greedy bigcaps reach a dead end, and the placing finishes it.
#[test]
fn a_corner_filled_by_the_inner_box() {
    let outer = [
        [0.0, 4.0, 4.0],
        [4.0, 4.0, 0.0],
        [0.0, 0.0, 4.0],
        [4.0, 0.0, 4.0],
        [4.0, 4.0, 4.0],
        [0.0, 0.0, 0.0],
        [4.0, 0.0, 0.0],
        [0.0, 4.0, 0.0],
    ];
    let inner = [
        [3.0, 4.0, 0.0],
        [3.0, 1.0, 2.0],
        [4.0, 1.0, 2.0],
        [4.0, 4.0, 2.0],
        [4.0, 1.0, 0.0],
        [4.0, 4.0, 0.0],
        [3.0, 4.0, 2.0],
        [3.0, 1.0, 0.0],
    ];
    let (shell, mesh) = solve(&outer, &inner);
    assert!(
        mesh.tets.iter().flatten().all(|&v| v != 1),
        "the shared corner"
    );
    let (best, _) = optimum(&shell, &Control::new()).unwrap();
    let Outcome::Optimal { tets, .. } = best else {
        panic!("{best:?}")
    };
    assert_eq!(certify_shell(&shell.points, &tets, &shell.inner), Ok(()));
    assert!(tets.len() <= mesh.tets.len());
}

/// The generators refuse with the parameter, its value and its range, as a variant.
#[test]
fn generators_name_the_parameter_out_of_range() {
    use tetrakit::params::GenerateError;
    let out_of_range = |e: GenerateError| match e {
        GenerateError::OutOfRange { parameter, .. } => parameter,
        GenerateError::Unbuildable(why) => panic!("{why}"),
    };
    assert_eq!(out_of_range(bern_disk(2, 10, 1).unwrap_err()), "ridge");
    assert_eq!(
        out_of_range(contact(Contact::Edge, 10, 3, 1).unwrap_err()),
        "n_inner"
    );
    let bad_gap = NestedParams {
        outer: Shape::Sphere,
        inner: Shape::Sphere,
        n_outer: 20,
        n_inner: 20,
        gap: 1.5,
        seed: 1,
    };
    assert_eq!(out_of_range(nested(&bad_gap).unwrap_err()), "gap");
}

/// Lemma 4.1 fails as stated: `--method thesis` answers `assumption_fails` on the stored
/// counterexample, with the tip, `U_v` and a bottom triangle the tip is behind (checked
/// here with `orient3d_value`, not the module's code); where the lemma holds the shell is
/// meshed.
#[test]
fn thesis_method_names_the_lemma_that_fails() {
    use tetrakit::control::Verdict;
    use tetrakit::shell::lemma41::counterexample;
    let (outer, inner, tip) = counterexample();
    let shell = Shell::new(&outer, &inner).unwrap();
    let opts = ShellOptions::new(Method::Thesis);
    let o = tetrakit::shell::shell(&shell, opts, &Control::new()).unwrap();
    assert_eq!(
        (o.verdict, o.lemma_4_1),
        (Verdict::AssumptionFails, Some("fails"))
    );
    let w = o.witness.expect("a witness");
    assert_eq!((w.tip, w.removed.clone()), (tip, vec![2, 5]));
    let point = |v: tetrakit::shell::FileVertex| match v.polytope {
        "outer" => outer[v.index as usize],
        _ => inner[v.index as usize],
    };
    let [a, b, c] = w.bottom.map(point);
    let sign = |x: &Point3| orient3d_value(&a, &b, &c, x).sign();
    assert_eq!((sign(&outer[tip as usize]), sign(&point(w.kept))), (-1, -1));
    // Every point of the new hull (the points not removed) is on that side or the plane.
    for (k, p) in outer
        .iter()
        .enumerate()
        .filter(|(k, _)| !w.removed.contains(&(*k as u32)))
    {
        assert!(sign(p) <= 0, "outer {k}");
    }
    assert!(inner.iter().all(|p| sign(p) <= 0));
    // Stopped before the check ends, the answer is undecided, with no witness.
    let stopped = Control::new();
    stopped.stop();
    let o = tetrakit::shell::shell(&shell, opts, &stopped).unwrap();
    assert_eq!((o.verdict, o.witness.is_none()), (Verdict::Undecided, true));
    // The other methods mesh it.
    let cap = ShellOptions::new(Method::Cap);
    assert_eq!(
        tetrakit::shell::shell(&shell, cap, &Control::new())
            .unwrap()
            .verdict,
        Verdict::Yes
    );
    // In a tetrahedron every other vertex has the facet opposite the tip, and the cone
    // from the tip over it holds Q: `U_v` is the tip alone and the bigcap a cap.
    let outer = [
        [0.0, 0.0, 0.0],
        [8.0, 0.0, 0.0],
        [0.0, 8.0, 0.0],
        [0.0, 0.0, 8.0],
    ];
    let inner = [
        [1.0, 1.0, 1.0],
        [3.0, 1.0, 1.0],
        [1.0, 3.0, 1.0],
        [1.0, 1.0, 3.0],
    ];
    let shell = Shell::new(&outer, &inner).unwrap();
    let o = tetrakit::shell::shell(&shell, opts, &Control::new()).unwrap();
    assert_eq!((o.verdict, o.lemma_4_1), (Verdict::Yes, Some("holds")));
}

/// `optimum`: the exact minimum beside the removals' and flips' count, its mesh printed
/// (and certified) when it has fewer; a shell above the exact solver's size is refused.
#[test]
fn shell_reports_the_exact_minimum() {
    let p = NestedParams {
        outer: Shape::Random,
        inner: Shape::Sphere,
        n_outer: 9,
        n_inner: 6,
        gap: 0.5,
        seed: 4,
    };
    let (outer, inner, _) = nested(&p).unwrap();
    let shell = Shell::new(&outer, &inner).unwrap();
    let opts = ShellOptions {
        optimum: true,
        ..ShellOptions::new(Method::Cap)
    };
    let o = tetrakit::shell::shell(&shell, opts, &Control::new()).unwrap();
    let best = o.optimum.expect("asked");
    let Outcome::Optimal { tets, .. } = optimum(&shell, &Control::new()).unwrap().0 else {
        panic!("small")
    };
    assert!(best.proven);
    assert_eq!(
        (best.lower_bound, best.upper_bound),
        (tets.len(), tets.len())
    );
    assert_eq!(o.tetrahedra, Some(tets.len()));
    assert!(
        best.heuristic > tets.len(),
        "this shell's flips stop above the minimum"
    );
    assert_eq!(certify_shell(&shell.points, &o.tets, &shell.inner), Ok(()));
    let p = NestedParams {
        outer: Shape::Sphere,
        n_outer: 60,
        n_inner: 20,
        ..p
    };
    let (outer, inner, _) = nested(&p).unwrap();
    let big = Shell::new(&outer, &inner).unwrap();
    let refused = tetrakit::shell::shell(&big, opts, &Control::new());
    assert!(matches!(refused, Err(ShellError::TooLargeForOptimum { n }) if n == big.n()));
}

/// Every box with integer corners in `[0, 4]³` other than the cube itself (999), each
/// as its 8 corners.
fn boxes_in_the_cube() -> Vec<Vec<Point3>> {
    let big = cube([0.0; 3], 4.0);
    let spans: Vec<[f64; 2]> = (0..4)
        .flat_map(|lo| (lo + 1..=4).map(move |hi| [lo as f64, hi as f64]))
        .collect();
    let pick = |k: usize, i: usize, [a, b]: [f64; 2]| if (i >> k) & 1 == 1 { b } else { a };
    let mut boxes = Vec::new();
    for &x in &spans {
        for &y in &spans {
            for &z in &spans {
                let corners: Vec<Point3> = (0..8)
                    .map(|i| [pick(0, i, x), pick(1, i, y), pick(2, i, z)])
                    .collect();
                if !corners.iter().all(|p| big.contains(p)) {
                    boxes.push(corners);
                }
            }
        }
    }
    boxes
}

/// The degenerate shells of this file in one list: boxes anywhere in a box (999),
/// lattice spheres with `Q = P/2` and `Q = P/3` (parallel facets, cospherical points),
/// grids with a grid inside or on a facet, coaxial prisms, the contact families and
/// random nested shapes.
fn degenerate_shells() -> Vec<(Vec<Point3>, Vec<Point3>)> {
    let big = cube([0.0; 3], 4.0);
    let mut cases: Vec<_> = boxes_in_the_cube()
        .into_iter()
        .map(|inner| (big.clone(), inner))
        .collect();
    for r2 in [3, 9, 11, 17, 25, 27, 50] {
        let outer = tetrakit::generate::cospherical_points(r2);
        for k in [2.0, 3.0] {
            cases.push((
                outer.clone(),
                outer.iter().map(|p| p.map(|x| x / k)).collect(),
            ));
        }
    }
    for shape in [Shape::Sphere, Shape::Cube, Shape::Random, Shape::Cylinder] {
        for inner in [Shape::Sphere, Shape::Cube, Shape::Random, Shape::Cylinder] {
            for seed in 0..6 {
                let p = NestedParams {
                    outer: shape,
                    inner,
                    n_outer: 8 + 5 * seed as usize,
                    n_inner: 8 + 3 * seed as usize,
                    gap: 0.1 + 0.15 * seed as f64,
                    seed,
                };
                let (o, i, _) = nested(&p).unwrap();
                cases.push((o, i));
            }
        }
    }
    for kind in [
        Contact::Vertex,
        Contact::Edge,
        Contact::Facet,
        Contact::FacetPoint,
    ] {
        for seed in 0..10u64 {
            cases.push(contact(kind, 5 + 3 * seed as usize, 4 + seed as usize, seed).unwrap());
        }
    }
    cases
}

/// Zeros written -0 or 0 at random give the same meshes: -0 is 0, and no hull, sort or
/// key may tell them apart (before the twenty-fourth session the corner family's box of
/// 10^3 points made 1850 tetrahedra with some of its zeros written -0, 1853 without).
#[test]
fn signed_zeros_change_no_mesh() {
    let mut rng = tetrakit::rng::Rng::new(9);
    let mut sign = |pts: &[Point3]| -> Vec<Point3> {
        (pts.iter())
            .map(|p| {
                p.map(|x| {
                    if x == 0.0 && rng.below(2) == 0 {
                        -0.0
                    } else {
                        x
                    }
                })
            })
            .collect()
    };
    let mut signed = 0;
    for (outer, inner) in degenerate_shells().into_iter().step_by(2) {
        let (o, i) = (sign(&outer), sign(&inner));
        let bits = |v: &[Point3]| v.iter().map(|p| p.map(f64::to_bits)).collect::<Vec<_>>();
        signed += usize::from(bits(&o) != bits(&outer) || bits(&i) != bits(&inner));
        let (a, b) = (
            Shell::new(&outer, &inner).unwrap(),
            Shell::new(&o, &i).unwrap(),
        );
        for m in [Method::Cap, Method::Bigcap] {
            let ma = tetrahedralize(&a, m, &Control::new()).unwrap();
            let mb = tetrahedralize(&b, m, &Control::new()).unwrap();
            assert_eq!(ma.tets, mb.tets, "{m:?} {o:?} {i:?}");
        }
    }
    assert!(signed > 300, "{signed}");
}

/// `geom::placing`, the construction the shell's guarantee rests on: `Q`'s boundary,
/// then `P`'s other vertices in any order (as given, reversed, and two random orders),
/// each coned to what it sees; certified (and filling the shell, by exact volume) on
/// every degenerate shell above, none refused.
#[test]
fn placing_tiles_every_shell_in_any_order() {
    let mut rng = tetrakit::rng::Rng::new(45);
    let cases = degenerate_shells();
    assert!(cases.len() > 1100);
    for (outer, inner) in cases {
        let shell = Shell::new(&outer, &inner).expect("a shell");
        let removable: Vec<u32> = shell
            .outer
            .iter()
            .copied()
            .filter(|v| !shell.inner.contains(v))
            .collect();
        let mut orders = vec![removable.clone(), removable.iter().rev().copied().collect()];
        for _ in 0..2 {
            let mut o = removable.clone();
            for i in (1..o.len()).rev() {
                o.swap(i, rng.below(i + 1));
            }
            orders.push(o);
        }
        for order in orders {
            let tets = tetrakit::geom::placing(&shell.points, &shell.inner, &order).unwrap();
            let cert = certify_shell(&shell.points, &tets, &shell.inner);
            assert_eq!(cert, Ok(()), "{outer:?} {inner:?} {order:?}");
            assert!(fills_the_shell(&shell, &tets));
        }
    }
}

/// Every degenerate shell above, both methods: certified, filling the shell, within
/// 9n − 6, whether the removal took every outer vertex or left some to the placing
/// (`Finish::Placing`, the removal's order reversed). Some of each happen, so both
/// endings are exercised; the placing ends 34 of the 2,298 runs, and a removal that
/// leaves an edge of `Q` out of a bottom's polygon facet would leave it more (138 with
/// Q's edges recovered only where points are refined in: tried).
#[test]
fn every_degenerate_shell_is_tetrahedralized() {
    let mut endings = [0usize; 2];
    for (outer, inner) in degenerate_shells() {
        let shell = Shell::new(&outer, &inner).unwrap();
        for m in [Method::Cap, Method::Bigcap] {
            let mesh = tetrahedralize(&shell, m, &Control::new()).unwrap();
            let cert = certify_shell(&shell.points, &mesh.tets, &shell.inner);
            assert_eq!(cert, Ok(()), "{m:?} {outer:?} {inner:?}");
            assert!(fills_the_shell(&shell, &mesh.tets));
            assert!(mesh.tets.len() <= 9 * shell.n() - 6);
            assert!(ledger_is_exact(&mesh), "{m:?} {outer:?} {inner:?}");
            endings[usize::from(mesh.finished_by == Finish::Placing)] += 1;
        }
    }
    assert!(
        endings[0] > 2000 && (10..=60).contains(&endings[1]),
        "{endings:?}"
    );
}

/// BIGCAP-REMOVE's steps (`Method::Thesis`, the lemma's check left out) on the issue's
/// small random shells in general position: 8 to 14 points on a sphere or a flattened
/// one around 4 to 8 on a small off-centre sphere. Every mesh is certified; what the
/// steps did and §4.4's largest weight are printed.
#[test]
fn thesis_steps_on_small_random_shells() {
    let mut rng = tetrakit::rng::Rng::new(41);
    let (mut whole, mut repaired, mut rounds, mut heaviest, mut by_removal) = (0, 0, 0, 0, 0);
    let (mut caps_by_removal, mut valid) = (0, 0);
    let (mut exact, mut every_tip, mut largest) = (0, 0, 0);
    let (mut chains, mut step_6) = (0, 0);
    let mut worst_per_vertex = 0f64;
    let sphere = |rng: &mut tetrakit::rng::Rng, m: usize, r: f64, c: Point3, flat: f64| {
        (0..m)
            .map(|_| {
                let p = [0; 3].map(|_| 2.0 * rng.unit() - 1.0);
                let l = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt();
                [
                    c[0] + r * p[0] / l,
                    c[1] + r * p[1] / l,
                    c[2] + flat * r * p[2] / l,
                ]
            })
            .collect::<Vec<Point3>>()
    };
    let shells = 200;
    for k in 0..shells {
        let flat = if k % 2 == 0 { 1.0 } else { 0.5 };
        let outer = sphere(&mut rng, 8 + k % 7, 1.0, [0.0; 3], flat);
        let c = [0.1, 0.1, 0.05].map(|s| s * (2.0 * rng.unit() - 1.0));
        let inner = sphere(&mut rng, 4 + k % 5, 0.15, c, 1.0);
        let Ok(shell) = Shell::new(&outer, &inner) else {
            continue; // Q reaches out of P
        };
        valid += 1;
        let mesh = tetrahedralize(&shell, Method::Thesis, &Control::new()).expect("a mesh");
        let cert = certify_shell(&shell.points, &mesh.tets, &shell.inner);
        assert_eq!(cert, Ok(()), "shell {k}");
        assert!(ledger_is_exact(&mesh), "shell {k}");
        let steps = mesh.thesis.expect("the steps ran");
        (whole, repaired, rounds) = (
            whole + steps.s_bigcaps,
            repaired + steps.repaired,
            rounds + steps.rounds,
        );
        assert_eq!(steps.step_3a_exact + steps.step_3a_every_tip, steps.rounds);
        (exact, every_tip) = (
            exact + steps.step_3a_exact,
            every_tip + steps.step_3a_every_tip,
        );
        largest = largest.max(steps.largest_p_a_searched);
        (chains, step_6) = (chains + steps.step_6_chains, step_6 + steps.step_6_bigcaps);
        if let Some(l) = &mesh.ledger {
            heaviest = heaviest.max(l.heaviest().0);
            by_removal += 1;
        }
        worst_per_vertex = worst_per_vertex.max(mesh.tets.len() as f64 / shell.n() as f64);
        let cap = tetrahedralize(&shell, Method::Cap, &Control::new()).expect("a mesh");
        caps_by_removal += usize::from(cap.finished_by == Finish::Removal);
    }
    eprintln!(
        "{valid} of {shells} shells nested: {rounds} rounds ({exact} with Step 3a's exact minimum, |P_a| up to {largest}; {every_tip} with every tip), {whole} S-bigcaps whole, {repaired} repaired, {chains} Step-6 chains with {step_6} S_b-bigcaps; {by_removal} finished by removal (caps: {caps_by_removal}); largest weight {heaviest}; most tetrahedra per vertex {worst_per_vertex:.2}"
    );
    assert!(rounds > 0 && whole + repaired > 0 && heaviest <= 8);
    assert!(
        exact * 2 > rounds && largest >= 3,
        "{exact} of {rounds}, {largest}"
    );
    assert!(valid > 100 && by_removal == valid && caps_by_removal == valid);
}

/// BIGCAP-REMOVE's Step 6 on contact shells (`Q` touching `P` at a vertex, where the
/// lemma is not examined): chains of `P_b` are found and removed chord by chord, every
/// mesh certified, the ledger exact and Theorem 4.2's weights at most 8.
#[test]
fn step_6_removes_chains_on_contact_shells() {
    let (mut chains, mut bigcaps) = (0, 0);
    for seed in 0..6u64 {
        let (outer, inner) = contact(Contact::Vertex, 40, 40, seed).unwrap();
        let shell = Shell::new(&outer, &inner).unwrap();
        let mesh = tetrahedralize(&shell, Method::Thesis, &Control::new()).expect("a mesh");
        let cert = certify_shell(&shell.points, &mesh.tets, &shell.inner);
        assert_eq!(cert, Ok(()), "seed {seed}");
        assert!(ledger_is_exact(&mesh), "seed {seed}");
        assert!(
            mesh.ledger.as_ref().is_none_or(|l| l.heaviest().0 <= 8),
            "seed {seed}"
        );
        let steps = mesh.thesis.expect("the steps ran");
        (chains, bigcaps) = (chains + steps.step_6_chains, bigcaps + steps.step_6_bigcaps);
    }
    eprintln!("{chains} Step-6 chains, {bigcaps} S_b-bigcaps");
    assert!(
        chains > 0 && bigcaps >= chains,
        "{chains} chains, {bigcaps} S_b-bigcaps"
    );
}

/// Two slightly bent perpendicular arcs around a small sphere (`benches/shell.sh`'s
/// arcs at n = 400): bigcaps pass their budget there and the Delaunay shell, which
/// `Q` is a union of, has more than 5 tetrahedra per vertex (the two arcs' Delaunay
/// edges cross: quadratic). No route may end above that budget when another ends below
/// it: the caps' mesh is kept.
#[test]
fn a_delaunay_shortcut_above_the_budget_is_not_kept() {
    let m = 100;
    let t = |j: usize| 2.0 * j as f64 / (m - 1) as f64 - 1.0;
    let mut outer: Vec<Point3> = (0..m)
        .map(|j| [t(j), 0.0, 1.0 - 0.05 * t(j) * t(j)])
        .collect();
    outer.extend((0..m).map(|j| [0.0, t(j), -1.0 + 0.05 * t(j) * t(j)]));
    let mut rng = tetrakit::rng::Rng::new(3);
    let inner = tetrakit::shell::generate::shape_points(Shape::Sphere, 200, 0.1, &mut rng);
    let shell = Shell::new(&outer, &inner).unwrap();
    let opts = ShellOptions::new(Method::Bigcap);
    let o = tetrakit::shell::shell(&shell, opts, &Control::new()).unwrap();
    let t = o.tetrahedra.unwrap();
    assert!(
        t <= tetrakit::shell::REMOVAL_BUDGET * shell.n(),
        "{t} tetrahedra, {o:?}"
    );
    assert_eq!((o.method, o.finished_by), ("cap", Some(Finish::Removal)));
}
