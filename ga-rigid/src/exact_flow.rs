//! The exact flow of the free rigid body: body angular momentum by Jacobi elliptic
//! functions, attitude by an elliptic integral of the third kind.
//!
//! After E. Celledoni, F. Fassò, N. Säfström and A. Zanna, "The exact computation of the
//! free rigid body motion and its use in splitting methods", SIAM J. Sci. Comput. 30(4)
//! (2008) 2084-2112. Their published formulas carry sign and copy errors (documented by
//! later implementers, e.g. Principia's tests), so the attitude here is derived afresh;
//! the derivation is summarised below and checked in `tests/exact_flow.rs` against an
//! independent integration of Euler's equations in matrix form.
//!
//! # Conventions
//! Rotors are `[s, e12, e13, e23]` and act by `y = R x ~R`, body to space, with
//! `dR/dt = -1/2 R Omega_B`, `Omega_B = I w`. Internally they are unit quaternions
//! `(w, x, y, z) = (s, -e23, e13, -e12)`, for which the same equation reads
//! `dq/dt = 1/2 q w`. The body angular momentum is `m = J w`, `J = diag(i1, i2, i3)`,
//! and obeys `dm/dt = m x w`.
//!
//! # Derivation
//! Time is first rescaled so that |m| = 1 and the largest moment is 1 (the equations are
//! homogeneous: `m(t) = |m| u(|m| t)`). Bodies with two equal moments use the closed form
//! of the symmetric top, `R(t) = exp(-Omega_l t / 2) R(0) exp(-Omega_r t / 2)` (Doran &
//! Lasenby, "Physical Applications of Geometric Algebra", Cambridge, 1999, lecture 3);
//! spheres and rotations about a principal axis are a constant body angular velocity.
//!
//! Otherwise the body axes are permuted by a proper rotation into a work frame whose
//! axis 3 is the one the momentum orbit encircles (its component never changes sign),
//! with `u3 > 0` and `u1 >= 0`. With `j_ab = i_a - i_b` in that frame and the
//! cancellation-free combinations `d1 = u2^2 j21/i2 + u3^2 j31/i3 = 1 - 2E i1`,
//! `d3 = u1^2 j31/i1 + u2^2 j32/i2 = 2E i3 - 1` and `d2 = 2E i2 - 1` (the one difference
//! that decides the case), the momentum is (Landau & Lifshitz, Mechanics, section 37)
//! `u = (b1 cn tau, b2 sn tau, b3 dn tau)`, `tau = tau0 + omega t`, with
//! `b1^2 = d3 i1/j31`, `b2^2 = d3 i2/j32`, `b3^2 = d1 i3/j31`,
//! `omega^2 = j32 d1/(i1 i2 i3)` (omega < 0 when axis 3 has the smallest moment),
//! parameter `m = j21 d3/(j32 d1)` and complementary parameter
//! `1 - m = -j31 d2/(j32 d1)`, a product, so it keeps full precision near the separatrix.
//! On the separatrix itself (`d2 = 0`) sn, cn, dn become tanh, sech, sech.
//!
//! For the attitude, write the body-to-space rotation as
//! `M(t) = B Rz(psi(t)) A(u(t))`, where `A(u)` is the shortest-arc rotation taking `u` to
//! `e3` (smooth because `u3 > 0`) and `B` is constant. Differentiating `M' = M [w]x`
//! gives `psi' = w.u - (1 - u3) alpha'` with `alpha = atan2(u2, u1)`, which splits as
//! `psi = Phi - alpha + const`, `Phi' = 1/i3 + (2E - 1/i3)/(1 - u3^2)`. On the orbit,
//! `1 - u3^2 = (i1 d3/j31)(1 - n sn^2 tau)` with `n = -i3 j21/(i1 j32) < 0`, so
//! `Phi(t) = t/i3 + j31/(i1 i3 omega) [G(tau) - G(tau0)]`,
//! `G(tau) = integral_0^tau dv/(1 - n sn^2 v) = Pi(n; am tau | m)`, which has no pole
//! since `n < 0` (on the separatrix it is elementary). `alpha` is read from the
//! parametrisation as `atan2(b2 sn, b1 cn)` with the common factor `sqrt(d3)` removed,
//! so it stays defined for a rotation about axis 3 itself.
//!
//! # Nearly equal moments
//! Exactly equal moments take the closed forms. Otherwise a gap `j21` or `j32` may be
//! tiny, and the general solution divides by `j32`, but only in quotients the case
//! bounds: when `j32` is small the orbit encircles axis 3 only if `u1^2 <= u3^2 j32 i1 /
//! (i3 j21)`, so `d3 / j32` stays finite. For a nearly symmetric body this is the thin
//! band of orbits near the plane of the two close moments, where the momentum moves
//! slowly (`omega ~ sqrt(gap)`) while the body spins fast; there `n ~ -1/gap`, and
//! `Pi(n)` is evaluated through the characteristic `m/n` (see
//! [`crate::special::elliptic::ellip_pi_jacobi`]) so that `Phi` and `alpha`, each of
//! which turns quickly as the orbit passes the pole, keep full relative precision.

