//! Run-control: the one way every long-running capability is told to stop and reports
//! progress.
//!
//! Each long-running entry point takes its input, its options and a `&`[`Control`]. It
//! looks at [`Control::check`] between units of work (sites, vertices, edges, faces,
//! SAT restarts) and returns [`Stopped`] (inside its module's error type) once the
//! control is stopped: by [`Control::stop`] from any thread (a clone shares the flag),
//! or because its deadline passed. A capability whose partial work is itself an answer
//! returns that instead (the exact solver's `Outcome::Undecided` carries its bounds).
//!
//! Progress goes to one callback, from any thread: [`Progress::Stage`] as a stage
//! starts, [`Progress::Items`] now and then within a stage whose size is known.
//!
//! A part of the work may run under a [`Control::child`]: its own stop flag and deadline,
//! and it still stops when its parent does. Its deadline or its stop never stops the
//! parent, so a piece given ten seconds that runs out of them ends that piece, not the
//! run.
//!
//! ```
//! use std::sync::{Arc, Mutex};
//! use std::time::Duration;
//! use tetrakit::control::{Control, Progress, Stopped};
//!
//! let seen = Arc::new(Mutex::new(Vec::new()));
//! let log = Arc::clone(&seen);
//! let ctl = Control::new()
//!     .with_time_limit(Duration::from_secs(3600))
//!     .with_progress(move |p| log.lock().unwrap().push(p));
//! ctl.stage("counting");
//! assert_eq!(ctl.check(), Ok(()));
//! let other = ctl.clone(); // for another thread, a signal handler, a Python callback
//! other.stop();
//! assert_eq!(ctl.check(), Err(Stopped));
//! assert_eq!(seen.lock().unwrap()[0], Progress::Stage("counting"));
//! ```

use std::fmt;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering::Relaxed};
use std::time::{Duration, Instant};

/// What a long-running computation reports.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Progress {
    /// A stage starts (a name for a person: "LMT-skeleton", "vertex links").
    Stage(&'static str),
    /// Of the current stage's `total` items, `done` are finished (reported every few
    /// thousand items, from any thread, so not always in increasing order).
    Items {
        /// Items finished.
        done: u64,
        /// Items in the stage.
        total: u64,
    },
}

/// The computation was stopped (its control's [`Control::stop`] was called, or its
/// deadline passed) before it had an answer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Stopped;

impl fmt::Display for Stopped {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("stopped (time limit reached or stop requested) before an answer was found")
    }
}

impl std::error::Error for Stopped {}

/// A capability's answer, as every outcome and the JSON contract's `"verdict"` say it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Verdict {
    /// Valid, or a YES.
    Yes,
    /// A definite NO, with a witness.
    No,
    /// Stopped (time limit or stop request) before an answer.
    Undecided,
    /// An assumption of the thesis's algorithm fails on this input (`shell --method
    /// thesis`: Lemma 4.1), with a witness; the exit code of a NO.
    #[serde(rename = "assumption_fails")]
    AssumptionFails,
}

impl From<bool> for Verdict {
    /// `Yes` for `true`, `No` for `false`.
    fn from(yes: bool) -> Self {
        if yes { Verdict::Yes } else { Verdict::No }
    }
}

/// The progress callback's type.
type Callback = dyn Fn(Progress) + Send + Sync;

/// A stop flag, an optional deadline and an optional progress callback (see the module
/// documentation). Cheap to clone; clones share the stop flag.
#[derive(Clone, Default)]
pub struct Control {
    stop: Arc<AtomicBool>,
    deadline: Option<Instant>,
    progress: Option<Arc<Callback>>,
    /// The control this one is a [`child`](Control::child) of.
    parent: Option<Arc<Control>>,
}

impl fmt::Debug for Control {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Control")
            .field("stopped", &self.stop.load(Relaxed))
            .field("deadline", &self.deadline)
            .field("progress", &self.progress.is_some())
            .field("parent", &self.parent)
            .finish()
    }
}

impl Control {
    /// A control that never stops by itself and reports to nobody.
    pub fn new() -> Self {
        Control::default()
    }

    /// Stops at `deadline` (the earlier deadline wins when one is already set).
    pub fn with_deadline(mut self, deadline: Instant) -> Self {
        self.deadline = Some(self.deadline.map_or(deadline, |d| d.min(deadline)));
        self
    }

    /// Stops `limit` from now. A limit too large to add to the clock means no deadline.
    pub fn with_time_limit(self, limit: Duration) -> Self {
        match Instant::now().checked_add(limit) {
            Some(d) => self.with_deadline(d),
            None => self,
        }
    }

    /// Reports progress to `callback` (from any thread).
    pub fn with_progress(mut self, callback: impl Fn(Progress) + Send + Sync + 'static) -> Self {
        self.progress = Some(Arc::new(callback));
        self
    }

