//! The free-flow-plus-kick splitting: second order, and its fourth-order composition.
//!
//! The state is the orientation and the angular momentum **in the world frame**. A
//! torque constant in the world frame changes only the world momentum, and exactly:
//! `L += h T` (the kick), and `kick(h/2) free(h) kick(h/2)` is Strang's splitting:
//! symplectic, time-reversible, second order.
//!
//! The free body keeps its world momentum, and its kinetic energy
//! `H = L1^2/2I1 + L2^2/2I2 + L3^2/2I3` (body components) is split into its three
//! terms; each term's flow is a rotation of the body about one principal axis by the
//! angle `h L_k / I_k` (L_k is constant along it). The symmetric sequence
//! `1(h/2) 2(h/2) 3(h) 2(h/2) 1(h/2)` is the splitting of Dullweber, Leimkuhler and
//! McLachlan (J. Chem. Phys. 107, 1997; Touma and Wisdom, Astron. J. 107, 1994, for the
//! same idea).
//!
//! Each turn is written without sine or cosine: a turn by `2 atan2(s, p)` about a body
//! axis `e_k` is the quaternion `p + s e_k` up to a positive scale, and its matrix has
//! `cos = (p^2 - s^2)/(p^2 + s^2)`, `sin = 2 p s/(p^2 + s^2)` (the Cayley transform).
//! With `p = 1 - a^2/3` and `s = a`, the tangent of the half-angle is `a / (1 - a^2/3)`,
//! whose series agrees with `tan a` up to `a^3` and misses `a^5` by `a^5/45`: the
//! half-angle is off by O(h^5) per turn, far below the splitting's own O(h^3). The angle
//! is an odd function of `h L_k` that depends on `L_k` alone, so each turn is still the
//! exact flow of a Hamiltonian of `L_k` (one that tends to the term of `H`), and the
//! step stays symplectic, time-reversible and second order, at one division per turn
//! and one square root per step (the quaternion is normalised once, at the end), where
//! a sine and a cosine would put two polynomials on the step's critical path per turn.
//! Far beyond the steps an engine takes (a half-angle `a` above about 0.5 rad per turn)
//! the angle falls behind the exact one (`atan2` saturates at pi); the step stays
//! stable, unit, and keeps `|L|`.
//!
//! The turns sit one after another on the step's critical path (each angle needs the
//! momentum the last turn left), so each is written for latency: in `t = a^2/3` the
//! norm is `p^2 + a^2 = 1 + t + t^2` and the cosine's numerator `1 - 5t + t^2`; the
//! momentum is turned by those numerators and divided by the norm last, beside the
//! products; the next angle takes the division in the same multiply; and the final
//! normalisation divides by `|q_p| sqrt(prod (p^2 + a^2))`, known without waiting for
//! the last turn's quaternion. Measured in `engine/f32` (BENCHMARKS.md, issue 19), this
//! took the one-body step from 46.0 to 40.5 ns and the slice from 13.5 to 10.9 ns a body.
//!
//! For the steps an engine takes (`max_k (h |L| / 2 sqrt3 I_k)^2 < 0.05` and
//! `|L| < 1e18`), `projective.rs` does the same turns with no division at all: the
//! momentum and angle as numerators over one denominator, divided out once with the
//! final normalisation. It is the same map rounded differently (a test compares the two
//! forms to rounding), and 12% faster again in `engine/f32`. Beyond that range the
//! divided form runs, without its clamps where no angle can reach them; a lane group of
//! the slice form that mixes ranges computes both forms and takes each lane's own, so a
//! body gets the same bits in every form.
//!
//! Since the world momentum is never touched by the free flow, `|L|` of a torque-free
//! body is conserved to the bit, not just to rounding; the body momentum the angles need
//! is computed from it and the orientation at the start of each free flow and then turned
//! along with the body. The energy error is the splitting's (bounded, O(h^2)) plus the
//! orientation's rounding.
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