use crate::special::elliptic::{carlson_rf, ellip_k, ellip_pi_jacobi, jacobi};

/// A unit quaternion `(w, x, y, z)` rotating by `v -> q v q*`.
type Quat = [f64; 4];

/// The exact free-rigid-body flow: attitude and body angular momentum at time `t`.
///
/// `moments` are the principal moments `(i1, i2, i3)` (all positive), `m0` the body
/// angular momentum `J w` at time 0, `r0` the attitude rotor `[s, e12, e13, e23]` at time
/// 0 (normalised here; it acts `y = R x ~R`, body to space) and `t` any real time. Returns
/// `(R(t), m(t))`. Works for every body: symmetric and spherical bodies in closed form,
/// nearly symmetric ones and states on or near the separatrix through the elliptic
/// solution. Non-positive or non-finite inputs, or a zero rotor, give NaN; never panics.
#[must_use]
pub fn exact_free_body(
    moments: [f64; 3],
    m0: [f64; 3],
    r0: [f64; 4],
    t: f64,
) -> ([f64; 4], [f64; 3]) {
    let nan = ([f64::NAN; 4], [f64::NAN; 3]);
    let finite = |v: &[f64]| v.iter().all(|x| x.is_finite());
    let positive = moments.iter().all(|&i| i > 0.0);
    if !(positive && finite(&moments) && finite(&m0) && finite(&r0) && t.is_finite()) {
        return nan;
    }
    let Some(q0) = normalize(rotor_to_quat(r0)) else {
        return nan;
    };
    let size = m0[0].hypot(m0[1]).hypot(m0[2]);
    if size == 0.0 || t == 0.0 {
        return (quat_to_rotor(q0), m0);
    }
    let scale = moments[0].max(moments[1]).max(moments[2]);
    let inertia = moments.map(|i| i / scale);
    let u0 = m0.map(|x| x / size);
    // Time in units where |m| = 1 and the largest moment is 1.
    let time = size * (t / scale);
    let (q, u) = unit_flow(inertia, u0, q0, time);
    (quat_to_rotor(q), u.map(|x| x * size))
}

/// Energy, elliptic parameter and period of the body-momentum orbit of a free body.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FreeBodyOrbit {
    /// Kinetic energy `E = 1/2 m . J^-1 m`.
    pub energy: f64,
    /// Elliptic parameter `m = k^2` of the Jacobi functions in `m(t)` (0 for symmetric
    /// bodies, spheres and bodies at rest, 1 on the separatrix).
    pub parameter: f64,
    /// Complementary parameter `1 - m`, computed without cancellation.
    pub complementary_parameter: f64,
    /// Period of `m(t)`: `4 K / |omega|` in general, the precession period for a
    /// symmetric body, infinity on the separatrix and for a constant `m`.
    pub period: f64,
}

