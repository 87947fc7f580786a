//! A slow, dense reference geometric algebra, written from the definitions.
//!
//! A multivector is a `Vec<f64>` of length `2^n` indexed by blade bitmask (see
//! [`crate::blade`]). The metric is the list of generator squares (1, -1 or 0).
//! Every product other than the geometric one is computed as the lecture defines
//! it: split both operands into homogeneous parts, multiply each pair of parts
//! geometrically and keep one grade of the result. Nothing here is unrolled or
//! sparse; it is meant to be obviously right, not fast.

use crate::blade::{canonical_blades, grade, reorder_sign};

/// The bilinear products the generated algebras emit, named as in `TERM_COUNTS`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Product {
    /// `AB`.
    Geometric,
    /// `A ^ B`: the sum of `<A_r B_s>_{r+s}`.
    Outer,
    /// `A | B`, the lecture's inner product: the sum of `<A_r B_s>_{|r-s|}`.
    Inner,
    /// The sum of `<A_r B_s>_{s-r}` over `s >= r`.
    LeftContraction,
    /// The sum of `<A_r B_s>_{r-s}` over `r >= s`.
    RightContraction,
    /// `<AB>_0`.
    ScalarProduct,
    /// `(AB - BA) / 2`.
    Commutator,
    /// The regressive product (join) `undual(dual(A) ^ dual(B))`, through the right
    /// complement.
    Regressive,
}

impl Product {
    /// Every product, in the order the contract lists them.
    pub const ALL: [Product; 8] = [
        Product::Geometric,
        Product::Outer,
        Product::Inner,
        Product::LeftContraction,
        Product::RightContraction,
        Product::ScalarProduct,
        Product::Commutator,
        Product::Regressive,
    ];

    /// The product's name in `TERM_COUNTS`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Product::Geometric => "geometric",
            Product::Outer => "outer",
            Product::Inner => "inner",
            Product::LeftContraction => "left_contraction",
            Product::RightContraction => "right_contraction",
            Product::ScalarProduct => "scalar_product",
            Product::Commutator => "commutator",
            Product::Regressive => "regressive",
        }
    }

    /// The product named `name` in `TERM_COUNTS`.
    #[must_use]
    pub fn from_name(name: &str) -> Option<Product> {
        Product::ALL.into_iter().find(|p| p.name() == name)
    }

    /// For a grade-filter product, the grade it keeps of `<A_r B_s>`, or `None`
    /// when it keeps nothing of that pair. `Geometric` and `Commutator` are not
    /// grade filters and return `None`; neither is the regressive product, which is an
    /// outer product of complements.
    #[must_use]
    pub fn kept_grade(self, r: usize, s: usize) -> Option<usize> {
        match self {
            Product::Outer => Some(r + s),
            Product::Inner => Some(r.abs_diff(s)),
            Product::LeftContraction => s.checked_sub(r),
            Product::RightContraction => r.checked_sub(s),
            Product::ScalarProduct => Some(0),
            Product::Geometric | Product::Commutator | Product::Regressive => None,
        }
    }
}

/// A geometric algebra given by the squares of its generators.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Algebra {
    metric: Vec<i8>,
}

impl Algebra {
    /// The algebra whose generator `e_{i+1}` squares to `metric[i]`.
    ///
    /// # Panics
    /// If a square is not 1, -1 or 0, or there are more than 8 generators.
    #[must_use]
    pub fn new(metric: &[i8]) -> Self {
        assert!(
            metric.len() <= 8,
            "the reference is dense: 2^n must stay small"
        );
        assert!(
            metric.iter().all(|m| matches!(m, -1..=1)),
            "generator squares must be 1, -1 or 0: {metric:?}"
        );
        Algebra {
            metric: metric.to_vec(),
        }
    }

    /// The number of generators `n`.
    #[must_use]
    pub fn dim(&self) -> usize {
        self.metric.len()
    }

    /// The number of blades, `2^n`.
    #[must_use]
    pub fn size(&self) -> usize {
        1 << self.dim()
    }

    /// The generator squares.
    #[must_use]
    pub fn metric(&self) -> &[i8] {
        &self.metric
    }

    /// The blade with every generator, `e_{12..n}`.
    #[must_use]
    pub fn pseudoscalar_blade(&self) -> usize {
        self.size() - 1
    }

    /// `e_A e_B = sign e_{A xor B}`: the parity of the swaps times the squares of
    /// the shared generators (so the sign is 0 when a shared generator is null).
    #[must_use]
    pub fn blade_product(&self, a: usize, b: usize) -> (f64, usize) {
        let shared = a & b;
        let squares: f64 = (0..self.dim())
            .filter(|bit| shared & (1 << bit) != 0)
            .map(|bit| f64::from(self.metric[bit]))
            .product();
        (reorder_sign(a, b) * squares, a ^ b)
    }

