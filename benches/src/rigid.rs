//! Rigid-body bench support: the test bodies of `docs/references.md`, Euler's equations in
//! matrix form for ode_solvers' Dop853 (the peer in the work-precision race), the attitude
//! error of a rotation matrix, and the searches that find each method's cheapest setting
//! for a target error, run once before anything is timed.
//!
//! The criterion group and function names live here too, so that `benches/rigid.rs` and
//! [`crate::summary`] cannot disagree about them.

use ga_core::f64::g3::{Bivector, Rotor, Sandwich, Vector};
use ga_rigid::dynamics::{omega_from_vector, Gravity, RigidBody, State};
use ode_solvers::dop_shared::{IntegrationError, Stats};
use ode_solvers::{Dop853, OutputType, SVector, System};

/// Closed-form evaluation against one RK4 step, per item of a batch.
pub const TOP_GROUP: &str = "rigid/symmetric_top/f64/batch";
/// `SymmetricTop::rotor(t)` in [`TOP_GROUP`].
pub const CLOSED_FORM: &str = "closed-form rotor";
/// `Rk4::step_once` in [`TOP_GROUP`] and [`STEP_GROUP`].
pub const RK4_STEP: &str = "rk4 step";
/// One step of each method along a trajectory of the Hairer-Vilmart body, per step.
pub const STEP_GROUP: &str = "rigid/step/f64/chain";
/// 10^6 symmetric tops evaluated at one time, per top.
pub const MILLION_GROUP: &str = "rigid/symmetric_top_1e6/f64/batch";
/// The race to [`RACE_TARGET`] at t = [`RACE_T_END`] on the Hairer-Lubich-Wanner body,
/// per integration from t = 0.
pub const RACE_GROUP: &str = "rigid/reach_1e-10/f64/hlw_t10";
/// The geometric-algebra time-stepping methods of the race, each at its cheapest setting.
pub const RACE_GA_METHODS: [&str; 9] = [
    "rk4",
    "lie-rk4",
    "dopri5",
    "splitting",
    "splitting-4",
    "splitting-6",
    "splitting-8",
    "lie-dop853",
    "lie-dop853-cayley",
];
/// ode_solvers' Dop853 on the matrix form, in [`RACE_GROUP`].
pub const RACE_PEER: &str = "ode_solvers dop853";

/// The attitude error every contender of the race must reach, in radians.
pub const RACE_TARGET: f64 = 1e-10;
/// The end time of the race.
pub const RACE_T_END: f64 = 10.0;

/// The race to [`RACE_TARGET`] at t = [`HEAVY_T_END`] on the report's heavy top (a
/// Lagrange top: no exact flow, a closed-form free flow), per integration from t = 0.
pub const HEAVY_GROUP: &str = "rigid/reach_1e-10/f64/heavy_top_t4";
/// The geometric-algebra methods of the heavy-top race.
pub const HEAVY_GA_METHODS: [&str; 11] = [
    "rk4",
    "lie-rk4",
    "dopri5",
    "splitting",
    "splitting-4",
    "splitting-8",
    "exact-splitting",
    "exact-splitting-4",
    "exact-splitting-6",
    "exact-splitting-8",
    "lie-dop853",
];
/// The end time of the heavy-top race (the report's).
pub const HEAVY_T_END: f64 = 4.0;
/// The report's heavy top: moments (1, 1, 0.5) about the pivot.
pub const HEAVY_MOMENTS: [f64; 3] = [1.0, 1.0, 0.5];
/// Its centre of mass, 0.5 up the symmetry axis (body frame).
pub const HEAVY_COM: [f64; 3] = [0.0, 0.0, 0.5];
/// Its weight `m g` in the space frame (mass 1).
pub const HEAVY_WEIGHT: [f64; 3] = [0.0, 0.0, -9.81];
/// Its spin about the symmetry axis at t = 0, rad/s.
pub const HEAVY_SPIN: f64 = 20.0;
/// Its tilt at t = 0: a turn by 0.3 rad in the e23 plane.
pub const HEAVY_TILT: f64 = 0.3;