/// Energy, elliptic parameter and period of the momentum orbit through `m0`.
///
/// Same preconditions as [`exact_free_body`]; invalid input gives NaN fields.
#[must_use]
pub fn free_body_orbit(moments: [f64; 3], m0: [f64; 3]) -> FreeBodyOrbit {
    let nan = FreeBodyOrbit {
        energy: f64::NAN,
        parameter: f64::NAN,
        complementary_parameter: f64::NAN,
        period: f64::NAN,
    };
    if !(moments.iter().all(|&i| i > 0.0 && i.is_finite()) && m0.iter().all(|x| x.is_finite())) {
        return nan;
    }
    let energy = 0.5 * (0..3).map(|k| m0[k] * m0[k] / moments[k]).sum::<f64>();
    let constant = FreeBodyOrbit {
        energy,
        parameter: 0.0,
        complementary_parameter: 1.0,
        period: f64::INFINITY,
    };
    let size = m0[0].hypot(m0[1]).hypot(m0[2]);
    if size == 0.0 {
        return constant;
    }
    let scale = moments[0].max(moments[1]).max(moments[2]);
    let inertia = moments.map(|i| i / scale);
    let u = m0.map(|x| x / size);
    // Converts a rate in rescaled time into one in real time.
    let rate = size / scale;
    match classify(inertia, u) {
        Body::Sphere | Body::Stationary => constant,
        Body::Symmetric(axis) => {
            let spin = symmetric_spin(inertia, u, axis) * rate;
            FreeBodyOrbit {
                period: if spin == 0.0 {
                    f64::INFINITY
                } else {
                    2.0 * std::f64::consts::PI / spin.abs()
                },
                ..constant
            }
        }
        Body::General(frame) => {
            let orbit = Orbit::new(&frame);
            FreeBodyOrbit {
                energy,
                parameter: orbit.k2,
                complementary_parameter: orbit.kc2,
                period: 4.0 * ellip_k(orbit.kc2) / (orbit.omega.abs() * rate),
            }
        }
    }
}

/// Which closed form or elliptic case a (unit-momentum, rescaled) body falls into.
enum Body {
    /// All moments equal: the body angular velocity is constant.
    Sphere,
    /// Two moments equal: the symmetric top about the given axis.
    Symmetric(usize),
    /// The momentum lies exactly on a principal axis: a steady rotation.
    Stationary,
    /// Distinct moments: the elliptic solution in the given work frame.
    General(WorkFrame),
}

/// The body expressed in the work frame of the elliptic solution.
struct WorkFrame {
    /// The proper rotation from body to work coordinates, `x_work = C x_body`.
    c: Quat,
    /// `perm[k]` is the body axis that becomes work axis k.
    perm: [usize; 3],
    /// `sign[k]` multiplies that body coordinate.
    sign: [f64; 3],
    /// Moments in work order.
    i: [f64; 3],
    /// Unit momentum in work coordinates: `u[2] > 0`, `u[0] >= 0`.
    u: [f64; 3],
    /// `d2 = 2E i_mid - 1` computed once as a difference of two non-negative terms;
    /// exactly 0 on the separatrix.
    d2: f64,
}

/// Sort the axes and decide the case; the separatrix test uses the same two products
/// that give `d2`, so `d2 == 0` exactly when the case is the separatrix.
fn classify(i: [f64; 3], u: [f64; 3]) -> Body {
    if i[0] == i[1] && i[1] == i[2] {
        return Body::Sphere;
    }
    if i[0] == i[1] {
        return Body::Symmetric(2);
    }
    if i[1] == i[2] {
        return Body::Symmetric(0);
    }
    if i[0] == i[2] {
        return Body::Symmetric(1);
    }
    if u.iter().filter(|&&x| x == 0.0).count() == 2 {
        return Body::Stationary;
    }
    let mut order = [0, 1, 2];
    order.sort_by(|&a, &b| i[a].total_cmp(&i[b]));
    let [lo, mid, hi] = order;
    // 2E i_mid - 1 = u_lo^2 (i_mid - i_lo)/i_lo - u_hi^2 (i_hi - i_mid)/i_hi: the sign
    // says which extreme axis the orbit encircles.
    let t_lo = u[lo] * u[lo] * ((i[mid] - i[lo]) / i[lo]);
    let t_hi = u[hi] * u[hi] * ((i[hi] - i[mid]) / i[hi]);
    let d2 = t_lo - t_hi;
    let (first, third) = if d2 <= 0.0 { (lo, hi) } else { (hi, lo) };
    Body::General(WorkFrame::new(i, u, [first, mid, third], d2))
}

