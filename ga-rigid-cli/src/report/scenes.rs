//! The suite: the test models of `docs/references.md` as scenes, the stiff and extreme
//! cases, and the user's own scene files.

use ga_core::f64::g3::{Bivector, Rotor, Vector};

use ga_rigid::dynamics::{
    omega_from_vector, omega_to_vector, Gravity, GravityGradient, RigidBody, State,
};
use ga_rigid::error::Error;
use ga_rigid::exact_flow::free_body_orbit;
use ga_rigid::registry::{Method, StepKind};
use ga_rigid::scene::Scene;

use super::Size;

/// How many sample times every run is compared at (the end time included); every fixed
/// step count is a multiple of it, so the samples fall on step boundaries.
pub const SAMPLES: u64 = 25;

/// How thoroughly a scene is swept.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Sweep {
    /// A work-precision diagram: many steps and tolerances.
    WorkPrecision,
    /// A stiff or extreme case: the stated step and a few refinements.
    Stress,
    /// One long run: one step per method, and a method is left out when a short probe
    /// says a run would cost more than the budget.
    Long,
}

/// A test model: a body, a start and an end time, and the step sizes that make sense for it.
pub struct TestScene {
    /// The scene's name in the report.
    pub name: String,
    /// Where it comes from and what it stresses.
    pub source: String,
    /// The body (with its torque, if any).
    pub body: RigidBody,
    /// The state at t = 0.
    pub initial: State,
    /// The end time.
    pub t_end: f64,
    /// The coarsest number of fixed steps (a multiple of [`SAMPLES`]).
    pub coarsest_steps: u64,
    /// How thoroughly to sweep it.
    pub sweep: Sweep,
}

impl TestScene {
    /// A scene from its parts; the step count is rounded up to a multiple of [`SAMPLES`].
    pub fn new(
        name: impl Into<String>,
        source: impl Into<String>,
        body: RigidBody,
        initial: State,
        t_end: f64,
        coarsest_steps: u64,
        sweep: Sweep,
    ) -> TestScene {
        TestScene {
            name: name.into(),
            source: source.into(),
            body,
            initial,
            t_end,
            coarsest_steps: coarsest_steps.div_ceil(SAMPLES).max(1) * SAMPLES,
            sweep,
        }
    }

    /// A torque-free body with principal moments `moments` and body angular velocity `w`,
    /// starting at the identity attitude.
    pub fn free(
        name: &str,
        source: &str,
        moments: [f64; 3],
        w: [f64; 3],
        t_end: f64,
        coarsest_steps: u64,
        sweep: Sweep,
    ) -> Result<TestScene, Error> {
        let body = RigidBody::new_unphysical(moments)?;
        let initial = State {
            rotor: Rotor::ONE,
            omega: omega_from_vector(w),
        };
        Ok(TestScene::new(
            name,
            source,
            body,
            initial,
            t_end,
            coarsest_steps,
            sweep,
        ))
    }

    /// A user's scene file (the `simulate` format), run over its own `t_end` with a
    /// coarsest step of half a radian at the initial rate.
    pub fn from_scene(name: &str, scene: &Scene) -> Result<TestScene, Error> {
        let body = scene.principal_body()?;
        let initial = scene.principal_state();
        let t_end = scene.run.t_end;
        let turn = t_end * initial.omega.norm();
        // At least 50 steps; at most 10^6 for the coarsest setting.
        let steps = ((turn / 0.5).ceil()).clamp(50.0, 1e6) as u64;
        Ok(TestScene::new(
            name,
            format!(
                "user scene; moments {:?}, w(0) = {:?}{}",
                body.moments(),
                omega_to_vector(initial.omega),
                if body.has_torque() { ", gravity" } else { "" }
            ),
            body,
            initial,
            t_end,
            steps,
            Sweep::WorkPrecision,
        ))
    }

