//! Symmetric 3x3 eigen-decomposition and the rotation-matrix/rotor conversions.
//!
//! The public functions take and return glam's `DMat3` (column-major, the glam that
//! ga-core converts to, re-exported as `ga_rigid::glam`); inside, the solver works on
//! row-major arrays `m[row][column]`. The eigen-solver is the cyclic Jacobi method (Golub
//! & Van Loan, *Matrix Computations*, 4th ed., section 8.5.2; the rotation formulas of
//! Numerical Recipes section 11.1): slow for big matrices but, for 3x3, accurate to a few
//! ulps in every eigenvalue, including repeated ones, and never fails to converge. The
//! matrix-to-rotor conversion is Shepperd's method (Shepperd, "Quaternion from rotation
//! matrix", J. Guidance and Control 1(3), 1978). ga-core has the same conversions
//! (`DMat3::from(r)`, `Rotor::from_mat3`), equal to rounding; these stay because the
//! command prints the inertia's rotor and every row of a simulation to the last digit, and
//! ga-core's versions round differently in that digit.
//!
//! Rotor convention: `R = s + e12 b12 + e13 b13 + e23 b23` acts by `x -> R x ~R`, and
//! `R = cos(t/2) - e12 sin(t/2)` turns e1 into `cos t e1 + sin t e2`. As a unit
//! quaternion `w + x i + y j + z k` acting by `v -> q v q*` this rotor is
//! `(w, x, y, z) = (s, -b23, b13, -b12)`: the rotation by t about the unit axis n is
//! `cos(t/2) - sin(t/2) I n`, and `I n = n1 e23 - n2 e13 + n3 e12`.

use ga_core::f64::g3::Rotor;
use ga_core::glam::DMat3;

/// A 3x3 matrix, `m[row][column]`.
pub(crate) type Matrix3 = [[f64; 3]; 3];

/// Eigenvalues and eigenvectors of a symmetric 3x3 matrix.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SymmetricEigen {
    /// Eigenvalues in ascending order.
    pub values: [f64; 3],
    /// Orthonormal eigenvectors as columns (`vectors.col(k)` belongs to `values[k]`),
    /// forming a proper rotation: the determinant is +1.
    pub vectors: DMat3,
}

/// The most sweeps the solver makes; 3x3 matrices converge in fewer than ten, so this is
/// only a guard against a NaN that compares false forever.
const MAX_SWEEPS: usize = 64;

/// Eigen-decompose the symmetric part of `a` by cyclic Jacobi rotations.
///
/// The values are sorted ascending and the eigenvector matrix is made right-handed
/// (determinant +1) by flipping the last column if needed, so it can be turned into a
/// rotor with [`rotor_from_matrix`]. Repeated eigenvalues (a symmetric top, a sphere)
/// are handled: the solver stops as soon as the off-diagonal part vanishes, and any
/// orthonormal basis of a repeated eigenspace is a valid answer. `a` must be finite.
#[must_use]
pub fn symmetric_eigen(a: &DMat3) -> SymmetricEigen {
    let (values, vectors) = eigen_rows(&to_rows(a));
    SymmetricEigen {
        values,
        vectors: from_rows(&vectors),
    }
}

/// [`symmetric_eigen`] on a row-major array: the ascending eigenvalues and the
/// eigenvector matrix (`vectors[row][k]` belongs to `values[k]`, determinant +1).
#[must_use]
pub(crate) fn eigen_rows(a: &Matrix3) -> ([f64; 3], Matrix3) {
    // Work on the symmetric part so that a slightly asymmetric input (rounding in the
    // caller) cannot make the rotations chase a non-symmetric target.
    let mut m = [[0.0; 3]; 3];
    for (i, row) in m.iter_mut().enumerate() {
        for (j, x) in row.iter_mut().enumerate() {
            *x = 0.5 * (a[i][j] + a[j][i]);
        }
    }
    let mut v = identity();

    for sweep in 0..MAX_SWEEPS {
        let mut rotated = false;
        for (p, q) in [(0, 1), (0, 2), (1, 2)] {
            let apq = m[p][q];
            if apq == 0.0 {
                continue;
            }
            // An off-diagonal entry below an ulp of both diagonal entries cannot change
            // them any more: zero it instead of rotating (Numerical Recipes' test, used
            // from the fourth sweep on so that early sweeps always rotate).
            let small = 100.0 * apq.abs();
            if sweep > 3
                && m[p][p].abs() + small == m[p][p].abs()
                && m[q][q].abs() + small == m[q][q].abs()
            {
                m[p][q] = 0.0;
                m[q][p] = 0.0;
                continue;
            }
            let theta = (m[q][q] - m[p][p]) / (2.0 * apq);
            // t = tan(phi), the smaller root of t^2 + 2 t theta - 1 = 0; for huge theta
            // theta^2 would overflow, and t = 1/(2 theta) is exact to rounding there.
            let t = if theta.abs() > 1e150 {
                0.5 / theta
            } else {
                theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt())
            };
            let c = 1.0 / (t * t + 1.0).sqrt();
            let s = t * c;
            rotate(&mut m, &mut v, p, q, c, s);
            rotated = true;
        }
        if !rotated {
            break;
        }
    }

    let diag = [m[0][0], m[1][1], m[2][2]];
    let mut order = [0usize, 1, 2];
    order.sort_by(|&i, &j| diag[i].total_cmp(&diag[j]));
    let values = [diag[order[0]], diag[order[1]], diag[order[2]]];
    let mut vectors = [[0.0; 3]; 3];
    for (row, vrow) in vectors.iter_mut().enumerate() {
        for (k, &o) in order.iter().enumerate() {
            vrow[k] = v[row][o];
        }
    }
    if determinant(&vectors) < 0.0 {
        for row in &mut vectors {
            row[2] = -row[2];
        }
    }
    (values, vectors)
}