/// The report's heavy top as a library body and its state at t = 0.
#[must_use]
pub fn heavy_top() -> (RigidBody, State) {
    let [gx, gy, gz] = HEAVY_WEIGHT;
    let [cx, cy, cz] = HEAVY_COM;
    let body = RigidBody::new(HEAVY_MOMENTS)
        .expect("physical moments")
        .with_torque(Gravity {
            mass: 1.0,
            g: Vector::new(gx, gy, gz),
            com_offset: Vector::new(cx, cy, cz),
        });
    let state = State {
        rotor: (Bivector::E23 * (-0.5 * HEAVY_TILT)).exp(),
        omega: omega_from_vector([0.0, 0.0, HEAVY_SPIN]),
    };
    (body, state)
}

/// The heavy top in matrix form for Dop853: [`EulerMatrix`] plus the gravity couple
/// `tau = c x (M^T (m g))`, linear in `M`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HeavyMatrix {
    free: EulerMatrix,
}

impl HeavyMatrix {
    /// The report's heavy top.
    #[must_use]
    pub fn new() -> Self {
        HeavyMatrix {
            free: EulerMatrix::new(HEAVY_MOMENTS),
        }
    }

    /// `M(0)` and `m(0)` of [`heavy_top`].
    #[must_use]
    pub fn initial() -> MatrixState {
        let (_, state) = heavy_top();
        let mut y = MatrixState::zeros();
        for (i, entry) in rotation_matrix(state.rotor).into_iter().enumerate() {
            y[i] = entry;
        }
        y[11] = HEAVY_MOMENTS[2] * HEAVY_SPIN;
        y
    }
}

impl Default for HeavyMatrix {
    fn default() -> Self {
        Self::new()
    }
}

impl System<f64, MatrixState> for HeavyMatrix {
    #[inline]
    fn system(&self, t: f64, y: &MatrixState, dy: &mut MatrixState) {
        self.free.system(t, y, dy);
        let f: [f64; 3] =
            std::array::from_fn(|c| (0..3).map(|r| y[3 * r + c] * HEAVY_WEIGHT[r]).sum());
        let tau = cross(HEAVY_COM, f);
        for k in 0..3 {
            dy[9 + k] += tau[k];
        }
    }
}

/// Dop853 on [`HeavyMatrix`] over `[0, t_end]` with `rtol = atol = tol`: the end state
/// and ode_solvers' counts.
pub fn dop853_heavy(t_end: f64, tol: f64) -> Result<(MatrixState, Stats), IntegrationError> {
    let mut stepper = Dop853::new(
        HeavyMatrix::new(),
        0.0,
        t_end,
        t_end,
        HeavyMatrix::initial(),
        tol,
        tol,
    );
    stepper.set_output(OutputType::Sparse);
    let stats = stepper.integrate()?;
    let end = *stepper
        .y_out()
        .last()
        .expect("the initial state is always kept");
    Ok((end, stats))
}

/// The attitude error of a rotor against a reference matrix, `|M(R) - M_ref|_F / sqrt 2`
/// (the measure of [`matrix_attitude_error`], so that both sides of the heavy-top race
/// are measured alike).
#[must_use]
pub fn rotor_matrix_error(rotor: Rotor, reference: &MatrixState) -> f64 {
    let m = rotation_matrix(rotor);
    let squared: f64 = (0..9).map(|i| (m[i] - reference[i]).powi(2)).sum();
    (0.5 * squared).sqrt()
}

