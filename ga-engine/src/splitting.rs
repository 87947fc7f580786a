//! The free-flow-plus-kick splitting: second order, and its fourth-order composition.
//!
//! The state is the orientation and the angular momentum **in the world frame**. A
//! torque constant in the world frame changes only the world momentum, and exactly:
//! `L += h T` (the kick), and `kick(h/2) free(h) kick(h/2)` is Strang's splitting:
//! time-reversible, second order.
//!
//! **The free flow** keeps the world momentum and the kinetic energy
//! `H = m_o^2/2I_o + m_m^2/2I_m + m_r^2/2I_r` (body components; `split.rs` orders the
//! principal axes: `o` the smallest moment, `r` the largest). `H` is split around the
//! Casimir `|m|^2` (McLachlan, Phys. Rev. Lett. 71, 1993; Fassò, J. Comput. Phys. 189,
//! 2003): `H = k_r |m|^2/2 + alpha m_o^2/2 + beta m_m^2/2` with `alpha = k_o - k_r`,
//! `beta = k_m - k_r` (`k` the inverse moments). The Casimir's flow turns the body about
//! `L` and commutes with everything; the other two parts are turns about one body axis
//! each, so the free flow is three turns in a chain, `o(h/2) m(h) o(h/2)`, and the turn
//! about `L`, known from the step's start (Dullweber, Leimkuhler and McLachlan's split
//! of the three terms takes five).
//!
//! **The corrected turns.** Strang's splitting of `A = alpha m_o^2/2` and
//! `B = beta m_m^2/2` keeps the modified energy
//! `H + h^2 (-{A,{A,B}}/24 + {B,{B,A}}/12) + O(h^4)` (Baker-Campbell-Hausdorff); with
//! `{A,{A,B}} = alpha^2 beta m_o^2 (m_r^2 - m_m^2)` and
//! `{B,{B,A}} = alpha beta^2 m_m^2 (m_r^2 - m_o^2)` and `m_r^2 = |m|^2 - m_o^2 - m_m^2`,
//! that term is a function of `m_o` alone, one of `m_m` alone (each times a function of
//! `|m|^2`), and `alpha beta (alpha - 2 beta)/12 m_o^2 m_m^2`. A turn may be the flow of
//! any function of its own component and of `|m|^2` (it stays a turn about that axis),
//! so each turn's angle carries the negative of its own single-axis term: the outer half
//! turn by `2 atan2(b, e_o - lambda_o b^2)` with `b = h alpha m_o / 4`, the middle turn
//! by `2 atan2(b, e_m - lambda_m b^2)` with `b = h beta m_m / 2`, where
//! `e_o = 1 - h^2 |m|^2 alpha beta/12`, `e_m = 1 + h^2 |m|^2 alpha beta/6`,
//! `lambda_o = (alpha - 8 beta)/3 alpha`, `lambda_m = (beta + 4 alpha)/3 beta` (the
//! `b^3` terms of those arctangents are the `m^4` parts, the `e` the `|m|^2 m^2` parts;
//! docs/references.md has the algebra). What is left of the `h^2` term is the cross term
//! alone, small where the body is near symmetric, and the energy error with it: on the
//! T-handle 1 : 2 : 3 at 60 Hz its largest excursion is 3.4e-5 in f64, against 1.0e-4
//! for the uncorrected split and 7.6e-5 for the five-turn one (a unit test checks that
//! the modified energy is kept to `O(h^4)`).
//!
//! Each turn is written without sine or cosine: a turn by `2 atan2(b, p)` about a body
//! axis `e_k` is the quaternion `p + b e_k` up to a positive scale, and its matrix has
//! `cos = (p^2 - b^2)/(p^2 + b^2)`, `sin = 2 p b/(p^2 + b^2)` (the Cayley transform), so
//! the step takes no sine and one square root, the quaternion normalised once at the end.
//! The turn about `L` is `(1 - w^2/3) + (h k_r / 2) L`, `w = h k_r |L| / 2`, by the
//! angle `2 atan(w / (1 - w^2/3))`, which agrees with `h k_r |L|` to `w^5`.
//!
//! The body-momentum map is a composition of exact Lie-Poisson flows (each turn the flow
//! of a function of its component and `|m|^2`), so `|m|` is kept and the energy's error
//! stays bounded. The orientation follows each turn about its axis; the rotation about
//! `L` that the `|m|^2`-dependence of the angles adds to the exact flow of those
//! functions (of order `h^3` a step, about `L`, which no other quantity depends on) is
//! left out.
//!
//! For the steps an engine takes (`projective::RANGE`, `|L| < 1e18`), `projective.rs`
//! does the same turns with no division at all: the momentum and angle as numerators
//! over one denominator, divided out once with the final normalisation, and in that
//! range the result provably stays in the starting hemisphere, so the hemisphere test
//! is left out. Beyond it the divided form runs with its clamps; a lane group of the
//! slice form that mixes ranges computes both forms and takes each lane's own, so a body
//! gets the same bits in every form.
//!
//! Since the world momentum is never touched by the free flow, `|L|` of a torque-free
//! body is conserved to the bit, not just to rounding; the body momentum the angles need
//! is computed from it and the orientation at the start of each free flow and then turned
//! along with the body.
//!
//! Unoptimised builds: every function of a step is `#[inline(always)]` so that the
//! optimiser sees one body's (or one lane group's) whole chain, but unoptimised, each
//! inlined temporary keeps its own stack slot, and the slice form's AVX loop had a frame
//! of over a megabyte (its fourth order two: a test thread's 2 MiB stack overflowed).
//! With debug assertions on, the turns and free flows are ordinary functions instead.
//!
//! The fourth-order step is the symmetric triple jump `S(g1 h) S(g0 h) S(g1 h)` with
//! `g1 = 1/(2 - 2^(1/3))`, `g0 = 1 - 2 g1` (Yoshida, Phys. Lett. A 150, 1990; Suzuki,
//! Phys. Lett. A 146, 1990), the kicks between free flows merged.

