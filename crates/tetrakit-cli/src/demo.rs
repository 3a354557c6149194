//! `tetrakit demo`: a newcomer's tour on built-in examples, a few seconds, no arguments.

use crate::exit::{CmdResult, Verdict};
use std::time::Instant;
use tetrakit::control::Control;
use tetrakit::detect::{Answer, Cells, Options, Route, detect};
use tetrakit::generate::{self, Corruption};
use tetrakit::mesh::Tetrahedralization;

fn verdict(name: &str, t: &Tetrahedralization, edges: &[[u32; 2]]) {
    let start = Instant::now();
    let d = detect(&t.points, edges, &Options::default(), &Control::new())
        .expect("generated input is well-formed");
    let ms = start.elapsed().as_secs_f64() * 1e3;
    match &d.answer {
        Answer::Yes(Cells::Tetrahedra(tets)) => out!(
            "  {name}: YES, {} segments on {} points form a tetrahedralization with {} tetrahedra ({}) [{ms:.1} ms]",
            edges.len(),
            t.points.len(),
            tets.len(),
            match d.route {
                Route::Delaunay =>
                    "the Delaunay tetrahedra of the graph, each found once, certified",
                Route::Links => "every one found from all four of its vertices, certified",
            }
        ),
        Answer::Yes(Cells::Triangles(tris)) => out!(
            "  {name}: YES, a planar triangulation with {} triangles [{ms:.1} ms]",
            tris.len()
        ),
        Answer::No(w) => out!(
            "  {name}: NO [{ms:.1} ms]\n      witness {}: {}",
            w.kind,
            w.detail
        ),
        Answer::Undecided => out!("  {name}: UNDECIDED [{ms:.1} ms]"),
    }
}

pub fn run() -> CmdResult {
    out!("tetrakit demo — is a set of segments exactly the edge set of a tetrahedralization?");
    out!(
        "(thesis ch. 2, TETRAHEDRALIZATION-DETECTION, exact and without the general-position assumption)\n"
    );

    let grid = generate::kuhn(4);
    let e = grid.edges();
    out!("1. A Kuhn grid of 4x4x4 cubes: full of coplanar and cospherical points.");
    verdict("valid grid", &grid, &e);
    let crossing = generate::corrupt_edges(&grid.points, &e, Corruption::AddCrossing, 3)
        .expect("grid has crossings");
    verdict("plus one segment", &grid, &crossing);
    let dropped =
        generate::corrupt_edges(&grid.points, &e, Corruption::DropEdge, 3).expect("non-empty");
    verdict("minus one segment", &grid, &dropped);

    let rand = generate::random_tetrahedralization(400, 800, 11, None);
    let e = rand.edges();
    out!("\n2. A random non-Delaunay tetrahedralization of 400 points (insertion plus 800 flips).");
    verdict("valid", &rand, &e);
    let dropped =
        generate::corrupt_edges(&rand.points, &e, Corruption::DropEdge, 5).expect("non-empty");
    verdict("minus one segment", &rand, &dropped);

    let skew = generate::skew_lines(40);
    out!(
        "\n3. Twenty points on each of two skew lines: Θ(n²) tetrahedra, the thesis's worst case."
    );
    verdict("valid", &skew, &skew.edges());

    out!("\n4. Mesh validation (`tetrakit check --convex`): the random mesh with one extra");
    out!(
        "   tetrahedron laid over two others, the kind of error a check without embedding tests accepts."
    );
    match generate::add_overlapping_tet(&rand, 1) {
        None => out!("  (no pair of neighbours admits an overlapping tetrahedron)"),
        Some(bad) => {
            let report = bad.verify_convex();
            out!(
                "  {} problem(s); first: {}",
                report.problem_count,
                report
                    .problems
                    .first()
                    .map_or("-".to_string(), |p| p.detail.to_string())
            );
        }
    }
    let boxes = generate::two_cubes([1.0, 1.0, 0.0]);
    let report = tetrakit::mesh::verify(&boxes.points, &boxes.tets, None);
    let strict = report.clone().require_manifold();
    out!(
        "  two cubes touching along an edge (a non-manifold domain): valid: {}, {} non-manifold edge(s); with `check --manifold`: valid: {}",
        report.is_valid(),
        report.non_manifold.len(),
        strict.is_valid()
    );
    minimal_tetrahedralizations();
    prescribed_edges_section();
    shell_section();
    planar_section();
    flip_graph_section();
    out!("\nTry: tetrakit generate kuhn --size 10 -o /tmp/k.ele && tetrakit detect /tmp/k.edge");
    out!(
        "     tetrakit generate two-level -o /tmp/p.off && tetrakit mintetra /tmp/p.off --confirm"
    );
    Ok(Verdict::Yes)
}

