//! The free flow's three turns about body axes, divided form: each turn divides the body
//! momentum by its squared norm as it goes, with the clamps that keep any input finite
//! (`split.rs`'s limits). It runs wherever the division-free form (`projective.rs`) may
//! not: long steps, fast bodies, overflowing or NaN input.
//!
//! A turn by `2 atan2(b, p)`, `p = e - lambda b^2`, about the body axis `e_K` is the
//! quaternion `p + b e_K` up to a positive scale, and turns the momentum by
//! `cos = (p^2 - b^2)/(p^2 + b^2)`, `sin = 2 p b/(p^2 + b^2)` (the Cayley transform): no
//! sine or cosine (docs/derivations/corrected-splitting.md).

use super::inertia::Inertia;
use super::rates::Rates;
use super::real::Real;
use super::rotation::{turn_body_about, V};
use super::turning::Turning;

/// The turn `p + b e_K` for the linear half-angle `b` (limited to `limit` where
/// `CLAMP`), `p = e - lambda b^2`: `p`, `b`, `b^2` and the squared norm `p^2 + b^2`.
#[inline(always)]
fn cayley_turn<R: Real, const CLAMP: bool>(b: R, limit: R, cubic: R, e: R) -> (R, R, R, R) {
    let b = if CLAMP {
        b.min_or(limit).max_or(-limit)
    } else {
        b
    };
    // `opaque`: one body's chain stays scalar (see `Real::opaque`).
    let t = (b * b).opaque();
    let p = (e - (t * cubic).opaque()).opaque();
    let norm = ((p * p).opaque() + t).opaque();
    (p, b, t, norm)
}

/// A turn about the body axis `K` by the linear half-angle `b` (not yet limited):
/// `q -> q (p + b e_K)` (not normalised), the body momentum turned back by it, the next
/// turn's `b`, `rate` times the turned momentum's component `N`, and the turn's squared
/// norm `p^2 + b^2` (the factor `q`'s squared norm grew by).
///
/// The momentum turns by `cos = (p^2 - b^2) / n` and `sin = 2 p b / n`. The division by
/// `n` is applied last, to the turned components and to the next `b`, so that it runs
/// beside their products rather than before them.
// Inlined only when optimised (see "Unoptimised builds" in `splitting.rs`).
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline)]
#[allow(clippy::too_many_arguments)]
fn body_turn<R: Real, T: Turning<R>, const K: usize, const N: usize, const CLAMP: bool>(
    q: T,
    body: V<R>,
    b: R,
    (limit, cubic, e): (R, R, R),
    rate: R,
) -> (T, V<R>, R, R) {
    let (p, b, t, norm) = cayley_turn::<R, CLAMP>(b, limit, cubic, e);
    let cos_n = ((p * p).opaque() - t).opaque();
    let sin_n = ((p + p) * b).opaque();
    let r = (R::splat(1.0) / norm).opaque();
    let turned = turn_body_about(K, cos_n, sin_n, body);
    let turned = V {
        x: turned.x.opaque(),
        y: turned.y.opaque(),
        z: turned.z.opaque(),
    };
    let next = ((rate * turned.get(N)) * r).opaque();
    let body = match K {
        0 => V {
            x: turned.x,
            y: turned.y * r,
            z: turned.z * r,
        },
        1 => V {
            x: turned.x * r,
            y: turned.y,
            z: turned.z * r,
        },
        _ => V {
            x: turned.x * r,
            y: turned.y * r,
            z: turned.z,
        },
    };
    (q.turned_about::<K>(p, b), body, next, norm)
}

