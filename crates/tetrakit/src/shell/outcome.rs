//! The `shell` capability as one call: removal by the chosen method, the flips inside the
//! shell, and the certificate ([`certify_shell`](crate::mesh::certify_shell)), composed
//! here so that every front end gets the same certified outcome. A mesh above Theorem
//! 4.2's bound 9n − 6 is not the answer while another route may stay within it: the
//! other method is run too and the smaller mesh kept; `within_bound` says how it ended.

use super::delaunay::delaunay_shell;
use super::lemma41::{Lemma41, Lemma41Witness, lemma_4_1};
use super::{
    Improvement, Method, Shell, ShellError, ThesisSteps, improve, tetrahedralize,
    tetrahedralize_within,
};
use crate::bug::Bug;
use crate::control::{Control, Verdict};
use crate::geom::orient3d_value;
use serde::Serialize;
use std::sync::OnceLock;

/// What [`shell`] is asked.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ShellOptions {
    /// How pieces are removed.
    pub method: Method,
    /// Improve the removals' mesh by flips inside the shell.
    pub flips: bool,
    /// Also the exact minimum ([`super::optimum`], at most
    /// [`crate::exact::MAX_VERTICES`] vertices); the minimum mesh is the one returned
    /// when proven.
    pub optimum: bool,
}

impl ShellOptions {
    /// `method` with the command's defaults: flips on, no exact minimum.
    pub const fn new(method: Method) -> Self {
        ShellOptions {
            method,
            flips: true,
            optimum: false,
        }
    }
}

/// The flips the improvement kept.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct FlipCounts {
    /// 3-2 flips.
    pub three_two: usize,
    /// The Delaunay pass, when it was tried and kept.
    pub delaunay: Option<crate::flip::Flips>,
}

/// The outcome of [`shell`]: `yes` with a certified mesh, or `undecided` (stopped) with
/// the shell's facts only. Serialized, the JSON of `tetrakit shell --json` without the
/// timing.
#[derive(Clone, Debug, Serialize)]
pub struct ShellOutcome {
    /// `yes`, or `undecided` when stopped.
    pub verdict: Verdict,
    /// Vertices of both polytopes (`|P| + |Q|`, shared ones once).
    pub n: usize,
    /// Corners of the outer polytope.
    pub outer_vertices: usize,
    /// Corners of the inner polytope.
    pub inner_vertices: usize,
    /// Outer points that are not corners.
    pub outer_ignored: usize,
    /// Inner points that are not corners.
    pub inner_ignored: usize,
    /// Inner corners on the outer surface (shared, or on its facets and edges).
    pub inner_on_outer: usize,
    /// The bound of chapter 4, 9n − 6.
    pub bound: usize,
    /// Always 0.
    pub steiner_points: usize,
    /// The method whose mesh is printed: the one asked for, or the other one when the
    /// asked one ended above the bound and the other did not (or ended lower).
    pub method: &'static str,
    /// `--method thesis`: what the check of Lemma 4.1 found (`holds`, `fails`, or
    /// `not_examined` where `Q` touches `P`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lemma_4_1: Option<&'static str>,
    /// Where the lemma fails: the tip, `U_v` and the bottom triangle the tip cannot see.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub witness: Option<AssumptionWitness>,
    /// `--method thesis` where the lemma does not stop it: what BIGCAP-REMOVE's steps did
    /// (Step 1's caps, rounds of Steps 2–3, S-bigcaps removed whole and repaired).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub thesis_steps: Option<ThesisSteps>,
    /// With `optimum`: the exact minimum, or its bounds when stopped first.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub optimum: Option<Optimum>,
    /// Whether the printed mesh has at most `bound` tetrahedra (a YES).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub within_bound: Option<bool>,
    /// Tetrahedra (a YES).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tetrahedra: Option<usize>,
    /// Tetrahedra the removals made (a YES).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tetrahedra_before_flips: Option<usize>,
    /// Edges not on the boundary surfaces (a YES).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub interior_edges: Option<usize>,
    /// Pieces removed, or vertices placed (a YES).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pieces: Option<usize>,
    /// How the method's mesh was made (a YES): `removal`, or `placing` where the removal
    /// left vertices no piece could take ([`super::tetrahedralize`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub finished_by: Option<super::Finish>,
    /// The flips kept (a YES with flips; `null` without).
    #[serde(skip_serializing_if = "undecided")]
    pub flips: Option<Option<FlipCounts>>,
    /// The weights of §4.4 on the removal's edges (a YES finished by removal).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub weights: Option<Weights>,
    /// The certified tetrahedra on [`Shell::points`] (empty when undecided).
    #[serde(skip)]
    pub tets: Vec<[u32; 4]>,
}

