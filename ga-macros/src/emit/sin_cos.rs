//! The trigonometric kernels of the exponential, written out, with no call into the
//! platform's library for the angles a rotation has: `cosh_sinhc_series`, the even series
//! of `cos r` and `sin(r)/r` in `x = -r^2` (no root, no division, no reduction) for
//! `|x| <= 2.5`, which holds every rotor's half-angle up to a half turn; and `sin_cos`, one
//! reduction by pi/2 and two polynomials, for the larger `f64` angles.
//!
//! The C library's `sincos` was most of the time of a G3 exp. Here the reduction is Cody
//! and Waite's (W. J. Cody, W. Waite, *Software Manual for the Elementary Functions*,
//! Prentice-Hall 1980): `x - n pi/2` with pi/2 split into pieces of 33 bits, so that `n`
//! times each of the first two is exact for `|n| < 2^20`; the polynomials are the Taylor
//! series, long enough that the first term left out is below half an ulp on `|r| <= pi/4`.
//! Beyond `2^19` (and for NaN and infinities) the library's own `sin_cos` runs, which
//! reduces any finite angle exactly.
//! `f32` keeps the library's `sincosf` for the larger angles: it measured faster than this
//! kernel evaluated in `f64`.

use proc_macro2::{Literal, TokenStream};
use quote::quote;

use crate::spec::Scalar;

/// pi/2 to 33 bits, then the next 33 bits, then the next 53 (the remainder is below
/// 1.1e-37): `n * PIO2_1` and `n * PIO2_2` are exact for `|n| < 2^20`.
const PIO2_1: f64 = 1.570_796_326_734_125_6;
const PIO2_2: f64 = 6.077_100_506_303_966e-11;
const PIO2_3: f64 = 2.022_266_248_795_950_6e-21;

/// The largest angle reduced here: `|n| <= 2^19 * 2/pi + 1 < 2^20`.
const REDUCED_MAX: f64 = 524_288.0;

/// `value` as a literal a person can read: scientific notation below 1e-3, where the
/// plain form would be a row of zeros.
fn readable(value: f64) -> Literal {
    if value == 0.0 || value.abs() >= 1e-3 {
        Literal::f64_unsuffixed(value)
    } else {
        format!("{value:e}")
            .parse()
            .expect("a float printed by `{:e}` is a float literal")
    }
}