    /// The size of the initial body angular velocity, for `h |w|`.
    #[must_use]
    pub fn rate(&self) -> f64 {
        self.initial.omega.norm()
    }

    /// The methods that apply to this scene, and the ones left out with the reason.
    #[must_use]
    pub fn methods(&self) -> (Vec<Method>, Vec<(Method, String)>) {
        let mut run = Vec::new();
        let mut left_out = Vec::new();
        for method in Method::ALL {
            match method {
                Method::ClosedForm | Method::Exact if self.body.has_torque() => {
                    left_out.push((method, "a torque acts: no closed-form solution".into()))
                }
                Method::ClosedForm if self.body.symmetry_axis(1e-12).is_none() => {
                    left_out.push((method, "the body is not symmetric".into()))
                }
                // Without a torque the kicks vanish and each step is the exact free flow:
                // the rows would be `exact`'s at a higher cost, and fit no order.
                Method::ExactSplitting
                | Method::ExactSplitting4
                | Method::ExactSplitting6
                | Method::ExactSplitting8
                    if !self.body.has_torque() =>
                {
                    left_out.push((
                        method,
                        "no torque: each step is the exact free flow (see exact)".into(),
                    ))
                }
                _ => run.push(method),
            }
        }
        (run, left_out)
    }

    /// The fixed step counts (coarsest first) or tolerances a method runs at.
    #[must_use]
    pub fn settings(&self, method: Method, size: Size) -> Vec<f64> {
        let quick = size == Size::Quick;
        match method.step_kind() {
            StepKind::AtSamples => vec![self.t_end / SAMPLES as f64],
            StepKind::Fixed => {
                let levels = match (self.sweep, quick) {
                    (Sweep::WorkPrecision, true) => 4,
                    (Sweep::WorkPrecision, false) => 8,
                    (Sweep::Stress, true) => 2,
                    (Sweep::Stress, false) => 4,
                    (Sweep::Long, _) => 1,
                };
                // A long run at --quick takes half the steps: it must fit in CI's minute.
                let coarsest = if self.sweep == Sweep::Long && quick {
                    self.coarsest_steps / 2
                } else {
                    self.coarsest_steps
                };
                (0..levels)
                    .map(|k| self.t_end / (coarsest << k) as f64)
                    .collect()
            }
            StepKind::Adaptive => {
                let exponents: &[i32] = match (self.sweep, quick) {
                    (Sweep::WorkPrecision, true) => &[4, 6, 8, 10],
                    (Sweep::WorkPrecision, false) => &[3, 4, 5, 6, 7, 8, 9, 10, 11, 12],
                    (Sweep::Stress, true) => &[6],
                    (Sweep::Stress, false) => &[6, 9],
                    (Sweep::Long, _) => &[8],
                };
                exponents.iter().map(|&e| 10f64.powi(-e)).collect()
            }
        }
    }
}

/// The whole built-in suite: the seven reference scenes, then the stiff and extreme cases.
pub fn suite() -> Result<Vec<TestScene>, Error> {
    let mut scenes = reference_scenes()?;
    scenes.extend(stability_scenes()?);
    Ok(scenes)
}

/// The work-precision scenes (test models of `docs/references.md`).
pub fn reference_scenes() -> Result<Vec<TestScene>, Error> {
    let hlw = 1.1f64;
    let wp = Sweep::WorkPrecision;
    Ok(vec![
        free_with_momentum(
            "Hairer-Lubich-Wanner body",
            "Geometric Numerical Integration; moments (2, 1, 2/3), m(0) = (cos 1.1, 0, sin 1.1)",
            [2.0, 1.0, 2.0 / 3.0],
            [hlw.cos(), 0.0, hlw.sin()],
            10.0,
            25,
            wp,
        )?,
        free_with_momentum(
            "Hairer-Vilmart driver",
            "moments (0.6, 0.8, 1.0), m(0) = (1.8, 0.4, -0.9)",
            [0.6, 0.8, 1.0],
            [1.8, 0.4, -0.9],
            10.0,
            100,
            wp,
        )?,
        free_with_momentum(
            "Dzhanibekov (near the separatrix)",
            "moments (3, 5, 9), m(0) = (0, 2, 0.01), 1 - m = 4.2e-5",
            [3.0, 5.0, 9.0],
            [0.0, 2.0, 0.01],
            100.0,
            200,
            wp,
        )?,
        free_with_momentum(
            "symmetric short fat top",
            "moments (3, 3, 9), m(0) = (0, 5, 7)",
            [3.0, 3.0, 9.0],
            [0.0, 5.0, 7.0],
            10.0,
            25,
            wp,
        )?,
        heavy_top()?,
        asymmetric_heavy_top()?,
        satellite()?,
    ])
}

