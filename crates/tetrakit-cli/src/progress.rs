//! The run-control of a command: a deadline from `--time-limit` and, when stderr is a
//! terminal and the work is large, a progress display fed by the library's
//! [`Progress`] reports. Nothing else in the CLI knows about threads, flags or clocks.

use indicatif::{ProgressBar, ProgressStyle};
use std::io::IsTerminal;
use std::time::Duration;
use tetrakit::control::{Control, Progress};

/// A [`Control`] for one command and the display it reports to (cleared on drop).
pub struct Run {
    /// What the library is given.
    pub ctl: Control,
    bar: Option<ProgressBar>,
}

impl Run {
    /// A control stopping after `time_limit`, showing progress when `items` (the work's
    /// size: sites, vertices) is at least `min` and stderr is a terminal.
    pub fn new(time_limit: Option<Duration>, items: usize, min: usize) -> Run {
        let mut ctl = Control::new();
        if let Some(limit) = time_limit {
            ctl = ctl.with_time_limit(limit);
        }
        let bar = (items >= min && std::io::stderr().is_terminal()).then(spinner);
        if let Some(b) = &bar {
            let b = b.clone();
            ctl = ctl.with_progress(move |p| show(&b, p));
        }
        Run { ctl, bar }
    }

    /// Names what the command does next on the display (work outside the library).
    pub fn stage(&self, what: &'static str) {
        if let Some(b) = &self.bar {
            show(b, Progress::Stage(what));
        }
    }
}

impl Drop for Run {
    fn drop(&mut self) {
        if let Some(b) = &self.bar {
            b.finish_and_clear();
        }
    }
}

fn spinner() -> ProgressBar {
    let bar = ProgressBar::new_spinner();
    if let Ok(style) = ProgressStyle::with_template("{spinner} {msg} ({elapsed})") {
        bar.set_style(style);
    }
    bar.enable_steady_tick(Duration::from_millis(120));
    bar
}

/// A stage names the display; items turn it into a bar with their count.
fn show(bar: &ProgressBar, p: Progress) {
    match p {
        Progress::Stage(name) => bar.set_message(name),
        Progress::Items { done, total } => {
            if bar.length() != Some(total) {
                if let Ok(style) =
                    ProgressStyle::with_template("{msg} [{bar:40}] {pos}/{len} ({eta})")
                {
                    bar.set_style(style.progress_chars("=> "));
                }
                bar.set_length(total);
            }
            bar.set_position(done.max(bar.position()));
        }
    }
}
