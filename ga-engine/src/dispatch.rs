//! Which group width steps a slice: for `f32` on x86-64, eight bodies in one AVX register
//! where the CPU has AVX (checked at run time with `std`, or enabled at compile time),
//! else four; for `f64`, four in one AVX register where the CPU has AVX, else two in one
//! SSE2 register on x86-64 (four in arrays elsewhere). Every width and form gives each
//! body the bits it gets alone.

#[cfg(all(target_arch = "x86_64", any(feature = "std", target_feature = "avx")))]
use super::avx::F32x8;
#[cfg(all(target_arch = "x86_64", any(feature = "std", target_feature = "avx")))]
use super::avx64::F64x4;
#[cfg(feature = "columns")]
use super::blocks::Block;
use super::parts::{Order, Parts};
use super::real::Lanes;
use super::slice;
#[cfg(target_arch = "x86_64")]
use super::sse64::F64x2;

/// Whether this CPU has AVX.
#[cfg(all(target_arch = "x86_64", any(feature = "std", target_feature = "avx")))]
#[inline(always)]
fn avx_available() -> bool {
    #[cfg(target_feature = "avx")]
    {
        true
    }
    #[cfg(all(not(target_feature = "avx"), feature = "std"))]
    {
        std::is_x86_feature_detected!("avx")
    }
}

/// Every `f32` body of `states`, eight at a time in one AVX register: the generic slice
/// step inlined into the one function compiled for AVX.
///
/// # Safety
/// The CPU must have AVX ([`avx_available`]).
#[cfg(all(target_arch = "x86_64", any(feature = "std", target_feature = "avx")))]
#[target_feature(enable = "avx")]
unsafe fn step_all_avx<S: Parts<f32>>(states: &mut [S], h: f32, order: Order) {
    slice::step_all::<f32, S, F32x8, 8>(states, h, order);
}

/// Every f32 body of `states`: eight at a time in one AVX register where the CPU has AVX
/// (checked at run time with `std`, or enabled at compile time), else four at a time.
/// Both give each body the bits it gets alone.
#[inline(always)]
pub(crate) fn step_all_f32<S: Parts<f32>>(states: &mut [S], h: f32, order: Order) {
    #[cfg(all(target_arch = "x86_64", any(feature = "std", target_feature = "avx")))]
    {
        if avx_available() {
            // SAFETY: the CPU has AVX (checked just above).
            unsafe { step_all_avx(states, h, order) };
            return;
        }
    }
    slice::step_all::<f32, S, Lanes<f32, 4>, 4>(states, h, order);
}

/// Every block of `f32` bodies, eight lanes in one AVX register.
///
/// # Safety
/// The CPU must have AVX ([`avx_available`]).
#[cfg(all(
    feature = "columns",
    target_arch = "x86_64",
    any(feature = "std", target_feature = "avx")
))]
#[target_feature(enable = "avx")]
unsafe fn step_blocks_avx(blocks: &mut [Block<f32, 8>], h: f32, order: Order) {
    for block in blocks {
        block.step_lanes::<F32x8, 8>(0, h, order);
    }
}

/// Every block of `f32` bodies: one AVX register a component where the CPU has AVX, else
/// two groups of four. Both give each body the bits it gets alone.
#[cfg(feature = "columns")]
#[inline(always)]
pub(crate) fn step_blocks_f32(blocks: &mut [Block<f32, 8>], h: f32, order: Order) {
    #[cfg(all(target_arch = "x86_64", any(feature = "std", target_feature = "avx")))]
    {
        if avx_available() {
            // SAFETY: the CPU has AVX (checked just above).
            unsafe { step_blocks_avx(blocks, h, order) };
            return;
        }
    }
    for block in blocks {
        for from in [0, 4] {
            step_half(block, from, h, order);
        }
    }
}

/// Lanes `from .. from + 4` of a block as one group of four: one copy of the lane code
/// for both halves (inlined twice, it tripled the crate's release build time).
#[cfg(feature = "columns")]
#[inline(never)]
fn step_half(block: &mut Block<f32, 8>, from: usize, h: f32, order: Order) {
    block.step_lanes::<Lanes<f32, 4>, 4>(from, h, order);
}

/// Every block of `f64` bodies, four lanes in one AVX register.
///
/// # Safety
/// The CPU must have AVX ([`avx_available`]).
#[cfg(all(
    feature = "columns",
    target_arch = "x86_64",
    any(feature = "std", target_feature = "avx")
))]
#[target_feature(enable = "avx")]
unsafe fn step_blocks_avx64(blocks: &mut [Block<f64, 4>], h: f64, order: Order) {
    for block in blocks {
        block.step_lanes::<F64x4, 4>(0, h, order);
    }
}

