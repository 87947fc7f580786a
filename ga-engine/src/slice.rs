//! Many bodies with one `dt`: groups of `N` bodies stepped side by side in lanes.
//!
//! The bodies of a group are gathered into a [`Group`] (one lane per body: [`Lanes`] of
//! four, or eight in one AVX register for f32 where the CPU has AVX), stepped by the
//! same generic code as one body, and scattered back; the bodies left over at the end
//! are stepped one by one. Each lane rounds as the scalar does, so a body's bits do not
//! depend on its neighbours, its position in the slice, the group width or the CPU.

use super::inertia::{Inertia, Precision};
use super::real::{Group, Lanes, Real};
use super::rotation::{Q, V};
use super::split::Split;

/// Which of the splitting steps.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Order {
    /// `splitting::step2`.
    Two,
    /// `splitting::step4`.
    Four,
}

/// Inertia, orientation, world momentum and world torque of a body.
pub(crate) type BodyParts<'a, T> = (&'a Inertia<T>, Q<T>, V<T>, V<T>);

/// A body of a slice, as the generic steps see it.
pub(crate) trait Parts<T: Real> {
    /// Inertia, orientation, world momentum, world torque.
    fn parts(&self) -> BodyParts<'_, T>;
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
        frame: quaternion(|i| parts[i].0.frame),
        turned: G::pack_mask(core::array::from_fn(|i| parts[i].0.turned)),
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

/// Every f32 body of `states`: eight at a time in one AVX register where the CPU has AVX
/// (checked at run time with `std`, or enabled at compile time), else four at a time.
/// Both give each body the bits it gets alone.
#[inline(always)]
pub(crate) fn step_all_f32<S: Parts<f32>>(states: &mut [S], h: f32, order: Order) {
    #[cfg(all(target_arch = "x86_64", any(feature = "std", target_feature = "avx")))]
    {
        if super::avx::available() {
            // SAFETY: the CPU has AVX (checked just above).
            unsafe { super::avx::step_all(states, h, order) };
            return;
        }
    }
    step_all::<f32, S, Lanes<f32, 4>, 4>(states, h, order);
}

/// Every f64 body of `states`, four at a time.
#[inline(always)]
pub(crate) fn step_all_f64<S: Parts<f64>>(states: &mut [S], h: f64, order: Order) {
    step_all::<f64, S, Lanes<f64, 4>, 4>(states, h, order);
}

#[cfg(all(test, feature = "std"))]
mod tests {
    use super::*;

    /// A body of the tests' slices.
    #[derive(Clone, Copy, Debug)]
    struct Body<T: Precision> {
        inertia: Inertia<T>,
        q: Q<T>,
        l: V<T>,
        t: V<T>,
    }

    impl<T: Precision> Parts<T> for Body<T> {
        fn parts(&self) -> BodyParts<'_, T> {
            (&self.inertia, self.q, self.l, self.t)
        }
        fn store(&mut self, q: Q<T>, l: V<T>) {
            self.q = q;
            self.l = l;
        }
    }

    /// Varied bodies (some with a turned principal frame, so that groups mix both).
    fn crowd<T: Precision>(n: usize) -> Vec<Body<T>> {
        (0..n)
            .map(|i| {
                let f = i as f64;
                let frame = if i % 3 == 0 {
                    Q {
                        x: T::splat(0.3),
                        y: T::splat(-0.2),
                        z: T::splat(0.1),
                        w: T::splat(0.9),
                    }
                } else {
                    Q {
                        x: T::splat(0.0),
                        y: T::splat(0.0),
                        z: T::splat(0.0),
                        w: T::splat(1.0),
                    }
                };
                let moments = [1.0 + 0.1 * f, 2.0 + 0.07 * f, 3.0 - 0.05 * f].map(T::splat);
                let (x, y, z, w) = ((f * 0.7).sin(), (f * 1.3).cos(), (f * 0.4).sin(), 2.0);
                let n = (x * x + y * y + z * z + w * w).sqrt();
                Body {
                    inertia: Inertia::from_principal(moments, frame).expect("valid"),
                    q: Q {
                        x: T::splat(x / n),
                        y: T::splat(y / n),
                        z: T::splat(z / n),
                        w: T::splat(w / n),
                    },
                    l: V {
                        x: T::splat(0.3 * f - 2.0),
                        y: T::splat(12.0 - f),
                        z: T::splat(0.5),
                    },
                    t: V {
                        x: T::splat(0.01 * f),
                        y: T::splat(-0.02),
                        z: T::splat(0.03),
                    },
                }
            })
            .collect()
    }

