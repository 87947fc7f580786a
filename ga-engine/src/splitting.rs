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
//! For the steps an engine takes (`range::RANGE`, `|L| < 1e18`), `projective.rs`
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

use super::free_flow::free_flow_normalized;
use super::inertia::Inertia;
use super::real::Real;
use super::rotation::{Q, V};
use super::turning::Turning;

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

#[cfg(all(test, target_arch = "x86_64"))]
mod tests {
    use super::*;
    use crate::sse::Q4;

    /// A seeded stream of floats in [-1, 1).
    fn stream(mut seed: u64) -> impl FnMut() -> f32 {
        move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 40) as f32 / (1u64 << 23) as f32 - 1.0
        }
    }

    fn bits(q: Q<f32>, l: V<f32>) -> [u32; 7] {
        [q.x, q.y, q.z, q.w, l.x, l.y, l.z].map(f32::to_bits)
    }

    #[test]
    fn the_register_form_gives_the_component_forms_bits() {
        let mut next = stream(0x2545_f491_4f6c_dd1d);
        let mut compared = 0;
        for case in 0..20_000 {
            let moments = [1.0 + next().abs() * 3.0, 0.5 + next().abs(), 2.0 + next()];
            let frame = Q {
                x: next(),
                y: next(),
                z: next(),
                w: next(),
            };
            let inertia = if case % 2 == 0 {
                Inertia::from_principal(moments, frame)
            } else {
                Inertia::from_principal(
                    moments,
                    Q {
                        x: 0.0,
                        y: 0.0,
                        z: 0.0,
                        w: 1.0,
                    },
                )
            };
            let Ok(inertia) = inertia else { continue };
            // Every few cases, momenta and steps far out, where the clamps decide.
            let scale = match case % 5 {
                0 => 1e3,
                1 => 1e19,
                _ => 10.0,
            };
            let q = Q {
                x: next(),
                y: next(),
                z: next(),
                w: next(),
            };
            let l = V {
                x: next() * scale,
                y: next() * scale,
                z: next() * scale,
            };
            let t = V {
                x: next(),
                y: next(),
                z: next(),
            };
            let h = if case % 7 == 0 { 2.0 } else { 1.0 / 60.0 };
            let (q, _) = step2(&inertia, q, l, t, h);
            let expected = step2(&inertia, q, l, t, h);
            let got = step2_in::<f32, Q4>(&inertia, q, l, t, h);
            assert_eq!(
                bits(got.0, got.1),
                bits(expected.0, expected.1),
                "case {case}"
            );
            // What `step2_f32` runs: the frame's products in the register too.
            let got = step2_f32(&inertia, q, l, t, h);
            assert_eq!(
                bits(got.0, got.1),
                bits(expected.0, expected.1),
                "case {case}"
            );
            compared += 1;
        }
        assert!(compared > 15_000);
    }
}
