//! `Even::log` near -1 (issue 34, item 3). Over `Dual64` the derivative of
//! `log(exp(pi e12) exp(t e12))` at `t = 0` came out `0` instead of `e12` (pi in `f64` is
//! just under pi), and `1e-10` from -1 it was off by 4e-6: the weight `atan2(m, c) / m`
//! times `P` differentiates to the difference of two terms of size `pi / m`. Here, in G2,
//! G3 and G4:
//!
//! - along the rotation's own plane the derivative is `e12` exactly, checked against
//!   central differences of the `f64` log (unwrapped by the full turn it jumps by when
//!   the angle crosses pi);
//! - across it, against the derivative of the logarithm on the rotation group,
//!   `dB = D_par + theta cot(theta) D_anti + theta N D_anti` for `R = exp(theta N) exp(t D)`
//!   with `D_par` and `D_anti` the parts of `D` that commute and anticommute with `N`
//!   (the inverse of the exponential's differential, `z / (1 - exp(-z))` at
//!   `z = ad(theta N)`), its products taken in the slow reference algebra; where the step
//!   stays on one branch also against central differences;
//! - exactly at -1 (`P` zero, with a derivative), the derivative of the branch taken;
//! - and the `f64` values near -1 against `(pi - delta) N` for `R = -cos(delta) +
//!   sin(delta) N`, which is that rotor's logarithm by construction.

use ga_core::num_dual::Dual64;
use ga_tests::blade::blades_of_grades;
use ga_tests::reference::Algebra;
use std::f64::consts::PI;

/// The step of the central differences; Richardson's extrapolation of `h` and `2h` leaves
/// an error of order `h^4` times the fifth derivative and `u |f| / h` of rounding.
const H: f64 = 1e-4;

/// `(8 (f(h) - f(-h)) - (f(2h) - f(-2h))) / 12h`, per component.
fn richardson(f: &dyn Fn(f64) -> Vec<f64>, h: f64) -> Vec<f64> {
    let (p1, m1, p2, m2) = (f(h), f(-h), f(2.0 * h), f(-2.0 * h));
    (0..p1.len())
        .map(|k| (8.0 * (p1[k] - m1[k]) - (p2[k] - m2[k])) / (12.0 * h))
        .collect()
}

/// `actual` within `tolerance` of `expected`, relative to each component's size (at
/// least 1).
fn assert_near(what: &str, actual: &[f64], expected: &[f64], tolerance: f64) {
    assert_eq!(actual.len(), expected.len(), "{what}");
    for (k, (a, e)) in actual.iter().zip(expected).enumerate() {
        assert!(
            (a - e).abs() <= tolerance * e.abs().max(1.0),
            "{what}: component {k}: {a} against {e} (all: {actual:?} against {expected:?})"
        );
    }
}

/// The derivative of the logarithm at `R = exp(theta N) exp(t D)`, `t = 0`, for a unit
/// basis plane `N` (`N N = -1`), from the reference algebra: `D_par + theta cot(theta)
/// D_anti + theta N D_anti`, in the canonical order of the bivectors.
fn log_derivative(metric: &[i8], theta: f64, plane: usize, d: &[f64]) -> Vec<f64> {
    let algebra = Algebra::new(metric);
    let blades = blades_of_grades(metric.len(), &[2]);
    let d = algebra.from_components(&blades, d);
    let n = algebra.basis(plane, 1.0);
    let ndn = algebra.geometric(&algebra.geometric(&n, &d), &n);
    // N D N is D on the commuting part and -D on the anticommuting part (N^-1 = -N).
    let parallel = algebra.scale(&algebra.sub(&d, &ndn), 0.5);
    let anti = algebra.scale(&algebra.add(&d, &ndn), 0.5);
    let turned = algebra.geometric(&n, &anti);
    let value = algebra.add(
        &parallel,
        &algebra.add(
            &algebra.scale(&anti, theta * theta.cos() / theta.sin()),
            &algebra.scale(&turned, theta),
        ),
    );
    algebra.components(&value, &blades)
}

