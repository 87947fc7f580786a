//! Shared by the integrator and symmetric-top tests: the scenes of docs/references.md as test
//! models, error measures, and the MATRIX REFERENCE, an independent solution of Euler's
//! equations that shares no code with the library.
//!
//! The reference integrates the textbook matrix form
//!
//! ```text
//! dM/dt = M [w]x,      J dw/dt = (J w) x w + tau,      tau = c x (M^T (mass g))
//! ```
//!
//! (`M` maps body to space; `tau` is the heavy top's gravity couple, linear in `M`) with
//! the Taylor-series method: the right-hand side is bilinear in `(M, w)`, so the Taylor
//! coefficients follow from Cauchy products (`y_{k+1} = (1/(k+1)) sum_j B(y_j, y_{k-j})`),
//! and a series of order 30 with the step of Jorba and Zou (Experiment. Math. 14, 2005)
//! reaches rounding-level accuracy per step. Its conventions are checked against the
//! published values of docs/references.md in `tests/integrators.rs`.

// Each test binary uses a different part of this module.
#![allow(dead_code)]
// Index loops over 3x3 matrices and Taylor coefficients read like the formulas.
#![allow(clippy::needless_range_loop)]

use ga_core::f64::g3::*;
use ga_rigid::dynamics::{omega_from_vector, RigidBody, State};

/// A 3x3 matrix, rows first.
pub type Matrix = [[f64; 3]; 3];

/// A free rigid body and its initial body momentum, with `R(0) = 1`.
#[derive(Clone, Copy, Debug)]
pub struct Scene {
    /// The scene's name in docs/references.md.
    pub name: &'static str,
    /// Principal moments.
    pub moments: [f64; 3],
    /// Body angular momentum `m(0) = J w(0)`.
    pub m0: [f64; 3],
}

/// Hairer, Lubich, Wanner: m(10) and R(10) published.
pub const HLW: Scene = Scene {
    name: "Hairer-Lubich-Wanner",
    moments: [2.0, 1.0, 2.0 / 3.0],
    m0: [0.453_596_121_425_577_3, 0.0, 0.891_207_360_061_435_4],
};
/// Hairer-Vilmart DMV driver: m(10) and R(10) published.
pub const HAIRER_VILMART: Scene = Scene {
    name: "Hairer-Vilmart",
    moments: [0.6, 0.8, 1.0],
    m0: [1.8, 0.4, -0.9],
};
/// Hairer-Nørsett-Wanner EULR without its forcing: m(20) published.
pub const EULR: Scene = Scene {
    name: "EULR",
    moments: [0.5, 2.0, 3.0],
    m0: [0.5, 0.0, 2.7],
};
/// Principia's Dzhanibekov scene, close to the separatrix: m(100) published.
pub const DZHANIBEKOV: Scene = Scene {
    name: "Dzhanibekov",
    moments: [3.0, 5.0, 9.0],
    m0: [0.0, 2.0, 0.01],
};
/// Principia's symmetric "short fat" top.
pub const SHORT_FAT: Scene = Scene {
    name: "short fat",
    moments: [3.0, 3.0, 9.0],
    m0: [0.0, 5.0, 7.0],
};
/// A needle spinning fast about its axis: 16.65 rad per step at h = 1/60.
pub const NEEDLE: Scene = Scene {
    name: "needle",
    moments: [1.0, 1.0, 1e-3],
    m0: [0.01, 0.0, 1.0],
};

/// docs/references.md: HLW m(10).
pub const HLW_M10: [f64; 3] = [0.407_066_136_588, 0.283_007_426_813, 0.868_449_167_662];
/// docs/references.md: HLW R(10) as [s, e12, e13, e23].
pub const HLW_R10: [f64; 4] = [
    0.765_111_030_829,
    -0.513_722_699_054,
    0.102_854_131_455,
    -0.374_319_551_483,
];
/// docs/references.md: Hairer-Vilmart m(10).
pub const HV_M10: [f64; 3] = [1.765_962_508_518, -0.695_464_197_033, 0.779_554_981_482];
/// docs/references.md: Hairer-Vilmart R(10).
pub const HV_R10: [f64; 4] = [
    0.736_061_364_161,
    -0.206_839_086_105,
    0.299_388_571_831,
    -0.570_786_951_240,
];
/// docs/references.md: EULR m(20).
pub const EULR_M20: [f64; 3] = [0.303_101_926_982, 1.257_494_420_900, 2.422_155_445_727];
/// docs/references.md: Dzhanibekov m(100).
pub const DZHANIBEKOV_M100: [f64; 3] = [0.209_094_262_834, 1.972_485_481_093, 0.256_282_297_721];

