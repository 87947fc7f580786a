//! The steps: the free flow between torque kicks, second order, and its fourth-order
//! composition (docs/derivations/corrected-splitting.md has the derivation, its sources
//! and the tests that check it).
//!
//! The state is the orientation and the angular momentum **in the world frame**. A
//! torque constant in the world frame changes only the world momentum, and exactly:
//! `L += h T` (the kick), and `kick(h/2) free(h) kick(h/2)` is Strang's splitting:
//! time-reversible, second order. The free flow (`free_flow.rs`) never touches the world
//! momentum, so `|L|` of a torque-free body is kept to the bit; it is the free body's
//! energy split around the Casimir `|L|^2` into three turns about principal axes, each
//! angle corrected for its own part of the splitting's `h^2` energy error, and a turn
//! about `L`, all rational (no sine or cosine) and normalised once.
//!
//! The fourth-order step is the symmetric triple jump `S(g1 h) S(g0 h) S(g1 h)` with
//! `g1 = 1/(2 - 2^(1/3))`, `g0 = 1 - 2 g1` (Yoshida, Phys. Lett. A 150, 1990; Suzuki,
//! Phys. Lett. A 146, 1990), the kicks between free flows merged.
//!
//! Unoptimised builds: every function of a step is `#[inline(always)]` so that the
//! optimiser sees one body's (or one lane group's) whole chain, but unoptimised, each
//! inlined temporary keeps its own stack slot, and the slice form's AVX loop had a frame
//! of over a megabyte (its fourth order two: a test thread's 2 MiB stack overflowed).
//! With debug assertions on, the turns, the free flows and each order's step are ordinary
//! functions instead (CI's tests build through clippy, which also turns MIR's own
//! optimisations off, so their frames are larger still than a plain `cargo test`'s).

use super::free_flow::{free_flow_from, free_flow_normalized};
use super::inertia::Inertia;
use super::real::Real;
use super::rotation::{Q, V};
use super::turning::{Momentum, Turning};

/// One second-order step of `h`: body orientation `q` (body to world), world momentum
/// `l`, world torque `t` held over the step.
// Inlined only when optimised (see "Unoptimised builds" above): unoptimised, the slice
// form's loop would hold the stack slots of both orders at once.
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline)]
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
    // Each kick `h (t/2)`: `t/2` is exact and known early, and the kick is one product
    // after `h` (as `kicked` in the register form).
    let t = t.scale_all(R::splat(0.5));
    let l = l.add_scaled(h, t);
    let (q_p, q_p2) = principal(inertia, q);
    let q_p = free_flow_from(inertia, T::pack(q_p), q_p2, T::Momentum::pack(l), h).unpack();
    let l = l.add_scaled(h, t);
    (inertia.body_orientation(q_p), l)
}

/// The unit orientation in the principal frame, `q p` ([`Inertia::principal_orientation`]),
/// and its squared norm: the unit check's where the frame is not turned (`Q::dot` and
/// `Turning::dot` sum in one order, so it is the bits the free flow would compute).
#[inline(always)]
fn principal<R: Real>(inertia: &Inertia<R>, q: Q<R>) -> (Q<R>, R) {
    let (q, q2) = q.unit_and_norm2();
    principal_of_unit(inertia, q, q2)
}

/// [`principal`] of a unit `q` whose squared norm is `q2`.
#[inline(always)]
fn principal_of_unit<R: Real>(inertia: &Inertia<R>, q: Q<R>, q2: R) -> (Q<R>, R) {
    if R::any(inertia.turned) {
        let q_p = inertia.principal_orientation(q);
        (q_p, q_p.dot(q_p))
    } else {
        (q, q2)
    }
}

/// [`step2_in`] with the frame's products also in the form `T` (one register for one f32
/// body), as `Inertia::principal_orientation` and `body_orientation` do them: the same
/// bits. Kept apart from [`step2_in`], which the lane forms run: written this way there,
/// the slice form measured slower (BENCHMARKS.md).
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn step2_in_framed<R: Real, T: Turning<R>>(
    inertia: &Inertia<R>,
    q: Q<R>,
    l: V<R>,
    t: V<R>,
    h: R,
) -> (Q<R>, V<R>) {
    // The kicks `h (t/2)` (as `step2_in`) on the momentum in the form `T` reads (one
    // register for one f32 body).
    let t = T::Momentum::pack(t).scaled(R::splat(0.5));
    let l = T::Momentum::pack(l).add_scaled(h, t);
    let (q, q2, _) = unit_packed::<R, T>(q);
    let (q_p, q_p2) = into_principal(inertia, q, q2);
    let q = out_of_principal(inertia, free_flow_from(inertia, q_p, q_p2, l, h));
    let l = l.add_scaled(h, t);
    (q.unpack(), l.unpack())
}