/// The largest half-angle parameter `a` a turn takes: beyond it `a^2` could
/// overflow (and a NaN, from an overflowed momentum, lands here too, so the output
/// stays finite). The angle is already saturated there (`2 atan2(64, -1364)`).
const MAX_HALF_ANGLE: f64 = 64.0;

/// Below this bound on `max_k (h L / 2 sqrt3 I_k)^2`, no turn's `b` can reach the clamps'
/// limit (a quarter of its square, for the rounding of the body momentum), so the turns
/// skip them and give the same bits.
const FAST_LIMIT: f64 = MAX_HALF_ANGLE * MAX_HALF_ANGLE / 3.0 / 4.0;

/// `sqrt 3`: the turns work with `b = a / sqrt 3`, whose square is `a^2 / 3`.
pub(crate) const SQRT_3: f64 = 1.732_050_807_568_877_2;

/// `b` limited to `[-MAX_HALF_ANGLE, MAX_HALF_ANGLE] / sqrt 3`, NaN to the upper end.
#[inline(always)]
fn limited<R: Real>(b: R) -> R {
    let limit = R::splat(MAX_HALF_ANGLE / SQRT_3);
    b.min_or(limit).max_or(-limit)
}

/// The turn `p + a e_K` for `b = a / sqrt 3` (not yet limited), so `t = b^2 = a^2/3`:
/// its scalar and vector parts `p = 1 - t` and `a`, its squared norm
/// `p^2 + a^2 = 1 + t + t^2`, and `t`. Written in `t`, the norm is two additions deep
/// after `t` instead of four operations after `p`: the turns sit one after another on
/// the step's critical path.
#[inline(always)]
fn cayley_turn<R: Real, const CLAMP: bool>(b: R) -> (R, R, R, R) {
    let b = if CLAMP { limited(b) } else { b };
    // `opaque`: one body's chain stays scalar (see `Real::opaque`).
    let t = (b * b).opaque();
    let t2 = (t * t).opaque();
    let (p, a) = (
        (R::splat(1.0) - t).opaque(),
        (b * R::splat(SQRT_3)).opaque(),
    );
    let norm = ((R::splat(1.0) + t) + t2).opaque();
    (t, p, a, norm)
}

/// A turn about the body axis `K` by `b` (the half-angle over `sqrt 3`, not yet
/// limited): `q -> q (p + a e_K)` (not normalised), the body momentum turned back by it,
/// the next turn's `b`, `rate` times the turned momentum's component `N`, and the turn's
/// squared norm `p^2 + a^2` (the factor `q`'s squared norm grew by).
///
/// The momentum turns by `cos = (p^2 - a^2) / n = (1 - 5t + t^2) / n` and
/// `sin = 2 p a / n`. The division by `n` is applied last, to the turned components and
/// to the next `b`, so that it runs beside their products rather than before them.
// Inlined only when optimised (see "Unoptimised builds" in `splitting.rs`).
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline)]
fn body_turn<R: Real, T: Turning<R>, const K: usize, const N: usize, const CLAMP: bool>(
    q: T,
    body: V<R>,
    b: R,
    rate: R,
) -> (T, V<R>, R, R) {
    let (t, p, a, norm) = cayley_turn::<R, CLAMP>(b);
    let cos_n = ((R::splat(1.0) - R::splat(5.0) * t) + t * t).opaque();
    let sin_n = ((p + p) * a).opaque();
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
    (q.turned_about::<K>(p, a), body, next, norm)
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

/// The factors `r_k` that take a body momentum component `L_k` to the parameter
/// `b = a / sqrt 3` of the turns about axis `k` in `1(h/2) 2(h/2) 3(h) 2(h/2) 1(h/2)`:
/// the turn over `h f` is by `h f L_k / I_k`, its half-angle `a = (h f / 2 I_k) L_k`.
/// Axes 1 and 2 turn over `h/2`, axis 3 over `h`. Both forms of the turns use them.
#[inline(always)]
pub(crate) fn turn_rates<R: Real>(inertia: &Inertia<R>, h: R) -> (R, R, R) {
    let quarter = h * R::splat(0.25 / SQRT_3);
    let half = h * R::splat(0.5 / SQRT_3);
    let inv = inertia.inverse;
    (quarter * inv.x, quarter * inv.y, half * inv.z)
}

/// The free flow over `h`: `q_p` (principal axes to world, unit) turned by the five
/// body-axis turns `1(h/2) 2(h/2) 3(h) 2(h/2) 1(h/2)`, from the body momentum `body`
/// (the world momentum seen from `q_p`). The result is the rotation scaled by a positive
/// number (not normalised), and the product of the turns' squared norms (so `|q_p|^2`
/// times that is the result's squared norm). `CLAMP` limits each turn's angle; the
/// caller may leave it out where no angle can reach the limit (the same bits).
// Inlined only when optimised (see "Unoptimised builds" in `splitting.rs`).
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline)]
fn free_flow<R: Real, T: Turning<R>, const CLAMP: bool>(
    inertia: &Inertia<R>,
    q_p: T,
    body: V<R>,
    h: R,
) -> (T, R) {
    let (r1, r2, r3) = turn_rates(inertia, h);
    let b1 = r1 * body.x;
    let (q, body, b2, n1) = body_turn::<R, T, 0, 1, CLAMP>(q_p, body, b1, r2);
    let (q, body, b3, n2) = body_turn::<R, T, 1, 2, CLAMP>(q, body, b2, r3);
    let (q, body, b4, n3) = body_turn::<R, T, 2, 1, CLAMP>(q, body, b3, r2);
    let (q, _, b5, n4) = body_turn::<R, T, 1, 0, CLAMP>(q, body, b4, r1);
    // The last turn needs only its quaternion and its norm.
    let (_, p, a, n5) = cayley_turn::<R, CLAMP>(b5);
    let norm = ((n1 * n2) * (n3 * n4)) * n5;
    (q.turned_about::<0>(p, a), norm)
}

