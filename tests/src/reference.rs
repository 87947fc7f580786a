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