/// The odd Taylor coefficients `(-1)^k / (2k+1)!` from `k = 1`, and the even ones
/// `(-1)^k / (2k)!` from `k = 2`, `terms` of each: with eight and seven the first terms
/// left out, `r^19/19!` and `r^18/18!` at `r = pi/4`, are below 1e-17.
fn taylor(first_power: u32, terms: u32) -> Vec<TokenStream> {
    (0..terms)
        .map(|k| {
            let power = first_power + 2 * k;
            // n! is exact in f64 up to 22!, so each coefficient is correctly rounded.
            let factorial: f64 = (1..=power).map(f64::from).product();
            let size = readable(1.0 / factorial);
            if (first_power / 2 + k) % 2 == 1 {
                quote!(-#size)
            } else {
                quote!(#size)
            }
        })
        .collect()
}

/// Estrin's scheme in `z` over `coefficients`, lowest first: pairs `c0 + z c1`, then pairs
/// of those with `z2 = z^2`, then with `z4`, so that the chain of dependent operations is
/// about log2 of the degree long instead of the degree (Horner's), which is what a
/// dependent chain of exponentials waits for.
pub(super) fn estrin(coefficients: &[TokenStream]) -> TokenStream {
    let powers = [quote!(z), quote!(z2), quote!(z4), quote!(z8)];
    let mut level: Vec<TokenStream> = coefficients.to_vec();
    let mut power = powers.iter();
    while level.len() > 1 {
        let x = power.next().expect("at most 16 coefficients");
        level = level
            .chunks(2)
            .map(|pair| match pair {
                [low, high] => quote!((#low + #x * #high)),
                [low] => low.clone(),
                _ => unreachable!("chunks of two"),
            })
            .collect();
    }
    level.pop().expect("at least one coefficient")
}

/// The limit of `cosh_sinhc_series`: `|<B B>| <= 2.5`, a half-angle of up to 1.58, so a
/// rotation of up to 3.16 radians, just over a half turn: every rotor of a rotation by at
/// most pi takes it. (Ten terms would reach `|<B B>| <= 10` in `f32`, every half-angle up
/// to pi, but measured slower for the G3 `f32` exp in batch form: BENCHMARKS.md, "Choices in
/// the generated code".)
const SERIES_MAX: f64 = 2.5;

/// `1/(2k + parity)!` for `k = 0..terms` (no signs: the series are in `x = -r^2`, which
/// carries them).
fn even_series(parity: u32, terms: u32) -> Vec<TokenStream> {
    (0..terms)
        .map(|k| {
            let factorial: f64 = (1..=2 * k + parity).map(f64::from).product();
            let c = readable(1.0 / factorial);
            quote!(#c)
        })
        .collect()
}

/// `fn cosh_sinhc_series(x)` and `SERIES_MAX`, beside the exponential's scalar functions.
///
/// `cosh(sqrt x) = sum x^k/(2k)!` and `sinh(sqrt x)/sqrt x = sum x^k/(2k+1)!` are entire in
/// `x` and give `cos r` and `sin(r)/r` for `x = -r^2`. On `|x| <= 2.5` the first term left
/// out is below 2.1e-17 with eleven terms each (`f64`), and below 7e-9 with seven (`f32`,
/// summed in `f64`). Near a zero of `cos r` the result is right to an ulp of 1, not of
/// itself: what a rotor's components need, since they are measured against its norm.
pub fn emit_even_series(scalar: Scalar) -> TokenStream {
    let terms = match scalar {
        Scalar::F64 => 11,
        Scalar::F32 => 7,
    };
    let cosh = estrin(&even_series(0, terms));
    let sinhc = estrin(&even_series(1, terms));
    let limit = Literal::f64_unsuffixed(SERIES_MAX);
    let (s, widen, narrow) = match scalar {
        Scalar::F64 => (quote!(f64), quote!(x), quote!([cosh, sinhc])),
        Scalar::F32 => (
            quote!(f32),
            quote!(x as f64),
            quote!([cosh as f32, sinhc as f32]),
        ),
    };
    quote! {
        /// The bound on `|x|` below which `cosh_sinhc_series` is exact to rounding.
        #[allow(dead_code)]
        const SERIES_MAX: #s = #limit;

        /// `[cosh(sqrt x), sinh(sqrt x)/sqrt x]`, that is `[cos r, sin(r)/r]` for
        /// `x = -r^2`, by their series for `|x| <= SERIES_MAX`.
        #[allow(dead_code)]
        #[inline]
        fn cosh_sinhc_series(x: #s) -> [#s; 2] {
            let z: f64 = #widen;
            let z2 = z * z;
            let z4 = z2 * z2;
            let z8 = z4 * z4;
            let cosh = #cosh;
            let sinhc = #sinhc;
            #narrow
        }
    }
}

/// `fn sin_cos(x)` in the `math` module, falling back to `sin_cos_any` (the library's).
pub fn emit_sin_cos(scalar: Scalar) -> TokenStream {
    if scalar == Scalar::F32 {
        // The platform's `sincosf` (glibc's: one reduction, a short polynomial in double)
        // measured faster than this kernel evaluated in f64 (G4 exp 0.65x the time), so
        // f32 keeps it.
        return quote! {
            /// `(sin x, cos x)`: the library's, which is as fast as a written-out kernel
            /// for `f32`.
            #[inline]
            pub(super) fn sin_cos(x: f32) -> (f32, f32) {
                sin_cos_any(x)
            }
        };
    }
    let sin_series = estrin(&taylor(3, 8));
    let cos_series = estrin(&taylor(4, 7));
    let pio2_1 = Literal::f64_unsuffixed(PIO2_1);
    let pio2_2 = readable(PIO2_2);
    let pio2_3 = readable(PIO2_3);
    let reduced_max = Literal::f64_unsuffixed(REDUCED_MAX);
    super::template::fill(
        SIN_COS,
        &[
            ("reduced_max", &reduced_max),
            ("pio2_1", &pio2_1),
            ("pio2_2", &pio2_2),
            ("pio2_3", &pio2_3),
            ("sin_series", &sin_series),
            ("cos_series", &cos_series),
        ],
    )
}

/// `sin_cos` by one reduction and two polynomials (the series and constants filled in).
const SIN_COS: &str = r#"
/// `(sin x, cos x)` by one reduction to `|r| <= pi/4` and two polynomials, for
/// `|x| <= 2^19`; beyond that, and for NaN and infinities, the library's.
#[inline]
pub(super) fn sin_cos(x: f64) -> (f64, f64) {
    if !(x.abs() <= #reduced_max) {
        return sin_cos_any(x);
    }
    // The nearest integer to x 2/pi: adding and removing 1.5 * 2^52 rounds it.
    let n = (x * ::core::f64::consts::FRAC_2_PI + 6755399441055744.0) - 6755399441055744.0;
    let r = ((x - n * #pio2_1) - n * #pio2_2) - n * #pio2_3;
    let z = r * r;
    let z2 = z * z;
    let z4 = z2 * z2;
    let sin = r + r * z * #sin_series;
    // 1 - z/2 rounded, and what that rounding lost added back.
    let half = 0.5 * z;
    let w = 1.0 - half;
    let cos = w + (((1.0 - w) - half) + z2 * #cos_series);
    quadrant(sin, cos, n as i64 as u64)
}

/// `(sin, cos)` of `r + q pi/2` from those of `r`: odd quadrants swap the two, and
/// the signs follow the quadrant, by bit operations rather than branches that
/// random angles would mispredict.
#[inline]
fn quadrant(sin: f64, cos: f64, q: u64) -> (f64, f64) {
    let swap = (q & 1).wrapping_neg();
    let (s, c) = (sin.to_bits(), cos.to_bits());
    let first = (s & !swap) | (c & swap);
    let second = (c & !swap) | (s & swap);
    (
        f64::from_bits(first ^ ((q & 2) << 62)),
        f64::from_bits(second ^ ((q.wrapping_add(1) & 2) << 62)),
    )
}
"#;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn split_pi_over_two_sums_to_pi_over_two() {
        assert_eq!(PIO2_1 + PIO2_2, core::f64::consts::FRAC_PI_2);
        // 33 significant bits each: the low 20 bits of the first two are zero.
        assert_eq!(PIO2_1.to_bits() & 0xF_FFFF, 0);
        assert_eq!(PIO2_2.to_bits() & 0xF_FFFF, 0);
    }

    #[test]
    fn taylor_coefficients_alternate_from_the_right_power() {
        let value = |t: &TokenStream| -> f64 { t.to_string().replace(' ', "").parse().unwrap() };
        let sin = taylor(3, 3);
        assert_eq!(value(&sin[0]), -1.0 / 6.0);
        assert_eq!(value(&sin[1]), 1.0 / 120.0);
        assert_eq!(value(&sin[2]), -1.0 / 5040.0);
        let cos = taylor(4, 2);
        assert_eq!(value(&cos[0]), 1.0 / 24.0);
        assert_eq!(value(&cos[1]), -1.0 / 720.0);
    }
}
