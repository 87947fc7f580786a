//! The principal frame of an `n x n` second-moment matrix, `n <= 4`: the cyclic Jacobi
//! eigen-solver (Golub & Van Loan, *Matrix Computations*, 4th ed., section 8.5.2; the
//! rotation formulas of Numerical Recipes, section 11.1), as `crate::inertia` uses for
//! 3x3, and the rotor of the eigenvector frame built from Householder reflections
//! (Cartan-Dieudonne: a rotation of R^n is a product of at most `n` reflections, and the
//! reflection `x -> -v x v` of a unit vector `v` makes the rotor `v1 v2 ... vm`).

// The matrix kernels index rows and columns by name, as the formulas they transcribe do.
#![allow(clippy::needless_range_loop)]

use super::algebra::{Algebra, MAX_DIMENSION};

/// A square matrix of size up to 4, `m[row][column]`; only the leading `n x n` block is
/// read.
pub type Matrix = [[f64; MAX_DIMENSION]; MAX_DIMENSION];

/// The most sweeps the solver makes (4x4 matrices converge in fewer than ten): a guard
/// against a NaN that compares false forever.
const MAX_SWEEPS: usize = 64;

/// The eigenvalues (ascending) and orthonormal eigenvectors (as columns, a proper
/// rotation: determinant +1) of the symmetric leading `n x n` block of `a`.
#[must_use]
pub fn symmetric_eigen(a: &Matrix, n: usize) -> ([f64; MAX_DIMENSION], Matrix) {
    let mut a = *a;
    let mut v = identity();
    for _ in 0..MAX_SWEEPS {
        let off: f64 = (0..n)
            .flat_map(|p| (p + 1..n).map(move |q| (p, q)))
            .map(|(p, q)| a[p][q] * a[p][q])
            .sum();
        let scale: f64 = (0..n).map(|i| a[i][i] * a[i][i]).sum::<f64>() + off;
        if off <= f64::EPSILON * f64::EPSILON * scale || off == 0.0 || off.is_nan() {
            break;
        }
        for p in 0..n {
            for q in p + 1..n {
                if a[p][q] == 0.0 {
                    continue;
                }
                // The rotation that zeroes a[p][q] (Numerical Recipes 11.1.8-11.1.10).
                let theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
                let t = theta.signum() / (theta.abs() + theta.hypot(1.0));
                let c = 1.0 / t.hypot(1.0);
                let s = t * c;
                for k in 0..n {
                    let (akp, akq) = (a[k][p], a[k][q]);
                    a[k][p] = c * akp - s * akq;
                    a[k][q] = s * akp + c * akq;
                }
                for k in 0..n {
                    let (apk, aqk) = (a[p][k], a[q][k]);
                    a[p][k] = c * apk - s * aqk;
                    a[q][k] = s * apk + c * aqk;
                }
                for row in v.iter_mut().take(n) {
                    let (vkp, vkq) = (row[p], row[q]);
                    row[p] = c * vkp - s * vkq;
                    row[q] = s * vkp + c * vkq;
                }
            }
        }
    }
    // Sort ascending, carrying the eigenvector columns along.
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by(|&i, &j| a[i][i].total_cmp(&a[j][j]));
    let mut values = [0.0; MAX_DIMENSION];
    let mut vectors = [[0.0; MAX_DIMENSION]; MAX_DIMENSION];
    for (new, &old) in order.iter().enumerate() {
        values[new] = a[old][old];
        for r in 0..n {
            vectors[r][new] = v[r][old];
        }
    }
    if determinant(&vectors, n) < 0.0 {
        for row in vectors.iter_mut().take(n) {
            row[n - 1] = -row[n - 1];
        }
    }
    (values, vectors)
}

/// The identity matrix.
fn identity() -> Matrix {
    let mut m = [[0.0; MAX_DIMENSION]; MAX_DIMENSION];
    for (i, row) in m.iter_mut().enumerate() {
        row[i] = 1.0;
    }
    m
}

/// The determinant of the leading `n x n` block, by Gaussian elimination with pivoting.
fn determinant(m: &Matrix, n: usize) -> f64 {
    let mut a = *m;
    let mut det = 1.0;
    for c in 0..n {
        let pivot = (c..n)
            .max_by(|&i, &j| a[i][c].abs().total_cmp(&a[j][c].abs()))
            .unwrap_or(c);
        if a[pivot][c] == 0.0 {
            return 0.0;
        }
        if pivot != c {
            a.swap(pivot, c);
            det = -det;
        }
        det *= a[c][c];
        for r in c + 1..n {
            let f = a[r][c] / a[c][c];
            for k in c..n {
                a[r][k] -= f * a[c][k];
            }
        }
    }
    det
}

