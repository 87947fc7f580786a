//! `nd_results.csv`: one row per four-dimensional scene, method and step or tolerance,
//! in the columns of `results.csv` that apply.

use std::fmt::Write as _;

use super::run::NdSceneResult;
use crate::report::results::quote;

/// The CSV header: the attitude error in rad (largest over the samples), the energy drift
/// relative to the initial energy (largest over the samples).
pub const ND_CSV_HEADER: &str = "scene,method,param_kind,param,steps,repeats,time_median_us,\
err_attitude_max,energy_drift_rel_max,reference,status";

/// The whole CSV text. A run that stopped has empty measurement cells and its reason in
/// `status`. Numbers are written with `{:e}`, which reads back to the same `f64`.
#[must_use]
pub fn nd_csv(scenes: &[NdSceneResult]) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "{ND_CSV_HEADER}");
    for scene in scenes {
        for row in &scene.rows {
            let _ = write!(
                out,
                "{},{},{},{:e},{},",
                quote(&scene.name),
                row.method.name(),
                row.param_kind(),
                row.param,
                row.steps
            );
            match (row.timing, row.errors) {
                (Some(t), Some(e)) => {
                    let _ = write!(
                        out,
                        "{},{:e},{:e},{:e},",
                        t.repeats,
                        t.median.as_secs_f64() * 1e6,
                        e.attitude_max,
                        e.energy_max
                    );
                }
                _ => out.push_str(",,,,"),
            }
            let status = match &row.failure {
                Some(why) => format!("failed: {why}"),
                None => "ok".to_string(),
            };
            let _ = writeln!(out, "{},{}", row.reference.name(), quote(&status));
        }
    }
    out
}
