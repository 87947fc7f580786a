//! Jacobi elliptic functions, the elliptic integrals of the first and third kinds, and
//! Carlson's symmetric integrals RF, RD and RJ.
//!
//! Every function that depends on the parameter `m` also takes the complementary
//! parameter `m1 = 1 - m`. Near `m = 1` (the separatrix of the free rigid body) the
//! interesting quantity is `m1`, and forming it as `1.0 - m` would leave only the few
//! digits that survive the cancellation; callers who can compute `m1` as a product
//! (see [`crate::exact_flow`]) keep it to full relative precision.
//!
//! Methods:
//! - `sn, cn, dn`: the descending Gauss (Landen) transformation driven by the
//!   arithmetic-geometric mean, Abramowitz & Stegun 16.12 and 16.4, run on the ratio
//!   `cs = cn / sn` as in Bulirsch, "Numerical calculation of elliptic integrals and
//!   elliptic functions", Numer. Math. 7 (1965), so that `cn` keeps its relative
//!   precision where it is small. The argument is first reduced to `|u| <= K / 2` with
//!   the quarter-period shifts of A&S 16.8.
//! - `K`: the arithmetic-geometric mean, `K = pi / (2 AGM(1, sqrt(m1)))` (A&S 17.6).
//! - `F`, `Pi` and the integrals: Carlson's duplication algorithm, B. C. Carlson,
//!   "Numerical computation of real or complex elliptic integrals", Numer. Algorithms 10
//!   (1995) 13-26, with the reductions of DLMF 19.25.5 and 19.25.14.

use std::f64::consts::{FRAC_PI_2, PI};

/// Cap on Carlson's duplication steps; they converge in well under 40 steps for every
/// finite input, so this only stops a NaN from looping forever.
const MAX_STEPS: usize = 100;

/// Carlson's stopping factors `(3 r)^(-1/6)` for RF and `(r / 4)^(-1/6)` for RD and RJ
/// with error parameter r = 1e-16 (Carlson 1995, eqs. 2.2 and 2.18): the truncated
/// series are then accurate to about r.
const CARLSON_RF_FACTOR: f64 = 386.497_293_934_345_75;
/// See [`CARLSON_RF_FACTOR`].
const CARLSON_RJ_FACTOR: f64 = 584.803_547_642_573;

/// Below this argument sn(u) = u, cn(u) = dn(u) = 1 to double precision: the first
/// corrections are (1 + m) u^2 / 6 and u^2 / 2, both under 1e-18.
const TINY_ARGUMENT: f64 = 1e-9;

/// The Landen descent stops when the modulus k_n = c_n / a_n is below this: the
/// neglected terms are O(k_n^2) = 1e-20.
const LANDEN_STOP: f64 = 1e-10;

/// Clamp a parameter into [0, 1]; NaN stays NaN.
fn clamp_unit(m: f64) -> f64 {
    m.clamp(0.0, 1.0)
}

/// Most AGM steps kept: from `b0 = sqrt(m1)` as small as 2e-162 (the smallest positive
/// `m1`) the modulus `c_n / a_n` falls below [`LANDEN_STOP`] in about 15 steps.
const AGM_CAPACITY: usize = 32;

/// The arithmetic-geometric mean table of A&S 16.4 started from
/// `(a0, b0, c0) = (1, sqrt(m1), sqrt(m))`, on the stack.
///
/// `c` is carried by `c_n = c_{n-1}^2 / (4 a_n)` rather than `(a_{n-1} - b_{n-1}) / 2`,
/// which would lose every digit as the means converge.
struct Agm {
    a: [f64; AGM_CAPACITY],
    b: [f64; AGM_CAPACITY],
    c: [f64; AGM_CAPACITY],
    /// Index of the last filled entry, N.
    top: usize,
}

impl Agm {
    /// Build the table; requires `m1 > 0` (for `m1 = 0` the means converge to zero).
    fn new(m: f64, m1: f64) -> Self {
        let mut agm = Agm {
            a: [0.0; AGM_CAPACITY],
            b: [0.0; AGM_CAPACITY],
            c: [0.0; AGM_CAPACITY],
            top: 0,
        };
        agm.a[0] = 1.0;
        agm.b[0] = m1.sqrt();
        agm.c[0] = m.sqrt();
        while agm.top + 1 < AGM_CAPACITY {
            let n = agm.top;
            if agm.c[n].is_nan() || agm.c[n] <= LANDEN_STOP * agm.a[n] {
                break;
            }
            let an = 0.5 * (agm.a[n] + agm.b[n]);
            agm.a[n + 1] = an;
            agm.b[n + 1] = (agm.a[n] * agm.b[n]).sqrt();
            agm.c[n + 1] = 0.25 * agm.c[n] * agm.c[n] / an;
            agm.top = n + 1;
        }
        agm
    }

