//! What the page says about the measurements: the fastest method at each error level,
//! each method's observed order, and its stability verdict.

use ga_rigid::registry::{Method, StepKind};

use super::{Measurement, SceneResult};

/// The attitude errors (rad, largest over the run) the page asks each method to reach.
pub const ERROR_LEVELS: [f64; 5] = [1e-2, 1e-4, 1e-6, 1e-8, 1e-10];

/// An error (rad or relative) above which a run has lost the solution.
const LOST: f64 = 0.1;

/// Errors below this are rounding, not truncation: left out of the order fit whatever
/// the references' agreement.
const ROUNDING_FLOOR: f64 = 1e-12;

/// The fastest row (by median time) whose largest attitude error is at most `level`.
#[must_use]
pub fn fastest_at(scene: &SceneResult, level: f64) -> Option<&Measurement> {
    fastest_of(scene, level, |_| true)
}

/// The fastest of the rows `eligible` picks whose largest attitude error is at most
/// `level`.
pub fn fastest_of(
    scene: &SceneResult,
    level: f64,
    eligible: impl Fn(&Measurement) -> bool,
) -> Option<&Measurement> {
    scene
        .rows
        .iter()
        .filter(|r| eligible(r))
        .filter(|r| r.errors.is_some_and(|e| e.attitude_max <= level))
        .filter(|r| r.time_us().is_some())
        .min_by(|a, b| {
            a.time_us()
                .unwrap_or(0.0)
                .total_cmp(&b.time_us().unwrap_or(0.0))
        })
}

/// The error below which a scene's runs are not resolved: ten times the disagreement of
/// its two references (the page prints it), and never below rounding (1e-12).
#[must_use]
pub fn error_floor(scene: &SceneResult) -> f64 {
    (10.0 * scene.check.errors.attitude_max).max(ROUNDING_FLOOR)
}

/// A method's runs that an order can be fitted to: (log mean step, log largest attitude
/// error) for errors above the scene's [`error_floor`] and below 0.1.
fn order_points(scene: &SceneResult, method: Method) -> Vec<(f64, f64)> {
    let floor = error_floor(scene);
    scene
        .rows
        .iter()
        .filter(|r| r.method == method)
        .filter_map(|r| {
            let e = r.errors?.attitude_max;
            (e > floor && e < LOST && e.is_finite())
                .then(|| (r.mean_step(scene.t_end).ln(), e.ln()))
        })
        .collect()
}

/// The fewest runs between the floor and 0.1 an order is fitted to.
pub const MIN_ORDER_POINTS: usize = 3;

/// What the page can say of a method's order on a scene.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Order {
    /// The fitted slope, from this many runs.
    Fitted(f64, usize),
    /// Only this many runs lie between the floor and 0.1: no fit.
    TooFewPoints(usize),
}

/// The least-squares slope of log(largest attitude error) against log(mean step) over a
/// method's runs whose error lies between the scene's [`error_floor`] and 0.1, when there
/// are at least [`MIN_ORDER_POINTS`] of them.
#[must_use]
pub fn order(scene: &SceneResult, method: Method) -> Order {
    fit_order(&order_points(scene, method))
}

/// The least-squares slope of `(log step, log error)` points, when there are at least
/// [`MIN_ORDER_POINTS`] of them: the fit of [`order`], for any runs.
#[must_use]
pub fn fit_order(points: &[(f64, f64)]) -> Order {
    if points.len() < MIN_ORDER_POINTS {
        return Order::TooFewPoints(points.len());
    }
    let n = points.len() as f64;
    let (mx, my) = points
        .iter()
        .fold((0.0, 0.0), |(a, b), (x, y)| (a + x / n, b + y / n));
    let (sxy, sxx) = points.iter().fold((0.0, 0.0), |(a, b), (x, y)| {
        (a + (x - mx) * (y - my), b + (x - mx) * (x - mx))
    });
    if sxx > 0.0 {
        Order::Fitted(sxy / sxx, points.len())
    } else {
        Order::TooFewPoints(1)
    }
}

/// The fitted order of [`order`], `None` when there are too few runs to fit.
#[must_use]
pub fn observed_order(scene: &SceneResult, method: Method) -> Option<f64> {
    match order(scene, method) {
        Order::Fitted(p, _) => Some(p),
        Order::TooFewPoints(_) => None,
    }
}

