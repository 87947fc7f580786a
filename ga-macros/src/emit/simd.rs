//! Four-lane SIMD bodies for the products the cost model picks (see `plan/lanes.rs`), and
//! the one module of intrinsics they go through. The scalar body stays beside each SIMD
//! body for every other target, and is the reference the SIMD body is tested against.

use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote};

use super::expr::{field_ident, mirrored_sum, signed_sum, type_tokens};
use crate::algebra::blade_name;
use crate::plan::lanes::LANES;
use crate::plan::{LaneProduct, Output, PairColumns, Plan, Side, TypeId};

/// Whether any product or sandwich of the module has a SIMD body, so that the helpers are
/// emitted.
pub fn module_uses_lanes(plan: &Plan) -> bool {
    if !plan.emits_simd() {
        return false;
    }
    let products = plan.products.iter().any(|&kind| {
        plan.operand_pairs()
            .into_iter()
            .any(|(a, b)| plan.lane_form(kind, a, b).is_some())
    });
    let sandwiches = plan.has(crate::spec::Op::Sandwich)
        && plan.versors().into_iter().any(|v| {
            plan.emitted.iter().any(|&x| {
                [false, true].into_iter().any(|unit| {
                    matches!(
                        plan.sandwich_form(v, x, unit),
                        Some(crate::plan::SandwichForm::Commutator { lanes: Some(_), .. })
                    )
                })
            })
        });
    products || sandwiches
}

/// A body with a SIMD arm for x86-64 and the scalar arm for every other target.
pub fn target_arms(simd: TokenStream, scalar: TokenStream) -> TokenStream {
    quote! {
        #[cfg(target_arch = "x86_64")]
        {
            #simd
        }
        #[cfg(not(target_arch = "x86_64"))]
        {
            #scalar
        }
    }
}

/// The `simd` module: an SSE register of four `f32` behind arithmetic operators, a
/// broadcast, a swizzle, a sign flip and a lane mask. Every `unsafe` block of the
/// generated code is here.
pub fn emit_lane_helpers() -> TokenStream {
    super::template::fill(LANE_HELPERS, &[])
}

/// The `simd` module (no placeholders).
const LANE_HELPERS: &str = r#"
/// Four `f32` lanes in one SSE register: the form that products of types with at
/// most four components take on x86-64 (see `plan/lanes.rs` in ga-macros).
///
/// Every intrinsic used here is SSE or SSE2, which every x86-64 CPU has (they are
/// part of the architecture's baseline, enabled for every x86-64 target), so each
/// `unsafe` block below only asserts that the instruction exists.
#[cfg(target_arch = "x86_64")]
mod simd {
    use ::core::arch::x86_64::{
        __m128, _mm_add_ps, _mm_and_ps, _mm_castsi128_ps, _mm_mul_ps, _mm_set1_ps,
        _mm_set_epi32, _mm_set_ps, _mm_shuffle_ps, _mm_sub_ps, _mm_xor_ps,
    };

    /// Four `f32` lanes.
    #[derive(Clone, Copy)]
    pub(super) struct F32x4(__m128);

    /// The immediate of `_mm_shuffle_ps` that puts lane `order[i]` in lane `i`.
    pub(super) const fn order(l0: i32, l1: i32, l2: i32, l3: i32) -> i32 {
        l0 | (l1 << 2) | (l2 << 4) | (l3 << 6)
    }

    impl F32x4 {
        /// The lanes of an array, lane 0 first.
        #[inline(always)]
        pub(super) fn new(lanes: [f32; 4]) -> Self {
            // SAFETY: `[f32; 4]` and `__m128` are both 16 bytes, and every bit
            // pattern is a valid value of either.
            F32x4(unsafe { ::core::mem::transmute::<[f32; 4], __m128>(lanes) })
        }

        /// The lanes as an array, lane 0 first.
        #[inline(always)]
        pub(super) fn to_array(self) -> [f32; 4] {
            // SAFETY: as in `new`.
            unsafe { ::core::mem::transmute::<__m128, [f32; 4]>(self.0) }
        }

        /// `x` in every lane.
        #[inline(always)]
        pub(super) fn splat(x: f32) -> Self {
            // SAFETY: SSE is in the x86-64 baseline.
            F32x4(unsafe { _mm_set1_ps(x) })
        }

        /// Lane `i` of the result is lane `order[i]` of `self`; `ORDER` is
        /// [`order`]'s immediate.
        #[inline(always)]
        pub(super) fn swizzle<const ORDER: i32>(self) -> Self {
            // SAFETY: SSE is in the x86-64 baseline.
            F32x4(unsafe { _mm_shuffle_ps::<ORDER>(self.0, self.0) })
        }