    /// Whether the blade pair `(a, b)` contributes a term to `product`: its
    /// geometric product is non-zero and passes the product's grade filter (for
    /// the commutator: `e_A e_B = -e_B e_A`).
    #[must_use]
    pub fn contributes(&self, product: Product, a: usize, b: usize) -> bool {
        if product == Product::Regressive {
            let full = self.pseudoscalar_blade();
            return (full ^ a) & (full ^ b) == 0;
        }
        let (sign, blade) = self.blade_product(a, b);
        if sign == 0.0 {
            return false;
        }
        match product {
            Product::Geometric => true,
            Product::Commutator => self.blade_product(b, a).0 == -sign,
            _ => product.kept_grade(grade(a), grade(b)) == Some(grade(blade)),
        }
    }

    /// How many `(i, j)` pairs of blades of `lhs` and `rhs` contribute a term to
    /// `product`: the number of multiplications an unrolled product needs.
    #[must_use]
    pub fn term_count(&self, product: Product, lhs: &[usize], rhs: &[usize]) -> usize {
        lhs.iter()
            .flat_map(|&a| rhs.iter().map(move |&b| (a, b)))
            .filter(|&(a, b)| self.contributes(product, a, b))
            .count()
    }

    /// The zero multivector.
    #[must_use]
    pub fn zero(&self) -> Vec<f64> {
        vec![0.0; self.size()]
    }

    /// The multivector `value e_blade`.
    #[must_use]
    pub fn basis(&self, blade: usize, value: f64) -> Vec<f64> {
        let mut out = self.zero();
        out[blade] = value;
        out
    }

    /// The scalar `value`.
    #[must_use]
    pub fn scalar(&self, value: f64) -> Vec<f64> {
        self.basis(0, value)
    }

    /// The multivector with `values[k]` on `blades[k]`.
    ///
    /// # Panics
    /// If the lists differ in length.
    #[must_use]
    pub fn from_components(&self, blades: &[usize], values: &[f64]) -> Vec<f64> {
        assert_eq!(blades.len(), values.len(), "one value per blade");
        let mut out = self.zero();
        for (&blade, &value) in blades.iter().zip(values) {
            out[blade] += value;
        }
        out
    }

    /// The components of `a` on `blades`, in that order.
    #[must_use]
    pub fn components(&self, a: &[f64], blades: &[usize]) -> Vec<f64> {
        blades.iter().map(|&blade| a[blade]).collect()
    }

    /// The components of `a` in canonical order (what `Multivector::to_array` holds).
    #[must_use]
    pub fn to_canonical(&self, a: &[f64]) -> Vec<f64> {
        self.components(a, &canonical_blades(self.dim()))
    }

    /// The multivector whose canonical-order components are `values`.
    #[must_use]
    pub fn from_canonical(&self, values: &[f64]) -> Vec<f64> {
        self.from_components(&canonical_blades(self.dim()), values)
    }

    /// `a + b`.
    #[must_use]
    pub fn add(&self, a: &[f64], b: &[f64]) -> Vec<f64> {
        a.iter().zip(b).map(|(x, y)| x + y).collect()
    }

    /// `a - b`.
    #[must_use]
    pub fn sub(&self, a: &[f64], b: &[f64]) -> Vec<f64> {
        a.iter().zip(b).map(|(x, y)| x - y).collect()
    }

    /// `s a`.
    #[must_use]
    pub fn scale(&self, a: &[f64], s: f64) -> Vec<f64> {
        a.iter().map(|x| x * s).collect()
    }

    /// The geometric product `ab`, summed blade pair by blade pair.
    #[must_use]
    pub fn geometric(&self, a: &[f64], b: &[f64]) -> Vec<f64> {
        let mut out = self.zero();
        for (i, &x) in a.iter().enumerate().filter(|(_, x)| **x != 0.0) {
            for (j, &y) in b.iter().enumerate().filter(|(_, y)| **y != 0.0) {
                let (sign, blade) = self.blade_product(i, j);
                out[blade] += sign * x * y;
            }
        }
        out
    }

    /// For every output blade, the sum of `|a_i b_j|` over the blade pairs of the
    /// geometric product that land on it: the magnitude that floating-point error
    /// in any product of `a` and `b` is relative to.
    #[must_use]
    pub fn product_magnitude(&self, a: &[f64], b: &[f64]) -> Vec<f64> {
        let mut out = self.zero();
        for (i, x) in a.iter().enumerate() {
            for (j, y) in b.iter().enumerate() {
                out[i ^ j] += (x * y).abs();
            }
        }
        out
    }

