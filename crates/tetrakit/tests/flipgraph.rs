//! The flip graph (thesis ch. 6): the enumeration against TOPCOM and a brute-force oracle
//! on random and degenerate point sets, the known results, and the flips' shape.

use std::collections::{BTreeSet, HashSet};
use std::io::Write;
use std::process::{Command, Stdio};
use tetrakit::control::{Control, Verdict};
use tetrakit::flipgraph::{FlipError, FlipGraph, FlipKind, FlipOptions, flip_graph};
use tetrakit::geom::{
    Hull3, Point3, SetDefect, orient3d, point_in_closed_tetrahedron, tetrahedra_overlap,
};
use tetrakit::rng::Rng;

fn graph(pts: &[Point3]) -> FlipGraph {
    flip_graph(pts, &FlipOptions::default(), &Control::new()).expect("flip graph")
}

/// Integer points: random in a cube, on a few planes, on a sphere, grids, lines.
fn families(seed: u64) -> Vec<(String, Vec<Point3>)> {
    let mut rng = Rng::new(seed);
    let mut r = |k: usize| rng.below(k) as f64;
    let mut out = Vec::new();
    for n in 5..=9 {
        let mut pts: Vec<Point3> = (0..n).map(|_| [r(21), r(21), r(21)]).collect();
        dedup(&mut pts);
        out.push((format!("random {n}"), pts));
    }
    // Points on two or three axis planes of a box, and the box's corners.
    for n in 1..=1 {
        let mut pts: Vec<Point3> = (0..8)
            .map(|i| {
                [
                    (i & 1) as f64 * 6.0,
                    (i >> 1 & 1) as f64 * 6.0,
                    (i >> 2) as f64 * 6.0,
                ]
            })
            .collect();
        for _ in 0..n {
            pts.push([0.0, 1.0 + r(5), 1.0 + r(5)]);
            pts.push([1.0 + r(5), 0.0, 1.0 + r(5)]);
        }
        dedup(&mut pts);
        out.push((format!("box with facet points {n}"), pts));
    }
    // Cospherical: integer points on the sphere of radius 3 (x² + y² + z² = 9).
    let sphere: Vec<Point3> = (-3i32..=3)
        .flat_map(|x| (-3i32..=3).flat_map(move |y| (-3i32..=3).map(move |z| [x, y, z])))
        .filter(|[x, y, z]| x * x + y * y + z * z == 9)
        .map(|p| p.map(f64::from))
        .collect();
    for n in [6, 8, 10] {
        let mut s = sphere.clone();
        Rng::new(seed ^ n as u64).shuffle(&mut s);
        s.truncate(n);
        out.push((format!("cospherical {n}"), s));
    }
    // A 2×2×2 grid, perturbed by ±1 on a scale of 4, and with its centre.
    let grid: Vec<Point3> = (0..8)
        .map(|i| {
            [
                (i & 1) as f64 * 4.0,
                (i >> 1 & 1) as f64 * 4.0,
                (i >> 2) as f64 * 4.0,
            ]
        })
        .collect();
    let mut perturbed = grid.clone();
    for p in &mut perturbed {
        for x in p.iter_mut() {
            *x += r(3) - 1.0;
        }
    }
    out.push(("perturbed cube".into(), perturbed));
    let mut centred = grid.clone();
    centred.push([2.0, 2.0, 2.0]);
    out.push(("cube and centre".into(), centred));
    // The octahedron (three coplanar squares, 4-4 flips), with a point off centre.
    let mut octahedron: Vec<Point3> = (0..6)
        .map(|i| {
            let mut p = [0.0; 3];
            p[i / 2] = if i % 2 == 0 { 2.0 } else { -2.0 };
            p
        })
        .collect();
    out.push(("octahedron".into(), octahedron.clone()));
    octahedron.push([r(2) - 0.5, 0.0, 0.5]);
    out.push(("octahedron and a point".into(), octahedron));
    // A square pyramid on a square of 3 × 3 points (2-2 flips on the floor).
    let mut pyramid: Vec<Point3> = (0..9)
        .map(|i| [(i % 3) as f64, (i / 3) as f64, 0.0])
        .collect();
    pyramid.push([1.0 + r(2), 1.0, 2.0]);
    out.push(("pyramid on a grid".into(), pyramid));
    // Collinear points: three on an edge of a tetrahedron, and a line through it.
    out.push((
        "collinear".into(),
        vec![
            [0.0, 0.0, 0.0],
            [2.0, 0.0, 0.0],
            [4.0, 0.0, 0.0],
            [0.0, 4.0, 0.0],
            [0.0, 0.0, 4.0],
            [1.0, 1.0, 1.0],
            [1.0 + r(2), 2.0, 1.0 + r(2)],
        ],
    ));
    out
}