fn undecided(f: &Option<Option<FlipCounts>>) -> bool {
    f.is_none()
}

/// Tetrahedralizes the region between the polytopes of `shell` (see [`ShellOptions`]) and
/// certifies the mesh; stopped by `ctl`, the outcome is `undecided`. An error is a bug
/// (a removal that every fallback refused, or a failed certificate), never an answer.
///
/// ```
/// use tetrakit::control::Control;
/// use tetrakit::shell::{Method, Shell, ShellOptions, generate::bern_disk, shell};
/// let (outer, inner) = bern_disk(60, 12, 1).unwrap();
/// let s = Shell::new(&outer, &inner).unwrap();
/// let opts = ShellOptions::new(Method::Cap);
/// let o = shell(&s, opts, &Control::new()).unwrap();
/// assert_eq!(o.verdict, tetrakit::control::Verdict::Yes);
/// assert!(o.tetrahedra.unwrap() <= o.bound);
/// ```
pub fn shell(s: &Shell, opts: ShellOptions, ctl: &Control) -> Result<ShellOutcome, ShellError> {
    let n = s.n();
    let inner_on_outer = s.touching.len()
        + s.inner
            .iter()
            .filter(|&&v| (v as usize) < s.outer.len())
            .count();
    let mut o = ShellOutcome {
        verdict: Verdict::Undecided,
        n,
        outer_vertices: s.outer.len(),
        inner_vertices: s.inner.len(),
        outer_ignored: s.outer_ignored.len(),
        inner_ignored: s.inner_ignored.len(),
        inner_on_outer,
        bound: 9 * n - 6,
        steiner_points: 0,
        method: opts.method.name(),
        lemma_4_1: None,
        witness: None,
        optimum: None,
        within_bound: None,
        tetrahedra: None,
        tetrahedra_before_flips: None,
        interior_edges: None,
        pieces: None,
        finished_by: None,
        flips: None,
        weights: None,
        thesis_steps: None,
        tets: Vec::new(),
    };
    if opts.method == Method::Thesis {
        let found = match lemma_4_1(s, ctl) {
            Ok(found) => found,
            Err(_) => return Ok(o),
        };
        o.lemma_4_1 = Some(match &found {
            Lemma41::Holds { .. } => "holds",
            Lemma41::Fails(_) => "fails",
            Lemma41::NotExamined => "not_examined",
        });
        if let Lemma41::Fails(w) = found {
            o.verdict = Verdict::AssumptionFails;
            o.witness = Some(AssumptionWitness::new(s, &w));
            return Ok(o);
        }
    }
    if opts.optimum && n > crate::exact::MAX_VERTICES {
        return Err(ShellError::TooLargeForOptimum { n });
    }
    // The certificate's hulls owe nothing to the mesh: built beside it.
    let (meshed, hulls) = rayon::join(
        || within_bound(s, opts, o.bound, ctl),
        || crate::mesh::ShellHulls::new(&s.points, &s.inner),
    );
    let (mut mesh, done, method) = match meshed {
        Ok(m) => m,
        Err(ShellError::Stopped(_)) => return Ok(o),
        Err(e) => return Err(e),
    };
    // Each flip changes the tetrahedra and the interior edges by the same ±1 (Lemma
    // 4.9), so the ledger's sum gives the flipped mesh's interior edges.
    let mut interior = mesh
        .ledger
        .as_ref()
        .and_then(|l| (l.edges() + mesh.tets.len()).checked_sub(done.before));
    if opts.optimum {
        let (report, best) = exact_minimum(s, mesh.tets.len(), ctl)?;
        o.optimum = Some(report);
        if let Some(best) = best {
            mesh.tets = best;
            interior = None;
        }
    }
    // The count of interior edges (without a ledger, from the mesh) beside the certificate.
    let (certified, interior) = rayon::join(
        || hulls.certify_shell(&mesh.tets),
        || interior.unwrap_or_else(|| mesh.interior_edges()),
    );
    certified.map_err(ShellError::Uncertified)?;
    o.verdict = Verdict::Yes;
    o.method = method.name();
    o.within_bound = Some(mesh.tets.len() <= o.bound);
    o.tetrahedra = Some(mesh.tets.len());
    o.tetrahedra_before_flips = Some(done.before);
    o.interior_edges = Some(interior);
    o.pieces = Some(mesh.pieces);
    o.finished_by = Some(mesh.finished_by);
    o.weights = mesh.ledger.as_ref().map(|l| Weights::new(s, l));
    o.thesis_steps = mesh.thesis;
    o.flips = Some(opts.flips.then_some(FlipCounts {
        three_two: done.three_two,
        delaunay: done.delaunay,
    }));
    o.tets = mesh.tets;
    Ok(o)
}