    /// [`Algebra::product_magnitude`] for `product`: the regressive product's blade
    /// pairs land on the shared generators `A & B` rather than on `A xor B`.
    #[must_use]
    pub fn magnitude_of(&self, product: Product, a: &[f64], b: &[f64]) -> Vec<f64> {
        if product != Product::Regressive {
            return self.product_magnitude(a, b);
        }
        let mut out = self.zero();
        for (i, x) in a.iter().enumerate() {
            for (j, y) in b.iter().enumerate() {
                out[i & j] += (x * y).abs();
            }
        }
        out
    }

    /// The grade-`r` part `<a>_r` (zero for `r > n`).
    #[must_use]
    pub fn grade(&self, a: &[f64], r: usize) -> Vec<f64> {
        a.iter()
            .enumerate()
            .map(|(blade, &x)| if grade(blade) == r { x } else { 0.0 })
            .collect()
    }

    /// The sum of `<a_r b_s>_t` over the grade pairs `(r, s)` for which `keep`
    /// returns `Some(t)`.
    fn graded_product(
        &self,
        a: &[f64],
        b: &[f64],
        keep: impl Fn(usize, usize) -> Option<usize>,
    ) -> Vec<f64> {
        let n = self.dim();
        let mut out = self.zero();
        for r in 0..=n {
            let a_r = self.grade(a, r);
            for s in 0..=n {
                if let Some(t) = keep(r, s) {
                    let b_s = self.grade(b, s);
                    let part = self.grade(&self.geometric(&a_r, &b_s), t);
                    out = self.add(&out, &part);
                }
            }
        }
        out
    }

    /// `a ^ b`: the sum of `<a_r b_s>_{r+s}`.
    #[must_use]
    pub fn outer(&self, a: &[f64], b: &[f64]) -> Vec<f64> {
        self.graded_product(a, b, |r, s| Some(r + s))
    }

    /// The lecture's inner product `a . b`: the sum of `<a_r b_s>_{|r-s|}`.
    #[must_use]
    pub fn inner(&self, a: &[f64], b: &[f64]) -> Vec<f64> {
        self.graded_product(a, b, |r, s| Some(r.abs_diff(s)))
    }

    /// The left contraction: the sum of `<a_r b_s>_{s-r}` for `s >= r`.
    #[must_use]
    pub fn left_contraction(&self, a: &[f64], b: &[f64]) -> Vec<f64> {
        self.graded_product(a, b, |r, s| s.checked_sub(r))
    }

    /// The right contraction: the sum of `<a_r b_s>_{r-s}` for `r >= s`.
    #[must_use]
    pub fn right_contraction(&self, a: &[f64], b: &[f64]) -> Vec<f64> {
        self.graded_product(a, b, |r, s| r.checked_sub(s))
    }

    /// The scalar product `<ab>_0`.
    #[must_use]
    pub fn scalar_product(&self, a: &[f64], b: &[f64]) -> f64 {
        self.geometric(a, b)[0]
    }

    /// The commutator product `(ab - ba) / 2`.
    #[must_use]
    pub fn commutator(&self, a: &[f64], b: &[f64]) -> Vec<f64> {
        let difference = self.sub(&self.geometric(a, b), &self.geometric(b, a));
        self.scale(&difference, 0.5)
    }

    /// The regressive product `a v b = undual(dual(a) ^ dual(b))`: the outer product of
    /// the right complements, taken back. Neither step reads the metric (the outer
    /// product of blades with no shared generator is their geometric product), so it is
    /// the same in degenerate metrics such as PGA's.
    #[must_use]
    pub fn regressive(&self, a: &[f64], b: &[f64]) -> Vec<f64> {
        self.undual(&self.outer(&self.dual(a), &self.dual(b)))
    }

    /// Any of the bilinear products.
    #[must_use]
    pub fn product(&self, product: Product, a: &[f64], b: &[f64]) -> Vec<f64> {
        match product {
            Product::Geometric => self.geometric(a, b),
            Product::Outer => self.outer(a, b),
            Product::Inner => self.inner(a, b),
            Product::LeftContraction => self.left_contraction(a, b),
            Product::RightContraction => self.right_contraction(a, b),
            Product::ScalarProduct => self.scalar(self.scalar_product(a, b)),
            Product::Commutator => self.commutator(a, b),
            Product::Regressive => self.regressive(a, b),
        }
    }

    /// Multiplies the grade-`r` part by `sign(r)`.
    fn grade_signs(&self, a: &[f64], sign: impl Fn(usize) -> bool) -> Vec<f64> {
        a.iter()
            .enumerate()
            .map(|(blade, &x)| if sign(grade(blade)) { -x } else { x })
            .collect()
    }