/// A dyadic coordinate as the exact fraction TOPCOM reads.
fn exact(x: f64) -> String {
    let mut k = 0;
    while (x * f64::powi(2.0, k)).fract() != 0.0 {
        k += 1;
    }
    format!("{}/{}", x * f64::powi(2.0, k), 1u64 << k)
}

/// Keeps the first of equal points.
fn dedup(pts: &mut Vec<Point3>) {
    let mut seen = HashSet::new();
    pts.retain(|p| seen.insert(p.map(f64::to_bits)));
}

/// The number of fine triangulations TOPCOM counts (`points2nallfinetriangs`), those its
/// flips reach from the regular one (`points2nfinetriangs`), and the flips among them. `None` when TOPCOM is
/// missing (and `TETRAKIT_REQUIRE_TOPCOM` unset).
fn topcom(pts: &[Point3]) -> Option<(usize, usize, usize)> {
    let run = |prog: &str, args: &[&str]| -> Option<String> {
        let mut child = match Command::new(prog)
            .args(args)
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
        {
            Ok(c) => c,
            Err(_) => {
                assert!(
                    std::env::var_os("TETRAKIT_REQUIRE_TOPCOM").is_none(),
                    "TOPCOM is required here but {prog} is not on the PATH"
                );
                return None;
            }
        };
        let rows: Vec<String> = pts
            .iter()
            .map(|p| format!("[{},{},{},1]", exact(p[0]), exact(p[1]), exact(p[2])))
            .collect();
        let input = format!("[{}]\n", rows.join(","));
        child
            .stdin
            .take()
            .unwrap()
            .write_all(input.as_bytes())
            .unwrap();
        let out = child.wait_with_output().unwrap();
        Some(String::from_utf8(out.stdout).unwrap())
    };
    let count = |text: &str| -> usize {
        let last = text.lines().last().unwrap_or_default().trim();
        last.parse()
            .unwrap_or_else(|_| panic!("TOPCOM printed no count: {text}"))
    };
    let all = count(&run("topcom-points2nallfinetriangs", &[])?);
    let reached = run("topcom-points2nfinetriangs", &["--flips"])?;
    let flips = reached.lines().filter(|l| l.starts_with("flip[")).count();
    Some((all, count(&reached), flips))
}

/// Counts equal TOPCOM's on every family; TOPCOM's flips from its regular triangulation
/// reach one whole component, with as many flips; every tetrahedralization is distinct.
#[test]
fn counts_equal_topcom() {
    let mut compared = 0;
    for seed in 0..6 {
        for (name, pts) in families(seed) {
            let g = graph(&pts);
            let distinct: HashSet<BTreeSet<[u32; 4]>> = (0..g.tetrahedralizations)
                .map(|i| set(&g.tetrahedralization(i)))
                .collect();
            assert_eq!(distinct.len(), g.tetrahedralizations, "{name}: repeats");
            let c = tetrakit::flipgraph::count(&pts, usize::MAX, &Control::new()).unwrap();
            assert_eq!(
                (c.tetrahedralizations, c.candidates),
                (g.tetrahedralizations, g.candidates)
            );
            let Some((all, reached, flips)) = topcom(&pts) else {
                eprintln!("TOPCOM not on the PATH: skipped");
                return;
            };
            assert_eq!(g.tetrahedralizations, all, "{name} (seed {seed}): {pts:?}");
            let facts = g.graph.as_ref().unwrap();
            assert!(
                facts.component_sizes.contains(&reached),
                "{name}: TOPCOM's flips reach {reached} of {all}; components {:?}",
                facts.component_sizes
            );
            if facts.components == 1 {
                assert_eq!(facts.flips.total, flips, "{name} (seed {seed}): flips");
            }
            compared += 1;
        }
    }
    assert!(compared >= 60);
}

