//! The method registry: every method's one name, the step control it takes and how to
//! build it, held in one table ([`METHODS`]). The command line, scene files, the report
//! and the CSV all read names from here, so a method is spelt the same everywhere.
//!
//! To add a method: a variant of [`Method`], one row in [`METHODS`] (its order included),
//! one arm in [`Method::integrator`], and its promises in the harness that runs every
//! method on every report scene (`ga-rigid-cli/tests/methods.rs`).

use std::fmt;
use std::str::FromStr;

use crate::error::{self, Error};

use crate::integrators::{
    Adams, CasimirSplitting, ClosedForm, ComposedSplitting, CorrectedSplitting, DormandPrince,
    ExactFreeBody, ExactSplitting, ImplicitMidpoint, Integrator, LieDop853, LieRk4, Rk4, Splitting,
};
use crate::peers::{
    Buss, ExplicitGyroscopicEuler, ImplicitGyroscopicEuler, MoserVeselov, QuaternionMidpoint,
    Spiers, SpiersForm,
};

/// The absolute tolerance paired with a relative tolerance `tol` for Dormand-Prince, as a
/// fraction of `tol`.
pub const DOPRI_ABSOLUTE_TOLERANCE_RATIO: f64 = 1e-3;

/// The smallest relative tolerance a run may ask for ([`Method::step`]).
pub const MIN_TOLERANCE: f64 = 1e-14;

/// A step size: finite, positive and a normal number (a subnormal step has lost its
/// precision and turns into zero or infinity in the first product), or an error naming
/// `dt`.
fn step_size(dt: f64) -> Result<f64, Error> {
    if !(dt.is_finite() && dt > 0.0) {
        return Err(Error::invalid(
            "dt",
            format!(
                "the step size must be positive and finite, got {}",
                error::num(dt)
            ),
        ));
    }
    if dt < f64::MIN_POSITIVE {
        return Err(Error::invalid(
            "dt",
            format!(
                "the step size must be at least {:e} (a normal number), got {dt:e}",
                f64::MIN_POSITIVE
            ),
        ));
    }
    Ok(dt)
}

/// A time-stepping (or solution-evaluating) method for the rigid body.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Method {
    /// The closed-form solution of the torque-free symmetric top.
    ClosedForm,
    /// Classical fourth-order Runge-Kutta on the rotor and angular velocity.
    Rk4,
    /// Fourth-order Runge-Kutta-Munthe-Kaas on the rotor group.
    LieRk4,
    /// The implicit midpoint rule.
    Midpoint,
    /// Splitting into exact rotations (Dullweber-Leimkuhler-McLachlan).
    Splitting,
    /// The same splitting with rational (Cayley) axis turns.
    SplittingCayley,
    /// The free body split around its Casimir `|m|^2`, rational turns.
    SplittingCasimir,
    /// The Casimir split with corrected turns, as `engine`'s step.
    SplittingCorrected,
    /// Adaptive Dormand-Prince 5(4).
    Dopri,
    /// The exact flow of the free body through Jacobi elliptic functions.
    Exact,
    /// Torque kick, exact free flow, torque kick (Celledoni-Fassò-Säfström-Zanna), order 2.
    ExactSplitting,
    /// The exact-flow splitting raised to order 4 (Blanes-Moan `SRKN_6^b`).
    ExactSplitting4,
    /// The exact-flow splitting raised to order 6 (Blanes-Moan `SRKN_11^b`).
    ExactSplitting6,
    /// The exact-flow splitting composed to order 8 (Kahan-Li).
    ExactSplitting8,
    /// The DLM splitting composed to order 4 (Suzuki).
    Splitting4,
    /// The DLM splitting composed to order 6 (Kahan-Li).
    Splitting6,
    /// The DLM splitting composed to order 8 (Kahan-Li).
    Splitting8,
    /// Adaptive Runge-Kutta-Munthe-Kaas on the rotor group with the Dormand-Prince 8(5,3)
    /// pair.
    LieDop853,
    /// [`Method::LieDop853`] in Cayley coordinates (no exponential in the stages).
    LieDop853Cayley,
    /// Adams-Bashforth-Moulton PECE of order 10 on the seven-unknown embedding, fixed step.
    Adams10,
    /// Adams-Bashforth-Moulton PECE of order 12 on the seven-unknown embedding, fixed step.
    Adams12,
    /// Peer: ode_solvers' Dop853 on the quaternion form.
    Dop853Quaternion,
    /// Peer: ode_solvers' Dopri5 on the quaternion form.
    Dopri5Quaternion,
    /// Peer: the explicit gyroscopic Euler step of game engines.
    EulerGyroExplicit,
    /// Peer: the implicit gyroscopic Euler step (one Newton iteration) of Bullet and Jolt.
    EulerGyroImplicit,
    /// Peer: Buss's augmented second-order rotation update.
    Buss2,
    /// Peer: the implicit midpoint rule on the seven-unknown quaternion form (Newton).
    MidpointQuaternion,
    /// Peer: the discrete Moser-Veselov step (RATTLE), Strang-split with torque kicks.
    MoserVeselov,
    /// Peer: Spiers's gyroscopic step as avian's pull request #993 uses it, a velocity
    /// update before the engine's orientation update.
    SpiersVelocity,
    /// Peer: Spiers's momentum-first step, a precession about `L` and a spin.
    SpiersMomentum,
}