    /// The complete integral K = pi / (2 a_N).
    fn k(&self) -> f64 {
        FRAC_PI_2 / self.a[self.top]
    }
}

/// (sn, cn, dn)(x) for |x| <= K / 2, by the descending Gauss transformation on cs = cn/sn.
///
/// With k_n = c_n / a_n, one descent step is (A&S 16.12.2-4)
/// `cs(u | k_{n-1}) = cs(v | k_n) dn(v | k_n) / (1 + k_n)` and
/// `dn(u | k_{n-1}) = (1 - k_n sn^2(v | k_n)) / (1 + k_n sn^2(v | k_n))`, `v = u a_n / a_{n-1}`,
/// and at the bottom k_N is negligible, so cs = cot(x a_N). Both `1 + k_n = a_{n-1} / a_n`
/// and `1 - k_n = b_{n-1} / a_n` are exact ratios, free of cancellation when k_n is near 1.
fn jacobi_small(x: f64, agm: &Agm) -> (f64, f64, f64) {
    if x.abs() < TINY_ARGUMENT {
        return (x, 1.0, 1.0);
    }
    let top = agm.top;
    let (a, b, c) = (&agm.a, &agm.b, &agm.c);
    let v = x.abs() * a[top];
    let (s, co) = v.sin_cos();
    let mut cs = co / s;
    let kn = c[top] / a[top];
    let mut dn = (1.0 - kn * kn * s * s).sqrt();
    for n in (1..=top).rev() {
        let sn2 = 1.0 / (1.0 + cs * cs);
        let cn2 = cs * cs * sn2;
        let next_cs = cs * dn * a[n] / a[n - 1];
        dn = (b[n - 1] + c[n] * cn2) / (a[n] + c[n] * sn2);
        cs = next_cs;
    }
    let sn = 1.0 / (1.0 + cs * cs).sqrt();
    let cn = cs * sn;
    // dn^2 = m1 + m cn^2 has no cancellation and makes dn consistent with cn; the value
    // from the descent agrees to rounding.
    let dn = b[0].mul_add(b[0], c[0] * c[0] * cn * cn).sqrt();
    (sn.copysign(x), cn, dn)
}

/// Jacobi elliptic functions `(sn, cn, dn)(u | m)`, given `m` and `m1 = 1 - m`.
///
/// `m` and `m1` are clamped into [0, 1]; pass `m1` computed without cancellation when
/// `m` is near 1. `m = 0` gives (sin, cos, 1) and `m1 = 0` gives (tanh, sech, sech).
/// Accurate to a few ulps in absolute terms, and `cn`, `dn` keep their relative
/// precision near the quarter period where they are small. Non-finite `u` gives NaN.
#[must_use]
pub fn jacobi(u: f64, m: f64, m1: f64) -> (f64, f64, f64) {
    let (m, m1) = (clamp_unit(m), clamp_unit(m1));
    if u.is_nan() || m.is_nan() || m1.is_nan() {
        return (f64::NAN, f64::NAN, f64::NAN);
    }
    if m == 0.0 {
        let (s, c) = u.sin_cos();
        return (s, c, 1.0);
    }
    if m1 == 0.0 {
        let sech = 1.0 / u.cosh();
        return (u.tanh(), sech, sech);
    }
    if !u.is_finite() {
        return (f64::NAN, f64::NAN, f64::NAN);
    }
    let agm = Agm::new(m, m1);
    let (r, flip) = reduce(u, agm.k());
    let (sn, cn, dn) = jacobi_reduced(r, &agm, m1.sqrt());
    if flip {
        (-sn, -cn, dn)
    } else {
        (sn, cn, dn)
    }
}

/// Reduce `u` by multiples of the half period 2K: returns `r` in [-K, K] and whether the
/// multiple is odd (sn and cn change sign under u -> u + 2K, A&S 16.8.2).
fn reduce(u: f64, k: f64) -> (f64, bool) {
    let (r, j) = reduce_count(u, k);
    (r, j % 2.0 != 0.0)
}

/// Like [`reduce`], returning the multiple `j` of 2K itself (as a float, exact up to 2^53).
fn reduce_count(u: f64, k: f64) -> (f64, f64) {
    let j = (u / (2.0 * k)).round();
    if j == 0.0 {
        return (u, 0.0);
    }
    ((-j).mul_add(2.0 * k, u), j)
}