/// A thousand small sets on a 5 × 5 × 5 lattice (coplanar, collinear and cospherical
/// subsets everywhere): count and flips equal TOPCOM's.
#[test]
fn lattice_sets_equal_topcom() {
    let mut rng = Rng::new(2026);
    let mut compared = 0;
    while compared < 1000 {
        let n = 5 + rng.below(4);
        let mut pts: Vec<Point3> = (0..n)
            .map(|_| [0, 1, 2].map(|_| rng.below(5) as f64))
            .collect();
        dedup(&mut pts);
        if pts.len() < 5 {
            // TOPCOM 1.1.2's `points2nfinetriangs` does not return on a lone simplex.
            continue;
        }
        let g = match flip_graph(&pts, &FlipOptions::default(), &Control::new()) {
            Ok(g) => g,
            Err(FlipError::Set(_)) => continue,
            Err(e) => panic!("{pts:?}: {e}"),
        };
        let Some((all, reached, flips)) = topcom(&pts) else {
            eprintln!("TOPCOM not on the PATH: skipped");
            return;
        };
        let facts = g.graph.as_ref().unwrap();
        assert_eq!(g.tetrahedralizations, all, "{pts:?}");
        let c = tetrakit::flipgraph::count(&pts, usize::MAX, &Control::new()).unwrap();
        assert_eq!(
            (c.tetrahedralizations, c.verdict),
            (all, Verdict::Yes),
            "{pts:?}"
        );
        assert_eq!(facts.components, 1, "{pts:?}: TOPCOM reaches {reached}");
        assert_eq!((reached, facts.flips.total), (all, flips), "{pts:?}");
        compared += 1;
    }
}

fn sorted(mut t: [u32; 4]) -> [u32; 4] {
    t.sort_unstable();
    t
}

/// A tetrahedralization as a set of tetrahedra, each with its corners ascending.
fn set(t: &[[u32; 4]]) -> BTreeSet<[u32; 4]> {
    t.iter().map(|q| sorted(*q)).collect()
}

/// The tetrahedralizations of small integer sets by brute force: the sets of empty
/// tetrahedra with pairwise disjoint interiors whose volumes add up to the hull's, kept
/// when the verifier accepts them.
fn brute_force(pts: &[Point3]) -> BTreeSet<BTreeSet<[u32; 4]>> {
    let n = pts.len() as u32;
    let mut cands = Vec::new();
    for a in 0..n {
        for b in a + 1..n {
            for c in b + 1..n {
                for d in c + 1..n {
                    let t = [a, b, c, d];
                    let g = t.map(|v| pts[v as usize]);
                    if orient3d(&g[0], &g[1], &g[2], &g[3]) != 0
                        && (0..n).all(|x| {
                            t.contains(&x) || !point_in_closed_tetrahedron(&pts[x as usize], &g)
                        })
                    {
                        cands.push(t);
                    }
                }
            }
        }
    }
    let six = |t: &[u32; 4]| {
        let [a, b, c, d] = t.map(|v| pts[v as usize]);
        let u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
        let v = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
        let w = [d[0] - a[0], d[1] - a[1], d[2] - a[2]];
        (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
            + u[2] * (v[0] * w[1] - v[1] * w[0]))
            .abs() as i64
    };
    let hull = Hull3::new(pts);
    // The hull's volume: that of the exact solver's tetrahedralization (other code).
    let one = tetrakit::exact::tetrahedralize(
        tetrakit::exact::Domain::Points(pts),
        tetrakit::exact::TetraOptions::default(),
        &Control::new(),
    )
    .unwrap();
    let total: i64 = one.tets.iter().map(six).sum();
    let mut b = Brute {
        vols: cands.iter().map(six).collect(),
        cands,
        pts,
        hull,
        chosen: Vec::new(),
        out: BTreeSet::new(),
    };
    b.go(0, total);
    b.out
}

struct Brute<'a> {
    cands: Vec<[u32; 4]>,
    vols: Vec<i64>,
    pts: &'a [Point3],
    hull: Hull3,
    chosen: Vec<usize>,
    out: BTreeSet<BTreeSet<[u32; 4]>>,
}

impl Brute<'_> {
    /// Candidates from `i` on, `left` the volume still to fill (six times, exact).
    fn go(&mut self, i: usize, left: i64) {
        let geo = |t: &[u32; 4]| t.map(|v| self.pts[v as usize]);
        if left == 0 {
            let tets: Vec<[u32; 4]> = self.chosen.iter().map(|&k| self.cands[k]).collect();
            let oriented: Vec<[u32; 4]> = tets
                .iter()
                .map(|t| {
                    let g = geo(t);
                    if orient3d(&g[0], &g[1], &g[2], &g[3]) < 0 {
                        [t[0], t[1], t[3], t[2]]
                    } else {
                        *t
                    }
                })
                .collect();
            let report = tetrakit::mesh::verify(self.pts, &oriented, Some(&self.hull));
            if report.problems.is_empty() {
                self.out.insert(tets.into_iter().collect());
            }
            return;
        }
        if i == self.cands.len() || self.vols[i..].iter().sum::<i64>() < left {
            return;
        }
        let g = geo(&self.cands[i]);
        let fits = self.vols[i] <= left
            && (self.chosen.iter()).all(|&k| !tetrahedra_overlap(&g, &geo(&self.cands[k])));
        if fits {
            self.chosen.push(i);
            self.go(i + 1, left - self.vols[i]);
            self.chosen.pop();
        }
        self.go(i + 1, left);
    }
}

