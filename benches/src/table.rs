//! A table-driven geometric algebra: what a generic multivector library does.
//!
//! Multivectors are dense arrays `[S; N]` with `N = 2^n`, indexed by blade bitmask
//! (bit `i` set when the blade contains `e_{i+1}`, so G3 is ordered
//! `1, e1, e2, e12, e3, e13, e23, e123`). The geometric product loops over all `N * N`
//! blade pairs and looks up the sign and the result blade in tables built once at run
//! time by [`Algebra::new`]. Nothing is specialised for a grade or a type: a rotor is a
//! multivector whose odd coefficients are zero, and the product still visits them. This
//! is the baseline the generated code is measured against.

use std::fmt::Debug;
use std::ops::{Add, AddAssign, Div, Mul, Neg, Sub};

/// The floating-point operations the table-driven algebra needs (f32 and f64).
pub trait Scalar:
    Copy
    + Default
    + PartialOrd
    + Debug
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + AddAssign
{
    /// Zero.
    const ZERO: Self;
    /// One.
    const ONE: Self;
    /// The machine epsilon.
    const EPSILON: Self;
    /// Terms kept in the exponential series after scaling the argument to 1-norm <= 1/2.
    const EXP_SERIES_TERMS: usize;
    /// Converts from f64 (rounding for f32).
    fn from_f64(x: f64) -> Self;
    /// Converts to f64.
    fn to_f64(self) -> f64;
    /// -1, 0 or +1 as a scalar.
    fn from_sign(sign: i8) -> Self;
    /// The absolute value.
    fn abs(self) -> Self;
    /// The square root.
    fn sqrt(self) -> Self;
    /// The sine.
    fn sin(self) -> Self;
    /// The cosine.
    fn cos(self) -> Self;
    /// The hyperbolic sine.
    fn sinh(self) -> Self;
    /// The hyperbolic cosine.
    fn cosh(self) -> Self;
    /// The four-quadrant arctangent of `self / x`.
    fn atan2(self, x: Self) -> Self;
}

macro_rules! impl_scalar {
    ($t:ty, $terms:expr) => {
        impl Scalar for $t {
            const ZERO: Self = 0.0;
            const ONE: Self = 1.0;
            const EPSILON: Self = <$t>::EPSILON;
            const EXP_SERIES_TERMS: usize = $terms;
            #[inline]
            fn from_f64(x: f64) -> Self {
                x as $t
            }
            #[inline]
            fn to_f64(self) -> f64 {
                self as f64
            }
            #[inline]
            fn from_sign(sign: i8) -> Self {
                <$t>::from(sign)
            }
            #[inline]
            fn abs(self) -> Self {
                <$t>::abs(self)
            }
            #[inline]
            fn sqrt(self) -> Self {
                <$t>::sqrt(self)
            }
            #[inline]
            fn sin(self) -> Self {
                <$t>::sin(self)
            }
            #[inline]
            fn cos(self) -> Self {
                <$t>::cos(self)
            }
            #[inline]
            fn sinh(self) -> Self {
                <$t>::sinh(self)
            }
            #[inline]
            fn cosh(self) -> Self {
                <$t>::cosh(self)
            }
            #[inline]
            fn atan2(self, x: Self) -> Self {
                <$t>::atan2(self, x)
            }
        }
    };
}

// Truncation error after scaling to |x|_1 <= 1/2 is below 0.5^(d+1)/(d+1)!:
// 5e-9 for d = 8 (f32), 7e-16 for d = 13 (f64).
impl_scalar!(f32, 8);
impl_scalar!(f64, 13);

/// The sign and the result blade of the product of two basis blades given as bitmasks:
/// the parity of the swaps that sort the generators, times the squares of the shared ones.
#[must_use]
pub fn blade_product(metric: &[i8], a: usize, b: usize) -> (i8, usize) {
    let mut swaps = 0;
    let mut rest = a >> 1;
    while rest != 0 {
        swaps += (rest & b).count_ones();
        rest >>= 1;
    }
    let mut sign: i8 = if swaps % 2 == 0 { 1 } else { -1 };
    for (i, square) in metric.iter().enumerate() {
        if (a & b) >> i & 1 == 1 {
            sign *= square;
        }
    }
    (sign, a ^ b)
}