/// The kind of step control a method takes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum StepKind {
    /// A fixed step size `dt`.
    Fixed,
    /// An error tolerance `tol`: the method chooses its own steps.
    Adaptive,
    /// Neither: the method evaluates an exact solution at the sample times.
    AtSamples,
}

/// A step control, validated against the method it is for by [`Method::step`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Step {
    /// A fixed step size, finite and positive.
    Fixed(f64),
    /// An error tolerance, finite and positive.
    Tolerance(f64),
    /// No step control: the method evaluates its solution at the sample times.
    AtSamples,
}

/// The largest step a fixed-step method stays stable at, as `h |w|max`: the step times
/// the fastest rate the body can reach. Measured on the report's bodies (the Hairer-Vilmart
/// and Dzhanibekov bodies, a symmetric top, a needle, the heavy top): at the limit every
/// one keeps its energy within half of its start over 300 steps (and a symmetric top its
/// conserved `w3`); above it some do not (`tests/stability_limits.rs`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum StepLimit {
    /// No step makes the method unstable, or it takes no steps.
    None,
    /// Stable up to this `h |w|max`.
    Rate(f64),
    /// Stable up to this `h |w|max` under a torque; without one each step is the exact
    /// free flow, stable at any step.
    RateUnderTorque(f64),
}

/// One row of the registry.
#[derive(Clone, Copy, Debug)]
pub struct MethodInfo {
    /// The method.
    pub method: Method,
    /// Its one name: on the command line, in scene files, the report and the CSV.
    pub name: &'static str,
    /// The step control it takes.
    pub kind: StepKind,
    /// The order `p` of a fixed-step method on a free body: its global error falls as
    /// `h^p`. `None` for the adaptive methods and the exact solutions.
    pub order: Option<u32>,
    /// The order under a torque; it differs where a torque enters less accurately than the
    /// free flow (Buss's update takes the torque's
    /// impulse by an explicit Euler step, first order).
    pub order_under_torque: Option<u32>,
    /// About how long one step takes in a release build, in nanoseconds: measured here on
    /// a heavy top (the dearer case) by timing `simulate` over 4e5 steps, on a shared
    /// 2-core AMD EPYC; per sample for the methods evaluated at the samples, and per
    /// *estimated* step (`tol^(-1/5)` per radian) for the adaptive ones. It turns a step
    /// estimate into a time estimate (`--max-seconds`), so it errs on the slow side.
    pub ns_per_step: f64,
    /// One line for `--help` and the report.
    pub summary: &'static str,
    /// The step beyond which the method is unstable.
    pub step_limit: StepLimit,
    /// For a method people use today rather than one of ours (a peer in the report), where
    /// it comes from.
    pub peer: Option<&'static str>,
    /// The dimensions it runs in: the 3D-only methods are written on G3's vectors
    /// (quaternion forms, the elliptic exact flow, Euler-equation peers); the rest run on
    /// any algebra through `nd`.
    pub dimensions: Dimensions,
}

/// The dimensions a method runs in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dimensions {
    /// Only in 3D.
    Three,
    /// In 2D, 3D and 4D (`closed-form` where the body has one: a planar body, the
    /// symmetric top, the 4D body with second moments `(a, a, b, b)`).
    Any,
}

/// The engines' explicit step's stability limit `h |w|max` (see [`StepLimit`]).
const STEP_LIMIT_EULER_EXPLICIT: f64 = 0.1;
/// The engines' implicit step's stability limit `h |w|max`.
const STEP_LIMIT_EULER_IMPLICIT: f64 = 0.2;
/// Buss's method's stability limit `h |w|max`.
const STEP_LIMIT_BUSS: f64 = 0.5;
/// The implicit midpoint rule's on the quaternion form: `midpoint`'s (the same rule; both
/// first lose the Dzhanibekov body between 3.6 and 3.7).
const STEP_LIMIT_MIDPOINT_QUATERNION: f64 = 2.5;
/// The discrete Moser-Veselov step's: about a principal axis it turns by `asin(h w)`, so
/// beyond `h |w| = 1` it has no step (measured: every free body bounded at 1.0, the heavy
/// top at 0.9, whose torque raises `|w|`).
const STEP_LIMIT_MOSER_VESELOV: f64 = 0.8;
/// Spiers's two forms': both keep `|L|`, so the energy stays within the moments' range, and
/// the limit is where the Dzhanibekov body first leaves half its energy (measured: bounded
/// at 2.5, not at 2.55; every other body bounded up to 4, the heavy top up to 3.45 in the
/// velocity form).
const STEP_LIMIT_SPIERS: f64 = 2.5;

/// Adams-Bashforth-Moulton PECE of order 10's stability limit `h |w|max`: the needle (its
/// fast mode's frequency is about its `|w|`) is first unbounded at 0.24; the other bodies
/// at 0.43 (heavy top) to 0.71 (Hairer-Vilmart).
const STEP_LIMIT_ADAMS_10: f64 = 0.2;
/// Order 12's: the needle first unbounded at 0.13; the others at 0.22 (heavy top) to 0.36.
/// The stability regions of Adams methods shrink as the order grows.
const STEP_LIMIT_ADAMS_12: f64 = 0.1;

