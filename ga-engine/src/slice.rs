//! Many bodies with one `dt`: groups of `N` bodies stepped side by side in lanes.
//!
//! The bodies of a group are gathered into a [`Group`] (one lane per body: four in
//! [`Lanes`](crate::real::Lanes), or eight in one AVX register for f32 where the CPU has
//! AVX, as `dispatch.rs` chooses), stepped by the same generic code as one body, and
//! scattered back; the bodies left over at the end
//! are stepped one by one. Each lane rounds as the scalar does, so a body's bits do not
//! depend on its neighbours, its position in the slice, the group width or the CPU.

use super::inertia::{Inertia, Precision};
use super::parts::{BodyParts, Order, Parts};
use super::real::{Group, Real};
use super::rotation::{Q, V};
use super::split::Split;

/// One body by the generic step.
#[inline(always)]
pub(crate) fn step_one<T: Real, S: Parts<T>>(state: &mut S, h: T, order: Order) {
    let (inertia, q, l, t) = state.parts();
    let (q, l) = match order {
        Order::Two => super::splitting::step2(inertia, q, l, t, h),
        Order::Four => super::splitting::step4(inertia, q, l, t, h),
    };
    state.store(q, l);
}

/// Every body of `states`, `N` at a time in the lanes of `G`.
#[inline(always)]
pub(crate) fn step_all<T: Precision, S: Parts<T>, G: Group<T, N>, const N: usize>(
    states: &mut [S],
    h: T,
    order: Order,
) {
    let mut groups = states.chunks_exact_mut(N);
    for group in &mut groups {
        step_group::<T, S, G, N>(group, h, order);
    }
    for state in groups.into_remainder() {
        step_one(state, h, order);
    }
}

/// `N` bodies in lanes.
#[inline(always)]
fn step_group<T: Precision, S: Parts<T>, G: Group<T, N>, const N: usize>(
    group: &mut [S],
    h: T,
    order: Order,
) {
    // Each lane's component read straight from its body (an array built from `N`
    // values, not a loop filling arrays in memory: read back as one vector, such arrays
    // stall on store forwarding).
    let parts: [BodyParts<'_, T>; N] = core::array::from_fn(|i| group[i].parts());
    let turned = G::pack_mask(core::array::from_fn(|i| parts[i].0.turned));
    // A body whose frame is not turned has the identity there: the frames are gathered
    // only for a group with a turned one (most bodies have none).
    let frame = if G::any(turned) {
        quaternion(|i| parts[i].0.frame)
    } else {
        Q::identity()
    };
    let inertia = Inertia::<G> {
        moments: vector(|i| parts[i].0.moments),
        split: Split {
            outer_rate: lane(|i| parts[i].0.split.outer_rate),
            middle_rate: lane(|i| parts[i].0.split.middle_rate),
            outer_cubic: lane(|i| parts[i].0.split.outer_cubic),
            middle_cubic: lane(|i| parts[i].0.split.middle_cubic),
            shift: lane(|i| parts[i].0.split.shift),
            reach: lane(|i| parts[i].0.split.reach),
        },
        frame,
        turned,
        order: [0, 1, 2],
    };
    let (q0, l0, t0) = (
        quaternion(|i| parts[i].1),
        vector(|i| parts[i].2),
        vector(|i| parts[i].3),
    );
    let h = G::pack([h; N]);
    let (qn, ln) = match order {
        Order::Two => super::splitting::step2(&inertia, q0, l0, t0, h),
        Order::Four => super::splitting::step4(&inertia, q0, l0, t0, h),
    };
    let (qn, ln) = (
        [qn.x, qn.y, qn.z, qn.w].map(G::unpack),
        [ln.x, ln.y, ln.z].map(G::unpack),
    );
    for (i, state) in group.iter_mut().enumerate() {
        state.store(
            Q {
                x: qn[0][i],
                y: qn[1][i],
                z: qn[2][i],
                w: qn[3][i],
            },
            V {
                x: ln[0][i],
                y: ln[1][i],
                z: ln[2][i],
            },
        );
    }
}

/// The lanes of component `f` of each body.
#[inline(always)]
fn lane<T, G: Group<T, N>, const N: usize>(f: impl Fn(usize) -> T) -> G {
    G::pack(core::array::from_fn(f))
}

/// A vector of lanes, `f(i)` the vector of lane `i`.
#[inline(always)]
fn vector<T: Copy, G: Group<T, N>, const N: usize>(f: impl Fn(usize) -> V<T>) -> V<G> {
    V {
        x: lane(|i| f(i).x),
        y: lane(|i| f(i).y),
        z: lane(|i| f(i).z),
    }
}

/// A quaternion of lanes, `f(i)` the quaternion of lane `i`.
#[inline(always)]
fn quaternion<T: Copy, G: Group<T, N>, const N: usize>(f: impl Fn(usize) -> Q<T>) -> Q<G> {
    Q {
        x: lane(|i| f(i).x),
        y: lane(|i| f(i).y),
        z: lane(|i| f(i).z),
        w: lane(|i| f(i).w),
    }
}