/// Chapter 3: MINTETRA against the lower bound and the exact solver.
fn minimal_tetrahedralizations() {
    use tetrakit::exact::{Domain, Options, Outcome, minimal_tetrahedralization};
    use tetrakit::polyhedra::{
        self,
        generate::{self, BpParams},
    };
    out!("\n5. Minimal tetrahedralizations (thesis ch. 3): an augmented BP-polyhedron.");
    let params = BpParams {
        core: 10,
        nets: 2,
        levels: 1,
        max_m: 4,
        augment: 3,
        hide_all: false,
        seed: 7,
    };
    let (p, _) = generate::bp_polyhedron(params);
    let start = Instant::now();
    let m = polyhedra::mintetra(&p, polyhedra::Checks::Shelling);
    let ms = start.elapsed().as_secs_f64() * 1e3;
    let certified = tetrakit::mesh::certify_polyhedron(&p, &m.tets).is_ok();
    out!(
        "  MINTETRA: {} tetrahedra for {} vertices (lower bound n - 3 = {}), polar edges {:?}, certified: {certified} [{ms:.1} ms]",
        m.tets.len(),
        p.points.len(),
        p.points.len() - 3,
        m.polar_edges
    );
    let start = Instant::now();
    let opts = Options {
        unique: true,
        ..Options::default()
    };
    let ctl = Control::new();
    match minimal_tetrahedralization(Domain::Polyhedron(&p), &opts, &ctl) {
        Ok((Outcome::Optimal { tets, unique, .. }, stats)) => out!(
            "  exact SAT solver: minimum {} over {} candidate tetrahedra, unique: {} [{:.1} ms]",
            tets.len(),
            stats.candidates,
            unique.map_or("?".to_string(), |u| u.to_string()),
            start.elapsed().as_secs_f64() * 1e3
        ),
        other => out!("  exact SAT solver: {other:?}"),
    }
    let s = generate::schonhardt();
    let verdict =
        match minimal_tetrahedralization(Domain::Polyhedron(&s), &Options::default(), &ctl) {
            Ok((Outcome::Infeasible, _)) => "no tetrahedralization exists (proved)",
            _ => "unexpected",
        };
    out!("  Schönhardt's twisted prism: {verdict}");
    let sbp = generate::schonhardt_bp();
    let m = polyhedra::mintetra(&sbp, polyhedra::Checks::Shelling);
    out!(
        "  Schönhardt with three BP-nets (Figure 3.21, convex): MINTETRA says {} ({})",
        if m.yes { "YES" } else { "NO" },
        m.reason
    );
}

