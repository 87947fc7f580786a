//! The stiff and extreme cases: does each method stay finite, and what does it keep?

use std::fmt::Write as _;

use crate::error::Error;
use crate::integrators::{Step, StepKind};

use super::measure::{attitude_error, energy_drift, momentum_error, reference, run};
use super::scenes::TestScene;

/// The stability table of every scene.
pub fn section(out: &mut String, scenes: &[TestScene]) -> Result<(), Error> {
    let _ = writeln!(
        out,
        "## Stability on stiff and extreme cases\n\nOne fixed step per scene for the \
         fixed-step methods, tol = 1e-8 for Dormand-Prince.\n"
    );
    for scene in scenes {
        let reference = reference(scene)?;
        let h = scene.t_end / f64::from(scene.coarsest_steps);
        let _ = writeln!(
            out,
            "### {}\n\n{}.\n\n| method | outcome | attitude error | m error | energy drift | time (us) |\n|---|---|---|---|---|---|",
            scene.name, scene.source
        );
        let (methods, left_out) = scene.methods();
        for method in methods {
            let step = match method.step_kind() {
                StepKind::Fixed => Step::Fixed(h),
                StepKind::Adaptive => Step::Tolerance(1e-8),
                StepKind::AtSamples => Step::AtSamples,
            };
            let outcome = run(scene, method, step, 1)?;
            let micros = outcome.time.as_secs_f64() * 1e6;
            match &outcome.end {
                Ok(end) => {
                    let _ = writeln!(
                        out,
                        "| {} | finite | {:.2e} | {:.2e} | {:.2e} | {micros:.1} |",
                        method.name(),
                        attitude_error(end.rotor, reference.rotor),
                        momentum_error(scene, end, &reference),
                        energy_drift(scene, end),
                    );
                }
                Err(e) => {
                    let _ = writeln!(
                        out,
                        "| {} | failed: {e} | | | | {micros:.1} |",
                        method.name()
                    );
                }
            }
        }
        for (method, why) in left_out {
            let _ = writeln!(out, "\nLeft out: {} ({why}).", method.name());
        }
        let _ = writeln!(out);
    }
    Ok(())
}