/// On small sets of every family the enumeration is exactly the brute force's.
#[test]
fn tetrahedralizations_are_exactly_the_brute_force_ones() {
    let mut checked = 0;
    for seed in 0..4 {
        for (name, pts) in families(seed) {
            if pts.len() > 7 {
                continue;
            }
            let g = graph(&pts);
            let mine: BTreeSet<BTreeSet<[u32; 4]>> = (0..g.tetrahedralizations)
                .map(|i| set(&g.tetrahedralization(i)))
                .collect();
            assert_eq!(mine, brute_force(&pts), "{name} (seed {seed}): {pts:?}");
            checked += 1;
        }
    }
    assert!(checked >= 20, "{checked}");
}

/// The 3-cube: 74 tetrahedralizations (every one uses the 8 corners), one component.
#[test]
fn the_cube_has_74_tetrahedralizations_in_one_component() {
    let cube: Vec<Point3> = (0..8)
        .map(|i| [(i & 1) as f64, (i >> 1 & 1) as f64, (i >> 2) as f64])
        .collect();
    let g = graph(&cube);
    assert_eq!(g.tetrahedralizations, 74);
    assert_eq!(g.verdict, Verdict::Yes);
    let f = g.graph.unwrap();
    assert_eq!((f.components, f.isolated.len()), (1, 0));
    assert_eq!((g.min_tetrahedra, g.max_tetrahedra), (5, 6));
    // TOPCOM's `points2nfinetriangs --flips` lists 152 flips; 8 of them are 2-3 (a
    // corner against the regular tetrahedron), the rest swap a square's diagonal.
    assert_eq!(f.flips.total, 152);
    assert_eq!(
        (f.flips.two_three, f.flips.two_two, f.flips.four_four),
        (8, 120, 24)
    );
}

/// de Loera et al.: in convex position (no three collinear), every tetrahedralization of
/// `n` points has at least `n − 4` flip neighbours.
#[test]
fn convex_position_gives_at_least_n_minus_4_flips() {
    let mut rng = Rng::new(11);
    let mut tested = 0;
    while tested < 40 {
        let n = 5 + rng.below(5);
        let pts: Vec<Point3> = (0..n)
            .map(|_| {
                let (u, v) = (rng.unit() * 2.0 - 1.0, rng.unit() * std::f64::consts::TAU);
                let r = (1.0 - u * u).sqrt();
                [r * v.cos(), r * v.sin(), u]
            })
            .collect();
        if (0..n).any(|i| !Hull3::new(&pts).on_boundary(i)) {
            continue;
        }
        let f = graph(&pts).graph.unwrap();
        assert!(f.min_flips >= n - 4, "n = {n}: {} flips", f.min_flips);
        assert_eq!(f.components, 1);
        tested += 1;
    }
}

/// Every flip joins two tetrahedralizations that differ exactly as its kind says, both
/// ways.
#[test]
fn flips_have_their_shape_and_go_both_ways() {
    for (name, pts) in families(3) {
        let g = graph(&pts);
        for (i, ns) in g.neighbours.iter().enumerate() {
            let a = set(&g.tetrahedralization(i));
            for &(j, kind) in ns {
                assert!(
                    g.neighbours[j as usize].contains(&(i as u32, kind)),
                    "{name}"
                );
                let b = set(&g.tetrahedralization(j as usize));
                let gone = a.difference(&b).count();
                let new = b.difference(&a).count();
                let corners: BTreeSet<u32> = a
                    .symmetric_difference(&b)
                    .flat_map(|t| t.iter().copied())
                    .collect();
                let expected = match kind {
                    FlipKind::TwoThree => (gone + new == 5, 5),
                    FlipKind::TwoTwo => (gone == 2 && new == 2, 5),
                    FlipKind::FourFour => (gone == 4 && new == 4, 6),
                };
                assert!(expected.0, "{name}: {kind:?} removes {gone}, adds {new}");
                assert_eq!(corners.len(), expected.1, "{name}: {kind:?}");
            }
        }
    }
}