/// The mesh of the method asked for, or, when it ends above `bound` (Theorem 4.2's
/// 9n − 6) or, with flips, above [`REMOVAL_BUDGET`] per vertex, the smaller of it and the
/// other method's. With flips no route should end above that budget, but a Delaunay
/// shortcut can: bigcaps on two crossing arcs of 10^3 points passed their budget and
/// took the Delaunay shell, 11 per vertex (8.8 after the flips) where caps make 1.9.
fn within_bound(
    s: &Shell,
    opts: ShellOptions,
    bound: usize,
    ctl: &Control,
) -> Result<(super::ShellMesh, Improvement, Method), ShellError> {
    let (first, done) = mesh(s, opts, ctl)?;
    let enough = match opts.flips {
        true => bound.min(REMOVAL_BUDGET * s.n()),
        false => bound,
    };
    if first.tets.len() <= enough {
        return Ok((first, done, opts.method));
    }
    let other = match opts.method {
        Method::Cap => Method::Bigcap,
        Method::Bigcap | Method::Thesis => Method::Cap,
    };
    let second = mesh(
        s,
        ShellOptions {
            method: other,
            ..opts
        },
        ctl,
    )?;
    Ok(match second.0.tets.len() < first.tets.len() {
        true => (second.0, second.1, other),
        false => (first, done, opts.method),
    })
}

/// The removals' mesh, improved by flips when asked. With flips, a removal by caps or
/// bigcaps that passes [`REMOVAL_BUDGET`] tetrahedra per vertex is abandoned for the
/// Delaunay tetrahedralization when `Q` is a union of its tetrahedra ([`delaunay_shell`]):
/// the flips would end at that count, and reaching it directly costs a fraction.
fn mesh(
    s: &Shell,
    opts: ShellOptions,
    ctl: &Control,
) -> Result<(super::ShellMesh, Improvement), ShellError> {
    if opts.flips && opts.method != Method::Thesis {
        match removal_or_delaunay(s, opts.method, ctl)? {
            Route::Removal(mut mesh, pending) => {
                // The ledger owes nothing to the flips: drawn up beside them.
                let (done, ledger) = rayon::join(
                    || improve(&s.points, &mut mesh, ctl),
                    || pending.map(|p| p.ledger(s)),
                );
                mesh.ledger = ledger;
                return Ok((mesh, done?));
            }
            Route::Delaunay(Some(tets)) => return delaunay_mesh(s, tets, ctl),
            Route::Delaunay(None) => {}
        }
    }
    let mut mesh = tetrahedralize(s, opts.method, ctl)?;
    let done = match opts.flips {
        true => improve(&s.points, &mut mesh, ctl)?,
        false => Improvement {
            before: mesh.tets.len(),
            ..Default::default()
        },
    };
    Ok((mesh, done))
}

/// How [`removal_or_delaunay`] ended.
enum Route {
    /// The removal, within its budget, and what its ledger needs.
    Removal(super::ShellMesh, Option<super::Pending>),
    /// The removal passed its budget: the Delaunay shell, `None` when `Q` is not a union
    /// of Delaunay tetrahedra.
    Delaunay(Option<Vec<[u32; 4]>>),
}