/// Every block of `f64` bodies, four lanes at a time: in one AVX register where the CPU has
/// AVX, else in arrays (columns load them whole, so arrays of four are fast there). Both
/// give each body the bits it gets alone.
#[cfg(feature = "columns")]
#[inline(always)]
pub(crate) fn step_blocks_f64(blocks: &mut [Block<f64, 4>], h: f64, order: Order) {
    #[cfg(all(target_arch = "x86_64", any(feature = "std", target_feature = "avx")))]
    {
        if avx_available() {
            // SAFETY: the CPU has AVX (checked just above).
            unsafe { step_blocks_avx64(blocks, h, order) };
            return;
        }
    }
    for block in blocks {
        block.step_lanes::<Lanes<f64, 4>, 4>(0, h, order);
    }
}

/// Every `f64` body of `states`, four at a time in one AVX register.
///
/// # Safety
/// The CPU must have AVX ([`avx_available`]).
#[cfg(all(target_arch = "x86_64", any(feature = "std", target_feature = "avx")))]
#[target_feature(enable = "avx")]
unsafe fn step_all_avx64<S: Parts<f64>>(states: &mut [S], h: f64, order: Order) {
    slice::step_all::<f64, S, F64x4, 4>(states, h, order);
}

/// Every f64 body of `states`: four at a time in one AVX register where the CPU has AVX,
/// else two at a time in one SSE2 register on x86-64 (in arrays of four, LLVM stepped part
/// of the lanes with scalar instructions: the slice took longer than one body at a time),
/// else four at a time in arrays. All give each body the bits it gets alone.
#[inline(always)]
pub(crate) fn step_all_f64<S: Parts<f64>>(states: &mut [S], h: f64, order: Order) {
    #[cfg(all(target_arch = "x86_64", any(feature = "std", target_feature = "avx")))]
    {
        if avx_available() {
            // SAFETY: the CPU has AVX (checked just above).
            unsafe { step_all_avx64(states, h, order) };
            return;
        }
    }
    #[cfg(target_arch = "x86_64")]
    slice::step_all::<f64, S, F64x2, 2>(states, h, order);
    #[cfg(not(target_arch = "x86_64"))]
    slice::step_all::<f64, S, Lanes<f64, 4>, 4>(states, h, order);
}

