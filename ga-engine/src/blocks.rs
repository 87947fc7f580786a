//! Bodies stored column-wise, `N` to a block: each component of `N` bodies side by side
//! in one array, as the lanes of a group hold them, so that stepping a block loads each
//! component with one instruction instead of gathering it from `N` bodies and
//! scattering the results back (`slice.rs`, where the gather and the scatter took half
//! of the time: BENCHMARKS.md).
//!
//! A block steps by the same generic code as one body, each lane rounding as the scalar
//! does, so a body gets the bits it gets alone. A partly filled block (the last) steps
//! its empty lanes too, on copies of a body in it; they are never read.

use super::inertia::{Inertia, Order as AxisOrder, Precision};
use super::parts::Order;
use super::real::{Group, Lanes};
use super::rotation::{Q, V};
use super::split::Split;

/// `N` bodies, component by component.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Block<T: Precision, const N: usize> {
    /// Each lane's inertia (its `order` unused: see `orders`).
    inertia: Inertia<Lanes<T, N>>,
    /// Each lane's axis order (for the accessors).
    orders: [AxisOrder; N],
    /// Orientations.
    q: Q<Lanes<T, N>>,
    /// World momenta.
    l: V<Lanes<T, N>>,
    /// World torques.
    t: V<Lanes<T, N>>,
}

/// One body as a block holds it: inertia, orientation, world momentum, world torque.
pub(crate) type Lane<T> = (Inertia<T>, Q<T>, V<T>, V<T>);

impl<T: Precision, const N: usize> Block<T, N> {
    /// Every lane `body`.
    pub(crate) fn filled(body: &Lane<T>) -> Self {
        let (inertia, q, l, t) = body;
        let all = |x: T| Lanes([x; N]);
        Block {
            inertia: Inertia {
                moments: v_map(inertia.moments, all),
                split: split_map(&inertia.split, all),
                frame: q_map(inertia.frame, all),
                turned: [inertia.turned; N],
                order: [0, 1, 2],
            },
            orders: [inertia.order; N],
            q: q_map(*q, all),
            l: v_map(*l, all),
            t: v_map(*t, all),
        }
    }

    /// Lane `i` (below `N`).
    pub(crate) fn get(&self, i: usize) -> Lane<T> {
        let at = |x: Lanes<T, N>| x.0[i];
        let inertia = Inertia {
            moments: v_map(self.inertia.moments, at),
            split: split_map(&self.inertia.split, at),
            frame: q_map(self.inertia.frame, at),
            turned: self.inertia.turned[i],
            order: self.orders[i],
        };
        (
            inertia,
            q_map(self.q, at),
            v_map(self.l, at),
            v_map(self.t, at),
        )
    }

    /// Sets lane `i` (below `N`).
    pub(crate) fn set(&mut self, i: usize, body: &Lane<T>) {
        let (inertia, q, l, t) = body;
        let put = |to: &mut Lanes<T, N>, x: T| to.0[i] = x;
        let m = &mut self.inertia;
        v_put(&mut m.moments, inertia.moments, put);
        let (s, from) = (&mut m.split, &inertia.split);
        put(&mut s.outer_rate, from.outer_rate);
        put(&mut s.middle_rate, from.middle_rate);
        put(&mut s.outer_cubic, from.outer_cubic);
        put(&mut s.middle_cubic, from.middle_cubic);
        put(&mut s.shift, from.shift);
        put(&mut s.reach, from.reach);
        q_put(&mut m.frame, inertia.frame, put);
        m.turned[i] = inertia.turned;
        self.orders[i] = inertia.order;
        q_put(&mut self.q, *q, put);
        v_put(&mut self.l, *l, put);
        v_put(&mut self.t, *t, put);
    }

    /// Lane `i`'s orientation and momentum (below `N`).
    pub(crate) fn motion(&self, i: usize) -> (Q<T>, V<T>) {
        let at = |x: Lanes<T, N>| x.0[i];
        (q_map(self.q, at), v_map(self.l, at))
    }

    /// Sets lane `i`'s momentum.
    pub(crate) fn set_momentum(&mut self, i: usize, l: V<T>) {
        v_put(&mut self.l, l, |to: &mut Lanes<T, N>, x: T| to.0[i] = x);
    }

    /// Sets lane `i`'s torque.
    pub(crate) fn set_torque(&mut self, i: usize, t: V<T>) {
        v_put(&mut self.t, t, |to: &mut Lanes<T, N>, x: T| to.0[i] = x);
    }

    /// Lane `i`'s torque.
    pub(crate) fn torque(&self, i: usize) -> V<T> {
        v_map(self.t, |x| x.0[i])
    }

    /// Steps lanes `from .. from + M` as one group `G`.
    #[inline(always)]
    pub(crate) fn step_lanes<G: Group<T, M>, const M: usize>(
        &mut self,
        from: usize,
        h: T,
        order: Order,
    ) {
        let lanes = |x: Lanes<T, N>| G::pack(core::array::from_fn(|i| x.0[from + i]));
        let m = &self.inertia;
        let inertia = Inertia::<G> {
            moments: v_map(m.moments, lanes),
            split: split_map(&m.split, lanes),
            frame: q_map(m.frame, lanes),
            turned: G::pack_mask(core::array::from_fn(|i| m.turned[from + i])),
            order: [0, 1, 2],
        };
        let (q, l, t) = (
            q_map(self.q, lanes),
            v_map(self.l, lanes),
            v_map(self.t, lanes),
        );
        let h = G::pack([h; M]);
        let (q, l) = match order {
            Order::Two => super::splitting::step2(&inertia, q, l, t, h),
            Order::Four => super::splitting::step4(&inertia, q, l, t, h),
        };
        let put = |to: &mut Lanes<T, N>, x: G| {
            to.0[from..from + M].copy_from_slice(&x.unpack());
        };
        q_put(&mut self.q, q, put);
        v_put(&mut self.l, l, put);
    }
}

/// `f` on each component.
#[inline(always)]
fn v_map<A: Copy, B>(v: V<A>, f: impl Fn(A) -> B) -> V<B> {
    V {
        x: f(v.x),
        y: f(v.y),
        z: f(v.z),
    }
}

/// `f` on each component.
#[inline(always)]
fn q_map<A: Copy, B>(q: Q<A>, f: impl Fn(A) -> B) -> Q<B> {
    Q {
        x: f(q.x),
        y: f(q.y),
        z: f(q.z),
        w: f(q.w),
    }
}

/// `f` on each constant.
#[inline(always)]
fn split_map<A: Copy, B>(s: &Split<A>, f: impl Fn(A) -> B) -> Split<B> {
    Split {
        outer_rate: f(s.outer_rate),
        middle_rate: f(s.middle_rate),
        outer_cubic: f(s.outer_cubic),
        middle_cubic: f(s.middle_cubic),
        shift: f(s.shift),
        reach: f(s.reach),
    }
}

/// `put(to, from)` for each component.
#[inline(always)]
fn v_put<A, B: Copy>(to: &mut V<A>, from: V<B>, put: impl Fn(&mut A, B)) {
    put(&mut to.x, from.x);
    put(&mut to.y, from.y);
    put(&mut to.z, from.z);
}

/// `put(to, from)` for each component.
#[inline(always)]
fn q_put<A, B: Copy>(to: &mut Q<A>, from: Q<B>, put: impl Fn(&mut A, B)) {
    put(&mut to.x, from.x);
    put(&mut to.y, from.y);
    put(&mut to.z, from.z);
    put(&mut to.w, from.w);
}