/// The registry: one row per method, in the order tables list them; ours first, then the
/// peers (`peer` set).
pub const METHODS: [MethodInfo; 30] = [
    MethodInfo {
        method: Method::ClosedForm,
        name: "closed-form",
        kind: StepKind::AtSamples,
        order: None,
        order_under_torque: None,
        ns_per_step: 200.0,
        summary: "the closed-form solution (torque-free symmetric top)",
        step_limit: StepLimit::None,
        peer: None,
        dimensions: Dimensions::Any,
    },
    MethodInfo {
        method: Method::Exact,
        name: "exact",
        kind: StepKind::AtSamples,
        order: None,
        order_under_torque: None,
        ns_per_step: 1000.0,
        summary: "the exact flow of the free body (Jacobi elliptic functions)",
        step_limit: StepLimit::None,
        peer: None,
        dimensions: Dimensions::Three,
    },
    MethodInfo {
        method: Method::Rk4,
        name: "rk4",
        kind: StepKind::Fixed,
        order: Some(4),
        order_under_torque: Some(4),
        ns_per_step: 250.0,
        summary: "classical fourth-order Runge-Kutta, rotor renormalised",
        step_limit: StepLimit::Rate(2.0),
        peer: None,
        dimensions: Dimensions::Any,
    },
    MethodInfo {
        method: Method::LieRk4,
        name: "lie-rk4",
        kind: StepKind::Fixed,
        order: Some(4),
        order_under_torque: Some(4),
        ns_per_step: 250.0,
        summary: "fourth-order Runge-Kutta-Munthe-Kaas on the rotor group",
        step_limit: StepLimit::Rate(2.0),
        peer: None,
        dimensions: Dimensions::Any,
    },
    MethodInfo {
        method: Method::Midpoint,
        name: "midpoint",
        kind: StepKind::Fixed,
        order: Some(2),
        order_under_torque: Some(2),
        ns_per_step: 400.0,
        summary: "the implicit midpoint rule (symplectic, order two)",
        step_limit: StepLimit::Rate(2.5),
        peer: None,
        dimensions: Dimensions::Any,
    },
    MethodInfo {
        method: Method::Splitting,
        name: "splitting",
        kind: StepKind::Fixed,
        order: Some(2),
        order_under_torque: Some(2),
        ns_per_step: 500.0,
        summary: "splitting into exact axis rotations (Dullweber-Leimkuhler-McLachlan)",
        step_limit: StepLimit::Rate(3.0),
        peer: None,
        dimensions: Dimensions::Any,
    },
    MethodInfo {
        method: Method::SplittingCayley,
        name: "splitting-cayley",
        kind: StepKind::Fixed,
        order: Some(2),
        order_under_torque: Some(2),
        ns_per_step: 150.0,
        summary: "the same splitting with rational (Cayley) axis turns, no sine",
        step_limit: StepLimit::Rate(3.0),
        peer: None,
        dimensions: Dimensions::Three,
    },
    MethodInfo {
        method: Method::SplittingCasimir,
        name: "splitting-casimir",
        kind: StepKind::Fixed,
        order: Some(2),
        order_under_torque: Some(2),
        ns_per_step: 120.0,
        summary: "the free body split around its Casimir |m|^2, rational turns, order two",
        step_limit: StepLimit::Rate(3.0),
        peer: None,
        dimensions: Dimensions::Three,
    },
    MethodInfo {
        method: Method::SplittingCorrected,
        name: "splitting-corrected",
        kind: StepKind::Fixed,
        order: Some(2),
        order_under_torque: Some(2),
        ns_per_step: 120.0,
        summary:
            "the Casimir split with turns corrected to cancel its one-axis h^2 error: engine's step",
        step_limit: StepLimit::Rate(3.0),
        peer: None,
        dimensions: Dimensions::Three,
    },
    MethodInfo {
        method: Method::Dopri,
        name: "dopri",
        kind: StepKind::Adaptive,
        order: None,
        order_under_torque: None,
        ns_per_step: 100.0,
        summary: "adaptive Dormand-Prince 5(4)",
        step_limit: StepLimit::None,
        peer: None,
        dimensions: Dimensions::Three,
    },
    MethodInfo {
        method: Method::ExactSplitting,
        name: "exact-splitting",
        kind: StepKind::Fixed,
        order: Some(2),
        order_under_torque: Some(2),
        ns_per_step: 250.0,
        summary: "torque kick, exact free flow, torque kick (Celledoni et al. 2008), order two",
        step_limit: StepLimit::RateUnderTorque(30.0),
        peer: None,
        dimensions: Dimensions::Three,
    },
    MethodInfo {
        method: Method::ExactSplitting4,
        name: "exact-splitting-4",
        kind: StepKind::Fixed,
        order: Some(4),
        order_under_torque: Some(4),
        ns_per_step: 700.0,
        summary: "the exact-flow splitting raised to order four (Blanes-Moan SRKN_6^b)",
        step_limit: StepLimit::RateUnderTorque(30.0),
        peer: None,
        dimensions: Dimensions::Three,
    },
    MethodInfo {
        method: Method::ExactSplitting6,
        name: "exact-splitting-6",
        kind: StepKind::Fixed,
        order: Some(6),
        order_under_torque: Some(6),
        ns_per_step: 1100.0,
        summary: "the exact-flow splitting raised to order six (Blanes-Moan SRKN_11^b)",
        step_limit: StepLimit::RateUnderTorque(30.0),
        peer: None,
        dimensions: Dimensions::Three,
    },
    MethodInfo {
        method: Method::ExactSplitting8,
        name: "exact-splitting-8",
        kind: StepKind::Fixed,
        order: Some(8),
        order_under_torque: Some(8),
        ns_per_step: 1500.0,
        summary: "the exact-flow splitting composed to order eight (Kahan-Li)",
        step_limit: StepLimit::RateUnderTorque(30.0),
        peer: None,
        dimensions: Dimensions::Three,
    },
    MethodInfo {
        method: Method::Splitting4,
        name: "splitting-4",
        kind: StepKind::Fixed,
        order: Some(4),
        order_under_torque: Some(4),
        ns_per_step: 1300.0,
        summary: "the axis-rotation splitting composed to order four (Suzuki)",
        step_limit: StepLimit::Rate(4.0),
        peer: None,
        dimensions: Dimensions::Three,
    },
    MethodInfo {
        method: Method::Splitting6,
        name: "splitting-6",
        kind: StepKind::Fixed,
        order: Some(6),
        order_under_torque: Some(6),
        ns_per_step: 2200.0,
        summary: "the axis-rotation splitting composed to order six (Kahan-Li)",
        step_limit: StepLimit::Rate(4.0),
        peer: None,
        dimensions: Dimensions::Three,
    },
    MethodInfo {
        method: Method::Splitting8,
        name: "splitting-8",
        kind: StepKind::Fixed,
        order: Some(8),
        order_under_torque: Some(8),
        ns_per_step: 3000.0,
        summary: "the axis-rotation splitting composed to order eight (Kahan-Li)",
        step_limit: StepLimit::Rate(4.0),
        peer: None,
        dimensions: Dimensions::Three,
    },
    MethodInfo {
        method: Method::LieDop853,
        name: "lie-dop853",
        kind: StepKind::Adaptive,
        order: None,
        order_under_torque: None,
        ns_per_step: 100.0,
        summary: "adaptive order-8 Runge-Kutta-Munthe-Kaas on the rotor group (DOP853 pair)",
        step_limit: StepLimit::None,
        peer: None,
        dimensions: Dimensions::Any,
    },
    MethodInfo {
        method: Method::LieDop853Cayley,
        name: "lie-dop853-cayley",
        kind: StepKind::Adaptive,
        order: None,
        order_under_torque: None,
        ns_per_step: 100.0,
        summary: "lie-dop853 in Cayley coordinates: the same pair, no exponentials in the stages",
        step_limit: StepLimit::None,
        peer: None,
        dimensions: Dimensions::Three,
    },
    MethodInfo {
        method: Method::Adams10,
        name: "adams-10",
        kind: StepKind::Fixed,
        order: Some(10),
        order_under_torque: Some(10),
        ns_per_step: 150.0,
        summary: "Adams-Bashforth-Moulton PECE of order 10, two rates a step, rotor renormalised",
        step_limit: StepLimit::Rate(STEP_LIMIT_ADAMS_10),
        peer: None,
        dimensions: Dimensions::Three,
    },
    MethodInfo {
        method: Method::Adams12,
        name: "adams-12",
        kind: StepKind::Fixed,
        order: Some(12),
        order_under_torque: Some(12),
        ns_per_step: 150.0,
        summary: "Adams-Bashforth-Moulton PECE of order 12, two rates a step, rotor renormalised",
        step_limit: StepLimit::Rate(STEP_LIMIT_ADAMS_12),
        peer: None,
        dimensions: Dimensions::Three,
    },
    MethodInfo {
        method: Method::Dop853Quaternion,
        name: "dop853-quaternion",
        kind: StepKind::Adaptive,
        order: None,
        order_under_torque: None,
        ns_per_step: 300.0,
        summary: "peer: ode_solvers' Dop853 on body momentum and a unit quaternion",
        step_limit: StepLimit::None,
        peer: Some("ode_solvers 0.6 Dop853 (Hairer's DOP853), 7-unknown quaternion form"),
        dimensions: Dimensions::Three,
    },
    MethodInfo {
        method: Method::Dopri5Quaternion,
        name: "dopri5-quaternion",
        kind: StepKind::Adaptive,
        order: None,
        order_under_torque: None,
        ns_per_step: 200.0,
        summary: "peer: ode_solvers' Dopri5 on body momentum and a unit quaternion",
        step_limit: StepLimit::None,
        peer: Some("ode_solvers 0.6 Dopri5 (Hairer's DOPRI5), 7-unknown quaternion form"),
        dimensions: Dimensions::Three,
    },
    MethodInfo {
        method: Method::EulerGyroExplicit,
        name: "euler-gyro-explicit",
        kind: StepKind::Fixed,
        order: Some(1),
        order_under_torque: Some(1),
        ns_per_step: 100.0,
        summary: "peer: game engines' explicit gyroscopic Euler step",
        step_limit: StepLimit::Rate(STEP_LIMIT_EULER_EXPLICIT),
        peer: Some("engines' explicit gyroscopic Euler (Catto, GDC 2015)"),
        dimensions: Dimensions::Three,
    },
    MethodInfo {
        method: Method::EulerGyroImplicit,
        name: "euler-gyro-implicit",
        kind: StepKind::Fixed,
        order: Some(1),
        order_under_torque: Some(1),
        ns_per_step: 150.0,
        summary: "peer: Bullet's and Jolt's implicit gyroscopic Euler step (one Newton iteration)",
        step_limit: StepLimit::Rate(STEP_LIMIT_EULER_IMPLICIT),
        peer: Some("Bullet computeGyroscopicImpulseImplicit_Body, Jolt (Catto, GDC 2015)"),
        dimensions: Dimensions::Three,
    },
    MethodInfo {
        method: Method::Buss2,
        name: "buss-2",
        kind: StepKind::Fixed,
        order: Some(2),
        order_under_torque: Some(1),
        ns_per_step: 300.0,
        summary: "peer: Buss's augmented second-order rotation update",
        step_limit: StepLimit::Rate(STEP_LIMIT_BUSS),
        peer: Some("Buss, J. Comput. Phys. 164 (2000), augmented second-order method"),
        dimensions: Dimensions::Three,
    },
    MethodInfo {
        method: Method::MidpointQuaternion,
        name: "midpoint-quaternion",
        kind: StepKind::Fixed,
        order: Some(2),
        order_under_torque: Some(2),
        ns_per_step: 500.0,
        summary: "peer: implicit midpoint on body momentum and a quaternion, Newton-solved",
        step_limit: StepLimit::Rate(STEP_LIMIT_MIDPOINT_QUATERNION),
        peer: Some("implicit midpoint, 7-unknown quaternion form (Hairer-Lubich-Wanner IV.2)"),
        dimensions: Dimensions::Three,
    },
    MethodInfo {
        method: Method::MoserVeselov,
        name: "moser-veselov",
        kind: StepKind::Fixed,
        order: Some(2),
        order_under_torque: Some(2),
        ns_per_step: 350.0,
        summary: "peer: discrete Moser-Veselov step (RATTLE), torque kicks around it",
        step_limit: StepLimit::Rate(STEP_LIMIT_MOSER_VESELOV),
        peer: Some("Moser-Veselov, Comm. Math. Phys. 139 (1991); McLachlan-Zanna 2005"),
        dimensions: Dimensions::Three,
    },
    MethodInfo {
        method: Method::SpiersVelocity,
        name: "spiers-velocity",
        kind: StepKind::Fixed,
        order: Some(1),
        order_under_torque: Some(1),
        ns_per_step: 200.0,
        summary: "peer: Spiers's gyroscopic velocity update, then R1 = Q(h w1) R0 (avian PR 993)",
        step_limit: StepLimit::Rate(STEP_LIMIT_SPIERS),
        peer: Some("Spiers, \"A better way to spin\" (modified Jolt); avian pull request #993"),
        dimensions: Dimensions::Three,
    },
    MethodInfo {
        method: Method::SpiersMomentum,
        name: "spiers-momentum",
        kind: StepKind::Fixed,
        order: Some(1),
        order_under_torque: Some(1),
        ns_per_step: 250.0,
        summary: "peer: Spiers's momentum-first step, precession about L then spin",
        step_limit: StepLimit::Rate(STEP_LIMIT_SPIERS),
        peer: Some("Spiers, \"A better way to spin\" (momentum-first method)"),
        dimensions: Dimensions::Three,
    },
];

