//! Partitioned meshes (`.pvtu` and multi-piece `.vtu`): checking the pieces gives the
//! verdict and the problems of checking the merged mesh, on valid and corrupted meshes
//! cut into pieces in several ways (slabs, random labels), interface vertices written
//! once per piece.

mod common;

use std::path::{Path, PathBuf};
use tetrakit::geom::Point3;
use tetrakit::io::{ReadOptions, read_input_with, write_pieces};
use tetrakit::mesh::{CheckOptions, check};
use tetrakit::rng::Rng;

fn dir(name: &str) -> PathBuf {
    let d = common::scratch().join(name);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// A problem's kind and its tetrahedra, each as its sorted corners' coordinate bits.
type Named = (String, Vec<[[u64; 3]; 4]>);

/// The problems of a check as (kind, the tetrahedra named as their corners' coordinates),
/// sorted: comparable across numberings.
fn problems(points: &[Point3], tets: &[[u32; 4]]) -> (bool, Vec<Named>) {
    let o = check(points, tets.to_vec(), CheckOptions::default());
    let corners = |t: u32| {
        let mut c = tets[t as usize].map(|v| points[v as usize].map(f64::to_bits));
        c.sort();
        c
    };
    let mut found: Vec<_> = o
        .problems
        .iter()
        .map(|p| {
            let mut cells: Vec<_> = p.cells.iter().map(|&t| corners(t)).collect();
            cells.sort();
            (p.kind.to_string(), cells)
        })
        .collect();
    found.sort();
    (o.is_valid(), found)
}

/// Writes `tets` in pieces by `piece_of` and reads them back as one mesh.
fn through_pieces(
    path: &Path,
    points: &[Point3],
    tets: &[[u32; 4]],
    piece_of: &[u32],
) -> (Vec<Point3>, Vec<[u32; 4]>) {
    write_pieces(path, points, tets, piece_of, None).unwrap();
    let opts = ReadOptions {
        mesh: true,
        ..Default::default()
    };
    let input = read_input_with(path, opts).unwrap();
    (input.points, input.tets)
}

/// Cuts in slabs along x (`generate::slabs`, as `generate -o X.pvtu` does) or at random.
fn partitions(points: &[Point3], tets: &[[u32; 4]], k: u32, rng: &mut Rng) -> [Vec<u32>; 2] {
    [
        tetrakit::generate::slabs(points, tets, k as usize),
        tets.iter().map(|_| rng.below(k as usize) as u32).collect(),
    ]
}

#[test]
fn pieces_check_as_the_merged_mesh() {
    let d = dir("diff");
    let mut rng = Rng::new(46);
    let (mut cases, mut invalid) = (0, 0);
    for round in 0..60u64 {
        let t = match round % 3 {
            0 => tetrakit::generate::kuhn(2 + (round as usize % 3)),
            1 => {
                tetrakit::generate::random_tetrahedralization(20 + round as usize, 30, round, None)
            }
            _ => tetrakit::generate::random_tetrahedralization(30, 20, round, Some(4)),
        };
        let (points, mut tets) = (t.points, t.tets);
        // Corruptions, at whatever piece boundary they fall on: a tetrahedron dropped,
        // one inverted, one repeated.
        match round % 4 {
            1 => {
                tets.remove(rng.below(tets.len()));
            }
            2 => {
                let k = rng.below(tets.len());
                tets[k].swap(0, 1);
            }
            3 => {
                let k = rng.below(tets.len());
                tets.push(tets[k]);
            }
            _ => {}
        }
        let want = problems(&points, &tets);
        for (how, piece_of) in partitions(&points, &tets, 2 + (round % 4) as u32, &mut rng)
            .iter()
            .enumerate()
        {
            let path = d.join(format!("m{round}_{how}.pvtu"));
            let (p, t) = through_pieces(&path, &points, &tets, piece_of);
            assert_eq!(t.len(), tets.len());
            assert_eq!(problems(&p, &t), want, "round {round}, partition {how}");
            cases += 1;
            invalid += usize::from(!want.0);
        }
    }
    assert!(
        cases == 120 && invalid >= 40,
        "{cases} cases, {invalid} invalid"
    );
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn a_piece_outside_the_folder_or_missing_is_named() {
    let d = dir("bad");
    let t = tetrakit::generate::kuhn(1);
    let path = d.join("k.pvtu");
    write_pieces(&path, &t.points, &t.tets, &[0, 0, 0, 1, 1, 1], None).unwrap();
    let read = |text: &str| {
        std::fs::write(&path, text).unwrap();
        tetrakit::io::read_input(&path)
            .map(|_| ())
            .unwrap_err()
            .to_string()
    };
    let index = std::fs::read_to_string(&path).unwrap();
    let outside = read(&index.replace("k_1.vtu", "../k_1.vtu"));
    assert!(outside.contains("k.pvtu:8:"), "{outside}");
    assert!(
        outside.contains("not a file inside the .pvtu's folder"),
        "{outside}"
    );
    let missing = read(&index.replace("k_1.vtu", "k_9.vtu"));
    assert!(missing.contains("k_9.vtu"), "{missing}");
    let none = read(
        "<VTKFile type=\"PUnstructuredGrid\"><PUnstructuredGrid></PUnstructuredGrid></VTKFile>",
    );
    assert!(none.contains("without a Piece"), "{none}");
    let _ = std::fs::remove_dir_all(&d);
}

/// An interface vertex one ulp off in one piece. Without a shared global id it is
/// another vertex: the merged mesh has two vertices there, and the faces around them,
/// unpaired, are boundary: a cavity one ulp thick, closed, so a valid mesh of a domain
/// with a void (what checking the merged mesh says too). With the global id the pieces
/// give it (`GlobalNodeIds`), it is an `interface_mismatch` naming both points.
#[test]
fn an_interface_vertex_one_ulp_apart_is_a_problem() {
    let d = dir("ulp");
    let t = tetrakit::generate::kuhn(2);
    let right = |tt: &[u32; 4]| tt.iter().any(|&v| t.points[v as usize][0] > 1.0);
    let piece_of: Vec<u32> = t.tets.iter().map(|tt| u32::from(right(tt))).collect();
    let path = d.join("u.pvtu");
    let (p, tets) = through_pieces(&path, &t.points, &t.tets, &piece_of);
    let whole = check(&p, tets, CheckOptions::default());
    assert!(whole.is_valid());
    // The interface vertex (1, 1, 1), one ulp further in piece 1.
    let v = t.points.iter().position(|q| *q == [1.0, 1.0, 1.0]).unwrap() as u32;
    let mut points = t.points.clone();
    points.push([f64::from_bits(1.0f64.to_bits() + 1), 1.0, 1.0]);
    let nudged = points.len() as u32 - 1;
    let tets: Vec<[u32; 4]> = t
        .tets
        .iter()
        .map(|tt| match right(tt) {
            true => tt.map(|x| if x == v { nudged } else { x }),
            false => *tt,
        })
        .collect();
    let (p, tets) = through_pieces(&path, &points, &tets, &piece_of);
    assert_eq!(p.len(), t.points.len() + 1, "two vertices, one ulp apart");
    let o = check(&p, tets, CheckOptions::default());
    assert!(
        o.boundary_faces > whole.boundary_faces,
        "the cavity's faces"
    );
    assert_eq!(o.is_valid(), problems(&p, &o.tets).0);
    let _ = std::fs::remove_dir_all(&d);
}

/// The tetrahedra of `tets` grouped by `piece_of` (stable), with each piece's first.
fn grouped(tets: &[[u32; 4]], piece_of: &[u32], k: u32) -> (Vec<[u32; 4]>, Vec<u32>) {
    let mut order: Vec<usize> = (0..tets.len()).collect();
    order.sort_by_key(|&i| piece_of[i]);
    let first = (0..k)
        .map(|p| piece_of.iter().filter(|&&q| q < p).count() as u32)
        .collect();
    (order.iter().map(|&i| tets[i]).collect(), first)
}

/// A corruption of kind `kind` of a mesh: what a partitioned mesh goes wrong with.
fn corrupt(points: &mut Vec<Point3>, tets: &mut Vec<[u32; 4]>, kind: u64, rng: &mut Rng) {
    let k = rng.below(tets.len());
    match kind {
        1 => {
            tets.remove(k);
        }
        2 => tets[k].swap(0, 1),
        3 => tets.push(tets[k]),
        4 => {
            // A tetrahedron over a face of another, its apex some other vertex.
            let apex = tets[rng.below(tets.len())][rng.below(4)];
            let t = tets[k];
            if !t.contains(&apex) {
                tets.push([t[0], t[1], t[2], apex]);
            }
        }
        5 => {
            // A small separate tetrahedron inside another one.
            let c = tets[k].map(|v| points[v as usize]);
            let at = |w: [f64; 4]| -> Point3 {
                std::array::from_fn(|i| (0..4).map(|j| w[j] * c[j][i]).sum::<f64>())
            };
            let n = points.len() as u32;
            points.extend([
                at([0.4, 0.2, 0.2, 0.2]),
                at([0.2, 0.4, 0.2, 0.2]),
                at([0.2, 0.2, 0.4, 0.2]),
                at([0.2, 0.2, 0.2, 0.4]),
            ]);
            tets.push([n, n + 1, n + 2, n + 3]);
        }
        6 => {
            // A vertex moved far: tetrahedra around it turn or overlap.
            let v = tets[k][0] as usize;
            points[v] = std::array::from_fn(|i| points[v][i] + rng.unit() - 0.5);
        }
        7 | 8 => {
            // A vertex copied (exactly, or one ulp off) for some of its tetrahedra.
            let v = tets[k][rng.below(4)];
            let mut p = points[v as usize];
            if let Some(c) = (0..3).rev().find(|&c| p[c] != 0.0).filter(|_| kind == 8) {
                p[c] = f64::from_bits(p[c].to_bits() + 1);
            }
            points.push(p);
            let copy = points.len() as u32 - 1;
            for t in tets.iter_mut().filter(|_| rng.below(2) == 0) {
                t.iter_mut().filter(|x| **x == v).for_each(|x| *x = copy);
            }
        }
        _ => {}
    }
}

/// Mesh number `round`: a Kuhn grid, a random tetrahedralization or one on an integer
/// grid, with corruption `round mod 9` ([`corrupt`]).
fn corrupted(round: u64, rng: &mut Rng) -> (Vec<Point3>, Vec<[u32; 4]>) {
    let t = match round % 3 {
        0 => tetrakit::generate::kuhn(2 + (round as usize % 3)),
        1 => {
            tetrakit::generate::random_tetrahedralization(12 + round as usize % 40, 30, round, None)
        }
        _ => tetrakit::generate::random_tetrahedralization(20, 20, round, Some(3)),
    };
    let (mut points, mut tets) = (t.points, t.tets);
    corrupt(&mut points, &mut tets, round % 9, rng);
    (points, tets)
}

/// Checked part by part (`check_pieces`), a mesh gives exactly what the merged check
/// gives (verdict, problems in order with their texts, counts), valid or corrupted in
/// nine ways, cut in slabs, at random and in blocks into 2 to 6 pieces, with and without
/// `convex` and `manifold`.
#[test]
fn checking_part_by_part_is_checking_the_merged_mesh() {
    use tetrakit::mesh::check_pieces;
    let mut rng = Rng::new(4646);
    let (mut cases, mut invalid, mut kinds) = (0, 0, std::collections::BTreeSet::new());
    for round in 0..450u64 {
        let (points, tets) = corrupted(round, &mut rng);
        let k = 2 + (round % 5) as u32;
        let [slabs, random] = partitions(&points, &tets, k, &mut rng);
        let blocks: Vec<u32> = (0..tets.len())
            .map(|i| (i * k as usize / tets.len()) as u32)
            .collect();
        for (how, piece_of) in [slabs, random, blocks].iter().enumerate() {
            let (tets, first) = grouped(&tets, piece_of, k);
            for (convex, manifold) in [(false, false), (true, false), (false, true)] {
                let opts = CheckOptions {
                    convex,
                    manifold,
                    reorient: false,
                };
                let whole = check(&points, tets.clone(), opts);
                let parts = check_pieces(&points, tets.clone(), &first, opts);
                let at =
                    format!("round {round}, partition {how}, convex {convex}, manifold {manifold}");
                assert_eq!(parts.problems, whole.problems, "{at}");
                assert_eq!(
                    (
                        parts.verdict,
                        parts.problem_count,
                        parts.boundary_faces,
                        parts.non_manifold_edges
                    ),
                    (
                        whole.verdict,
                        whole.problem_count,
                        whole.boundary_faces,
                        whole.non_manifold_edges
                    ),
                    "{at}"
                );
                assert_eq!(parts.cell_problems, whole.cell_problems, "{at}");
                cases += 1;
                invalid += usize::from(!whole.is_valid());
                kinds.extend(whole.problems.iter().map(|p| p.kind.to_string()));
            }
        }
    }
    assert!(
        cases >= 4000 && invalid >= 1500,
        "{cases} cases, {invalid} invalid"
    );
    for kind in [
        "inverted",
        "same_side",
        "face_shared_by_more",
        "open_boundary",
        "overlap",
        "coincident_vertices",
        "boundary_not_on_hull",
        "non_manifold_edge",
    ] {
        assert!(kinds.contains(kind), "no case found {kind}: {kinds:?}");
    }
}

/// The mesh partitioned by `piece_of` written to `path` (a `.pvtu`), its points with
/// global ids or without.
fn written(path: &Path, points: &[Point3], tets: &[[u32; 4]], piece_of: &[u32], ids: bool) {
    let global: Vec<i32> = (0..points.len() as i32).collect();
    write_pieces(path, points, tets, piece_of, ids.then_some(&global[..])).unwrap();
}

/// The `.pvtu` at `path` read as `tetrakit check` reads it and checked part by part, the
/// problems in the merged mesh's numbering.
fn merged_check(
    path: &Path,
    opts: CheckOptions,
) -> (tetrakit::io::Input, tetrakit::mesh::CheckOutcome) {
    let read = ReadOptions {
        mesh: true,
        ..Default::default()
    };
    let input = read_input_with(path, read).unwrap();
    let first: Vec<u32> = input.pieces.iter().map(|p| p.first_tet).collect();
    let o = tetrakit::mesh::check_pieces(&input.points, input.tets.clone(), &first, opts)
        .with_problems(input.interface_problems());
    (input, o)
}

/// What `tetrakit check X.pvtu` says: the merged mesh checked part by part, in the
/// file's numbering.
fn cli_check(path: &Path, opts: CheckOptions) -> tetrakit::mesh::CheckOutcome {
    let (input, o) = merged_check(path, opts);
    o.relabeled(
        |v| input.point_label(v as usize),
        |t| input.tet_label(t as usize),
    )
}

/// Checked by 1 to 5 ranks that each read only their pieces and exchange messages
/// (`distributed::check_in_ranks`, what `mpirun python3 -m tetrakit.mpi` runs), a
/// `.pvtu` gives what `tetrakit check` gives, problem for problem, with and without
/// global ids, and with more ranks than pieces.
#[test]
fn ranks_check_as_the_merged_mesh() {
    use tetrakit::distributed::check_in_ranks;
    let d = dir("ranks");
    let mut rng = Rng::new(4647);
    let (mut cases, mut invalid) = (0, 0);
    for round in 0..120u64 {
        let (points, tets) = corrupted(round, &mut rng);
        let k = 2 + (round % 4) as u32;
        let [slabs, random] = partitions(&points, &tets, k, &mut rng);
        for (how, piece_of) in [slabs, random].iter().enumerate() {
            let path = d.join(format!("r{round}_{how}.pvtu"));
            written(&path, &points, &tets, piece_of, (round / 2) % 2 == 0);
            let opts = match round % 4 {
                1 => CheckOptions {
                    convex: true,
                    ..Default::default()
                },
                2 => CheckOptions {
                    manifold: true,
                    reorient: true,
                    ..Default::default()
                },
                _ => CheckOptions::default(),
            };
            let want = cli_check(&path, opts);
            for size in [1, 2, 3, 5] {
                let (got, sent) = check_in_ranks(&path, size, opts);
                let got = got.unwrap();
                let at = format!("round {round}, partition {how}, {size} ranks, {opts:?}");
                assert_eq!(got.problems, want.problems, "{at}");
                assert_eq!(
                    (
                        got.verdict,
                        got.problem_count,
                        got.boundary_faces,
                        got.non_manifold_edges
                    ),
                    (
                        want.verdict,
                        want.problem_count,
                        want.boundary_faces,
                        want.non_manifold_edges
                    ),
                    "{at}"
                );
                assert_eq!(
                    (got.tetrahedra, got.vertices, got.reoriented),
                    (want.tetrahedra, want.vertices, want.reoriented),
                    "{at}"
                );
                assert!(sent.iter().all(|&b| b > 0), "{at}");
                cases += 1;
                invalid += usize::from(!want.is_valid());
            }
        }
    }
    assert!(
        cases >= 900 && invalid >= 300,
        "{cases} cases, {invalid} invalid"
    );
    let _ = std::fs::remove_dir_all(&d);
}

/// Pieces that disagree in layout (one with global ids, one without) are bad input, in
/// the reader and under ranks alike, naming both pieces.
#[test]
fn pieces_with_and_without_global_ids_are_refused() {
    let d = dir("layout");
    let t = tetrakit::generate::kuhn(2);
    let path = d.join("m.pvtu");
    let piece_of = tetrakit::generate::slabs(&t.points, &t.tets, 2);
    write_pieces(&path, &t.points, &t.tets, &piece_of, None).unwrap();
    let second = d.join("m_1.vtu");
    let text = std::fs::read_to_string(&second).unwrap();
    let (a, b) = (
        text.find("<PointData>").unwrap(),
        text.find("</PointData>").unwrap(),
    );
    std::fs::write(&second, format!("{}{}", &text[..a], &text[b + 12..])).unwrap();
    let err = tetrakit::io::read_input(&path).unwrap_err().to_string();
    assert!(
        err.contains("m_0.vtu") && err.contains("m_1.vtu") && err.contains("disagree in layout"),
        "{err}"
    );
    let (ranks, _) = tetrakit::distributed::check_in_ranks(&path, 2, CheckOptions::default());
    let err = ranks.unwrap_err().to_string();
    assert!(
        err.contains("m_0.vtu") && err.contains("m_1.vtu") && err.contains("disagree in layout"),
        "{err}"
    );
    let _ = std::fs::remove_dir_all(&d);
}

/// An empty piece (a partition without cells, as ParaView writes one) takes part: the
/// check is the other pieces', in `check` and under ranks, with global ids or without.
#[test]
fn an_empty_piece_is_a_piece() {
    let d = dir("empty");
    let t = tetrakit::generate::kuhn(2);
    // Labels 0 and 2: piece 1 is empty.
    let piece_of: Vec<u32> = (tetrakit::generate::slabs(&t.points, &t.tets, 2).iter())
        .map(|&p| 2 * p)
        .collect();
    for ids in [false, true] {
        let path = d.join(format!("e{ids}.pvtu"));
        let all: Vec<i32> = (0..t.points.len() as i32).collect();
        write_pieces(
            &path,
            &t.points,
            &t.tets,
            &piece_of,
            ids.then_some(&all[..]),
        )
        .unwrap();
        let want = cli_check(&path, CheckOptions::default());
        assert!(want.is_valid());
        for size in [1, 2, 3] {
            let (got, _) =
                tetrakit::distributed::check_in_ranks(&path, size, CheckOptions::default());
            let got = got.unwrap();
            assert_eq!(
                (got.verdict, got.tetrahedra, got.vertices),
                (want.verdict, want.tetrahedra, want.vertices)
            );
        }
    }
    let _ = std::fs::remove_dir_all(&d);
}

/// A coordinate the exact predicates cannot take (here 1e-300, below 2^-142) in one
/// piece is bad input, in `check` and under ranks: never checked.
#[test]
fn a_piece_with_a_coordinate_out_of_range_is_refused() {
    let d = dir("range");
    let mut t = tetrakit::generate::kuhn(2);
    let piece_of = tetrakit::generate::slabs(&t.points, &t.tets, 2);
    let v = t.points.iter().position(|p| p[0] == 2.0).unwrap();
    t.points[v][1] = 1e-300;
    let path = d.join("m.pvtu");
    write_pieces(&path, &t.points, &t.tets, &piece_of, None).unwrap();
    let err = tetrakit::io::read_input(&path).unwrap_err().to_string();
    assert!(err.contains("1e-300") && err.contains("m_1.vtu"), "{err}");
    let (ranks, _) = tetrakit::distributed::check_in_ranks(&path, 2, CheckOptions::default());
    let err = ranks.unwrap_err().to_string();
    assert!(err.contains("1e-300") && err.contains("m_1.vtu"), "{err}");
    let _ = std::fs::remove_dir_all(&d);
}

/// `--output P.pvtu` under ranks (`RankCheck::with_output`: each rank writes its own
/// pieces, rank 0 the index) writes the files `tetrakit check X.pvtu --output P.pvtu`
/// writes, byte for byte: the same points, tetrahedra (turned with `reorient`), global
/// ids and problem codes on cells and points, on valid and corrupted meshes.
#[test]
fn ranks_write_the_pieces_check_writes() {
    use tetrakit::distributed::check_in_ranks_writing;
    let d = dir("ranks-output");
    let mut rng = Rng::new(91);
    let mut marked = 0;
    for round in 0..40u64 {
        let (points, tets) = corrupted(round, &mut rng);
        let k = 2 + (round % 3) as u32;
        let [slabs, random] = partitions(&points, &tets, k, &mut rng);
        let piece_of = if round % 2 == 0 { slabs } else { random };
        let path = d.join(format!("w{round}.pvtu"));
        written(&path, &points, &tets, &piece_of, (round / 2) % 2 == 0);
        let opts = CheckOptions {
            reorient: round % 3 == 1,
            manifold: round % 5 == 2,
            ..Default::default()
        };
        let (input, want) = merged_check(&path, opts);
        let one = d.join(format!("one{round}.pvtu"));
        tetrakit::io::write_check_output(&one, &input, &want).unwrap();
        marked += usize::from(want.cell_problems.iter().any(|&c| c != 0));
        for size in [1, 2, 4] {
            let many = d.join(format!("many{round}_{size}.pvtu"));
            let (got, _) = check_in_ranks_writing(&path, size, opts, Some(&many));
            assert_eq!(
                got.unwrap().problem_count,
                want.problem_count,
                "round {round}"
            );
            for p in 0..k as usize {
                let a = std::fs::read(tetrakit::io::piece_path(&one, p)).unwrap();
                let b = std::fs::read(tetrakit::io::piece_path(&many, p)).unwrap();
                assert!(a == b, "round {round}, {size} ranks: piece {p} differs");
            }
            let index =
                |p: &Path, stem: &str| std::fs::read_to_string(p).unwrap().replace(stem, "X");
            assert_eq!(
                index(&one, &format!("one{round}")),
                index(&many, &format!("many{round}_{size}")),
                "round {round}"
            );
        }
    }
    assert!(marked >= 10, "only {marked} meshes had problems to mark");
}

/// The pieces of the `.pvtu` at `path` (written by [`written`], `k` of them) regrouped
/// into files of several `Piece`s each (`sizes`, in order), under a new index at `to`.
fn regrouped(path: &Path, k: usize, sizes: &[usize], to: &Path) {
    let stem = to.file_stem().unwrap().to_string_lossy().into_owned();
    let mut names = Vec::new();
    let mut next = 0;
    for (g, &n) in sizes.iter().enumerate() {
        let texts: Vec<String> = (next..(next + n).min(k))
            .map(|p| std::fs::read_to_string(tetrakit::io::piece_path(path, p)).unwrap())
            .collect();
        next += n;
        let piece = |t: &String| {
            let (a, b) = (t.find("<Piece ").unwrap(), t.rfind("</Piece>").unwrap());
            t[a..b + "</Piece>\n".len()].to_string()
        };
        let head = &texts[0][..texts[0].find("<Piece ").unwrap()];
        let tail = &texts[0][texts[0].rfind("</Piece>").unwrap() + "</Piece>\n".len()..];
        let body: String = texts.iter().map(piece).collect();
        let name = to.with_file_name(format!("{stem}_group{g}.vtu"));
        std::fs::write(&name, format!("{head}{body}{tail}")).unwrap();
        names.push(name);
    }
    tetrakit::io::write_pvtu_index(to, &names).unwrap();
}

/// A `.pvtu` whose files hold several `Piece`s each (as VTK's writers may put them) has
/// that many pieces: `tetrakit check` and the ranks (which read whole files) number the
/// pieces and their vertices alike, so the problems are those of the same pieces one per
/// file, and `--output` under ranks writes what `check --output` writes.
#[test]
fn several_pieces_in_one_file_are_pieces_under_ranks() {
    use tetrakit::distributed::{check_in_ranks, check_in_ranks_writing};
    let d = dir("grouped");
    let mut rng = Rng::new(4646);
    let (mut cases, mut invalid) = (0, 0);
    for round in 0..60u64 {
        let (points, tets) = corrupted(round, &mut rng);
        let k = 3 + (round % 4) as usize;
        let [slabs, random] = partitions(&points, &tets, k as u32, &mut rng);
        let piece_of = if round % 2 == 0 { slabs } else { random };
        let path = d.join(format!("g{round}.pvtu"));
        written(&path, &points, &tets, &piece_of, (round / 2) % 2 == 0);
        let mut sizes = Vec::new();
        while sizes.iter().sum::<usize>() < k {
            sizes.push(1 + rng.below(3));
        }
        let grouped = d.join(format!("h{round}.pvtu"));
        regrouped(&path, k, &sizes, &grouped);
        let opts = CheckOptions {
            reorient: round % 3 == 1,
            manifold: round % 5 == 2,
            convex: round % 7 == 3,
        };
        let want = cli_check(&path, opts);
        let (input, merged) = merged_check(&grouped, opts);
        assert_eq!(input.pieces.len(), k, "round {round}");
        assert_eq!(
            cli_check(&grouped, opts).problems,
            want.problems,
            "round {round}"
        );
        let one = d.join(format!("one{round}.pvtu"));
        tetrakit::io::write_check_output(&one, &input, &merged).unwrap();
        for size in [1, 2, 3] {
            let at = format!("round {round}, groups {sizes:?}, {size} ranks");
            let (got, _) = check_in_ranks(&grouped, size, opts);
            let got = got.unwrap();
            assert_eq!(got.problems, want.problems, "{at}");
            assert_eq!(
                (got.verdict, got.tetrahedra, got.vertices, got.reoriented),
                (
                    want.verdict,
                    want.tetrahedra,
                    want.vertices,
                    want.reoriented
                ),
                "{at}"
            );
            let many = d.join(format!("many{round}_{size}.pvtu"));
            let (written, _) = check_in_ranks_writing(&grouped, size, opts, Some(&many));
            assert_eq!(written.unwrap().problem_count, want.problem_count, "{at}");
            for p in 0..k {
                let a = std::fs::read(tetrakit::io::piece_path(&one, p)).unwrap();
                let b = std::fs::read(tetrakit::io::piece_path(&many, p)).unwrap();
                assert!(a == b, "{at}: piece {p} differs");
            }
            cases += 1;
            invalid += usize::from(!want.is_valid());
        }
    }
    assert!(
        cases == 180 && invalid >= 60,
        "{cases} cases, {invalid} invalid"
    );
    let _ = std::fs::remove_dir_all(&d);
}

/// The pieces are decoded several files at a time but merged in order: with a bad cell
/// in piece 1 and a file that is not XML at piece 2, the error is piece 1's, on one
/// thread or four, as reading one file after another finds it.
#[test]
fn the_first_bad_piece_is_the_one_named() {
    let d = dir("first-bad");
    let t = tetrakit::generate::kuhn(3);
    let path = d.join("m.pvtu");
    let piece_of = tetrakit::generate::slabs(&t.points, &t.tets, 4);
    write_pieces(&path, &t.points, &t.tets, &piece_of, None).unwrap();
    let one = d.join("m_1.vtu");
    let text = std::fs::read_to_string(&one).unwrap();
    let at = text
        .find("Name=\"connectivity\" format=\"ascii\">\n")
        .unwrap()
        + 36;
    let first = at + text[at..].find(' ').unwrap();
    std::fs::write(&one, format!("{}999{}", &text[..at], &text[first..])).unwrap();
    std::fs::write(d.join("m_2.vtu"), "<VTKFile").unwrap();
    for threads in [1, 4] {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        let err = pool
            .install(|| tetrakit::io::read_input(&path))
            .unwrap_err();
        let err = err.to_string();
        assert!(
            err.contains("m_1.vtu") && err.contains("999"),
            "{threads} threads: {err}"
        );
    }
    let _ = std::fs::remove_dir_all(&d);
}

/// The tetrahedra of `a` and of `b`, `b`'s points moved by `place`, as one mesh.
fn both(
    a: &tetrakit::mesh::Tetrahedralization,
    b: &tetrakit::mesh::Tetrahedralization,
    place: impl Fn(&Point3) -> Point3,
) -> (Vec<Point3>, Vec<[u32; 4]>) {
    let n = a.points.len() as u32;
    let mut points = a.points.clone();
    points.extend(b.points.iter().map(place));
    let mut tets = a.tets.clone();
    tets.extend(b.tets.iter().map(|t| t.map(|v| v + n)));
    (points, tets)
}

/// Two Kuhn grids pushed into each other (each valid, their boundaries crossing), cut
/// into pieces: under ranks the boundary's self-intersection test is spread over a grid
/// of cells, each pair decided by one rank, and the problems are the merged check's,
/// the first 100 pairs included where there are more.
#[test]
fn crossing_boundaries_are_found_across_ranks() {
    use tetrakit::distributed::check_in_ranks;
    let d = dir("crossing");
    let mut rng = Rng::new(4648);
    let (mut cases, mut many, mut few) = (0, 0, 0);
    for round in 0..24u64 {
        let a = tetrakit::generate::kuhn(3 + (round as usize % 4));
        let b = tetrakit::generate::kuhn(3 + (round as usize / 4 % 3));
        let shift: Point3 = std::array::from_fn(|_| 0.3 + 2.0 * rng.unit());
        let (points, tets) = both(&a, &b, |p| std::array::from_fn(|i| p[i] + shift[i]));
        let k = 2 + (round % 4) as u32;
        let [slabs, random] = partitions(&points, &tets, k, &mut rng);
        for (how, piece_of) in [slabs, random].iter().enumerate() {
            let path = d.join(format!("x{round}_{how}.pvtu"));
            written(&path, &points, &tets, piece_of, round % 2 == 0);
            let want = cli_check(&path, CheckOptions::default());
            let crossings = (want.problems.iter())
                .filter(|p| p.kind.to_string() == "boundary_self_intersection")
                .count();
            for size in [1, 2, 3, 5] {
                let (got, _) = check_in_ranks(&path, size, CheckOptions::default());
                let got = got.unwrap();
                let at = format!("round {round}, partition {how}, {size} ranks");
                assert_eq!(got.problems, want.problems, "{at}");
                assert_eq!(got.problem_count, want.problem_count, "{at}");
                cases += 1;
            }
            many += usize::from(crossings == 100);
            few += usize::from((1..100).contains(&crossings));
        }
    }
    assert!(
        cases == 192 && many >= 3 && few >= 3,
        "{cases} cases, {many} with 100 crossings, {few} with fewer"
    );
    let _ = std::fs::remove_dir_all(&d);
}

/// A small Kuhn grid inside one tetrahedron of a larger one, the tetrahedra of both
/// spread over the pieces at random, so that the inner grid's boundary is cut across
/// ranks: its pieces on each rank are joined into one component (by the edges they
/// share), so the check names one nested piece, at the vertex `tetrakit check` names,
/// with 1 to 5 ranks.
#[test]
fn a_nested_mesh_cut_across_ranks_is_one_component() {
    use tetrakit::distributed::check_in_ranks;
    let d = dir("nested");
    let mut rng = Rng::new(91);
    let outer = tetrakit::generate::kuhn(2);
    let host = outer.tets[5].map(|v| outer.points[v as usize]);
    let centre: Point3 = std::array::from_fn(|i| host.iter().map(|c| c[i]).sum::<f64>() / 4.0);
    let (points, tets) = both(&outer, &outer, |p| {
        std::array::from_fn(|i| centre[i] + (p[i] - 1.0) / 64.0)
    });
    let mut split = 0;
    for round in 0..24 {
        let k = 2 + round % 5;
        let piece_of: Vec<u32> = tets.iter().map(|_| rng.below(k as usize) as u32).collect();
        let path = d.join(format!("n{round}.pvtu"));
        written(&path, &points, &tets, &piece_of, round % 2 == 0);
        let want = cli_check(&path, CheckOptions::default());
        let nested: Vec<_> = (want.problems.iter())
            .filter(|p| p.detail.contains("separate piece"))
            .collect();
        assert_eq!(nested.len(), 1, "round {round}: {:?}", want.problems);
        for size in [1, 2, 3, 5] {
            let (got, _) = check_in_ranks(&path, size, CheckOptions::default());
            let got = got.unwrap();
            assert_eq!(got.problems, want.problems, "round {round}, {size} ranks");
        }
        let inner_pieces: std::collections::BTreeSet<u32> =
            piece_of[outer.tets.len()..].iter().copied().collect();
        split += usize::from(inner_pieces.len() > 1);
    }
    assert!(
        split >= 20,
        "the inner grid was cut across pieces {split} times"
    );
    let _ = std::fs::remove_dir_all(&d);
}