/// Hairer-Lubich-Wanner's body (*Geometric Numerical Integration*): moments (2, 1, 2/3).
pub const HLW_MOMENTS: [f64; 3] = [2.0, 1.0, 2.0 / 3.0];
/// Hairer-Lubich-Wanner's `R(10)` from `R(0) = 1`, `[s, e12, e13, e23]` with `s >= 0`
/// (docs/references.md; twelve decimals).
pub const HLW_ROTOR_AT_10: [f64; 4] = [
    0.765_111_030_829,
    -0.513_722_699_054,
    0.102_854_131_455,
    -0.374_319_551_483,
];
/// Hairer-Vilmart's body (the DMV driver): moments (0.6, 0.8, 1.0).
pub const HV_MOMENTS: [f64; 3] = [0.6, 0.8, 1.0];
/// Hairer-Vilmart's `m(0)`.
pub const HV_MOMENTUM: [f64; 3] = [1.8, 0.4, -0.9];
/// Principia's symmetric "short fat" top: moments (3, 3, 9).
pub const SHORT_FAT_MOMENTS: [f64; 3] = [3.0, 3.0, 9.0];
/// The short fat top's `m(0)`; then `m(t) = (5 sin wt, 5 cos wt, 7)` with `w = -14/9`.
pub const SHORT_FAT_MOMENTUM: [f64; 3] = [0.0, 5.0, 7.0];

/// Hairer-Lubich-Wanner's `m(0) = (cos 1.1, 0, sin 1.1)`.
#[must_use]
pub fn hlw_momentum() -> [f64; 3] {
    [1.1f64.cos(), 0.0, 1.1f64.sin()]
}

/// The state with `R(0) = 1` and body momentum `m` on a body with these moments.
#[must_use]
pub fn initial_state(moments: [f64; 3], m: [f64; 3]) -> State {
    State {
        rotor: Rotor::ONE,
        omega: omega_from_vector([0, 1, 2].map(|k| m[k] / moments[k])),
    }
}

/// A torque-free body with these moments (unphysical ones allowed: the literature's test
/// bodies need not satisfy the triangle inequality).
///
/// # Panics
/// If a moment is not finite and positive.
#[must_use]
pub fn body(moments: [f64; 3]) -> RigidBody {
    RigidBody::new_unphysical(moments).expect("finite positive moments")
}

/// The state of Euler's equations in matrix form: the body-to-space rotation `M` row by
/// row (entries 0..9), then the body momentum `m` (entries 9..12).
pub type MatrixState = SVector<f64, 12>;

/// Euler's equations of the free body in matrix form, the textbook way a general ODE
/// solver is handed a rigid body: `dM/dt = M [w]x`, `dm/dt = m x w`, `w = J^-1 m`. Row `r`
/// of `M [w]x` is `M_r x w`, so the right-hand side is four cross products.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EulerMatrix {
    inverse_moments: [f64; 3],
}

impl EulerMatrix {
    /// The equations of a body with principal moments `moments`.
    #[must_use]
    pub fn new(moments: [f64; 3]) -> Self {
        EulerMatrix {
            inverse_moments: moments.map(|i| 1.0 / i),
        }
    }

    /// `M = 1` and body momentum `m`.
    #[must_use]
    pub fn initial(m: [f64; 3]) -> MatrixState {
        let mut y = MatrixState::zeros();
        y[0] = 1.0;
        y[4] = 1.0;
        y[8] = 1.0;
        y[9] = m[0];
        y[10] = m[1];
        y[11] = m[2];
        y
    }
}

#[inline]
fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

impl System<f64, MatrixState> for EulerMatrix {
    #[inline]
    fn system(&self, _t: f64, y: &MatrixState, dy: &mut MatrixState) {
        let m = [y[9], y[10], y[11]];
        let [j1, j2, j3] = self.inverse_moments;
        let w = [m[0] * j1, m[1] * j2, m[2] * j3];
        for row in 0..4 {
            let a = if row < 3 {
                [y[3 * row], y[3 * row + 1], y[3 * row + 2]]
            } else {
                m
            };
            let d = cross(a, w);
            dy[3 * row] = d[0];
            dy[3 * row + 1] = d[1];
            dy[3 * row + 2] = d[2];
        }
    }
}

