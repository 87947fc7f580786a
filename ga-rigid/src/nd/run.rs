//! Running a 2D or 4D scene: the methods the n-dimensional body has, named as in the 3D
//! registry ([`crate::registry::Method`]), under the 3D runs' rule book (the step control
//! of [`Method::given_step`], the default step of [`crate::limits::default_step`], the
//! limits of [`crate::limits::plan`] with a simpler bound on the angular speed), and the
//! CSV rows.

use super::algebra::{Algebra, G2, G4};
use super::closed_form::{planar, SymmetricBody4};
use super::integrator::Integrator;
use super::scene::{BodyScene, NdScene};
use super::state::State;
use super::{ImplicitMidpoint, LieDop853, LieRk4, PlaneSplitting, Rk4};
use crate::error::{num, num_short, Error};
use crate::limits::{Limits, StepSource, DEFAULT_STEPS_PER_PERIOD, DEFAULT_TOLERANCE};
use crate::registry::{
    Dimensions, Method, Step, StepKind, DOPRI_ABSOLUTE_TOLERANCE_RATIO, METHODS,
};

/// The CSV header of a 2D run, without the line break.
pub const HEADER_2D: &str = "t,r_s,r_e12,w_e12,energy,l_e12";

/// The CSV header of a 4D run: the rotor, `Omega_B` (`w`), the kinetic energy and the
/// space momentum `L = R I(Omega_B) ~R` (`l`), bivectors in canonical order.
pub const HEADER_4D: &str = "t,r_s,r_e12,r_e13,r_e14,r_e23,r_e24,r_e34,r_e1234,\
w_e12,w_e13,w_e14,w_e23,w_e24,w_e34,energy,\
l_e12,l_e13,l_e14,l_e23,l_e24,l_e34";

/// The methods a 2D or 4D scene runs with: those of the registry's table that run in any
/// dimension, in the table's order.
pub fn methods() -> impl Iterator<Item = Method> {
    METHODS
        .iter()
        .filter(|info| info.dimensions == Dimensions::Any)
        .map(|info| info.method)
}

/// The header of a run in `dimension` (2 or 4).
#[must_use]
pub fn header(dimension: usize) -> &'static str {
    if dimension == 2 {
        HEADER_2D
    } else {
        HEADER_4D
    }
}

/// Refuse a method the n-dimensional body does not have, naming it and the dimension.
pub fn check_method(method: Method, dimension: usize) -> Result<(), Error> {
    if method.info().dimensions == Dimensions::Any {
        return Ok(());
    }
    let names: Vec<&str> = methods().map(Method::name).collect();
    Err(Error::invalid(
        "method",
        format!(
            "{} is 3D-only; dimension {dimension} takes {}",
            method.name(),
            names.join(", ")
        ),
    ))
}

/// A run that passed its checks: the step control, where it came from, and its estimated
/// steps and seconds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plan {
    /// The step control to run with.
    pub step: Step,
    /// Where the step control came from.
    pub source: StepSource,
    /// The estimated number of steps (or evaluations).
    pub steps: f64,
    /// The estimated seconds in a release build.
    pub seconds: f64,
}

/// What the limits need of a scene: its largest angular speed, run and column count.
struct Shape {
    speed: f64,
    torque: bool,
    t_end: f64,
    samples: f64,
    columns: usize,
    planes: usize,
}

/// A bound on `|Omega_B|` over the run. Without torque `|M|` and the energy are constant,
/// and `|Omega|^2 <= min(2 E, |M|^2 / I_min) / I_min` with `I_min` the smallest plane
/// moment; a constant torque `T` grows `|M|` by at most `|T| t_end`.
fn speed_bound<A: Algebra>(scene: &BodyScene<A>) -> f64 {
    let body = &scene.body;
    let state = scene.principal_state();
    let moments = body.plane_moments();
    let planes = A::PLANES.len();
    let smallest = (0..planes)
        .map(|k| moments[k])
        .fold(f64::INFINITY, f64::min);
    let norm = |b: A::Bivector| (0..planes).map(|k| b[k] * b[k]).sum::<f64>().sqrt();
    let momentum = norm(body.body_momentum(state.omega));
    let torque = norm(body.torque(0.0, &state));
    if torque > 0.0 {
        (momentum + torque * scene.run.t_end) / smallest
    } else {
        let by_energy = (2.0 * body.energy(state.omega) / smallest).sqrt();
        by_energy.min(momentum / smallest)
    }
}