use super::inertia::Inertia;
use super::projective;
use super::real::Real;
use super::rotation::{turn_body_about, Q, V};

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

/// The quaternion the turns build up: in components ([`Q`]), or, for one `f32` body on
/// x86-64, in one SSE register (`sse.rs`), where a turn is seven instructions instead of
/// twelve. Both do the same IEEE operations on each component, so they give the same bits.
pub(crate) trait Turning<R: Real>: Copy {
    /// From components.
    fn pack(q: Q<R>) -> Self;
    /// To components.
    fn unpack(self) -> Q<R>;
    /// `self (c + s e_K)`, as [`Q::turn_about`].
    fn turned_about<const K: usize>(self, c: R, s: R) -> Self;
    /// `w self`, as [`Q::mul`].
    fn turned_by(self, w: Q<R>) -> Self;
    /// `self b`, as [`Q::mul`].
    fn times(self, b: Q<R>) -> Self;
    /// As [`Q::normalized_by`].
    fn normalized_by(self, norm2: R, reference: Self) -> Self;
    /// As [`Q::divided_by_norm`].
    fn divided_by_norm(self, norm2: R) -> Self;
    /// As [`Q::dot`].
    fn dot(self, b: Self) -> R;
    /// As [`Q::rotate_inv`].
    fn rotate_inv(self, v: V<R>) -> V<R>;
    /// As [`Q::select`].
    fn select(mask: R::Mask, yes: Self, no: Self) -> Self;
}

impl<R: Real> Turning<R> for Q<R> {
    #[inline(always)]
    fn pack(q: Q<R>) -> Self {
        q
    }
    #[inline(always)]
    fn unpack(self) -> Q<R> {
        self
    }
    #[inline(always)]
    fn turned_about<const K: usize>(self, c: R, s: R) -> Self {
        self.turn_about(K, c, s)
    }
    #[inline(always)]
    fn turned_by(self, w: Q<R>) -> Self {
        w.mul(self)
    }
    #[inline(always)]
    fn times(self, b: Q<R>) -> Self {
        self.mul(b)
    }
    #[inline(always)]
    fn normalized_by(self, norm2: R, reference: Self) -> Self {
        Q::normalized_by(self, norm2, reference)
    }
    #[inline(always)]
    fn divided_by_norm(self, norm2: R) -> Self {
        Q::divided_by_norm(self, norm2)
    }
    #[inline(always)]
    fn dot(self, b: Self) -> R {
        Q::dot(self, b)
    }
    #[inline(always)]
    fn rotate_inv(self, v: V<R>) -> V<R> {
        Q::rotate_inv(self, v)
    }
    #[inline(always)]
    fn select(mask: R::Mask, yes: Self, no: Self) -> Self {
        Q::select(mask, yes, no)
    }
}

