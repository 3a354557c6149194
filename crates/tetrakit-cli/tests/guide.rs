//! `docs/guide.md` stays true: every `$` line of its plain code blocks is run (by `sh`, in
//! one empty directory, in order, with this build's `tetrakit` first on the `PATH`) and
//! must exit with the code its `# exit N` gives (0 without one) and print the first word
//! the guide shows under it; every picture the guide shows (`![...](F)`) must be the file
//! `F` those lines wrote. `TETRAKIT_BLESS=1` copies the pictures into `docs/` instead.

use std::path::{Path, PathBuf};
use std::process::Command;

/// A `$` line of the guide: the command, the exit code it promises, and the first word
/// of the output shown under it (if any).
struct Step {
    command: String,
    exit: i32,
    first_word: Option<String>,
}

fn docs() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs")
}

/// The steps of the guide's plain code blocks (```` ``` ```` with no language).
fn steps(guide: &str) -> Vec<Step> {
    let (mut steps, mut in_plain, mut in_other) = (Vec::<Step>::new(), false, false);
    for line in guide.lines() {
        if let Some(lang) = line.strip_prefix("```") {
            match (in_plain, in_other) {
                (false, false) if lang.is_empty() => in_plain = true,
                (false, false) => in_other = true,
                _ => (in_plain, in_other) = (false, false),
            }
            continue;
        }
        if !in_plain {
            continue;
        }
        if let Some(cmd) = line.strip_prefix("$ ") {
            let (command, exit) = match cmd.rsplit_once("# exit ") {
                Some((c, code)) => (c.trim_end(), code.trim().parse().unwrap()),
                None => (cmd, 0),
            };
            steps.push(Step {
                command: command.to_string(),
                exit,
                first_word: None,
            });
        } else if let Some(last) = steps.last_mut().filter(|s| s.first_word.is_none()) {
            last.first_word = line.split_whitespace().next().map(str::to_string);
        }
    }
    steps
}

#[test]
fn every_command_of_the_guide_runs_as_shown() {
    let guide = std::fs::read_to_string(docs().join("guide.md")).unwrap();
    let steps = steps(&guide);
    assert!(steps.len() >= 30, "{} steps", steps.len());
    let scratch = tempfile::Builder::new()
        .prefix("tetrakit-guide-")
        .tempdir()
        .unwrap();
    let work = scratch.path().to_path_buf();
    let bin = Path::new(env!("CARGO_BIN_EXE_tetrakit")).parent().unwrap();
    let path = format!(
        "{}:{}",
        bin.display(),
        std::env::var("PATH").unwrap_or_default()
    );
    for step in &steps {
        let o = Command::new("sh")
            .args(["-c", &step.command])
            .current_dir(&work)
            .env("PATH", &path)
            .output()
            .unwrap();
        let (out, err) = (
            String::from_utf8_lossy(&o.stdout),
            String::from_utf8_lossy(&o.stderr),
        );
        assert_eq!(
            o.status.code(),
            Some(step.exit),
            "`{}`:\n{out}{err}",
            step.command
        );
        let shown = if out.trim().is_empty() { &err } else { &out };
        let first = shown.split_whitespace().next().map(str::to_string);
        if step.first_word.is_some() {
            assert_eq!(first, step.first_word, "`{}`:\n{shown}", step.command);
        }
    }
    let pictures = guide
        .split("![")
        .skip(1)
        .filter_map(|s| s.split_once("](")?.1.split_once(')'));
    for (name, _) in pictures {
        let made = std::fs::read(work.join(name)).unwrap_or_else(|_| panic!("no {name} made"));
        let committed = docs().join(name);
        if std::env::var_os("TETRAKIT_BLESS").is_some() {
            std::fs::write(&committed, &made).unwrap();
        } else {
            let current = std::fs::read(&committed).ok() == Some(made);
            assert!(current, "docs/{name} is stale: rerun with TETRAKIT_BLESS=1");
        }
    }
}