/// A scene the library can run, and how its attitude relates to the original's.
///
/// `RigidBody::new` refuses moments that break the triangle inequality, as HLW's
/// (2, 1, 2/3), Dzhanibekov's (3, 5, 9) and the short fat top's (3, 3, 9) do. Adding the
/// same `shift` to every inverse moment leaves `dm/dt = m x J^-1 m` unchanged (`m x m = 0`)
/// and, for a large enough shift, gives valid moments; the attitude then differs by a
/// turn about the constant space momentum `L`: `R_original(t) = exp(shift t (I L)/2) R(t)`.
#[derive(Clone, Copy, Debug)]
pub struct Runnable {
    /// The scene with valid moments (the original when it already has them).
    pub scene: Scene,
    /// The shift added to every inverse moment (0 when none was needed).
    pub shift: f64,
}

impl Runnable {
    /// The original scene's attitude at `t` from the runnable scene's (R(0) = 1).
    pub fn original_rotor(&self, rotor: Rotor, t: f64) -> Rotor {
        (omega_from_vector(self.scene.m0) * (0.5 * self.shift * t)).exp() * rotor
    }
}

impl Scene {
    /// This scene, or one with shifted inverse moments and the same `m(t)` that
    /// `RigidBody::new` accepts (see [`Runnable`]).
    pub fn runnable(&self) -> Runnable {
        if RigidBody::new(self.moments).is_ok() {
            return Runnable {
                scene: *self,
                shift: 0.0,
            };
        }
        let inverse = self.moments.map(|i| 1.0 / i);
        let mut shift = inverse.iter().copied().fold(f64::INFINITY, f64::min);
        loop {
            let moments = inverse.map(|a| 1.0 / (a + shift));
            if RigidBody::new(moments).is_ok() {
                return Runnable {
                    scene: Scene { moments, ..*self },
                    shift,
                };
            }
            shift *= 2.0;
        }
    }

    /// `w(0) = J^-1 m(0)`.
    pub fn w0(&self) -> [f64; 3] {
        std::array::from_fn(|k| self.m0[k] / self.moments[k])
    }

    /// The library's body.
    pub fn body(&self) -> RigidBody {
        RigidBody::new(self.moments).expect("scene moments are valid")
    }

    /// The library's initial state, `R(0) = 1`.
    pub fn state(&self) -> State {
        State {
            rotor: Rotor::ONE,
            omega: omega_from_vector(self.w0()),
        }
    }

    /// The matrix reference at each of `times` (ascending, from t = 0).
    pub fn reference(&self, times: &[f64]) -> Vec<Solution> {
        reference(self.moments, IDENTITY, self.w0(), None, times)
    }
}

/// The heavy top's gravity couple `tau = c x (M^T (mass g))` in the reference's terms.
#[derive(Clone, Copy, Debug)]
pub struct HeavyTop {
    /// The body's mass.
    pub mass: f64,
    /// Gravity in the space frame.
    pub g: [f64; 3],
    /// The centre of mass from the pivot, body frame.
    pub com: [f64; 3],
}

/// A point of the reference solution.
#[derive(Clone, Copy, Debug)]
pub struct Solution {
    /// Time.
    pub t: f64,
    /// The attitude matrix, body to space.
    pub matrix: Matrix,
    /// The body angular velocity.
    pub w: [f64; 3],
    /// The body angular momentum `J w`.
    pub m: [f64; 3],
}

impl Solution {
    /// The attitude as a rotor `[s, e12, e13, e23]` with `s >= 0`.
    pub fn rotor(&self) -> Rotor {
        let r = rotor_from_matrix(&self.matrix);
        Rotor::new(r[0], r[1], r[2], r[3])
    }
}

/// The identity matrix.
pub const IDENTITY: Matrix = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];

