//! Rotor products of two slices with a register per component.
//!
//! A G3 rotor is four components, so one item's product in lanes spends a swizzle on
//! three of its four terms and a broadcast on each, and Intel cores have one port for
//! shuffles. Here four registers of rotors are transposed into four registers of
//! components (the `s`, `e12`, `e13` and `e23` of 8 `f32` items in AVX2, 16 in
//! AVX-512; 4 `f64` items in AVX2, 8 in AVX-512), the product is 16 multiplies and 12
//! additions for all of them, and the result is transposed back: 24 shuffles per 8 (or
//! 16) `f32` items; per 4 `f64` items in AVX2, 12 unpacks and 12 half-register inserts
//! and extracts, and 24 permutes per 8 in AVX-512; where the lane form needs 3 swizzles
//! per item and 4 broadcasts.
//!
//! The arithmetic is the one-item product's, operation for operation and in its order,
//! without fused multiply-adds, and with its negations where they decide the sign of a
//! zero: each result is bit for bit `a[i] * b[i]`, signed zeros included, for every input
//! without NaN (a NaN input gives NaN in the same components, its sign and payload not
//! promised: the compiler may swap a product's operands, which picks the NaN that
//! survives). The `f32` and `f64` products order the terms of `s` and `e23` differently
//! (the `f32` one follows its lane form), so each precision has its own order below;
//! `ga-core/tests/kernels.rs` checks every copy against the one-item product bit for bit,
//! on every rotor pair with components in {+0, -0, 1, -1} among others.

/// `[s, e12, e13, e23]` of `a b`, component registers in, component registers out, with
/// `add`, `sub` and `mul` the lane-wise operations; `s` and `e23` group and negate their
/// terms as the precision's one-item product does.
macro_rules! rotor_product {
    ($a:expr, $b:expr, $add:ident, $sub:ident, $mul:ident, s: $s:tt, e23: $e23:ident) => {{
        let [a_s, a_12, a_13, a_23] = $a;
        let [b_s, b_12, b_13, b_23] = $b;
        [
            rotor_product!(@s $s a_s, a_12, a_13, a_23, b_s, b_12, b_13, b_23, $add, $sub, $mul),
            $add(
                $add($mul(a_s, b_12), $mul(a_12, b_s)),
                $sub($mul(a_23, b_13), $mul(a_13, b_23)),
            ),
            $add(
                $add($mul(a_s, b_13), $mul(a_12, b_23)),
                $sub($mul(a_13, b_s), $mul(a_23, b_12)),
            ),
            rotor_product!(@$e23 a_s, a_12, a_13, a_23, b_s, b_12, b_13, b_23, $add, $sub, $mul),
        ]
    }};
    // (s bs - a12 b12) - (a13 b13 + a23 b23): the f64 product's order.
    (@s subtracted $as:ident, $a12:ident, $a13:ident, $a23:ident,
     $bs:ident, $b12:ident, $b13:ident, $b23:ident, $add:ident, $sub:ident, $mul:ident) => {
        $sub(
            $sub($mul($as, $bs), $mul($a12, $b12)),
            $add($mul($a13, $b13), $mul($a23, $b23)),
        )
    };
    // (s bs - a12 b12) + (a13 (-b13) - a23 b23): the f32 lane form's, which adds products
    // by negated operands. `-(p + q)` and `(-p) + (-q)` differ in the sign of an exact
    // zero (`p = -q`), so the kernel negates `b13` as the lane form does; `x + (-y)` is
    // `x - y` in IEEE 754, sign of zero included, so the rest subtracts.
    (@s (negated $neg:ident) $as:ident, $a12:ident, $a13:ident, $a23:ident,
     $bs:ident, $b12:ident, $b13:ident, $b23:ident, $add:ident, $sub:ident, $mul:ident) => {
        $add(
            $sub($mul($as, $bs), $mul($a12, $b12)),
            $sub($mul($a13, $neg($b13)), $mul($a23, $b23)),
        )
    };
    // (s b23 + a13 b12) + (a23 bs - a12 b13): the f64 product's order.
    (@scalar_first $as:ident, $a12:ident, $a13:ident, $a23:ident,
     $bs:ident, $b12:ident, $b13:ident, $b23:ident, $add:ident, $sub:ident, $mul:ident) => {
        $add(
            $add($mul($as, $b23), $mul($a13, $b12)),
            $sub($mul($a23, $bs), $mul($a12, $b13)),
        )
    };
    // (a23 bs + a13 b12) + (s b23 - a12 b13): the f32 lane form's order.
    (@lane_order $as:ident, $a12:ident, $a13:ident, $a23:ident,
     $bs:ident, $b12:ident, $b13:ident, $b23:ident, $add:ident, $sub:ident, $mul:ident) => {
        $add(
            $add($mul($a23, $bs), $mul($a13, $b12)),
            $sub($mul($as, $b23), $mul($a12, $b13)),
        )
    };
}