/// (sn, cn, dn)(r) for |r| <= K (a little beyond is tolerated), via the quarter-period
/// shift `sn(K - y) = cd y`, `cn(K - y) = k' sd y`, `dn(K - y) = k' nd y` (A&S 16.8.1)
/// when |r| > K/2; the shift keeps cn and dn relatively accurate near K where they are
/// small.
fn jacobi_reduced(r: f64, agm: &Agm, kc: f64) -> (f64, f64, f64) {
    let k = agm.k();
    if r.abs() <= 0.5 * k {
        return jacobi_small(r, agm);
    }
    let y = k - r.abs();
    let (sy, cy, dy) = jacobi_small(y, agm);
    ((cy / dy).copysign(r), kc * sy / dy, kc / dy)
}

/// The complete elliptic integral of the first kind K(m), given `m1 = 1 - m`.
///
/// Computed by the arithmetic-geometric mean, `K = pi / (2 AGM(1, sqrt(m1)))`; `m1 = 0`
/// gives infinity and `m1 > 1` (that is m < 0) is allowed. Negative or NaN `m1` gives NaN.
#[must_use]
pub fn ellip_k(m1: f64) -> f64 {
    if m1.is_nan() || m1 < 0.0 {
        return f64::NAN;
    }
    if m1 == 0.0 {
        return f64::INFINITY;
    }
    if m1 == f64::INFINITY {
        return 0.0;
    }
    // Only `a` and `b` matter for K; `c0 = sqrt|1 - m1|` just drives the stopping test,
    // which holds for m1 > 1 too.
    Agm::new((1.0 - m1).abs(), m1).k()
}

/// The incomplete elliptic integral of the first kind F(phi | m), given `m1 = 1 - m`.
///
/// `F(phi | m) = sin(phi) RF(cos^2 phi, m1 + m cos^2 phi, 1)` for |phi| <= pi/2 (DLMF
/// 19.25.5, with `1 - m sin^2 = m1 + m cos^2` to avoid cancellation), extended by
/// `F(phi + j pi) = F(phi) + 2 j K`. `m` and `m1` are clamped into [0, 1].
#[must_use]
pub fn ellip_f(phi: f64, m: f64, m1: f64) -> f64 {
    let (m, m1) = (clamp_unit(m), clamp_unit(m1));
    let j = (phi / PI).round();
    let r = if j == 0.0 { phi } else { (-j).mul_add(PI, phi) };
    let (s, c) = r.sin_cos();
    let c2 = c * c;
    let base = if m1 == 0.0 {
        // The separatrix: F(phi | 1) = asinh(tan phi), infinite at phi = pi/2.
        (s / c).asinh()
    } else {
        s * carlson_rf(c2, m.mul_add(c2, m1), 1.0)
    };
    if j == 0.0 {
        base
    } else {
        2.0 * j * ellip_k(m1) + base
    }
}

/// The incomplete elliptic integral of the third kind
/// `Pi(n; phi | m) = integral_0^phi dt / ((1 - n sin^2 t) sqrt(1 - m sin^2 t))`,
/// given `m1 = 1 - m`, for characteristic `n < 1`.
///
/// `Pi = s RF(c^2, d^2, 1) + (n/3) s^3 RJ(c^2, d^2, 1, 1 - n s^2)` with `s = sin phi`,
/// `c = cos phi`, `d^2 = m1 + m c^2` (DLMF 19.25.14), extended by
/// `Pi(n; phi + j pi) = Pi(n; phi) + 2 j Pi(n | m)`. `n >= 1` (a Cauchy principal value)
/// is not supported and gives NaN; `m1 = 0` with |phi| >= pi/2 gives infinity. For
/// `n < -1` the characteristic is exchanged for `m/n` (DLMF 19.7.9), which avoids the
/// cancellation of the first form when Pi is much smaller than F.
#[must_use]
pub fn ellip_pi(n: f64, phi: f64, m: f64, m1: f64) -> f64 {
    let (m, m1) = (clamp_unit(m), clamp_unit(m1));
    if n.is_nan() || n >= 1.0 || !phi.is_finite() {
        return f64::NAN;
    }
    let j = (phi / PI).round();
    let r = if j == 0.0 { phi } else { (-j).mul_add(PI, phi) };
    let (s, c) = r.sin_cos();
    let base = pi_from_sn(n, s, c, m.mul_add(c * c, m1), m);
    if j == 0.0 {
        base
    } else {
        2.0 * j * complete_pi(n, m, m1) + base
    }
}