/// The median cost of one step (or evaluation) over a method's finished runs, in ns: the
/// middle one, or the mean of the two middle ones of an even number.
#[must_use]
pub fn cost_per_step_ns(scene: &SceneResult, method: Method) -> Option<f64> {
    let mut costs: Vec<f64> = scene
        .rows
        .iter()
        .filter(|r| r.method == method && r.steps > 0)
        .filter_map(|r| Some(r.time_us()? * 1e3 / r.steps as f64))
        .collect();
    costs.sort_by(f64::total_cmp);
    let half = costs.len() / 2;
    match costs.len() {
        0 => None,
        n if n % 2 == 1 => Some(costs[half]),
        _ => Some(0.5 * (costs[half - 1] + costs[half])),
    }
}

/// Whether a method kept the solution at the steps it ran: accurate (attitude and momentum
/// errors below 0.1 over the whole run), inaccurate, or failed, by `h |w|`.
#[must_use]
pub fn verdict(scene: &SceneResult, method: Method) -> String {
    let rows: Vec<&Measurement> = scene.rows.iter().filter(|r| r.method == method).collect();
    if rows.is_empty() {
        return "not run".to_string();
    }
    let good = |r: &Measurement| {
        r.errors
            .is_some_and(|e| e.attitude_max < LOST && e.momentum_max < LOST)
    };
    if method.step_kind() == StepKind::AtSamples {
        return match rows.iter().find_map(|r| r.failure.as_ref()) {
            Some(why) => format!("fails: {why}"),
            None if rows.iter().all(|r| good(r)) => {
                "no steps: the solution is evaluated at each sample".to_string()
            }
            None => "evaluated at each sample, but off the reference by more than 0.1".to_string(),
        };
    }
    let hw = |r: &Measurement| r.mean_step(scene.t_end) * scene.rate;
    // An adaptive method's runs differ by tolerance, not step: its h|w| is the mean step's.
    let (step, steps) = if method.step_kind() == StepKind::Adaptive {
        ("mean h|w|", "tolerance")
    } else {
        ("h|w|", "step")
    };
    let bad: Vec<&&Measurement> = rows.iter().filter(|r| !good(r)).collect();
    let coarsest_good = rows
        .iter()
        .filter(|r| good(r))
        .map(|r| hw(r))
        .fold(f64::NAN, f64::max);
    if bad.is_empty() {
        return format!(
            "keeps the solution at every {steps} tried, up to {step} = {coarsest_good:.3}"
        );
    }
    let failed = bad.iter().filter(|r| r.failure.is_some()).count();
    let least_bad = bad.iter().map(|r| hw(r)).fold(f64::NAN, f64::min);
    let most_bad = bad.iter().map(|r| hw(r)).fold(f64::NAN, f64::max);
    let what = if failed == bad.len() {
        "fails"
    } else if failed == 0 {
        "loses the solution (error > 0.1)"
    } else {
        "fails or loses the solution"
    };
    if coarsest_good.is_nan() {
        if bad.len() == 1 {
            format!("{what} at the one {steps} tried ({step} = {least_bad:.3})")
        } else {
            format!("{what} at every {steps} tried ({step} from {least_bad:.3} to {most_bad:.3})")
        }
    } else {
        format!("{what} from {step} = {least_bad:.3}; keeps it up to {step} = {coarsest_good:.3}")
    }
}

/// The kinds of scene the page's summary answers for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum SceneKind {
    /// A free body with three distinct moments.
    FreeAsymmetric,
    /// A free body with two moments within 1e-6 of each other, not equal.
    NearSymmetric,
    /// A free body with two equal moments.
    Symmetric,
    /// A body under a torque.
    Torqued,
    /// The stiff and extreme cases (needles, a flat disk, huge and tiny scales).
    StiffOrExtreme,
    /// One long run: not part of the summary (one setting a method).
    Long,
}

impl SceneKind {
    /// The kind's name on the page.
    #[must_use]
    pub fn label(self) -> &'static str {
        match self {
            SceneKind::FreeAsymmetric => "free, asymmetric",
            SceneKind::NearSymmetric => "free, near-symmetric",
            SceneKind::Symmetric => "free, symmetric",
            SceneKind::Torqued => "torqued (heavy top)",
            SceneKind::StiffOrExtreme => "stiff or extreme",
            SceneKind::Long => "long run",
        }
    }
}