impl WorkFrame {
    /// Build the signed permutation taking body axes `perm` to work axes 1, 2, 3 with
    /// determinant +1, `u3 > 0` and `u1 >= 0`.
    fn new(i: [f64; 3], u: [f64; 3], perm: [usize; 3], d2: f64) -> Self {
        let sign_of = |x: f64| if x < 0.0 { -1.0 } else { 1.0 };
        let s1 = sign_of(u[perm[0]]);
        let s3 = sign_of(u[perm[2]]);
        // Parity of the permutation: even permutations of (0, 1, 2) are the rotations.
        let even = matches!(perm, [0, 1, 2] | [1, 2, 0] | [2, 0, 1]);
        let s2 = s1 * s3 * if even { 1.0 } else { -1.0 };
        let sign = [s1, s2, s3];
        let mut mat = [[0.0; 3]; 3];
        for k in 0..3 {
            mat[k][perm[k]] = sign[k];
        }
        WorkFrame {
            c: quat_from_matrix(&mat),
            perm,
            sign,
            i: perm.map(|a| i[a]),
            u: [0, 1, 2].map(|k| sign[k] * u[perm[k]]),
            d2,
        }
    }

    /// Body coordinates of a work-frame vector.
    fn to_body(&self, v: [f64; 3]) -> [f64; 3] {
        let mut out = [0.0; 3];
        for k in 0..3 {
            out[self.perm[k]] = self.sign[k] * v[k];
        }
        out
    }
}

/// The constants of the elliptic solution in the work frame (see the module docs).
struct Orbit {
    /// Moments in work order.
    i: [f64; 3],
    /// Parameter m = k^2.
    k2: f64,
    /// Complementary parameter 1 - m; 0 on the separatrix.
    kc2: f64,
    /// Rate of the Jacobi argument, negative when axis 3 has the smallest moment.
    omega: f64,
    /// Amplitudes of u = (b1 cn, b2 sn, b3 dn).
    b: [f64; 3],
    /// `(b1, b2) / sqrt(|d3|)`: the shape of the ellipse, defined even when d3 = 0.
    rho: [f64; 2],
    /// Characteristic of the third-kind integral, `-i3 j21 / (i1 j32) < 0`.
    n: f64,
    /// Coefficient of `G(tau)` in `Phi`, `j31 / (i1 i3 omega)`.
    phi_coef: f64,
}

impl Orbit {
    /// Every ratio below is a quotient of same-signed factors (all positive when axis 3
    /// has the largest moment, pairs of negatives when it has the smallest), so `abs`
    /// only removes signs that cancel.
    fn new(f: &WorkFrame) -> Self {
        let [i1, i2, i3] = f.i;
        let [u1, u2, u3] = f.u;
        let (j21, j32, j31) = (i2 - i1, i3 - i2, i3 - i1);
        let d1 = u2 * u2 * (j21 / i2) + u3 * u3 * (j31 / i3);
        let d3 = u1 * u1 * (j31 / i1) + u2 * u2 * (j32 / i2);
        let k2 = ((j21 / j32) * (d3 / d1)).clamp(0.0, 1.0);
        let kc2 = (-(j31 / j32) * (f.d2 / d1)).clamp(0.0, 1.0);
        let omega = ((j32 / i2) * (d1 / (i1 * i3))).abs().sqrt() * j31.signum();
        let rho = [(i1 / j31).abs().sqrt(), (i2 / j32).abs().sqrt()];
        let sd3 = d3.abs().sqrt();
        let b = [sd3 * rho[0], sd3 * rho[1], (d1 * (i3 / j31)).abs().sqrt()];
        let n = -(i3 / i1) * (j21 / j32);
        let phi_coef = j31 / (i1 * i3 * omega);
        Orbit {
            i: f.i,
            k2,
            kc2,
            omega,
            b,
            rho,
            n,
            phi_coef,
        }
    }

    /// The Jacobi argument at which the orbit passes through `u` (with `u1 >= 0`, so it
    /// lies in [-K, K]), together with the normalised (sn, cn) there.
    fn phase(&self, u: [f64; 3]) -> Option<(f64, f64, f64)> {
        // (sn, cn) is proportional to (u2 / b2, u1 / b1), i.e. to (u2 rho1, u1 rho2).
        let (ps, pc) = (u[1] * self.rho[0], u[0] * self.rho[1]);
        let h = ps.hypot(pc);
        let (s, c) = if h == 0.0 {
            (0.0, 1.0)
        } else {
            (ps / h, pc / h)
        };
        let tau = if self.kc2 == 0.0 {
            if c == 0.0 {
                return None;
            }
            (s / c).asinh()
        } else {
            let c2 = c * c;
            s * carlson_rf(c2, self.k2.mul_add(c2, self.kc2), 1.0)
        };
        Some((tau, s, c))
    }