/// `integral_0^phi dt / ((1 - n sin^2 t) sqrt(1 - m sin^2 t))` from `s = sin phi`,
/// `c = cos phi >= 0` and `d2 = 1 - m s^2`, for |phi| <= pi/2.
///
/// For `n >= -1` this is DLMF 19.25.14, `s RF + (n/3) s^3 RJ`. For `n < -1` the two
/// terms of that form nearly cancel (Pi is O(1/sqrt(-n)) while each term is O(F)), so
/// the characteristic is swapped for `w = m/n`, small, by DLMF 19.7.9:
/// `Pi(n) = F - Pi(w) + sqrt(c) RC(...)`, where `F - Pi(w) = -(w/3) s^3 RJ(.., 1 - w s^2)`
/// and, by homogeneity of RC, the last term is `s RC(c^2 d^2, (1 - n s^2)(1 - w s^2))`.
/// Every term then keeps its relative precision.
fn pi_from_sn(n: f64, s: f64, c: f64, d2: f64, m: f64) -> f64 {
    let c2 = c * c;
    let s2 = s * s;
    if n < -1.0 {
        let w = m / n;
        let p = (-w).mul_add(s2, 1.0);
        let elementary = s * carlson_rc(c2 * d2, (-n).mul_add(s2, 1.0) * p);
        if w == 0.0 {
            return elementary;
        }
        return elementary - w / 3.0 * s * s2 * carlson_rj(c2, d2, 1.0, p);
    }
    let rf = carlson_rf(c2, d2, 1.0);
    if n == 0.0 {
        return s * rf;
    }
    s * rf + n / 3.0 * s * s2 * carlson_rj(c2, d2, 1.0, (-n).mul_add(s2, 1.0))
}

/// The complete integral of the third kind `Pi(n | m) = RF(0, m1, 1) + (n/3) RJ(0, m1, 1, 1 - n)`,
/// or for `n < -1`, as in [`pi_from_sn`],
/// `-(w/3) RJ(0, m1, 1, 1 - w) + pi / (2 sqrt((1 - n)(1 - w)))` with `w = m/n`.
fn complete_pi(n: f64, m: f64, m1: f64) -> f64 {
    if m1 == 0.0 {
        return f64::INFINITY;
    }
    if n < -1.0 {
        let w = m / n;
        let elementary = FRAC_PI_2 / ((1.0 - n) * (1.0 - w)).sqrt();
        if w == 0.0 {
            return elementary;
        }
        return elementary - w / 3.0 * carlson_rj(0.0, m1, 1.0, 1.0 - w);
    }
    let rf = ellip_k(m1);
    if n == 0.0 {
        return rf;
    }
    rf + n / 3.0 * carlson_rj(0.0, m1, 1.0, 1.0 - n)
}

/// `integral_0^u dv / (1 - n sn^2(v | m))`, given `m1 = 1 - m`, for `n < 1` and any real `u`.
///
/// This is `Pi(n; am u | m)` without forming the amplitude: `u` is reduced by the half
/// period 2K, each of which adds the complete `2 Pi(n | m)`, and the remainder is
/// evaluated from sn, cn, dn. On the separatrix (`m1 = 0`) it is elementary:
/// `(u + sqrt(-n) atan(sqrt(-n) tanh u)) / (1 - n)` for n < 0 and
/// `(u - sqrt(n) atanh(sqrt(n) tanh u)) / (1 - n)` for 0 <= n < 1. NaN if `n >= 1`.
/// Large negative `n` keeps full relative precision, as in [`ellip_pi`].
#[must_use]
pub fn ellip_pi_jacobi(n: f64, u: f64, m: f64, m1: f64) -> f64 {
    let (m, m1) = (clamp_unit(m), clamp_unit(m1));
    if n.is_nan() || n >= 1.0 || !u.is_finite() || m.is_nan() || m1.is_nan() {
        return f64::NAN;
    }
    if m1 == 0.0 {
        let th = u.tanh();
        let extra = if n < 0.0 {
            let r = (-n).sqrt();
            r * (r * th).atan()
        } else {
            let r = n.sqrt();
            -r * (r * th).atanh()
        };
        return (u + extra) / (1.0 - n);
    }
    if m == 0.0 {
        // sn = sin: the Jacobi form is the trigonometric Pi(n; u | 0).
        return ellip_pi(n, u, 0.0, 1.0);
    }
    let agm = Agm::new(m, m1);
    let k = agm.k();
    let (r, j) = reduce_count(u, k);
    let (s, c, d) = jacobi_reduced(r, &agm, m1.sqrt());
    let base = pi_from_sn(n, s, c.abs(), d * d, m);
    if j == 0.0 {
        base
    } else {
        2.0 * j * complete_pi(n, m, m1) + base
    }
}