    /// The reverse `~a`: grade `r` times `(-1)^(r(r-1)/2)`.
    #[must_use]
    pub fn reverse(&self, a: &[f64]) -> Vec<f64> {
        self.grade_signs(a, |r| (r * (r.saturating_sub(1)) / 2) % 2 == 1)
    }

    /// The grade involution: grade `r` times `(-1)^r`.
    #[must_use]
    pub fn grade_involution(&self, a: &[f64]) -> Vec<f64> {
        self.grade_signs(a, |r| r % 2 == 1)
    }

    /// The Clifford conjugate, the reverse of the grade involution: grade `r`
    /// times `(-1)^(r(r+1)/2)`.
    #[must_use]
    pub fn conjugate(&self, a: &[f64]) -> Vec<f64> {
        self.grade_signs(a, |r| (r * (r + 1) / 2) % 2 == 1)
    }

    /// The right complement: `e_A` goes to `sign e_C`, `C` the generators not in
    /// `A`, with the sign chosen so that `e_A ^ (sign e_C) = e_{12..n}`. It never
    /// uses the metric.
    #[must_use]
    pub fn dual(&self, a: &[f64]) -> Vec<f64> {
        let full = self.pseudoscalar_blade();
        let mut out = self.zero();
        for (blade, &x) in a.iter().enumerate() {
            let complement = full ^ blade;
            out[complement] += reorder_sign(blade, complement) * x;
        }
        out
    }

    /// The inverse of [`Algebra::dual`].
    #[must_use]
    pub fn undual(&self, a: &[f64]) -> Vec<f64> {
        let full = self.pseudoscalar_blade();
        let mut out = self.zero();
        for (complement, &x) in a.iter().enumerate() {
            let blade = full ^ complement;
            out[blade] += reorder_sign(blade, complement) * x;
        }
        out
    }

    /// `<a ~a>_0`, which may be negative or zero in a non-Euclidean metric.
    #[must_use]
    pub fn norm_squared(&self, a: &[f64]) -> f64 {
        self.scalar_product(a, &self.reverse(a))
    }

    /// The sum of the absolute values of the components, a submultiplicative
    /// norm: `|ab|_1 <= |a|_1 |b|_1` since every blade product has a sign of
    /// magnitude at most 1.
    #[must_use]
    pub fn l1_norm(&self, a: &[f64]) -> f64 {
        a.iter().map(|x| x.abs()).sum()
    }

    /// `exp(a)` by its Taylor series after scaling `a` down by `2^k` until
    /// `|a|_1 <= 1/4`, then squaring the result `k` times.
    #[must_use]
    pub fn exp(&self, a: &[f64]) -> Vec<f64> {
        let norm = self.l1_norm(a);
        let mut squarings = 0;
        while norm / f64::from(1u32 << squarings.min(31)) > 0.25 {
            squarings += 1;
        }
        let x = self.scale(a, 0.5f64.powi(squarings));
        let mut sum = self.scalar(1.0);
        let mut term = self.scalar(1.0);
        for k in 1..=40 {
            term = self.scale(&self.geometric(&term, &x), 1.0 / f64::from(k));
            sum = self.add(&sum, &term);
            if self.l1_norm(&term) <= f64::EPSILON * 1e-3 * self.l1_norm(&sum) {
                break;
            }
        }
        for _ in 0..squarings {
            sum = self.geometric(&sum, &sum);
        }
        sum
    }

    /// The matrix of `x -> a x` on blades: `m[k][j]` is the `e_k` component of `a e_j`.
    fn left_multiplication_matrix(&self, a: &[f64]) -> Vec<Vec<f64>> {
        let columns: Vec<Vec<f64>> = (0..self.size())
            .map(|j| self.geometric(a, &self.basis(j, 1.0)))
            .collect();
        (0..self.size())
            .map(|k| columns.iter().map(|column| column[k]).collect())
            .collect()
    }

