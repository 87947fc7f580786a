//! The free-flow-plus-kick splitting: second order, and its fourth-order composition.
//!
//! The state is the orientation and the angular momentum **in the world frame**. A
//! torque constant in the world frame changes only the world momentum, and exactly:
//! `L += h T` (the kick). The free body keeps its world momentum, and its kinetic energy
//! `H = L1^2/2I1 + L2^2/2I2 + L3^2/2I3` (body components) is split into its three
//! terms; each term's flow is an exact rotation of the body about one principal axis by
//! the angle `h L_k / I_k` (L_k is constant along it). The symmetric sequence
//! `1(h/2) 2(h/2) 3(h) 2(h/2) 1(h/2)` is the splitting of Dullweber, Leimkuhler and
//! McLachlan (J. Chem. Phys. 107, 1997; Touma and Wisdom, Astron. J. 107, 1994, for the
//! same idea), and `kick(h/2) free(h) kick(h/2)` is Strang's splitting around it:
//! symplectic, time-reversible, second order.
//!
//! Since the world momentum is never touched by the free flow, `|L|` of a torque-free
//! body is conserved to the bit, not just to rounding; the body momentum the angles need
//! is computed from it and the orientation at the start of each free flow and then turned
//! along with the body. The energy error is the splitting's (bounded, O(h^2)) plus the
//! orientation's rounding.
//!
//! The fourth-order step is the symmetric triple jump `S(g1 h) S(g0 h) S(g1 h)` with
//! `g1 = 1/(2 - 2^(1/3))`, `g0 = 1 - 2 g1` (Yoshida, Phys. Lett. A 150, 1990; Suzuki,
//! Phys. Lett. A 146, 1990), the kicks between free flows merged.

use super::inertia::Inertia;
use super::real::Real;
use super::rotation::{unturn_about, Q, V};
use super::trig::cos_sin_mod_pi;

/// One sub-rotation about axis `K` with the half-angle rate `rate` (`h f / 2 I_K`):
/// `q -> q (cos a + sin a e_K)`, `a = rate L_K`, and the body momentum turned back.
#[inline(always)]
fn sub_rotation<R: Real, const K: usize>(q: Q<R>, body: V<R>, rate: R) -> (Q<R>, V<R>, R, R) {
    let (c, s) = cos_sin_mod_pi(rate * body.get(K));
    (q.turn_about(K, c, s), body, c, s)
}

/// The free flow over `h`: `q_p` (principal axes to world) turned by the five
/// sub-rotations `1(h/2) 2(h/2) 3(h) 2(h/2) 1(h/2)` for the world momentum `l`.
#[inline(always)]
fn free_flow<R: Real>(inertia: &Inertia<R>, q_p: Q<R>, l: V<R>, h: R) -> Q<R> {
    // The sub-rotation about axis k over h f is by h f L_k / I_k: the quaternion
    // cos(a) + sin(a) e_k with a = (h f / 2 I_k) L_k.
    let quarter = h * R::splat(0.25);
    let half = h * R::splat(0.5);
    let (r1, r2, r3) = (
        quarter * inertia.inverse.x,
        quarter * inertia.inverse.y,
        half * inertia.inverse.z,
    );
    let body = q_p.rotate_inv(l);
    let (q, body, c, s) = sub_rotation::<R, 0>(q_p, body, r1);
    let body = unturn_about(0, c, s, body);
    let (q, body, c, s) = sub_rotation::<R, 1>(q, body, r2);
    let body = unturn_about(1, c, s, body);
    let (q, body, c, s) = sub_rotation::<R, 2>(q, body, r3);
    let body = unturn_about(2, c, s, body);
    let (q, body, c, s) = sub_rotation::<R, 1>(q, body, r2);
    let body = unturn_about(1, c, s, body);
    let (q, _, _, _) = sub_rotation::<R, 0>(q, body, r1);
    q
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
    let half = h * R::splat(0.5);
    let l = l.add_scaled(half, t);
    let q_p = inertia.principal_orientation(q);
    let q_p = free_flow(inertia, q_p, l, h).normalized_near(q_p);
    let l = l.add_scaled(half, t);
    (inertia.body_orientation(q_p), l)
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
    let q_p = free_flow(inertia, q_p, l, h).normalized_near(q_p);
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
    let q1 = free_flow(inertia, q_p, l, h1);
    let l = l.add_scaled(inner_kick, t);
    let q2 = free_flow(inertia, q1, l, h0);
    let l = l.add_scaled(inner_kick, t);
    let q3 = free_flow(inertia, q2, l, h1).normalized_near(q_p);
    let l = l.add_scaled(outer_kick, t);
    (inertia.body_orientation(q3), l)
}