/// Carlson's symmetric integral of the first kind
/// `RF(x, y, z) = 1/2 integral_0^inf dt / sqrt((t + x)(t + y)(t + z))`.
///
/// Requires x, y, z >= 0 with at most one of them zero (two zeros give infinity);
/// negative or NaN arguments give NaN. Duplication algorithm of Carlson (1995), section 2.
#[must_use]
pub fn carlson_rf(x: f64, y: f64, z: f64) -> f64 {
    if !(x >= 0.0 && y >= 0.0 && z >= 0.0) {
        return f64::NAN;
    }
    if zeros(&[x, y, z]) >= 2 {
        return f64::INFINITY;
    }
    if x.is_infinite() || y.is_infinite() || z.is_infinite() {
        return 0.0;
    }
    let (x_orig, y_orig) = (x, y);
    let (mut x, mut y, mut z) = (x, y, z);
    let a0 = (x + y + z) / 3.0;
    let mut a = a0;
    let q = CARLSON_RF_FACTOR * max_dev(a0, &[x, y, z]);
    let mut scale = 1.0_f64; // 4^-n
    for _ in 0..MAX_STEPS {
        if scale * q < a.abs() {
            break;
        }
        let (sx, sy, sz) = (x.sqrt(), y.sqrt(), z.sqrt());
        let lambda = sx * sy + sy * sz + sz * sx;
        x = 0.25 * (x + lambda);
        y = 0.25 * (y + lambda);
        z = 0.25 * (z + lambda);
        a = 0.25 * (a + lambda);
        scale *= 0.25;
    }
    let xx = scale * (a0 - x_orig) / a;
    let yy = scale * (a0 - y_orig) / a;
    let zz = -(xx + yy);
    let e2 = xx * yy - zz * zz;
    let e3 = xx * yy * zz;
    (1.0 - e2 / 10.0 + e3 / 14.0 + e2 * e2 / 24.0 - 3.0 * e2 * e3 / 44.0) / a.sqrt()
}

/// How many of the arguments are exactly zero.
fn zeros(v: &[f64]) -> usize {
    v.iter().filter(|&&t| t == 0.0).count()
}

/// The largest |a0 - v| over the arguments.
fn max_dev(a0: f64, v: &[f64]) -> f64 {
    v.iter().fold(0.0_f64, |acc, &t| acc.max((a0 - t).abs()))
}

/// Carlson's symmetric integral of the second kind
/// `RD(x, y, z) = 3/2 integral_0^inf dt / ((t + z) sqrt((t + x)(t + y)(t + z)))`.
///
/// Requires x, y >= 0 (at most one zero) and z > 0; otherwise NaN or infinity.
/// Duplication algorithm of Carlson (1995), section 2, eqs. 2.28-2.30.
#[must_use]
pub fn carlson_rd(x: f64, y: f64, z: f64) -> f64 {
    if !(x >= 0.0 && y >= 0.0 && z >= 0.0) {
        return f64::NAN;
    }
    if z == 0.0 || zeros(&[x, y]) == 2 {
        return f64::INFINITY;
    }
    if x.is_infinite() || y.is_infinite() || z.is_infinite() {
        return 0.0;
    }
    let (x_orig, y_orig) = (x, y);
    let (mut x, mut y, mut z) = (x, y, z);
    let a0 = (x + y + 3.0 * z) / 5.0;
    let mut a = a0;
    let q = CARLSON_RJ_FACTOR * max_dev(a0, &[x, y, z]);
    let mut scale = 1.0_f64;
    let mut sum = 0.0;
    for _ in 0..MAX_STEPS {
        if scale * q < a.abs() {
            break;
        }
        let (sx, sy, sz) = (x.sqrt(), y.sqrt(), z.sqrt());
        let lambda = sx * sy + sy * sz + sz * sx;
        sum += scale / (sz * (z + lambda));
        x = 0.25 * (x + lambda);
        y = 0.25 * (y + lambda);
        z = 0.25 * (z + lambda);
        a = 0.25 * (a + lambda);
        scale *= 0.25;
    }
    let xx = scale * (a0 - x_orig) / a;
    let yy = scale * (a0 - y_orig) / a;
    let zz = -(xx + yy) / 3.0;
    let xy = xx * yy;
    let z2 = zz * zz;
    let e2 = xy - 6.0 * z2;
    let e3 = (3.0 * xy - 8.0 * z2) * zz;
    let e4 = 3.0 * (xy - z2) * z2;
    let e5 = xy * z2 * zz;
    let series = 1.0 - 3.0 * e2 / 14.0 + e3 / 6.0 + 9.0 * e2 * e2 / 88.0
        - 3.0 * e4 / 22.0
        - 9.0 * e2 * e3 / 52.0
        + 3.0 * e5 / 26.0;
    scale * series / (a * a.sqrt()) + 3.0 * sum
}

