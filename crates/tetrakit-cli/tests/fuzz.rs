//! A mutation fuzzer over every reader, run through the binary with a fixed budget: from
//! valid files of each format (TetGen, OBJ, OFF, JSON, point lists; Gmsh `.msh` 2.2 and
//! 4.1, ASCII and binary; Medit `.mesh`; `.vtu` in every layout VTK writes; legacy
//! `.vtk`, ASCII and binary; binary STL), inputs mutated by byte flips, truncation,
//! duplicated and deleted lines, extreme numbers and swapped tokens go to the commands
//! that read them. Every run must end with an exit code of the CLI contract (0, 1, 2, 3),
//! without a panic, within a time bound; an exit 2 must be one line on stderr; every YES
//! with `--output` must pass `check`; no run may hold more than [`memory_bound`] of a
//! mutant's size in memory (GNU `time`'s peak resident size, where `/usr/bin/time` is
//! installed: CI installs it); a mesh that `check` reads from a mutant must be the mesh
//! meshio reads from it (where meshio reads it at all; CI installs meshio). Seeds are
//! fixed, and a failure prints the seed and the input file, which is kept.
//!
//! `TETRAKIT_FUZZ_RUNS` sets the mutations per base file (default 120, about 2,000 runs);
//! `TETRAKIT_FUZZ_BIN` runs another binary (an older build, to see what it would catch).

mod common;

use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};
use tetrakit::rng::Rng;

/// The most memory (peak resident bytes) a run on an input of `bytes` may take: the
/// program itself, and a stated multiple of the input: `.vtu` blocks may inflate up to
/// 1032:1 (zlib's own limit, which the reader enforces for every compressor).
fn memory_bound(bytes: u64) -> u64 {
    (48 << 20) + 1100 * bytes
}

/// Peak resident bytes of the last run, from GNU time's report in `rss`.
fn peak(rss: &Path) -> Option<u64> {
    let text = std::fs::read_to_string(rss).ok()?;
    text.trim()
        .lines()
        .last()?
        .trim()
        .parse::<u64>()
        .ok()
        .map(|kb| kb << 10)
}

/// Runs the binary with a wall-clock bound: `(exit code, stderr)`, or `None` when it had
/// to be killed. Where GNU time is installed, the run's peak memory is written to `rss`.
fn run(args: &[&str], limit: Duration) -> Option<(i32, String)> {
    run_measured(args, limit, None)
}

fn run_measured(args: &[&str], limit: Duration, rss: Option<&Path>) -> Option<(i32, String)> {
    let bin = std::env::var_os("TETRAKIT_FUZZ_BIN")
        .unwrap_or_else(|| env!("CARGO_BIN_EXE_tetrakit").into());
    // Memory is bounded too where util-linux's prlimit is at hand: 4 GiB of address
    // space, far above what these small inputs need (an allocation past it aborts, and
    // the exit code fails the test).
    let mut argv: Vec<std::ffi::OsString> = Vec::new();
    if Path::new("/usr/bin/prlimit").exists() {
        argv.extend(["/usr/bin/prlimit".into(), "--as=4294967296".into()]);
    }
    if let Some(r) = rss.filter(|_| Path::new("/usr/bin/time").exists()) {
        argv.extend(["/usr/bin/time", "-f", "%M", "-o"].map(Into::into));
        argv.push(r.into());
    }
    argv.push(bin);
    let mut cmd = Command::new(&argv[0]);
    let mut child = cmd
        .args(&argv[1..])
        .args(args)
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .expect("binary runs");
    let start = Instant::now();
    loop {
        if let Some(status) = child.try_wait().expect("wait") {
            let out = child.wait_with_output().expect("output");
            let err = String::from_utf8_lossy(&out.stderr).into_owned();
            return Some((status.code().unwrap_or(-1), err));
        }
        if start.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            return None;
        }
        std::thread::sleep(Duration::from_millis(2));
    }
}