/// The generator indices (1-based) of a blade bitmask, ascending: `0b101` is `[1, 3]`.
#[must_use]
pub fn blade_indices(mask: usize) -> Vec<usize> {
    (0..usize::BITS as usize)
        .filter(|i| mask >> i & 1 == 1)
        .map(|i| i + 1)
        .collect()
}

/// A geometric algebra of dimension `n` with `N = 2^n` blades and its product tables.
#[derive(Clone, Debug)]
pub struct Algebra<const N: usize> {
    metric: Vec<i8>,
    sign: [[i8; N]; N],
    index: [[u8; N]; N],
    reverse_sign: [i8; N],
    grade: [u8; N],
    canonical: [usize; N],
}

/// Euclidean 3D space: 8 blades.
pub type G3 = Algebra<8>;
/// Euclidean 4D space: 16 blades.
pub type G4 = Algebra<16>;

impl<const N: usize> Algebra<N> {
    /// Builds the tables for the given generator squares (+1, -1 or 0).
    ///
    /// Panics unless `2^metric.len() == N` and `N <= 256`.
    #[must_use]
    pub fn new(metric: &[i8]) -> Self {
        assert_eq!(1usize << metric.len(), N, "N must be 2^metric.len()");
        assert!(N <= 256, "blade indices are stored as u8");
        let mut sign = [[0i8; N]; N];
        let mut index = [[0u8; N]; N];
        for a in 0..N {
            for b in 0..N {
                let (s, c) = blade_product(metric, a, b);
                sign[a][b] = s;
                index[a][b] = c as u8;
            }
        }
        let grade = std::array::from_fn(|a| a.count_ones() as u8);
        // Reversing a grade-k blade takes k(k-1)/2 swaps: grades 2 and 3 (mod 4) flip.
        let reverse_sign = std::array::from_fn(|a| {
            let k = a.count_ones();
            if (k * k.saturating_sub(1) / 2) % 2 == 0 {
                1
            } else {
                -1
            }
        });
        let mut canonical: [usize; N] = std::array::from_fn(|a| a);
        canonical.sort_by_key(|&a| (a.count_ones(), blade_indices(a)));
        Self {
            metric: metric.to_vec(),
            sign,
            index,
            reverse_sign,
            grade,
            canonical,
        }
    }

    /// The algebra with every generator squaring to +1.
    #[must_use]
    pub fn euclidean() -> Self {
        Self::new(&vec![1; N.trailing_zeros() as usize])
    }

    /// The number of generators `n`.
    #[must_use]
    pub fn dimension(&self) -> usize {
        self.metric.len()
    }

    /// The sign and result blade of `e_a e_b`, read from the tables.
    #[must_use]
    pub fn blade_product(&self, a: usize, b: usize) -> (i8, usize) {
        (self.sign[a][b], usize::from(self.index[a][b]))
    }

    /// The blade bitmasks in canonical order: grade first, then lexicographic on indices.
    #[must_use]
    pub fn canonical_blades(&self) -> [usize; N] {
        self.canonical
    }

    /// The blade bitmasks of the given grades, in canonical order.
    #[must_use]
    pub fn blades_of_grades(&self, grades: &[u32]) -> Vec<usize> {
        self.canonical
            .iter()
            .copied()
            .filter(|a| grades.contains(&a.count_ones()))
            .collect()
    }

    /// The multivector with `values[i]` on blade `blades[i]` and zero elsewhere.
    #[must_use]
    pub fn embed<S: Scalar>(&self, blades: &[usize], values: &[S]) -> [S; N] {
        assert_eq!(blades.len(), values.len());
        let mut out = [S::ZERO; N];
        for (&blade, &value) in blades.iter().zip(values) {
            out[blade] = value;
        }
        out
    }

    /// The coefficients of `mv` on `blades`, in that order.
    #[must_use]
    pub fn extract<S: Scalar>(&self, blades: &[usize], mv: &[S; N]) -> Vec<S> {
        blades.iter().map(|&blade| mv[blade]).collect()
    }

    /// The multivector whose coefficients are given in canonical order.
    #[must_use]
    pub fn from_canonical<S: Scalar>(&self, values: &[S; N]) -> [S; N] {
        self.embed(&self.canonical, values)
    }