/// A heavy top with three different moments and its centre of mass off every axis: no
/// closed form, and the free part of a splitting is a full elliptic flow.
fn asymmetric_heavy_top() -> Result<TestScene, Error> {
    let body = RigidBody::new([1.0, 1.4, 0.6])?.with_torque(Gravity {
        mass: 1.0,
        g: Vector::new(0.0, 0.0, -9.81),
        com_offset: Vector::new(0.05, -0.02, 0.3),
    });
    Ok(TestScene::new(
        "asymmetric heavy top",
        "moments (1, 1.4, 0.6) about the pivot, centre of mass (0.05, -0.02, 0.3), mass 1, \
         tilted 0.3 rad, w(0) = (0.3, -0.2, 8)",
        body,
        State {
            rotor: (Bivector::E23 * -0.15).exp(),
            omega: omega_from_vector([0.3, -0.2, 8.0]),
        },
        4.0,
        100,
        Sweep::WorkPrecision,
    ))
}

/// A satellite under the gravity-gradient torque of a circular orbit (time in units of
/// the inverse orbital rate), tumbling at a few times the orbital rate for two orbits.
fn satellite() -> Result<TestScene, Error> {
    let moments = [1.0, 1.5, 2.0];
    let body = RigidBody::new(moments)?.with_torque(GravityGradient {
        orbit_rate: 1.0,
        moments,
    });
    Ok(TestScene::new(
        "gravity-gradient satellite",
        "moments (1, 1.5, 2), circular orbit at rate 1, w(0) = (0.2, 0.5, 3) for two orbits \
         (t_end = 4 pi); the standard attitude problem (Hughes 1986, section 8.2)",
        body,
        State {
            rotor: Rotor::ONE,
            omega: omega_from_vector([0.2, 0.5, 3.0]),
        },
        4.0 * std::f64::consts::PI,
        100,
        Sweep::WorkPrecision,
    ))
}

fn free_with_momentum(
    name: &str,
    source: &str,
    moments: [f64; 3],
    momentum: [f64; 3],
    t_end: f64,
    coarsest_steps: u64,
    sweep: Sweep,
) -> Result<TestScene, Error> {
    let w = [0, 1, 2].map(|k| momentum[k] / moments[k]);
    TestScene::free(name, source, moments, w, t_end, coarsest_steps, sweep)
}

fn heavy_top() -> Result<TestScene, Error> {
    let body = RigidBody::new([1.0, 1.0, 0.5])?.with_torque(Gravity {
        mass: 1.0,
        g: Vector::new(0.0, 0.0, -9.81),
        com_offset: Vector::new(0.0, 0.0, 0.5),
    });
    let tilt = (Bivector::E23 * -0.15).exp();
    Ok(TestScene::new(
        "heavy top",
        "moments (1, 1, 0.5) about the pivot, centre of mass 0.5 up the axis, tilted 0.3 rad, \
         spin 20 rad/s",
        body,
        State {
            rotor: tilt,
            omega: omega_from_vector([0.0, 0.0, 20.0]),
        },
        4.0,
        100,
        Sweep::WorkPrecision,
    ))
}