/// The removal by `method` within [`REMOVAL_BUDGET`], or the Delaunay shell when it
/// passes it. Once the removal passes [`DELAUNAY_START`] tetrahedra per vertex, the
/// Delaunay tetrahedralization is built beside it on a spare core, and given up as soon
/// as the removal ends within its budget: the answer is the same whichever ends first,
/// and on one core the Delaunay tetrahedralization is built after the removal.
fn removal_or_delaunay(s: &Shell, method: Method, ctl: &Control) -> Result<Route, ShellError> {
    let (spare, found) = (ctl.child(), OnceLock::new());
    let removed = rayon::scope(|sc| {
        let (spare, found) = (&spare, &found);
        let mut started = false;
        let mut go_on = |tets: usize| {
            if tets > DELAUNAY_START * s.n() && !std::mem::replace(&mut started, true) {
                sc.spawn(move |_| _ = found.set(delaunay_shell(s, spare)));
            }
            tets <= REMOVAL_BUDGET * s.n()
        };
        let removed = tetrahedralize_within(s, (method, &mut go_on), ctl);
        if !matches!(removed, Ok(None)) {
            spare.stop();
        }
        removed
    })?;
    Ok(match removed {
        Some((mesh, pending)) => Route::Removal(mesh, pending),
        None => Route::Delaunay(
            found
                .into_inner()
                .unwrap_or_else(|| delaunay_shell(s, ctl))?,
        ),
    })
}

/// Tetrahedra per vertex past which [`shell`] abandons a removal for the Delaunay
/// tetrahedralization: above what the removals make on ordinary shells (1.8–3.7 per
/// vertex on the families of `benches/shell.sh`), below Bern disks' (7.9 at n = 1502,
/// 10.1 at 15,002).
pub const REMOVAL_BUDGET: usize = 5;

/// Tetrahedra per vertex past which [`shell`] starts the Delaunay tetrahedralization on a
/// spare core, in case the removal passes its budget. The families of `benches/shell.sh`
/// pass it after three quarters of their removable vertices (spheres, lattice, dome) or
/// in their last pieces (prisms, arcs, circles, corner), Bern disks after half of theirs
/// (a fifth of the removal's time: its last caps are its largest).
pub const DELAUNAY_START: usize = 1;

/// The Delaunay shell `tets`, improved by 3-2 flips (its faces are Delaunay already).
fn delaunay_mesh(
    s: &Shell,
    mut tets: Vec<[u32; 4]>,
    ctl: &Control,
) -> Result<(super::ShellMesh, Improvement), ShellError> {
    let before = tets.len();
    let three_two = crate::flip::reduce(&s.points, &mut tets, ctl)?;
    let mesh = super::ShellMesh {
        tets,
        pieces: 0,
        finished_by: super::Finish::Delaunay,
        ledger: None,
        thesis: None,
    };
    let done = Improvement {
        before,
        three_two,
        delaunay: None,
    };
    Ok((mesh, done))
}

/// Theorem 4.2's weights (§4.4) on the interior edges the removal added, each charged to
/// one vertex as Lemmas 4.10–4.12 charge it ([`super::Ledger`]).
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Weights {
    /// The interior edges the removal added: the sum of the weights.
    pub edges: usize,
    /// The largest weight.
    pub max: usize,
    /// `histogram[w]`: how many vertices have weight `w`.
    pub histogram: Vec<usize>,
    /// A vertex of the largest weight.
    pub heaviest: FileVertex,
    /// Theorem 4.2's claim on this run: every weight at most 8.
    pub at_most_8: bool,
}

impl Weights {
    fn new(s: &Shell, l: &super::Ledger) -> Weights {
        let (max, v) = l.heaviest();
        Weights {
            edges: l.edges(),
            max,
            histogram: l.histogram(),
            heaviest: s.file_vertex(v),
            at_most_8: max <= 8,
        }
    }
}

/// A vertex of a shell named in its input file: `polytope` is `outer` or `inner`, `index`
/// 0-based among that file's points.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct FileVertex {
    /// `outer` or `inner`.
    pub polytope: &'static str,
    /// The point's 0-based index in that file.
    pub index: u32,
}