/// The derivative tests for one algebra: `$d` over `Dual64`, `$r` in `f64`, `$metric`
/// its squares and `$across` bivectors that leave the plane `e12` (commuting with it or
/// not).
macro_rules! near_minus_one {
    ($name:ident, dual = $($d:ident)::+, real = $($r:ident)::+, metric = $metric:expr,
     across = [$($across:expr),* $(,)?] $(,)?) => {
        mod $name {
            use super::*;
            use $($d)::+ as d;
            use $($r)::+ as r;

            const NB: usize = r::Bivector::LEN;

            /// `cos(theta) + sin(theta) e12`, built from its components rather than by
            /// `exp`, whose rounding can carry an angle of `pi` in `f64` past pi.
            fn dual_start(theta: f64) -> d::Even {
                let mut array = [Dual64::from(0.0); r::Even::LEN];
                array[0] = Dual64::from(theta.cos());
                array[1] = Dual64::from(theta.sin());
                d::Even::from_array(array)
            }

            /// The same in `f64`.
            fn real_start(theta: f64) -> r::Even {
                let mut array = [0.0; r::Even::LEN];
                array[0] = theta.cos();
                array[1] = theta.sin();
                r::Even::from_array(array)
            }

            /// `exp(theta e12) exp(t D)` over dual numbers, `t` the dual unit.
            fn dual_log(theta: f64, direction: &[f64]) -> Vec<Dual64> {
                let start = dual_start(theta);
                let t = Dual64::from(0.0).derivative();
                let dir = d::Bivector::from_array(
                    direction
                        .iter()
                        .map(|&x| Dual64::from(x))
                        .collect::<Vec<_>>()
                        .try_into()
                        .unwrap(),
                );
                let log = (start * (dir * t).exp()).log().expect("a rotor");
                log.to_array().to_vec()
            }

            /// The same in `f64` at `t`, the in-plane component moved by a full turn
            /// where the angle crossed pi (the logarithm's two sides of the cut differ by
            /// `2 pi e12`, nothing else).
            fn real_log(theta: f64, direction: &[f64], t: f64) -> Vec<f64> {
                let start = real_start(theta);
                let dir = r::Bivector::from_array(direction.try_into().unwrap());
                let mut log = (start * (dir * t).exp())
                    .log()
                    .expect("a rotor")
                    .to_array()
                    .to_vec();
                if theta > 2.0 && log[0] < 0.0 {
                    log[0] += 2.0 * PI;
                }
                log
            }

            fn e12() -> Vec<f64> {
                let mut v = vec![0.0; NB];
                v[0] = 1.0;
                v
            }

            /// The finding: at pi in `f64` and `1e-10` from -1, and at angles that reach
            /// the new branch from further away.
            #[test]
            fn in_plane_derivative_is_the_plane() {
                for theta in [PI, PI - 1e-10, PI - 1e-6, 3.0, 2.0, 1.0] {
                    let dual = dual_log(theta, &e12());
                    let eps: Vec<f64> = dual.iter().map(|x| x.eps).collect();
                    let fd = richardson(&|t| real_log(theta, &e12(), t), H);
                    assert_near(&format!("theta {theta}: against e12"), &eps, &e12(), 1e-12);
                    assert_near(&format!("theta {theta}: against differences"), &eps, &fd, 1e-9);
                    let values: Vec<f64> = dual.iter().map(|x| x.re).collect();
                    assert_near(&format!("theta {theta}: value"), &values, &real_log(theta, &e12(), 0.0), 1e-14);
                }
            }

            /// Across the plane, where the derivative grows like `1/delta` near -1.
            #[test]
            fn derivative_across_the_plane_is_the_group_logarithm() {
                let across: Vec<Vec<f64>> = vec![$($across.to_vec()),*];
                for direction in &across {
                    for theta in [PI, PI - 1e-10, PI - 1e-6, 3.0, 2.5, 2.0, 1.0] {
                        let eps: Vec<f64> = dual_log(theta, direction).iter().map(|x| x.eps).collect();
                        let expected = log_derivative(&$metric, theta, 0b11, direction);
                        assert_near(&format!("theta {theta}, D {direction:?}"), &eps, &expected, 1e-9);
                        if PI - theta > 0.1 {
                            let fd = richardson(&|t| real_log(theta, direction, t), H);
                            assert_near(&format!("theta {theta}, D {direction:?}: differences"), &eps, &fd, 1e-8);
                        }
                    }
                }
            }

            /// `R = -exp(t e12)`: `P` is exactly zero at `t = 0`, the branch of `log(-1)`,
            /// and its derivative `e12` must survive that branch (it was 0).
            #[test]
            fn at_minus_one_the_derivative_survives() {
                let t = Dual64::from(0.0).derivative();
                let dual = ((d::Bivector::E12 * t).exp() * Dual64::from(-1.0)).log().expect("a rotor");
                let eps: Vec<f64> = dual.to_array().iter().map(|x| x.eps).collect();
                let real = |t: f64| {
                    let mut log = ((r::Bivector::E12 * t).exp() * -1.0).log().unwrap().to_array().to_vec();
                    if log[0] < 0.0 {
                        log[0] += 2.0 * PI;
                    }
                    log
                };
                assert_near("-exp(t e12)", &eps, &e12(), 1e-15);
                assert_near("-exp(t e12): differences", &eps, &richardson(&real, H), 1e-9);
            }
        }
    };
}