fn shape_of(scene: &NdScene) -> Shape {
    fn of<A: Algebra>(s: &BodyScene<A>) -> Shape {
        Shape {
            speed: speed_bound(s),
            torque: s.body.has_torque(),
            t_end: s.run.t_end,
            samples: s.run.samples as f64,
            columns: 2 + A::ROTOR_LEN + 2 * A::PLANES.len(),
            planes: A::PLANES.len(),
        }
    }
    match scene {
        NdScene::Planar(s) => of(s),
        NdScene::Four(s) => of(s),
    }
}

/// The step control when none is given, as [`crate::limits::default_step`]: the period
/// of the fastest rotation over 200, `t_end / 200` at rest, the default tolerance.
#[must_use]
pub fn default_step(scene: &NdScene, method: Method) -> (Step, StepSource) {
    let shape = shape_of(scene);
    match method.step_kind() {
        StepKind::Fixed => {
            let period = std::f64::consts::TAU / shape.speed;
            if period.is_finite() && period > 0.0 {
                (
                    Step::Fixed(period / DEFAULT_STEPS_PER_PERIOD),
                    StepSource::Default("the period 2 pi / |w|max over 200"),
                )
            } else {
                (
                    Step::Fixed(shape.t_end / DEFAULT_STEPS_PER_PERIOD),
                    StepSource::Default("t_end / 200 for a body at rest"),
                )
            }
        }
        StepKind::Adaptive => (
            Step::Tolerance(DEFAULT_TOLERANCE),
            StepSource::Default("the default relative tolerance"),
        ),
        StepKind::AtSamples => (Step::AtSamples, StepSource::Given),
    }
}

/// Check a run before it starts, in the order of [`crate::limits::plan`]: the method, the
/// step control, the phase rounding loses, the stability of a fixed step, the steps, the
/// output and the time, with the 3D messages.
pub fn plan(
    scene: &NdScene,
    method: Method,
    given: Option<Step>,
    limits: &Limits,
) -> Result<Plan, Error> {
    check_method(method, scene.dimension())?;
    let (step, source) = match given {
        Some(step) => (step, StepSource::Given),
        None => default_step(scene, method),
    };
    let shape = shape_of(scene);
    if limits.max_phase_error.is_nan() || limits.max_phase_error <= 0.0 {
        return Err(Error::invalid(
            "max_phase_error",
            format!(
                "the bound must be positive (infinity turns the check off), got {}",
                num(limits.max_phase_error)
            ),
        ));
    }
    let phase = shape.speed * shape.t_end * f64::EPSILON;
    if phase.is_nan() || phase > limits.max_phase_error {
        return Err(Error::invalid(
            "run.t_end",
            format!(
                "t_end = {} at |w|max = {} loses about {phase:.1e} rad of attitude to rounding \
                 (|w|max t_end eps), above the bound {}; shorten the run or raise \
                 max_phase_error",
                num_short(shape.t_end),
                num_short(shape.speed),
                num_short(limits.max_phase_error)
            ),
        ));
    }
    if let (Step::Fixed(h), Some(limit), false) = (
        step,
        method.stable_step_rate(shape.torque),
        limits.allow_unstable,
    ) {
        crate::limits::stable_step(method, h, shape.speed, limit)?;
    }
    let steps = match step {
        Step::Fixed(h) => shape.t_end / h + shape.samples,
        Step::Tolerance(tol) => shape.t_end * shape.speed * tol.powf(-0.2) + shape.samples,
        Step::AtSamples => shape.samples,
    };
    let (field, what) = match step {
        Step::Fixed(h) => ("dt", format!("a step of {}", num(h))),
        Step::Tolerance(tol) => ("tol", format!("a tolerance of {}", num(tol))),
        Step::AtSamples => ("run.samples", "one evaluation per sample".to_string()),
    };
    if steps.is_nan() || steps > limits.max_steps as f64 {
        return Err(Error::invalid(
            field,
            format!(
                "{what} needs about {steps:.1e} steps to reach t_end = {}, above the limit {}; \
                 raise it with max_steps",
                num(shape.t_end),
                limits.max_steps
            ),
        ));
    }
    let megabytes = (shape.samples + 1.0) * (shape.columns * 25) as f64 / 1e6;
    if megabytes > limits.max_output_mb as f64 {
        return Err(Error::invalid(
            "run.samples",
            format!(
                "{} rows may take {megabytes:.0} MB of CSV, above the limit {} MB; \
                 raise it with max_output_mb",
                shape.samples, limits.max_output_mb
            ),
        ));
    }
    // The registry's cost is for the three planes of G3; a step's work grows with the
    // planes (and their brackets) at least linearly.
    let seconds = method.seconds_for(steps) * (shape.planes as f64 / 3.0).max(1.0);
    if seconds.is_nan() || seconds > limits.max_seconds as f64 {
        return Err(Error::invalid(
            field,
            format!(
                "{what} needs about {steps:.1e} steps of {} in {}D, about {} s, above the \
                 limit of {} s; raise it with max_seconds",
                method.name(),
                scene.dimension(),
                num_short(seconds),
                limits.max_seconds
            ),
        ));
    }
    Ok(Plan {
        step,
        source,
        steps,
        seconds,
    })
}