#[cfg(all(test, feature = "std"))]
mod tests {
    use super::*;
    use crate::inertia::{Inertia, Precision};
    use crate::parts::BodyParts;
    use crate::rotation::{Q, V};
    use crate::slice::{step_all, step_one};

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
    fn crowd_of_size<T: Precision>(sizes: &[f64]) -> Vec<Body<T>> {
        let mut bodies = crowd::<T>(21);
        for (i, body) in bodies.iter_mut().enumerate() {
            let size = sizes[i % sizes.len()];
            body.l = V {
                x: T::splat(size),
                y: T::splat(-size),
                z: T::splat(0.5 * size),
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
            if avx_available() {
                // SAFETY: the CPU has AVX (checked just above).
                unsafe { step_all_avx(&mut eight, h, Order::Two) };
            }
        }
        assert_eq!(bits(&alone), bits(&four));
        #[cfg(target_arch = "x86_64")]
        if avx_available() {
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
        // f64, order 2 and 4, four lanes in arrays, two in an SSE2 register and (with AVX)
        // four in one register: both forms of the turns in one group, and the divided
        // form's clamps among the lanes (momenta whose squares overflow, near the largest
        // f64).
        let wide = crowd_of_size::<f64>(&[1.0, 300.0, 1e5, 1e20, 1e200, 1e307]);
        for (start, h, order) in [
            (crowd::<f64>(21), 0.01, Order::Four),
            (crowd::<f64>(21), 0.01, Order::Two),
            (crowd_of_size(&[1.0, 300.0, 1e5]), 1.0 / 60.0, Order::Two),
            (wide.clone(), 10.0, Order::Two),
            (wide, 1e160, Order::Two),
        ] {
            let mut alone = start;
            let mut four = alone.clone();
            #[cfg(target_arch = "x86_64")]
            let (mut two, mut avx) = (alone.clone(), alone.clone());
            for _ in 0..50 {
                for body in &mut alone {
                    step_one(body, h, order);
                }
                step_all::<f64, _, Lanes<f64, 4>, 4>(&mut four, h, order);
                #[cfg(target_arch = "x86_64")]
                step_all::<f64, _, F64x2, 2>(&mut two, h, order);
                #[cfg(target_arch = "x86_64")]
                if avx_available() {
                    // SAFETY: the CPU has AVX (checked just above).
                    unsafe { step_all_avx64(&mut avx, h, order) };
                }
            }
            assert_eq!(bits(&alone), bits(&four));
            #[cfg(target_arch = "x86_64")]
            assert_eq!(bits(&alone), bits(&two));
            #[cfg(target_arch = "x86_64")]
            if avx_available() {
                assert_eq!(bits(&alone), bits(&avx));
            }
        }
    }

    /// `bodies` in blocks of `N` lanes.
    #[cfg(feature = "columns")]
    fn blocks_of<T: Precision, const N: usize>(bodies: &[Body<T>]) -> Vec<Block<T, N>> {
        let lane = |b: &Body<T>| (b.inertia, b.q, b.l, b.t);
        bodies
            .chunks(N)
            .map(|bodies| {
                let mut block = Block::filled(&lane(&bodies[0]));
                for (i, b) in bodies.iter().enumerate() {
                    block.set(i, &lane(b));
                }
                block
            })
            .collect()
    }

    /// The first `n` bodies of `blocks`.
    #[cfg(feature = "columns")]
    fn bodies_of<T: Precision, const N: usize>(blocks: &[Block<T, N>], n: usize) -> Vec<Body<T>> {
        (0..n)
            .map(|i| {
                let (inertia, q, l, t) = blocks[i / N].get(i % N);
                Body { inertia, q, l, t }
            })
            .collect()
    }

    /// Blocks of four f64 bodies stepped in arrays and (with AVX) in one register: each
    /// body's bits stepped alone, order 2 and 4, with turned frames among the lanes.
    #[cfg(feature = "columns")]
    #[test]
    fn every_f64_block_form_gives_the_bits_of_one_body_at_a_time() {
        let mut alone = crowd::<f64>(8);
        let mut blocks = blocks_of::<f64, 4>(&alone);
        #[cfg(target_arch = "x86_64")]
        let mut avx = blocks.clone();
        for order in [Order::Two, Order::Four] {
            for _ in 0..20 {
                for body in &mut alone {
                    step_one(body, 0.01, order);
                }
                for block in &mut blocks {
                    block.step_lanes::<Lanes<f64, 4>, 4>(0, 0.01, order);
                }
                #[cfg(target_arch = "x86_64")]
                if avx_available() {
                    // SAFETY: the CPU has AVX (checked just above).
                    unsafe { step_blocks_avx64(&mut avx, 0.01, order) };
                }
            }
            assert_eq!(bits(&alone), bits(&bodies_of(&blocks, 8)));
            #[cfg(target_arch = "x86_64")]
            if avx_available() {
                assert_eq!(bits(&alone), bits(&bodies_of(&avx, 8)));
            }
        }
    }

    /// A block of eight f32 bodies stepped as two groups of four (the form without AVX)
    /// and, with AVX, as one group of eight: each body's bits stepped alone, order 2 and
    /// 4, both forms of the turns and the clamps among the lanes.
    #[cfg(feature = "columns")]
    #[test]
    fn every_block_width_gives_the_bits_of_one_body_at_a_time() {
        for (sizes, h) in [
            (&[1.0][..], 1.0 / 60.0),
            (&[1.0, 300.0, 1e5, 1e20][..], 10.0),
        ] {
            let mut alone = crowd_of_size(sizes);
            alone.truncate(16);
            let mut blocks = blocks_of::<f32, 8>(&alone);
            #[cfg(target_arch = "x86_64")]
            let mut eight = blocks.clone();
            for order in [Order::Two, Order::Four] {
                for _ in 0..20 {
                    for body in &mut alone {
                        step_one(body, h, order);
                    }
                    for block in &mut blocks {
                        block.step_lanes::<Lanes<f32, 4>, 4>(0, h, order);
                        block.step_lanes::<Lanes<f32, 4>, 4>(4, h, order);
                    }
                    #[cfg(target_arch = "x86_64")]
                    if avx_available() {
                        // SAFETY: the CPU has AVX (checked just above).
                        unsafe { step_blocks_avx(&mut eight, h, order) };
                    }
                }
                assert_eq!(bits(&alone), bits(&bodies_of(&blocks, 16)));
                #[cfg(target_arch = "x86_64")]
                if avx_available() {
                    assert_eq!(bits(&alone), bits(&bodies_of(&eight, 16)));
                }
            }
        }
    }
}