/// One mutation of `text` (text or binary).
fn mutate(text: &[u8], rng: &mut Rng) -> Vec<u8> {
    let mut bytes = text.to_vec();
    let lines: Vec<&[u8]> = text.split(|&c| c == b'\n').collect();
    const EXTREME: [&str; 12] = [
        "1e308",
        "-1e-320",
        "1e39",
        "1e-400",
        "NaN",
        "inf",
        "18446744073709551617",
        "-1",
        "0",
        "4294967296",
        "9223372036854775807",
        "\u{1b}[31m",
    ];
    match rng.below(7) {
        0 => {
            for _ in 0..1 + rng.below(4) {
                if !bytes.is_empty() {
                    let i = rng.below(bytes.len());
                    bytes[i] ^= 1 << rng.below(8);
                }
            }
        }
        1 => bytes.truncate(rng.below(bytes.len() + 1)),
        2 | 3 if lines.len() > 1 => {
            let k = rng.below(lines.len() - 1);
            let mut out = lines.clone();
            if rng.below(2) == 0 {
                out.insert(k, lines[k]);
            } else {
                out.remove(k);
            }
            bytes = out.join(&b'\n');
        }
        4 | 5 => {
            // A number token replaced by an extreme value.
            let toks = token_spans(text);
            if !toks.is_empty() {
                let (a, b) = toks[rng.below(toks.len())];
                let v = EXTREME[rng.below(EXTREME.len())];
                bytes = [&text[..a], v.as_bytes(), &text[b..]].concat();
            }
        }
        _ => {
            // Two tokens swapped.
            let toks = token_spans(text);
            if toks.len() >= 2 {
                let (i, j) = (rng.below(toks.len()), rng.below(toks.len()));
                let ((a, b), (c, d)) = (toks[i.min(j)], toks[i.max(j)]);
                if b <= c {
                    let t = text;
                    bytes = [&t[..a], &t[c..d], &t[b..c], &t[a..b], &t[d..]].concat();
                }
            }
        }
    }
    bytes
}

/// Byte spans of the ASCII-whitespace-separated tokens of `text`.
fn token_spans(text: &[u8]) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    let mut start = None;
    for (i, c) in text.iter().enumerate() {
        match (c.is_ascii_whitespace(), start) {
            (true, Some(s)) => {
                out.push((s, i));
                start = None;
            }
            (false, None) => start = Some(i),
            _ => {}
        }
    }
    if let Some(s) = start {
        out.push((s, text.len()));
    }
    out
}

