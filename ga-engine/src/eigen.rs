//! A symmetric 3x3 tensor's principal moments and frame, once per body, in f64.
//!
//! A port of ga-rigid's `inertia::symmetric_eigen` (its cyclic Jacobi method: Golub & Van
//! Loan, *Matrix Computations*, 4th ed., section 8.5.2) that needs no standard library:
//! square roots from `libm`, no sorting, and a diagonal input left exactly as it is (the
//! frame is then the identity; the steps skip it where the moments also do not decrease
//! from x to z, see `Body::from_tensor`). The eigenvector matrix is made
//! right-handed by flipping its last column, then turned into a quaternion by
//! Shepperd's method (Shepperd, J. Guidance and Control 1(3), 1978).

/// `m[row][column]`.
type M3 = [[f64; 3]; 3];

/// The most sweeps: 3x3 matrices converge in fewer than ten; this only stops a loop on
/// values no comparison can settle.
const MAX_SWEEPS: usize = 64;

/// The principal moments `d` and the unit quaternion `[x, y, z, w]` of the rotation `P`
/// (principal axes to the tensor's frame, `A = P diag(d) P^T`), and whether `P` is the
/// identity (the input was diagonal). `a` must be finite; its symmetric part is used.
pub(crate) fn principal_axes(a: &M3) -> ([f64; 3], [f64; 4], bool) {
    let mut m = [[0.0; 3]; 3];
    for (i, row) in m.iter_mut().enumerate() {
        for (j, x) in row.iter_mut().enumerate() {
            *x = 0.5 * (a[i][j] + a[j][i]);
        }
    }
    if m[0][1] == 0.0 && m[0][2] == 0.0 && m[1][2] == 0.0 {
        return ([m[0][0], m[1][1], m[2][2]], [0.0, 0.0, 0.0, 1.0], true);
    }
    let mut v = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    for sweep in 0..MAX_SWEEPS {
        let mut rotated = false;
        for (p, q) in [(0, 1), (0, 2), (1, 2)] {
            let apq = m[p][q];
            if apq == 0.0 {
                continue;
            }
            // An entry below an ulp of both diagonal entries can no longer change them:
            // zero it (Numerical Recipes' test, from the fourth sweep on).
            let small = 100.0 * libm::fabs(apq);
            if sweep > 3
                && libm::fabs(m[p][p]) + small == libm::fabs(m[p][p])
                && libm::fabs(m[q][q]) + small == libm::fabs(m[q][q])
            {
                m[p][q] = 0.0;
                m[q][p] = 0.0;
                continue;
            }
            let theta = (m[q][q] - m[p][p]) / (2.0 * apq);
            // t = tan(phi), the smaller root of t^2 + 2 t theta - 1 = 0; 1/(2 theta) where
            // theta^2 would overflow.
            let t = if libm::fabs(theta) > 1e150 {
                0.5 / theta
            } else {
                let sign = if theta < 0.0 { -1.0 } else { 1.0 };
                sign / (libm::fabs(theta) + libm::sqrt(theta * theta + 1.0))
            };
            let c = 1.0 / libm::sqrt(t * t + 1.0);
            let s = t * c;
            jacobi_rotate(&mut m, &mut v, p, q, c, s);
            rotated = true;
        }
        if !rotated {
            break;
        }
    }
    if determinant(&v) < 0.0 {
        for row in &mut v {
            row[2] = -row[2];
        }
    }
    ([m[0][0], m[1][1], m[2][2]], quaternion_of(&v), false)
}

/// `m <- P^T m P`, `v <- v P` for the rotation `P` in the plane `(p, q)`, the annihilated
/// entries set to an exact zero and the two triangles averaged.
fn jacobi_rotate(m: &mut M3, v: &mut M3, p: usize, q: usize, c: f64, s: f64) {
    let mut r = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    r[p][p] = c;
    r[q][q] = c;
    r[p][q] = s;
    r[q][p] = -s;
    let mr = multiply(m, &r);
    *m = multiply(&transpose(&r), &mr);
    m[p][q] = 0.0;
    m[q][p] = 0.0;
    for (i, j) in [(0, 1), (0, 2), (1, 2)] {
        let x = 0.5 * (m[i][j] + m[j][i]);
        m[i][j] = x;
        m[j][i] = x;
    }
    *v = multiply(v, &r);
}

/// `a b`.
fn multiply(a: &M3, b: &M3) -> M3 {
    let mut c = [[0.0; 3]; 3];
    for (i, row) in c.iter_mut().enumerate() {
        for (j, x) in row.iter_mut().enumerate() {
            *x = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
        }
    }
    c
}

/// `a^T`.
fn transpose(a: &M3) -> M3 {
    let mut t = [[0.0; 3]; 3];
    for (i, row) in t.iter_mut().enumerate() {
        for (j, x) in row.iter_mut().enumerate() {
            *x = a[j][i];
        }
    }
    t
}

/// `det a`.
fn determinant(a: &M3) -> f64 {
    a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1])
        - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
        + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0])
}

/// The unit quaternion `[x, y, z, w]` turning `e_k` into column `k` of the rotation `m`
/// (Shepperd: the square root of the largest of 4w^2, 4x^2, 4y^2, 4z^2), `w >= 0`.
pub(crate) fn quaternion_of(m: &M3) -> [f64; 4] {
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
            let w = 0.5 * libm::sqrt(1.0 + trace);
            let f = 0.25 / w;
            (
                w,
                (m[2][1] - m[1][2]) * f,
                (m[0][2] - m[2][0]) * f,
                (m[1][0] - m[0][1]) * f,
            )
        }
        1 => {
            let x = 0.5 * libm::sqrt(1.0 + m[0][0] - m[1][1] - m[2][2]);
            let f = 0.25 / x;
            (
                (m[2][1] - m[1][2]) * f,
                x,
                (m[0][1] + m[1][0]) * f,
                (m[0][2] + m[2][0]) * f,
            )
        }
        2 => {
            let y = 0.5 * libm::sqrt(1.0 - m[0][0] + m[1][1] - m[2][2]);
            let f = 0.25 / y;
            (
                (m[0][2] - m[2][0]) * f,
                (m[0][1] + m[1][0]) * f,
                y,
                (m[1][2] + m[2][1]) * f,
            )
        }
        _ => {
            let z = 0.5 * libm::sqrt(1.0 - m[0][0] - m[1][1] + m[2][2]);
            let f = 0.25 / z;
            (
                (m[1][0] - m[0][1]) * f,
                (m[0][2] + m[2][0]) * f,
                (m[1][2] + m[2][1]) * f,
                z,
            )
        }
    };
    let sign = if w < 0.0 { -1.0 } else { 1.0 };
    let n = sign / libm::sqrt(w * w + x * x + y * y + z * z);
    [x * n, y * n, z * n, w * n]
}