/// [`step2_with`] with the orientation in the form `T` (as [`step2_in_framed`]): the same
/// bits. The torque reads the orientation in components.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn step2_with_framed<R: Real, T: Turning<R>>(
    inertia: &Inertia<R>,
    q: Q<R>,
    l: V<R>,
    h: R,
    mut torque: impl FnMut(Q<R>) -> V<R>,
) -> (Q<R>, V<R>) {
    let half = h * R::splat(0.5);
    let (packed, q2, q) = unit_packed::<R, T>(q);
    let l = l.add_scaled(half, torque(q));
    let (q_p, q_p2) = into_principal(inertia, packed, q2);
    let flowed = free_flow_from(inertia, q_p, q_p2, T::Momentum::pack(l), h);
    let q = out_of_principal(inertia, flowed).unpack();
    let l = l.add_scaled(half, torque(q));
    (q, l)
}

/// [`step4`] with the orientation and the momentum in the form `T` (as
/// [`step2_in_framed`]): the same bits.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn step4_framed<R: Real, T: Turning<R>>(
    inertia: &Inertia<R>,
    q: Q<R>,
    l: V<R>,
    t: V<R>,
    h: R,
) -> (Q<R>, V<R>) {
    let (h1, h0) = (h * R::splat(G1), h * R::splat(G0));
    let outer_kick = h * R::splat(0.5 * G1);
    let inner_kick = h * R::splat(0.5 * (G1 + G0));
    let t = T::Momentum::pack(t);
    let (q, q2, _) = unit_packed::<R, T>(q);
    let (q_p, q_p2) = into_principal(inertia, q, q2);
    let l = T::Momentum::pack(l).add_scaled(outer_kick, t);
    let q1 = free_flow_from(inertia, q_p, q_p2, l, h1);
    let l = l.add_scaled(inner_kick, t);
    let q2 = free_flow_normalized(inertia, q1, l, h0);
    let l = l.add_scaled(inner_kick, t);
    let q3 = free_flow_normalized(inertia, q2, l, h1);
    let l = l.add_scaled(outer_kick, t);
    (out_of_principal(inertia, q3).unpack(), l.unpack())
}

/// `Q::unit_and_norm2` in the form `T`: the unit orientation packed, its squared norm,
/// and it in components. The squared norm comes from the packed form (the same sums in
/// the same order; one instruction fewer than LLVM's from components).
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn unit_packed<R: Real, T: Turning<R>>(q: Q<R>) -> (T, R, Q<R>) {
    let packed = T::pack(q);
    let norm2 = packed.dot(packed);
    if R::all(Q::unit_norm2(norm2)) {
        (packed, norm2, q)
    } else {
        let (q, q2) = q.unit_and_norm2();
        (T::pack(q), q2, q)
    }
}

/// [`principal_of_unit`] in the form `T`: `q p` and its squared norm, or `q` and `q2`
/// where the frame is not turned.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn into_principal<R: Real, T: Turning<R>>(inertia: &Inertia<R>, q: T, q2: R) -> (T, R) {
    let turned = inertia.turned;
    if R::any(turned) {
        let q_p = T::select(turned, q.times(inertia.frame), q);
        (q_p, q_p.dot(q_p))
    } else {
        (q, q2)
    }
}

/// `Inertia::body_orientation` in the form `T`: `q_p p*`.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn out_of_principal<R: Real, T: Turning<R>>(inertia: &Inertia<R>, q_p: T) -> T {
    let turned = inertia.turned;
    if R::any(turned) {
        T::select(turned, q_p.times_conj(inertia.frame), q_p)
    } else {
        q_p
    }
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

