//! One run of one method on a four-dimensional scene: the states at the sample times, the
//! attitude error and energy drift against a reference that is not the method itself,
//! and the 3D report's timing rule ([`crate::report::timed`]).

use ga_core::f64::g4::Rotor;

use ga_rigid::error::Error;
use ga_rigid::nd::{Integrator, State, G4};
use ga_rigid::registry::StepKind;

use super::methods::{fixed_step, lie_dop853, lie_dopri5, NdMethod};
use super::scenes::NdTestScene;
use crate::report::{sample_times, TIGHTEST_TOL};

/// The angle between two attitudes of G4: `sqrt(theta_1^2 + theta_2^2)`, the two rotation
/// angles (each in `[-pi, pi]`) of the relative rotation `D = ~R_ref R`, which is
/// `2 |log(+-D)|` for the sign with the shorter logarithm, the geodesic distance on
/// SO(4). For a simple rotation it is the 3D report's angle.
///
/// `D = s + B + p I` splits into its two isoclinic halves by `(1 +- I)/2` (`I I = 1`, and
/// `I` commutes with `D`): for `D = exp(a P + b Q)`, `P Q = I` unit planes, the halves'
/// scalars are `s +- p = cos(a -+ b)` and their bivectors' norms `|B +- I B| / sqrt 2 =
/// |sin(a -+ b)|`. So `u = |a - b|` and `v = |a + b|` come from two `atan2`s (accurate at
/// small angles, where an `acos` is not), and `theta_1^2 + theta_2^2 = 4 (a^2 + b^2) =
/// 2 (u^2 + v^2)`. `-D` is the same rotation, with `u, v` turned into `pi - u, pi - v`:
/// the smaller of the two sums is taken. Both halves' signs are not free: `I` itself
/// (`x -> -x`, both angles pi) is `pi sqrt 2` from the identity.
#[must_use]
pub fn attitude_error(rotor: Rotor, reference: Rotor) -> f64 {
    let d = reference.reverse() * rotor;
    let b = Rotor::from(d.grade2());
    let ib = (Rotor::E1234 * b).grade2();
    let half = std::f64::consts::FRAC_1_SQRT_2;
    let u = ((b.grade2() + ib).norm() * half).atan2(d.s + d.e1234);
    let v = ((b.grade2() - ib).norm() * half).atan2(d.s - d.e1234);
    let (u, v) = if u + v > std::f64::consts::PI {
        (std::f64::consts::PI - u, std::f64::consts::PI - v)
    } else {
        (u, v)
    };
    (2.0 * (u * u + v * v)).sqrt()
}

/// The errors of a run against a reference over the samples.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct NdErrors {
    /// The largest [`attitude_error`] over the samples (rad).
    pub attitude_max: f64,
    /// The largest `|Omega_B - Omega_ref|` over the samples, relative to `|Omega_B(0)|`.
    pub omega_max: f64,
    /// The largest `|E(t) - E(0)| / E(0)` of the run itself over the samples: the free
    /// body's energy is constant.
    pub energy_max: f64,
}

/// The errors of `states` against `reference` (both at the scene's sample times).
#[must_use]
pub fn errors(scene: &NdTestScene, states: &[State<G4>], reference: &[State<G4>]) -> NdErrors {
    let e0 = scene.body.energy(scene.initial.omega);
    let rate = scene.rate();
    // `max` would drop a NaN: keep it, it is the news.
    let worse = |a: f64, b: f64| if a.is_nan() || a > b { a } else { b };
    let mut out = NdErrors::default();
    for (state, r) in states.iter().zip(reference) {
        let attitude = attitude_error(state.rotor, r.rotor);
        let omega = (state.omega - r.omega).norm() / rate;
        let energy = (scene.body.energy(state.omega) - e0).abs() / e0.abs();
        out.attitude_max = worse(attitude, out.attitude_max);
        out.omega_max = worse(omega, out.omega_max);
        out.energy_max = worse(energy, out.energy_max);
    }
    out
}