/// Taylor order of the reference.
const ORDER: usize = 30;

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// `M [w]x`: column c is `M (w x e_c)`.
fn matrix_times_cross(m: &Matrix, w: [f64; 3]) -> Matrix {
    let mut out = [[0.0; 3]; 3];
    for c in 0..3 {
        let mut e = [0.0; 3];
        e[c] = 1.0;
        let v = cross(w, e);
        for r in 0..3 {
            out[r][c] = m[r][0] * v[0] + m[r][1] * v[1] + m[r][2] * v[2];
        }
    }
    out
}

fn norm_matrix(m: &Matrix) -> f64 {
    m.iter().flatten().map(|x| x * x).sum::<f64>().sqrt()
}

fn norm3(v: [f64; 3]) -> f64 {
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
}

/// Euler's equations in matrix form from `(matrix0, w0)` at t = 0, sampled at `times`.
pub fn reference(
    moments: [f64; 3],
    matrix0: Matrix,
    w0: [f64; 3],
    heavy: Option<HeavyTop>,
    times: &[f64],
) -> Vec<Solution> {
    let mut out = Vec::with_capacity(times.len());
    let (mut t, mut m, mut w) = (0.0_f64, matrix0, w0);
    let mut ms = vec![[[0.0; 3]; 3]; ORDER + 1];
    let mut ws = vec![[0.0; 3]; ORDER + 1];
    for &target in times {
        assert!(target >= t, "reference times must ascend");
        while t < target {
            // Taylor coefficients by Cauchy products of the bilinear right-hand side.
            ms[0] = m;
            ws[0] = w;
            for k in 0..ORDER {
                let mut dm = [[0.0; 3]; 3];
                let mut jdw = [0.0; 3];
                for j in 0..=k {
                    let p = matrix_times_cross(&ms[j], ws[k - j]);
                    for r in 0..3 {
                        for c in 0..3 {
                            dm[r][c] += p[r][c];
                        }
                    }
                    let jw: [f64; 3] = std::array::from_fn(|i| moments[i] * ws[j][i]);
                    let g = cross(jw, ws[k - j]);
                    for i in 0..3 {
                        jdw[i] += g[i];
                    }
                }
                if let Some(top) = heavy {
                    // tau_k = c x (M_k^T (mass g)), linear in M.
                    let f: [f64; 3] = std::array::from_fn(|c| {
                        (0..3).map(|r| ms[k][r][c] * top.mass * top.g[r]).sum()
                    });
                    let tau = cross(top.com, f);
                    for i in 0..3 {
                        jdw[i] += tau[i];
                    }
                }
                let scale = 1.0 / (k + 1) as f64;
                for r in 0..3 {
                    for c in 0..3 {
                        ms[k + 1][r][c] = dm[r][c] * scale;
                    }
                }
                ws[k + 1] = std::array::from_fn(|i| jdw[i] * scale / moments[i]);
            }
            // Jorba-Zou step from the last two coefficients, for M and w apart.
            let eps = 1e-17;
            let w_scale = norm3(w).max(1e-300);
            let mut h = target - t;
            for k in [ORDER - 1, ORDER] {
                let bound_m = (eps / norm_matrix(&ms[k]).max(1e-300)).powf(1.0 / k as f64);
                let bound_w = (eps * w_scale / norm3(ws[k]).max(1e-300)).powf(1.0 / k as f64);
                h = h.min(bound_m).min(bound_w);
            }
            // Horner.
            let mut m_next = ms[ORDER];
            let mut w_next = ws[ORDER];
            for k in (0..ORDER).rev() {
                for r in 0..3 {
                    for c in 0..3 {
                        m_next[r][c] = m_next[r][c] * h + ms[k][r][c];
                    }
                }
                w_next = std::array::from_fn(|i| w_next[i] * h + ws[k][i]);
            }
            m = m_next;
            w = w_next;
            t = if h == target - t { target } else { t + h };
        }
        out.push(Solution {
            t: target,
            matrix: m,
            w,
            m: std::array::from_fn(|i| moments[i] * w[i]),
        });
    }
    out
}