    /// The geometric product: a loop over all blade pairs with table lookups.
    #[inline]
    #[must_use]
    pub fn geometric<S: Scalar>(&self, a: &[S; N], b: &[S; N]) -> [S; N] {
        let mut out = [S::ZERO; N];
        for ((&ai, signs), targets) in a.iter().zip(&self.sign).zip(&self.index) {
            for ((&bj, &sign), &target) in b.iter().zip(signs).zip(targets) {
                // The mask keeps the store in bounds without a check: N is a power of two.
                out[usize::from(target) & (N - 1)] += S::from_sign(sign) * ai * bj;
            }
        }
        out
    }

    /// The reverse: grades 2 and 3 (mod 4) change sign.
    #[inline]
    #[must_use]
    pub fn reverse<S: Scalar>(&self, a: &[S; N]) -> [S; N] {
        std::array::from_fn(|i| S::from_sign(self.reverse_sign[i]) * a[i])
    }

    /// The grade-`k` part.
    #[inline]
    #[must_use]
    pub fn grade_part<S: Scalar>(&self, a: &[S; N], k: u32) -> [S; N] {
        std::array::from_fn(|i| {
            if u32::from(self.grade[i]) == k {
                a[i]
            } else {
                S::ZERO
            }
        })
    }

    /// `r x ~r`: two geometric products and a reverse. `r` must be a unit versor.
    #[inline]
    #[must_use]
    pub fn sandwich<S: Scalar>(&self, r: &[S; N], x: &[S; N]) -> [S; N] {
        self.geometric(&self.geometric(r, x), &self.reverse(r))
    }

    /// The exponential of a bivector: the closed form when `b * b` is a scalar (every
    /// bivector of G3, simple bivectors of G4), the scaled series otherwise.
    #[inline]
    #[must_use]
    pub fn exp<S: Scalar>(&self, b: &[S; N]) -> [S; N] {
        let square = self.geometric(b, b);
        let off_scalar: S = square[1..].iter().fold(S::ZERO, |acc, &c| acc + c.abs());
        let size = norm_squared(b);
        if off_scalar > S::from_f64(64.0) * S::EPSILON * size {
            return self.exp_series(b);
        }
        let a = square[0];
        let (even, odd_factor) = if a < S::ZERO {
            let beta = (-a).sqrt();
            (beta.cos(), sin_over(beta, beta.sin()))
        } else if a > S::ZERO {
            let beta = a.sqrt();
            (beta.cosh(), sin_over(beta, beta.sinh()))
        } else {
            (S::ONE, S::ONE)
        };
        let mut out = scale(b, odd_factor);
        out[0] += even;
        out
    }

    /// The exponential by scaling and squaring a truncated Taylor series: valid for any
    /// multivector. The 1-norm of the coefficients is submultiplicative under the
    /// product (each blade product is a signed blade), which bounds the truncation error.
    #[must_use]
    pub fn exp_series<S: Scalar>(&self, b: &[S; N]) -> [S; N] {
        let one_norm = b.iter().fold(S::ZERO, |acc, &c| acc + c.abs());
        let half = S::from_f64(0.5);
        let mut squarings = 0;
        let mut factor = S::ONE;
        while one_norm * factor > half {
            factor = factor * half;
            squarings += 1;
        }
        let x = scale(b, factor);
        // Horner: 1 + x (1 + x/2 (1 + x/3 (...))).
        let mut sum = [S::ZERO; N];
        sum[0] = S::ONE;
        for j in (1..=S::EXP_SERIES_TERMS).rev() {
            let mut next = scale(&self.geometric(&x, &sum), S::ONE / S::from_f64(j as f64));
            next[0] += S::ONE;
            sum = next;
        }
        for _ in 0..squarings {
            sum = self.geometric(&sum, &sum);
        }
        sum
    }

    /// The logarithm of a rotor with no grade-4 part (any G3 rotor): `theta B / |B|` with
    /// `theta = atan2(|B|, s)`, on the principal range. Other grades are ignored.
    #[inline]
    #[must_use]
    pub fn log<S: Scalar>(&self, r: &[S; N]) -> [S; N] {
        let b = self.grade_part(r, 2);
        let minus_square = -self.geometric(&b, &b)[0];
        let size = if minus_square > S::ZERO {
            minus_square.sqrt()
        } else {
            norm_squared(&b).sqrt()
        };
        let angle = size.atan2(r[0]);
        scale(&b, sin_over(size, angle))
    }
}

