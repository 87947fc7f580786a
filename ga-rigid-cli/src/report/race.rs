//! The page's race table: on each free asymmetric and each torqued scene, this library's
//! fastest stepper against ode_solvers' Dop853 on the quaternion form (the peer a
//! physicist reaches for), at the tightest error levels, with the ratio and the target.

use std::fmt::Write as _;

use ga_rigid::registry::{Method, StepKind, StepLimit};

use super::analysis::{fastest_of, SceneKind};
use super::escape::esc;
use super::{Measurement, Report, SceneResult};

/// The error levels the race is run to.
const RACE_LEVELS: [f64; 2] = [1e-6, 1e-10];

/// The target ratio (our time over Dop853's) on a kind of scene: at most as fast as Dop853
/// on free bodies, at most half its time under a torque.
fn target(kind: SceneKind) -> Option<f64> {
    match kind {
        SceneKind::FreeAsymmetric => Some(1.0),
        SceneKind::Torqued => Some(0.5),
        _ => None,
    }
}

/// The registry's stability limit `h |w|max` of a fixed-step method under a torque or
/// without one, if it has one.
fn step_limit(method: Method) -> Option<f64> {
    match method.info().step_limit {
        StepLimit::Rate(limit) | StepLimit::RateUnderTorque(limit) => Some(limit),
        StepLimit::None => None,
    }
}

/// The registry's limit a fixed-step run's `h |w(0)|` exceeds, if it does (`|w|max` is at
/// least `|w(0)|`, so such a run is certainly beyond the limit `simulate` checks).
fn above_limit(run: &Measurement, rate: f64) -> Option<f64> {
    step_limit(run.method)
        .filter(|&limit| run.method.step_kind() == StepKind::Fixed && run.param * rate > limit)
}

/// This library's stepping methods (no peers, no exact forms).
fn ours(method: Method) -> bool {
    method.info().peer.is_none() && method.step_kind() != StepKind::AtSamples
}