    fn bits<T: Precision + Into<f64>>(bodies: &[Body<T>]) -> Vec<u64> {
        bodies
            .iter()
            .flat_map(|b| [b.q.x, b.q.y, b.q.z, b.q.w, b.l.x, b.l.y, b.l.z])
            .map(|x| x.into().to_bits())
            .collect()
    }

    /// 21 bodies whose momenta take the sizes of `sizes` in turn.
    fn crowd_of_size(sizes: &[f32]) -> Vec<Body<f32>> {
        let mut bodies = crowd::<f32>(21);
        for (i, body) in bodies.iter_mut().enumerate() {
            let size = sizes[i % sizes.len()];
            body.l = V {
                x: size,
                y: -size,
                z: 0.5 * size,
            };
        }
        bodies
    }

    /// `steps` order-2 steps of `h` of `bodies` one at a time, by four lanes and (with
    /// AVX) by eight: the same bits. Returns the bodies stepped one at a time.
    fn widths_against_one_body(mut alone: Vec<Body<f32>>, h: f32, steps: usize) -> Vec<Body<f32>> {
        let mut four = alone.clone();
        #[cfg(target_arch = "x86_64")]
        let mut eight = alone.clone();
        for _ in 0..steps {
            for body in &mut alone {
                step_one(body, h, Order::Two);
            }
            step_all::<f32, _, Lanes<f32, 4>, 4>(&mut four, h, Order::Two);
            #[cfg(target_arch = "x86_64")]
            if super::super::avx::available() {
                // SAFETY: the CPU has AVX (checked just above).
                unsafe { super::super::avx::step_all(&mut eight, h, Order::Two) };
            }
        }
        assert_eq!(bits(&alone), bits(&four));
        #[cfg(target_arch = "x86_64")]
        if super::super::avx::available() {
            assert_eq!(bits(&alone), bits(&eight));
        }
        alone
    }

    /// 200 steps of 21 bodies (groups and a remainder) by each group width this build
    /// has, against each body stepped alone: the same bits.
    #[test]
    fn every_group_width_gives_the_bits_of_one_body_at_a_time() {
        let h32 = 1.0_f32 / 60.0;
        widths_against_one_body(crowd::<f32>(21), h32, 200);
        // Saturated angles and an overflowing body momentum, where the clamps decide
        // (`minps` and `maxps` must pick what the scalar's comparisons pick, NaN
        // included).
        let alone = widths_against_one_body(crowd_of_size(&[1e3, 1e20, 1e37]), 10.0, 20);
        assert!(alone
            .iter()
            .all(|b| [b.q.x, b.q.y, b.q.z, b.q.w].iter().all(|c| c.is_finite())));
        // Both forms of the turns in one group: projective (small momenta) and divided
        // (with its clamps); each lane must get the form one body alone gets.
        widths_against_one_body(crowd_of_size(&[1.0, 300.0, 1e5]), h32, 50);
        // f64, order 4, four lanes.
        let mut alone = crowd::<f64>(21);
        let mut four = alone.clone();
        for _ in 0..50 {
            for body in &mut alone {
                step_one(body, 0.01, Order::Four);
            }
            step_all::<f64, _, Lanes<f64, 4>, 4>(&mut four, 0.01, Order::Four);
        }
        assert_eq!(bits(&alone), bits(&four));
    }
}