/// A run's states at the sample times and the steps it took.
pub struct NdRun {
    /// The states at [`sample_times`].
    pub states: Vec<State<G4>>,
    /// Fixed steps, accepted adaptive steps, or evaluations of the closed form.
    pub steps: u64,
}

/// Advance from the scene's start through each sample time, keeping the states there.
fn through(
    integrator: &mut dyn Integrator<G4>,
    scene: &NdTestScene,
) -> Result<Vec<State<G4>>, Error> {
    let (mut t, mut state) = (0.0, scene.initial);
    let mut states = Vec::new();
    for sample in sample_times(scene.t_end) {
        state = integrator.advance(&scene.body, t, state, sample - t)?;
        t = sample;
        states.push(state);
    }
    Ok(states)
}

/// One run of `method` at `setting` (a step, a tolerance, or the sample spacing).
pub fn run_once(scene: &NdTestScene, method: NdMethod, setting: f64) -> Result<NdRun, Error> {
    match method {
        NdMethod::ClosedForm => {
            let closed = scene.closed_form().ok_or_else(|| {
                Error::invalid(
                    "closed-form",
                    "the body's second moments are not (a, a, b, b)",
                )
            })?;
            let times = sample_times(scene.t_end);
            Ok(NdRun {
                steps: times.len() as u64,
                states: times.iter().map(|&t| closed.at(scene.initial, t)).collect(),
            })
        }
        NdMethod::LieDop853 => {
            let mut integrator = lie_dop853(setting)?;
            let states = through(&mut integrator, scene)?;
            Ok(NdRun {
                states,
                steps: integrator.steps().0,
            })
        }
        NdMethod::LieDopri5 => {
            let mut integrator = lie_dopri5(setting)?;
            let states = through(&mut integrator, scene)?;
            Ok(NdRun {
                states,
                steps: integrator.steps().0,
            })
        }
        _ => {
            // A hair above h, so that rounding in dt / h never adds a sub-step: every
            // sample interval is a whole number of steps of exactly h.
            let mut integrator = fixed_step(method, setting * (1.0 + 1e-9))?;
            Ok(NdRun {
                states: through(integrator.as_mut(), scene)?,
                steps: (scene.t_end / setting).round() as u64,
            })
        }
    }
}

/// A solution at the sample times that others are measured against.
pub struct NdReference {
    /// What it is, for the page.
    pub label: String,
    /// The method that produced it: a run of this method is measured against the other
    /// reference, never against itself.
    pub method: NdMethod,
    /// The states at [`sample_times`].
    pub states: Vec<State<G4>>,
}

/// The fine step of the Rk4 check: `h |w(0)| = 1e-3`.
const CHECK_STEP_RATE: f64 = 1e-3;

/// The two references of a scene. The symmetric body's are its closed form and
/// `lie-dop853` at tol 1e-13; the others' are `lie-dop853` at tol 1e-13 and classical
/// RK4 at `h |w(0)| = 1e-3`, a method of another kind (no Lie algebra, no error control).
pub fn references(scene: &NdTestScene) -> Result<(NdReference, NdReference), Error> {
    let dop853 = NdReference {
        label: format!("lie-dop853 at tol {TIGHTEST_TOL:.0e}"),
        method: NdMethod::LieDop853,
        states: run_once(scene, NdMethod::LieDop853, TIGHTEST_TOL)?.states,
    };
    if scene.closed_form().is_some() {
        let closed = NdReference {
            label: "the closed form of the symmetric body (docs/derivations/symmetric-body-4d.md)"
                .into(),
            method: NdMethod::ClosedForm,
            states: run_once(scene, NdMethod::ClosedForm, 0.0)?.states,
        };
        return Ok((closed, dop853));
    }
    let h = CHECK_STEP_RATE / scene.rate();
    // Whole steps between samples: the step count is a multiple of the sample count.
    let samples = sample_times(scene.t_end).len() as f64;
    let steps = ((scene.t_end / h / samples).ceil() * samples).max(samples);
    let h = scene.t_end / steps;
    let rk4 = NdReference {
        label: format!("rk4 at h = {h:.2e} (h |w(0)| = {:.0e})", h * scene.rate()),
        method: NdMethod::Rk4,
        states: run_once(scene, NdMethod::Rk4, h)?.states,
    };
    Ok((dop853, rk4))
}