/// One free flow's per-step constants, from the body's [`Split`](super::split::Split),
/// `h` and `|L|^2`: each turn's `b` is its rate times the body momentum's component, its
/// `lambda b` the cubic rate times it, and its `p = e - lambda b^2`.
#[derive(Clone, Copy)]
pub(crate) struct Rates<R> {
    /// `h alpha / 4`.
    pub(crate) outer: R,
    /// `lambda_o h alpha / 4`.
    pub(crate) outer_cubic: R,
    /// `1 - h^2 |L|^2 alpha beta / 12`.
    pub(crate) outer_e: R,
    /// `h beta / 2`.
    pub(crate) middle: R,
    /// `lambda_m h beta / 2`.
    pub(crate) middle_cubic: R,
    /// `1 + h^2 |L|^2 alpha beta / 6`.
    pub(crate) middle_e: R,
    /// `h k_r / 2`: the turn about `L` is `(1 - w^2/3) + (h k_r / 2) L`, `w^2` its
    /// square times `|L|^2`.
    pub(crate) casimir: R,
}

impl<R: Real> Rates<R> {
    /// For a step of `h` with `hh_l2 = h^2 |L|^2`; with `LIMIT`, each `e` limited to
    /// `[0.5, 1.5]` (NaN to 1.5), which only the divided form's far range reaches (in
    /// the projective range `|1 - e| <= 0.05`, and the limit changes no bit).
    #[inline(always)]
    pub(crate) fn new<const LIMIT: bool>(inertia: &Inertia<R>, h: R, hh_l2: R) -> Self {
        let split = &inertia.split;
        let (outer, middle) = (h * split.outer_rate, h * split.middle_rate);
        let half = R::splat(0.5);
        let e = |shift: R| {
            let eps = hh_l2 * shift;
            R::splat(1.0)
                - if LIMIT {
                    eps.min_or(half).max_or(-half)
                } else {
                    eps
                }
        };
        Rates {
            outer,
            outer_cubic: split.outer_cubic * outer,
            outer_e: e(split.shift),
            middle,
            middle_cubic: split.middle_cubic * middle,
            middle_e: e(split.shift * R::splat(-2.0)),
            // `0.5 / I_r` is `(1 / I_r) / 2` exactly: off the chain, a division.
            casimir: h * (R::splat(0.5) / inertia.moments.z),
        }
    }
}