impl Method {
    /// Every method, in the registry's order.
    pub const ALL: [Method; METHODS.len()] = {
        let mut all = [Method::ClosedForm; METHODS.len()];
        let mut i = 0;
        while i < METHODS.len() {
            all[i] = METHODS[i].method;
            i += 1;
        }
        all
    };

    /// The method's row in the registry.
    #[must_use]
    pub fn info(self) -> &'static MethodInfo {
        // Every variant has a row: `registry_is_complete` checks it.
        METHODS
            .iter()
            .find(|row| row.method == self)
            .unwrap_or(&METHODS[0])
    }

    /// The method's one name.
    #[must_use]
    pub fn name(self) -> &'static str {
        self.info().name
    }

    /// The step control the method takes.
    #[must_use]
    pub fn step_kind(self) -> StepKind {
        self.info().kind
    }

    /// The order of a fixed-step method's global error on a body with or without a
    /// torque, if it has one (see [`MethodInfo::order`]).
    #[must_use]
    pub fn order(self, torque: bool) -> Option<u32> {
        let info = self.info();
        if torque {
            info.order_under_torque
        } else {
            info.order
        }
    }

    /// The largest stable `h |w|max` on a body with or without a torque, if any step is
    /// unstable (see [`StepLimit`]).
    #[must_use]
    pub fn stable_step_rate(self, torque: bool) -> Option<f64> {
        match self.info().step_limit {
            StepLimit::None => None,
            StepLimit::Rate(rate) => Some(rate),
            StepLimit::RateUnderTorque(rate) => torque.then_some(rate),
        }
    }

    /// About how many seconds `steps` steps take in a release build (see
    /// [`MethodInfo::ns_per_step`]).
    #[must_use]
    pub fn seconds_for(self, steps: f64) -> f64 {
        steps * self.info().ns_per_step * 1e-9
    }

    /// The method with this name, if there is one.
    #[must_use]
    pub fn from_name(name: &str) -> Option<Method> {
        METHODS
            .iter()
            .find(|row| row.name == name)
            .map(|r| r.method)
    }

    /// The one rule book for a run's step control: match a step size `dt` or a tolerance
    /// `tol` to the method. Fixed-step methods need `dt`, adaptive ones `tol`, and methods
    /// evaluated at the sample times take neither; at most one may be given. `dt` must be
    /// finite, positive and a normal number; `tol` as well, and between
    /// [`MIN_TOLERANCE`] and 1. Errors name `dt` or `tol` (the command renames them to its
    /// flags at its edge).
    pub fn step(self, dt: Option<f64>, tol: Option<f64>) -> Result<Step, Error> {
        let name = self.name();
        if dt.is_some() && tol.is_some() {
            return Err(Error::invalid(
                "dt",
                "dt and tol are mutually exclusive: give one",
            ));
        }
        if let Some(dt) = dt {
            step_size(dt)?;
        }
        if let Some(tol) = tol {
            if !(tol.is_finite() && tol > 0.0) {
                return Err(Error::invalid(
                    "tol",
                    format!(
                        "the tolerance must be positive and finite, got {}",
                        error::num(tol)
                    ),
                ));
            }
            // Below about 1e-14 the rounding error of a step exceeds the tolerance and the
            // step size shrinks without end; above 1 a "relative" tolerance means nothing.
            if !(MIN_TOLERANCE..=1.0).contains(&tol) {
                return Err(Error::invalid(
                    "tol",
                    format!(
                        "the tolerance must be between 1e-14 and 1, got {}",
                        error::num(tol)
                    ),
                ));
            }
        }
        match (self.step_kind(), dt, tol) {
            (StepKind::Fixed, Some(dt), None) => Ok(Step::Fixed(dt)),
            (StepKind::Fixed, None, Some(_)) => Err(Error::invalid(
                "tol",
                format!("method {name} takes a fixed step: give dt, not tol"),
            )),
            (StepKind::Fixed, _, _) => Err(Error::invalid(
                "dt",
                format!("method {name} takes a fixed step: give dt"),
            )),
            (StepKind::Adaptive, None, Some(tol)) => Ok(Step::Tolerance(tol)),
            (StepKind::Adaptive, Some(_), None) => Err(Error::invalid(
                "dt",
                format!("method {name} is adaptive: give tol, not dt"),
            )),
            (StepKind::Adaptive, _, _) => Err(Error::invalid(
                "tol",
                format!("method {name} is adaptive: give tol"),
            )),
            (StepKind::AtSamples, None, None) => Ok(Step::AtSamples),
            (StepKind::AtSamples, Some(_), _) => Err(Error::invalid(
                "dt",
                format!("method {name} evaluates its solution at the sample times and takes no dt"),
            )),
            (StepKind::AtSamples, None, Some(_)) => Err(Error::invalid(
                "tol",
                format!(
                    "method {name} evaluates its solution at the sample times and takes no tol"
                ),
            )),
        }
    }

    /// [`Method::step`] where leaving both out is allowed: `None` when neither `dt` nor
    /// `tol` is given to a method that takes one, so that the scene's default applies
    /// ([`crate::limits::default_step`]).
    pub fn given_step(self, dt: Option<f64>, tol: Option<f64>) -> Result<Option<Step>, Error> {
        match (self.step_kind(), dt, tol) {
            (StepKind::Fixed | StepKind::Adaptive, None, None) => Ok(None),
            _ => self.step(dt, tol).map(Some),
        }
    }

    /// The integrator for this method and a step control of its kind (see
    /// [`Method::step`]); an error naming `dt` or `tol` if the step does not fit.
    pub fn integrator(self, step: Step) -> Result<Box<dyn Integrator>, Error> {
        let name = self.name();
        let fixed = || match step {
            Step::Fixed(h) => Ok(h),
            _ => Err(Error::invalid(
                "dt",
                format!("method {name} takes a fixed step dt"),
            )),
        };
        let tolerance = || match step {
            Step::Tolerance(tol) => Ok(tol),
            _ => Err(Error::invalid(
                "tol",
                format!("method {name} is adaptive and takes a tolerance tol"),
            )),
        };
        Ok(match self {
            Method::ClosedForm => Box::new(ClosedForm::new()),
            Method::Exact => Box::new(ExactFreeBody::new()),
            Method::Rk4 => Box::new(Rk4::new(fixed()?).map_err(|e| e.at("dt"))?),
            Method::LieRk4 => Box::new(LieRk4::new(fixed()?).map_err(|e| e.at("dt"))?),
            Method::Midpoint => Box::new(ImplicitMidpoint::new(fixed()?).map_err(|e| e.at("dt"))?),
            Method::Splitting => Box::new(Splitting::new(fixed()?).map_err(|e| e.at("dt"))?),
            Method::SplittingCayley => {
                Box::new(Splitting::cayley(fixed()?).map_err(|e| e.at("dt"))?)
            }
            Method::SplittingCasimir => {
                Box::new(CasimirSplitting::new(fixed()?).map_err(|e| e.at("dt"))?)
            }
            Method::SplittingCorrected => {
                Box::new(CorrectedSplitting::new(fixed()?).map_err(|e| e.at("dt"))?)
            }
            Method::Dopri => Box::new(
                DormandPrince::new(tolerance()?, tolerance()? * DOPRI_ABSOLUTE_TOLERANCE_RATIO)
                    .map_err(|e| e.at("tol"))?,
            ),
            Method::LieDop853 => Box::new(
                LieDop853::new(tolerance()?, tolerance()? * DOPRI_ABSOLUTE_TOLERANCE_RATIO)
                    .map_err(|e| e.at("tol"))?,
            ),
            Method::LieDop853Cayley => Box::new(
                LieDop853::cayley(tolerance()?, tolerance()? * DOPRI_ABSOLUTE_TOLERANCE_RATIO)
                    .map_err(|e| e.at("tol"))?,
            ),
            Method::ExactSplitting => {
                Box::new(ExactSplitting::new(fixed()?).map_err(|e| e.at("dt"))?)
            }
            Method::ExactSplitting4 => {
                Box::new(ExactSplitting::with_order(fixed()?, 4).map_err(|e| e.at("dt"))?)
            }
            Method::ExactSplitting6 => {
                Box::new(ExactSplitting::with_order(fixed()?, 6).map_err(|e| e.at("dt"))?)
            }
            Method::ExactSplitting8 => {
                Box::new(ExactSplitting::with_order(fixed()?, 8).map_err(|e| e.at("dt"))?)
            }
            Method::Splitting4 => {
                Box::new(ComposedSplitting::new(fixed()?, 4).map_err(|e| e.at("dt"))?)
            }
            Method::Splitting6 => {
                Box::new(ComposedSplitting::new(fixed()?, 6).map_err(|e| e.at("dt"))?)
            }
            Method::Splitting8 => {
                Box::new(ComposedSplitting::new(fixed()?, 8).map_err(|e| e.at("dt"))?)
            }
            Method::Adams10 => Box::new(Adams::new(fixed()?, 10).map_err(|e| e.at("dt"))?),
            Method::Adams12 => Box::new(Adams::new(fixed()?, 12).map_err(|e| e.at("dt"))?),
            Method::Dop853Quaternion | Method::Dopri5Quaternion => {
                quaternion_ode(self, tolerance()?)?
            }
            Method::EulerGyroExplicit => {
                Box::new(ExplicitGyroscopicEuler::new(fixed()?).map_err(|e| e.at("dt"))?)
            }
            Method::EulerGyroImplicit => {
                Box::new(ImplicitGyroscopicEuler::new(fixed()?).map_err(|e| e.at("dt"))?)
            }
            Method::Buss2 => Box::new(Buss::new(fixed()?).map_err(|e| e.at("dt"))?),
            Method::MidpointQuaternion => {
                Box::new(QuaternionMidpoint::new(fixed()?).map_err(|e| e.at("dt"))?)
            }
            Method::MoserVeselov => Box::new(MoserVeselov::new(fixed()?).map_err(|e| e.at("dt"))?),
            Method::SpiersVelocity => {
                Box::new(Spiers::new(fixed()?, SpiersForm::Velocity).map_err(|e| e.at("dt"))?)
            }
            Method::SpiersMomentum => {
                Box::new(Spiers::new(fixed()?, SpiersForm::Momentum).map_err(|e| e.at("dt"))?)
            }
        })
    }
}