/// The free flow's three turns `x(h/2) y(h) x(h/2)` from `q_p` (principal axes in the
/// split's order to world, unit) and the body momentum `body` (the world momentum seen
/// from `q_p`), divided form: the result scaled by a positive number, and the product of
/// the turns' squared norms. `CLAMP` limits each turn's `b`; the caller may leave it out
/// where no `b` can reach the limit (the same bits).
// Inlined only when optimised (see "Unoptimised builds" in `splitting.rs`).
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline)]
pub(crate) fn free_flow<R: Real, T: Turning<R>, const CLAMP: bool>(
    inertia: &Inertia<R>,
    rates: &Rates<R>,
    q_p: T,
    body: V<R>,
) -> (T, R) {
    let split = &inertia.split;
    let (outer_limit, middle_limit) = split.limits();
    let outer = (outer_limit, split.outer_cubic, rates.outer_e);
    let middle = (middle_limit, split.middle_cubic, rates.middle_e);
    let b1 = rates.outer * body.x;
    let (q, body, b2, n1) = body_turn::<R, T, 0, 1, CLAMP>(q_p, body, b1, outer, rates.middle);
    let (q, _, b3, n2) = body_turn::<R, T, 1, 0, CLAMP>(q, body, b2, middle, rates.outer);
    // The last turn needs only its quaternion and its norm.
    let (p, b, _, n3) = cayley_turn::<R, CLAMP>(b3, outer.0, outer.1, outer.2);
    (q.turned_about::<0>(p, b), (n1 * n2) * n3)
}

#[cfg(all(test, feature = "std"))]
mod tests {
    use super::*;
    use crate::rotation::Q;

    /// The angle `body_turn` turns the momentum by, from its cosine and sine, and the
    /// one its quaternion turns by, for the linear half-angle `b`, `lambda` and `e`.
    fn turn_angle(b: f64, cubic: f64, e: f64) -> (f64, f64) {
        let body = V {
            x: 1.0,
            y: 1.0,
            z: 0.0,
        };
        let (q, turned, _, _) =
            body_turn::<f64, Q<f64>, 0, 1, true>(Q::identity(), body, b, (64.0, cubic, e), 0.0);
        // The body momentum (., 1, 0) turned about e1 to (., c, -s).
        let from_momentum = (-turned.z).atan2(turned.y);
        let from_quaternion = 2.0 * q.x.atan2(q.w);
        (from_momentum, from_quaternion)
    }

    #[test]
    fn a_turn_is_by_twice_atan2_of_b_over_e_minus_lambda_b_squared() {
        for i in -100..=100 {
            // Half-angles up to 0.5 rad. With lambda = 1/3 and e = 1 the angle is 2b to
            // fifth order: 2 atan(b / (1 - b^2/3)) = 2b - 2b^5/45 + O(b^7).
            let b = f64::from(i) * 0.005;
            let (by_momentum, by_quaternion) = turn_angle(b, 1.0 / 3.0, 1.0);
            let bound = 2.0 * b.powi(5).abs() / 45.0 * 1.1 + 1e-15;
            assert!((by_momentum - 2.0 * b).abs() <= bound, "{b}: {by_momentum}");
            assert!((by_quaternion - by_momentum).abs() <= 1e-15, "{b}");
            for (cubic, e) in [(-0.3, 1.02), (5.7, 0.97), (0.0, 1.0)] {
                let (by_momentum, by_quaternion) = turn_angle(b, cubic, e);
                let exact = 2.0 * b.atan2(e - cubic * b * b);
                // Angles past a half turn wrap: compare on the circle.
                let apart = |x: f64, y: f64| (x - y).sin().abs() + (1.0 - (x - y).cos());
                assert!(apart(by_momentum, exact) <= 2e-15, "{b} {cubic} {e}");
                assert!(apart(by_quaternion, exact) <= 2e-15, "{b} {cubic} {e}");
            }
        }
    }
    #[test]
    fn huge_and_nan_angles_give_a_finite_unit_turn() {
        for (limit, cubic) in [(64.0, 1.0 / 3.0), (0.036, 1e6), (64.0, -0.3)] {
            for a in [1e30, -1e300, f64::MAX, f64::INFINITY, f64::NAN] {
                let body = V {
                    x: a,
                    y: 1.0,
                    z: 0.0,
                };
                let (_, turned, _, _) = body_turn::<f64, Q<f64>, 0, 1, true>(
                    Q::identity(),
                    body,
                    a,
                    (limit, cubic, 1.0),
                    0.0,
                );
                let (c, s) = (turned.y, -turned.z);
                assert!(c.is_finite() && s.is_finite(), "{a}");
                assert!((c * c + s * s - 1.0).abs() < 1e-15, "{a}");
            }
        }
    }
}
