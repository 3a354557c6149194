//! The module graph of ARCHITECTURE.md, checked on the source: the layers (exact
//! predicates and shared helpers at the bottom, then `mesh`, then the algorithms, `io`
//! at both ends), and no cycle between sibling modules anywhere (a strategy and the
//! types it shares are parent and child, never two siblings importing each other).
//! Test code (from a file's first `#[cfg(test)]` on) is not part of the graph.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

type Module = Vec<String>;

/// What each top-level module may use (besides itself): the layers below it, and the
/// few algorithm-to-algorithm edges ARCHITECTURE.md names.
fn allowed(top: &str) -> Vec<&'static str> {
    const BASE: &[&str] = &[
        "bug",
        "control",
        "numbering",
        "params",
        "partition",
        "rows",
        "rng",
        "witness",
    ];
    if top == "witness" {
        return vec!["numbering"]; // a witness's sentence names vertices as `#12`
    }
    if BASE.contains(&top) {
        return Vec::new();
    }
    // `report` prints every capability's outcome: it sits above the algorithms.
    const ALGORITHMS: &[&str] = &[
        "detect",
        "polyhedra",
        "exact",
        "flip",
        "flipgraph",
        "dualpath",
        "shell",
        "planar",
        "generate",
        "constrain",
        "reduce",
    ];
    let below: &[&str] = match top {
        "geom" => &[],
        "mesh" => &["geom"],
        "report" => &["geom", "mesh", "io"],
        _ => &["geom", "mesh"],
    };
    if top == "report" {
        return [BASE, below, ALGORITHMS].concat();
    }
    // The shell asks the exact solver for `--optimum`'s minimum and improves its meshes
    // by flips; `constrain` asks `detect` first and the
    // exact solver after, and builds its niche instances on `polyhedra`'s twisted prism;
    // `reduce` triangulates its generated quasi-prisms with `planar`'s Delaunay and hands a
    // quasi-prism without staircases to the exact solver; `mintetra`
    // confirms its minimality with the exact solver; `dualpath` enumerates every
    // tetrahedralization of a small set with `flipgraph` when no cone gives a path.
    let extra: &[&str] = match top {
        "distributed" => &["io"],
        "constrain" => &["detect", "exact", "polyhedra"],
        "shell" => &["exact", "flip"],
        "dualpath" => &["flipgraph", "exact"],
        "reduce" => &["planar", "exact"],
        "polyhedra" => &["exact"],
        _ => &[],
    };
    [BASE, below, extra].concat()
}

