//! Sine and cosine from `+ - * /` alone, so that a step rounds the same on every machine.
//!
//! A platform's `sin`/`cos` (libm, the C library, a vector math library) may differ in
//! the last bit between operating systems and versions; these polynomials cannot. The
//! steps only need a rotation by an angle, and a rotation by `a` and by `a - n pi` give
//! the same quaternion up to sign, so the argument is reduced by the nearest multiple of
//! pi (Cody and Waite's two-part constant) into [-pi/2, pi/2], where truncated Taylor
//! series are accurate to well under an ulp (the coefficients are exact rationals:
//! docs/references.md).

use super::real::Real;

/// `(cos r, sin r)` for `r = a - n pi`, the nearest multiple of pi removed: the same
/// rotation (as a quaternion `cos r + sin r u`, up to its sign) as the angle `a`.
///
/// Every input gives a unit pair: an angle too large to reduce (|a| > 2^22 pi in f32),
/// infinite or NaN is clamped to [-pi/2, pi/2] after the reduction, which keeps
/// `cos^2 + sin^2 = 1` but not the angle (a step of that size has no meaningful angle in
/// that precision).
#[inline(always)]
pub(crate) fn cos_sin_mod_pi<R: Real>(a: R) -> (R, R) {
    let half_pi = R::splat(core::f64::consts::FRAC_PI_2);
    // Within [-pi/2, pi/2] the reduction gives n = 0 and r = a exactly, so skipping it
    // (the usual case, and off the step's critical path) changes no bit; a group of lanes
    // skips it only if every lane may.
    let r = if R::any(a.lt(-half_pi)) || R::any(half_pi.lt(a)) {
        let n = (a * R::splat(core::f64::consts::FRAC_1_PI)).round_small();
        (a - n * R::splat(R::PI_HI)) - n * R::splat(R::PI_LO)
    } else {
        a
    };
    // Written so that a NaN (an angle that overflowed) also lands in range.
    let r = R::select(r.lt(half_pi), r, half_pi);
    let r = R::select((-half_pi).lt(r), r, -half_pi);
    let x2 = r * r;
    let x4 = x2 * x2;
    (estrin(x2, x4, R::COS), r * estrin(x2, x4, R::SIN))
}

/// `c[0] + c[1] x + c[2] x^2 + ...` by Estrin's scheme (pairs `c[2i] + c[2i+1] x`, then
/// pairs of pairs with `x^2`, ...): a third of Horner's dependency chain, which is what
/// bounds a step's latency. `x2` is `x * x`; at most 16 coefficients.
#[inline(always)]
fn estrin<R: Real>(x: R, x2: R, c: &[f64]) -> R {
    let mut terms = [R::splat(0.0); 8];
    let mut n = 0;
    for pair in c.chunks(2) {
        terms[n] = match pair {
            [a, b] => R::splat(*a) + R::splat(*b) * x,
            _ => R::splat(pair[0]),
        };
        n += 1;
    }
    let mut power = x2;
    while n > 1 {
        let mut m = 0;
        for i in (0..n).step_by(2) {
            terms[m] = if i + 1 < n {
                terms[i] + terms[i + 1] * power
            } else {
                terms[i]
            };
            m += 1;
        }
        n = m;
        power = power * power;
    }
    terms[0]
}

#[cfg(all(test, feature = "std"))]
mod tests {
    use super::*;

    #[test]
    fn taylor_sin_cos_are_within_two_ulps_of_std_on_the_reduced_range() {
        for i in -1000..=1000 {
            // Up to just inside pi/2, where the series are evaluated unreduced.
            let a = f64::from(i) * (core::f64::consts::FRAC_PI_2 - 1e-4) / 1000.0;
            let (c, s) = cos_sin_mod_pi(a);
            assert!((c - a.cos()).abs() <= 4.5e-16, "cos {a}");
            assert!((s - a.sin()).abs() <= 4.5e-16, "sin {a}");
            let a32 = a as f32;
            let (c, s) = cos_sin_mod_pi(a32);
            assert!((c - a32.cos()).abs() <= 2.4e-7, "cos32 {a}");
            assert!((s - a32.sin()).abs() <= 2.4e-7, "sin32 {a}");
        }
    }

    #[test]
    fn reduction_by_pi_keeps_the_rotation_up_to_sign() {
        for &a in &[3.0_f64, -7.5, 100.25, 12345.678, -98765.4321] {
            let (c, s) = cos_sin_mod_pi(a);
            let sign = if c * a.cos() + s * a.sin() < 0.0 {
                -1.0
            } else {
                1.0
            };
            // The reduction's error grows with n (PI_LO's rounding times n).
            let tol = 1e-15 * (1.0 + a.abs());
            assert!((sign * c - a.cos()).abs() <= tol, "{a}");
            assert!((sign * s - a.sin()).abs() <= tol, "{a}");
        }
    }

    #[test]
    fn huge_angles_stay_finite_and_unit() {
        for &a in &[1e30_f32, -3e38, f32::MAX, f32::INFINITY, f32::NAN] {
            let (c, s) = cos_sin_mod_pi(a);
            assert!(c.is_finite() && s.is_finite());
            assert!((c * c + s * s - 1.0).abs() < 1e-6);
        }
    }
}