/// The reference's distance from published values: the largest component difference of
/// `R` and of `Omega_B` at the published time (a sample time).
#[must_use]
pub fn published_check(scene: &NdTestScene, reference: &NdReference) -> Option<(f64, f64)> {
    let published = scene.published?;
    let times = sample_times(scene.t_end);
    let k = times.iter().position(|&t| t == published.t)?;
    let state = reference.states[k];
    let max = |a: &[f64], b: &[f64]| {
        a.iter()
            .zip(b)
            .map(|(x, y)| (x - y).abs())
            .fold(0.0, f64::max)
    };
    Some((
        max(&state.rotor.to_array(), &published.rotor),
        max(&state.omega.to_array(), &published.omega),
    ))
}

/// The growth of a perturbation of a steady double rotation along the reference: the
/// size of `Omega_B` outside `planes` at t = 0 and the largest over the samples, with its
/// time.
#[must_use]
pub fn perturbation_growth(
    scene: &NdTestScene,
    reference: &NdReference,
    planes: [usize; 2],
) -> (f64, f64, f64) {
    let off = |omega: ga_core::f64::g4::Bivector| {
        let mut rest = omega;
        for k in planes {
            rest[k] = 0.0;
        }
        rest.norm()
    };
    let (mut largest, mut at) = (0.0, 0.0);
    for (state, t) in reference.states.iter().zip(sample_times(scene.t_end)) {
        let size = off(state.omega);
        if size > largest {
            (largest, at) = (size, t);
        }
    }
    (off(scene.initial.omega), largest, at)
}

/// Whether a method's kind takes a step count (for the steps of a failed run).
#[must_use]
pub fn nominal_steps(scene: &NdTestScene, method: NdMethod, setting: f64) -> u64 {
    match method.step_kind() {
        StepKind::Fixed => (scene.t_end / setting).round() as u64,
        StepKind::Adaptive => 0,
        StepKind::AtSamples => sample_times(scene.t_end).len() as u64,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ga_core::f64::g4::Bivector;
    use std::f64::consts::PI;

    /// The angle of a simple turn is the 3D angle; a double rotation by `(theta_1,
    /// theta_2)` is `hypot(theta_1, theta_2)` from the identity, whatever the planes and
    /// the rotor's sign; `x -> -x` is `pi sqrt 2` away.
    #[test]
    fn the_attitude_error_is_the_hypotenuse_of_the_two_rotation_angles() {
        let turn = Bivector::new(0.3, -0.2, 0.5, 0.1, 0.7, -0.4).exp();
        let in_planes = |a: f64, b: f64| {
            // exp(-theta/2 e12) turns by theta in e12; turned into general planes.
            let r = Bivector::new(-0.5 * a, 0.0, 0.0, 0.0, 0.0, -0.5 * b).exp();
            turn * r * turn.reverse()
        };
        for (a, b) in [(1e-9, 0.0), (0.3, 0.0), (0.3, 1.2), (2.5, -0.7), (3.0, 3.0)] {
            let r = in_planes(a, b);
            let expected = f64::hypot(a, b);
            for sign in [1.0, -1.0] {
                let e = attitude_error(r * sign, Rotor::ONE);
                assert!(
                    (e - expected).abs() < 1e-12 * (1.0 + expected),
                    "{a} {b}: {e}"
                );
                let e = attitude_error(turn * r * sign, turn);
                assert!(
                    (e - expected).abs() < 1e-12 * (1.0 + expected),
                    "{a} {b}: {e}"
                );
            }
        }
        let minus_one = attitude_error(Rotor::E1234, Rotor::ONE);
        assert!((minus_one - PI * 2f64.sqrt()).abs() < 1e-15, "{minus_one}");
        // Angles beyond pi come back the short way: a turn by 2 pi - x is x away.
        let e = attitude_error(in_planes(2.0 * PI - 0.25, 0.0), Rotor::ONE);
        assert!((e - 0.25).abs() < 1e-12, "{e}");
    }
}