/// The kind of a measured scene, from its sweep and its body.
#[must_use]
pub fn scene_kind(scene: &super::TestScene) -> SceneKind {
    use super::Sweep;
    match scene.sweep {
        Sweep::Long => return SceneKind::Long,
        Sweep::Stress => return SceneKind::StiffOrExtreme,
        Sweep::WorkPrecision => {}
    }
    if scene.body.has_torque() {
        return SceneKind::Torqued;
    }
    if scene.body.symmetry_axis(1e-12).is_some() {
        return SceneKind::Symmetric;
    }
    if scene.body.symmetry_axis(1e-6).is_some() {
        return SceneKind::NearSymmetric;
    }
    SceneKind::FreeAsymmetric
}

/// One cell of the summary: the fastest method that reaches an error level on every scene
/// of a kind, and its time summed over those scenes.
#[derive(Clone, Debug, PartialEq)]
pub struct Pick {
    /// The method.
    pub method: Method,
    /// The sum over the kind's scenes of its fastest run that reaches the level (µs).
    pub time_us: f64,
}

/// The fastest method of those `eligible` that reaches `level` on every one of `scenes`,
/// by the sum over the scenes of its fastest run at that level.
#[must_use]
pub fn fastest_over(
    scenes: &[&SceneResult],
    level: f64,
    eligible: impl Fn(Method) -> bool,
) -> Option<Pick> {
    let mut best: Option<Pick> = None;
    for method in Method::ALL.into_iter().filter(|&m| eligible(m)) {
        let mut total = 0.0;
        let mut everywhere = !scenes.is_empty();
        for scene in scenes {
            let fastest = scene
                .rows
                .iter()
                .filter(|r| r.method == method)
                .filter(|r| r.errors.is_some_and(|e| e.attitude_max <= level))
                .filter_map(Measurement::time_us)
                .min_by(f64::total_cmp);
            match fastest {
                Some(t) => total += t,
                None => everywhere = false,
            }
        }
        if everywhere && best.as_ref().is_none_or(|b| total < b.time_us) {
            best = Some(Pick {
                method,
                time_us: total,
            });
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::fixtures;

    /// A finished run of `method` with `steps` steps over `t_end = 10` in `time_us` and
    /// largest attitude error `attitude`.
    fn row(method: Method, steps: u64, time_us: f64, attitude: f64) -> Measurement {
        fixtures::run(method, 10.0 / steps as f64, steps, time_us, attitude)
    }

    fn scene(rows: Vec<Measurement>) -> SceneResult {
        fixtures::scene(SceneKind::FreeAsymmetric, rows)
    }

    /// "Reaches the level" includes a run whose error is exactly the level.
    #[test]
    fn a_run_exactly_at_a_level_reaches_it() {
        let scene = scene(vec![
            row(Method::Rk4, 100, 50.0, 1e-8),
            row(Method::Splitting, 100, 5.0, 1e-6),
        ]);
        assert_eq!(fastest_at(&scene, 1e-6).unwrap().method, Method::Splitting);
    }

    /// The median of an even number of costs is the mean of the two middle ones: costs
    /// 1, 2, 4 and 8 ns a step (given out of order) have the median 3 ns.
    #[test]
    fn the_median_cost_of_an_even_number_of_runs_is_the_mean_of_the_middle_two() {
        let scene = scene(vec![
            row(Method::Rk4, 1000, 4.0, 1e-3),
            row(Method::Rk4, 1000, 1.0, 1e-3),
            row(Method::Rk4, 1000, 8.0, 1e-3),
            row(Method::Rk4, 1000, 2.0, 1e-3),
            row(Method::Splitting, 1000, 100.0, 1e-3),
        ]);
        let median = cost_per_step_ns(&scene, Method::Rk4).unwrap();
        assert!((median - 3.0).abs() < 1e-9, "{median}");
        let odd = scene.rows[1..].to_vec();
        let median = cost_per_step_ns(&self::scene(odd), Method::Rk4).unwrap();
        assert!((median - 2.0).abs() < 1e-9, "{median}");
        assert_eq!(
            cost_per_step_ns(&self::scene(Vec::new()), Method::Rk4),
            None
        );
    }
}
