//! The free flow, normalised: the three turns about body axes in the division-free form
//! (`projective.rs`) where every lane is in its range (`range.rs`), else in the divided
//! form (`divided.rs`) with each lane in the range taking the projective result; and the
//! turn about `L` (the Casimir's flow, which commutes with them: first in the projective
//! form, last in the divided one); then one normalisation.

use super::divided;
use super::inertia::Inertia;
use super::projective;
use super::range::FAST_MOMENTUM2;
use super::rates::Rates;
use super::real::Real;
use super::rotation::{Q, V};
use super::split::MAX_HALF_ANGLE;
use super::turning::{Momentum, Turning};

/// The turn about the world momentum `l` by the Casimir's flow, `(1 - w^2/3) + k l` for
/// `k = rates.casimir`, `w^2 = k^2 |L|^2`: its scalar part, its `k`, and its squared norm.
/// `w` is limited to 64 (its angle is saturated there) where `w^2` is not below `64^2`
/// (or is NaN), with `l`'s direction from `|L|`, when `LIMIT`; without it (the projective
/// range) the plain form.
#[inline(always)]
fn casimir_turn<R: Real, const LIMIT: bool>(rates: &Rates<R>, l: V<R>, l2: R) -> (R, R, R) {
    let k = rates.casimir;
    let w2 = (k * k) * l2;
    let third = R::splat(1.0 / 3.0);
    if !LIMIT {
        let p = R::splat(1.0) - w2 * third;
        return (p, k, p * p + w2);
    }
    let limit = R::splat(MAX_HALF_ANGLE);
    let inside = w2.lt(limit * limit);
    let capped = w2.min_or(limit * limit);
    // Outside, `limit / |L|` (0 where `|L|^2` overflowed) with the sign of `k`; 0 where
    // `|L|^2` is 0 too (`w^2` is NaN there for a step so long that `k^2` overflows, such
    // as `dt = f32::MAX`: `limit / 0` times a zero `L` would be NaN, where the turn about
    // a zero `L` is none).
    let zero = R::splat(0.0);
    let reach = R::select(zero.lt(l2), limit / R::sqrt(l2), zero);
    let outside = R::select(k.lt(zero), -reach, reach);
    let f = R::select(inside, k, outside);
    let w = Q {
        x: f * l.x,
        y: f * l.y,
        z: f * l.z,
        w: R::splat(1.0) - capped * third,
    };
    (w.w, f, w.dot(w))
}

/// The free flow from the unit `q_p` (`start`, in the form the turns build up) under
/// the world momentum `l`, normalised (in `start`'s hemisphere; in the projective range
/// it cannot leave it, see `range::RANGE`): the three turns and the turn about `l`,
/// which commutes with them. `q_p`'s own squared norm (1 up to
/// rounding) times the turns' product gives the result's squared norm without waiting
/// for the last turn's quaternion.
///
/// Where every lane is in the projective form's range (every body of an engine's scene
/// at an engine's step), the turns are `projective.rs`'s. Otherwise the divided turns
/// run with their clamps; lanes in the projective range take its result, so a body
/// gets the same bits in every form.
// Inlined only when optimised (see "Unoptimised builds" in `splitting.rs`).
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline)]
pub(crate) fn free_flow_normalized<R: Real, T: Turning<R>>(
    inertia: &Inertia<R>,
    start: T,
    l: T::Momentum,
    h: R,
) -> T {
    free_flow_from(inertia, start, start.dot(start), l, h)
}