/// The limit and the time limit cut the enumeration: UNDECIDED, nothing about the graph.
#[test]
fn a_cut_enumeration_is_undecided() {
    let grid: Vec<Point3> = (0..12)
        .map(|i| [(i % 2) as f64, (i / 2 % 2) as f64, (i / 4) as f64])
        .collect();
    let opts = FlipOptions {
        limit: 10,
        ..FlipOptions::default()
    };
    let g = flip_graph(&grid, &opts, &Control::new()).unwrap();
    assert_eq!((g.verdict, g.tetrahedralizations), (Verdict::Undecided, 10));
    assert!(g.graph.is_none() && g.witness.is_none());
    let stopped = Control::new();
    stopped.stop();
    let g = flip_graph(&grid, &FlipOptions::default(), &stopped).unwrap();
    assert_eq!(g.verdict, Verdict::Undecided);
}

#[test]
fn degenerate_inputs_are_refused() {
    let ctl = Control::new();
    let o = FlipOptions::default();
    let flat = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [1.0, 1.0, 0.0],
    ];
    assert_eq!(
        flip_graph(&flat, &o, &ctl),
        Err(FlipError::Set(SetDefect::Flat))
    );
    assert_eq!(
        flip_graph(&flat[..3], &o, &ctl),
        Err(FlipError::Set(SetDefect::TooFew(3)))
    );
    let dup = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
        [1.0, 0.0, 0.0],
    ];
    assert_eq!(
        flip_graph(&dup, &o, &ctl),
        Err(FlipError::Set(SetDefect::Duplicate {
            first: 1,
            second: 4
        }))
    );
}

/// Two independent parts agree: the cube with each square split by a diagonal (64
/// choices) can be tetrahedralized by the exact solver exactly when one of the cube's 74
/// enumerated tetrahedralizations has those diagonals on its surface.
#[test]
fn the_cubes_triangulated_surfaces_agree_with_its_tetrahedralizations() {
    use tetrakit::exact::{Domain, TetraOptions, tetrahedralize};
    use tetrakit::mesh::Polyhedron;
    let cube: Vec<Point3> = (0..8)
        .map(|i| [(i & 1) as f64, (i >> 1 & 1) as f64, (i >> 2) as f64])
        .collect();
    let g = graph(&cube);
    // The surface triangles of each tetrahedralization (corners ascending).
    let surfaces: HashSet<BTreeSet<[u32; 3]>> = (0..g.tetrahedralizations)
        .map(|i| {
            let mut count = std::collections::HashMap::<[u32; 3], u32>::new();
            for t in g.tetrahedralization(i) {
                for k in 0..4 {
                    let mut f = [t[(k + 1) % 4], t[(k + 2) % 4], t[(k + 3) % 4]];
                    f.sort_unstable();
                    *count.entry(f).or_default() += 1;
                }
            }
            count
                .into_iter()
                .filter(|&(_, c)| c == 1)
                .map(|(f, _)| f)
                .collect()
        })
        .collect();
    // The squares by their corners in cyclic order (bit i of a corner is coordinate i).
    let squares = [
        [0, 1, 3, 2],
        [4, 5, 7, 6],
        [0, 1, 5, 4],
        [2, 3, 7, 6],
        [0, 2, 6, 4],
        [1, 3, 7, 5],
    ];
    let mut yes = 0;
    for pattern in 0..64u32 {
        let faces: Vec<[u32; 3]> = (0..6)
            .flat_map(|k| {
                let [a, b, c, d] = squares[k];
                if pattern >> k & 1 == 0 {
                    [[a, b, c], [a, c, d]]
                } else {
                    [[a, b, d], [b, c, d]]
                }
            })
            .collect();
        let surface: BTreeSet<[u32; 3]> = faces
            .iter()
            .map(|f| {
                let mut s = *f;
                s.sort_unstable();
                s
            })
            .collect();
        let p = Polyhedron::new(cube.clone(), faces).unwrap();
        let o = tetrahedralize(
            Domain::Polyhedron(&p),
            TetraOptions::default(),
            &Control::new(),
        )
        .unwrap();
        let extends = surfaces.contains(&surface);
        assert_eq!(o.verdict == Verdict::Yes, extends, "pattern {pattern}");
        yes += usize::from(extends);
    }
    assert!(yes > 0 && yes < 64, "{yes}");
}
