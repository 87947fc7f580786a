//! The exact free-rigid-body flow over any `ga_core::Scalar`, for derivatives: the same
//! algorithm as `exact_flow::exact_free_body` (Jacobi's elliptic functions for the body
//! momentum, Legendre's third integral for the azimuth, in Carlson's forms), written once in
//! a macro and instantiated for `f64` (tested against `exact_flow`) and, with the feature
//! `dual`, for `num_dual::Dual64`. Every branch and every iteration count is decided on
//! real parts; the derivative parts follow them.
//!
//! A branch taken on an exact equality (t = 0, m(0) = 0, m(0) on a principal axis, equal
//! moments, the separatrix, `m = 0` or `m1 = 0` in the elliptic functions) is a point
//! where the flow stays smooth but one formula stops covering it. There the shortcut is
//! taken only when the quantity is zero in every part (`Scalar::is_exact_zero`; for `f64`
//! that is the old test, and the `f64` instantiation returns the same bits); a quantity
//! zero in value but not in derivative gets the derivative of the flow through the point:
//! the general formula where it is valid at the point, a first-order expansion where it is
//! not (each at its branch says which). Those expansions are first order: right for
//! `Dual64`, not for second derivatives. A symmetric body whose momentum is perpendicular
//! to the symmetry axis, moved along a derivative that makes the pair of equal moments
//! unequal, is one where the general frame degenerates: there the derivative along the gap
//! comes from the flow linearised about the steady rotation (`perpendicular_gap`).
//!
//! `exact_flow.rs` and `special/elliptic.rs` keep their own `f64` code, untouched (the
//! registry's `exact` and the reference runs use them at full speed). Differences from
//! them: `mul_add` is an unfused multiply-add and `hypot` `ga_core::Scalar`'s (both change
//! the last bits only), and an orbit with elliptic parameter exactly 0 but a body that is
//! not symmetric (the momentum on a principal axis's separatrix end) gives NaN here.