    /// The azimuth of `u = (b1 cn, b2 sn, .)` about axis 3, without the factor sqrt(d3).
    fn azimuth(&self, sn: f64, cn: f64) -> f64 {
        (self.rho[1] * sn).atan2(self.rho[0] * cn)
    }

    /// `G(tau) = integral_0^tau dv / (1 - n sn^2 v)`.
    fn g(&self, tau: f64) -> f64 {
        ellip_pi_jacobi(self.n, tau, self.k2, self.kc2)
    }
}

/// The flow with |u| = 1 and rescaled time `t`.
fn unit_flow(i: [f64; 3], u0: [f64; 3], q0: Quat, t: f64) -> (Quat, [f64; 3]) {
    match classify(i, u0) {
        Body::Sphere | Body::Stationary => {
            let w = [0, 1, 2].map(|k| u0[k] / i[k]);
            (qmul(q0, qexp(w, t)), u0)
        }
        Body::Symmetric(axis) => symmetric_flow(i, u0, q0, t, axis),
        Body::General(frame) => general_flow(&frame, q0, t),
    }
}

/// Spin rate `c = u_s (i_p - i_s) / (i_s i_p)` of the body frame about the symmetry
/// axis `s`, relative to the precession about the momentum.
fn symmetric_spin(i: [f64; 3], u: [f64; 3], axis: usize) -> f64 {
    let ip = i[(axis + 1) % 3];
    let is = i[axis];
    u[axis] * ((ip - is) / (is * ip))
}

/// The symmetric top: `q(t) = exp(l t / (2 i_p)) q0 exp(c e_s t / 2)` with `l` the space
/// momentum, the quaternion form of `R(t) = exp(-Omega_l t/2) R(0) exp(-Omega_r t/2)`;
/// the body momentum turns about `e_s` by `-c t`.
fn symmetric_flow(i: [f64; 3], u0: [f64; 3], q0: Quat, t: f64, axis: usize) -> (Quat, [f64; 3]) {
    let ip = i[(axis + 1) % 3];
    let spin = symmetric_spin(i, u0, axis);
    let l = rotate(q0, u0);
    let mut e = [0.0; 3];
    e[axis] = spin;
    let q = qmul(qmul(qexp(l, t / ip), q0), qexp(e, t));
    // Body momentum: rotate u0 about e_s by angle -spin t.
    let (a, b) = ((axis + 1) % 3, (axis + 2) % 3);
    let (sn, cs) = (-spin * t).sin_cos();
    let mut u = u0;
    u[a] = cs * u0[a] - sn * u0[b];
    u[b] = sn * u0[a] + cs * u0[b];
    (q, u)
}

/// The elliptic solution in the work frame, mapped back to body coordinates.
fn general_flow(frame: &WorkFrame, q0: Quat, t: f64) -> (Quat, [f64; 3]) {
    let orbit = Orbit::new(frame);
    let Some((tau0, s0, c0)) = orbit.phase(frame.u) else {
        // Only reachable with an exact zero where the algebra says none can be: fall back
        // to the steady rotation it approximates.
        let w = [0, 1, 2].map(|k| frame.u[k] / orbit.i[k]);
        let qw = qmul(qmul(q0, qconj(frame.c)), qexp(w, t));
        return (qmul(qw, frame.c), frame.to_body(frame.u));
    };
    let tau = orbit.omega.mul_add(t, tau0);
    let (sn, cn, dn) = jacobi(tau, orbit.k2, orbit.kc2);
    let u = [orbit.b[0] * cn, orbit.b[1] * sn, orbit.b[2] * dn];
    let phi = t / orbit.i[2] + orbit.phi_coef * (orbit.g(tau) - orbit.g(tau0));
    let psi = phi - orbit.azimuth(sn, cn) + orbit.azimuth(s0, c0);
    // Work-frame attitude: q'(t) = q'(0) A(u0)* Rz(psi) A(u(t)).
    let qw0 = qmul(q0, qconj(frame.c));
    let qw = qmul(
        qmul(
            qmul(qw0, qconj(to_pole(frame.u))),
            qexp([0.0, 0.0, 1.0], psi),
        ),
        to_pole(u),
    );
    (qmul(qw, frame.c), frame.to_body(u))
}

