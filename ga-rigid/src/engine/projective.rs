//! The free flow's five turns without a division: the body momentum and each angle carried
//! as numerators over one common denominator, for the steps an engine takes.
//!
//! `splitting.rs` turns the body momentum by `cos = (p^2 - a^2)/n`, `sin = 2pa/n` and
//! divides by `n = p^2 + a^2` every turn; each turn's angle needs the last turn's
//! momentum, so those divisions sit one after another on the step's critical path. Here
//! the momentum is `X / D` and the angle parameter `b = B / D` (`b = a / sqrt 3` as in
//! `splitting.rs`), and a turn works on the numerators:
//!
//! - `P = D^2 - B^2` and `A = sqrt3 B D` are `p` and `a` times `D^2`, so the turn's
//!   quaternion `P + A e_K` is `p + a e_K` scaled by `D^2` (the scale goes with the
//!   normalisation at the end);
//! - `C = P^2 - A^2` and `S = 2 P A` are `cos` and `sin` times `D^4 n`, and
//!   `N = P^2 + A^2` is `D^4 n`;
//! - the turned components are `C X_i + S X_j`, the untouched one `N X_K`, all over the
//!   new denominator `D N`, and the next angle's numerator is `C (r X_i) + S (r X_j)`.
//!
//! That is the same map as `splitting.rs` (the same rational turns, so the step is as
//! symplectic and as symmetric), rounded differently, with no division until the
//! quaternion is normalised. The chain of a turn is `D^2`, `P`, `P^2`, `C`, a product and
//! a sum: about 16 cycles where the divided form takes about 21.
//!
//! The numerators grow: `D` is multiplied by `N ~ D^4 (1 + t + t^2)` each turn, with
//! `t = b^2`. Over the five turns every value stays below `g^781` times `|L|`, for
//! `g = 1 + t_max + t_max^2`, so the form is used only where `t <= FAST_T` (far above an
//! engine's 60 Hz steps: a turn of up to about 46 rad/s) and `|L| < 1e18`, where nothing
//! can overflow in `f32`; elsewhere `splitting.rs` turns with its clamps.

use super::inertia::Inertia;
use super::real::Real;
use super::rotation::{turn_body_about, V};
use super::splitting::{turn_rates, Turning, SQRT_3};

/// The largest `t = b^2` the projective form takes: `g = 1 + t + t^2 = 1.0525`, and
/// `g^781 < 3e17`, far from `f32::MAX`.
///
/// In that range the result stays in the starting quaternion's hemisphere, so it is
/// normalised without the hemisphere test (one dot product and a select fewer at the end
/// of the step's chain; `free_flow_normalized` in `splitting.rs`). The turn `P + A e_K`
/// has the half-angle `atan(sqrt3 b / (1 - b^2))`: at most 0.387 rad for the middle turn
/// (`b^2 <= FAST_T`) and 0.194 rad for the four others (their rate is half, so
/// `b^2 <= FAST_T / 4`). Half-angles are distances on the unit sphere of quaternions, so
/// the five turns move `q_p` by at most 1.16 rad there, and the result's dot product
/// with `q_p` is at least `cos 1.16 = 0.40` times their norms: the test would never
/// negate (a unit test checks it at the range's edge).
pub(crate) const FAST_T: f64 = 0.05;

/// The largest squared body momentum the projective form takes (`|L| < 1e18`): with
/// `D < g^156 < 3000`, no numerator reaches `1e22 |L|`.
pub(crate) const FAST_MOMENTUM2: f64 = 1e36;

/// One turn about the body axis `K` by `b = B / D`: the quaternion `q (P + A e_K)`, the
/// momentum's numerators turned, the next turn's `B` for the axis `N` at `rate`, the new
/// denominator, and `N = P^2 + A^2` (the factor `q`'s squared norm grew by).
// Inlined only when optimised (see "Unoptimised builds" in `splitting.rs`).
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline)]
fn turn<R: Real, T: Turning<R>, const K: usize, const N: usize>(
    q: T,
    x: V<R>,
    b: R,
    d: R,
    rate: R,
) -> (T, V<R>, R, R, R) {
    // `opaque`: one body's chain stays scalar (see `Real::opaque`).
    let (bb, dd) = ((b * b).opaque(), (d * d).opaque());
    let p = (dd - bb).opaque();
    let bd = (b * d).opaque();
    let a = (bd * R::splat(SQRT_3)).opaque();
    let (pp, aa) = ((p * p).opaque(), (a * a).opaque());
    let c = (pp - aa).opaque();
    let s = (p * (bd * R::splat(2.0 * SQRT_3))).opaque();
    let norm = (pp + aa).opaque();
    let turned = turn_body_about(K, c, s, x);
    // The next angle's numerator from the momentum scaled by its rate before the turn:
    // the rate's product runs beside the turn's, not after it.
    let scaled = V {
        x: rate * x.x,
        y: rate * x.y,
        z: rate * x.z,
    };
    let x = match K {
        0 => V {
            x: x.x * norm,
            y: turned.y,
            z: turned.z,
        },
        1 => V {
            x: turned.x,
            y: x.y * norm,
            z: turned.z,
        },
        _ => V {
            x: turned.x,
            y: turned.y,
            z: x.z * norm,
        },
    };
    let x = V {
        x: x.x.opaque(),
        y: x.y.opaque(),
        z: x.z.opaque(),
    };
    let next = turn_body_about(K, c, s, scaled).get(N).opaque();
    (
        q.turned_about::<K>(p, a),
        x,
        next,
        (d * norm).opaque(),
        norm,
    )
}

/// The free flow over `h` from `q_p` (unit up to rounding; `q_p2` its squared norm) and
/// the body momentum `body` (the world momentum seen from `q_p`), by the five turns
/// `1(h/2) 2(h/2) 3(h) 2(h/2) 1(h/2)` of `splitting.rs`: the rotation scaled by a
/// positive number, and its squared norm, `q_p2` times the turns' `N` (the last turn's
/// multiplied in last, as it is the last to be known). The caller checks the range
/// (`FAST_T`, `FAST_MOMENTUM2`).
// Inlined only when optimised (see "Unoptimised builds" in `splitting.rs`).
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline)]
pub(crate) fn free_flow<R: Real, T: Turning<R>>(
    inertia: &Inertia<R>,
    q_p: T,
    q_p2: R,
    body: V<R>,
    h: R,
) -> (T, R) {
    let (r1, r2, r3) = turn_rates(inertia, h);
    let one = R::splat(1.0);
    let b1 = r1 * body.x;
    let (q, x, b2, d2, n1) = turn::<R, T, 0, 1>(q_p, body, b1, one, r2);
    let (q, x, b3, d3, n2) = turn::<R, T, 1, 2>(q, x, b2, d2, r3);
    let (q, x, b4, d4, n3) = turn::<R, T, 2, 1>(q, x, b3, d3, r2);
    let (q, _, b5, d5, n4) = turn::<R, T, 1, 0>(q, x, b4, d4, r1);
    // The last turn needs only its quaternion and its `N`.
    let (bb, dd) = ((b5 * b5).opaque(), (d5 * d5).opaque());
    let p = (dd - bb).opaque();
    let a = ((b5 * d5) * R::splat(SQRT_3)).opaque();
    let n5 = (p * p + a * a).opaque();
    let norm = (q_p2 * ((n1 * n2) * (n3 * n4))) * n5;
    (q.turned_about::<0>(p, a), norm)
}