/// [`free_flow_normalized`] with `start`'s squared norm `q_p2` given (the steps have it
/// from checking that the orientation is unit).
// Inlined only when optimised (see "Unoptimised builds" in `splitting.rs`).
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline)]
pub(crate) fn free_flow_from<R: Real, T: Turning<R>>(
    inertia: &Inertia<R>,
    start: T,
    q_p2: R,
    l: T::Momentum,
    h: R,
) -> T {
    // `|L|^2` from the world momentum, beside the turn into the body frame.
    let l2 = l.norm2();
    let hh_l2 = (h * h) * l2;
    let body = start.rotate_inv(l);
    let projective = R::and(
        (hh_l2 * inertia.split.reach).lt(R::splat(1.0)),
        l2.lt(R::splat(FAST_MOMENTUM2)),
    );
    let rates = Rates::new::<false>(inertia, h, hh_l2);
    if R::all(projective) {
        return projective_flow(&rates, start, q_p2, body, (l, l2));
    }
    let limited = Rates::new::<true>(inertia, h, hh_l2);
    let (q, norm) = divided::free_flow::<R, T, true>(inertia, &limited, start, body);
    let (p, k, w2) = casimir_turn::<R, true>(&limited, l.unpack(), l2);
    let divided = q
        .turned_about_momentum(p, k, l)
        .normalized_by((q_p2 * norm) * w2, start);
    if R::any(projective) {
        T::select(
            projective,
            projective_flow(&rates, start, q_p2, body, (l, l2)),
            divided,
        )
    } else {
        divided
    }
}

/// The free flow in the projective range: the turn about `l` first (a turn in the world
/// frame, on the left, commutes with the body turns on the right, and it is known from
/// the step's start, so it leaves the chain of turns), then the three turns, then one
/// division by the norm.
#[inline(always)]
fn projective_flow<R: Real, T: Turning<R>>(
    rates: &Rates<R>,
    start: T,
    q_p2: R,
    body: V<R>,
    (l, l2): (T::Momentum, R),
) -> T {
    let (p, k, w2) = casimir_turn::<R, false>(rates, l.unpack(), l2);
    let start = start.turned_about_momentum(p, k, l);
    let (q, norm2) = projective::free_flow::<R, T>(rates, start, q_p2 * w2, body);
    q.divided_by_norm(norm2)
}

#[cfg(all(test, feature = "std"))]
mod tests {
    use super::*;

    /// A seeded stream in [-1, 1) (the workspace's test generator).
    fn stream(seed: u64) -> impl FnMut() -> f64 {
        let mut rng = ga_test_rng::Rng::new(seed);
        move || rng.signed()
    }

    /// Seeded principal moments, their inertia, and a unit orientation whose `w` was
    /// drawn with `w_offset` added (to keep it away from a half turn).
    fn seeded_body(
        next: &mut impl FnMut() -> f64,
        w_offset: f64,
    ) -> ([f64; 3], Inertia<f64>, Q<f64>) {
        let moments = [1.0 + next().abs() * 3.0, 0.5 + next().abs(), 2.0 + next()];
        let inertia = Inertia::<f64>::from_principal(moments, Q::identity()).unwrap();
        let frame = Q {
            x: next(),
            y: next(),
            z: next(),
            w: next() + w_offset,
        };
        (moments, inertia, frame.normalized_near(frame))
    }

    /// `l` scaled so that `h^2 |L|^2 reach` is `edge`.
    fn at_reach(inertia: &Inertia<f64>, l: V<f64>, h: f64, edge: f64) -> V<f64> {
        let k = (edge / (h * h * l.dot(l) * inertia.split.reach)).sqrt();
        l.scale(V { x: k, y: k, z: k })
    }

    /// The projective form's turns and its turn about `L`, normalised with the
    /// hemisphere test, for `q_p` and the world momentum `l`.
    fn projective_flow(inertia: &Inertia<f64>, q: Q<f64>, l: V<f64>, h: f64) -> Q<f64> {
        let l2 = l.dot(l);
        let rates = Rates::new::<false>(inertia, h, h * h * l2);
        let (turned, norm2) =
            projective::free_flow::<f64, Q<f64>>(&rates, q, q.dot(q), q.rotate_inv(l));
        let (p, k, w2) = casimir_turn::<f64, false>(&rates, l, l2);
        turned
            .turned_about_momentum(p, k, l)
            .normalized_by(norm2 * w2, q)
    }

