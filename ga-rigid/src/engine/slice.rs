//! Many bodies with one `dt`: groups of `N` bodies stepped side by side in lanes.
//!
//! The bodies of a group are gathered into [`Lanes`] (one lane per body), stepped by the
//! same generic code as one body, and scattered back; the bodies left over at the end
//! are stepped one by one. Each lane rounds as the scalar does, so a body's bits do not
//! depend on its neighbours, its position in the slice or the group width.

use super::inertia::{Inertia, Precision};
use super::real::{Lanes, Real};
use super::rotation::{Q, V};

/// Which of the splitting steps.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Order {
    /// `splitting::step2`.
    Two,
    /// `splitting::step4`.
    Four,
}

/// A body of a slice, as the generic steps see it.
pub(crate) trait Parts<T: Real> {
    /// Inertia, orientation, world momentum, world torque.
    fn parts(&self) -> (&Inertia<T>, Q<T>, V<T>, V<T>);
    /// Store the stepped orientation and momentum.
    fn store(&mut self, q: Q<T>, l: V<T>);
}

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

/// Every body of `states`, `N` at a time.
#[inline(always)]
pub(crate) fn step_all<T: Precision, S: Parts<T>, const N: usize>(
    states: &mut [S],
    h: T,
    order: Order,
) {
    let mut groups = states.chunks_exact_mut(N);
    for group in &mut groups {
        step_group::<T, S, N>(group, h, order);
    }
    for state in groups.into_remainder() {
        step_one(state, h, order);
    }
}

/// `N` bodies in lanes.
#[inline(always)]
fn step_group<T: Precision, S: Parts<T>, const N: usize>(group: &mut [S], h: T, order: Order) {
    let zero = T::splat(0.0);
    let mut lanes = Gathered::<T, N> {
        moments: [[zero; N]; 3],
        inverse: [[zero; N]; 3],
        frame: [[zero; N]; 4],
        turned: [false; N],
        q: [[zero; N]; 4],
        l: [[zero; N]; 3],
        t: [[zero; N]; 3],
    };
    for (i, state) in group.iter().enumerate() {
        let (inertia, q, l, t) = state.parts();
        put3(&mut lanes.moments, i, inertia.moments);
        put3(&mut lanes.inverse, i, inertia.inverse);
        put4(&mut lanes.frame, i, inertia.frame);
        lanes.turned[i] = inertia.turned;
        put4(&mut lanes.q, i, q);
        put3(&mut lanes.l, i, l);
        put3(&mut lanes.t, i, t);
    }
    let inertia = Inertia::<Lanes<T, N>> {
        moments: v(lanes.moments),
        inverse: v(lanes.inverse),
        frame: q(lanes.frame),
        turned: lanes.turned,
    };
    let h = Lanes([h; N]);
    let (qn, ln) = match order {
        Order::Two => super::splitting::step2(&inertia, q(lanes.q), v(lanes.l), v(lanes.t), h),
        Order::Four => super::splitting::step4(&inertia, q(lanes.q), v(lanes.l), v(lanes.t), h),
    };
    for (i, state) in group.iter_mut().enumerate() {
        state.store(
            Q {
                x: qn.x.0[i],
                y: qn.y.0[i],
                z: qn.z.0[i],
                w: qn.w.0[i],
            },
            V {
                x: ln.x.0[i],
                y: ln.y.0[i],
                z: ln.z.0[i],
            },
        );
    }
}

/// A group's inputs, component by component.
struct Gathered<T, const N: usize> {
    moments: [[T; N]; 3],
    inverse: [[T; N]; 3],
    frame: [[T; N]; 4],
    turned: [bool; N],
    q: [[T; N]; 4],
    l: [[T; N]; 3],
    t: [[T; N]; 3],
}

#[inline(always)]
fn put3<T: Copy, const N: usize>(dst: &mut [[T; N]; 3], i: usize, x: V<T>) {
    dst[0][i] = x.x;
    dst[1][i] = x.y;
    dst[2][i] = x.z;
}

#[inline(always)]
fn put4<T: Copy, const N: usize>(dst: &mut [[T; N]; 4], i: usize, x: Q<T>) {
    dst[0][i] = x.x;
    dst[1][i] = x.y;
    dst[2][i] = x.z;
    dst[3][i] = x.w;
}

#[inline(always)]
fn v<T, const N: usize>(c: [[T; N]; 3]) -> V<Lanes<T, N>> {
    let [x, y, z] = c;
    V {
        x: Lanes(x),
        y: Lanes(y),
        z: Lanes(z),
    }
}

#[inline(always)]
fn q<T, const N: usize>(c: [[T; N]; 4]) -> Q<Lanes<T, N>> {
    let [x, y, z, w] = c;
    Q {
        x: Lanes(x),
        y: Lanes(y),
        z: Lanes(z),
        w: Lanes(w),
    }
}
