//! Error against run time for every method on one scene: fixed-step methods over a
//! geometric series of steps, Dormand-Prince over a series of tolerances (SciML's
//! work-precision practice).

use std::fmt::Write as _;

use crate::error::Error;
use crate::integrators::{Method, Step, StepKind};

use super::measure::{attitude_error, energy_drift, momentum_error, reference, run};
use super::scenes::TestScene;
use super::Size;

/// The attitude error the summary asks each method to reach.
const TARGET: f64 = 1e-8;

/// One scene's table and its summary lines.
pub fn section(out: &mut String, scene: &TestScene, size: Size) -> Result<(), Error> {
    let reference = reference(scene)?;
    let (methods, left_out) = scene.methods();
    let _ = writeln!(
        out,
        "## {}\n\n{}; t_end = {}.",
        scene.name, scene.source, scene.t_end
    );
    for (method, why) in &left_out {
        let _ = writeln!(out, "Left out: {} ({why}).", method.name());
    }
    let _ = writeln!(
        out,
        "\n| method | step or tol | attitude error | m error | energy drift | time (us) |\n\
         |---|---|---|---|---|---|"
    );
    let (levels, repeats) = match size {
        Size::Quick => (3, 1),
        Size::Full => (9, 3),
    };
    // The fastest of all methods, and of the time-stepping ones (which also run where no
    // exact solution exists).
    let mut fastest: Option<(f64, Method, String)> = None;
    let mut fastest_stepping: Option<(f64, Method, String)> = None;
    for method in methods {
        for (step, label) in steps(scene, method, levels) {
            let outcome = run(scene, method, step, repeats)?;
            let micros = outcome.time.as_secs_f64() * 1e6;
            let end = match &outcome.end {
                Ok(end) => end,
                Err(e) => {
                    let _ = writeln!(
                        out,
                        "| {} | {label} | failed: {e} | | | {micros:.1} |",
                        method.name()
                    );
                    continue;
                }
            };
            let attitude = attitude_error(end.rotor, reference.rotor);
            let _ = writeln!(
                out,
                "| {} | {label} | {attitude:.2e} | {:.2e} | {:.2e} | {micros:.1} |",
                method.name(),
                momentum_error(scene, end, &reference),
                energy_drift(scene, end),
            );
            let stepping = method.step_kind() != StepKind::AtSamples;
            for (slot, eligible) in [(&mut fastest, true), (&mut fastest_stepping, stepping)] {
                let faster = slot.as_ref().is_none_or(|(t, _, _)| micros < *t);
                if eligible && attitude <= TARGET && faster {
                    *slot = Some((micros, method, label.clone()));
                }
            }
        }
    }
    let _ = writeln!(out);
    for (what, slot) in [
        ("method", fastest),
        ("time-stepping method", fastest_stepping),
    ] {
        match slot {
            Some((micros, method, label)) => {
                let _ = writeln!(
                    out,
                    "Fastest {what} to an attitude error of {TARGET:.0e}: {} ({label}), {micros:.1} us.",
                    method.name()
                );
            }
            None => {
                let _ = writeln!(out, "No {what} reached {TARGET:.0e} at these settings.");
            }
        }
    }
    let _ = writeln!(out);
    Ok(())
}

/// The step sizes (or tolerances) a method runs at, coarsest first.
fn steps(scene: &TestScene, method: Method, levels: u32) -> Vec<(Step, String)> {
    match method.step_kind() {
        StepKind::AtSamples => vec![(Step::AtSamples, "-".to_string())],
        StepKind::Fixed => (0..levels)
            .map(|k| {
                let h = scene.t_end / f64::from(scene.coarsest_steps << k);
                (Step::Fixed(h), format!("h = {h:.3e}"))
            })
            .collect(),
        StepKind::Adaptive => (0..levels)
            .map(|k| {
                let tol = 10f64.powi(-4 - (9 * k as i32) / levels.max(1) as i32);
                (Step::Tolerance(tol), format!("tol = {tol:.0e}"))
            })
            .collect(),
    }
}