/// Thesis ch. 2 §2.5–2.6: tetrahedralizations with prescribed edges, NP-complete,
/// decided exactly with witnesses and DRAT proofs.
fn prescribed_edges_section() {
    use tetrakit::constrain::{Answer, Options, constrained, contains};
    use tetrakit::exact::{self, Domain, Proof};
    out!("\n6. Prescribed edges (thesis §2.5–2.6, NP-complete): exact answers, checkable proofs.");
    let ctl = Control::new();
    for deg in [30.0, -30.0] {
        let p = tetrakit::polyhedra::generate::twisted_prism(deg).expect("a valid twist");
        let opts = exact::Options::default();
        match exact::minimal_tetrahedralization(Domain::Polyhedron(&p), &opts, &ctl) {
            Ok((exact::Outcome::Optimal { tets, .. }, _)) => out!(
                "  prism twisted {deg:+}°: YES, convex; {} tetrahedra at least (`tetrahedralize --minimal`)",
                tets.len()
            ),
            Ok((exact::Outcome::Infeasible, stats)) => out!(
                "  prism twisted {deg:+}°: NO, Schönhardt's polyhedron: {}",
                stats
                    .obstacle
                    .map_or("the formula is unsatisfiable".into(), |o| o.to_string())
            ),
            other => out!("  prism twisted {deg:+}°: {other:?}"),
        }
    }
    // Seven random points and three quarters of their pairs, until the answer needs the
    // SAT solver and is NO: then its refutation.
    let mut rng = tetrakit::rng::Rng::new(7);
    for _ in 0..200 {
        let pts: Vec<[f64; 3]> = (0..7)
            .map(|_| [0, 1, 2].map(|_| (rng.unit() * 64.0).round() / 64.0))
            .collect();
        let l: Vec<[u32; 2]> = (0..7u32)
            .flat_map(|a| (a + 1..7).map(move |b| [a, b]))
            .filter(|_| rng.below(4) < 3)
            .collect();
        let Ok(d) = contains(&pts, &l, &Options::default(), &ctl) else {
            continue;
        };
        if !matches!(d.answer, Answer::No(_)) || d.route != tetrakit::constrain::Route::Solver {
            continue;
        }
        let (mut cnf, mut drat) = (Vec::new(), Vec::new());
        let q = tetrakit::constrain::Question::Contains;
        if let Ok(Proof::Refuted { variables, clauses }) =
            tetrakit::constrain::prove(q, &pts, &l, &mut cnf, &mut drat, &ctl)
        {
            out!(
                "  7 random points, {} of their 21 pairs (`contains --proof`): NO, no short reason; {} candidate tetrahedra, DRAT refutation of {} lines for {variables} variables and {clauses} clauses",
                l.len(),
                d.stats.candidates,
                drat.split(|&b| b == b'\n')
                    .filter(|x| !x.is_empty())
                    .count()
            );
            break;
        }
    }
    let cube: Vec<[f64; 3]> = (0..8)
        .map(|i| [(i & 1) as f64, ((i >> 1) & 1) as f64, (i >> 2) as f64])
        .chain([[0.5, 0.5, 0.5]])
        .collect();
    let show = |name: &str, a: &Answer| match a {
        Answer::Yes(tetrakit::detect::Cells::Tetrahedra(t)) => {
            out!("  {name}: YES, {} tetrahedra, certified", t.len())
        }
        Answer::Yes(tetrakit::detect::Cells::Triangles(t)) => {
            out!("  {name}: YES, {} triangles, certified", t.len())
        }
        Answer::No(w) => out!("  {name}: NO, {}: {}", w.kind, w.detail),
        Answer::Undecided => out!("  {name}: undecided"),
    };
    let opts = Options::default();
    let through = constrained(&cube, &[[0, 7]], &opts, &ctl).expect("valid input");
    show(
        "cube and centre, constraint along a long diagonal (`constrained`)",
        &through.answer,
    );
    let star: Vec<[u32; 2]> = (0..8).map(|v| [v, 8]).collect();
    let fine = constrained(&cube, &star, &opts, &ctl).expect("valid input");
    show("the same, every corner joined to the centre", &fine.answer);
    // Every pair but the cube's face diagonals through corner 0: the solver decides.
    let l: Vec<[u32; 2]> = (0..9u32)
        .flat_map(|a| (a + 1..9).map(move |b| [a, b]))
        .filter(|&[a, b]| !(a == 0 && [3, 5, 6].contains(&b)))
        .collect();
    let d = contains(&cube, &l, &Options { minimal: true }, &ctl).expect("valid input");
    show(
        "all 33 pairs but corner 0's face diagonals (`contains --minimal`)",
        &d.answer,
    );
    let square = [
        [0.0, 0.0, 0.0],
        [2.0, 0.0, 0.0],
        [2.0, 2.0, 0.0],
        [0.0, 2.0, 0.0],
        [1.0, 0.5, 0.0],
    ];
    let ring = [
        [0, 1],
        [1, 2],
        [2, 3],
        [3, 0],
        [0, 4],
        [1, 4],
        [2, 4],
        [3, 4],
    ];
    let trid = contains(&square, &ring, &opts, &ctl).expect("valid input");
    show(
        "planar (TRID): a square, a point inside, the spokes",
        &trid.answer,
    );
    let no_spoke = contains(&square, &ring[..7], &opts, &ctl).expect("valid input");
    show("the same without one spoke", &no_spoke.answer);
    // Theorem 2.9: the same two instances carried to space.
    let flat: Vec<[f64; 2]> = square.iter().map(|p| [p[0], p[1]]).collect();
    for (name, e) in [("with every spoke", &ring[..]), ("without one", &ring[..7])] {
        let apexes = tetrakit::reduce::trid_to_tetrad(&flat, e).expect("no three collinear");
        let sphere = tetrakit::reduce::sphere_reduction(&flat, e).expect("the conditions hold");
        for (how, pts, segs) in [
            (
                "reduced to space (`reduce trid-to-tetrad`",
                &apexes.points,
                &apexes.segments,
            ),
            (
                "the thesis's sphere construction (`--construction sphere`",
                &sphere.points,
                &sphere.segments,
            ),
        ] {
            let d = contains(pts, segs, &opts, &ctl).expect("valid input");
            show(&format!("{how}, {} points), {name}", pts.len()), &d.answer);
        }
    }
    constructions(&ctl);
}