near_minus_one!(
    g2,
    dual = ga_tests::dual_algebras::g2,
    real = ga_core::f64::g2,
    metric = [1, 1],
    across = [],
);
near_minus_one!(
    g3,
    dual = ga_core::dual64::g3,
    real = ga_core::f64::g3,
    metric = [1, 1, 1],
    across = [[0.0, 1.0, 0.0], [0.0, 0.6, -0.8], [0.3, -0.5, 0.7]],
);
// G4's bivectors e12, e13, e14, e23, e24, e34: e34 commutes with e12, the rest of the
// last three anticommute.
near_minus_one!(
    g4,
    dual = ga_tests::dual_algebras::g4,
    real = ga_core::f64::g4,
    metric = [1, 1, 1, 1],
    across = [
        [0.0, 0.0, 0.0, 0.0, 0.0, 1.0],
        [0.0, 0.6, 0.0, 0.0, -0.8, 0.0],
        [0.3, -0.5, 0.2, 0.7, 0.1, -0.4],
    ],
);

/// G3 exactly at -1 moved out of the plane the branch chose (`D = e13`): the value is
/// `pi e12` but on either side the logarithm is `(t -+ pi) e13`, whose derivative `e13` the
/// branch's `P / c` carries.
#[test]
fn g3_at_minus_one_out_of_the_chosen_plane() {
    use ga_core::dual64::g3 as d;
    let t = Dual64::from(0.0).derivative();
    let log = ((d::Bivector::E13 * t).exp() * Dual64::from(-1.0))
        .log()
        .expect("a rotor");
    let eps: Vec<f64> = log.to_array().iter().map(|x| x.eps).collect();
    assert_near("-exp(t e13)", &eps, &[0.0, 1.0, 0.0], 1e-15);
    for h in [1e-3, -1e-3] {
        let moved = ((ga_core::f64::g3::Bivector::E13 * h).exp() * -1.0)
            .log()
            .unwrap();
        let slope = (moved.e13 - h.signum() * -PI) / h;
        assert!(
            (slope - 1.0).abs() <= 1e-9,
            "one-sided slope {slope} at {h}"
        );
    }
}

/// `R = -cos(delta) + P` with `P = sin(delta) N` for unit planes `N` has the logarithm
/// `(pi - delta) N` by construction, for `delta` from 0.1 down to a subnormal `P`. The
/// direction expected is that of `P` as rounded (scaled by a power of two, which is exact,
/// and divided by its length), so that a subnormal `P`'s few digits are not charged to the
/// logarithm; the tolerance is a few units of `pi`, or of the last digit of a subnormal
/// `P`'s components relative to its size.
#[test]
fn values_near_minus_one_are_the_constructed_angle() {
    let deltas: [f64; 7] = [0.1, 1e-5, 1e-10, 1e-17, 1e-150, 1e-300, 1e-310];
    let check = |what: &str, log: &[f64], p: &[f64], delta: f64| {
        let size = p.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
        let power = if size < 1e-200 { 2f64.powi(700) } else { 1.0 };
        let scaled: Vec<f64> = p.iter().map(|x| x * power).collect();
        let length = scaled.iter().map(|x| x * x).sum::<f64>().sqrt();
        let expected: Vec<f64> = scaled.iter().map(|x| (PI - delta) * x / length).collect();
        let digit = (f64::from_bits(1) / size).max(f64::EPSILON);
        for (k, (a, e)) in log.iter().zip(&expected).enumerate() {
            assert!(
                (a - e).abs() <= 8.0 * digit * PI,
                "{what}, delta {delta}: component {k}: {a} against {e}"
            );
        }
    };
    for delta in deltas {
        let (c, s) = (-delta.cos(), delta.sin());
        for sign in [1.0, -1.0] {
            let r = ga_core::f64::g2::Even::new(c, sign * s);
            check("g2", &r.log().unwrap().to_array(), &[sign * s], delta);
        }
        // (2, -3, 6) / 7 is a unit plane; in G4 the same plane, and e14.
        let n3 = [2.0 / 7.0, -3.0 / 7.0, 6.0 / 7.0];
        let r = ga_core::f64::g3::Even::new(c, s * n3[0], s * n3[1], s * n3[2]);
        check(
            "g3",
            &r.log().unwrap().to_array(),
            &r.to_array()[1..],
            delta,
        );
        for n4 in [
            [2.0 / 7.0, -3.0 / 7.0, 0.0, 6.0 / 7.0, 0.0, 0.0],
            [0.0, 0.0, 1.0, 0.0, 0.0, 0.0],
        ] {
            let mut array = [0.0; 8];
            array[0] = c;
            for k in 0..6 {
                array[k + 1] = s * n4[k];
            }
            let r = ga_core::f64::g4::Even::from_array(array);
            check("g4", &r.log().unwrap().to_array(), &array[1..7], delta);
        }
    }
}