    /// At the edge of the projective range (`h^2 |L|^2 reach` just below 1), the free
    /// flow moves `q_p` by at most 1.07 rad on the unit sphere (`range::RANGE`'s
    /// bound): the result's cosine with `q_p` stays above `cos 1.07 = 0.48`, so
    /// `divided_by_norm` is `normalized_by` there. Long steps of fast bodies, one axis
    /// at a time and all three together.
    #[test]
    fn the_projective_range_stays_in_the_starting_hemisphere() {
        let mut next = stream(0x2545_f491_4f6c_dd1d);
        let mut least = f64::INFINITY;
        for case in 0..20_000 {
            let (_, inertia, q) = seeded_body(&mut next, 0.0);
            let h = 0.05 * next().abs() + 1e-3;
            let axis = match case % 4 {
                0 => V {
                    x: 1.0,
                    y: 0.0,
                    z: 0.0,
                },
                1 => V {
                    x: 0.0,
                    y: 1.0,
                    z: 0.0,
                },
                2 => V {
                    x: 0.0,
                    y: 0.0,
                    z: 1.0,
                },
                _ => V {
                    x: next(),
                    y: next(),
                    z: next(),
                },
            };
            // World momentum along `q`'s axes, so one body axis takes all of it.
            let l = at_reach(&inertia, q.rotate(axis), h, 0.999);
            let result = projective_flow(&inertia, q, l, h);
            least = least.min(result.dot(q));
        }
        assert!(least > 1.07f64.cos(), "{least}");
        // The cases reach far into the range: some turn by over half a radian.
        assert!(least < 0.25f64.cos(), "{least}");
    }

    /// The free flow's turns in the projective form (`projective.rs`, no division) and in
    /// the divided form are the same map, rounded differently: over bodies up to the
    /// projective form's range limit, the normalised results agree to rounding in `f64`
    /// and in `f32`, and a wrong coefficient or axis in either would show far above it.
    #[test]
    fn the_projective_turns_are_the_divided_turns() {
        let mut next = stream(0x9e37_79b9_7f4a_7c15);
        let (mut worst64, mut worst32) = (0.0f64, 0.0f64);
        fn divided<R: Real>(inertia: &Inertia<R>, q: Q<R>, l: V<R>, h: R) -> Q<R> {
            let l2 = l.dot(l);
            let rates = Rates::new::<true>(inertia, h, h * h * l2);
            let (turned, norm) =
                divided::free_flow::<R, Q<R>, true>(inertia, &rates, q, q.rotate_inv(l));
            let (p, k, w2) = casimir_turn::<R, true>(&rates, l, l2);
            turned
                .turned_about_momentum(p, k, l)
                .normalized_by((q.dot(q) * norm) * w2, q)
        }
        fn projective<R: Real>(inertia: &Inertia<R>, q: Q<R>, l: V<R>, h: R) -> Q<R> {
            let l2 = l.dot(l);
            let rates = Rates::new::<false>(inertia, h, h * h * l2);
            let (turned, norm2) =
                projective::free_flow::<R, Q<R>>(&rates, q, q.dot(q), q.rotate_inv(l));
            let (p, k, w2) = casimir_turn::<R, false>(&rates, l, l2);
            turned
                .turned_about_momentum(p, k, l)
                .normalized_by(norm2 * w2, q)
        }
        let gap = |a: [f64; 4], b: [f64; 4]| (0..4).fold(0.0f64, |m, k| m.max((a[k] - b[k]).abs()));
        for case in 0..5_000 {
            let (moments, inertia, q) = seeded_body(&mut next, 1.5);
            let h = 0.05 * next().abs() + 1e-4;
            let l = V {
                x: next(),
                y: next(),
                z: next(),
            };
            let l = at_reach(&inertia, l, h, [0.999, 0.5, 1e-3][case % 3]);
            let parts = |q: Q<f64>| [q.x, q.y, q.z, q.w];
            worst64 = worst64.max(gap(
                parts(divided(&inertia, q, l, h)),
                parts(projective(&inertia, q, l, h)),
            ));
            // The same body in f32.
            let inertia32 =
                Inertia::<f32>::from_principal(moments.map(|m| m as f32), Q::identity()).unwrap();
            let q32 = Q {
                x: q.x as f32,
                y: q.y as f32,
                z: q.z as f32,
                w: q.w as f32,
            };
            let l32 = V {
                x: l.x as f32,
                y: l.y as f32,
                z: l.z as f32,
            };
            let wide = |q: Q<f32>| [q.x, q.y, q.z, q.w].map(f64::from);
            worst32 = worst32.max(gap(
                wide(divided(&inertia32, q32, l32, h as f32)),
                wide(projective(&inertia32, q32, l32, h as f32)),
            ));
        }
        assert!(worst64 < 4e-15, "f64: {worst64:e}");
        assert!(worst32 < 2e-6, "f32: {worst32:e}");
    }