    /// A control for a part of the work: its own stop flag and (with
    /// [`with_time_limit`](Self::with_time_limit)) its own deadline, the same progress
    /// callback, and stopped whenever `self` is. Stopping it, or its deadline passing,
    /// does not stop `self`.
    ///
    /// ```
    /// use std::time::Duration;
    /// use tetrakit::control::Control;
    /// let run = Control::new();
    /// let piece = run.child().with_time_limit(Duration::ZERO);
    /// assert!(piece.is_stopped() && !run.is_stopped()); // the piece's time is up, not the run's
    /// let other = run.child();
    /// run.stop();
    /// assert!(other.is_stopped()); // the run's stop reaches every piece
    /// ```
    pub fn child(&self) -> Control {
        Control {
            stop: Arc::default(),
            deadline: None,
            progress: self.progress.clone(),
            parent: Some(Arc::new(self.clone())),
        }
    }

    /// Asks every computation under this control (or a clone of it, or a child) to stop.
    pub fn stop(&self) {
        self.stop.store(true, Relaxed);
    }

    /// True once [`stop`](Self::stop) was called, the deadline passed, or the parent (for
    /// a [`child`](Self::child)) is stopped.
    #[inline]
    pub fn is_stopped(&self) -> bool {
        if self.stop.load(Relaxed) {
            return true;
        }
        let expired = match self.deadline {
            Some(d) => Instant::now() >= d,
            None => false,
        };
        if expired {
            self.stop.store(true, Relaxed);
            return true;
        }
        self.parent.as_ref().is_some_and(|p| p.is_stopped())
    }

    /// `Err(Stopped)` once the control is stopped ([`is_stopped`](Self::is_stopped)).
    #[inline]
    pub fn check(&self) -> Result<(), Stopped> {
        if self.is_stopped() {
            Err(Stopped)
        } else {
            Ok(())
        }
    }

    /// The deadline, if any: its own or an ancestor's, whichever comes first.
    pub fn deadline(&self) -> Option<Instant> {
        let parent = self.parent.as_ref().and_then(|p| p.deadline());
        match (self.deadline, parent) {
            (Some(a), Some(b)) => Some(a.min(b)),
            (a, b) => a.or(b),
        }
    }

    /// Reports that stage `name` starts.
    pub fn stage(&self, name: &'static str) {
        self.report(Progress::Stage(name));
    }

    /// Reports `done` of `total` items of the current stage finished.
    pub fn items(&self, done: u64, total: u64) {
        self.report(Progress::Items { done, total });
    }

    /// True when somebody listens to progress (so a caller may skip counting).
    pub fn reports(&self) -> bool {
        self.progress.is_some()
    }

    fn report(&self, p: Progress) {
        if let Some(f) = &self.progress {
            f(p);
        }
    }
}

/// The run-control, asked by the SAT solver (batsat) at its periodic stop check.
#[derive(Default)]
pub(crate) struct SatStop(Control);

impl batsat::Callbacks for SatStop {
    fn stop(&self) -> bool {
        self.0.is_stopped()
    }
}

/// The SAT solver every exact decision uses, stopped through a [`Control`].
pub(crate) type SatSolver = rustsat_batsat::Solver<SatStop>;

/// A SAT solver that answers `Interrupted` once `ctl` stops.
pub(crate) fn sat_solver(ctl: &Control) -> SatSolver {
    let mut solver = SatSolver::default();
    solver.batsat_mut().cb_mut().0 = ctl.clone();
    solver
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_passed_deadline_stops_and_a_new_control_does_not() {
        assert_eq!(Control::new().check(), Ok(()));
        let past = Control::new().with_deadline(Instant::now());
        assert_eq!(past.check(), Err(Stopped));
        let far = Control::new().with_time_limit(Duration::MAX);
        assert_eq!(far.deadline(), None);
        assert!(!far.is_stopped());
    }

    #[test]
    fn the_earlier_deadline_wins() {
        let now = Instant::now();
        let later = now + Duration::from_secs(60);
        let c = Control::new().with_deadline(later).with_deadline(now);
        assert_eq!(c.deadline(), Some(now));
        let c = Control::new().with_deadline(now).with_deadline(later);
        assert_eq!(c.deadline(), Some(now));
    }

    #[test]
    fn a_childs_deadline_and_stop_stay_with_the_child() {
        let run = Control::new().with_time_limit(Duration::from_secs(3600));
        let piece = run.child().with_deadline(Instant::now());
        assert!(piece.is_stopped());
        assert!(!run.is_stopped(), "the piece's deadline stopped the run");
        let second = run.child();
        second.stop();
        assert!(!run.is_stopped() && !run.child().is_stopped());
        let grandchild = run.child().child();
        assert_eq!(grandchild.deadline(), run.deadline());
        run.stop();
        assert!(
            grandchild.is_stopped(),
            "a stopped run must stop every piece"
        );
    }

    #[test]
    fn clones_share_the_stop_flag() {
        let a = Control::new();
        let b = a.clone();
        std::thread::spawn(move || b.stop()).join().unwrap();
        assert!(a.is_stopped());
    }
}