        /// Flips the sign of the lanes marked `true` (one xor with a constant).
        #[inline(always)]
        pub(super) fn negate(self, lanes: [bool; 4]) -> Self {
            let sign = |flip: bool| if flip { -0.0 } else { 0.0 };
            // SAFETY: SSE is in the x86-64 baseline.
            F32x4(unsafe {
                _mm_xor_ps(
                    self.0,
                    _mm_set_ps(sign(lanes[3]), sign(lanes[2]), sign(lanes[1]), sign(lanes[0])),
                )
            })
        }

        /// Clears the lanes marked `false` (one and with a constant).
        #[inline(always)]
        pub(super) fn keep(self, lanes: [bool; 4]) -> Self {
            let bits = |keep: bool| if keep { -1 } else { 0 };
            // SAFETY: SSE and SSE2 are in the x86-64 baseline.
            F32x4(unsafe {
                _mm_and_ps(
                    self.0,
                    _mm_castsi128_ps(_mm_set_epi32(
                        bits(lanes[3]),
                        bits(lanes[2]),
                        bits(lanes[1]),
                        bits(lanes[0]),
                    )),
                )
            })
        }
    }

    impl ::core::ops::Add for F32x4 {
        type Output = F32x4;
        #[inline(always)]
        fn add(self, rhs: F32x4) -> F32x4 {
            // SAFETY: SSE is in the x86-64 baseline.
            F32x4(unsafe { _mm_add_ps(self.0, rhs.0) })
        }
    }

    impl ::core::ops::Sub for F32x4 {
        type Output = F32x4;
        #[inline(always)]
        fn sub(self, rhs: F32x4) -> F32x4 {
            // SAFETY: SSE is in the x86-64 baseline.
            F32x4(unsafe { _mm_sub_ps(self.0, rhs.0) })
        }
    }

    impl ::core::ops::Mul for F32x4 {
        type Output = F32x4;
        #[inline(always)]
        fn mul(self, rhs: F32x4) -> F32x4 {
            // SAFETY: SSE is in the x86-64 baseline.
            F32x4(unsafe { _mm_mul_ps(self.0, rhs.0) })
        }
    }
}
"#;