/// Carlson's symmetric integral of the third kind
/// `RJ(x, y, z, p) = 3/2 integral_0^inf dt / ((t + p) sqrt((t + x)(t + y)(t + z)))`.
///
/// Requires x, y, z >= 0 (at most one zero) and p > 0; p <= 0 (the Cauchy principal
/// value) is not supported and gives NaN. Duplication algorithm of Carlson (1995),
/// section 2, with the sum of RC terms of Carlson's eq. 2.36 in the alpha/beta form.
#[must_use]
pub fn carlson_rj(x: f64, y: f64, z: f64, p: f64) -> f64 {
    if !(x >= 0.0 && y >= 0.0 && z >= 0.0 && p > 0.0) {
        return f64::NAN;
    }
    if zeros(&[x, y, z]) >= 2 {
        return f64::INFINITY;
    }
    if x.is_infinite() || y.is_infinite() || z.is_infinite() || p.is_infinite() {
        return 0.0;
    }
    let (x_orig, y_orig, z_orig) = (x, y, z);
    let (mut x, mut y, mut z, mut p) = (x, y, z, p);
    let a0 = (x + y + z + 2.0 * p) / 5.0;
    let mut a = a0;
    let q = CARLSON_RJ_FACTOR * max_dev(a0, &[x, y, z, p]);
    let mut scale = 1.0_f64;
    let mut sum = 0.0;
    for _ in 0..MAX_STEPS {
        if scale * q < a.abs() {
            break;
        }
        let (sx, sy, sz, sp) = (x.sqrt(), y.sqrt(), z.sqrt(), p.sqrt());
        let lambda = sx * sy + sy * sz + sz * sx;
        let alpha = p * (sx + sy + sz) + sx * sy * sz;
        let beta = sp * (p + lambda);
        sum += scale * carlson_rc(alpha * alpha, beta * beta);
        x = 0.25 * (x + lambda);
        y = 0.25 * (y + lambda);
        z = 0.25 * (z + lambda);
        p = 0.25 * (p + lambda);
        a = 0.25 * (a + lambda);
        scale *= 0.25;
    }
    let xx = scale * (a0 - x_orig) / a;
    let yy = scale * (a0 - y_orig) / a;
    let zz = scale * (a0 - z_orig) / a;
    let pp = -(xx + yy + zz) / 2.0;
    let xyz = xx * yy * zz;
    let p2 = pp * pp;
    let e2 = xx * yy + xx * zz + yy * zz - 3.0 * p2;
    let e3 = xyz + 2.0 * e2 * pp + 4.0 * pp * p2;
    let e4 = (2.0 * xyz + e2 * pp + 3.0 * pp * p2) * pp;
    let e5 = xyz * p2;
    let series = 1.0 - 3.0 * e2 / 14.0 + e3 / 6.0 + 9.0 * e2 * e2 / 88.0
        - 3.0 * e4 / 22.0
        - 9.0 * e2 * e3 / 52.0
        + 3.0 * e5 / 26.0;
    scale * series / (a * a.sqrt()) + 3.0 * sum
}

/// Carlson's degenerate integral `RC(x, y) = RF(x, y, y)` for x >= 0, y > 0, in the
/// inverse-tangent forms (DLMF 19.2.18-19) that stay accurate when x is close to y.
fn carlson_rc(x: f64, y: f64) -> f64 {
    if x < y {
        let d = y - x;
        if x == 0.0 {
            return FRAC_PI_2 / y.sqrt();
        }
        let t = (d / x).sqrt();
        t.atan() / d.sqrt()
    } else if x > y {
        let d = x - y;
        let t = (d / x).sqrt();
        t.atanh() / d.sqrt()
    } else {
        1.0 / x.sqrt()
    }
}