/// Apply the Jacobi rotation P (identity but P_pp = P_qq = c, P_pq = s, P_qp = -s):
/// m <- P^T m P, v <- v P, and set the annihilated entry to an exact zero.
fn rotate(m: &mut Matrix3, v: &mut Matrix3, p: usize, q: usize, c: f64, s: f64) {
    let mut pm = identity();
    pm[p][p] = c;
    pm[q][q] = c;
    pm[p][q] = s;
    pm[q][p] = -s;
    let mp = multiply(m, &pm);
    *m = multiply(&transpose(&pm), &mp);
    m[p][q] = 0.0;
    m[q][p] = 0.0;
    // Re-symmetrise: the two triangles are computed by different sums.
    for (i, j) in [(0, 1), (0, 2), (1, 2)] {
        let x = 0.5 * (m[i][j] + m[j][i]);
        m[i][j] = x;
        m[j][i] = x;
    }
    *v = multiply(v, &pm);
}

/// The 3x3 identity matrix.
#[must_use]
pub(crate) fn identity() -> Matrix3 {
    [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
}

/// The matrix product `a b`.
#[must_use]
pub(crate) fn multiply(a: &Matrix3, b: &Matrix3) -> Matrix3 {
    let mut c = [[0.0; 3]; 3];
    for (i, row) in c.iter_mut().enumerate() {
        for (j, x) in row.iter_mut().enumerate() {
            *x = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
        }
    }
    c
}

/// The transpose of `a`.
#[must_use]
pub(crate) fn transpose(a: &Matrix3) -> Matrix3 {
    let mut t = [[0.0; 3]; 3];
    for (i, row) in t.iter_mut().enumerate() {
        for (j, x) in row.iter_mut().enumerate() {
            *x = a[j][i];
        }
    }
    t
}

/// The determinant of `a`.
#[must_use]
pub(crate) fn determinant(a: &Matrix3) -> f64 {
    a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1])
        - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
        + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0])
}

/// The rotation matrix of a unit rotor: column k is `R e_k ~R`. It agrees with
/// ga-core's `DMat3::from(r)` to rounding (the quaternion formula here, the sandwich
/// there); this is the one the inertia constructors use.
///
/// `r` must be normalised; a rotor of norm n gives n^2 times a rotation.
#[must_use]
pub fn matrix_from_rotor(r: Rotor) -> DMat3 {
    from_rows(&rows_from_rotor(r))
}

/// The unit rotor R with `R e_k ~R` = column k of the proper rotation matrix `m`, by
/// Shepperd's method, returned with a non-negative scalar part. It agrees with ga-core's
/// [`Rotor::from_mat3`] to rounding (the two pick Shepperd's branch by different tests);
/// this is the one the inertia constructors use. `m` must be a rotation (orthonormal,
/// determinant +1) to rounding; [`Rotor::from_matrix`] is the checked form, `None` for a
/// matrix that is not one.
#[must_use]
pub fn rotor_from_matrix(m: &DMat3) -> Rotor {
    rotor_from_rows(&to_rows(m))
}

/// [`matrix_from_rotor`] as a row-major array, by the quaternion formula.
#[must_use]
pub(crate) fn rows_from_rotor(r: Rotor) -> Matrix3 {
    let (w, x, y, z) = (r.s, -r.e23, r.e13, -r.e12);
    [
        [
            1.0 - 2.0 * (y * y + z * z),
            2.0 * (x * y - w * z),
            2.0 * (x * z + w * y),
        ],
        [
            2.0 * (x * y + w * z),
            1.0 - 2.0 * (x * x + z * z),
            2.0 * (y * z - w * x),
        ],
        [
            2.0 * (x * z - w * y),
            2.0 * (y * z + w * x),
            1.0 - 2.0 * (x * x + y * y),
        ],
    ]
}