fn source_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).expect("readable src") {
        let path = entry.expect("entry").path();
        if path.is_dir() {
            source_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// `src/a/b.rs` and `src/a/b/mod.rs` are module `[a, b]`; `src/lib.rs` is `[]`.
fn module_of(src: &Path, file: &Path) -> Module {
    let rel = file.strip_prefix(src).expect("under src");
    let mut parts: Vec<String> = rel
        .iter()
        .map(|s| s.to_string_lossy().trim_end_matches(".rs").to_string())
        .collect();
    if matches!(parts.last().map(String::as_str), Some("mod" | "lib")) {
        parts.pop();
    }
    parts
}

/// The code of a file without its tests and comments.
fn code(text: &str) -> String {
    let body = text.split("#[cfg(test)]").next().unwrap_or("");
    body.lines()
        .filter(|l| !l.trim_start().starts_with("//"))
        .collect::<Vec<_>>()
        .join("\n")
}

/// Paths written after `crate::` or `super::` in `code`, braces expanded one level.
fn paths(code: &str, root: &str) -> Vec<Vec<String>> {
    let mut found = Vec::new();
    for (i, _) in code.match_indices(root) {
        if i > 0 && code[..i].ends_with(|c: char| c.is_alphanumeric() || c == '_') {
            continue;
        }
        let rest = &code[i + root.len()..];
        let mut segs = Vec::new();
        let mut r = rest;
        loop {
            let name: String = r
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            if name.is_empty() {
                if let Some(inner) = r.strip_prefix('{') {
                    let inner = &inner[..inner.find('}').unwrap_or(inner.len())];
                    for item in inner.split(',') {
                        let head: String = item
                            .trim()
                            .chars()
                            .take_while(|c| c.is_alphanumeric() || *c == '_')
                            .collect();
                        if !head.is_empty() {
                            let mut s = segs.clone();
                            s.push(head);
                            found.push(s);
                        }
                    }
                }
                break;
            }
            r = &r[name.len()..];
            segs.push(name);
            match r.strip_prefix("::") {
                Some(next) => r = next,
                None => break,
            }
        }
        if !segs.is_empty() {
            found.push(segs);
        }
    }
    found
}

/// The longest module that `path` (relative to `base`) names.
fn resolve(modules: &BTreeSet<Module>, base: &[String], path: &[String]) -> Module {
    let mut m: Module = base.to_vec();
    for seg in path {
        m.push(seg.clone());
        if !modules.contains(&m) {
            m.pop();
            break;
        }
    }
    m
}

fn graph() -> BTreeMap<Module, BTreeSet<Module>> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    source_files(&src, &mut files);
    let modules: BTreeSet<Module> = files.iter().map(|f| module_of(&src, f)).collect();
    let mut edges: BTreeMap<Module, BTreeSet<Module>> = BTreeMap::new();
    for f in &files {
        let m = module_of(&src, f);
        let text = code(&std::fs::read_to_string(f).expect("readable file"));
        let mut targets: Vec<Module> = paths(&text, "crate::")
            .iter()
            .map(|p| resolve(&modules, &[], p))
            .collect();
        let parent = &m[..m.len().saturating_sub(1)];
        targets.extend(
            paths(&text, "super::")
                .iter()
                .map(|p| resolve(&modules, parent, p)),
        );
        let entry = edges.entry(m.clone()).or_default();
        entry.extend(targets.into_iter().filter(|t| *t != m));
    }
    edges
}

#[test]
fn layers_point_down() {
    let mut wrong = Vec::new();
    for (from, tos) in graph() {
        let Some(top) = from.first() else { continue };
        for to in tos {
            let Some(dep) = to.first() else { continue };
            if dep != top && !allowed(top).contains(&dep.as_str()) {
                wrong.push(format!("{} uses {}", from.join("::"), to.join("::")));
            }
        }
    }
    assert!(wrong.is_empty(), "edges against the layers: {wrong:#?}");
}

#[test]
fn no_cycle_between_siblings() {
    // An edge between two modules, neither inside the other, is an edge between the two
    // children of their deepest common ancestor.
    let mut siblings: BTreeMap<Module, BTreeSet<Module>> = BTreeMap::new();
    for (from, tos) in graph() {
        for to in tos {
            let common = from.iter().zip(&to).take_while(|(a, b)| a == b).count();
            if common == from.len() || common == to.len() {
                continue; // parent and descendant
            }
            siblings
                .entry(from[..=common].to_vec())
                .or_default()
                .insert(to[..=common].to_vec());
        }
    }
    // Depth-first search for a back edge.
    fn visit(
        m: &Module,
        g: &BTreeMap<Module, BTreeSet<Module>>,
        state: &mut BTreeMap<Module, u8>,
        stack: &mut Vec<Module>,
    ) -> Option<Vec<Module>> {
        match state.get(m) {
            Some(1) => {
                let at = stack.iter().position(|x| x == m).unwrap_or(0);
                return Some(stack[at..].to_vec());
            }
            Some(_) => return None,
            None => {}
        }
        state.insert(m.clone(), 1);
        stack.push(m.clone());
        for n in g.get(m).into_iter().flatten() {
            if let Some(c) = visit(n, g, state, stack) {
                return Some(c);
            }
        }
        stack.pop();
        state.insert(m.clone(), 2);
        None
    }
    let mut state = BTreeMap::new();
    for m in siblings.keys() {
        let cycle = visit(m, &siblings, &mut state, &mut Vec::new());
        let names: Vec<String> = cycle.iter().flatten().map(|m| m.join("::")).collect();
        assert!(names.is_empty(), "a cycle between siblings: {names:?}");
    }
}

/// The checker finds what it is meant to find: a `super::` path and a braced list.
#[test]
fn paths_are_read_with_braces() {
    let p = paths(
        "use super::{grid::PointGrid, PlanarError};\nsuper::lens::f();",
        "super::",
    );
    let names: Vec<String> = p.iter().map(|s| s.join("::")).collect();
    assert_eq!(names, ["grid", "PlanarError", "lens::f"]);
}

/// The code (without tests and comments) of every `.rs` file under `dir`, by path.
fn sources(dir: &Path) -> Vec<(PathBuf, String)> {
    let mut files = Vec::new();
    source_files(dir, &mut files);
    files.sort();
    files
        .into_iter()
        .map(|f| {
            let text = code(&std::fs::read_to_string(&f).expect("readable file"));
            (f, text)
        })
        .collect()
}

/// The front ends print through the report layer: no JSON built by hand in the CLI or
/// the Python binding.
#[test]
fn front_ends_build_no_json() {
    let crates = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut found = Vec::new();
    for front in ["tetrakit-cli/src", "tetrakit-py/src"] {
        for (f, text) in sources(&crates.join(front)) {
            if text.contains("json!(") {
                found.push(f.display().to_string());
            }
        }
    }
    assert!(found.is_empty(), "json! in a front end: {found:?}");
}

/// Errors are typed: no public function returns a `String` error, and no error enum
/// keeps a free-form `String` variant (a bug is a `bug::Bug`, a failed certificate the
/// verifier's `mesh::Problem`).
#[test]
fn no_string_errors() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut found = Vec::new();
    for (f, text) in sources(&src) {
        let lines: Vec<&str> = text.lines().collect();
        for (k, line) in lines.iter().enumerate() {
            let returns_string_error = line.contains("pub fn")
                && lines[k..(k + 6).min(lines.len())]
                    .iter()
                    .any(|l| l.contains(", String>"));
            let in_error_enum = lines[..k]
                .iter()
                .rev()
                .find(|l| l.starts_with("pub enum") || l.starts_with("enum") || *l == &"}")
                .is_some_and(|l| l.starts_with("pub enum") && l.contains("Error"));
            let string_variant = in_error_enum && line.trim_end().ends_with("(String),");
            if returns_string_error || string_variant {
                found.push(format!("{}:{}: {}", f.display(), k + 1, line.trim()));
            }
        }
    }
    assert!(found.is_empty(), "String errors: {found:#?}");
}