/// The free flow's three turns `x(h/2) y(h) x(h/2)` from `q_p` (principal axes in the
/// split's order to world, unit) and the body momentum `body` (the world momentum seen
/// from `q_p`), divided form: the result scaled by a positive number, and the product of
/// the turns' squared norms. `CLAMP` limits each turn's `b`; the caller may leave it out
/// where no `b` can reach the limit (the same bits).
// Inlined only when optimised (see "Unoptimised builds" in `splitting.rs`).
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline)]
fn free_flow<R: Real, T: Turning<R>, const CLAMP: bool>(
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

/// The turn about the world momentum `l` by the Casimir's flow, `(1 - w^2/3) + k l` for
/// `k = rates.casimir`, `w^2 = k^2 |L|^2`, and its squared norm. `w` is limited to 64
/// (its angle is saturated there) where `w^2` is not below `64^2` (or is NaN), with `l`'s
/// direction from `|L|`, when `LIMIT`; without it (the projective range) the plain form.
#[inline(always)]
fn casimir_turn<R: Real, const LIMIT: bool>(rates: &Rates<R>, l: V<R>, l2: R) -> (Q<R>, R) {
    let k = rates.casimir;
    let w2 = (k * k) * l2;
    let third = R::splat(1.0 / 3.0);
    if !LIMIT {
        let p = R::splat(1.0) - w2 * third;
        let w = Q {
            x: k * l.x,
            y: k * l.y,
            z: k * l.z,
            w: p,
        };
        return (w, p * p + w2);
    }
    let limit = R::splat(super::split::MAX_HALF_ANGLE);
    let inside = w2.lt(limit * limit);
    let capped = w2.min_or(limit * limit);
    // Outside, `limit / |L|` (0 where `|L|^2` overflowed) with the sign of `k`.
    let outside = R::select(
        k.lt(R::splat(0.0)),
        -(limit / R::sqrt(l2)),
        limit / R::sqrt(l2),
    );
    let f = R::select(inside, k, outside);
    let w = Q {
        x: f * l.x,
        y: f * l.y,
        z: f * l.z,
        w: R::splat(1.0) - capped * third,
    };
    (w, w.dot(w))
}

/// The free flow from the unit `q_p` (`start`, in the form the turns build up) under
/// the world momentum `l`, normalised (in `start`'s hemisphere; in the projective range
/// it cannot leave it, see `projective::RANGE`): the three turns, then
/// the turn about `l`, which commutes with them. `q_p`'s own squared norm (1 up to
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
    l: V<R>,
    h: R,
) -> T {
    // `|L|^2` from the world momentum, beside the turn into the body frame.
    let l2 = l.dot(l);
    let hh_l2 = (h * h) * l2;
    let body = start.rotate_inv(l);
    let projective = R::and(
        (hh_l2 * inertia.split.reach).lt(R::splat(1.0)),
        l2.lt(R::splat(projective::FAST_MOMENTUM2)),
    );
    // `start` is `q_p`: its dot product gives the same bits in either form.
    let q_p2 = start.dot(start);
    let rates = Rates::new::<false>(inertia, h, hh_l2);
    if R::all(projective) {
        let (q, norm2) = projective::free_flow::<R, T>(&rates, start, q_p2, body);
        let (w, w2) = casimir_turn::<R, false>(&rates, l, l2);
        return q.turned_by(w).divided_by_norm(norm2 * w2);
    }
    let limited = Rates::new::<true>(inertia, h, hh_l2);
    let (q, norm) = free_flow::<R, T, true>(inertia, &limited, start, body);
    let (w, w2) = casimir_turn::<R, true>(&limited, l, l2);
    let divided = q.turned_by(w).normalized_by((q_p2 * norm) * w2, start);
    if R::any(projective) {
        let (q, norm2) = projective::free_flow::<R, T>(&rates, start, q_p2, body);
        let (w, w2) = casimir_turn::<R, false>(&rates, l, l2);
        T::select(
            projective,
            q.turned_by(w).divided_by_norm(norm2 * w2),
            divided,
        )
    } else {
        divided
    }
}

/// One second-order step of `h`: body orientation `q` (body to world), world momentum
/// `l`, world torque `t` held over the step.
#[inline(always)]
pub(crate) fn step2<R: Real>(
    inertia: &Inertia<R>,
    q: Q<R>,
    l: V<R>,
    t: V<R>,
    h: R,
) -> (Q<R>, V<R>) {
    step2_in::<R, Q<R>>(inertia, q, l, t, h)
}

/// [`step2`], the turns building up the quaternion in the form `T`.
#[inline(always)]
pub(crate) fn step2_in<R: Real, T: Turning<R>>(
    inertia: &Inertia<R>,
    q: Q<R>,
    l: V<R>,
    t: V<R>,
    h: R,
) -> (Q<R>, V<R>) {
    let half = h * R::splat(0.5);
    let l = l.add_scaled(half, t);
    let q_p = inertia.principal_orientation(q);
    let q_p = free_flow_normalized(inertia, T::pack(q_p), l, h).unpack();
    let l = l.add_scaled(half, t);
    (inertia.body_orientation(q_p), l)
}