/// The body of a product in lane form: pack the gathered operand, one column per
/// broadcast component, a balanced sum of the columns, unpack into the output type.
pub fn lane_body(
    plan: &Plan,
    form: &LaneProduct,
    lhs: (&TokenStream, TypeId),
    rhs: (&TokenStream, TypeId),
    output: Output,
) -> TokenStream {
    let Output::Type(output) = output else {
        unreachable!("a lane form has a non-zero output")
    };
    let (gathered, broadcast) = match form.broadcast {
        Side::Rhs => (lhs, rhs),
        Side::Lhs => (rhs, lhs),
    };
    let gathered_blades = &plan.types.get(gathered.1).blades;
    let broadcast_blades = &plan.types.get(broadcast.1).blades;
    let g = gathered.0;
    let packed = (0..LANES).map(|lane| match gathered_blades.get(lane) {
        Some(&blade) => {
            let field = field_ident(blade);
            quote!(#g.#field)
        }
        None => quote!(0.0),
    });
    let mut lets = quote!(let g = simd::F32x4::new([#(#packed),*]););
    let mut names = Vec::new();
    for column in &form.columns {
        let blade = broadcast_blades[column.broadcast];
        let name = format_ident!("by_{}", blade_name(blade));
        let mut factor = quote!(g);
        if let Some(order) = column.swizzle(form.gathered_len) {
            let [l0, l1, l2, l3] = order.map(|l| Literal::i32_unsuffixed(l as i32));
            factor = quote!(#factor.swizzle::<{ simd::order(#l0, #l1, #l2, #l3) }>());
        }
        if let Some(keep) = column.mask(form.gathered_len, form.outputs) {
            factor = quote!(#factor.keep([#(#keep),*]));
        }
        let b = broadcast.0;
        let field = field_ident(blade);
        // The signs go on the broadcast, so that a chain through the gathered operand
        // (`acc = acc * r`) has no sign flip on its path.
        let mut splat = quote!(simd::F32x4::splat(#b.#field));
        if let Some(flips) = column.flips(form.outputs) {
            splat = quote!(#splat.negate([#(#flips),*]));
        }
        lets.extend(quote!(let #name = #factor * #splat;));
        names.push((!column.all_negative(form.outputs), quote!(#name)));
    }
    let leaves: Vec<_> = form
        .sum_order()
        .into_iter()
        .map(|k| Some(names[k].clone()))
        .collect();
    let sum = mirrored_sum(&leaves).expect("a lane form has columns");
    let out_blades = &plan.types.get(output).blades;
    let fields: Vec<_> = out_blades.iter().map(|&b| field_ident(b)).collect();
    let rest = (fields.len() < LANES).then(|| quote!(..));
    let name = type_tokens(plan, output);
    quote! {
        #lets
        let [#(#fields,)* #rest] = (#sum).to_array();
        #name { #(#fields),* }
    }
}

/// The sandwich of an even versor `v = s + B` (four components) on an `x` of fewer than
/// four components in lanes: `c = C(x)`, then `(<v ~v> x + 2s c) + 2C(c)`, the factor 2
/// folded into the versor's lanes, or `((x + 2s c) + C(c)) + C(c)` for a unit versor
/// (whose partial sums stay within `sqrt 2 |x|`). The versor's swizzles are shared by
/// both commutators.
pub fn commutator_sandwich_lanes(
    plan: &Plan,
    v: TypeId,
    x: TypeId,
    lanes: &PairColumns,
    unit: bool,
) -> TokenStream {
    let versor = &plan.types.get(v).blades;
    let operand = &plan.types.get(x).blades;
    let pack = |expr: TokenStream, blades: &[u32]| {
        let lanes = (0..LANES).map(|lane| match blades.get(lane) {
            Some(&blade) => {
                let field = field_ident(blade);
                quote!(#expr.#field)
            }
            None => quote!(0.0),
        });
        quote!(simd::F32x4::new([#(#lanes),*]))
    };
    let order_tokens = |order: [usize; LANES]| {
        let [l0, l1, l2, l3] = order.map(|l| Literal::i32_unsuffixed(l as i32));
        quote!(swizzle::<{ simd::order(#l0, #l1, #l2, #l3) }>())
    };
    let packed_v = pack(quote!(self), versor);
    let packed_x = pack(quote!(x), operand);
    let mut lets = quote! {
        let v = #packed_v;
        let xs = #packed_x;
    };
    // Each column's versor lanes carry the column's signs, and the exact form's second
    // commutator's carry the factor 2 of `2 C(c)` too: both are fixed before `x` is read,
    // so the path through `x` is swizzles, multiplies and additions only.
    let mut names = Vec::new();
    for (k, column) in lanes.columns.iter().enumerate() {
        let (a, b) = (format_ident!("a{}", k + 1), format_ident!("b{}", k + 1));
        let mut value = quote!(v);
        if column.a_order != [0, 1, 2, 3] {
            let swizzle = order_tokens(column.a_order);
            value = quote!(#value.#swizzle);
        }
        let signs: [bool; LANES] = std::array::from_fn(|l| column.used[l] && column.negate[l]);
        if signs.iter().any(|&n| n) {
            value = quote!(#value.negate([#(#signs),*]));
        }
        lets.extend(quote!(let #a = #value;));
        if !unit {
            lets.extend(quote!(let #b = #a * simd::F32x4::splat(2.0);));
        }
        names.push((a, b));
    }
    let apply = |second: bool, input: TokenStream| {
        let summands: Vec<(i32, TokenStream)> = lanes
            .columns
            .iter()
            .zip(&names)
            .map(|(column, (a, b))| {
                let factor = if second { b } else { a };
                let operand = if column.b_order == [0, 1, 2, 3] {
                    input.clone()
                } else {
                    let swizzle = order_tokens(column.b_order);
                    quote!(#input.#swizzle)
                };
                (1, quote!(#factor * #operand))
            })
            .collect();
        signed_sum(&summands)
    };
    let c = apply(false, quote!(xs));
    let cc = apply(!unit, quote!(c));
    lets.extend(quote! {
        let c = #c;
        let s = v.swizzle::<{ simd::order(0, 0, 0, 0) }>();
        let two_s = s + s;
    });
    let y = if unit {
        // `C(c)` added twice, as in the scalar form: `2 C(c)` could overflow near `MAX`.
        lets.extend(quote!(let cc = #cc;));
        quote!(((xs + two_s * c) + cc) + cc)
    } else {
        // <v ~v>: each component squared with the sign of its blade times its reverse.
        let signs: Vec<i32> = versor
            .iter()
            .map(|&b| {
                i32::from(plan.metric.geometric(b, b).0)
                    * i32::from(crate::algebra::Involution::Reverse.sign(b))
            })
            .collect();
        let mut squares = quote!(v * v);
        if signs.contains(&0) {
            let keep = signs.iter().map(|&s| s != 0);
            squares = quote!((#squares).keep([#(#keep),*]));
        }
        if signs.iter().any(|&s| s < 0) {
            let flips = signs.iter().map(|&s| s < 0);
            squares = quote!((#squares).negate([#(#flips),*]));
        }
        lets.extend(quote! {
            let squares = #squares;
            let pairs = squares + squares.swizzle::<{ simd::order(1, 0, 3, 2) }>();
            let n = pairs + pairs.swizzle::<{ simd::order(2, 3, 0, 1) }>();
        });
        quote!((xs * n + two_s * c) + (#cc))
    };
    let fields: Vec<_> = operand.iter().map(|&b| field_ident(b)).collect();
    let name = type_tokens(plan, x);
    quote! {
        #lets
        let [#(#fields,)* ..] = (#y).to_array();
        #name { #(#fields),* }
    }
}