/// ode_solvers' pairs, with the `peers` feature.
#[cfg(feature = "peers")]
fn quaternion_ode(method: Method, tol: f64) -> Result<Box<dyn Integrator>, Error> {
    use crate::peers::{QuaternionOde, QuaternionSolver};
    let solver = if method == Method::Dop853Quaternion {
        QuaternionSolver::Dop853
    } else {
        QuaternionSolver::Dopri5
    };
    Ok(Box::new(
        QuaternionOde::new(solver, tol).map_err(|e| e.at("tol"))?,
    ))
}

/// Without the `peers` feature ode_solvers is not built: say so.
#[cfg(not(feature = "peers"))]
fn quaternion_ode(method: Method, _tol: f64) -> Result<Box<dyn Integrator>, Error> {
    Err(Error::invalid(
        "method",
        format!(
            "{} needs ga-rigid's `peers` feature (ode_solvers)",
            method.name()
        ),
    ))
}

impl fmt::Display for Method {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Method {
    type Err = Error;

    fn from_str(s: &str) -> Result<Method, Error> {
        Method::from_name(s).ok_or_else(|| {
            let names: Vec<&str> = METHODS.iter().map(|r| r.name).collect();
            Error::invalid(
                "method",
                format!("unknown method {s:?}; one of {}", names.join(", ")),
            )
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every variant, listed by hand: the match below has no wildcard, so a new variant
    /// fails to compile here until it is listed, and then needs its row in `METHODS`.
    const EVERY_VARIANT: [Method; 30] = [
        Method::ClosedForm,
        Method::Rk4,
        Method::LieRk4,
        Method::Midpoint,
        Method::Splitting,
        Method::SplittingCayley,
        Method::SplittingCasimir,
        Method::SplittingCorrected,
        Method::Dopri,
        Method::Exact,
        Method::ExactSplitting,
        Method::ExactSplitting4,
        Method::ExactSplitting6,
        Method::ExactSplitting8,
        Method::Splitting4,
        Method::Splitting6,
        Method::Splitting8,
        Method::LieDop853,
        Method::LieDop853Cayley,
        Method::Adams10,
        Method::Adams12,
        Method::Dop853Quaternion,
        Method::Dopri5Quaternion,
        Method::EulerGyroExplicit,
        Method::EulerGyroImplicit,
        Method::Buss2,
        Method::MidpointQuaternion,
        Method::MoserVeselov,
        Method::SpiersVelocity,
        Method::SpiersMomentum,
    ];

    #[test]
    fn registry_is_complete() {
        for method in EVERY_VARIANT {
            match method {
                Method::ClosedForm
                | Method::Rk4
                | Method::LieRk4
                | Method::Midpoint
                | Method::Splitting
                | Method::SplittingCayley
                | Method::SplittingCasimir
                | Method::SplittingCorrected
                | Method::Dopri
                | Method::Exact
                | Method::ExactSplitting
                | Method::ExactSplitting4
                | Method::ExactSplitting6
                | Method::ExactSplitting8
                | Method::Splitting4
                | Method::Splitting6
                | Method::Splitting8
                | Method::LieDop853
                | Method::LieDop853Cayley
                | Method::Adams10
                | Method::Adams12
                | Method::Dop853Quaternion
                | Method::Dopri5Quaternion
                | Method::EulerGyroExplicit
                | Method::EulerGyroImplicit
                | Method::Buss2
                | Method::MidpointQuaternion
                | Method::MoserVeselov
                | Method::SpiersVelocity
                | Method::SpiersMomentum => {}
            }
        }
        let count = |m: Method| METHODS.iter().filter(|r| r.method == m).count();
        for m in EVERY_VARIANT {
            assert_eq!(count(m), 1, "{m:?} must have exactly one row");
            assert!(Method::ALL.contains(&m));
        }
    }

    #[test]
    fn every_name_round_trips_and_is_unique() {
        for method in Method::ALL {
            assert_eq!(Method::from_name(method.name()), Some(method));
            assert_eq!(method.name().parse::<Method>().unwrap(), method);
            assert_eq!(method.to_string(), method.name());
            let same = METHODS.iter().filter(|r| r.name == method.name()).count();
            assert_eq!(same, 1, "{} is not unique", method.name());
        }
        assert!("euler".parse::<Method>().is_err());
    }

    #[test]
    fn integrator_names_match_the_registry() {
        for method in Method::ALL {
            let step = match method.step_kind() {
                StepKind::Fixed => Step::Fixed(0.1),
                StepKind::Adaptive => Step::Tolerance(1e-6),
                StepKind::AtSamples => Step::AtSamples,
            };
            assert_eq!(method.integrator(step).unwrap().name(), method.name());
        }
    }

    #[test]
    fn step_errors_name_dt_and_tol_not_flags() {
        let e = Method::Rk4.step(None, None).unwrap_err().to_string();
        assert!(e.starts_with("dt: "), "{e}");
        let e = Method::Dopri.step(None, None).unwrap_err().to_string();
        assert!(e.starts_with("tol: "), "{e}");
        let e = Method::Dopri.step(Some(0.1), None).unwrap_err().to_string();
        assert!(
            e.starts_with("dt: ") && e.contains("give tol, not dt"),
            "{e}"
        );
        let e = Method::Rk4.step(Some(-1.0), None).unwrap_err().to_string();
        assert!(e.starts_with("dt: ") && !e.contains("--"), "{e}");
        let e = Method::Exact
            .step(None, Some(1e-3))
            .unwrap_err()
            .to_string();
        assert!(e.starts_with("tol: "), "{e}");
        assert_eq!(Method::Exact.step(None, None).unwrap(), Step::AtSamples);
        assert!(Method::Rk4.integrator(Step::Tolerance(1.0)).is_err());
        assert!(Method::Dopri.integrator(Step::Tolerance(0.0)).is_err());
    }

    /// The tolerance's range and the subnormal step are the rule book's, not only the
    /// command's: a program calling the library meets the same rules.
    #[test]
    fn the_rule_book_bounds_the_tolerance_and_refuses_subnormal_steps() {
        let e = Method::Dopri
            .step(None, Some(1e-15))
            .unwrap_err()
            .to_string();
        assert_eq!(
            e,
            "tol: the tolerance must be between 1e-14 and 1, got 1e-15"
        );
        assert!(Method::Dopri.step(None, Some(2.0)).is_err());
        assert_eq!(
            Method::Dopri.step(None, Some(1e-14)).unwrap(),
            Step::Tolerance(1e-14)
        );
        let e = Method::Rk4
            .step(Some(1e-310), None)
            .unwrap_err()
            .to_string();
        assert!(e.starts_with("dt: ") && e.contains("normal number"), "{e}");
        let e = Method::Rk4
            .step(Some(f64::NAN), None)
            .unwrap_err()
            .to_string();
        assert_eq!(e, "dt: the step size must be positive and finite, got NaN");
        assert_eq!(Method::Rk4.given_step(None, None).unwrap(), None);
        assert_eq!(
            Method::Exact.given_step(None, None).unwrap(),
            Some(Step::AtSamples)
        );
    }
}
