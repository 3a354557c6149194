//! The text of a `shell` outcome.

use crate::shell::{Finish, REMOVAL_BUDGET, ShellOutcome};
use std::fmt::Write;

/// The lines a person reads for `o`, found in `seconds`.
pub fn shell_text(o: &ShellOutcome, seconds: f64) -> String {
    let mut s = String::new();
    if let Some(w) = &o.witness {
        let _ = writeln!(s, "ASSUMPTION FAILS: {} [{seconds:.3} s]", w.detail);
        return s;
    }
    let Some(t) = o.tetrahedra else {
        let _ = writeln!(
            s,
            "UNDECIDED: stopped at the time limit after {seconds:.3} s"
        );
        return s;
    };
    let bound = match o.within_bound {
        Some(false) => "ABOVE the bound",
        _ => "bound",
    };
    let _ = writeln!(
        s,
        "YES: {t} tetrahedra for the shell between {} outer and {} inner vertices (n = {}, {bound} 9n − 6 = {}, {:.2} per vertex), no Steiner point, certified. [{seconds:.3} s]",
        o.outer_vertices,
        o.inner_vertices,
        o.n,
        o.bound,
        t as f64 / o.n as f64
    );
    if let Some(opt) = o.optimum {
        let _ = match opt.proven {
            true => writeln!(
                s,
                "  the exact minimum (SAT over every tetrahedralization): {} tetrahedra, the mesh printed",
                opt.upper_bound
            ),
            false => writeln!(
                s,
                "  the exact minimum: between {} and {} tetrahedra (stopped first)",
                opt.lower_bound, opt.upper_bound
            ),
        };
    }
    match o.lemma_4_1 {
        Some("holds") => {
            let _ = writeln!(
                s,
                "  Lemma 4.1 holds at every tip of the outer polytope; BIGCAP-REMOVE's steps ran{}",
                steps_text(o)
            );
        }
        Some(_) => {
            let _ = writeln!(
                s,
                "  Lemma 4.1 not examined (the inner polytope touches the outer one); BIGCAP-REMOVE's steps ran{}",
                steps_text(o)
            );
        }
        None => {}
    }
    match o.finished_by {
        Some(Finish::Placing) => {
            let _ = writeln!(
                s,
                "  the removal left outer vertices no piece could take: the shell was placed instead (Q, then the outer vertices in the reverse of the removal's order)"
            );
        }
        Some(Finish::Delaunay) => {
            let _ = writeln!(
                s,
                "  the removal passed {REMOVAL_BUDGET} tetrahedra per vertex: the shell is the Delaunay tetrahedralization of its vertices outside Q (Q is a union of its tetrahedra, checked exactly)"
            );
        }
        _ => {}
    }
    if o.within_bound == Some(false) {
        let _ = writeln!(
            s,
            "  both methods ended above 9n − 6; the smaller mesh ({}) is printed",
            o.method
        );
    }
    let flipped = o.optimum.map_or(t, |x| x.heuristic);
    if let (Some(before), Some(Some(f))) = (o.tetrahedra_before_flips, o.flips)
        && before != flipped
    {
        let how = match f.delaunay {
            Some(_) => " (Delaunay flips, then 3-2 flips)",
            None => " (3-2 flips)",
        };
        let made = match o.finished_by {
            Some(Finish::Delaunay) => "the Delaunay tetrahedralization had",
            _ => "the removals made",
        };
        let _ = writeln!(
            s,
            "  {made} {before}; flips inside the shell took it to {flipped}{how}"
        );
    }
    if let Some(w) = &o.weights {
        let claim = match w.at_most_8 {
            true => "within",
            false => "ABOVE",
        };
        let _ = writeln!(
            s,
            "  the removal's {} interior edges weighted as in §4.4: largest weight {} (vertex {} {}), {claim} Theorem 4.2's 8",
            w.edges, w.max, w.heaviest.polytope, w.heaviest.index
        );
    }
    if o.outer_ignored + o.inner_ignored > 0 {
        let _ = writeln!(
            s,
            "  not vertices (inside a hull, or on it but not a corner, or repeated): {} outer and {} inner points",
            o.outer_ignored, o.inner_ignored
        );
    }
    s
}

/// What BIGCAP-REMOVE's steps did, for the text line (empty when the mesh is another
/// method's).
fn steps_text(o: &ShellOutcome) -> String {
    o.thesis_steps.map_or(String::new(), |t| {
        format!(
            ": {} round(s) of Steps 2–3 ({} with Step 3a's fewest tips by exact search, |P_a| up to {}; {} with every tip), {} S-bigcap(s) whole, {} repaired (refused as the thesis defines them), {} Step-1 cap(s), {} Step-6 chain(s) with {} S_b-bigcap(s)",
            t.rounds,
            t.step_3a_exact,
            t.largest_p_a_searched,
            t.step_3a_every_tip,
            t.s_bigcaps,
            t.repaired,
            t.step_1_caps,
            t.step_6_chains,
            t.step_6_bigcaps
        )
    })
}