/// Four registers of `f32` rotors (one rotor per 128-bit lane) to four registers of
/// components, or back: a 4 x 4 transpose within each 128-bit lane, which is its own
/// inverse. The items come out in a permuted order (0, 2, 4, 6, 1, 3, 5, 7 for 256 bits),
/// the same for every component, which is all a lane-wise product needs. Only the `f32`
/// copies use it: without the `f32` feature (ga-rigid's build) it would be an unused macro.
#[cfg(feature = "f32")]
macro_rules! transpose_in_lanes {
    ($y:expr, $lo:ident, $hi:ident, $shuffle:ident) => {{
        let [y0, y1, y2, y3] = $y;
        let (t0, t1) = ($lo(y0, y1), $hi(y0, y1));
        let (t2, t3) = ($lo(y2, y3), $hi(y2, y3));
        [
            $shuffle::<0b01_00_01_00>(t0, t2),
            $shuffle::<0b11_10_11_10>(t0, t2),
            $shuffle::<0b01_00_01_00>(t1, t3),
            $shuffle::<0b11_10_11_10>(t1, t3),
        ]
    }};
}

#[cfg(feature = "f32")]
pub mod f32 {
    use core::arch::x86_64::{
        __m256, __m512, _mm256_add_ps, _mm256_loadu_ps, _mm256_mul_ps, _mm256_set1_ps,
        _mm256_shuffle_ps, _mm256_storeu_ps, _mm256_sub_ps, _mm256_unpackhi_ps, _mm256_unpacklo_ps,
        _mm256_xor_ps, _mm512_add_ps, _mm512_castps_si512, _mm512_castsi512_ps, _mm512_loadu_ps,
        _mm512_mul_ps, _mm512_set1_epi32, _mm512_shuffle_ps, _mm512_storeu_ps, _mm512_sub_ps,
        _mm512_unpackhi_ps, _mm512_unpacklo_ps, _mm512_xor_si512,
    };

    use crate::f32::g3::Rotor;
    use crate::kernels::InstructionSet;

    /// `-x` lane by lane, by flipping the sign bit as the one-item lane form's `negate`
    /// does: exact for every value, zeros included.
    #[inline]
    #[target_feature(enable = "avx2")]
    fn negate_256(x: __m256) -> __m256 {
        _mm256_xor_ps(x, _mm256_set1_ps(-0.0))
    }

    /// [`negate_256`] for 512 bits, with an integer xor (`vxorps` on 512 bits needs
    /// AVX-512DQ, which the copy does not ask for).
    #[inline]
    #[target_feature(enable = "avx512f")]
    fn negate_512(x: __m512) -> __m512 {
        _mm512_castsi512_ps(_mm512_xor_si512(
            _mm512_castps_si512(x),
            _mm512_set1_epi32(i32::MIN),
        ))
    }