/// Lemma 2.6, Lemma 2.7 and the hard families, one line each.
fn constructions(ctl: &Control) {
    use tetrakit::exact::{self, Domain};
    use tetrakit::polyhedra::{generate, hard};
    let s = generate::schonhardt();
    match tetrakit::reduce::hull_gap(&s, ctl) {
        Ok(gap) => out!(
            "  Schönhardt's gap to its hull (`reduce hull-gap`, Lemma 2.6): {} tetrahedra by reflex-edge flips, certified",
            gap.len()
        ),
        Err(e) => out!("  Schönhardt's gap to its hull: {e}"),
    }
    for twist in [0.0, 3.0, 20.0] {
        let q = tetrakit::reduce::QuasiPrism::lens(8, 6, twist, 1);
        let how = match q.tetrahedralize(ctl) {
            Ok(st) if st.by_order => format!("{} tetrahedra by one vertex order", st.tets.len()),
            Ok(st) => format!(
                "{} tetrahedra by a SAT orientation of the diagonals",
                st.tets.len()
            ),
            Err(e) => format!("no staircase ({e}); `reduce quasi-prism` asks the exact solver"),
        };
        out!(
            "  quasi-prism of {} prisms twisted {twist}° (Lemma 2.7): {how}",
            q.triangles.len()
        );
    }
    let c = hard::chazelle(5).expect("valid grooves");
    let opts = exact::Options {
        any: true,
        ..exact::Options::default()
    };
    match exact::minimal_tetrahedralization(Domain::Polyhedron(&c), &opts, ctl) {
        Ok((exact::Outcome::Infeasible, stats)) => out!(
            "  Chazelle's polyhedron, 5 grooves ({} vertices, `generate chazelle`): NO, {}",
            c.points.len(),
            stats
                .obstacle
                .map_or("the formula is unsatisfiable".into(), |o| o.to_string())
        ),
        other => out!("  Chazelle's polyhedron: {other:?}"),
    }
}