    /// The multivector `y` with `a y = 1`, found by Gaussian elimination with
    /// partial pivoting on the left-multiplication matrix of `a`; `None` when a
    /// pivot falls below `1e-10` times the largest entry (not invertible, or too
    /// ill-conditioned to tell).
    #[must_use]
    pub fn inverse(&self, a: &[f64]) -> Option<Vec<f64>> {
        let size = self.size();
        let mut m = self.left_multiplication_matrix(a);
        let mut rhs = self.scalar(1.0);
        let largest = m.iter().flatten().fold(0.0f64, |acc, x| acc.max(x.abs()));
        if largest == 0.0 {
            return None;
        }
        for col in 0..size {
            let pivot = (col..size).max_by(|&p, &q| m[p][col].abs().total_cmp(&m[q][col].abs()))?;
            if m[pivot][col].abs() < 1e-10 * largest {
                return None;
            }
            m.swap(col, pivot);
            rhs.swap(col, pivot);
            let (done, below) = m.split_at_mut(col + 1);
            let pivot_row = &done[col];
            for (offset, row) in below.iter_mut().enumerate() {
                let factor = row[col] / pivot_row[col];
                if factor != 0.0 {
                    for (x, p) in row.iter_mut().zip(pivot_row).skip(col) {
                        *x -= factor * p;
                    }
                    rhs[col + 1 + offset] -= factor * rhs[col];
                }
            }
        }
        let mut y = self.zero();
        for row in (0..size).rev() {
            let known: f64 = (row + 1..size).map(|k| m[row][k] * y[k]).sum();
            y[row] = (rhs[row] - known) / m[row][row];
        }
        Some(y)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::blade::{blade_from_name, blades_of_grades};
    use crate::{assert_close, prop_assert_close};
    use proptest::prelude::*;

    fn e(name: &str) -> usize {
        blade_from_name(name).unwrap()
    }

    /// The multivector `value e_name` in `algebra`.
    fn b(algebra: &Algebra, name: &str, value: f64) -> Vec<f64> {
        algebra.basis(e(name), value)
    }

    fn g3() -> Algebra {
        Algebra::new(&[1, 1, 1])
    }

    #[test]
    fn orthogonal_vectors_anticommute_e1e2e1_is_minus_e2() {
        let g3 = g3();
        let e1 = b(&g3, "e1", 1.0);
        let e2 = b(&g3, "e2", 1.0);
        let e1e2e1 = g3.geometric(&g3.geometric(&e1, &e2), &e1);
        assert_eq!(e1e2e1, b(&g3, "e2", -1.0));
    }

    #[test]
    fn unit_bivectors_and_pseudoscalars_square_as_in_the_textbook() {
        let g3 = g3();
        let e12 = b(&g3, "e12", 1.0);
        assert_eq!(g3.geometric(&e12, &e12), g3.scalar(-1.0));
        let e123 = b(&g3, "e123", 1.0);
        assert_eq!(g3.geometric(&e123, &e123), g3.scalar(-1.0));
        let g2 = Algebra::new(&[1, 1]);
        assert_eq!(
            g2.geometric(&b(&g2, "e12", 1.0), &b(&g2, "e12", 1.0)),
            g2.scalar(-1.0)
        );
        let g4 = Algebra::new(&[1, 1, 1, 1]);
        let i4 = b(&g4, "e1234", 1.0);
        assert_eq!(g4.geometric(&i4, &i4), g4.scalar(1.0));
        let sta = Algebra::new(&[1, -1, -1, -1]);
        let i_sta = b(&sta, "e1234", 1.0);
        assert_eq!(sta.geometric(&i_sta, &i_sta), sta.scalar(-1.0));
        // A boost plane squares to +1: (g0 g1)^2 = -g0^2 g1^2 = 1.
        let boost = b(&sta, "e12", 1.0);
        assert_eq!(sta.geometric(&boost, &boost), sta.scalar(1.0));
    }

    #[test]
    fn pga_null_generator_squares_to_zero_but_still_anticommutes() {
        let pga = Algebra::new(&[1, 1, 1, 0]);
        let e0 = b(&pga, "e4", 1.0);
        assert_eq!(pga.geometric(&e0, &e0), pga.zero());
        let e1 = b(&pga, "e1", 1.0);
        assert_eq!(pga.geometric(&e1, &e0), b(&pga, "e14", 1.0));
        assert_eq!(pga.geometric(&e0, &e1), b(&pga, "e14", -1.0));
        // A translator generator squares to zero: (e1 e0)^2 = -e1^2 e0^2 = 0.
        let e14 = b(&pga, "e14", 1.0);
        assert_eq!(pga.geometric(&e14, &e14), pga.zero());
        assert_eq!(
            pga.exp(&b(&pga, "e14", 0.5)),
            pga.add(&pga.scalar(1.0), &b(&pga, "e14", 0.5))
        );
    }

    #[test]
    fn cga_has_a_null_vector_built_from_e4_and_e5() {
        let cga = Algebra::new(&[1, 1, 1, 1, -1]);
        let e5 = b(&cga, "e5", 1.0);
        assert_eq!(cga.geometric(&e5, &e5), cga.scalar(-1.0));
        let null = cga.add(&b(&cga, "e4", 1.0), &e5);
        assert_eq!(cga.geometric(&null, &null), cga.zero());
        assert!(cga.inverse(&null).is_none());
    }

    #[test]
    fn quaternion_multiplication_table_is_the_g3_even_subalgebra() {
        // i = e3e2, j = e1e3, k = e2e1 satisfy Hamilton's i^2 = j^2 = k^2 = ijk = -1.
        let g3 = g3();
        let i = b(&g3, "e23", -1.0);
        let j = b(&g3, "e13", 1.0);
        let k = b(&g3, "e12", -1.0);
        let minus_one = g3.scalar(-1.0);
        let neg = |x: &[f64]| g3.scale(x, -1.0);
        for q in [&i, &j, &k] {
            assert_eq!(g3.geometric(q, q), minus_one);
        }
        assert_eq!(g3.geometric(&g3.geometric(&i, &j), &k), minus_one);
        assert_eq!(g3.geometric(&i, &j), k);
        assert_eq!(g3.geometric(&j, &k), i);
        assert_eq!(g3.geometric(&k, &i), j);
        assert_eq!(g3.geometric(&j, &i), neg(&k));
        assert_eq!(g3.geometric(&k, &j), neg(&i));
        assert_eq!(g3.geometric(&i, &k), neg(&j));
    }

    #[test]
    fn vector_products_split_into_inner_and_outer_parts() {
        let g3 = g3();
        let a = g3.from_components(&blades_of_grades(3, &[1]), &[1.0, 2.0, 3.0]);
        let c = g3.from_components(&blades_of_grades(3, &[1]), &[4.0, 5.0, 6.0]);
        assert_eq!(g3.inner(&a, &c), g3.scalar(32.0));
        assert_eq!(g3.scalar_product(&a, &c), 32.0);
        // a ^ c = (1*5 - 2*4) e12 + (1*6 - 3*4) e13 + (2*6 - 3*5) e23.
        let wedge = g3.from_components(&blades_of_grades(3, &[2]), &[-3.0, -6.0, -3.0]);
        assert_eq!(g3.outer(&a, &c), wedge);
        assert_eq!(g3.commutator(&a, &c), wedge);
        assert_eq!(g3.geometric(&a, &c), g3.add(&g3.scalar(32.0), &wedge));
    }

    #[test]
    fn contractions_of_basis_blades_match_hand_computation() {
        let g3 = g3();
        let e12 = b(&g3, "e12", 1.0);
        assert_eq!(
            g3.left_contraction(&b(&g3, "e1", 1.0), &e12),
            b(&g3, "e2", 1.0)
        );
        assert_eq!(
            g3.left_contraction(&b(&g3, "e2", 1.0), &e12),
            b(&g3, "e1", -1.0)
        );
        assert_eq!(g3.left_contraction(&e12, &b(&g3, "e1", 1.0)), g3.zero());
        assert_eq!(
            g3.right_contraction(&e12, &b(&g3, "e2", 1.0)),
            b(&g3, "e1", 1.0)
        );
        assert_eq!(g3.right_contraction(&b(&g3, "e1", 1.0), &e12), g3.zero());
        // The lecture's inner product is symmetric in which side has the lower grade.
        assert_eq!(g3.inner(&e12, &b(&g3, "e2", 1.0)), b(&g3, "e1", 1.0));
        assert_eq!(g3.inner(&b(&g3, "e1", 1.0), &e12), b(&g3, "e2", 1.0));
        // ... and, taken literally (t = |r - s|), scales by a scalar operand.
        assert_eq!(g3.inner(&g3.scalar(2.0), &e12), b(&g3, "e12", 2.0));
        assert_eq!(
            g3.left_contraction(&g3.scalar(2.0), &e12),
            b(&g3, "e12", 2.0)
        );
        assert_eq!(g3.right_contraction(&g3.scalar(2.0), &e12), g3.zero());
        assert_eq!(g3.outer(&b(&g3, "e1", 1.0), &b(&g3, "e1", 1.0)), g3.zero());
        assert_eq!(
            g3.outer(&b(&g3, "e2", 1.0), &b(&g3, "e13", 1.0)),
            b(&g3, "e123", -1.0)
        );
    }

    #[test]
    fn commutator_vanishes_exactly_for_commuting_blades() {
        let g3 = g3();
        assert_eq!(
            g3.commutator(&b(&g3, "e12", 1.0), &b(&g3, "e3", 1.0)),
            g3.zero()
        );
        assert_eq!(
            g3.commutator(&b(&g3, "e12", 1.0), &b(&g3, "e1", 1.0)),
            b(&g3, "e2", -1.0)
        );
        // e12 e23 = e13 and e23 e12 = -e13.
        assert_eq!(
            g3.commutator(&b(&g3, "e12", 1.0), &b(&g3, "e23", 1.0)),
            b(&g3, "e13", 1.0)
        );
    }

    #[test]
    fn involutions_flip_the_textbook_grades() {
        let g4 = Algebra::new(&[1, 1, 1, 1]);
        let ones = vec![1.0; 16];
        // Grades 0..=4: reverse + + - - +, involution + - + - +, conjugate + - - + +.
        let signs = |f: &dyn Fn(&[f64]) -> Vec<f64>| -> Vec<f64> {
            let out = f(&ones);
            (0..=4).map(|r| out[blades_of_grades(4, &[r])[0]]).collect()
        };
        assert_eq!(signs(&|x| g4.reverse(x)), [1.0, 1.0, -1.0, -1.0, 1.0]);
        assert_eq!(
            signs(&|x| g4.grade_involution(x)),
            [1.0, -1.0, 1.0, -1.0, 1.0]
        );
        assert_eq!(signs(&|x| g4.conjugate(x)), [1.0, -1.0, -1.0, 1.0, 1.0]);
    }

    #[test]
    fn dual_is_the_right_complement() {
        let g3 = g3();
        assert_eq!(g3.dual(&b(&g3, "e1", 1.0)), b(&g3, "e23", 1.0));
        assert_eq!(g3.dual(&b(&g3, "e2", 1.0)), b(&g3, "e13", -1.0));
        assert_eq!(g3.dual(&b(&g3, "e12", 1.0)), b(&g3, "e3", 1.0));
        assert_eq!(g3.dual(&g3.scalar(1.0)), b(&g3, "e123", 1.0));
        assert_eq!(g3.dual(&b(&g3, "e123", 1.0)), g3.scalar(1.0));
        // Metric-free: the null generator of PGA has a dual too.
        let pga = Algebra::new(&[1, 1, 1, 0]);
        assert_eq!(pga.dual(&b(&pga, "e4", 1.0)), b(&pga, "e123", -1.0));
        for algebra in [g3, pga, Algebra::new(&[1, 1, 1, 1, -1])] {
            let i = algebra.pseudoscalar_blade();
            for blade in 0..algebra.size() {
                let x = algebra.basis(blade, 1.0);
                let wedge = algebra.outer(&x, &algebra.dual(&x));
                assert_eq!(
                    wedge,
                    algebra.basis(i, 1.0),
                    "e_A ^ dual(e_A) for A = {blade:b}"
                );
                assert_eq!(algebra.undual(&algebra.dual(&x)), x);
                assert_eq!(algebra.dual(&algebra.undual(&x)), x);
            }
        }
    }

    #[test]
    fn norm_squared_may_be_negative_or_zero() {
        let g3 = g3();
        assert_eq!(g3.norm_squared(&b(&g3, "e12", 3.0)), 9.0);
        let sta = Algebra::new(&[1, -1, -1, -1]);
        assert_eq!(sta.norm_squared(&b(&sta, "e2", 2.0)), -4.0);
        let pga = Algebra::new(&[1, 1, 1, 0]);
        assert_eq!(pga.norm_squared(&b(&pga, "e14", 2.0)), 0.0);
    }

    #[test]
    fn exp_of_a_plane_is_cos_plus_sin_and_cosh_plus_sinh() {
        let g3 = g3();
        for angle in [1e-9, 0.3, 2.0, 3.1, 30.0] {
            let rotor = g3.exp(&b(&g3, "e12", angle));
            let expected = g3.add(&g3.scalar(angle.cos()), &b(&g3, "e12", angle.sin()));
            assert_close!(rotor, expected, rel = 1e-13);
        }
        let sta = Algebra::new(&[1, -1, -1, -1]);
        for rapidity in [1e-9, 0.5, 3.0] {
            let boost = sta.exp(&b(&sta, "e12", rapidity));
            let expected = sta.add(
                &sta.scalar(rapidity.cosh()),
                &b(&sta, "e12", rapidity.sinh()),
            );
            assert_close!(boost, expected, rel = 1e-13);
        }
    }

    #[test]
    fn inverse_of_a_vector_is_the_vector_over_its_square() {
        let g3 = g3();
        let v = g3.add(&b(&g3, "e1", 1.0), &b(&g3, "e2", 1.0));
        let inverse = g3.inverse(&v).unwrap();
        assert_close!(inverse, g3.scale(&v, 0.5));
        let pga = Algebra::new(&[1, 1, 1, 0]);
        assert!(pga.inverse(&b(&pga, "e4", 1.0)).is_none());
        assert!(g3.inverse(&g3.zero()).is_none());
        // 1 + e1 is a zero divisor: (1 + e1)(1 - e1) = 0.
        assert!(g3
            .inverse(&g3.add(&g3.scalar(1.0), &b(&g3, "e1", 1.0)))
            .is_none());
    }

    #[test]
    fn term_counts_of_textbook_products() {
        let g3 = g3();
        let vector = blades_of_grades(3, &[1]);
        let bivector = blades_of_grades(3, &[2]);
        let even = blades_of_grades(3, &[0, 2]);
        assert_eq!(g3.term_count(Product::Geometric, &vector, &vector), 9);
        assert_eq!(g3.term_count(Product::Inner, &vector, &vector), 3);
        assert_eq!(g3.term_count(Product::Outer, &vector, &vector), 6);
        assert_eq!(g3.term_count(Product::Commutator, &vector, &vector), 6);
        assert_eq!(g3.term_count(Product::Commutator, &bivector, &bivector), 6);
        assert_eq!(g3.term_count(Product::Geometric, &even, &even), 16);
        assert_eq!(
            g3.term_count(Product::LeftContraction, &bivector, &vector),
            0
        );
        assert_eq!(
            g3.term_count(Product::RightContraction, &bivector, &vector),
            6
        );
        let pga = Algebra::new(&[1, 1, 1, 0]);
        let pga_vector = blades_of_grades(4, &[1]);
        assert_eq!(
            pga.term_count(Product::ScalarProduct, &pga_vector, &pga_vector),
            3
        );
    }

    const METRICS: [&[i8]; 6] = [
        &[1, 1],
        &[1, 1, 1],
        &[1, 1, 1, 1],
        &[1, -1, -1, -1],
        &[1, 1, 1, 0],
        &[1, 1, 1, 1, -1],
    ];

    fn algebra_and_two() -> impl Strategy<Value = (Algebra, Vec<f64>, Vec<f64>)> {
        (0..METRICS.len()).prop_flat_map(|k| {
            let algebra = Algebra::new(METRICS[k]);
            let size = algebra.size();
            let values = || prop::collection::vec(-4.0..4.0f64, size);
            (Just(algebra), values(), values())
        })
    }

    proptest! {
        /// The graded products, written as the lecture defines them, must agree
        /// with the blade-pair filter that term counts use.
        #[test]
        fn graded_products_agree_with_the_blade_pair_filter((algebra, a, b) in algebra_and_two()) {
            // The regressive product is no filter of the geometric product's pairs (its
            // pairs land on `A & B`); its definition is its own, through complements.
            for product in Product::ALL.into_iter().filter(|p| *p != Product::Regressive) {
                let mut expected = algebra.zero();
                for (i, x) in a.iter().enumerate() {
                    for (j, y) in b.iter().enumerate() {
                        if algebra.contributes(product, i, j) {
                            let (sign, blade) = algebra.blade_product(i, j);
                            expected[blade] += sign * x * y;
                        }
                    }
                }
                prop_assert_close!(algebra.product(product, &a, &b), expected, rel = 1e-12, "{product:?}");
            }
        }

        #[test]
        fn geometric_product_is_associative((algebra, a, b) in algebra_and_two()) {
            let c = algebra.add(&a, &algebra.reverse(&b));
            let left = algebra.geometric(&algebra.geometric(&a, &b), &c);
            let right = algebra.geometric(&a, &algebra.geometric(&b, &c));
            prop_assert_close!(left, right, rel = 1e-12);
        }

        #[test]
        fn reverse_is_an_anti_automorphism((algebra, a, b) in algebra_and_two()) {
            let left = algebra.reverse(&algebra.geometric(&a, &b));
            let right = algebra.geometric(&algebra.reverse(&b), &algebra.reverse(&a));
            prop_assert_close!(left, right, rel = 1e-12);
        }

        #[test]
        fn inverse_multiplies_to_one_on_both_sides((algebra, a, _b) in algebra_and_two()) {
            if let Some(inverse) = algebra.inverse(&a) {
                let one = algebra.scalar(1.0);
                let scale = algebra.l1_norm(&a) * algebra.l1_norm(&inverse);
                prop_assert_close!(algebra.geometric(&a, &inverse), one, scale = scale, rel = 1e-9);
                prop_assert_close!(algebra.geometric(&inverse, &a), one, scale = scale, rel = 1e-9);
            }
        }

        #[test]
        fn exp_of_a_sum_of_commuting_terms_is_the_product((algebra, a, _b) in algebra_and_two()) {
            let x = algebra.scale(&algebra.grade(&a, 2), 0.5);
            let both = algebra.exp(&algebra.scale(&x, 2.0));
            let squared = algebra.geometric(&algebra.exp(&x), &algebra.exp(&x));
            let scale = algebra.l1_norm(&both).max(1.0);
            prop_assert_close!(both, squared, scale = scale, rel = 1e-11);
        }
    }
}