/// A base file set: the files to write (name, text), the file to mutate, and the commands
/// to run on it (`{}` is the mutated file, `{out}` an output path, `{dir}` the case's
/// directory, where the other files are).
struct Base {
    files: Vec<(&'static str, Vec<u8>)>,
    target: &'static str,
    commands: Vec<Vec<&'static str>>,
}

fn bases(d: &Path) -> Vec<Base> {
    let make = |args: &[&str]| {
        let (code, err) = run(args, Duration::from_secs(60)).expect("generator finishes");
        assert_eq!(code, 0, "{args:?}: {err}");
    };
    let p = |name: &str| d.join(name).to_str().unwrap().to_string();
    make(&["generate", "kuhn", "--size", "2", "-o", &p("k.ele")]);
    make(&["generate", "bipyramid", "--m", "6", "-o", &p("b.off")]);
    make(&["generate", "bipyramid", "--m", "5", "-o", &p("b.obj")]);
    make(&[
        "generate",
        "random-tetrahedralization",
        "--points",
        "12",
        "-o",
        &p("r.json"),
    ]);
    make(&["generate", "points2d", "--n", "30", "-o", &p("p.xyz")]);
    make(&[
        "generate",
        "nested",
        "--n-outer",
        "30",
        "--n-inner",
        "12",
        "--outer-output",
        &p("o.xyz"),
        "--inner-output",
        &p("i.xyz"),
    ]);
    let read = |name: &str| std::fs::read(d.join(name)).unwrap();
    let node = read("k.node");
    let detect = vec!["detect", "{}", "--output", "{out}.ele"];
    vec![
        Base {
            files: vec![("k.node", node.clone()), ("k.ele", read("k.ele"))],
            target: "k.edge",
            commands: vec![
                detect.clone(),
                vec![
                    "contains",
                    "{}",
                    "--time-limit",
                    "5",
                    "--output",
                    "{out}.ele",
                ],
            ],
        },
        Base {
            files: vec![("k.node", node.clone()), ("k.edge", read("k.edge"))],
            target: "k.ele",
            commands: vec![vec!["check", "{}"], vec!["check", "{}", "--convex"]],
        },
        Base {
            files: vec![("k.edge", read("k.edge"))],
            target: "k.node",
            commands: vec![
                TETRAHEDRALIZE.to_vec(),
                vec!["mwt", "{}", "--xy", "--time-limit", "5"],
            ],
        },
        Base {
            files: vec![],
            target: "b.off",
            commands: vec![vec!["mintetra", "{}"], TETRAHEDRALIZE.to_vec()],
        },
        Base {
            files: vec![],
            target: "b.obj",
            commands: vec![vec!["mintetra", "{}"]],
        },
        Base {
            files: vec![],
            target: "r.json",
            commands: vec![
                detect,
                vec!["check", "{}", "--convex"],
                vec!["constrained", "{}", "--time-limit", "5"],
            ],
        },
        Base {
            files: vec![("o.xyz", read("o.xyz"))],
            target: "i.xyz",
            commands: vec![vec![
                "shell",
                "{dir}/o.xyz",
                "{}",
                "--time-limit",
                "5",
                "--output",
                "{out}.ele",
            ]],
        },
        Base {
            files: vec![("i.xyz", read("i.xyz"))],
            target: "o.xyz",
            commands: vec![vec![
                "shell",
                "{}",
                "{dir}/i.xyz",
                "--method",
                "bigcap",
                "--time-limit",
                "5",
            ]],
        },
        Base {
            files: vec![],
            target: "p.xyz",
            commands: vec![
                vec!["mwt", "{}", "--time-limit", "5", "--output", "{out}.off"],
                vec!["skeleton", "{}", "--beta", "0.5"],
                vec!["skeleton", "{}", "--beta", "1.5", "--lune"],
            ],
        },
    ]
    .into_iter()
    .chain(mesh_bases(d))
    .collect()
}

/// The command a polyhedron or point-set base runs, writing what it answers for `check`.
const TETRAHEDRALIZE: [&str; 6] = [
    "tetrahedralize",
    "{}",
    "--time-limit",
    "5",
    "--output",
    "{out}.ele",
];

/// The command every mesh base runs: `check`, writing the mesh it read for the
/// comparison with meshio.
const CHECK_MESH: [&str; 4] = ["check", "{}", "--output", "{out}.vtu"];

/// Mesh files in every binary and text layout the mesh readers take: Kuhn's grid as
/// Gmsh 2.2 and 4.1 (ASCII and binary) and Medit; the cube VTK wrote in every `.vtu`
/// layout and as legacy `.vtk`; a bipyramid as binary STL.
fn mesh_bases(d: &Path) -> Vec<Base> {
    let k = tetrakit::io::read_input(&d.join("k.ele")).unwrap();
    let (pts, tets) = (&k.points, &k.tets);
    let mut out: Vec<Base> = [
        ("m22.msh", msh(pts, tets, false, false)),
        ("m22b.msh", msh(pts, tets, false, true)),
        ("m41.msh", msh(pts, tets, true, false)),
        ("m41b.msh", msh(pts, tets, true, true)),
        ("m.mesh", medit(pts, tets)),
    ]
    .into_iter()
    .map(|(name, bytes)| {
        std::fs::write(d.join(name), bytes).unwrap();
        Base {
            files: vec![],
            target: name,
            commands: vec![CHECK_MESH.to_vec()],
        }
    })
    .collect();
    let vtk = Path::new(env!("CARGO_MANIFEST_DIR")).join("../tetrakit/tests/data/vtk");
    let mut names: Vec<String> = std::fs::read_dir(&vtk)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    names.sort();
    for name in names {
        std::fs::copy(vtk.join(&name), d.join(&name)).unwrap();
        let name: &'static str = Box::leak(name.into_boxed_str());
        out.push(Base {
            files: vec![],
            target: name,
            commands: vec![CHECK_MESH.to_vec()],
        });
    }
    let b = tetrakit::io::read_input(&d.join("b.off")).unwrap();
    std::fs::write(d.join("b.stl"), stl_binary(&b.points, &b.faces)).unwrap();
    out.push(Base {
        files: vec![],
        target: "b.stl",
        commands: vec![TETRAHEDRALIZE.to_vec()],
    });
    out
}

/// A Gmsh file (4.1 or 2.2, ASCII or binary) of tetrahedra, as Gmsh writes it.
fn msh(pts: &[[f64; 3]], tets: &[[u32; 4]], v41: bool, binary: bool) -> Vec<u8> {
    let head = format!("{} {} 8", if v41 { "4.1" } else { "2.2" }, u8::from(binary));
    let mut b = format!("$MeshFormat\n{head}\n").into_bytes();
    if binary {
        b.extend(1i32.to_le_bytes());
        b.push(b'\n');
    }
    b.extend(b"$EndMeshFormat\n$Nodes\n");
    let (n, m) = (pts.len() as u64, tets.len() as u64);
    let text = |b: &mut Vec<u8>, s: String| b.extend(s.into_bytes());
    match (v41, binary) {
        (false, false) => {
            text(&mut b, format!("{n}\n"));
            for (k, p) in pts.iter().enumerate() {
                text(&mut b, format!("{} {} {} {}\n", k + 1, p[0], p[1], p[2]));
            }
            text(&mut b, format!("$EndNodes\n$Elements\n{m}\n"));
            for (k, t) in tets.iter().enumerate() {
                let [a, c, e, f] = t.map(|v| v + 1);
                text(&mut b, format!("{} 4 2 1 1 {a} {c} {e} {f}\n", k + 1));
            }
        }
        (false, true) => {
            text(&mut b, format!("{n}\n"));
            for (k, p) in pts.iter().enumerate() {
                b.extend((k as i32 + 1).to_le_bytes());
                p.iter().for_each(|x| b.extend(x.to_le_bytes()));
            }
            text(&mut b, format!("\n$EndNodes\n$Elements\n{m}\n"));
            [4i32, m as i32, 2]
                .iter()
                .for_each(|x| b.extend(x.to_le_bytes()));
            for (k, t) in tets.iter().enumerate() {
                [k as i32 + 1, 1, 1]
                    .iter()
                    .for_each(|x| b.extend(x.to_le_bytes()));
                t.iter()
                    .for_each(|&v| b.extend((v as i32 + 1).to_le_bytes()));
            }
            b.push(b'\n');
        }
        (true, false) => {
            text(&mut b, format!("1 {n} 1 {n}\n3 1 0 {n}\n"));
            (1..=n).for_each(|t| text(&mut b, format!("{t}\n")));
            for p in pts {
                text(&mut b, format!("{} {} {}\n", p[0], p[1], p[2]));
            }
            text(
                &mut b,
                format!("$EndNodes\n$Elements\n1 {m} 1 {m}\n3 1 4 {m}\n"),
            );
            for (k, t) in tets.iter().enumerate() {
                let [a, c, e, f] = t.map(|v| v + 1);
                text(&mut b, format!("{} {a} {c} {e} {f}\n", k + 1));
            }
        }
        (true, true) => {
            [1, n, 1, n].iter().for_each(|x| b.extend(x.to_le_bytes()));
            [3i32, 1, 0].iter().for_each(|x| b.extend(x.to_le_bytes()));
            b.extend(n.to_le_bytes());
            (1..=n).for_each(|t| b.extend(t.to_le_bytes()));
            pts.iter().flatten().for_each(|x| b.extend(x.to_le_bytes()));
            b.extend(b"\n$EndNodes\n$Elements\n");
            [1, m, 1, m].iter().for_each(|x| b.extend(x.to_le_bytes()));
            [3i32, 1, 4].iter().for_each(|x| b.extend(x.to_le_bytes()));
            b.extend(m.to_le_bytes());
            for (k, t) in tets.iter().enumerate() {
                b.extend((k as u64 + 1).to_le_bytes());
                t.iter()
                    .for_each(|&v| b.extend((u64::from(v) + 1).to_le_bytes()));
            }
            b.push(b'\n');
        }
    }
    b.extend(b"$EndElements\n");
    b
}

/// A Medit `.mesh` of tetrahedra.
fn medit(pts: &[[f64; 3]], tets: &[[u32; 4]]) -> Vec<u8> {
    let mut s = format!(
        "MeshVersionFormatted 2\nDimension 3\nVertices\n{}\n",
        pts.len()
    );
    pts.iter()
        .for_each(|p| s += &format!("{} {} {} 0\n", p[0], p[1], p[2]));
    s += &format!("Tetrahedra\n{}\n", tets.len());
    for t in tets {
        let [a, b, c, d] = t.map(|v| v + 1);
        s += &format!("{a} {b} {c} {d} 1\n");
    }
    (s + "End\n").into_bytes()
}

/// A binary STL of `faces`.
fn stl_binary(pts: &[[f64; 3]], faces: &[[u32; 3]]) -> Vec<u8> {
    let mut b = vec![0u8; 80];
    b.extend((faces.len() as u32).to_le_bytes());
    for f in faces {
        b.extend([0u8; 12]);
        for &v in f {
            pts[v as usize]
                .iter()
                .for_each(|&x| b.extend((x as f32).to_le_bytes()));
        }
        b.extend([0u8; 2]);
    }
    b
}

#[test]
fn mutated_inputs_keep_the_cli_contract() {
    let runs: usize = std::env::var("TETRAKIT_FUZZ_RUNS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(120);
    let src = common::dir("fuzz").join("src");
    std::fs::create_dir_all(&src).unwrap();
    let bases = bases(&src);
    let limit = Duration::from_secs(30);
    let mut checked = 0;
    let read_meshes = common::dir("fuzz").join("read");
    std::fs::create_dir_all(&read_meshes).unwrap();
    for (b, base) in bases.iter().enumerate() {
        let text = std::fs::read(src.join(base.target)).unwrap();
        for k in 0..runs {
            let seed = 1000 * b as u64 + k as u64;
            let case = common::dir("fuzz").join(format!("c{seed}"));
            std::fs::create_dir_all(&case).unwrap();
            for (name, t) in &base.files {
                std::fs::write(case.join(name), t).unwrap();
            }
            let mut rng = Rng::new(seed);
            let file = case.join(base.target);
            let mutant = mutate(&text, &mut rng);
            std::fs::write(&file, &mutant).unwrap();
            let out = case.join("out");
            for cmd in &base.commands {
                let f = file.to_str().unwrap().to_string();
                let o = out.to_str().unwrap().to_string();
                let args: Vec<String> = cmd
                    .iter()
                    .map(|a| {
                        a.replace("{out}", &o)
                            .replace("{dir}", case.to_str().unwrap())
                            .replace("{}", &f)
                    })
                    .collect();
                let argv: Vec<&str> = args.iter().map(String::as_str).collect();
                let what = format!("seed {seed}, {argv:?} (input kept in {})", case.display());
                let rss = case.join("rss");
                let (code, err) = run_measured(&argv, limit, Some(&rss))
                    .unwrap_or_else(|| panic!("{what}: no answer in {limit:?}"));
                if let Some(used) = peak(&rss) {
                    let bound = memory_bound(mutant.len() as u64);
                    assert!(
                        used <= bound,
                        "{what}: {used} bytes in memory, over {bound}"
                    );
                }
                assert!([0, 1, 2, 3].contains(&code), "{what}: exit {code}: {err}");
                assert!(!err.contains("panicked"), "{what}: {err}");
                if code == 2 {
                    assert_eq!(err.lines().count(), 1, "{what}: {err}");
                    assert!(err.len() <= 400, "{what}: {} bytes: {err}", err.len());
                }
                if code < 2 && cmd == &CHECK_MESH {
                    // Kept to compare with meshio's reading of the same mutant.
                    let keep = read_meshes.join(format!("{seed}"));
                    std::fs::create_dir_all(&keep).unwrap();
                    std::fs::copy(&file, keep.join(base.target)).unwrap();
                    std::fs::copy(out.with_extension("vtu"), keep.join("read.vtu")).unwrap();
                }
                if code == 0 && args.iter().any(|a| a.ends_with("out.ele")) {
                    let written = out.with_extension("ele");
                    let w = written.to_str().unwrap();
                    let (c, e) = run(&["check", w, "--convex"], limit).expect("check answers");
                    let (c2, e2) = run(&["check", w], limit).expect("check answers");
                    assert!(
                        c == 0 || c2 == 0,
                        "{what}: the YES output fails check: {e} {e2}"
                    );
                }
                checked += 1;
            }
            let _ = std::fs::remove_dir_all(&case);
        }
    }
    assert!(checked >= 7 * runs, "{checked} runs");
    same_as_meshio(&read_meshes);
}

/// Every mutant `check` read (each in a folder of `dir`, beside `read.vtu`, the mesh it
/// read) is the mesh meshio reads from it, points and tetrahedra exactly, where meshio
/// reads it at all. Skipped where python3 with meshio is missing, unless
/// `TETRAKIT_REQUIRE_GMSH` is set (CI).
fn same_as_meshio(dir: &Path) {
    let script = r#"
import sys, pathlib, numpy as np, meshio
def tets(m):
    b = [np.asarray(c.data)[:, :4] for c in m.cells if c.type in ("tetra", "tetra10")]
    return np.concatenate(b) if b else np.zeros((0, 4), dtype=np.int64)
same = refused = bad = 0
for case in sorted(pathlib.Path(sys.argv[1]).iterdir()):
    mutant = next(f for f in case.iterdir() if f.name != "read.vtu")
    try:
        theirs = meshio.read(mutant)
    except (Exception, SystemExit):  # meshio exits on some files it cannot read
        refused += 1
        continue
    mine = meshio.read(case / "read.vtu")
    pts = np.asarray(theirs.points, dtype=float)
    if pts.shape[1] == 2:
        pts = np.hstack([pts, np.zeros((len(pts), 1))])
    if not (np.array_equal(mine.points, pts) and np.array_equal(tets(mine), tets(theirs))):
        bad += 1
        print(f"{mutant}: tetrakit read {len(mine.points)} points, {len(tets(mine))} tets; meshio {len(pts)}, {len(tets(theirs))}")
        continue
    same += 1
print(f"{same} the same, {refused} refused by meshio, {bad} read otherwise")
sys.exit(1 if bad else 0)
"#;
    let out = Command::new("python3")
        .args(["-c", "import meshio"])
        .output();
    if !out.is_ok_and(|o| o.status.success()) {
        assert!(
            std::env::var_os("TETRAKIT_REQUIRE_GMSH").is_none(),
            "python3 with meshio is required (TETRAKIT_REQUIRE_GMSH is set)"
        );
        return;
    }
    let out = Command::new("python3")
        .arg("-c")
        .arg(script)
        .arg(dir)
        .output()
        .expect("python3 runs");
    let said = String::from_utf8_lossy(&out.stdout).into_owned();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        out.status.success(),
        "tetrakit and meshio read a mutant differently: {said} {err}"
    );
    eprintln!("meshio: {said}");
}
