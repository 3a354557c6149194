//! The JSON and the text of the chapter 5 outcomes: the β-skeleton, the minimum weight
//! triangulation (or its certified bounds when stopped), Keil's construction and the
//! random check of β-skeleton ⊆ MWT.

use crate::control::Verdict;
use crate::geom::{Interval, Ratio};
use crate::planar::{
    KeilConstruction, KeilOutcome, KeilResult, MwtOutcome, Region, Skeleton, Violation,
};
use serde::Serialize;
use serde_json::Value;

/// `skeleton --json`'s own fields.
#[derive(Serialize)]
struct SkeletonJson {
    verdict: Verdict,
    beta: String,
    region: &'static str,
    vertices: usize,
    edges: usize,
    candidates: usize,
    cell_diameters: usize,
}

fn region_name(region: Region) -> &'static str {
    match region {
        Region::Circle => "circle",
        Region::Lune => "lune",
    }
}

/// The JSON of the β-skeleton `sk` of `vertices` sites, with `extra` fields after:
/// `verdict` is `undecided` when the search was stopped (`edges` then counts those
/// found).
///
/// ```
/// use tetrakit::control::Control;
/// use tetrakit::planar::{Region, beta_skeleton};
/// let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
/// let beta = "1".parse().unwrap();
/// let sk = beta_skeleton(&square, beta, Region::Circle, &Control::new()).unwrap();
/// let v = tetrakit::report::skeleton_json(&sk, beta, Region::Circle, 4, []);
/// assert_eq!((v["verdict"].as_str(), v["edges"].as_u64()), (Some("yes"), Some(6)));
/// ```
pub fn skeleton_json<'a>(
    sk: &Skeleton,
    beta: Ratio,
    region: Region,
    vertices: usize,
    extra: impl IntoIterator<Item = (&'a str, Value)>,
) -> Value {
    let j = SkeletonJson {
        verdict: match sk.complete {
            true => Verdict::Yes,
            false => Verdict::Undecided,
        },
        beta: beta.to_string(),
        region: region_name(region),
        vertices,
        edges: sk.edges.len(),
        candidates: sk.candidates,
        cell_diameters: sk.cell_diameters,
    };
    super::json(&j, extra)
}

/// The line a person reads for the β-skeleton, found in `seconds`.
pub fn skeleton_text(
    sk: &Skeleton,
    beta: Ratio,
    region: Region,
    vertices: usize,
    seconds: f64,
) -> String {
    let region = region_name(region);
    let (edges, tested) = (sk.edges.len(), sk.candidates);
    match sk.complete {
        true => format!(
            "{region}-based β-skeleton, β = {beta}: {edges} edges on {vertices} sites ({tested} candidates tested exactly) in {seconds:.3} s"
        ),
        false => format!(
            "UNDECIDED: stopped at the time limit after {seconds:.3} s; {edges} edges of the {region}-based β-skeleton, β = {beta}, found on {vertices} sites so far ({tested} candidates tested exactly), not all"
        ),
    }
}

/// The seconds of the MWT solver's stages.
#[derive(Serialize)]
struct Stages {
    diamond: f64,
    lmt: f64,
    exact: f64,
}

/// `mwt --json`'s own fields: a YES with the certified weight and the solver's sizes, or
/// undecided with certified bounds.
#[derive(Serialize)]
struct MwtJson {
    verdict: Verdict,
    vertices: usize,
    edges: usize,
    triangles: usize,
    #[serde(skip_serializing_if = "Option::is_none")]
    weight: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    weight_interval: Option<[f64; 2]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    candidates: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    skeleton_edges: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    undecided_edges: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    faces_left: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    faces_with_holes: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    largest_face: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    stage_seconds: Option<Stages>,
    #[serde(skip_serializing_if = "Option::is_none")]
    lower_bound: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    lower_bound_from: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    upper_bound: Option<f64>,
}