/// Dop853 on [`EulerMatrix`] from `M = 1` and momentum `m` over `[0, t_end]` with
/// `rtol = atol = tol`, keeping only the accepted steps (no dense output): the end state
/// and ode_solvers' counts.
pub fn dop853(
    moments: [f64; 3],
    m: [f64; 3],
    t_end: f64,
    tol: f64,
) -> Result<(MatrixState, Stats), IntegrationError> {
    let system = EulerMatrix::new(moments);
    let mut stepper = Dop853::new(system, 0.0, t_end, t_end, EulerMatrix::initial(m), tol, tol);
    stepper.set_output(OutputType::Sparse);
    let stats = stepper.integrate()?;
    let end = *stepper
        .y_out()
        .last()
        .expect("the initial state is always kept");
    Ok((end, stats))
}

/// The body-to-space rotation matrix of `rotor` (`y = R x ~R`), row by row.
#[must_use]
pub fn rotation_matrix(rotor: Rotor) -> [f64; 9] {
    let columns = [Vector::E1, Vector::E2, Vector::E3].map(|e| rotor.sandwich(e));
    std::array::from_fn(|i| {
        let v = columns[i % 3];
        [v.e1, v.e2, v.e3][i / 3]
    })
}

/// The attitude error of a matrix `M` against the rotation of `reference`:
/// `|M - M_ref|_F / sqrt 2`. For a rotation by `theta` away from the reference this is
/// `2 sin(theta / 2)`, the rotor angle of [`ga_rigid_cli::report::attitude_error`] to third
/// order; unlike the angle it also counts how far `M` has drifted from orthogonal, which a
/// general ODE solver does not preserve.
#[must_use]
pub fn matrix_attitude_error(y: &MatrixState, reference: Rotor) -> f64 {
    let m_ref = rotation_matrix(reference);
    let squared: f64 = (0..9).map(|i| (y[i] - m_ref[i]).powi(2)).sum();
    (0.5 * squared).sqrt()
}

/// The fewest steps `n` for which `error_of(n) <= target`, and that error, for an error that
/// falls as `n` grows: doubling from `start`, then bisection. `None` if `max_steps` do not
/// reach the target.
pub fn fewest_steps(
    target: f64,
    start: u64,
    max_steps: u64,
    mut error_of: impl FnMut(u64) -> f64,
) -> Option<(u64, f64)> {
    let mut lo = 0; // The largest n known to miss (0: none tried).
    let mut hi = start.max(1);
    let mut hi_error = error_of(hi);
    while hi_error > target {
        if hi >= max_steps {
            return None;
        }
        lo = hi;
        hi = (2 * hi).min(max_steps);
        hi_error = error_of(hi);
    }
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        let error = error_of(mid);
        if error <= target {
            (hi, hi_error) = (mid, error);
        } else {
            lo = mid;
        }
    }
    Some((hi, hi_error))
}

/// Tolerances from `1e-6` down to `1e-15`, twenty a decade, loosest first.
pub fn tolerance_grid() -> impl Iterator<Item = f64> {
    (120..=300).map(|k| 10f64.powf(-f64::from(k) / 20.0))
}

