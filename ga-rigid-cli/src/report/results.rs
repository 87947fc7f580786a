//! `results.csv`: one row per scene, method and step or tolerance, every measured column.

use std::fmt::Write as _;

use super::Report;

/// The CSV header; errors are over the sample times (`_max`) or at the end (`_end`),
/// attitude in rad, momentum and energy relative.
pub const CSV_HEADER: &str = "scene,method,param_kind,param,steps,repeats,time_median_us,\
time_min_us,cost_per_step_ns,err_attitude_end,err_attitude_max,err_momentum_rel_end,\
err_momentum_rel_max,energy_drift_rel,energy_drift_rel_max,reference,status";

/// The whole CSV text. A run that stopped has empty measurement cells and its reason in
/// `status`.
#[must_use]
pub fn csv(report: &Report) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "{CSV_HEADER}");
    for scene in &report.scenes {
        for row in &scene.rows {
            let _ = write!(
                out,
                "{},{},{},{:e},{},",
                quote(&scene.name),
                row.method.name(),
                row.param_kind,
                row.param,
                row.steps
            );
            match (row.timing, row.errors) {
                (Some(t), Some(e)) => {
                    let median = t.median.as_secs_f64() * 1e6;
                    let _ = write!(
                        out,
                        "{},{median:.3},{:.3},{:.3},{:e},{:e},{:e},{:e},{:e},{:e},",
                        t.repeats,
                        t.min.as_secs_f64() * 1e6,
                        median * 1e3 / row.steps.max(1) as f64,
                        e.attitude_end,
                        e.attitude_max,
                        e.momentum_end,
                        e.momentum_max,
                        e.energy_end,
                        e.energy_max,
                    );
                }
                _ => out.push_str(",,,,,,,,,,"),
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

/// A CSV field, quoted when it holds a comma, a quote or a line break (RFC 4180).
pub(crate) fn quote(field: &str) -> String {
    if field.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", field.replace('"', "\"\""))
    } else {
        field.to_string()
    }
}