    /// What the corrected turns are for: the body-momentum map of the free flow keeps
    /// `H + h^2 alpha beta (alpha - 2 beta) / 12 L_o^2 L_m^2` (the splitting's modified
    /// energy once the single-axis terms of its `h^2` error are cancelled, from the
    /// Baker-Campbell-Hausdorff formula; docs/derivations/corrected-splitting.md) to
    /// `O(h^4)`, while `H` itself moves at `O(h^2)`. A T-handle spun near its middle axis,
    /// in f64, two step sizes.
    #[test]
    fn the_corrected_split_keeps_its_modified_energy_to_fourth_order() {
        let inertia = Inertia::<f64>::from_principal([1.0, 2.0, 3.0], Q::identity()).unwrap();
        let split = inertia.split;
        let inv = V {
            x: 1.0 / inertia.moments.x,
            y: 1.0 / inertia.moments.y,
            z: 1.0 / inertia.moments.z,
        };
        let (alpha, beta) = (inv.x - inv.z, inv.y - inv.z);
        let l = V {
            x: 0.02 * 4.0 * core::f64::consts::PI,
            y: 4.0 * core::f64::consts::PI,
            z: 0.0,
        };
        assert_eq!(split.outer_rate, alpha / 4.0);
        let excursions = |h: f64| {
            let energy = |m: V<f64>| 0.5 * m.dot(m.scale(inv));
            let modified = |m: V<f64>| {
                energy(m)
                    + h * h * alpha * beta * (alpha - 2.0 * beta) / 12.0 * (m.x * m.x * m.y * m.y)
            };
            let mut q = Q::<f64>::identity();
            let (h0, m0) = (energy(l), modified(l));
            let (mut worst_h, mut worst_m) = (0.0f64, 0.0f64);
            for _ in 0..(20.0 / h) as usize {
                q = free_flow_normalized(&inertia, q, l, h);
                let m = q.rotate_inv(l);
                worst_h = worst_h.max((energy(m) / h0 - 1.0).abs());
                worst_m = worst_m.max((modified(m) / m0 - 1.0).abs());
            }
            (worst_h, worst_m)
        };
        let (h1, m1) = excursions(1.0 / 60.0);
        let (h2, m2) = excursions(1.0 / 120.0);
        println!("energy {h1:e} -> {h2:e}, modified {m1:e} -> {m2:e}");
        // H: second order (a factor of 4 for half the step).
        assert!(h1 / h2 > 3.5 && h1 / h2 < 4.5, "{h1:e} {h2:e}");
        // The modified energy: far smaller, and fourth order.
        assert!(m1 < h1 / 100.0, "{m1:e} {h1:e}");
        assert!(m1 / m2 > 12.0, "{m1:e} {m2:e}");
    }
}