/// The shortest-arc rotation taking the unit vector `u` (with `u3 > -1`) to `e3`:
/// `(1 + u3, u x e3) / sqrt(2 (1 + u3))`, renormalised so that a slightly non-unit `u`
/// still gives a unit quaternion.
fn to_pole(u: [f64; 3]) -> Quat {
    let q = [1.0 + u[2], u[1], -u[0], 0.0];
    normalize(q).unwrap_or([1.0, 0.0, 0.0, 0.0])
}

/// `exp(v t / 2)` for a pure quaternion `v`: the rotation by angle `|v| t` about `v`.
fn qexp(v: [f64; 3], t: f64) -> Quat {
    let size = v[0].hypot(v[1]).hypot(v[2]);
    if size == 0.0 {
        return [1.0, 0.0, 0.0, 0.0];
    }
    let (s, c) = (0.5 * size * t).sin_cos();
    let f = s / size;
    [c, f * v[0], f * v[1], f * v[2]]
}

/// Hamilton product `a b`.
fn qmul(a: Quat, b: Quat) -> Quat {
    [
        a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
        a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
        a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
        a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0],
    ]
}

/// Conjugate (the inverse of a unit quaternion).
fn qconj(q: Quat) -> Quat {
    [q[0], -q[1], -q[2], -q[3]]
}

/// `q v q*` for a unit quaternion.
fn rotate(q: Quat, v: [f64; 3]) -> [f64; 3] {
    let r = qmul(qmul(q, [0.0, v[0], v[1], v[2]]), qconj(q));
    [r[1], r[2], r[3]]
}

/// `q / |q|`, or `None` for a zero quaternion.
fn normalize(q: Quat) -> Option<Quat> {
    let size = q[0].hypot(q[1]).hypot(q[2].hypot(q[3]));
    if size == 0.0 || !size.is_finite() {
        return None;
    }
    Some(q.map(|x| x / size))
}

/// Rotor `[s, e12, e13, e23]` to quaternion `(s, -e23, e13, -e12)`.
fn rotor_to_quat(r: [f64; 4]) -> Quat {
    [r[0], -r[3], r[2], -r[1]]
}

/// Quaternion `(w, x, y, z)` to rotor `[w, -z, y, -x]`.
fn quat_to_rotor(q: Quat) -> [f64; 4] {
    [q[0], -q[3], q[2], -q[1]]
}

/// The quaternion of a proper rotation matrix `m[row][col]` by Shepperd's method
/// (pivot on the largest of the trace and the diagonal), exact for the signed
/// permutations used here.
fn quat_from_matrix(m: &[[f64; 3]; 3]) -> Quat {
    let tr = m[0][0] + m[1][1] + m[2][2];
    let q = if tr >= m[0][0] && tr >= m[1][1] && tr >= m[2][2] {
        let s = 2.0 * (1.0 + tr).sqrt();
        [
            0.25 * s,
            (m[2][1] - m[1][2]) / s,
            (m[0][2] - m[2][0]) / s,
            (m[1][0] - m[0][1]) / s,
        ]
    } else if m[0][0] >= m[1][1] && m[0][0] >= m[2][2] {
        let s = 2.0 * (1.0 + m[0][0] - m[1][1] - m[2][2]).sqrt();
        [
            (m[2][1] - m[1][2]) / s,
            0.25 * s,
            (m[0][1] + m[1][0]) / s,
            (m[0][2] + m[2][0]) / s,
        ]
    } else if m[1][1] >= m[2][2] {
        let s = 2.0 * (1.0 + m[1][1] - m[0][0] - m[2][2]).sqrt();
        [
            (m[0][2] - m[2][0]) / s,
            (m[0][1] + m[1][0]) / s,
            0.25 * s,
            (m[1][2] + m[2][1]) / s,
        ]
    } else {
        let s = 2.0 * (1.0 + m[2][2] - m[0][0] - m[1][1]).sqrt();
        [
            (m[1][0] - m[0][1]) / s,
            (m[0][2] + m[2][0]) / s,
            (m[1][2] + m[2][1]) / s,
            0.25 * s,
        ]
    };
    normalize(q).unwrap_or([1.0, 0.0, 0.0, 0.0])
}