/// Lemma 4.1 failing at a tip, in the files' numbering (JSON `witness`).
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct AssumptionWitness {
    /// Always `lemma_4_1`.
    pub kind: &'static str,
    /// The tip `v`, an outer point.
    pub tip: u32,
    /// `U_v`, outer points (the tip among them).
    pub removed: Vec<u32>,
    /// A bottom triangle `(a, b, c)` of the bigcap, on a facet of the new hull `H` and
    /// oriented out of it: `det[b − a, c − a, x − a] <= 0` for every vertex `x` of `H`.
    pub bottom: [FileVertex; 3],
    /// The sign of `det[b − a, c − a, tip − a]`: `-1`, the side of `H`'s interior, so the
    /// tip is behind the triangle and sees none of its interior.
    pub orientation: i8,
    /// A vertex of `H` off the triangle's plane, on the same side as the tip.
    pub kept: FileVertex,
    /// The sign of `det[b − a, c − a, kept − a]`, equal to `orientation`.
    pub kept_orientation: i8,
    /// The same in one sentence.
    pub detail: String,
}

impl AssumptionWitness {
    fn new(s: &Shell, w: &Lemma41Witness) -> Self {
        let file = |k: u32| s.file_vertex(k);
        let p = |k: u32| &s.points[k as usize];
        let [a, b, c] = w.bottom;
        let side = |d: u32| orient3d_value(p(a), p(b), p(c), p(d)).sign();
        let bottom = w.bottom.map(file);
        let name = |v: FileVertex| format!("{} {}", v.polytope, v.index);
        let detail = format!(
            "Lemma 4.1 fails at tip outer {}: U_v = outer {:?} gives a simple bigcap, but its bottom triangle ({}, {}, {}) faces away from the tip: det[b − a, c − a, tip − a] has the sign {:+} of the new hull's vertex {} (the hull's side)",
            s.outer_source[w.tip as usize],
            w.removed
                .iter()
                .map(|&r| s.outer_source[r as usize])
                .collect::<Vec<_>>(),
            name(bottom[0]),
            name(bottom[1]),
            name(bottom[2]),
            side(w.tip),
            name(file(w.kept)),
        );
        AssumptionWitness {
            kind: "lemma_4_1",
            tip: s.outer_source[w.tip as usize],
            removed: w
                .removed
                .iter()
                .map(|&r| s.outer_source[r as usize])
                .collect(),
            bottom,
            orientation: side(w.tip),
            kept: file(w.kept),
            kept_orientation: side(w.kept),
            detail,
        }
    }
}

/// The exact minimum of a shell's tetrahedra (`shell --optimum`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct Optimum {
    /// The minimum was proven (then `lower_bound == upper_bound`).
    pub proven: bool,
    /// No tetrahedralization has fewer tetrahedra.
    pub lower_bound: usize,
    /// The fewest found: the removals' and flips' mesh, or the exact solver's.
    pub upper_bound: usize,
    /// The removals' and flips' count, before the exact solver.
    pub heuristic: usize,
}

type Tets = Vec<[u32; 4]>;

/// The exact solver's minimum against `found` tetrahedra, and its mesh when it has fewer.
fn exact_minimum(
    s: &Shell,
    found: usize,
    ctl: &Control,
) -> Result<(Optimum, Option<Tets>), ShellError> {
    use crate::exact::Outcome;
    let (outcome, _) = super::optimum(s, ctl).map_err(ShellError::Exact)?;
    let (proven, lower, best) = match outcome {
        Outcome::Optimal { tets, .. } | Outcome::Found { tets } => (true, tets.len(), Some(tets)),
        Outcome::Undecided { best, lower } => (false, lower, best),
        Outcome::Infeasible => {
            return Err(ShellError::Internal(Bug::new(
                "the exact solver finds a tetrahedralization of a shell that has one",
            )));
        }
    };
    let best = best.filter(|b| b.len() < found);
    let upper = best.as_ref().map_or(found, Vec::len);
    let report = Optimum {
        proven,
        lower_bound: if proven { upper } else { lower.min(upper) },
        upper_bound: upper,
        heuristic: found,
    };
    Ok((report, best))
}