/// The stiff and extreme cases.
pub fn stability_scenes() -> Result<Vec<TestScene>, Error> {
    let st = Sweep::Stress;
    let hv = [1.8 / 0.6, 0.4 / 0.8, -0.9];
    let hv_moments = [0.6, 0.8, 1.0];
    let mut scenes = vec![
        TestScene::free(
            "needle (i3/i1 = 1e-3)",
            "moments (1, 1, 1e-3), w(0) = (0.01, 0, 1000), h = 1/60: 16.7 rad a step",
            [1.0, 1.0, 1e-3],
            [0.01, 0.0, 1000.0],
            10.0,
            600,
            st,
        )?,
        TestScene::free(
            "needle (i3/i1 = 1e-6)",
            "moments (1, 1, 1e-6), w(0) = (0.01, 0, 1e6) for 0.01 s (10^4 rad of spin), \
             coarsest h = 1e-4: 100 rad a step",
            [1.0, 1.0, 1e-6],
            [0.01, 0.0, 1e6],
            0.01,
            100,
            st,
        )?,
        TestScene::free(
            "flat disk (i3 = i1 + i2)",
            "moments (1, 1, 2), the limit of the triangle inequality, w(0) = (1, 0.5, 2)",
            [1.0, 1.0, 2.0],
            [1.0, 0.5, 2.0],
            20.0,
            100,
            st,
        )?,
        TestScene::free(
            "sphere",
            "moments (1, 1, 1): w is constant, every method should keep it",
            [1.0, 1.0, 1.0],
            [0.3, -1.0, 2.0],
            20.0,
            100,
            st,
        )?,
        TestScene::free(
            "fast tumbling",
            "Hairer-Vilmart body at 100 times the rate, h = 0.01: 3.2 rad a step",
            hv_moments,
            hv.map(|w| 100.0 * w),
            2.0,
            200,
            st,
        )?,
        free_with_momentum(
            "near-symmetric body",
            "moments (1, 1 + 1e-9, 2), m(0) = (0.6, 0.8, 1), h = 0.01",
            [1.0, 1.0 + 1e-9, 2.0],
            [0.6, 0.8, 1.0],
            50.0,
            5000,
            st,
        )?,
        TestScene::free(
            "tiny and fast (moments 1e-20, rates 1e6)",
            "Hairer-Vilmart body scaled: moments x 1e-20, w x 1e6, time / 1e6",
            hv_moments.map(|i| i * 1e-20),
            hv.map(|w| w * 1e6),
            10.0e-6,
            100,
            st,
        )?,
        TestScene::free(
            "huge and slow (moments 1e20, rates 1e-6)",
            "Hairer-Vilmart body scaled: moments x 1e20, w x 1e-6, time x 1e6",
            hv_moments.map(|i| i * 1e20),
            hv.map(|w| w * 1e-6),
            10.0e6,
            100,
            st,
        )?,
    ];
    scenes.push(long_run()?);
    Ok(scenes)
}

/// The symmetric short fat top over 10^5 periods of its body-frame precession, 20 steps
/// a period. Symmetric so that two independent exact solutions (the closed form and the
/// elliptic-function flow) check each other at 10^5 periods, where Dormand-Prince at any
/// affordable tolerance has lost the phase.
fn long_run() -> Result<TestScene, Error> {
    let moments = [3.0, 3.0, 9.0];
    let m0 = [0.0, 5.0, 7.0];
    let period = free_body_orbit(moments, m0).period;
    let periods = 1e5;
    let w = [0, 1, 2].map(|k| m0[k] / moments[k]);
    TestScene::free(
        "long run (1e5 periods)",
        &format!(
            "symmetric short fat top, moments (3, 3, 9), m(0) = (0, 5, 7), for 10^5 periods of \
             m(t) (period {period:.4}), 20 steps a period (10 at --quick)"
        ),
        moments,
        w,
        periods * period,
        2_000_000,
        Sweep::Long,
    )
}