/// `y / x` for `y = f(x)` with `f(x) ~ x` near zero (sin, sinh, atan): 1 for tiny `x`.
fn sin_over<S: Scalar>(x: S, y: S) -> S {
    if x.abs() < S::EPSILON.sqrt() {
        S::ONE
    } else {
        y / x
    }
}

/// The sum of squared coefficients (the Euclidean norm squared of the coefficient array).
#[must_use]
pub fn norm_squared<S: Scalar, const N: usize>(a: &[S; N]) -> S {
    a.iter().fold(S::ZERO, |acc, &c| acc + c * c)
}

/// Every coefficient times `factor`.
#[must_use]
pub fn scale<S: Scalar, const N: usize>(a: &[S; N], factor: S) -> [S; N] {
    a.map(|c| c * factor)
}

/// The coefficient-wise sum.
#[must_use]
pub fn add<S: Scalar, const N: usize>(a: &[S; N], b: &[S; N]) -> [S; N] {
    std::array::from_fn(|i| a[i] + b[i])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::inputs::{g3_bivectors, g3_multivectors, g4_bivectors, g4_multivectors};

    const E1: usize = 0b001;
    const E2: usize = 0b010;
    const E3: usize = 0b100;
    const E12: usize = 0b011;
    const E13: usize = 0b101;
    const E23: usize = 0b110;
    const E123: usize = 0b111;

    fn blade<const N: usize>(mask: usize, value: f64) -> [f64; N] {
        let mut out = [0.0; N];
        out[mask] = value;
        out
    }

    fn assert_close<const N: usize>(a: &[f64; N], b: &[f64; N], tolerance: f64) {
        let worst = a
            .iter()
            .zip(b)
            .map(|(x, y)| (x - y).abs())
            .fold(0.0, f64::max);
        assert!(worst <= tolerance, "differ by {worst}:\n{a:?}\n{b:?}");
    }

    #[test]
    fn g3_blade_squares_are_plus_one_for_vectors_and_minus_one_for_bivectors_and_the_pseudoscalar()
    {
        let g3 = G3::euclidean();
        for (mask, square) in [
            (E1, 1),
            (E2, 1),
            (E3, 1),
            (E12, -1),
            (E13, -1),
            (E23, -1),
            (E123, -1),
        ] {
            assert_eq!(g3.blade_product(mask, mask), (square, 0), "blade {mask:#b}");
        }
    }

    #[test]
    fn g3_vectors_anticommute_into_bivectors() {
        let g3 = G3::euclidean();
        assert_eq!(g3.blade_product(E1, E2), (1, E12));
        assert_eq!(g3.blade_product(E2, E1), (-1, E12));
        assert_eq!(g3.blade_product(E2, E3), (1, E23));
        assert_eq!(g3.blade_product(E3, E1), (-1, E13));
        assert_eq!(g3.blade_product(E12, E3), (1, E123));
        assert_eq!(g3.blade_product(E1, E23), (1, E123));
        // The pseudoscalar commutes with everything in G3: I e1 = e23.
        assert_eq!(g3.blade_product(E123, E1), (1, E23));
        assert_eq!(g3.blade_product(E123, E2), (-1, E13));
        assert_eq!(g3.blade_product(E123, E3), (1, E12));
    }

    #[test]
    fn g3_bivectors_multiply_like_the_quaternion_table() {
        // i = -e23, j = e13, k = -e12 (the mapping of glam and ultraviolet).
        let g3 = G3::euclidean();
        let one: [f64; 8] = blade(0, 1.0);
        let i: [f64; 8] = blade(E23, -1.0);
        let j: [f64; 8] = blade(E13, 1.0);
        let k: [f64; 8] = blade(E12, -1.0);
        let minus_one = scale(&one, -1.0);
        let product = |a: &[f64; 8], b: &[f64; 8]| g3.geometric(a, b);
        assert_eq!(product(&i, &i), minus_one);
        assert_eq!(product(&j, &j), minus_one);
        assert_eq!(product(&k, &k), minus_one);
        assert_eq!(product(&i, &j), k);
        assert_eq!(product(&j, &k), i);
        assert_eq!(product(&k, &i), j);
        assert_eq!(product(&j, &i), scale(&k, -1.0));
        assert_eq!(product(&product(&i, &j), &k), minus_one);
    }

    #[test]
    fn g4_pseudoscalar_squares_to_plus_one() {
        let g4 = G4::euclidean();
        assert_eq!(g4.blade_product(0b1111, 0b1111), (1, 0));
        assert_eq!(g4.blade_product(0b0011, 0b1100), (1, 0b1111));
        assert_eq!(g4.blade_product(0b1001, 0b1001), (-1, 0));
    }

    #[test]
    fn degenerate_and_negative_generators_follow_the_metric() {
        let pga = Algebra::<8>::new(&[0, 1, 1]);
        assert_eq!(pga.blade_product(E1, E1), (0, 0));
        assert_eq!(pga.blade_product(E12, E12), (0, 0));
        assert_eq!(pga.blade_product(E23, E23), (-1, 0));
        let sta = Algebra::<16>::new(&[1, -1, -1, -1]);
        assert_eq!(sta.blade_product(0b0010, 0b0010), (-1, 0));
        assert_eq!(sta.blade_product(0b0011, 0b0011), (1, 0));
        assert_eq!(sta.blade_product(0b1111, 0b1111), (-1, 0));
    }

    #[test]
    fn canonical_order_is_grade_then_lexicographic() {
        assert_eq!(
            G3::euclidean().canonical_blades(),
            [0, E1, E2, E3, E12, E13, E23, E123]
        );
        let g4 = G4::euclidean();
        assert_eq!(
            g4.blades_of_grades(&[2]),
            vec![0b0011, 0b0101, 0b1001, 0b0110, 0b1010, 0b1100]
        );
        assert_eq!(g4.blades_of_grades(&[0, 4]), vec![0, 0b1111]);
    }

    #[test]
    fn product_is_associative_and_reverse_is_an_anti_automorphism() {
        let g4 = G4::euclidean();
        let xs = g4_multivectors(30, 1.0, 9);
        for w in xs.windows(3) {
            let (a, b, c) = (&w[0], &w[1], &w[2]);
            let left = g4.geometric(&g4.geometric(a, b), c);
            let right = g4.geometric(a, &g4.geometric(b, c));
            assert_close(&left, &right, 1e-12);
            let rev = g4.reverse(&g4.geometric(a, b));
            assert_close(&rev, &g4.geometric(&g4.reverse(b), &g4.reverse(a)), 1e-12);
        }
    }

    #[test]
    fn g3_exp_closed_form_matches_the_series() {
        let g3 = G3::euclidean();
        let blades = g3.blades_of_grades(&[2]);
        for b in g3_bivectors(100, 11) {
            let b = g3.embed(&blades, &scale(&b, 3.0));
            assert_close(&g3.exp(&b), &g3.exp_series(&b), 1e-13);
        }
    }

    #[test]
    fn g4_exp_of_a_non_simple_bivector_is_a_unit_rotor() {
        let g4 = G4::euclidean();
        let blades = g4.blades_of_grades(&[2]);
        for b in g4_bivectors(50, 12) {
            let r = g4.exp(&g4.embed(&blades, &b));
            let unit = g4.geometric(&r, &g4.reverse(&r));
            assert_close(&unit, &blade(0, 1.0), 1e-13);
            // exp(B) exp(-B) = 1 as well: the series is not just any unit rotor.
            let back = g4.geometric(&r, &g4.exp(&g4.embed(&blades, &scale(&b, -1.0))));
            assert_close(&back, &blade(0, 1.0), 1e-13);
        }
    }

    #[test]
    fn g3_log_inverts_exp_on_the_principal_range() {
        let g3 = G3::euclidean();
        let blades = g3.blades_of_grades(&[2]);
        for b in g3_bivectors(100, 13) {
            let b = g3.embed(&blades, &b);
            assert_close(&g3.log(&g3.exp(&b)), &b, 1e-13);
        }
    }

    #[test]
    fn f32_product_agrees_with_f64() {
        let g3 = G3::euclidean();
        for w in g3_multivectors(50, 1.0, 14).windows(2) {
            let exact = g3.geometric(&w[0], &w[1]);
            let single = g3.geometric(&w[0].map(|c| c as f32), &w[1].map(|c| c as f32));
            assert_close(&exact, &single.map(f64::from), 1e-5);
        }
    }
}