/// Run `scene` with `method` and `step` (checked by [`plan`]): one row per sample time,
/// numbers in the header's order, in the scene's frame.
pub fn run(scene: &NdScene, method: Method, step: Step) -> Result<Vec<Vec<f64>>, Error> {
    check_method(method, scene.dimension())?;
    match scene {
        NdScene::Planar(s) => run_in(s, method, step, planar_closed_form(s)),
        NdScene::Four(s) => {
            let closed = if method == Method::ClosedForm {
                Some(symmetric_closed_form(s)?)
            } else {
                None
            };
            run_in(s, method, step, closed)
        }
    }
}

/// The 2D closed form, with a constant torque too: `Omega(t) = Omega0 + T t / I`, and the
/// rotor turned by the integral `Omega0 t + T t^2 / (2 I)` (the one plane commutes).
fn planar_closed_form(scene: &BodyScene<G2>) -> Option<ClosedForm<G2>> {
    let body = scene.body.clone();
    Some(Box::new(move |s0: State<G2>, t: f64| {
        if !body.has_torque() {
            return planar(s0, t);
        }
        let rate = body.omega_rate(0.0, &s0);
        let angle = s0.omega * t + rate * (0.5 * t * t);
        State {
            rotor: s0.rotor * G2::exp(angle * -0.5),
            omega: s0.omega + rate * t,
        }
    }))
}

/// The 4D closed form of the free symmetric body, second moments `(a, a, b, b)`.
fn symmetric_closed_form(scene: &BodyScene<G4>) -> Result<ClosedForm<G4>, Error> {
    if scene.body.has_torque() {
        return Err(Error::invalid(
            "torque",
            "closed-form in 4D is for a free body: leave out [torque] or choose another method",
        ));
    }
    let closed = SymmetricBody4::new(&scene.body, 1e-12).map_err(|e| e.within("body"))?;
    Ok(Box::new(move |s0, t| closed.at(s0, t)))
}

/// The integrator of `method` at `step` for the n-dimensional body.
fn integrator<A: Algebra>(method: Method, step: Step) -> Result<Box<dyn Integrator<A>>, Error> {
    let name = method.name();
    let fixed = || match step {
        Step::Fixed(h) => Ok(h),
        _ => Err(Error::invalid(
            "dt",
            format!("method {name} takes a fixed step dt"),
        )),
    };
    let at_dt = |e: Error| e.at("dt");
    Ok(match method {
        Method::Rk4 => Box::new(Rk4::new(fixed()?).map_err(at_dt)?),
        Method::LieRk4 => Box::new(LieRk4::new(fixed()?).map_err(at_dt)?),
        Method::Midpoint => Box::new(ImplicitMidpoint::new(fixed()?).map_err(at_dt)?),
        Method::Splitting => Box::new(PlaneSplitting::new(fixed()?).map_err(at_dt)?),
        Method::LieDop853 => {
            let Step::Tolerance(tol) = step else {
                return Err(Error::invalid(
                    "tol",
                    format!("method {name} is adaptive and takes a tolerance tol"),
                ));
            };
            Box::new(
                LieDop853::new(tol, tol * DOPRI_ABSOLUTE_TOLERANCE_RATIO)
                    .map_err(|e| e.at("tol"))?,
            )
        }
        _ => {
            return Err(Error::invalid(
                "method",
                format!("{name} has no n-dimensional integrator"),
            ))
        }
    })
}

/// How a run moves from sample to sample.
enum Stepper<A: Algebra> {
    /// By a method's steps from the previous sample.
    Integrated(Box<dyn Integrator<A>>),
    /// By a closed form from the start.
    Closed(ClosedForm<A>),
}