/// Thesis ch. 4: the region between two nested convex polytopes, no Steiner point.
fn shell_section() {
    use tetrakit::shell::generate::{NestedParams, Shape, bern_disk, nested};
    use tetrakit::shell::{Method, Shell};
    out!(
        "\n7. Shells (thesis ch. 4): the region between nested convex polytopes, no Steiner point."
    );
    let shell_of = |p: NestedParams| {
        let (outer, inner, _) = nested(&p).ok()?;
        Shell::new(&outer, &inner).ok()
    };
    let around_cube = NestedParams {
        outer: Shape::Sphere,
        inner: Shape::Cube,
        n_outer: 200,
        n_inner: 8,
        gap: 0.4,
        seed: 3,
    };
    if let Some(shell) = shell_of(around_cube) {
        out!(
            "  200 random points on a sphere around a cube (n = {}):",
            shell.n()
        );
        both_methods(&shell);
    }
    let small = NestedParams {
        outer: Shape::Random,
        inner: Shape::Sphere,
        n_outer: 9,
        n_inner: 6,
        gap: 0.5,
        seed: 4,
    };
    if let Some(shell) = shell_of(small) {
        out!(
            "  a small shell (n = {}), against the exact optimum:",
            shell.n()
        );
        both_methods(&shell);
        let start = Instant::now();
        match tetrakit::shell::optimum(&shell, &Control::new()) {
            Ok((tetrakit::exact::Outcome::Optimal { tets, .. }, _)) => out!(
                "    optimum (SAT, every triangulation of the facets): {} tetrahedra, {} [{:.0} ms]",
                tets.len(),
                certified(&shell, &tets),
                start.elapsed().as_secs_f64() * 1e3
            ),
            other => out!("    optimum: {other:?}"),
        }
    }
    if let Some(shell) = bern_disk(1000, 250, 1)
        .ok()
        .and_then(|(o, i)| Shell::new(&o, &i).ok())
    {
        out!(
            "  a Bern disk (n = {}), where minimum-degree cap removal is Θ(n log n); the flips recover:",
            shell.n()
        );
        shell_line(&shell, Method::Cap);
    }
    use tetrakit::shell::generate::{Contact, contact};
    if let Some(shell) = contact(Contact::Edge, 30, 12, 1)
        .ok()
        .and_then(|(o, i)| Shell::new(&o, &i).ok())
    {
        out!(
            "  Q touching P along one shared edge (`generate contact --kind edge`, n = {}):",
            shell.n()
        );
        shell_line(&shell, Method::Cap);
    }
    let (outer, inner, _) = tetrakit::shell::lemma41::counterexample();
    if let Ok(shell) = Shell::new(&outer, &inner) {
        let opts = tetrakit::shell::ShellOptions::new(Method::Thesis);
        match tetrakit::shell::shell(&shell, opts, &Control::new()) {
            Ok(o) if o.witness.is_some() => out!(
                "  the thesis's Lemma 4.1 fails (`generate lemma41`, 10 points; `shell --method thesis`):\n    {}",
                o.witness.map(|w| w.detail).unwrap_or_default()
            ),
            other => out!("  Lemma 4.1's counterexample: {other:?}"),
        }
    }
}

fn certified(shell: &tetrakit::shell::Shell, tets: &[[u32; 4]]) -> String {
    match tetrakit::mesh::certify_shell(&shell.points, tets, &shell.inner) {
        Ok(()) => "certified".to_string(),
        Err(p) => format!("NOT certified: {p}"),
    }
}

fn both_methods(shell: &tetrakit::shell::Shell) {
    for method in [
        tetrakit::shell::Method::Cap,
        tetrakit::shell::Method::Bigcap,
    ] {
        shell_line(shell, method);
    }
}