/// The JSON of an MWT outcome on `vertices` sites, with `extra` fields after.
///
/// ```
/// use tetrakit::control::Control;
/// use tetrakit::planar::mwt_or_bounds;
/// let pts = [[0.0, 0.0], [4.0, 0.0], [4.0, 3.0], [0.0, 3.0], [1.0, 1.5]];
/// let m = mwt_or_bounds(&pts, &Control::new()).unwrap();
/// let v = tetrakit::report::mwt_json(&m, 5, []);
/// assert_eq!((v["verdict"].as_str(), v["triangles"].as_u64()), (Some("yes"), Some(4)));
/// ```
pub fn mwt_json<'a>(
    m: &MwtOutcome,
    vertices: usize,
    extra: impl IntoIterator<Item = (&'a str, Value)>,
) -> Value {
    let mut j = MwtJson {
        verdict: Verdict::Yes,
        vertices,
        edges: 0,
        triangles: 0,
        weight: None,
        weight_interval: None,
        candidates: None,
        skeleton_edges: None,
        undecided_edges: None,
        faces_left: None,
        faces_with_holes: None,
        largest_face: None,
        stage_seconds: None,
        lower_bound: None,
        lower_bound_from: None,
        upper_bound: None,
    };
    match m {
        MwtOutcome::Solved(m) => {
            let s = &m.stats;
            (j.edges, j.triangles) = (m.edges.len(), m.triangles.len());
            j.weight = Some(m.weight.mid());
            j.weight_interval = Some([m.weight.lo, m.weight.hi]);
            j.candidates = Some(s.candidates);
            j.skeleton_edges = Some(s.skeleton_edges);
            j.undecided_edges = Some(s.undecided_edges);
            j.faces_left = Some(s.faces_left);
            j.faces_with_holes = Some(s.faces_with_holes);
            j.largest_face = Some(s.largest_face);
            let [diamond, lmt, exact] = s.seconds;
            j.stage_seconds = Some(Stages {
                diamond,
                lmt,
                exact,
            });
        }
        MwtOutcome::Stopped(b) => {
            j.verdict = Verdict::Undecided;
            (j.edges, j.triangles) = (b.edges.len(), b.triangles.len());
            j.lower_bound = Some(b.lower.lo);
            j.lower_bound_from = Some(b.lower_source.to_string());
            j.upper_bound = Some(b.upper.hi);
        }
    }
    super::json(&j, extra)
}

/// The lines a person reads for an MWT outcome on `vertices` sites, found in `seconds`;
/// `written` when the undecided triangulation was written.
pub fn mwt_text(m: &MwtOutcome, vertices: usize, seconds: f64, written: bool) -> String {
    match m {
        MwtOutcome::Solved(m) => {
            let s = &m.stats;
            let fixed = 100.0 * s.skeleton_edges as f64 / m.edges.len().max(1) as f64;
            format!(
                "minimum weight triangulation of {vertices} sites: {} edges, {} triangles, weight {:.12} (certified in [{:.17e}, {:.17e}])\n  {} candidates after the diamond test; LMT-skeleton fixed {} edges ({fixed:.1}%); {} faces left to the exact stage ({} with holes, largest {}); {seconds:.3} s",
                m.edges.len(),
                m.triangles.len(),
                m.weight.mid(),
                m.weight.lo,
                m.weight.hi,
                s.candidates,
                s.skeleton_edges,
                s.faces_left,
                s.faces_with_holes,
                s.largest_face,
            )
        }
        MwtOutcome::Stopped(b) => format!(
            "undecided within the time limit ({seconds:.3} s): the minimum weight of a triangulation of {vertices} sites is between {:.17e} ({}) and {:.17e} (Delaunay triangulation flipped shorter{})",
            b.lower.lo,
            b.lower_source,
            b.upper.hi,
            if written { ", written" } else { "" }
        ),
    }
}

/// `keil --json`'s fields of the construction, decided or not.
#[derive(Serialize)]
struct ConstructionJson {
    beta: String,
    n: usize,
    sites: usize,
    xy: [u32; 2],
    lemma_5_8_bound: f64,
    xy_in_skeleton: bool,
}

impl ConstructionJson {
    fn new(c: &KeilConstruction) -> Self {
        ConstructionJson {
            beta: c.beta.to_string(),
            n: c.n,
            sites: c.sites.len(),
            xy: c.xy,
            lemma_5_8_bound: c.lemma_bound,
            xy_in_skeleton: c.xy_in_skeleton,
        }
    }
}

/// `keil --json`'s own fields (stopped before the optima: the construction's alone).
#[derive(Serialize)]
struct KeilJson {
    verdict: Verdict,
    #[serde(flatten)]
    construction: ConstructionJson,
    #[serde(flatten)]
    optima: Option<OptimaJson>,
}

/// `keil --json`'s fields of the two optima.
#[derive(Serialize)]
struct OptimaJson {
    xy_in_mwt: bool,
    refutes_keil: bool,
    weight_with_xy: f64,
    weight_with_xy_interval: [f64; 2],
    weight_without_xy: f64,
    weight_without_xy_interval: [f64; 2],
    with_minus_without_sign: i8,
    method: &'static str,
}

/// How the two optima were found.
fn keil_method(k: &KeilResult) -> &'static str {
    if k.split {
        "split along L (Lemma 5.6: every side of L certified to be in every triangulation), exact polygon DP"
    } else {
        "general exact MWT solver"
    }
}

