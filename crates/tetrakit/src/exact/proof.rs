//! Proofs of infeasibility a program can check: the solver's formula in DIMACS and a
//! DRAT refutation of it, from a proof-producing SAT solver (varisat, pure Rust, so no
//! C++ toolchain or libclang is needed; CaDiCaL's Rust binding needs libclang to build).
//!
//! The formula is exactly the one [`super::solve`] decides, without the objective: one
//! variable per candidate tetrahedron, numbered 1, 2, … in the order of the candidates'
//! sorted vertex quadruples, then helper variables of the at-most-one encodings. By the
//! module docs of [`super`], it is satisfiable exactly when a tetrahedralization obeying
//! the edge rules exists; so a checked refutation (for example by `rate` or
//! `drat-trim`) proves that none does.

use super::{Domain, Edges, ExactError, Formula};
use crate::control::Control;
use rustsat::instances::{Cnf, ManageVars};
use std::io::{self, Write};
use varisat::ExtendFormula;

/// What [`prove_infeasible`] found.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Proof {
    /// The formula was written and is unsatisfiable; the DRAT refutation was written.
    Refuted {
        /// Variables of the formula.
        variables: u32,
        /// Clauses of the formula.
        clauses: usize,
    },
    /// The formula is satisfiable: a tetrahedralization exists (nothing to refute).
    Satisfiable,
    /// The control stopped the solver first (the proof written so far is incomplete).
    Stopped,
}

/// Writes the formula of `domain` under `edges` to `formula` (DIMACS CNF) and, when it is
/// unsatisfiable, a DRAT refutation of it to `proof` (text DRAT).
///
/// ```
/// use tetrakit::control::Control;
/// use tetrakit::exact::{Domain, Edges, Proof, prove_infeasible};
/// use tetrakit::polyhedra::generate;
/// let s = generate::schonhardt();
/// let (mut cnf, mut drat) = (Vec::new(), Vec::new());
/// let p = prove_infeasible(Domain::Polyhedron(&s), Edges::default(), &mut cnf, &mut drat, &Control::new());
/// assert!(matches!(p, Ok(Proof::Refuted { .. })));
/// assert!(String::from_utf8(cnf).unwrap().lines().any(|l| l.starts_with("p cnf")));
/// ```
pub fn prove_infeasible(
    domain: Domain,
    edges: Edges,
    formula: &mut impl Write,
    proof: impl Write,
    ctl: &Control,
) -> Result<Proof, ExactError> {
    let Some(f) = Formula::new(domain, edges, ctl)? else {
        return Ok(Proof::Stopped);
    };
    let (cnf, variables) = without_empty_clauses(f.cnf, f.vars.n_used(), f.cand.tets.is_empty());
    let clauses = cnf.len();
    write_dimacs(formula, &f.cand.tets, &cnf, variables).map_err(|e| ExactError::Io(e.kind()))?;
    let mut solver = varisat::Solver::new();
    solver.write_proof(
        StopWriter {
            inner: proof,
            ctl: ctl.clone(),
        },
        varisat::ProofFormat::Drat,
    );
    let mut v = varisat::CnfFormula::new();
    for clause in cnf.iter() {
        let lits: Vec<varisat::Lit> = clause
            .iter()
            .map(|l| varisat::Lit::from_dimacs(l.to_ipasir() as isize))
            .collect();
        v.add_clause(&lits);
    }
    v.set_var_count(variables as usize);
    solver.add_formula(&v);
    let answer = solver.solve();
    if ctl.is_stopped() {
        return Ok(Proof::Stopped);
    }
    match answer {
        Ok(true) => Ok(Proof::Satisfiable),
        Ok(false) => {
            solver.close_proof().map_err(solver_error)?;
            Ok(Proof::Refuted { variables, clauses })
        }
        Err(e) => Err(solver_error(e)),
    }
}

/// A solver error while writing the proof: the proof writer's error kind.
fn solver_error(e: varisat::solver::SolverError) -> ExactError {
    match e {
        varisat::solver::SolverError::ProofIoError { cause } => ExactError::Io(cause.kind()),
        _ => ExactError::Io(std::io::ErrorKind::Other),
    }
}

/// The formula with each empty clause (a facet or a required segment that no candidate
/// has; with `no_candidate`, the clause "some candidate is chosen") written as the pair
/// `z`, `¬z` on a fresh variable `z`: the same unsatisfiability, in a form every checker
/// reads (some reject an empty input clause). Returns the formula and its variable count.
fn without_empty_clauses(cnf: Cnf, variables: u32, no_candidate: bool) -> (Cnf, u32) {
    if !no_candidate && cnf.iter().all(|c| !c.is_empty()) {
        return (cnf, variables);
    }
    let z = rustsat::types::Var::new(variables).pos_lit();
    let mut out = Cnf::new();
    for c in cnf.into_iter().filter(|c| !c.is_empty()) {
        out.add_clause(c);
    }
    out.add_clause([z].into_iter().collect());
    out.add_clause([!z].into_iter().collect());
    (out, variables + 1)
}

/// The formula in DIMACS, after comments naming each candidate's variable (`c tet 7: 0 1
/// 2 5`, vertices 0-based) so that a person can read a model or a core.
fn write_dimacs(
    out: &mut impl Write,
    tets: &[[u32; 4]],
    cnf: &Cnf,
    variables: u32,
) -> io::Result<()> {
    let mut w = io::BufWriter::new(out);
    writeln!(
        w,
        "c tetrakit exact formula: variable k is candidate tetrahedron k"
    )?;
    for (k, t) in tets.iter().enumerate() {
        writeln!(w, "c tet {}: {} {} {} {}", k + 1, t[0], t[1], t[2], t[3])?;
    }
    writeln!(w, "p cnf {variables} {}", cnf.len())?;
    for clause in cnf.iter() {
        for l in clause.iter() {
            write!(w, "{} ", l.to_ipasir())?;
        }
        writeln!(w, "0")?;
    }
    w.flush()
}

/// A proof writer that fails once the control is stopped, which is how the solver
/// (which has no stop callback) is interrupted: it writes a proof step for every clause
/// it learns.
struct StopWriter<W> {
    inner: W,
    ctl: Control,
}

impl<W: Write> Write for StopWriter<W> {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        if self.ctl.is_stopped() {
            return Err(io::Error::other("stopped"));
        }
        self.inner.write(buf)
    }

    fn flush(&mut self) -> io::Result<()> {
        self.inner.flush()
    }
}