/// The rotor `R` with `R e_k ~R = q e_k` (the columns of `q`) for a proper rotation `q`
/// (orthogonal, determinant +1) of the algebra's dimension.
///
/// Householder reflections `H_k` take column `k` of `H_(k-1) ... H_1 q` to `e_k`; then `q`
/// is the product `H_1 ... H_m` and, as each reflection is `x -> -v x v`, the rotor is
/// `v_1 ... v_m` (m is even because the determinant is +1). The difference `x - e_k` is
/// formed without cancellation: `1 - x_k = (sum_(j>k) x_j^2) / (1 + x_k)` for a unit `x`.
#[must_use]
pub fn rotor_from_matrix<A: Algebra>(q: &Matrix) -> A::Rotor {
    let n = A::DIMENSION;
    let mut m = *q;
    let mut vectors: Vec<[f64; MAX_DIMENSION]> = Vec::with_capacity(n);
    for k in 0..n {
        let x: Vec<f64> = (0..n).map(|r| m[r][k]).collect();
        let tail: f64 = x[k + 1..].iter().map(|v| v * v).sum();
        if tail == 0.0 && x[k] > 0.0 {
            continue;
        }
        let mut v = [0.0; MAX_DIMENSION];
        v[..n].copy_from_slice(&x);
        v[k] = if x[k] > 0.0 {
            -tail / (1.0 + x[k])
        } else {
            x[k] - 1.0
        };
        let size = v.iter().map(|c| c * c).sum::<f64>().sqrt();
        let v = v.map(|c| c / size);
        // m <- (1 - 2 v v^T) m
        for c in 0..n {
            let dot: f64 = (0..n).map(|r| v[r] * m[r][c]).sum();
            for r in 0..n {
                m[r][c] -= 2.0 * v[r] * dot;
            }
        }
        vectors.push(v);
    }
    // An even number of reflections for a proper rotation; an odd one (an improper input)
    // leaves the last vector out.
    vectors.chunks_exact(2).fold(A::ONE, |rotor, pair| {
        rotor * A::vector_product(pair[0], pair[1])
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::nd::{G2, G3, G4};

    fn check_eigen(a: &Matrix, n: usize) {
        let (values, v) = symmetric_eigen(a, n);
        for k in 0..n {
            for r in 0..n {
                let av: f64 = (0..n).map(|c| a[r][c] * v[c][k]).sum();
                assert!(
                    (av - values[k] * v[r][k]).abs() < 1e-14,
                    "A v = l v at {r}, {k}"
                );
            }
            for j in 0..n {
                let dot: f64 = (0..n).map(|r| v[r][k] * v[r][j]).sum();
                let expected = if j == k { 1.0 } else { 0.0 };
                assert!(
                    (dot - expected).abs() < 1e-15,
                    "orthonormal columns {k}, {j}"
                );
            }
        }
        assert!(values[..n].windows(2).all(|w| w[0] <= w[1]));
        assert!((determinant(&v, n) - 1.0).abs() < 1e-14);
    }

    #[test]
    fn jacobi_diagonalises_symmetric_matrices_of_each_size() {
        let a = [
            [2.0, 0.3, -0.4, 0.1],
            [0.3, 1.5, 0.2, -0.7],
            [-0.4, 0.2, 0.9, 0.5],
            [0.1, -0.7, 0.5, 3.0],
        ];
        for n in 2..=4 {
            check_eigen(&a, n);
        }
        // A repeated eigenvalue.
        check_eigen(&identity(), 4);
    }

    /// The matrix of a rotor, turned back into a rotor, is the rotor up to sign.
    fn round_trip<A: Algebra>(r: A::Rotor) {
        let n = A::DIMENSION;
        let mut q = [[0.0; MAX_DIMENSION]; MAX_DIMENSION];
        for k in 0..n {
            let mut e = [0.0; MAX_DIMENSION];
            e[k] = 1.0;
            let y = A::rotate(r, e);
            for (row, yr) in q.iter_mut().zip(y) {
                row[k] = yr;
            }
        }
        let back = rotor_from_matrix::<A>(&q);
        let plus = A::rotor_norm(back - r);
        let minus = A::rotor_norm(back + r);
        assert!(plus.min(minus) < 1e-14, "{back:?} vs {r:?}");
    }

    #[test]
    fn rotor_from_matrix_inverts_the_rotor_matrix() {
        round_trip::<G2>(G2::exp(G2::bivector(&[1.1])));
        round_trip::<G2>(G2::exp(G2::bivector(&[3.0])));
        round_trip::<G3>(G3::exp(G3::bivector(&[0.3, -1.2, 0.8])));
        round_trip::<G3>(G3::ONE);
        round_trip::<G4>(G4::exp(G4::bivector(&[0.3, -1.2, 0.8, 0.4, -0.9, 1.3])));
        round_trip::<G4>(G4::exp(G4::bivector(&[1.5, 0.0, 0.0, 0.0, 0.0, 1.5])));
        round_trip::<G4>(G4::exp(G4::bivector(&[3.1, 0.0, 0.0, 0.0, 0.0, 0.0])));
        round_trip::<G4>(G4::ONE);
    }
}