/// The exact flow over the scalar type `$s`.
macro_rules! exact_flow_over {
    ($(#[$doc:meta])* $name:ident, $s:ty) => {
        $(#[$doc])*
        pub mod $name {
            use ga_core::Scalar;

            /// This instantiation's scalar type.
            pub type S = $s;
            type Quat = [S; 4];

            #[inline]
            fn k(x: f64) -> S {
                <S as Scalar>::from_f64(x)
            }
            #[inline]
            fn mul_add(a: S, b: S, c: S) -> S {
                a * b + c
            }
            #[inline]
            fn clamp_unit(m: S) -> S {
                m.max(k(0.0)).min(k(1.0))
            }
            #[inline]
            fn atan(x: S) -> S {
                x.atan2(k(1.0))
            }
            #[inline]
            fn atanh(x: S) -> S {
                k(0.5) * (k(2.0) * x / (k(1.0) - x)).ln_1p()
            }
            #[inline]
            fn tanh(x: S) -> S {
                x.sinh() / x.cosh()
            }
            #[inline]
            fn is_infinite(x: S) -> bool {
                x.re().is_infinite()
            }

            const FRAC_PI_2: f64 = ::core::f64::consts::FRAC_PI_2;
            const MAX_STEPS: usize = 100;
            const LANDEN_STOP: f64 = 1e-10;
            const CARLSON_RF_FACTOR: f64 = 386.497_293_934_345_75;
            const CARLSON_RJ_FACTOR: f64 = 584.803_547_642_573;
            const TINY_ARGUMENT: f64 = 1e-9;
            const AGM_CAPACITY: usize = 32;

            struct Agm {
                a: [S; AGM_CAPACITY],
                b: [S; AGM_CAPACITY],
                c: [S; AGM_CAPACITY],
                top: usize,
            }

            impl Agm {
                fn new(m: S, m1: S) -> Self {
                    let zero = k(0.0);
                    let mut agm = Agm {
                        a: [zero; AGM_CAPACITY],
                        b: [zero; AGM_CAPACITY],
                        c: [zero; AGM_CAPACITY],
                        top: 0,
                    };
                    agm.a[0] = k(1.0);
                    agm.b[0] = m1.sqrt();
                    agm.c[0] = m.sqrt();
                    while agm.top + 1 < AGM_CAPACITY {
                        let n = agm.top;
                        if agm.c[n].is_nan() || agm.c[n] <= k(LANDEN_STOP) * agm.a[n] {
                            break;
                        }
                        let an = k(0.5) * (agm.a[n] + agm.b[n]);
                        agm.a[n + 1] = an;
                        agm.b[n + 1] = (agm.a[n] * agm.b[n]).sqrt();
                        agm.c[n + 1] = k(0.25) * agm.c[n] * agm.c[n] / an;
                        agm.top = n + 1;
                    }
                    agm
                }

                fn k(&self) -> S {
                    k(FRAC_PI_2) / self.a[self.top]
                }
            }

            fn jacobi_small(x: S, agm: &Agm) -> (S, S, S) {
                if x.abs() < k(TINY_ARGUMENT) {
                    return (x, k(1.0), k(1.0));
                }
                let top = agm.top;
                let (a, b, c) = (&agm.a, &agm.b, &agm.c);
                let v = x.abs() * a[top];
                let (s, co) = v.sin_cos();
                let mut cs = co / s;
                let kn = c[top] / a[top];
                let mut dn = (k(1.0) - kn * kn * s * s).sqrt();
                for n in (1..=top).rev() {
                    let sn2 = k(1.0) / (k(1.0) + cs * cs);
                    let cn2 = cs * cs * sn2;
                    let next_cs = cs * dn * a[n] / a[n - 1];
                    dn = (b[n - 1] + c[n] * cn2) / (a[n] + c[n] * sn2);
                    cs = next_cs;
                }
                let sn = k(1.0) / (k(1.0) + cs * cs).sqrt();
                let cn = cs * sn;
                let dn = mul_add(b[0], b[0], c[0] * c[0] * cn * cn).sqrt();
                (sn.copysign(x), cn, dn)
            }

            /// Jacobi's `(sn, cn, dn)(u | m)` with `m1 = 1 - m`.
            fn jacobi(u: S, m: S, m1: S) -> (S, S, S) {
                let (m, m1) = (clamp_unit(m), clamp_unit(m1));
                let nan = <S as Scalar>::NAN;
                if u.is_nan() || m.is_nan() || m1.is_nan() {
                    return (nan, nan, nan);
                }
                if m == k(0.0) {
                    let (s, c) = u.sin_cos();
                    if m.is_exact_zero() {
                        return (s, c, k(1.0));
                    }
                    // m is 0 in value only (a symmetric body's moments moved apart): the
                    // first order in m (Abramowitz & Stegun 16.13.1-3), valid for every u.
                    let shift = k(0.25) * m * (u - s * c);
                    return (s - shift * c, c + shift * s, k(1.0) - k(0.5) * m * s * s);
                }
                if m1 == k(0.0) {
                    let sech = k(1.0) / u.cosh();
                    let th = tanh(u);
                    if m1.is_exact_zero() {
                        return (th, sech, sech);
                    }
                    // On the separatrix in value only: the first order in m1 (Abramowitz &
                    // Stegun 16.15.1-3), valid for every u.
                    let sc = u.sinh() * u.cosh();
                    let q = k(0.25) * m1 * sech;
                    return (
                        th + q * (sc - u) * sech,
                        sech - q * (sc - u) * th,
                        sech + q * (sc + u) * th,
                    );
                }
                if !u.is_finite() {
                    return (nan, nan, nan);
                }
                let agm = Agm::new(m, m1);
                let (r, j) = reduce_count(u, agm.k());
                let (sn, cn, dn) = jacobi_reduced(r, &agm, m1.sqrt());
                if j % 2.0 != 0.0 {
                    (-sn, -cn, dn)
                } else {
                    (sn, cn, dn)
                }
            }

            /// `u - 2 j K` with `j` the nearest whole number of half periods (a constant).
            fn reduce_count(u: S, kk: S) -> (S, f64) {
                let j = (u / (k(2.0) * kk)).re().round();
                if j == 0.0 {
                    return (u, 0.0);
                }
                (mul_add(k(-j), k(2.0) * kk, u), j)
            }

            fn jacobi_reduced(r: S, agm: &Agm, kc: S) -> (S, S, S) {
                let kk = agm.k();
                if r.abs() <= k(0.5) * kk {
                    return jacobi_small(r, agm);
                }
                let y = kk - r.abs();
                let (sy, cy, dy) = jacobi_small(y, agm);
                ((cy / dy).copysign(r), kc * sy / dy, kc / dy)
            }

            fn ellip_k(m1: S) -> S {
                if m1.is_nan() || m1 < k(0.0) {
                    return <S as Scalar>::NAN;
                }
                if m1 == k(0.0) {
                    return <S as Scalar>::INFINITY;
                }
                if is_infinite(m1) {
                    return k(0.0);
                }
                Agm::new((k(1.0) - m1).abs(), m1).k()
            }

            /// `Pi(n; am(u | m) | m)` (NaN for `m = 0` with `m1 != 0`, see the module).
            fn ellip_pi_jacobi(n: S, u: S, m: S, m1: S) -> S {
                let (m, m1) = (clamp_unit(m), clamp_unit(m1));
                if n.is_nan() || n >= k(1.0) || !u.is_finite() || m.is_nan() || m1.is_nan() {
                    return <S as Scalar>::NAN;
                }
                if m1 == k(0.0) {
                    let th = tanh(u);
                    let extra = if n < k(0.0) {
                        let r = (-n).sqrt();
                        r * atan(r * th)
                    } else {
                        let r = n.sqrt();
                        -r * atanh(r * th)
                    };
                    let g = (u + extra) / (k(1.0) - n);
                    if m1.is_exact_zero() {
                        return g;
                    }
                    // On the separatrix in value only: g + m1 dG/dm1, from
                    // `dG/dm1 = int_0^u 2 n sn dsn/dm1 / (1 - n sn^2)^2` with A&S 16.15.1,
                    // integrated by parts and by partial fractions in T = tanh:
                    // `1/4 [n (u sech^2 u - T) / ((1 - n T^2)(1 - n)) + 2n/(1-n)^2 (u - P)]`,
                    // `P = int_0^T dx / (1 - n x^2)`, arranged so that no term grows with u
                    // faster than the result.
                    let p = if n < k(0.0) {
                        let r = (-n).sqrt();
                        atan(r * th) / r
                    } else if n > k(0.0) {
                        let r = n.sqrt();
                        atanh(r * th) / r
                    } else {
                        th
                    };
                    let sech = k(1.0) / u.cosh();
                    let one_n = k(1.0) - n;
                    let slope = k(0.25)
                        * (n * (u * sech * sech - th) / ((k(1.0) - n * th * th) * one_n)
                            + k(2.0) * n / (one_n * one_n) * (u - p));
                    return g + m1 * slope;
                }
                if m == k(0.0) {
                    if n == k(0.0) && !(m.is_exact_zero() && n.is_exact_zero()) {
                        // m and n are 0 in value only (a symmetric body's moments moved
                        // apart): `Pi = int_0^u dv / (1 - n sn^2 v)` is `u` for n = 0 and
                        // any m, and its n-derivative at m = 0 is `int_0^u sin^2`.
                        let (s, c) = u.sin_cos();
                        return u + k(0.5) * n * (u - s * c);
                    }
                    return <S as Scalar>::NAN;
                }
                let agm = Agm::new(m, m1);
                let kk = agm.k();
                let (r, j) = reduce_count(u, kk);
                let (s, c, d) = jacobi_reduced(r, &agm, m1.sqrt());
                let base = pi_from_sn(n, s, c.abs(), d * d, m);
                if j == 0.0 {
                    base
                } else {
                    k(2.0 * j) * complete_pi(n, m, m1) + base
                }
            }

            fn pi_from_sn(n: S, s: S, c: S, d2: S, m: S) -> S {
                let c2 = c * c;
                let s2 = s * s;
                if n < k(-1.0) {
                    let w = m / n;
                    let p = mul_add(-w, s2, k(1.0));
                    let elementary = s * carlson_rc(c2 * d2, mul_add(-n, s2, k(1.0)) * p);
                    if w == k(0.0) {
                        return elementary;
                    }
                    return elementary - w / k(3.0) * s * s2 * carlson_rj(c2, d2, k(1.0), p);
                }
                let rf = carlson_rf(c2, d2, k(1.0));
                if n == k(0.0) {
                    return s * rf;
                }
                s * rf + n / k(3.0) * s * s2 * carlson_rj(c2, d2, k(1.0), mul_add(-n, s2, k(1.0)))
            }

            fn complete_pi(n: S, m: S, m1: S) -> S {
                if m1 == k(0.0) {
                    return <S as Scalar>::INFINITY;
                }
                if n < k(-1.0) {
                    let w = m / n;
                    let elementary = k(FRAC_PI_2) / ((k(1.0) - n) * (k(1.0) - w)).sqrt();
                    if w == k(0.0) {
                        return elementary;
                    }
                    return elementary - w / k(3.0) * carlson_rj(k(0.0), m1, k(1.0), k(1.0) - w);
                }
                let rf = ellip_k(m1);
                if n == k(0.0) {
                    return rf;
                }
                rf + n / k(3.0) * carlson_rj(k(0.0), m1, k(1.0), k(1.0) - n)
            }

            fn zeros(v: &[S]) -> usize {
                v.iter().filter(|&&t| t == k(0.0)).count()
            }

            fn max_dev(a0: S, v: &[S]) -> S {
                v.iter().fold(k(0.0), |acc, &t| acc.max((a0 - t).abs()))
            }

            /// Carlson's `R_F(x, y, z)`.
            fn carlson_rf(x: S, y: S, z: S) -> S {
                if !(x >= k(0.0) && y >= k(0.0) && z >= k(0.0)) {
                    return <S as Scalar>::NAN;
                }
                if zeros(&[x, y, z]) >= 2 {
                    return <S as Scalar>::INFINITY;
                }
                if is_infinite(x) || is_infinite(y) || is_infinite(z) {
                    return k(0.0);
                }
                let (x_orig, y_orig) = (x, y);
                let (mut x, mut y, mut z) = (x, y, z);
                let a0 = (x + y + z) / k(3.0);
                let mut a = a0;
                let q = k(CARLSON_RF_FACTOR) * max_dev(a0, &[x, y, z]);
                let mut scale = k(1.0);
                for _ in 0..MAX_STEPS {
                    if scale * q < a.abs() {
                        break;
                    }
                    let (sx, sy, sz) = (x.sqrt(), y.sqrt(), z.sqrt());
                    let lambda = sx * sy + sy * sz + sz * sx;
                    x = k(0.25) * (x + lambda);
                    y = k(0.25) * (y + lambda);
                    z = k(0.25) * (z + lambda);
                    a = k(0.25) * (a + lambda);
                    scale *= k(0.25);
                }
                let xx = scale * (a0 - x_orig) / a;
                let yy = scale * (a0 - y_orig) / a;
                let zz = -(xx + yy);
                let e2 = xx * yy - zz * zz;
                let e3 = xx * yy * zz;
                (k(1.0) - e2 / k(10.0) + e3 / k(14.0) + e2 * e2 / k(24.0)
                    - k(3.0) * e2 * e3 / k(44.0))
                    / a.sqrt()
            }

            /// Carlson's `R_J(x, y, z, p)`.
            fn carlson_rj(x: S, y: S, z: S, p: S) -> S {
                if !(x >= k(0.0) && y >= k(0.0) && z >= k(0.0) && p > k(0.0)) {
                    return <S as Scalar>::NAN;
                }
                if zeros(&[x, y, z]) >= 2 {
                    return <S as Scalar>::INFINITY;
                }
                if is_infinite(x) || is_infinite(y) || is_infinite(z) || is_infinite(p) {
                    return k(0.0);
                }
                let (x_orig, y_orig, z_orig) = (x, y, z);
                let (mut x, mut y, mut z, mut p) = (x, y, z, p);
                let a0 = (x + y + z + k(2.0) * p) / k(5.0);
                let mut a = a0;
                let q = k(CARLSON_RJ_FACTOR) * max_dev(a0, &[x, y, z, p]);
                let mut scale = k(1.0);
                let mut sum = k(0.0);
                for _ in 0..MAX_STEPS {
                    if scale * q < a.abs() {
                        break;
                    }
                    let (sx, sy, sz, sp) = (x.sqrt(), y.sqrt(), z.sqrt(), p.sqrt());
                    let lambda = sx * sy + sy * sz + sz * sx;
                    let alpha = p * (sx + sy + sz) + sx * sy * sz;
                    let beta = sp * (p + lambda);
                    sum += scale * carlson_rc(alpha * alpha, beta * beta);
                    x = k(0.25) * (x + lambda);
                    y = k(0.25) * (y + lambda);
                    z = k(0.25) * (z + lambda);
                    p = k(0.25) * (p + lambda);
                    a = k(0.25) * (a + lambda);
                    scale *= k(0.25);
                }
                let xx = scale * (a0 - x_orig) / a;
                let yy = scale * (a0 - y_orig) / a;
                let zz = scale * (a0 - z_orig) / a;
                let pp = -(xx + yy + zz) / k(2.0);
                let xyz = xx * yy * zz;
                let p2 = pp * pp;
                let e2 = xx * yy + xx * zz + yy * zz - k(3.0) * p2;
                let e3 = xyz + k(2.0) * e2 * pp + k(4.0) * pp * p2;
                let e4 = (k(2.0) * xyz + e2 * pp + k(3.0) * pp * p2) * pp;
                let e5 = xyz * p2;
                let series = k(1.0) - k(3.0) * e2 / k(14.0) + e3 / k(6.0)
                    + k(9.0) * e2 * e2 / k(88.0)
                    - k(3.0) * e4 / k(22.0)
                    - k(9.0) * e2 * e3 / k(52.0)
                    + k(3.0) * e5 / k(26.0);
                scale * series / (a * a.sqrt()) + k(3.0) * sum
            }

            fn carlson_rc(x: S, y: S) -> S {
                if x < y {
                    let d = y - x;
                    if x == k(0.0) {
                        return k(FRAC_PI_2) / y.sqrt();
                    }
                    let t = (d / x).sqrt();
                    atan(t) / d.sqrt()
                } else if x > y {
                    let d = x - y;
                    let t = (d / x).sqrt();
                    atanh(t) / d.sqrt()
                } else {
                    k(1.0) / x.sqrt()
                }
            }

            // One value per call: the size of the general case does not matter.
            #[allow(clippy::large_enum_variant)]
            enum Body {
                Sphere,
                Symmetric(usize),
                /// Two moments equal in value but not in derivative, about the third.
                Breaking(usize),
                Stationary,
                General(WorkFrame),
            }

            /// The body frame permuted and signed so that the orbit is the textbook one.
            struct WorkFrame {
                c: Quat,
                perm: [usize; 3],
                sign: [f64; 3],
                i: [S; 3],
                u: [S; 3],
                d2: S,
            }

            /// Equal moments take the closed forms only when they are equal in every part
            /// (for `f64`, equal): moments equal in value but with different derivative
            /// parts leave the symmetric body, and the derivative is the general flow's.
            fn classify(i: [S; 3], u: [S; 3]) -> Body {
                let same = |a: usize, b: usize| (i[a] - i[b]).is_exact_zero();
                if same(0, 1) && same(1, 2) {
                    return Body::Sphere;
                }
                if same(0, 1) {
                    return Body::Symmetric(2);
                }
                if same(1, 2) {
                    return Body::Symmetric(0);
                }
                if same(0, 2) {
                    return Body::Symmetric(1);
                }
                // Three moments equal in value only: `exact_free_body` splits the
                // derivative into one moment at a time, each with an exact pair, before
                // it gets here; this keeps the sphere's value for any other caller.
                if i[0] == i[1] && i[1] == i[2] {
                    return Body::Sphere;
                }
                if u.iter().filter(|&&x| x == k(0.0)).count() == 2 {
                    return Body::Stationary;
                }
                if i[0] == i[1] {
                    return Body::Breaking(2);
                }
                if i[1] == i[2] {
                    return Body::Breaking(0);
                }
                if i[0] == i[2] {
                    return Body::Breaking(1);
                }
                let mut order = [0, 1, 2];
                order.sort_by(|&a, &b| i[a].re().total_cmp(&i[b].re()));
                let [lo, mid, hi] = order;
                let t_lo = u[lo] * u[lo] * ((i[mid] - i[lo]) / i[lo]);
                let t_hi = u[hi] * u[hi] * ((i[hi] - i[mid]) / i[hi]);
                let d2 = t_lo - t_hi;
                let (first, third) = if d2 <= k(0.0) { (lo, hi) } else { (hi, lo) };
                Body::General(WorkFrame::new(i, u, [first, mid, third], d2))
            }

            impl WorkFrame {
                fn new(i: [S; 3], u: [S; 3], perm: [usize; 3], d2: S) -> Self {
                    let sign_of = |x: S| if x < k(0.0) { -1.0 } else { 1.0 };
                    let s1 = sign_of(u[perm[0]]);
                    let s3 = sign_of(u[perm[2]]);
                    let even = matches!(perm, [0, 1, 2] | [1, 2, 0] | [2, 0, 1]);
                    let s2 = s1 * s3 * if even { 1.0 } else { -1.0 };
                    let sign = [s1, s2, s3];
                    let mut mat = [[0.0; 3]; 3];
                    for j in 0..3 {
                        mat[j][perm[j]] = sign[j];
                    }
                    WorkFrame {
                        c: quat_from_matrix(&mat).map(k),
                        perm,
                        sign,
                        i: perm.map(|a| i[a]),
                        u: [0, 1, 2].map(|j| k(sign[j]) * u[perm[j]]),
                        d2,
                    }
                }

                fn to_body(&self, v: [S; 3]) -> [S; 3] {
                    let mut out = [k(0.0); 3];
                    for j in 0..3 {
                        out[self.perm[j]] = k(self.sign[j]) * v[j];
                    }
                    out
                }
            }

            struct Orbit {
                i: [S; 3],
                k2: S,
                kc2: S,
                omega: S,
                b: [S; 3],
                rho: [S; 2],
                n: S,
                phi_coef: S,
            }

            impl Orbit {
                fn new(f: &WorkFrame) -> Self {
                    let [i1, i2, i3] = f.i;
                    let [u1, u2, u3] = f.u;
                    let (j21, j32, j31) = (i2 - i1, i3 - i2, i3 - i1);
                    let d1 = u2 * u2 * (j21 / i2) + u3 * u3 * (j31 / i3);
                    let d3 = u1 * u1 * (j31 / i1) + u2 * u2 * (j32 / i2);
                    let k2 = clamp_unit((j21 / j32) * (d3 / d1));
                    let kc2 = clamp_unit(-(j31 / j32) * (f.d2 / d1));
                    // On the separatrix in value only, m's derivative must be -m1's (the
                    // clamp above may drop it where the quotient rounds above 1).
                    let k2 = if kc2 == k(0.0) && !kc2.is_exact_zero() { k(1.0) - kc2 } else { k2 };
                    let omega = ((j32 / i2) * (d1 / (i1 * i3))).abs().sqrt() * j31.signum();
                    let rho = [(i1 / j31).abs().sqrt(), (i2 / j32).abs().sqrt()];
                    let sd3 = d3.abs().sqrt();
                    let b = [sd3 * rho[0], sd3 * rho[1], (d1 * (i3 / j31)).abs().sqrt()];
                    let n = -(i3 / i1) * (j21 / j32);
                    let phi_coef = j31 / (i1 * i3 * omega);
                    Orbit { i: f.i, k2, kc2, omega, b, rho, n, phi_coef }
                }

                fn phase(&self, u: [S; 3]) -> Option<(S, S, S)> {
                    let (ps, pc) = (u[1] * self.rho[0], u[0] * self.rho[1]);
                    let h = ps.hypot(pc);
                    let (s, c) = if h == k(0.0) { (k(0.0), k(1.0)) } else { (ps / h, pc / h) };
                    let tau = if self.kc2 == k(0.0) {
                        if c == k(0.0) {
                            return None;
                        }
                        let tau = (s / c).asinh();
                        if self.kc2.is_exact_zero() {
                            tau
                        } else {
                            // On the separatrix in value only: the value of the closed
                            // form, the derivative of Carlson's form (valid at m = 1).
                            let c2 = c * c;
                            with_slope(tau, s * carlson_rf(c2, mul_add(self.k2, c2, self.kc2), k(1.0)))
                        }
                    } else {
                        let c2 = c * c;
                        s * carlson_rf(c2, mul_add(self.k2, c2, self.kc2), k(1.0))
                    };
                    Some((tau, s, c))
                }

                fn azimuth(&self, sn: S, cn: S) -> S {
                    (self.rho[1] * sn).atan2(self.rho[0] * cn)
                }

                fn g(&self, tau: S) -> S {
                    ellip_pi_jacobi(self.n, tau, self.k2, self.kc2)
                }
            }

            fn unit_flow(i: [S; 3], u0: [S; 3], q0: Quat, t: S) -> (Quat, [S; 3]) {
                match classify(i, u0) {
                    Body::Sphere => {
                        let w = [0, 1, 2].map(|j| u0[j] / i[j]);
                        (qmul(q0, qexp(w, t)), u0)
                    }
                    Body::Stationary => stationary_flow(i, u0, q0, t),
                    Body::Symmetric(axis) => symmetric_flow(i, u0, q0, t, axis),
                    Body::Breaking(axis) => breaking_flow(i, u0, q0, t, axis),
                    Body::General(frame) => general_flow(&frame, q0, t),
                }
            }

            /// `q` or `-q` (the same attitude), whichever is on `reference`'s sheet.
            fn on_sheet(reference: Quat, q: Quat) -> Quat {
                let dot: f64 = (0..4).map(|j| reference[j].re() * q[j].re()).sum();
                if dot < 0.0 {
                    q.map(|x| -x)
                } else {
                    q
                }
            }

            /// `value`'s real part with `slope`'s derivative parts.
            fn with_slope(value: S, slope: S) -> S {
                k(value.re()) + (slope - k(slope.re()))
            }

            /// Two moments equal in value, apart in derivative: the symmetric top's value,
            /// the derivative of the general flow in the work frame whose axis 3 is the
            /// symmetry axis `s`. There the gap `j21` between the pair is 0 in value, so
            /// `m = j21 d3 / (j32 d1)` and `n = -i3 j21 / (i1 j32)` are too, and the general
            /// solution is analytic in them through 0 (`m < 0` on one side: the Jacobi
            /// functions continue analytically), so its derivative is the limit from
            /// either side; `jacobi` and `ellip_pi_jacobi` give the first order in `m`
            /// and `n` at 0. With `u_s = 0` in value that frame degenerates (`d1 = 0`),
            /// and [`perpendicular_gap`] adds the derivative along the gap instead.
            fn breaking_flow(i: [S; 3], u0: [S; 3], q0: Quat, t: S, axis: usize) -> (Quat, [S; 3]) {
                let (q, u) = symmetric_flow(i, u0, q0, t, axis);
                if u0[axis] == k(0.0) {
                    return perpendicular_gap(i, u0, t, axis, q, u);
                }
                let (a, b) = ((axis + 1) % 3, (axis + 2) % 3);
                let d2 = u0[a] * u0[a] * ((i[b] - i[a]) / i[a])
                    - u0[axis] * u0[axis] * ((i[axis] - i[b]) / i[axis]);
                let frame = WorkFrame::new(i, u0, [a, b, axis], d2);
                let (qg, ug) = general_flow(&frame, q0, t);
                let qg = on_sheet(q, qg);
                (
                    [0, 1, 2, 3].map(|j| with_slope(q[j], qg[j])),
                    [0, 1, 2].map(|j| with_slope(u[j], ug[j])),
                )
            }

            /// A symmetric top (`i_a = i_b` in value, `s` the axis, `(s, a, b)` cyclic)
            /// whose momentum is perpendicular to its axis (`u_s = 0` in value), with
            /// `(q, u)` its flow from [`symmetric_flow`]: that flow turns steadily about
            /// `u0` (every axis of the equal pair is principal) and carries the derivative
            /// of every change that keeps `i_a = i_b`; this adds the first-order response
            /// to the gap `g = 1/i_b - 1/i_a` (its derivative parts; its value is 0).
            ///
            /// With `J` the inverse moments and `w = u0 / i_a` the steady rate, the
            /// momentum `u0 + x` and attitude `q (1 + eta)` obey, to first order
            /// (`m' = m x w`, `q' = q w / 2`: `eta' = eta x w + dw / 2`, as in
            /// [`stationary_flow`]), `x' = u0 x (J x + g u_b e_b) + x x w`, which is
            /// `x_a' = c u_b x_s`, `x_b' = -c u_a x_s`, `x_s' = g u_a u_b` with
            /// `c = 1/i_s - 1/i_a`, and `eta' = eta x w + (J x + g u_b e_b) / 2`, from
            /// `x = 0`, `eta = 0`: a linear system driven by `g`, solved by the matrix
            /// exponential of its real parts with the constant drive as a seventh state.
            fn perpendicular_gap(
                i: [S; 3],
                u0: [S; 3],
                t: S,
                axis: usize,
                q: Quat,
                u: [S; 3],
            ) -> (Quat, [S; 3]) {
                let (a, b) = ((axis + 1) % 3, (axis + 2) % 3);
                let gap = k(1.0) / i[b] - k(1.0) / i[a];
                if gap.is_exact_zero() {
                    return (q, u);
                }
                let (ia, is) = (i[a].re(), i[axis].re());
                let (ua, ub) = (u0[a].re(), u0[b].re());
                let (wa, wb) = (ua / ia, ub / ia);
                let c = 1.0 / is - 1.0 / ia;
                // The state (x_a, x_b, x_s, eta_a, eta_b, eta_s, 1) for g = 1.
                let l = [
                    [0.0, 0.0, c * ub, 0.0, 0.0, 0.0, 0.0],
                    [0.0, 0.0, -c * ua, 0.0, 0.0, 0.0, 0.0],
                    [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, ua * ub],
                    [0.5 / ia, 0.0, 0.0, 0.0, 0.0, -wb, 0.0],
                    [0.0, 0.5 / ia, 0.0, 0.0, 0.0, wa, 0.5 * ub],
                    [0.0, 0.0, 0.5 / is, wb, -wa, 0.0, 0.0],
                    [0.0; 7],
                ];
                let e = expm(l, t.re());
                let z = [0, 1, 2, 3, 4, 5].map(|r| k(e[r][6]) * gap);
                let mut u = u;
                u[a] += z[0];
                u[b] += z[1];
                u[axis] += z[2];
                let mut eta = [k(1.0), k(0.0), k(0.0), k(0.0)];
                eta[1 + a] = z[3];
                eta[1 + b] = z[4];
                eta[1 + axis] = z[5];
                (qmul(q, eta), u)
            }

            /// The steady rotation about the principal axis that carries `u0`'s real part.
            ///
            /// The components of `u0` off that axis have real part 0; where their
            /// derivative parts are not 0, the momentum leaves the axis, and the derivative
            /// is that of the flow linearised about the steady rotation (a formula valid on
            /// both sides, unlike the constant angular velocity). With `k` the axis,
            /// `(a, b)` the other two in cyclic order, `M = u_k` and `W = M / i_k`, the
            /// first-order momentum `(x_a, x_b)` and attitude `q(t) (1 + eta)` (`eta`
            /// pure, in the body frame) obey
            /// `x_a' = M (1/i_k - 1/i_b) x_b`, `x_b' = M (1/i_a - 1/i_k) x_a`,
            /// `eta_a' = W eta_b + x_a / (2 i_a)`, `eta_b' = -W eta_a + x_b / (2 i_b)`
            /// (from `m' = m x w` and `q' = q w / 2`: `eta' = eta x w + dw / 2`), with
            /// `eta(0) = 0`. Its matrix exponential is taken on real parts, where it is
            /// all the first order needs (a product of two derivative parts vanishes);
            /// no closed form, which would divide by the difference of the nutation and
            /// spin rates (0 for moments (1, 2, 3)).
            fn stationary_flow(i: [S; 3], u0: [S; 3], q0: Quat, t: S) -> (Quat, [S; 3]) {
                let axis = (0..3).find(|&j| u0[j] != k(0.0)).unwrap_or(0);
                let (a, b) = ((axis + 1) % 3, (axis + 2) % 3);
                let mut w = [k(0.0); 3];
                w[axis] = u0[axis] / i[axis];
                let q = qmul(q0, qexp(w, t));
                if u0[a].is_exact_zero() && u0[b].is_exact_zero() {
                    return (q, u0);
                }
                let (ia, ib, ik) = (i[a].re(), i[b].re(), i[axis].re());
                let big_m = u0[axis].re();
                let spin = big_m / ik;
                let l = [
                    [0.0, big_m * (1.0 / ik - 1.0 / ib), 0.0, 0.0],
                    [big_m * (1.0 / ia - 1.0 / ik), 0.0, 0.0, 0.0],
                    [0.5 / ia, 0.0, 0.0, spin],
                    [0.0, 0.5 / ib, -spin, 0.0],
                ];
                let e = expm(l, t.re());
                let x = [0, 1, 2, 3].map(|r| k(e[r][0]) * u0[a] + k(e[r][1]) * u0[b]);
                let mut u = u0;
                u[a] = x[0];
                u[b] = x[1];
                let mut eta = [k(1.0), k(0.0), k(0.0), k(0.0)];
                eta[1 + a] = x[2];
                eta[1 + b] = x[3];
                (qmul(q, eta), u)
            }

            /// `exp(l t)` for a real square matrix: scaling and squaring of the Taylor
            /// series.
            fn expm<const N: usize>(l: [[f64; N]; N], t: f64) -> [[f64; N]; N] {
                type M<const N: usize> = [[f64; N]; N];
                let mul = |x: &M<N>, y: &M<N>| -> M<N> {
                    ::core::array::from_fn(|r| {
                        ::core::array::from_fn(|c| (0..N).map(|j| x[r][j] * y[j][c]).sum())
                    })
                };
                let norm = l.iter().map(|row| row.iter().map(|x| x.abs()).sum::<f64>()).fold(0.0, f64::max)
                    * t.abs();
                let mut squarings = 0;
                let mut scale = t;
                while norm * (scale / t).abs() > 0.25 && squarings < 1100 {
                    scale *= 0.5;
                    squarings += 1;
                }
                let a: M<N> = l.map(|row| row.map(|x| x * scale));
                let identity: M<N> = ::core::array::from_fn(|r| ::core::array::from_fn(|c| if r == c { 1.0 } else { 0.0 }));
                let (mut sum, mut term) = (identity, identity);
                for n in 1..=20 {
                    term = mul(&term, &a).map(|row| row.map(|x| x / n as f64));
                    for r in 0..N {
                        for c in 0..N {
                            sum[r][c] += term[r][c];
                        }
                    }
                }
                for _ in 0..squarings {
                    sum = mul(&sum, &sum);
                }
                sum
            }

            fn symmetric_flow(i: [S; 3], u0: [S; 3], q0: Quat, t: S, axis: usize) -> (Quat, [S; 3]) {
                let ip = i[(axis + 1) % 3];
                let is = i[axis];
                let spin = u0[axis] * ((ip - is) / (is * ip));
                let l = rotate(q0, u0);
                let mut e = [k(0.0); 3];
                e[axis] = spin;
                let q = qmul(qmul(qexp(l, t / ip), q0), qexp(e, t));
                let (a, b) = ((axis + 1) % 3, (axis + 2) % 3);
                let (sn, cs) = (-spin * t).sin_cos();
                let mut u = u0;
                u[a] = cs * u0[a] - sn * u0[b];
                u[b] = sn * u0[a] + cs * u0[b];
                (q, u)
            }

            fn general_flow(frame: &WorkFrame, q0: Quat, t: S) -> (Quat, [S; 3]) {
                let orbit = Orbit::new(frame);
                let Some((tau0, s0, c0)) = orbit.phase(frame.u) else {
                    let w = [0, 1, 2].map(|j| frame.u[j] / orbit.i[j]);
                    let qw = qmul(qmul(q0, qconj(frame.c)), qexp(w, t));
                    return (qmul(qw, frame.c), frame.to_body(frame.u));
                };
                let tau = mul_add(orbit.omega, t, tau0);
                let (sn, cn, dn) = jacobi(tau, orbit.k2, orbit.kc2);
                let u = [orbit.b[0] * cn, orbit.b[1] * sn, orbit.b[2] * dn];
                let phi = t / orbit.i[2] + orbit.phi_coef * (orbit.g(tau) - orbit.g(tau0));
                let psi = phi - orbit.azimuth(sn, cn) + orbit.azimuth(s0, c0);
                let qw0 = qmul(q0, qconj(frame.c));
                let qw = qmul(
                    qmul(
                        qmul(qw0, qconj(to_pole(frame.u))),
                        qexp([k(0.0), k(0.0), k(1.0)], psi),
                    ),
                    to_pole(u),
                );
                (qmul(qw, frame.c), frame.to_body(u))
            }

            fn to_pole(u: [S; 3]) -> Quat {
                let q = [k(1.0) + u[2], u[1], -u[0], k(0.0)];
                normalize(q).unwrap_or([k(1.0), k(0.0), k(0.0), k(0.0)])
            }

            fn qexp(v: [S; 3], t: S) -> Quat {
                let size = v[0].hypot(v[1]).hypot(v[2]);
                if size == k(0.0) {
                    if v.iter().all(|x| x.is_exact_zero()) {
                        return [k(1.0), k(0.0), k(0.0), k(0.0)];
                    }
                    // |v| is zero but its derivative part is not (hypot's is meaningless
                    // there): `exp(v t / 2) = 1 + v t / 2 + O(|v|^2)`, and the square of a
                    // pure derivative part vanishes.
                    let half = k(0.5) * t;
                    return [k(1.0), half * v[0], half * v[1], half * v[2]];
                }
                let (s, c) = (k(0.5) * size * t).sin_cos();
                let f = s / size;
                [c, f * v[0], f * v[1], f * v[2]]
            }

            fn qmul(a: Quat, b: Quat) -> Quat {
                [
                    a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
                    a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
                    a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
                    a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0],
                ]
            }

            fn qconj(q: Quat) -> Quat {
                [q[0], -q[1], -q[2], -q[3]]
            }

            fn rotate(q: Quat, v: [S; 3]) -> [S; 3] {
                let r = qmul(qmul(q, [k(0.0), v[0], v[1], v[2]]), qconj(q));
                [r[1], r[2], r[3]]
            }

            fn normalize(q: Quat) -> Option<Quat> {
                let size = q[0].hypot(q[1]).hypot(q[2].hypot(q[3]));
                if size == k(0.0) || !size.is_finite() {
                    return None;
                }
                Some(q.map(|x| x / size))
            }

            /// A signed permutation matrix's quaternion (constants: computed in `f64`).
            fn quat_from_matrix(m: &[[f64; 3]; 3]) -> [f64; 4] {
                let tr = m[0][0] + m[1][1] + m[2][2];
                let q = if tr >= m[0][0] && tr >= m[1][1] && tr >= m[2][2] {
                    let s = 2.0 * (1.0 + tr).sqrt();
                    [0.25 * s, (m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s]
                } else if m[0][0] >= m[1][1] && m[0][0] >= m[2][2] {
                    let s = 2.0 * (1.0 + m[0][0] - m[1][1] - m[2][2]).sqrt();
                    [(m[2][1] - m[1][2]) / s, 0.25 * s, (m[0][1] + m[1][0]) / s, (m[0][2] + m[2][0]) / s]
                } else if m[1][1] >= m[2][2] {
                    let s = 2.0 * (1.0 + m[1][1] - m[0][0] - m[2][2]).sqrt();
                    [(m[0][2] - m[2][0]) / s, (m[0][1] + m[1][0]) / s, 0.25 * s, (m[1][2] + m[2][1]) / s]
                } else {
                    let s = 2.0 * (1.0 + m[2][2] - m[0][0] - m[1][1]).sqrt();
                    [(m[1][0] - m[0][1]) / s, (m[0][2] + m[2][0]) / s, (m[1][2] + m[2][1]) / s, 0.25 * s]
                };
                let size = q.iter().map(|x| x * x).sum::<f64>().sqrt();
                if size == 0.0 || !size.is_finite() {
                    return [1.0, 0.0, 0.0, 0.0];
                }
                q.map(|x| x / size)
            }

            /// The exact free-body flow, as `exact_flow::exact_free_body`: `(R(t), m(t))`
            /// from principal moments, the body momentum `m0`, the rotor `r0`
            /// (`[s, e12, e13, e23]`, normalised here) and the time `t`; NaN for invalid
            /// input.
            #[must_use]
            pub fn exact_free_body(moments: [S; 3], m0: [S; 3], r0: [S; 4], t: S) -> ([S; 4], [S; 3]) {
                let nan = <S as Scalar>::NAN;
                let nans = ([nan; 4], [nan; 3]);
                let finite = |v: &[S]| v.iter().all(|x| x.is_finite());
                let positive = moments.iter().all(|&i| i > k(0.0));
                if !(positive && finite(&moments) && finite(&m0) && finite(&r0) && t.is_finite()) {
                    return nans;
                }
                let Some(q0) = normalize([r0[0], -r0[3], r0[2], -r0[1]]) else {
                    return nans;
                };
                let to_rotor = |q: Quat| [q[0], -q[3], q[2], -q[1]];
                let value = |x: S| k(x.re());
                let same = |a: usize, b: usize| (moments[a] - moments[b]).is_exact_zero();
                let tied = moments[0] == moments[1] && moments[1] == moments[2];
                if tied && !same(0, 1) && !same(1, 2) && !same(0, 2) {
                    // A sphere in value whose moments move apart in three different ways:
                    // no closed form covers that direction, but a first derivative is
                    // linear in it, so it is the sum of the sphere's derivative along
                    // everything but the moments and one derivative per moment moved alone
                    // (the other two stay exactly equal, a symmetric top in
                    // `classify`). Each part is a run with only its own derivative parts.
                    let (mut r, mut m) = exact_free_body(moments.map(value), m0, r0, t);
                    for j in 0..3 {
                        let mut alone = moments.map(value);
                        alone[j] = moments[j];
                        let (rj, mj) =
                            exact_free_body(alone, m0.map(value), r0.map(value), value(t));
                        let rj = on_sheet(r, rj);
                        r = [0, 1, 2, 3].map(|c| r[c] + (rj[c] - value(rj[c])));
                        m = [0, 1, 2].map(|c| m[c] + (mj[c] - value(mj[c])));
                    }
                    return (r, m);
                }
                let size = m0[0].hypot(m0[1]).hypot(m0[2]);
                if size == k(0.0) {
                    if m0.iter().all(|x| x.is_exact_zero()) {
                        return (to_rotor(q0), m0);
                    }
                    // m(0) is zero with a derivative part: to first order the momentum
                    // stays m(0) (its rate `m x w` is quadratic) and the body turns at
                    // `w = J^-1 m(0)`, which `qexp` expands to first order.
                    let w = [0, 1, 2].map(|j| m0[j] / moments[j]);
                    return (to_rotor(qmul(q0, qexp(w, t))), m0);
                }
                // Only an exact zero: a time whose real part is 0 but whose derivative part
                // is not takes the flow below, which is valid at 0, for the rate
                // `dR/dt = -1/2 R Omega`, `dm/dt = m x w`.
                if t.is_exact_zero() {
                    return (to_rotor(q0), m0);
                }
                let scale = moments[0].max(moments[1]).max(moments[2]);
                let inertia = moments.map(|i| i / scale);
                let u0 = m0.map(|x| x / size);
                let time = size * (t / scale);
                let (q, u) = unit_flow(inertia, u0, q0, time);
                (to_rotor(q), u.map(|x| x * size))
            }
        }
    };
}

exact_flow_over!(
    /// The exact flow in `f64` (the check that this copy is `exact_flow`'s algorithm).
    f64,
    f64
);

#[cfg(feature = "dual")]
exact_flow_over!(
    /// The exact flow over `num_dual::Dual64`: derivatives of `(R(t), m(t))` along any
    /// seeded input (moments, momentum, initial attitude, time).
    dual64,
    ga_core::num_dual::Dual64
);