/// The free flow from the unit `q_p` (`start`, in the form the turns build up) under
/// the world momentum `l`, normalised: `q_p`'s own squared norm (1 up to rounding) times
/// the turns' product gives the result's squared norm without waiting for the last
/// turn's quaternion.
///
/// Where every lane is in the projective form's range (every body of an engine's scene
/// at an engine's step), the turns are `projective.rs`'s. Otherwise, where no turn's
/// angle can reach the clamps' limit, the divided turns leave the clamps out (the same
/// bits, a few cycles a turn shorter); lanes in the projective range take its result.
// Inlined only when optimised (see "Unoptimised builds" in `splitting.rs`).
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline)]
pub(crate) fn free_flow_normalized<R: Real, T: Turning<R>>(
    inertia: &Inertia<R>,
    start: T,
    l: V<R>,
    h: R,
) -> T {
    let body = start.rotate_inv(l);
    // No `b = (h f / 2 sqrt3 I_k) L_k` exceeds `(h / 2 sqrt3 I_k) |body|`, and the
    // turns keep `|body|` to rounding: `b^2 <= h^2 |body|^2 max_k (1/I_k)^2 / 12`.
    let body2 = body.dot(body);
    let reach = (h * h) * (inertia.reach * body2);
    let in_range = reach.lt(R::splat(FAST_LIMIT));
    let projective = R::and(
        reach.lt(R::splat(projective::FAST_T)),
        body2.lt(R::splat(projective::FAST_MOMENTUM2)),
    );
    // `start` is `q_p`: its dot product gives the same bits in either form.
    let q_p2 = start.dot(start);
    // In the projective range the result needs no hemisphere test (`divided_by_norm`,
    // the same bits as `normalized_by`): see `projective::FAST_T`.
    if R::all(projective) {
        let (q, norm2) = projective::free_flow::<R, T>(inertia, start, q_p2, body, h);
        return q.divided_by_norm(norm2);
    }
    let (q, norm) = if R::all(in_range) {
        free_flow::<R, T, false>(inertia, start, body, h)
    } else {
        free_flow::<R, T, true>(inertia, start, body, h)
    };
    let divided = q.normalized_by(q_p2 * norm, start);
    if R::any(projective) {
        let (q, norm2) = projective::free_flow::<R, T>(inertia, start, q_p2, body, h);
        T::select(projective, q.divided_by_norm(norm2), divided)
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
        step2_in::<f32, super::sse::Q4>(inertia, q, l, t, h)
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        step2(inertia, q, l, t, h)
    }
}

