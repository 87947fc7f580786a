//! The free flow's three turns without a division, for the steps an engine takes (the
//! range in `range.rs`): the body momentum and each angle carried as numerators over one
//! common denominator, divided out once with the final normalisation. The same map as
//! the divided form (`divided.rs`), rounded differently; docs/derivations/projective-turns.md
//! has the derivation and the range's proof.
//!
//! The momentum is `X / D` and the angle parameter `b = B / D`; a turn works on the
//! numerators:
//!
//! - `P = e D^2 - lambda B^2` and `A = B D` are `p` and `b` times `D^2`, so the turn's
//!   quaternion `P + A e_K` is `p + b e_K` scaled by `D^2`;
//! - `C = P^2 - A^2` and `S = 2 P A` are `cos` and `sin` times `D^4 n`, and
//!   `N = P^2 + A^2` is `D^4 n`;
//! - the turned components are `C X_i + S X_j`, the untouched one `N X_K`, all over the
//!   new denominator `D N`, and the next angle's numerators are the turned component the
//!   next turn reads times `r` and times `lambda r` (so that `lambda B^2` is one product,
//!   not two).

use super::rates::Rates;
use super::real::Real;
use super::rotation::{turn_body_about, V};
use super::turning::Turning;

/// One turn about the body axis `K` by `b = B / D`: the quaternion `q (P + A e_K)`, the
/// momentum's numerators turned, the next turn's `B` and `lambda B` for the axis `N`
/// (rates `rate`, `cubic_rate`), the new denominator `D N`, the next turn's `e D^2`
/// (its `e` is `e_next`), and `N = P^2 + A^2` (the factor `q`'s squared norm grew by).
// Inlined only when optimised (see "Unoptimised builds" in `splitting.rs`).
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline)]
#[allow(clippy::too_many_arguments, clippy::type_complexity)]
fn turn<R: Real, T: Turning<R>, const K: usize, const N: usize>(
    q: T,
    x: V<R>,
    (b, cubic_b): (R, R),
    (d, edd): (R, R),
    (rate, cubic_rate): (R, R),
    e_next: R,
) -> (T, V<R>, (R, R), (R, R), R) {
    // `opaque`: one body's chain stays scalar (see `Real::opaque`).
    let p = (edd - (b * cubic_b).opaque()).opaque();
    let a = (b * d).opaque();
    let (pp, aa) = ((p * p).opaque(), (a * a).opaque());
    let c = (pp - aa).opaque();
    let s = (p * (a + a).opaque()).opaque();
    let norm = (pp + aa).opaque();
    let turned = turn_body_about(K, c, s, x);
    // The next angle's numerators are the rates times the turned momentum's component
    // `N`: two products after the turn rather than the turn applied again to the
    // momentum scaled by each rate (eight products and two sums more, which cost the
    // one-body step more than the product's latency on the chain does).
    let next = turned.get(N);
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
    let d_next = (d * norm).opaque();
    let edd_next = ((e_next * d_next).opaque() * d_next).opaque();
    let (next, cubic_next) = ((rate * next).opaque(), (cubic_rate * next).opaque());
    (
        q.turned_about::<K>(p, a),
        x,
        (next, cubic_next),
        (d_next, edd_next),
        norm,
    )
}

/// The three turns `x(h/2) y(h) x(h/2)` from `q_p` (unit up to rounding; `q_p2` its
/// squared norm) and the body momentum `body`: the turned quaternion scaled by a
/// positive number, and its squared norm, `q_p2` times the turns' `N` (the last turn's
/// multiplied in last, as it is the last to be known). The caller checks the range
/// ([`RANGE`](crate::range::RANGE), [`FAST_MOMENTUM2`](crate::range::FAST_MOMENTUM2)).
// Inlined only when optimised (see "Unoptimised builds" in `splitting.rs`).
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline)]
pub(crate) fn free_flow<R: Real, T: Turning<R>>(
    rates: &Rates<R>,
    q_p: T,
    q_p2: R,
    body: V<R>,
) -> (T, R) {
    let one = R::splat(1.0);
    let b1 = (rates.outer * body.x, rates.outer_cubic * body.x);
    let (q, x, b2, d2, n1) = turn::<R, T, 0, 1>(
        q_p,
        body,
        b1,
        (one, rates.outer_e),
        (rates.middle, rates.middle_cubic),
        rates.middle_e,
    );
    let (q, _, (b3, cubic_b3), (d3, edd3), n2) = turn::<R, T, 1, 0>(
        q,
        x,
        b2,
        d2,
        (rates.outer, rates.outer_cubic),
        rates.outer_e,
    );
    // The last turn needs only its quaternion and its `N`.
    let p = (edd3 - (b3 * cubic_b3).opaque()).opaque();
    let a = (b3 * d3).opaque();
    let n3 = (p * p + a * a).opaque();
    let norm = (q_p2 * (n1 * n2)) * n3;
    (q.turned_about::<0>(p, a), norm)
}