/// [`step2_in`] with the frame's products also in the form `T` (one register for one f32
/// body), as `Inertia::principal_orientation` and `body_orientation` do them: the same
/// bits. Kept apart from [`step2_in`], which the lane forms run: written this way there,
/// the slice form over 2^20 bodies measured 11% slower.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn step2_in_framed<R: Real, T: Turning<R>>(
    inertia: &Inertia<R>,
    q: Q<R>,
    l: V<R>,
    t: V<R>,
    h: R,
) -> (Q<R>, V<R>) {
    let half = h * R::splat(0.5);
    let l = l.add_scaled(half, t);
    let turned = inertia.turned;
    let q = T::pack(q);
    let q_p = if R::any(turned) {
        T::select(turned, q.times(inertia.frame), q)
    } else {
        q
    };
    let q_p = free_flow_normalized(inertia, q_p, l, h);
    let q = if R::any(turned) {
        T::select(turned, q_p.times(inertia.frame.conj()), q_p)
    } else {
        q_p
    };
    let l = l.add_scaled(half, t);
    (q.unpack(), l)
}

/// [`step2`] for one `f32` body: its quaternion in one SSE register on x86-64 (`sse.rs`,
/// the same bits), in components elsewhere.
#[inline(always)]
pub(crate) fn step2_f32(
    inertia: &Inertia<f32>,
    q: Q<f32>,
    l: V<f32>,
    t: V<f32>,
    h: f32,
) -> (Q<f32>, V<f32>) {
    #[cfg(target_arch = "x86_64")]
    {
        step2_in_framed::<f32, super::sse::Q4>(inertia, q, l, t, h)
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        step2(inertia, q, l, t, h)
    }
}

/// One second-order step of `h` under a torque that depends on the orientation:
/// `kick(h/2, T(q_n)) free(h) kick(h/2, T(q_n+1))`, Strang's splitting with the torque
/// read at both ends. For a torque from a potential (gravity on a top) the energy then
/// does not drift (3.6e-6 at most over an hour of a heavy top at 60 Hz in f32); holding
/// `T(q_n)` over the whole step lets it drift (30%).
#[inline(always)]
pub(crate) fn step2_with<R: Real>(
    inertia: &Inertia<R>,
    q: Q<R>,
    l: V<R>,
    h: R,
    mut torque: impl FnMut(Q<R>) -> V<R>,
) -> (Q<R>, V<R>) {
    let half = h * R::splat(0.5);
    let l = l.add_scaled(half, torque(q));
    let q_p = inertia.principal_orientation(q);
    let q_p = free_flow_normalized(inertia, q_p, l, h);
    let q = inertia.body_orientation(q_p);
    let l = l.add_scaled(half, torque(q));
    (q, l)
}

/// The triple jump's outer weight `1/(2 - 2^(1/3))`.
const G1: f64 = 1.351_207_191_959_657_8;
/// The triple jump's middle weight `1 - 2 g1` (negative).
const G0: f64 = 1.0 - 2.0 * G1;

/// One fourth-order step of `h`: three second-order steps of `g1 h, g0 h, g1 h`, their
/// adjacent half-kicks merged into one.
#[inline(always)]
pub(crate) fn step4<R: Real>(
    inertia: &Inertia<R>,
    q: Q<R>,
    l: V<R>,
    t: V<R>,
    h: R,
) -> (Q<R>, V<R>) {
    let (h1, h0) = (h * R::splat(G1), h * R::splat(G0));
    let outer_kick = h * R::splat(0.5 * G1);
    let inner_kick = h * R::splat(0.5 * (G1 + G0));
    let q_p = inertia.principal_orientation(q);
    let l = l.add_scaled(outer_kick, t);
    // Each free flow reads the body momentum through its starting quaternion, which must
    // be unit.
    let q1 = free_flow_normalized(inertia, q_p, l, h1);
    let l = l.add_scaled(inner_kick, t);
    let q2 = free_flow_normalized(inertia, q1, l, h0);
    let l = l.add_scaled(inner_kick, t);
    let q3 = free_flow_normalized(inertia, q2, l, h1);
    let l = l.add_scaled(outer_kick, t);
    (inertia.body_orientation(q3), l)
}

