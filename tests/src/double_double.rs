//! Double-double arithmetic (an unevaluated sum `hi + lo` of two `f64`, about 106 bits)
//! and the inverse of a dense reference multivector in it: the high-precision reference
//! for generated inverses near singular input, where an `f64` reference would be as
//! wrong as the code under test.
//!
//! The operations are Dekker's and Knuth's error-free transformations (`two_sum`,
//! `two_prod` by a fused multiply-add) as in the QD library of Hida, Li and Bailey; see
//! docs/references.md. The inverse is Gaussian elimination with partial pivoting on the
//! left-multiplication matrix built from [`Algebra::blade_product`], so it shares nothing
//! with the generated code.

use crate::reference::Algebra;

/// `hi + lo` with `|lo| <= ulp(hi) / 2`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dd {
    /// The leading part.
    pub hi: f64,
    /// The trailing part.
    pub lo: f64,
}

/// `(s, e)` with `s = fl(a + b)` and `s + e = a + b` exactly (Knuth).
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// [`two_sum`] for `|a| >= |b|` (Dekker).
fn quick_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    (s, b - (s - a))
}

/// `(p, e)` with `p = fl(a b)` and `p + e = a b` exactly (no underflow assumed).
fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, a.mul_add(b, -p))
}

impl Dd {
    /// Zero.
    pub const ZERO: Dd = Dd { hi: 0.0, lo: 0.0 };

    /// `x` exactly.
    #[must_use]
    pub fn from_f64(x: f64) -> Dd {
        Dd { hi: x, lo: 0.0 }
    }

    /// The nearest `f64` (to within an ulp).
    #[must_use]
    pub fn to_f64(self) -> f64 {
        self.hi + self.lo
    }

    /// `|self|`.
    #[must_use]
    pub fn abs(self) -> Dd {
        if self.hi < 0.0 || (self.hi == 0.0 && self.lo < 0.0) {
            -self
        } else {
            self
        }
    }
}

impl core::ops::Add for Dd {
    type Output = Dd;

    /// To about 2^-104 relative (the accurate sum of QD).
    fn add(self, other: Dd) -> Dd {
        let (s, e) = two_sum(self.hi, other.hi);
        let (t, f) = two_sum(self.lo, other.lo);
        let (s, e) = quick_two_sum(s, e + t);
        let (hi, lo) = quick_two_sum(s, e + f);
        Dd { hi, lo }
    }
}

impl core::ops::Neg for Dd {
    type Output = Dd;

    fn neg(self) -> Dd {
        Dd {
            hi: -self.hi,
            lo: -self.lo,
        }
    }
}

impl core::ops::Sub for Dd {
    type Output = Dd;

    fn sub(self, other: Dd) -> Dd {
        self + -other
    }
}

impl core::ops::Mul for Dd {
    type Output = Dd;

    /// To about 2^-104 relative.
    fn mul(self, other: Dd) -> Dd {
        let (p, e) = two_prod(self.hi, other.hi);
        let e = e + (self.hi * other.lo + self.lo * other.hi);
        let (hi, lo) = quick_two_sum(p, e);
        Dd { hi, lo }
    }
}

impl core::ops::Div for Dd {
    type Output = Dd;

    /// By three rounds of long division.
    fn div(self, other: Dd) -> Dd {
        let q1 = self.hi / other.hi;
        let r = self - other * Dd::from_f64(q1);
        let q2 = r.hi / other.hi;
        let r = r - other * Dd::from_f64(q2);
        let q3 = r.hi / other.hi;
        let (hi, lo) = quick_two_sum(q1, q2);
        Dd { hi, lo } + Dd::from_f64(q3)
    }
}

/// The inverse of the dense multivector `a` (components of order 1, so that nothing
/// underflows), in double-double, with its residual: `(y, sum |a y - 1|)` rounded to
/// `f64`. `None` when an elimination pivot is exactly zero.
#[must_use]
pub fn inverse(algebra: &Algebra, a: &[f64]) -> Option<(Vec<f64>, f64)> {
    let size = algebra.size();
    // m[k][j]: component k of a e_j.
    let mut m = vec![vec![Dd::ZERO; size]; size];
    for (i, &ai) in a.iter().enumerate() {
        if ai == 0.0 {
            continue;
        }
        // Column j's entries land on rows k that the blade product picks, so the loop
        // indexes rather than iterates.
        #[allow(clippy::needless_range_loop)]
        for j in 0..size {
            let (sign, k) = algebra.blade_product(i, j);
            if sign != 0.0 {
                m[k][j] = m[k][j] + Dd::from_f64(sign * ai);
            }
        }
    }
    let mut rhs = vec![Dd::ZERO; size];
    rhs[0] = Dd::from_f64(1.0);
    for col in 0..size {
        let pivot =
            (col..size).max_by(|&p, &q| m[p][col].abs().hi.total_cmp(&m[q][col].abs().hi))?;
        if m[pivot][col].hi == 0.0 {
            return None;
        }
        m.swap(col, pivot);
        rhs.swap(col, pivot);
        let (done, below) = m.split_at_mut(col + 1);
        let pivot_row = &done[col];
        for (offset, row) in below.iter_mut().enumerate() {
            let factor = row[col] / pivot_row[col];
            if factor.hi != 0.0 {
                for (x, p) in row.iter_mut().zip(pivot_row).skip(col) {
                    *x = *x - factor * *p;
                }
                rhs[col + 1 + offset] = rhs[col + 1 + offset] - factor * rhs[col];
            }
        }
    }
    let mut y = vec![Dd::ZERO; size];
    for row in (0..size).rev() {
        let mut sum = rhs[row];
        for c in row + 1..size {
            sum = sum - m[row][c] * y[c];
        }
        y[row] = sum / m[row][row];
    }
    // The residual a y - 1, in double-double, from the matrix of the original a.
    let mut residual = vec![Dd::ZERO; size];
    residual[0] = Dd::from_f64(-1.0);
    for (i, &ai) in a.iter().enumerate() {
        for (j, yj) in y.iter().enumerate() {
            let (sign, k) = algebra.blade_product(i, j);
            if sign != 0.0 && ai != 0.0 {
                residual[k] = residual[k] + Dd::from_f64(sign * ai) * *yj;
            }
        }
    }
    let residual_sum = residual.iter().map(|r| r.abs().to_f64()).sum();
    Some((y.iter().map(|v| v.to_f64()).collect(), residual_sum))
}