/// One second-order step of `h` under a torque that depends on the orientation:
/// `kick(h/2, T(q_n)) free(h) kick(h/2, T(q_n+1))`, Strang's splitting with the torque
/// read at both ends. For a torque from a potential (gravity on a top) it is symplectic,
/// so the energy does not drift; holding `T(q_n)` over the whole step would not be.
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
    /// one its quaternion turns by, for the half-angle `rate l_k`.
    fn turn_angle(rate: f64, l_k: f64) -> (f64, f64) {
        let q = Q {
            x: 0.0,
            y: 0.0,
            z: 0.0,
            w: 1.0,
        };
        let body = V {
            x: l_k,
            y: 1.0,
            z: 0.0,
        };
        let (q, turned, _, _) =
            body_turn::<f64, Q<f64>, 0, 1, true>(q, body, rate / SQRT_3 * l_k, 0.0);
        // The body momentum (0, 1, 0) turned about e1 to (0, c, -s).
        let from_momentum = (-turned.z).atan2(turned.y);
        let from_quaternion = 2.0 * q.x.atan2(q.w);
        (from_momentum, from_quaternion)
    }

    #[test]
    fn a_turn_is_by_twice_the_half_angle_to_fifth_order() {
        for i in -100..=100 {
            let a = f64::from(i) * 0.005; // half-angles up to 0.5 rad
            let (by_momentum, by_quaternion) = turn_angle(a, 1.0);
            // 2 atan(a / (1 - a^2/3)) = 2a - 2a^5/45 + O(a^7).
            let bound = 2.0 * a.powi(5).abs() / 45.0 * 1.1 + 1e-15;
            assert!((by_momentum - 2.0 * a).abs() <= bound, "{a}: {by_momentum}");
            assert!((by_quaternion - by_momentum).abs() <= 1e-15, "{a}");
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

    /// At the edge of the projective range (`reach` just below `FAST_T`), the free flow
    /// moves `q_p` by at most 1.16 rad on the unit sphere (`projective::FAST_T`'s
    /// bound): the result's cosine with `q_p` stays above `cos 1.16 = 0.398`, so
    /// `divided_by_norm` is `normalized_by` there. Long steps of fast bodies, one axis
    /// at a time and all three together, in `f64` and the step's own `reach`.
    #[test]
    fn the_projective_range_stays_in_the_starting_hemisphere() {
        let mut next = stream(0x2545_f491_4f6c_dd1d);
        let mut least = f64::INFINITY;
        for case in 0..20_000 {
            let (_, inertia, q) = seeded_body(&mut next, 0.0);
            let h = 0.05 * next().abs() + 1e-3;
            let l = match case % 4 {
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
            let l = q.rotate(l);
            let body = q.rotate_inv(l);
            let reach = h * h * inertia.reach * body.dot(body);
            let k = (projective::FAST_T * 0.999 / reach).sqrt();
            let l = l.scale(V { x: k, y: k, z: k });
            let body = q.rotate_inv(l);
            let reach = h * h * inertia.reach * body.dot(body);
            assert!(reach < projective::FAST_T && reach > 0.99 * projective::FAST_T);
            let (turned, norm2) =
                projective::free_flow::<f64, Q<f64>>(&inertia, q, q.dot(q), body, h);
            least = least.min(turned.dot(q) / (norm2.sqrt() * q.dot(q).sqrt()));
        }
        assert!(least > 1.16f64.cos(), "{least}");
        // The cases reach the range's edge: along the third axis the middle turn alone
        // takes its largest half-angle, 0.387 rad (cos 0.926).
        assert!(least < 0.38f64.cos(), "{least}");
    }

    /// The free flow's turns in the projective form (`projective.rs`, no division) and in
    /// the divided form are the same map, rounded differently: over bodies up to the
    /// projective form's range limit, the normalised results agree to rounding in `f64`
    /// and in `f32`, and a wrong coefficient or axis in either would show far above it.
    #[test]
    fn the_projective_turns_are_the_divided_turns() {
        let mut next = stream(0x9e37_79b9_7f4a_7c15);
        let (mut worst64, mut worst32) = (0.0f64, 0.0f64);
        for case in 0..5_000 {
            let (moments, inertia, q) = seeded_body(&mut next, 1.5);
            let h = 0.05 * next().abs() + 1e-4;
            // Up to the range limit: `widest (h/2 sqrt3 I)^2 |L|^2` up to `FAST_T`.
            let widest = moments.iter().fold(f64::INFINITY, |m, &i| m.min(i));
            let reach = (projective::FAST_T).sqrt() * 2.0 * SQRT_3 * widest / h;
            let size = reach * [0.999, 0.5, 1e-3][case % 3];
            let l = V {
                x: next(),
                y: next(),
                z: next(),
            };
            let k = size / l.dot(l).sqrt();
            let l = l.scale(V { x: k, y: k, z: k });
            let body = q.rotate_inv(l);
            let (divided, norm) = free_flow::<f64, Q<f64>, true>(&inertia, q, body, h);
            let divided = divided.normalized_by(q.dot(q) * norm, q);
            let (proj, norm2) =
                projective::free_flow::<f64, Q<f64>>(&inertia, q, q.dot(q), body, h);
            let proj = proj.normalized_by(norm2, q);
            let gap = |a: Q<f64>, b: Q<f64>| {
                [a.x - b.x, a.y - b.y, a.z - b.z, a.w - b.w]
                    .iter()
                    .fold(0.0f64, |m, d| m.max(d.abs()))
            };
            worst64 = worst64.max(gap(divided, proj));
            // The same body in f32.
            let to32 = |q: Q<f64>| Q {
                x: q.x as f32,
                y: q.y as f32,
                z: q.z as f32,
                w: q.w as f32,
            };
            let inertia32 =
                Inertia::<f32>::from_principal(moments.map(|m| m as f32), identity()).unwrap();
            let (q32, h32) = (to32(q), h as f32);
            let body32 = V {
                x: body.x as f32,
                y: body.y as f32,
                z: body.z as f32,
            };
            let (d32, n32) = free_flow::<f32, Q<f32>, true>(&inertia32, q32, body32, h32);
            let d32 = d32.normalized_by(q32.dot(q32) * n32, q32);
            let (p32, m32) =
                projective::free_flow::<f32, Q<f32>>(&inertia32, q32, q32.dot(q32), body32, h32);
            let p32 = p32.normalized_by(m32, q32);
            let wide = |q: Q<f32>| Q {
                x: f64::from(q.x),
                y: f64::from(q.y),
                z: f64::from(q.z),
                w: f64::from(q.w),
            };
            worst32 = worst32.max(gap(wide(d32), wide(p32)));
        }
        assert!(worst64 < 4e-15, "f64: {worst64:e}");
        assert!(worst32 < 2e-6, "f32: {worst32:e}");
    }

    #[test]
    fn huge_and_nan_angles_give_a_finite_unit_turn() {
        for a in [1e30, -1e300, f64::MAX, f64::INFINITY, f64::NAN] {
            let (c, s) = {
                let body = V {
                    x: a,
                    y: 1.0,
                    z: 0.0,
                };
                let q = Q {
                    x: 0.0,
                    y: 0.0,
                    z: 0.0,
                    w: 1.0,
                };
                let (_, turned, _, _) = body_turn::<f64, Q<f64>, 0, 1, true>(q, body, a, 0.0);
                (turned.y, -turned.z)
            };
            assert!(c.is_finite() && s.is_finite(), "{a}");
            assert!((c * c + s * s - 1.0).abs() < 1e-15, "{a}");
        }
    }
}
