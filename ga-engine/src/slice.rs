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
    // Four values a row, each row's side by side in memory where the layout allows
    // (`Inertia` is `repr(C)`: the split's constants follow the moments, then the
    // frame; the torque follows the momentum in the states rustc lays out so far), so
    // that a form with registers to transpose reads each row at once ([`Group::columns`]);
    // the values a row only fills are not read.
    let [q_x, q_y, q_z, q_w] = G::columns(core::array::from_fn(|i| {
        let q = parts[i].1;
        [q.x, q.y, q.z, q.w]
    }));
    let [moment, outer_rate, middle_rate, outer_cubic] = G::columns(core::array::from_fn(|i| {
        let (m, s) = (parts[i].0.moments, &parts[i].0.split);
        [m.z, s.outer_rate, s.middle_rate, s.outer_cubic]
    }));
    let [middle_cubic, shift, reach, _] = G::columns(core::array::from_fn(|i| {
        let (s, frame) = (&parts[i].0.split, parts[i].0.frame);
        [s.middle_cubic, s.shift, s.reach, frame.x]
    }));
    let [l_x, l_y, l_z, t_x] = G::columns(core::array::from_fn(|i| {
        let (l, t) = (parts[i].2, parts[i].3);
        [l.x, l.y, l.z, t.x]
    }));
    let [_, _, t_y, t_z] = G::columns(core::array::from_fn(|i| {
        let (l, t) = (parts[i].2, parts[i].3);
        [l.y, l.z, t.y, t.z]
    }));
    let inertia = Inertia::<G> {
        // The steps read only the reference moment `z` (the turn about `L`); the other
        // two are the baselines' and the accessors', not gathered. NaN, not a plausible
        // value, so that a step that came to read them would fail the tests comparing a
        // slice with one body at a time loudly.
        moments: V {
            x: G::splat(f64::NAN),
            y: G::splat(f64::NAN),
            z: moment,
        },
        split: Split {
            outer_rate,
            middle_rate,
            outer_cubic,
            middle_cubic,
            shift,
            reach,
        },
        frame,
        turned,
        order: [0, 1, 2],
    };
    let q0 = Q {
        x: q_x,
        y: q_y,
        z: q_z,
        w: q_w,
    };
    let (l0, t0) = (
        V {
            x: l_x,
            y: l_y,
            z: l_z,
        },
        V {
            x: t_x,
            y: t_y,
            z: t_z,
        },
    );
    let h = G::pack([h; N]);
    let (qn, ln) = match order {
        Order::Two => super::splitting::step2(&inertia, q0, l0, t0, h),
        Order::Four => super::splitting::step4(&inertia, q0, l0, t0, h),
    };
    // Back as rows of four, transposed in registers where the form has them.
    let q_rows = G::rows([qn.x, qn.y, qn.z, qn.w]);
    let l_rows = G::rows([ln.x, ln.y, ln.z, ln.z]);
    for ((state, q), l) in group.iter_mut().zip(q_rows).zip(l_rows) {
        state.store(
            Q {
                x: q[0],
                y: q[1],
                z: q[2],
                w: q[3],
            },
            V {
                x: l[0],
                y: l[1],
                z: l[2],
            },
        );
    }
}

/// The lanes of component `f` of each body.
#[inline(always)]
fn lane<T, G: Group<T, N>, const N: usize>(f: impl Fn(usize) -> T) -> G {
    G::pack(core::array::from_fn(f))
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