/// [`step2_with`] for one `f32` body: its quaternion in one SSE register on x86-64, as
/// [`step2_f32`] (the same bits).
#[inline(always)]
pub(crate) fn step2_with_f32(
    inertia: &Inertia<f32>,
    q: Q<f32>,
    l: V<f32>,
    h: f32,
    torque: impl FnMut(Q<f32>) -> V<f32>,
) -> (Q<f32>, V<f32>) {
    #[cfg(target_arch = "x86_64")]
    {
        step2_with_framed::<f32, super::sse::Q4>(inertia, q, l, h, torque)
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        step2_with(inertia, q, l, h, torque)
    }
}

/// [`step4`] for one `f32` body: its quaternion in one SSE register on x86-64, as
/// [`step2_f32`] (the same bits).
#[inline(always)]
pub(crate) fn step4_f32(
    inertia: &Inertia<f32>,
    q: Q<f32>,
    l: V<f32>,
    t: V<f32>,
    h: f32,
) -> (Q<f32>, V<f32>) {
    #[cfg(target_arch = "x86_64")]
    {
        step4_framed::<f32, super::sse::Q4>(inertia, q, l, t, h)
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        step4(inertia, q, l, t, h)
    }
}

/// One second-order step of `h` under a torque that depends on the orientation:
/// `kick(h/2, T(q_n)) free(h) kick(h/2, T(q_n+1))`, Strang's splitting with the torque
/// read at both ends. For a torque from a potential (gravity on a top) the energy then
/// does not drift; holding `T(q_n)` over the whole step lets it drift.
#[inline(always)]
pub(crate) fn step2_with<R: Real>(
    inertia: &Inertia<R>,
    q: Q<R>,
    l: V<R>,
    h: R,
    mut torque: impl FnMut(Q<R>) -> V<R>,
) -> (Q<R>, V<R>) {
    let half = h * R::splat(0.5);
    let (q, q2) = q.unit_and_norm2();
    let l = l.add_scaled(half, torque(q));
    let (q_p, q_p2) = principal_of_unit(inertia, q, q2);
    let q = inertia.body_orientation(free_flow_from(inertia, q_p, q_p2, l, h));
    let l = l.add_scaled(half, torque(q));
    (q, l)
}

/// The triple jump's outer weight `1/(2 - 2^(1/3))`.
const G1: f64 = 1.351_207_191_959_657_8;
/// The triple jump's middle weight `1 - 2 g1` (negative).
const G0: f64 = 1.0 - 2.0 * G1;

/// One fourth-order step of `h`: three second-order steps of `g1 h, g0 h, g1 h`, their
/// adjacent half-kicks merged into one.
// Inlined only when optimised (see "Unoptimised builds" above): unoptimised, the slice
// form's loop would hold the stack slots of both orders at once.
#[cfg_attr(not(debug_assertions), inline(always))]
#[cfg_attr(debug_assertions, inline)]
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
    let (q_p, q_p2) = principal(inertia, q);
    let l = l.add_scaled(outer_kick, t);
    // Each free flow reads the body momentum through its starting quaternion, which must
    // be unit.
    let q1 = free_flow_from(inertia, q_p, q_p2, l, h1);
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

    /// A seeded stream of floats in [-1, 1) (the workspace's test generator).
    fn stream(seed: u64) -> impl FnMut() -> f32 {
        let mut rng = ga_test_rng::Rng::new(seed);
        move || rng.uniform_f32(-1.0, 1.0)
    }

    fn bits(q: Q<f32>, l: V<f32>) -> [u32; 7] {
        [q.x, q.y, q.z, q.w, l.x, l.y, l.z].map(f32::to_bits)
    }

    #[test]
    fn the_register_forms_give_the_component_forms_bits() {
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
            let raw = q;
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
            // The fourth order and the step with a torque read at both ends (a torque
            // that turns with the body, so that the two reads differ), likewise, from a
            // unit orientation and from the drawn one (not unit: rescaled first).
            for q in [q, raw] {
                let expected = step4(&inertia, q, l, t, h);
                let got = step4_f32(&inertia, q, l, t, h);
                assert_eq!(
                    bits(got.0, got.1),
                    bits(expected.0, expected.1),
                    "order 4, case {case}"
                );
                let torque = |q: Q<f32>| q.rotate(t);
                let expected = step2_with(&inertia, q, l, h, torque);
                let got = step2_with_f32(&inertia, q, l, h, torque);
                assert_eq!(
                    bits(got.0, got.1),
                    bits(expected.0, expected.1),
                    "with a torque, case {case}"
                );
            }
            compared += 1;
        }
        assert!(compared > 15_000);
    }
}