/// The loosest tolerance of [`tolerance_grid`] for which `error_of(tol) <= target`, and
/// that error; `None` if even `1e-15` misses. An error (the method failed) counts as a miss.
pub fn loosest_tolerance<E>(
    target: f64,
    mut error_of: impl FnMut(f64) -> Result<f64, E>,
) -> Option<(f64, f64)> {
    tolerance_grid().find_map(|tol| match error_of(tol) {
        Ok(error) if error <= target => Some((tol, error)),
        _ => None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use ga_rigid::integrators::{ExactFreeBody, Integrator};
    use ga_rigid_cli::report::attitude_error;

    fn published_hlw_rotor() -> Rotor {
        let [s, e12, e13, e23] = HLW_ROTOR_AT_10;
        Rotor::new(s, e12, e13, e23)
    }

    #[test]
    fn rotation_matrix_maps_vectors_like_the_sandwich() {
        let rotor = (Bivector::new(0.3, -1.1, 0.7)).exp();
        let m = rotation_matrix(rotor);
        let x = Vector::new(0.2, -0.5, 0.9);
        let y = rotor.sandwich(x);
        for (row, expected) in [y.e1, y.e2, y.e3].into_iter().enumerate() {
            let got = m[3 * row] * x.e1 + m[3 * row + 1] * x.e2 + m[3 * row + 2] * x.e3;
            assert!(
                (got - expected).abs() < 1e-15,
                "row {row}: {got} vs {expected}"
            );
        }
    }

    #[test]
    fn matrix_attitude_error_is_the_angle_for_small_rotations() {
        let reference = published_hlw_rotor();
        let theta = 1e-6;
        let turned = reference * (Bivector::new(0.0, 0.6, 0.8) * (-0.5 * theta)).exp();
        let mut y = EulerMatrix::initial([0.0; 3]);
        for (i, entry) in rotation_matrix(turned).into_iter().enumerate() {
            y[i] = entry;
        }
        let error = matrix_attitude_error(&y, reference);
        assert!((error - theta).abs() < 1e-6 * theta, "{error} vs {theta}");
        assert!((attitude_error(turned, reference) - theta).abs() < 1e-6 * theta);
    }

    #[test]
    fn dop853_on_the_matrix_form_reaches_the_published_attitude() {
        let (end, stats) = dop853(HLW_MOMENTS, hlw_momentum(), 10.0, 1e-13).unwrap();
        let error = matrix_attitude_error(&end, published_hlw_rotor());
        assert!(error < 2e-12, "attitude error {error:e} after {stats}");
        let m = [end[9], end[10], end[11]];
        let published = [0.407_066_136_588, 0.283_007_426_813, 0.868_449_167_662];
        for k in 0..3 {
            assert!((m[k] - published[k]).abs() < 2e-12, "m{k} = {}", m[k]);
        }
    }

    /// The matrix form of the heavy top against the library's own equations: one
    /// right-hand side evaluation agrees, so the race compares the same motion.
    #[test]
    fn heavy_matrix_rates_match_the_library() {
        let (body, state) = heavy_top();
        let y = HeavyMatrix::initial();
        let mut dy = MatrixState::zeros();
        HeavyMatrix::new().system(0.0, &y, &mut dy);
        let rate = body.omega_rate(0.0, &state);
        let w = ga_rigid::dynamics::omega_to_vector(rate);
        for k in 0..3 {
            let expected = HEAVY_MOMENTS[k] * w[k];
            assert!(
                (dy[9 + k] - expected).abs() < 1e-12,
                "{k}: {} vs {expected}",
                dy[9 + k]
            );
        }
        assert!(rotor_matrix_error(state.rotor, &y) < 1e-15);
    }

    #[test]
    fn exact_flow_matches_the_published_hlw_rotor() {
        let moments = HLW_MOMENTS;
        let initial = initial_state(moments, hlw_momentum());
        let end = ExactFreeBody::new()
            .advance(&body(moments), 0.0, initial, RACE_T_END)
            .unwrap();
        assert!(attitude_error(end.rotor, published_hlw_rotor()) < 2e-12);
    }

    #[test]
    fn fewest_steps_finds_the_threshold_of_a_falling_error() {
        // C / n^4 with C = 1: 1e-8 needs n = 100.
        let error = |n: u64| 1.0 / (n as f64).powi(4);
        assert_eq!(fewest_steps(1e-8, 1, 1 << 20, error), Some((100, 1e-8)));
        assert_eq!(fewest_steps(1e-8, 1000, 1 << 20, error).unwrap().0, 100);
        assert_eq!(fewest_steps(1e-8, 1, 50, error), None);
    }

    #[test]
    fn loosest_tolerance_takes_the_first_grid_point_that_reaches() {
        let found = loosest_tolerance(1e-10, |tol| Ok::<_, ()>(3.0 * tol)).unwrap();
        assert!(found.1 <= 1e-10 && found.1 * 10f64.powf(0.05) > 1e-10);
        assert_eq!(loosest_tolerance(1e-20, Ok::<_, ()>), None);
        assert_eq!(loosest_tolerance(1.0, |_| Err(())), None);
    }
}