/// One method on a shell: the removals' count, the count after the flips, the bound,
/// and the certificate of the final mesh.
fn shell_line(shell: &tetrakit::shell::Shell, method: tetrakit::shell::Method) {
    let start = Instant::now();
    let ctl = Control::new();
    let result = tetrakit::shell::tetrahedralize(shell, method, &ctl).and_then(|mut m| {
        let done = tetrakit::shell::improve(&shell.points, &mut m, &ctl)?;
        Ok((m, done))
    });
    let ms = start.elapsed().as_secs_f64() * 1e3;
    let n = shell.n();
    match result {
        Ok((m, done)) => out!(
            "    {}: {} tetrahedra, {} after flips (9n − 6 = {}), {} [{ms:.0} ms]",
            method.name(),
            done.before,
            m.tets.len(),
            9 * n - 6,
            certified(shell, &m.tets)
        ),
        Err(e) => out!("    {}: {e}", method.name()),
    }
}

/// Chapter 5: β-skeleton, exact MWT with ties, and the Keil construction.
fn planar_section() {
    use tetrakit::planar::{self, Distribution, MwtOptions, Region};
    let (ctl, opts) = (Control::new(), MwtOptions::default());
    out!(
        "\n8. Planar proximity (thesis ch. 5): β-skeleton and exact minimum weight triangulation."
    );
    let pts = planar::points2d(Distribution::Uniform, 2000, 7);
    let start = Instant::now();
    let beta = "1.16".parse().expect("a ratio");
    let sk = planar::beta_skeleton(&pts, beta, Region::Circle, &ctl).expect("valid points");
    let m = planar::mwt(&pts, &opts, &ctl).expect("valid points");
    let inside = sk
        .edges
        .iter()
        .filter(|e| m.edges.binary_search(e).is_ok())
        .count();
    out!(
        "  2000 uniform points: 1.16-skeleton {} edges, MWT {} edges of weight {:.9} (certified to ±{:.1e}); {} of the skeleton's edges are in the MWT [{:.0} ms]",
        sk.edges.len(),
        m.edges.len(),
        m.weight.mid(),
        0.5 * (m.weight.hi - m.weight.lo),
        inside,
        start.elapsed().as_secs_f64() * 1e3
    );
    let grid = planar::points2d(Distribution::Grid, 36, 1);
    let g = planar::mwt(&grid, &opts, &ctl).expect("valid points");
    out!(
        "  a 6x6 integer grid (every square a tie): MWT weight {:.9}, {} faces left to the exact stage, ties decided exactly",
        g.weight.mid(),
        g.stats.faces_left
    );
    // β = 1.16 with n = 420, the smallest n at which this realization separates xy
    // (tests pin 400 and 420); `tetrakit keil --beta 1.16` uses Lemma 5.8's n instead.
    for (b, n) in [("1.1548", None), ("1.16", Some(420))] {
        let start = Instant::now();
        match planar::keil(b.parse().expect("a ratio"), n, &ctl).map(|k| k.decided()) {
            Ok(Some(k)) => {
                let svg = std::env::temp_dir().join(format!("tetrakit-keil-{b}.svg"));
                let picture = match std::fs::write(&svg, tetrakit::report::keil_svg(&k)) {
                    Ok(()) => format!("picture: {}", svg.display()),
                    Err(e) => format!("no picture ({e})"),
                };
                out!(
                    "  Keil construction (§5.2) at β = {b}, n = {} ({} sites; Lemma 5.8 asks n > {:.1}): xy in the β-skeleton: {}; in an MWT: {}",
                    k.construction.n,
                    k.construction.sites.len(),
                    k.construction.lemma_bound,
                    k.construction.xy_in_skeleton,
                    k.xy_in_mwt,
                );
                out!(
                    "    best with xy {:.9}, without {:.9}{} [{:.0} ms; {picture}]",
                    k.with_xy.0.mid(),
                    k.without_xy.0.mid(),
                    if k.construction.xy_in_skeleton && !k.xy_in_mwt {
                        " -> Keil's conjecture fails (exact)"
                    } else {
                        " (not separated at this n)"
                    },
                    start.elapsed().as_secs_f64() * 1e3
                );
            }
            Ok(None) => out!("  Keil construction at β = {b}: undecided"),
            Err(e) => out!("  Keil construction at β = {b}: {e}"),
        }
    }
}