    /// One `f32` copy: `$items` rotors a round, four registers of `$items / 4` rotors each,
    /// with the width's load, store, unpacks, shuffle and arithmetic.
    macro_rules! f32_copy {
        (
            $(#[$doc:meta])*
            $name:ident, $feature:literal, $set:expr, items: $items:literal,
            $load:ident, $store:ident, $lo:ident, $hi:ident, $shuffle:ident,
            $add:ident, $sub:ident, $mul:ident, $neg:ident
        ) => {
            $(#[$doc])*
            #[target_feature(enable = $feature)]
            pub unsafe fn $name(a: &[Rotor], b: &[Rotor], out: &mut [Rotor]) -> InstructionSet {
                const ITEMS: usize = $items;
                let full = a.len() / ITEMS * ITEMS;
                let (pa, pb) = (a.as_ptr().cast::<f32>(), b.as_ptr().cast::<f32>());
                let po = out.as_mut_ptr().cast::<f32>();
                // Register `k` of a round starts at float `4 i + k ITEMS`.
                let starts = [0, ITEMS, 2 * ITEMS, 3 * ITEMS];
                for i in (0..full).step_by(ITEMS) {
                    // SAFETY: `Rotor` is `#[repr(C)]` of four `f32`, so items
                    // `i..i + ITEMS` are the `4 ITEMS` floats from `4 i`, and
                    // `i + ITEMS <= full <= len` in all three slices.
                    let (x, y) = unsafe {
                        (
                            starts.map(|k| $load(pa.add(4 * i + k))),
                            starts.map(|k| $load(pb.add(4 * i + k))),
                        )
                    };
                    let x = transpose_in_lanes!(x, $lo, $hi, $shuffle);
                    let y = transpose_in_lanes!(y, $lo, $hi, $shuffle);
                    let p = rotor_product!(x, y, $add, $sub, $mul, s: (negated $neg), e23: lane_order);
                    let p = transpose_in_lanes!(p, $lo, $hi, $shuffle);
                    for (k, register) in starts.into_iter().zip(p) {
                        // SAFETY: as for the loads.
                        unsafe { $store(po.add(4 * i + k), register) };
                    }
                }
                crate::kernels::f32::mul_items(&a[full..], &b[full..], &mut out[full..]);
                $set
            }
        };
    }

    f32_copy! {
        /// `out[i] = a[i] b[i]`, 8 items a round in 256-bit registers.
        ///
        /// # Safety
        /// The CPU has AVX2, and the three slices have the same length.
        mul_pairs_avx2, "avx2", InstructionSet::Avx2Fma, items: 8,
        _mm256_loadu_ps, _mm256_storeu_ps, _mm256_unpacklo_ps, _mm256_unpackhi_ps,
        _mm256_shuffle_ps, _mm256_add_ps, _mm256_sub_ps, _mm256_mul_ps, negate_256
    }

    f32_copy! {
        /// `out[i] = a[i] b[i]`, 16 items a round in 512-bit registers.
        ///
        /// # Safety
        /// The CPU has AVX-512F, and the three slices have the same length.
        mul_pairs_avx512, "avx512f", InstructionSet::Avx512f, items: 16,
        _mm512_loadu_ps, _mm512_storeu_ps, _mm512_unpacklo_ps, _mm512_unpackhi_ps,
        _mm512_shuffle_ps, _mm512_add_ps, _mm512_sub_ps, _mm512_mul_ps, negate_512
    }
}

#[cfg(feature = "f64")]
pub mod f64 {
    use core::arch::x86_64::{
        __m512d, _mm256_add_pd, _mm256_loadu2_m128d, _mm256_mul_pd, _mm256_storeu2_m128d,
        _mm256_sub_pd, _mm256_unpackhi_pd, _mm256_unpacklo_pd, _mm512_add_pd, _mm512_loadu_pd,
        _mm512_mul_pd, _mm512_permutex2var_pd, _mm512_set_epi64, _mm512_storeu_pd, _mm512_sub_pd,
    };

    use crate::f64::g3::Rotor;
    use crate::kernels::InstructionSet;

    /// `out[i] = a[i] b[i]`, 4 items a round in 256-bit registers. Each register is
    /// loaded from two half-rotors (`[s, e12]` or `[e13, e23]` of items `k` and `k + 2`),
    /// so that one `unpack` per register finishes the transpose without a lane-crossing
    /// shuffle; the stores split the same way.
    ///
    /// # Safety
    /// The CPU has AVX2, and the three slices have the same length.
    #[target_feature(enable = "avx2")]
    pub unsafe fn mul_pairs_avx2(a: &[Rotor], b: &[Rotor], out: &mut [Rotor]) -> InstructionSet {
        const ITEMS: usize = 4;
        let full = a.len() / ITEMS * ITEMS;
        let (pa, pb) = (a.as_ptr().cast::<f64>(), b.as_ptr().cast::<f64>());
        let po = out.as_mut_ptr().cast::<f64>();
        // The half-rotors of a round start at doubles 0 (item 0's [s, e12]), 2 (its
        // [e13, e23]), 4 (item 1's [s, e12]), ...; register `r` holds the halves at
        // `LOW[r]` and `LOW[r] + 8`, the same half of the item two further on.
        const LOW: [usize; 4] = [0, 4, 2, 6];
        for i in (0..full).step_by(ITEMS) {
            // SAFETY: `Rotor` is `#[repr(C)]` of four `f64`, so items `i..i + 4` are the 16
            // doubles from `4 i`; every offset read is below `4 i + 16`, and
            // `i + 4 <= full <= len` in all three slices.
            let (x, y) = unsafe {
                (
                    LOW.map(|k| _mm256_loadu2_m128d(pa.add(4 * i + k + 8), pa.add(4 * i + k))),
                    LOW.map(|k| _mm256_loadu2_m128d(pb.add(4 * i + k + 8), pb.add(4 * i + k))),
                )
            };
            let x = [
                _mm256_unpacklo_pd(x[0], x[1]),
                _mm256_unpackhi_pd(x[0], x[1]),
                _mm256_unpacklo_pd(x[2], x[3]),
                _mm256_unpackhi_pd(x[2], x[3]),
            ];
            let y = [
                _mm256_unpacklo_pd(y[0], y[1]),
                _mm256_unpackhi_pd(y[0], y[1]),
                _mm256_unpacklo_pd(y[2], y[3]),
                _mm256_unpackhi_pd(y[2], y[3]),
            ];
            let [s, e12, e13, e23] = rotor_product!(x, y, _mm256_add_pd, _mm256_sub_pd, _mm256_mul_pd, s: subtracted, e23: scalar_first);
            let halves = [
                _mm256_unpacklo_pd(s, e12),
                _mm256_unpackhi_pd(s, e12),
                _mm256_unpacklo_pd(e13, e23),
                _mm256_unpackhi_pd(e13, e23),
            ];
            for (k, half) in LOW.into_iter().zip(halves) {
                // SAFETY: as for the loads.
                unsafe { _mm256_storeu2_m128d(po.add(4 * i + k + 8), po.add(4 * i + k), half) };
            }
        }
        crate::kernels::f64::mul_items(&a[full..], &b[full..], &mut out[full..]);
        InstructionSet::Avx2Fma
    }

    /// `out[i] = a[i] b[i]`, 8 items a round in 512-bit registers, each register two
    /// rotors. The transposes are two rounds of two-source permutes (`vpermt2pd`): the
    /// first gathers two components of four items from a pair of registers, the second
    /// joins the halves of eight items, and the way back is the same two rounds in
    /// reverse: 24 permutes per 8 items, where the AVX2 copy spends 12 unpacks and 12
    /// half-register inserts and extracts per 4.
    ///
    /// # Safety
    /// The CPU has AVX-512F, and the three slices have the same length.
    #[target_feature(enable = "avx512f")]
    pub unsafe fn mul_pairs_avx512(a: &[Rotor], b: &[Rotor], out: &mut [Rotor]) -> InstructionSet {
        const ITEMS: usize = 8;
        let full = a.len() / ITEMS * ITEMS;
        let (pa, pb) = (a.as_ptr().cast::<f64>(), b.as_ptr().cast::<f64>());
        let po = out.as_mut_ptr().cast::<f64>();
        // Element `e` of a pair of registers (`e` in 0..16) is component `e % 4` of the
        // pair's item `e / 4`. The first round takes components {0, 1} or {2, 3} of the
        // pair's four items, item-major within each component.
        let two_components = [
            _mm512_set_epi64(13, 9, 5, 1, 12, 8, 4, 0),
            _mm512_set_epi64(15, 11, 7, 3, 14, 10, 6, 2),
        ];
        // The second round joins the same component of items 0..4 and 4..8: the low or
        // the high four elements of each register.
        let one_component = [
            _mm512_set_epi64(11, 10, 9, 8, 3, 2, 1, 0),
            _mm512_set_epi64(15, 14, 13, 12, 7, 6, 5, 4),
        ];
        let to_components = |z: [__m512d; 4]| {
            let [low, high] = two_components;
            let (first01, first23) = (
                _mm512_permutex2var_pd(z[0], low, z[1]),
                _mm512_permutex2var_pd(z[0], high, z[1]),
            );
            let (last01, last23) = (
                _mm512_permutex2var_pd(z[2], low, z[3]),
                _mm512_permutex2var_pd(z[2], high, z[3]),
            );
            let [low, high] = one_component;
            [
                _mm512_permutex2var_pd(first01, low, last01),
                _mm512_permutex2var_pd(first01, high, last01),
                _mm512_permutex2var_pd(first23, low, last23),
                _mm512_permutex2var_pd(first23, high, last23),
            ]
        };
        for i in (0..full).step_by(ITEMS) {
            // SAFETY: `Rotor` is `#[repr(C)]` of four `f64`, so items `i..i + 8` are the
            // 32 doubles from `4 i`, four registers of eight; `i + 8 <= full <= len` in
            // all three slices.
            let (x, y) = unsafe {
                (
                    [0, 8, 16, 24].map(|k| _mm512_loadu_pd(pa.add(4 * i + k))),
                    [0, 8, 16, 24].map(|k| _mm512_loadu_pd(pb.add(4 * i + k))),
                )
            };
            let (x, y) = (to_components(x), to_components(y));
            let [s, e12, e13, e23] = rotor_product!(x, y, _mm512_add_pd, _mm512_sub_pd, _mm512_mul_pd, s: subtracted, e23: scalar_first);
            // Back: the same two rounds in the opposite order. Each round is a transpose
            // (of 4 x 4 elements across a pair of registers, or of their halves), so it
            // undoes itself.
            let [low, high] = one_component;
            let (first01, last01) = (
                _mm512_permutex2var_pd(s, low, e12),
                _mm512_permutex2var_pd(s, high, e12),
            );
            let (first23, last23) = (
                _mm512_permutex2var_pd(e13, low, e23),
                _mm512_permutex2var_pd(e13, high, e23),
            );
            let [low, high] = two_components;
            let rotors = [
                _mm512_permutex2var_pd(first01, low, first23),
                _mm512_permutex2var_pd(first01, high, first23),
                _mm512_permutex2var_pd(last01, low, last23),
                _mm512_permutex2var_pd(last01, high, last23),
            ];
            for (k, register) in [0, 8, 16, 24].into_iter().zip(rotors) {
                // SAFETY: as for the loads.
                unsafe { _mm512_storeu_pd(po.add(4 * i + k), register) };
            }
        }
        crate::kernels::f64::mul_items(&a[full..], &b[full..], &mut out[full..]);
        InstructionSet::Avx512f
    }
}
