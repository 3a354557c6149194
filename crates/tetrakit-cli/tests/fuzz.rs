//! A mutation fuzzer over every reader, run through the binary with a fixed budget: from
//! valid files of each format (TetGen, OBJ, OFF, JSON, point lists), inputs mutated by
//! byte flips, truncation, duplicated and deleted lines, extreme numbers and swapped
//! tokens go to the commands that read them. Every run must end with an exit code of the
//! CLI contract (0, 1, 2, 3), without a panic, within a time bound; an exit 2 must be one
//! line on stderr; every YES with `--output` must pass `check`; memory is bounded by
//! `prlimit` where it is installed. Seeds are fixed, and a
//! failure prints the seed and the input file, which is kept.
//!
//! `TETRAKIT_FUZZ_RUNS` sets the mutations per base file (default 120, about 2,000 runs);
//! `TETRAKIT_FUZZ_BIN` runs another binary (an older build, to see what it would catch).

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};
use tetrakit::rng::Rng;

fn dir() -> PathBuf {
    let d = std::env::temp_dir().join(format!("tetrakit-fuzz-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Runs the binary with a wall-clock bound: `(exit code, stderr)`, or `None` when it had
/// to be killed.
fn run(args: &[&str], limit: Duration) -> Option<(i32, String)> {
    let bin = std::env::var_os("TETRAKIT_FUZZ_BIN")
        .unwrap_or_else(|| env!("CARGO_BIN_EXE_tetrakit").into());
    // Memory is bounded too where util-linux's prlimit is at hand: 4 GiB of address
    // space, far above what these small inputs need (an allocation past it aborts, and
    // the exit code fails the test).
    let prlimit = Path::new("/usr/bin/prlimit");
    let mut cmd = if prlimit.exists() {
        let mut c = Command::new(prlimit);
        c.arg("--as=4294967296").arg(bin);
        c
    } else {
        Command::new(bin)
    };
    let mut child = cmd
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

/// One mutation of `text`.
fn mutate(text: &str, rng: &mut Rng) -> Vec<u8> {
    let mut bytes = text.as_bytes().to_vec();
    let lines: Vec<&str> = text.lines().collect();
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
        2 | 3 if !lines.is_empty() => {
            let k = rng.below(lines.len());
            let mut out: Vec<&str> = lines.clone();
            if rng.below(2) == 0 {
                out.insert(k, lines[k]);
            } else {
                out.remove(k);
            }
            bytes = (out.join("\n") + "\n").into_bytes();
        }
        4 | 5 => {
            // A number token replaced by an extreme value.
            let toks: Vec<(usize, usize)> = token_spans(text);
            if !toks.is_empty() {
                let (a, b) = toks[rng.below(toks.len())];
                let v = EXTREME[rng.below(EXTREME.len())];
                bytes = [&text.as_bytes()[..a], v.as_bytes(), &text.as_bytes()[b..]].concat();
            }
        }
        _ => {
            // Two tokens swapped.
            let toks = token_spans(text);
            if toks.len() >= 2 {
                let (i, j) = (rng.below(toks.len()), rng.below(toks.len()));
                let ((a, b), (c, d)) = (toks[i.min(j)], toks[i.max(j)]);
                if b <= c {
                    let t = text.as_bytes();
                    bytes = [&t[..a], &t[c..d], &t[b..c], &t[a..b], &t[d..]].concat();
                }
            }
        }
    }
    bytes
}

/// Byte spans of the whitespace-separated tokens of `text`.
fn token_spans(text: &str) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    let mut start = None;
    for (i, c) in text.char_indices() {
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
    files: Vec<(&'static str, String)>,
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
    let read = |name: &str| std::fs::read_to_string(d.join(name)).unwrap();
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
                vec![
                    "tetrahedralize",
                    "{}",
                    "--time-limit",
                    "5",
                    "--output",
                    "{out}.ele",
                ],
                vec!["mwt", "{}", "--xy", "--time-limit", "5"],
            ],
        },
        Base {
            files: vec![],
            target: "b.off",
            commands: vec![
                vec!["mintetra", "{}"],
                vec![
                    "tetrahedralize",
                    "{}",
                    "--time-limit",
                    "5",
                    "--output",
                    "{out}.ele",
                ],
            ],
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
}

#[test]
fn mutated_inputs_keep_the_cli_contract() {
    let runs: usize = std::env::var("TETRAKIT_FUZZ_RUNS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(120);
    let src = dir().join("src");
    std::fs::create_dir_all(&src).unwrap();
    let bases = bases(&src);
    let limit = Duration::from_secs(30);
    let mut checked = 0;
    for (b, base) in bases.iter().enumerate() {
        let text = std::fs::read_to_string(src.join(base.target)).unwrap();
        for k in 0..runs {
            let seed = 1000 * b as u64 + k as u64;
            let case = dir().join(format!("c{seed}"));
            std::fs::create_dir_all(&case).unwrap();
            for (name, t) in &base.files {
                std::fs::write(case.join(name), t).unwrap();
            }
            let mut rng = Rng::new(seed);
            let file = case.join(base.target);
            std::fs::write(&file, mutate(&text, &mut rng)).unwrap();
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
                let (code, err) =
                    run(&argv, limit).unwrap_or_else(|| panic!("{what}: no answer in {limit:?}"));
                assert!([0, 1, 2, 3].contains(&code), "{what}: exit {code}: {err}");
                assert!(!err.contains("panicked"), "{what}: {err}");
                if code == 2 {
                    assert_eq!(err.lines().count(), 1, "{what}: {err}");
                    assert!(err.len() <= 400, "{what}: {} bytes: {err}", err.len());
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
}