/// A closed form: the state at `t` from the state at 0.
type ClosedForm<A> = Box<dyn Fn(State<A>, f64) -> State<A>>;

/// The sampled run in the principal frame, each row turned back into the scene's frame.
fn run_in<A: Algebra>(
    scene: &BodyScene<A>,
    method: Method,
    step: Step,
    closed: Option<ClosedForm<A>>,
) -> Result<Vec<Vec<f64>>, Error> {
    let times = scene.run.times();
    let s0 = scene.principal_state();
    let mut rows = Vec::with_capacity(times.len());
    let mut stepper = match closed {
        Some(closed) if method == Method::ClosedForm => Stepper::Closed(closed),
        _ => Stepper::Integrated(integrator::<A>(method, step)?),
    };
    let (mut t, mut state) = (0.0, s0);
    for &sample in &times {
        state = match &mut stepper {
            Stepper::Integrated(integrator) => {
                integrator.advance(&scene.body, t, state, sample - t)?
            }
            Stepper::Closed(closed) => closed(s0, sample),
        };
        t = sample;
        rows.push(row(scene, method, t, &state)?);
    }
    Ok(rows)
}

/// One row in header order from a principal-frame state, checked finite.
fn row<A: Algebra>(
    scene: &BodyScene<A>,
    method: Method,
    t: f64,
    state: &State<A>,
) -> Result<Vec<f64>, Error> {
    let body = &scene.body;
    let shown = scene.scene_state(state);
    let planes = A::PLANES.len();
    let momentum = body.space_momentum(state);
    let mut values = Vec::with_capacity(2 + A::ROTOR_LEN + 2 * planes);
    values.push(t);
    values.extend((0..A::ROTOR_LEN).map(|k| shown.rotor[k]));
    values.extend((0..planes).map(|k| shown.omega[k]));
    values.push(body.energy(state.omega));
    values.extend((0..planes).map(|k| momentum[k]));
    let header = header(A::DIMENSION);
    for (value, column) in values.iter().zip(header.split(',')) {
        if !value.is_finite() {
            return Err(Error::invalid(
                method.name(),
                format!("{column} is not finite ({value}) at t = {}", num(t)),
            ));
        }
    }
    Ok(values)
}

/// The CSV of a run in `dimension`: the header, then the rows, numbers as the 3D CSV
/// writes them ([`crate::csv::write_number`]).
#[must_use]
pub fn to_csv(dimension: usize, rows: &[Vec<f64>]) -> String {
    let mut out = String::with_capacity((rows.len() + 1) * 25 * header(dimension).len() / 4);
    out.push_str(header(dimension));
    out.push('\n');
    for row in rows {
        for (k, &x) in row.iter().enumerate() {
            if k > 0 {
                out.push(',');
            }
            crate::csv::write_number(&mut out, x);
        }
        out.push('\n');
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn headers_have_one_column_per_row_number() {
        assert_eq!(HEADER_4D.split(',').count(), 2 + 8 + 2 * 6);
        assert_eq!(HEADER_2D.split(',').count(), 2 + 2 + 2);
    }

    #[test]
    fn a_3d_only_method_is_refused_naming_it_and_the_dimension() {
        let e = check_method(Method::EulerGyroExplicit, 4).unwrap_err();
        assert_eq!(
            e.to_string(),
            "method: euler-gyro-explicit is 3D-only; dimension 4 takes closed-form, rk4, \
             lie-rk4, midpoint, splitting, lie-dop853"
        );
    }

    /// The registry's table and this module's integrators say the same: every method the
    /// table marks as running in any dimension has an n-dimensional integrator (or is the
    /// closed form), and every other is refused.
    #[test]
    fn the_table_s_dimensions_match_the_n_dimensional_integrators() {
        for info in &METHODS {
            let step = match info.kind {
                StepKind::Fixed => Step::Fixed(0.01),
                StepKind::Adaptive => Step::Tolerance(1e-8),
                StepKind::AtSamples => Step::AtSamples,
            };
            let has_integrator = integrator::<G4>(info.method, step).is_ok();
            let runs_here = check_method(info.method, 4).is_ok();
            assert_eq!(
                runs_here,
                info.dimensions == Dimensions::Any,
                "{}",
                info.name
            );
            if info.method != Method::ClosedForm {
                assert_eq!(has_integrator, runs_here, "{}", info.name);
            }
        }
        assert_eq!(methods().count(), 6);
    }
}