/// Writes the race table (nothing if the report has none of the race's scenes).
pub(super) fn race_section(out: &mut String, report: &Report) {
    let scenes: Vec<&SceneResult> = report
        .scenes
        .iter()
        .filter(|s| target(s.kind).is_some())
        .collect();
    if scenes.is_empty() {
        return;
    }
    out.push_str(
        "<h2 id=\"race\">The race against Dop853</h2>\n<p>On each free asymmetric and each \
         torqued scene: this library's fastest stepping method (fixed-step or adaptive, no \
         exact forms) to each error level, against the fastest run of ode_solvers' Dop853 on \
         the quaternion form (seven unknowns), the integrator a physicist would reach for. \
         Where Dop853 stopped or did not reach the level, Dopri5 on the same form stands in \
         and is named. Ratio: our time over the peer's (below 1: ours is faster). Target: at \
         most 1.0x on free bodies, at most 0.5x under a torque. A step above the registry's \
         stability limit (which <code>ga-rigid simulate</code> refuses without \
         <code>allow_unstable</code>) is marked.</p>\n<table><tr><th>scene</th><th>target</th>",
    );
    for level in RACE_LEVELS {
        let _ = write!(
            out,
            "<th>≤ {level:.0e} rad: ours</th><th>peer</th><th>ratio</th>"
        );
    }
    out.push_str("</tr>\n");
    for scene in scenes {
        let goal = target(scene.kind).unwrap_or(1.0);
        let _ = write!(
            out,
            "<tr><td>{}</td><td class=\"num\">≤ {goal:.1}x</td>",
            esc(&scene.name)
        );
        for level in RACE_LEVELS {
            let pick = fastest_of(scene, level, |r| ours(r.method));
            let peer = fastest_of(scene, level, |r| r.method == Method::Dop853Quaternion)
                .or_else(|| fastest_of(scene, level, |r| r.method == Method::Dopri5Quaternion));
            match pick {
                Some(o) => {
                    let _ = write!(
                        out,
                        "<td>{} {}: {:.1} µs",
                        o.method.name(),
                        esc(&o.label()),
                        o.time_us().unwrap_or(f64::NAN)
                    );
                    if let Some(limit) = above_limit(o, scene.rate) {
                        let _ = write!(
                            out,
                            " <span class=\"note\">(h|w(0)| = {:.4} above its limit {limit}",
                            o.param * scene.rate
                        );
                        let within = fastest_of(scene, level, |r| {
                            ours(r.method) && above_limit(r, scene.rate).is_none()
                        });
                        let peer_time = peer.and_then(Measurement::time_us);
                        match within {
                            Some(w) => {
                                let t = w.time_us().unwrap_or(f64::NAN);
                                let _ = write!(
                                    out,
                                    "; within the limits: {} {}: {t:.1} µs",
                                    w.method.name(),
                                    esc(&w.label())
                                );
                                if let Some(p) = peer_time {
                                    let _ = write!(out, ", {:.2}x", t / p);
                                }
                            }
                            None => out.push_str("; none within the limits reached it"),
                        }
                        out.push_str(")</span>");
                    }
                    out.push_str("</td>");
                }
                None => out.push_str("<td>none reached it</td>"),
            }
            match peer {
                Some(p) => {
                    let _ = write!(
                        out,
                        "<td>{}: {:.1} µs</td>",
                        p.method.name(),
                        p.time_us().unwrap_or(f64::NAN)
                    );
                }
                None => out.push_str("<td>neither reached it</td>"),
            }
            match (
                pick.and_then(Measurement::time_us),
                peer.and_then(Measurement::time_us),
            ) {
                (Some(o), Some(p)) => {
                    let ratio = o / p;
                    let mark = if level == RACE_LEVELS[RACE_LEVELS.len() - 1] {
                        if ratio <= goal {
                            " met"
                        } else {
                            " missed"
                        }
                    } else {
                        ""
                    };
                    let _ = write!(out, "<td class=\"num\">{ratio:.2}x{mark}</td>");
                }
                _ => out.push_str("<td>–</td>"),
            }
        }
        out.push_str("</tr>\n");
    }
    out.push_str(
        "</table>\n<p class=\"note\">The target is judged at the tightest level. One report \
         run on one machine; the race bench (<code>cargo bench -p ga-benches --bench \
         race</code>) repeats it with medians of whole runs.</p>\n",
    );
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::{fixtures, Size};

    /// A finished run of `method` at step (or tolerance) `param` in `time_us` with largest
    /// attitude error `attitude`.
    fn row(method: Method, param: f64, time_us: f64, attitude: f64) -> Measurement {
        fixtures::run(method, param, 100, time_us, attitude)
    }

    fn report(kind: SceneKind, rows: Vec<Measurement>) -> Report {
        Report {
            size: Size::Quick,
            cpu: "a test CPU".into(),
            scenes: vec![fixtures::scene(kind, rows)],
            long_runs: Vec::new(),
            engine_runs: Vec::new(),
            nd_scenes: Vec::new(),
        }
    }

    fn page(report: &Report) -> String {
        let mut out = String::new();
        race_section(&mut out, report);
        out
    }

    /// Under a torque the target is half Dop853's time: 20 against 50 us is 0.40x, met;
    /// the exact form and the other peers never stand in for either side; the ratio at
    /// 1e-6 takes each side's fastest run at that level.
    #[test]
    fn a_torqued_scene_is_judged_against_dop853_at_half_its_time() {
        let rows = vec![
            row(Method::Adams10, 0.01, 20.0, 1e-11),
            row(Method::Adams10, 0.02, 8.0, 1e-7),
            row(Method::Exact, 0.1, 1.0, 1e-12),
            row(Method::Dop853Quaternion, 1e-12, 50.0, 1e-11),
            row(Method::Dop853Quaternion, 1e-8, 16.0, 1e-7),
            row(Method::Dopri5Quaternion, 1e-12, 30.0, 1e-11),
            row(Method::SpiersMomentum, 0.001, 2.0, 1e-11),
        ];
        let html = page(&report(SceneKind::Torqued, rows));
        assert!(html.contains("≤ 0.5x"), "{html}");
        assert!(html.contains("adams-10 h=1.0e-2: 20.0 µs"), "{html}");
        assert!(html.contains("dop853-quaternion: 50.0 µs"), "{html}");
        assert!(html.contains("0.40x met"), "{html}");
        assert!(html.contains("0.50x</td>"), "{html}");
        assert!(!html.contains("<td>exact"), "{html}");
        assert!(!html.contains("<td>spiers"), "{html}");
    }

    /// Where Dop853 did not reach the level, Dopri5 stands in and is named; a ratio above
    /// the target is "missed"; a fixed step above the registry's limit is marked, with the
    /// fastest run within the limits beside it.
    #[test]
    fn dopri5_stands_in_and_a_step_above_the_limit_is_marked() {
        let limit = step_limit(Method::Adams12).unwrap();
        let rows = vec![
            row(Method::Adams12, 2.0 * limit, 40.0, 1e-11),
            row(Method::Rk4, 0.01, 80.0, 1e-11),
            row(Method::Dopri5Quaternion, 1e-12, 50.0, 1e-11),
        ];
        let html = page(&report(SceneKind::Torqued, rows));
        assert!(html.contains("dopri5-quaternion: 50.0 µs"), "{html}");
        assert!(html.contains("0.80x missed"), "{html}");
        assert!(html.contains("above its limit"), "{html}");
        assert!(
            html.contains("within the limits: rk4 h=1.0e-2: 80.0 µs, 1.60x"),
            "{html}"
        );
        let rows = vec![
            row(Method::Adams12, limit / 2.0, 40.0, 1e-11),
            row(Method::Dopri5Quaternion, 1e-12, 50.0, 1e-11),
        ];
        assert!(!page(&report(SceneKind::Torqued, rows)).contains("above its limit"));
    }

    /// Free bodies race to 1.0x; scenes of other kinds have no race row.
    #[test]
    fn only_free_asymmetric_and_torqued_scenes_race() {
        let rows = || {
            vec![
                row(Method::Rk4, 0.1, 9.0, 1e-11),
                row(Method::Dop853Quaternion, 1e-12, 10.0, 1e-11),
            ]
        };
        let html = page(&report(SceneKind::FreeAsymmetric, rows()));
        assert!(
            html.contains("≤ 1.0x") && html.contains("0.90x met"),
            "{html}"
        );
        assert!(page(&report(SceneKind::Symmetric, rows())).is_empty());
        assert!(page(&report(SceneKind::StiffOrExtreme, rows())).is_empty());
    }
}