/// Shepperd's method: the unit rotor `[s, e12, e13, e23]`, `s >= 0`, of a rotation matrix.
/// A quaternion `(w, x, y, z)` is the rotor `w - z e12 + y e13 - x e23` (I n = n1 e23 -
/// n2 e13 + n3 e12, and R = cos - I n sin).
pub fn rotor_from_matrix(m: &Matrix) -> [f64; 4] {
    let trace = m[0][0] + m[1][1] + m[2][2];
    let (w, x, y, z);
    if trace >= m[0][0] && trace >= m[1][1] && trace >= m[2][2] {
        let s = 2.0 * (1.0 + trace).sqrt();
        w = s / 4.0;
        x = (m[2][1] - m[1][2]) / s;
        y = (m[0][2] - m[2][0]) / s;
        z = (m[1][0] - m[0][1]) / s;
    } else if m[0][0] >= m[1][1] && m[0][0] >= m[2][2] {
        let s = 2.0 * (1.0 + m[0][0] - m[1][1] - m[2][2]).sqrt();
        x = s / 4.0;
        w = (m[2][1] - m[1][2]) / s;
        y = (m[0][1] + m[1][0]) / s;
        z = (m[0][2] + m[2][0]) / s;
    } else if m[1][1] >= m[2][2] {
        let s = 2.0 * (1.0 - m[0][0] + m[1][1] - m[2][2]).sqrt();
        y = s / 4.0;
        w = (m[0][2] - m[2][0]) / s;
        x = (m[0][1] + m[1][0]) / s;
        z = (m[1][2] + m[2][1]) / s;
    } else {
        let s = 2.0 * (1.0 - m[0][0] - m[1][1] + m[2][2]).sqrt();
        z = s / 4.0;
        w = (m[1][0] - m[0][1]) / s;
        x = (m[0][2] + m[2][0]) / s;
        y = (m[1][2] + m[2][1]) / s;
    }
    let sign = if w < 0.0 { -1.0 } else { 1.0 };
    let n = (w * w + x * x + y * y + z * z).sqrt() * sign;
    [w / n, -z / n, y / n, -x / n]
}

/// The rotation matrix of a unit rotor `[s, e12, e13, e23]` (the inverse of
/// [`rotor_from_matrix`]), by the textbook quaternion formula.
pub fn matrix_from_rotor(r: [f64; 4]) -> Matrix {
    let (w, x, y, z) = (r[0], -r[3], r[2], -r[1]);
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

/// The attitude error in radians: `D = ~R_ref R`, `2 atan2(|<D>_2|, |<D>_0|)`.
pub fn attitude_error(rotor: Rotor, reference: Rotor) -> f64 {
    let d = reference.reverse() * rotor;
    let b = (d.e12 * d.e12 + d.e13 * d.e13 + d.e23 * d.e23).sqrt();
    2.0 * b.atan2(d.s.abs())
}

/// `|a - b|` for 3-vectors.
pub fn distance(a: [f64; 3], b: [f64; 3]) -> f64 {
    norm3([a[0] - b[0], a[1] - b[1], a[2] - b[2]])
}

/// The body momentum `m = J w` of a library state.
pub fn momentum(body: &RigidBody, state: &State) -> [f64; 3] {
    let m = body.body_momentum(state.omega);
    [m.e23, -m.e13, m.e12]
}

/// `|R ~R - 1|` of a rotor.
pub fn unit_defect(r: Rotor) -> f64 {
    (r.s * r.s + r.e12 * r.e12 + r.e13 * r.e13 + r.e23 * r.e23 - 1.0).abs()
}

/// A rotor as `[s, e12, e13, e23]`.
pub fn rotor_array(r: Rotor) -> [f64; 4] {
    [r.s, r.e12, r.e13, r.e23]
}

/// The least-squares slope of `log(error)` against `log(h)`.
pub fn fitted_order(steps: &[f64], errors: &[f64]) -> f64 {
    let n = steps.len() as f64;
    let xs: Vec<f64> = steps.iter().map(|h| h.ln()).collect();
    let ys: Vec<f64> = errors.iter().map(|e| e.ln()).collect();
    let (mx, my) = (xs.iter().sum::<f64>() / n, ys.iter().sum::<f64>() / n);
    let sxy: f64 = xs.iter().zip(&ys).map(|(x, y)| (x - mx) * (y - my)).sum();
    let sxx: f64 = xs.iter().map(|x| (x - mx) * (x - mx)).sum();
    sxy / sxx
}