#[cfg(all(test, feature = "std"))]
mod tests {
    use super::*;

    /// The angle `body_turn` turns the momentum by, from its cosine and sine, and the
    /// one its quaternion turns by, for the linear half-angle `b`, `lambda` and `e`.
    fn turn_angle(b: f64, cubic: f64, e: f64) -> (f64, f64) {
        let body = V {
            x: 1.0,
            y: 1.0,
            z: 0.0,
        };
        let (q, turned, _, _) =
            body_turn::<f64, Q<f64>, 0, 1, true>(identity(), body, b, (64.0, cubic, e), 0.0);
        // The body momentum (., 1, 0) turned about e1 to (., c, -s).
        let from_momentum = (-turned.z).atan2(turned.y);
        let from_quaternion = 2.0 * q.x.atan2(q.w);
        (from_momentum, from_quaternion)
    }

    #[test]
    fn a_turn_is_by_twice_atan2_of_b_over_e_minus_lambda_b_squared() {
        for i in -100..=100 {
            let b = f64::from(i) * 0.005; // half-angles up to 0.5 rad
                                          // lambda = 1/3, e = 1: the angle is 2b to fifth order,
                                          // 2 atan(b / (1 - b^2/3)) = 2b - 2b^5/45 + O(b^7).
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

    fn identity<R: Real>() -> Q<R> {
        let (zero, one) = (R::splat(0.0), R::splat(1.0));
        Q {
            x: zero,
            y: zero,
            z: zero,
            w: one,
        }
    }

    /// A seeded stream in [-1, 1).
    fn stream(mut seed: u64) -> impl FnMut() -> f64 {
        move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 52) as f64 - 1.0
        }
    }

    /// Seeded principal moments, their inertia, and a unit orientation whose `w` was
    /// drawn with `w_offset` added (to keep it away from a half turn).
    fn seeded_body(
        next: &mut impl FnMut() -> f64,
        w_offset: f64,
    ) -> ([f64; 3], Inertia<f64>, Q<f64>) {
        let moments = [1.0 + next().abs() * 3.0, 0.5 + next().abs(), 2.0 + next()];
        let inertia = Inertia::<f64>::from_principal(moments, identity()).unwrap();
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
        let (w, w2) = casimir_turn::<f64, false>(&rates, l, l2);
        turned.turned_by(w).normalized_by(norm2 * w2, q)
    }

    /// At the edge of the projective range (`h^2 |L|^2 reach` just below 1), the free
    /// flow moves `q_p` by at most 1.07 rad on the unit sphere (`projective::RANGE`'s
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
            let (turned, norm) = free_flow::<R, Q<R>, true>(inertia, &rates, q, q.rotate_inv(l));
            let (w, w2) = casimir_turn::<R, true>(&rates, l, l2);
            turned.turned_by(w).normalized_by((q.dot(q) * norm) * w2, q)
        }
        fn projective<R: Real>(inertia: &Inertia<R>, q: Q<R>, l: V<R>, h: R) -> Q<R> {
            let l2 = l.dot(l);
            let rates = Rates::new::<false>(inertia, h, h * h * l2);
            let (turned, norm2) =
                projective::free_flow::<R, Q<R>>(&rates, q, q.dot(q), q.rotate_inv(l));
            let (w, w2) = casimir_turn::<R, false>(&rates, l, l2);
            turned.turned_by(w).normalized_by(norm2 * w2, q)
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
                Inertia::<f32>::from_principal(moments.map(|m| m as f32), identity()).unwrap();
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
    /// Baker-Campbell-Hausdorff formula; docs/references.md) to `O(h^4)`, while `H` itself
    /// moves at `O(h^2)`. A T-handle spun near its middle axis, in f64, two step sizes.
    #[test]
    fn the_corrected_split_keeps_its_modified_energy_to_fourth_order() {
        let inertia = Inertia::<f64>::from_principal([1.0, 2.0, 3.0], identity()).unwrap();
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
            let mut q = identity::<f64>();
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
                    identity(),
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