/// Chapter 6: the flip graph, enumerated exactly.
fn flip_graph_section() {
    use tetrakit::flipgraph::{FlipOptions, flip_graph};
    out!("\n9. Open problems (thesis ch. 6): is the flip graph of tetrahedralizations connected?");
    let cube: Vec<[f64; 3]> = (0..8)
        .map(|i| [(i & 1) as f64, (i >> 1 & 1) as f64, (i >> 2) as f64])
        .collect();
    let mut rng = tetrakit::rng::Rng::new(6);
    let random: Vec<[f64; 3]> = (0..10)
        .map(|_| [0, 1, 2].map(|_| rng.below(1000) as f64))
        .collect();
    for (name, pts) in [("the cube's 8 corners", cube), ("10 random points", random)] {
        let start = Instant::now();
        match flip_graph(&pts, &FlipOptions::default(), &Control::new()) {
            Ok(g) => {
                let f = g.graph.as_ref().expect("a complete enumeration");
                out!(
                    "  {name}: {} tetrahedralizations (all enumerated, each certified), {} flips, {} component(s), {} to {} flips each, {} without a flip [{:.0} ms]",
                    g.tetrahedralizations,
                    f.flips.total,
                    f.components,
                    f.min_flips,
                    f.max_flips,
                    f.isolated.len(),
                    start.elapsed().as_secs_f64() * 1e3
                );
            }
            Err(e) => out!("  {name}: {e}"),
        }
    }
    let grid: Vec<[f64; 3]> = (0..12)
        .map(|i| [(i % 3) as f64, (i / 3 % 2) as f64, (i / 6) as f64])
        .collect();
    let start = Instant::now();
    match tetrakit::flipgraph::count(&grid, usize::MAX, &Control::new()) {
        Ok(c) => out!(
            "  a 3x2x2 grid (`flips --count-only`): {} tetrahedralizations, each certified, none kept [{:.0} ms]",
            c.tetrahedralizations,
            start.elapsed().as_secs_f64() * 1e3
        ),
        Err(e) => out!("  a 3x2x2 grid: {e}"),
    }
    let sphere = tetrakit::generate::points3d(tetrakit::generate::Distribution3::Convex, 60, 2);
    let start = Instant::now();
    let opts = tetrakit::dualpath::PathOptions::default();
    match tetrakit::dualpath::hamiltonian(&sphere, &opts, &Control::new()) {
        Ok(h) => out!(
            "  60 points on a sphere (`tetrahedralize --hamiltonian`): {} tetrahedra in a Hamiltonian dual path, certified ({} for an ordinary cone) [{:.0} ms]",
            h.tetrahedra,
            h.ordinary_tetrahedra.unwrap_or(0),
            start.elapsed().as_secs_f64() * 1e3
        ),
        Err(e) => out!("  60 points on a sphere: {e}"),
    }
    kleetope_demo(&opts);
}

/// The Kleetope of the octahedron (a pyramid on each facet): every cone from an
/// octahedron vertex has no Hamiltonian dual path, proven by SAT.
fn kleetope_demo(opts: &tetrakit::dualpath::PathOptions) {
    let mut klee: Vec<[f64; 3]> = (0..6)
        .map(|i| {
            let mut p = [0.0; 3];
            p[i % 3] = if i < 3 { 1.0 } else { -1.0 };
            p
        })
        .collect();
    klee.extend((0..8).map(|s| [0, 1, 2].map(|k| if s >> k & 1 == 1 { 0.4 } else { -0.4 })));
    let start = Instant::now();
    match tetrakit::dualpath::hamiltonian(&klee, opts, &Control::new()) {
        Ok(h) => out!(
            "  the octahedron's Kleetope: {} cones proven by SAT to have no Hamiltonian dual path, then one with a path of {} tetrahedra, certified [{:.0} ms]",
            h.cones_refuted,
            h.tetrahedra,
            start.elapsed().as_secs_f64() * 1e3
        ),
        Err(e) => out!("  the octahedron's Kleetope: {e}"),
    }
}