/// [`rotor_from_matrix`] on a row-major array, by Shepperd's method.
///
/// Shepperd's method takes the square root of the largest of the four quantities
/// 4w^2, 4x^2, 4y^2, 4z^2 (each a signed sum of the trace and diagonal), so it never
/// divides by a small number, unlike the trace-only formula near half turns. `m` must
/// be a rotation (orthonormal, determinant +1) to rounding.
#[must_use]
pub(crate) fn rotor_from_rows(m: &Matrix3) -> Rotor {
    let trace = m[0][0] + m[1][1] + m[2][2];
    let candidates = [trace, m[0][0], m[1][1], m[2][2]];
    let mut largest = 0;
    for k in 1..4 {
        if candidates[k] > candidates[largest] {
            largest = k;
        }
    }
    let (w, x, y, z) = match largest {
        0 => {
            let w = 0.5 * (1.0 + trace).sqrt();
            let f = 0.25 / w;
            (
                w,
                (m[2][1] - m[1][2]) * f,
                (m[0][2] - m[2][0]) * f,
                (m[1][0] - m[0][1]) * f,
            )
        }
        1 => {
            let x = 0.5 * (1.0 + m[0][0] - m[1][1] - m[2][2]).sqrt();
            let f = 0.25 / x;
            (
                (m[2][1] - m[1][2]) * f,
                x,
                (m[0][1] + m[1][0]) * f,
                (m[0][2] + m[2][0]) * f,
            )
        }
        2 => {
            let y = 0.5 * (1.0 - m[0][0] + m[1][1] - m[2][2]).sqrt();
            let f = 0.25 / y;
            (
                (m[0][2] - m[2][0]) * f,
                (m[0][1] + m[1][0]) * f,
                y,
                (m[1][2] + m[2][1]) * f,
            )
        }
        _ => {
            let z = 0.5 * (1.0 - m[0][0] - m[1][1] + m[2][2]).sqrt();
            let f = 0.25 / z;
            (
                (m[1][0] - m[0][1]) * f,
                (m[0][2] + m[2][0]) * f,
                (m[1][2] + m[2][1]) * f,
                z,
            )
        }
    };
    // R and -R are the same rotation: pick s >= 0 so the result is canonical.
    let sign = if w < 0.0 { -1.0 } else { 1.0 };
    let n = sign / (w * w + x * x + y * y + z * z).sqrt();
    Rotor::new(w * n, -z * n, y * n, -x * n)
}

/// glam's column-major `DMat3` as a row-major array (`m[row][column]`), the form the
/// solver and the inertia constructors compute in.
#[must_use]
pub(crate) fn to_rows(m: &DMat3) -> Matrix3 {
    m.transpose().to_cols_array_2d()
}

/// A row-major array (`m[row][column]`) as glam's `DMat3`.
#[must_use]
pub(crate) fn from_rows(m: &Matrix3) -> DMat3 {
    DMat3::from_cols_array_2d(m).transpose()
}

#[cfg(test)]
mod tests {
    use super::*;
    use ga_core::glam::DVec3;

    fn close(a: f64, b: f64, tol: f64) -> bool {
        (a - b).abs() <= tol
    }

    #[test]
    fn rotor_minus_e12_turns_e1_toward_e2() {
        let t: f64 = 0.7;
        let r = Rotor::new((t / 2.0).cos(), -(t / 2.0).sin(), 0.0, 0.0);
        let m = matrix_from_rotor(r);
        assert!(close(m.x_axis.x, t.cos(), 1e-15));
        assert!(close(m.x_axis.y, t.sin(), 1e-15));
        assert!(close(m.x_axis.z, 0.0, 1e-15));
        let back = rotor_from_matrix(&m);
        for (a, b) in back.to_array().iter().zip(r.to_array()) {
            assert!(close(*a, b, 1e-15));
        }
    }

    #[test]
    fn shepperd_handles_half_turns_about_each_axis() {
        let half_turns = [
            Rotor::new(0.0, 1.0, 0.0, 0.0),
            Rotor::new(0.0, 0.0, 1.0, 0.0),
            Rotor::new(0.0, 0.0, 0.0, 1.0),
        ];
        for r in half_turns {
            let back = rotor_from_matrix(&matrix_from_rotor(r));
            // -R is R; compare up to sign.
            let d: f64 = back
                .to_array()
                .iter()
                .zip(r.to_array())
                .map(|(a, b)| (a - b).abs())
                .sum();
            let d_neg: f64 = back
                .to_array()
                .iter()
                .zip(r.to_array())
                .map(|(a, b)| (a + b).abs())
                .sum();
            assert!(d.min(d_neg) < 1e-15);
        }
    }

    #[test]
    fn eigen_of_diagonal_is_sorted_and_exact() {
        let e = symmetric_eigen(&DMat3::from_diagonal(DVec3::new(3.0, 1.0, 2.0)));
        assert_eq!(e.values, [1.0, 2.0, 3.0]);
        assert!(close(e.vectors.determinant(), 1.0, 1e-15));
        assert!(close(determinant(&to_rows(&e.vectors)), 1.0, 1e-15));
    }

    #[test]
    fn rows_are_glam_rows_and_round_trip() {
        let m = DMat3::from_cols(
            DVec3::new(1.0, 2.0, 3.0),
            DVec3::new(4.0, 5.0, 6.0),
            DVec3::new(7.0, 8.0, 9.0),
        );
        let rows = to_rows(&m);
        assert_eq!(rows, [[1.0, 4.0, 7.0], [2.0, 5.0, 8.0], [3.0, 6.0, 9.0]]);
        for (r, row) in rows.iter().enumerate() {
            assert_eq!(*row, m.row(r).to_array());
        }
        assert_eq!(from_rows(&rows), m);
    }
}