/// The JSON of Keil's construction (thesis §5.2), with `extra` fields after. The verdict
/// is `yes` when the construction was built and both questions decided exactly
/// (`refutes_keil` says whether this realization separates `xy`), `undecided` with the
/// construction and the skeleton test when stopped before the optima.
pub fn keil_json<'a>(k: &KeilOutcome, extra: impl IntoIterator<Item = (&'a str, Value)>) -> Value {
    let iv = |w: &Interval| [w.lo, w.hi];
    let j = match k {
        KeilOutcome::Undecided(c) => KeilJson {
            verdict: Verdict::Undecided,
            construction: ConstructionJson::new(c),
            optima: None,
        },
        KeilOutcome::Decided(k) => KeilJson {
            verdict: Verdict::Yes,
            construction: ConstructionJson::new(&k.construction),
            optima: Some(OptimaJson {
                xy_in_mwt: k.xy_in_mwt,
                refutes_keil: k.construction.xy_in_skeleton && !k.xy_in_mwt,
                weight_with_xy: k.with_xy.0.mid(),
                weight_with_xy_interval: iv(&k.with_xy.0),
                weight_without_xy: k.without_xy.0.mid(),
                weight_without_xy_interval: iv(&k.without_xy.0),
                with_minus_without_sign: k.with_vs_without as i8,
                method: keil_method(k),
            }),
        },
    };
    super::json(&j, extra)
}

/// The lines a person reads for Keil's construction.
pub fn keil_text(k: &KeilOutcome) -> String {
    match k {
        KeilOutcome::Decided(k) => decided_keil_text(k),
        KeilOutcome::Undecided(c) => format!(
            "UNDECIDED: stopped at the time limit before the optima were found.\n  {}\n  xy in the β-skeleton: {} (exact)",
            construction_line(c),
            c.xy_in_skeleton
        ),
    }
}

/// The construction's line: β, n, the sites, Lemma 5.8's bound.
fn construction_line(c: &KeilConstruction) -> String {
    format!(
        "Keil construction (thesis §5.2), β = {}, n = {} ({} sites; Lemma 5.8 asks n > {:.1}):",
        c.beta,
        c.n,
        c.sites.len(),
        c.lemma_bound
    )
}

fn decided_keil_text(k: &KeilResult) -> String {
    let c = &k.construction;
    let verdict = if c.xy_in_skeleton && !k.xy_in_mwt {
        "xy is a β-skeleton edge in no MWT: Keil's conjecture fails here".to_string()
    } else {
        format!(
            "this realization does not separate xy yet at n = {}; try a larger --n (Lemma 5.8: n > {:.1} suffices)",
            c.n, c.lemma_bound
        )
    };
    format!(
        "{}\n  method: {}\n  xy in the β-skeleton: {} (exact)\n  xy in the minimum weight triangulation: {} (exact)\n  best triangulation with xy:    {:.15}\n  best triangulation without xy: {:.15}\n  verdict: {verdict}",
        construction_line(c),
        keil_method(k),
        c.xy_in_skeleton,
        k.xy_in_mwt,
        k.with_xy.0.mid(),
        k.without_xy.0.mid(),
    )
}

/// One violation of β-skeleton ⊆ MWT.
#[derive(Serialize)]
struct ViolationJson {
    set: usize,
    seed: u64,
    edge: [u32; 2],
}

/// The witness of a violation.
#[derive(Serialize)]
struct ViolationWitness {
    kind: &'static str,
    detail: String,
    set: usize,
    seed: u64,
    segments: [[u32; 2]; 1],
}

/// `keil --check-random --json`'s own fields.
#[derive(Serialize)]
struct CheckRandomJson {
    verdict: Verdict,
    beta: String,
    sets: usize,
    points: usize,
    skeleton_edges_checked: usize,
    violations: Vec<ViolationJson>,
    #[serde(skip_serializing_if = "Option::is_none")]
    witness: Option<ViolationWitness>,
}

/// The JSON of the random check of β-skeleton ⊆ MWT: `sets` sets of `points` points,
/// `checked` skeleton edges, the violations `bad` (the first is the witness of a NO).
pub fn check_random_json<'a>(
    beta: Ratio,
    [sets, points, checked]: [usize; 3],
    bad: &[Violation],
    extra: impl IntoIterator<Item = (&'a str, Value)>,
) -> Value {
    let witness = bad.first().map(|&(set, seed, e)| ViolationWitness {
        kind: "skeleton_edge_not_in_mwt",
        detail: format!(
            "edge {}-{} of the β-skeleton of random set {set} (seed {seed}) is in no minimum weight triangulation",
            e[0], e[1]
        ),
        set,
        seed,
        segments: [e],
    });
    let j = CheckRandomJson {
        verdict: Verdict::from(bad.is_empty()),
        beta: beta.to_string(),
        sets,
        points,
        skeleton_edges_checked: checked,
        violations: bad
            .iter()
            .map(|&(set, seed, edge)| ViolationJson { set, seed, edge })
            .collect(),
        witness,
    };
    super::json(&j, extra)
}

/// The lines a person reads for the random check.
pub fn check_random_text(
    beta: Ratio,
    [sets, points, checked]: [usize; 3],
    bad: &[Violation],
) -> String {
    let mut s = format!(
        "β = {beta}: {checked} skeleton edges of {sets} random sets of {points} points checked against the exact MWT; {} violations",
        bad.len()
    );
    for (k, seed, e) in bad {
        s.push_str(&format!(
            "\n  violation: set {k} (seed {seed}), edge {}-{}",
            e[0], e[1]
        ));
    }
    s
}
