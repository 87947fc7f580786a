//! The exact free-rigid-body flow against an independent reference: Euler's equations
//! in matrix form, `dM/dt = M [w]x`, `J dw/dt = (J w) x w`, integrated here by
//! Gragg-Bulirsch-Stoer extrapolation (fixed macro steps, order 16) and cross-checked
//! with a classical RK4 at tiny steps. The rotor is turned into a matrix by a small
//! geometric product written in this file, so the reference shares no code with
//! `exact_flow.rs`. Scene values are those of docs/references.md.

use ga_rigid::exact_flow::{exact_free_body, free_body_orbit};

type Mat = [[f64; 3]; 3];
type Vec3 = [f64; 3];

// ---------------------------------------------------------------------------------------
// Rotor to matrix through an independent G3 geometric product.
// ---------------------------------------------------------------------------------------

/// Sign of the product of basis blades `a b` (bitmasks over e1, e2, e3; Euclidean): the
/// parity of the swaps needed to sort the concatenated generators.
fn blade_sign(a: usize, b: usize) -> f64 {
    let mut a = a >> 1;
    let mut swaps = 0;
    while a != 0 {
        swaps += (a & b).count_ones();
        a >>= 1;
    }
    if swaps % 2 == 0 {
        1.0
    } else {
        -1.0
    }
}

/// Full geometric product of two G3 multivectors indexed by blade bitmask
/// (0: 1, 1: e1, 2: e2, 3: e12, 4: e3, 5: e13, 6: e23, 7: e123).
fn gp(x: &[f64; 8], y: &[f64; 8]) -> [f64; 8] {
    let mut out = [0.0; 8];
    for a in 0..8 {
        for b in 0..8 {
            out[a ^ b] += blade_sign(a, b) * x[a] * y[b];
        }
    }
    out
}

/// The matrix of `x -> R x ~R` for a rotor `[s, e12, e13, e23]`: column j is `R e_j ~R`.
fn rotor_matrix(r: [f64; 4]) -> Mat {
    let rotor = [r[0], 0.0, 0.0, r[1], 0.0, r[2], r[3], 0.0];
    let reverse = [r[0], 0.0, 0.0, -r[1], 0.0, -r[2], -r[3], 0.0];
    let mut m = [[0.0; 3]; 3];
    for (j, blade) in [1usize, 2, 4].iter().enumerate() {
        let mut e = [0.0; 8];
        e[*blade] = 1.0;
        let y = gp(&gp(&rotor, &e), &reverse);
        m[0][j] = y[1];
        m[1][j] = y[2];
        m[2][j] = y[4];
    }
    m
}

// ---------------------------------------------------------------------------------------
// The reference integrator.
// ---------------------------------------------------------------------------------------

/// State: the body-to-space matrix row by row (entries 0..9), then the body angular
/// momentum (9..12).
type State = [f64; 12];

fn cross(a: Vec3, b: Vec3) -> Vec3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// Euler's equations: `w = J^-1 m`, `dM/dt = M [w]x`, `dm/dt = m x w` (that is,
/// `J dw/dt = (J w) x w`), where `[w]x v = w x v`.
fn rhs(j: Vec3, y: &State) -> State {
    let m = [y[9], y[10], y[11]];
    let w = [m[0] / j[0], m[1] / j[1], m[2] / j[2]];
    let wx = [[0.0, -w[2], w[1]], [w[2], 0.0, -w[0]], [-w[1], w[0], 0.0]];
    let mut out = [0.0; 12];
    for i in 0..3 {
        for k in 0..3 {
            out[3 * i + k] = (0..3).map(|l| y[3 * i + l] * wx[l][k]).sum();
        }
    }
    let dm = cross(m, w);
    out[9..].copy_from_slice(&dm);
    out
}

/// `a + h b`, elementwise.
fn axpy(a: &State, h: f64, b: &State) -> State {
    let mut out = *a;
    for (o, x) in out.iter_mut().zip(b) {
        *o += h * x;
    }
    out
}

/// `f` at `y + delta`.
fn rhs_at(j: Vec3, y: &State, delta: &State) -> State {
    rhs(j, &axpy(y, 1.0, delta))
}

/// The increment of one Gragg-Bulirsch-Stoer macro step of size `h` from `y`: the
/// modified midpoint rule with 2, 4, ..., 16 substeps, run on the increment (small, so
/// it rounds less than the state would), extrapolated to zero step size in h^2 by the
/// Aitken-Neville scheme `T[j][k] = T[j][k-1] + (T[j][k-1] - T[j-1][k-1]) / ((n_j /
/// n_{j-k})^2 - 1)`. Order 16; at |w| h <= 0.1 the truncation error is far below
/// rounding.
fn gbs_increment(j: Vec3, y: &State, h: f64) -> State {
    const LEVELS: usize = 8;
    let steps: Vec<f64> = (1..=LEVELS).map(|k| 2.0 * k as f64).collect();
    let f0 = rhs(j, y);
    let mut prev_row: Vec<State> = Vec::new();
    for (level, &n) in steps.iter().enumerate() {
        let sub = h / n;
        let mut z0 = [0.0; 12];
        let mut z1 = axpy(&z0, sub, &f0);
        for _ in 1..(n as usize) {
            let z2 = axpy(&z0, 2.0 * sub, &rhs_at(j, y, &z1));
            z0 = z1;
            z1 = z2;
        }
        let end = rhs_at(j, y, &z1);
        let mut first = [0.0; 12];
        for e in 0..12 {
            first[e] = 0.5 * (z0[e] + z1[e] + sub * end[e]);
        }
        let mut row = vec![first];
        for k in 1..=level {
            let ratio = (n / steps[level - k]).powi(2) - 1.0;
            let (cur, old) = (row[k - 1], prev_row[k - 1]);
            let mut next = cur;
            for e in 0..12 {
                next[e] = cur[e] + (cur[e] - old[e]) / ratio;
            }
            row.push(next);
        }
        prev_row = row;
    }
    prev_row[LEVELS - 1]
}

fn initial_state(m0: Vec3, r0: [f64; 4]) -> State {
    let rot = rotor_matrix(r0);
    let mut y = [0.0; 12];
    for i in 0..3 {
        for k in 0..3 {
            y[3 * i + k] = rot[i][k];
        }
    }
    y[9..].copy_from_slice(&m0);
    y
}

fn split_state(y: &State) -> (Mat, Vec3) {
    let mut rot = [[0.0; 3]; 3];
    for i in 0..3 {
        for k in 0..3 {
            rot[i][k] = y[3 * i + k];
        }
    }
    (rot, [y[9], y[10], y[11]])
}

/// Integrate from (rotor r0, momentum m0) over time t with macro steps |w| h <= `c`,
/// adding the increments with Kahan's compensated summation.
fn reference_with(j: Vec3, m0: Vec3, r0: [f64; 4], t: f64, c: f64) -> (Mat, Vec3) {
    let wmax = norm(m0) / j[0].min(j[1]).min(j[2]);
    let steps = ((t.abs() * wmax / c).ceil() as usize).max(1);
    let h = t / steps as f64;
    let mut y = initial_state(m0, r0);
    let mut comp = [0.0; 12];
    for _ in 0..steps {
        let delta = gbs_increment(j, &y, h);
        for e in 0..12 {
            let add = delta[e] - comp[e];
            let sum = y[e] + add;
            comp[e] = (sum - y[e]) - add;
            y[e] = sum;
        }
    }
    split_state(&y)
}

/// The reference solution at time `t`.
fn reference(j: Vec3, m0: Vec3, r0: [f64; 4], t: f64) -> (Mat, Vec3) {
    reference_with(j, m0, r0, t, 0.1)
}

/// Classical RK4 with `steps` fixed steps, for cross-checking the reference.
fn rk4(j: Vec3, m0: Vec3, r0: [f64; 4], t: f64, steps: usize) -> (Mat, Vec3) {
    let h = t / steps as f64;
    let mut y = initial_state(m0, r0);
    for _ in 0..steps {
        let k1 = rhs(j, &y);
        let k2 = rhs(j, &axpy(&y, 0.5 * h, &k1));
        let k3 = rhs(j, &axpy(&y, 0.5 * h, &k2));
        let k4 = rhs(j, &axpy(&y, h, &k3));
        for e in 0..12 {
            y[e] += h / 6.0 * (k1[e] + 2.0 * k2[e] + 2.0 * k3[e] + k4[e]);
        }
    }
    split_state(&y)
}

// ---------------------------------------------------------------------------------------
// Comparisons.
// ---------------------------------------------------------------------------------------

fn norm(v: Vec3) -> f64 {
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
}

fn mat_diff(a: &Mat, b: &Mat) -> f64 {
    let mut d = 0.0_f64;
    for i in 0..3 {
        for k in 0..3 {
            d = d.max((a[i][k] - b[i][k]).abs());
        }
    }
    d
}

fn vec_diff(a: Vec3, b: Vec3) -> f64 {
    (0..3).map(|i| (a[i] - b[i]).abs()).fold(0.0, f64::max)
}

/// Largest attitude (matrix entries) and relative momentum error of the exact flow
/// against the reference, sampled at the given times.
fn max_errors(j: Vec3, m0: Vec3, r0: [f64; 4], times: &[f64]) -> (f64, f64) {
    let (mut ea, mut em) = (0.0_f64, 0.0_f64);
    let scale = norm(m0).max(f64::MIN_POSITIVE);
    for &t in times {
        let (r, m) = exact_free_body(j, m0, r0, t);
        let (rot_ref, m_ref) = reference(j, m0, r0, t);
        ea = ea.max(mat_diff(&rotor_matrix(r), &rot_ref));
        em = em.max(vec_diff(m, m_ref) / scale);
    }
    (ea, em)
}

/// Sample times up to 20, irregular so that no sample sits on a symmetry.
const TIMES: [f64; 6] = [0.37, 1.9, 4.6, 9.1, 14.3, 20.0];

#[track_caller]
fn assert_agrees(j: Vec3, m0: Vec3, r0: [f64; 4], tol: f64) -> (f64, f64) {
    let (ea, em) = max_errors(j, m0, r0, &TIMES);
    assert!(
        ea <= tol && em <= tol,
        "moments {j:?}, m0 {m0:?}: attitude error {ea:e}, momentum error {em:e} > {tol:e}"
    );
    (ea, em)
}

/// Same rotation as the reference rotor (R and -R agree).
#[track_caller]
fn assert_rotor(got: [f64; 4], want: [f64; 4], tol: f64) {
    let sign = if got[0] * want[0] + got[1] * want[1] + got[2] * want[2] + got[3] * want[3] < 0.0 {
        -1.0
    } else {
        1.0
    };
    let err = (0..4)
        .map(|k| (sign * got[k] - want[k]).abs())
        .fold(0.0, f64::max);
    assert!(err <= tol, "rotor {got:?} vs {want:?}: {err:e} > {tol:e}");
}

#[track_caller]
fn assert_vec(got: Vec3, want: Vec3, tol: f64) {
    let err = vec_diff(got, want);
    assert!(err <= tol, "{got:?} vs {want:?}: {err:e} > {tol:e}");
}

const ONE: [f64; 4] = [1.0, 0.0, 0.0, 0.0];

use ga_test_rng::Rng;

/// A unit rotor `[s, e12, e13, e23]`: four components uniform in [-1, 1), normalised.
fn rotor(rng: &mut Rng) -> [f64; 4] {
    let q: [f64; 4] = rng.uniform_array(-1.0, 1.0);
    let n = (q.iter().map(|x| x * x).sum::<f64>()).sqrt();
    q.map(|x| x / n)
}

// ---------------------------------------------------------------------------------------
// The tests.
// ---------------------------------------------------------------------------------------

#[test]
fn rotor_matrix_follows_the_convention() {
    // R = cos(t/2) - e12 sin(t/2) maps e1 to cos t e1 + sin t e2.
    let t = 0.7_f64;
    let m = rotor_matrix([(t / 2.0).cos(), -(t / 2.0).sin(), 0.0, 0.0]);
    assert!((m[0][0] - t.cos()).abs() < 1e-15 && (m[1][0] - t.sin()).abs() < 1e-15);
    assert!(m[2][0].abs() < 1e-15);
    // A general unit rotor gives a proper orthogonal matrix.
    let r = rotor(&mut Rng::new(7));
    let m = rotor_matrix(r);
    for a in 0..3 {
        for b in 0..3 {
            let dot: f64 = (0..3).map(|k| m[k][a] * m[k][b]).sum();
            assert!((dot - if a == b { 1.0 } else { 0.0 }).abs() < 1e-15);
        }
    }
}

#[test]
fn reference_integrator_agrees_with_rk4() {
    // The extrapolation reference and a plain RK4 at h = 1e-3 agree to RK4's error.
    let (j, m0, r0, t) = ([0.6, 0.8, 1.0], [1.8, 0.4, -0.9], ONE, 10.0);
    let (rot_a, m_a) = reference(j, m0, r0, t);
    let (rot_b, m_b) = rk4(j, m0, r0, t, 40_000);
    assert!(
        mat_diff(&rot_a, &rot_b) < 1e-12,
        "{}",
        mat_diff(&rot_a, &rot_b)
    );
    assert!(vec_diff(m_a, m_b) < 1e-12, "{}", vec_diff(m_a, m_b));
}

#[test]
fn hairer_lubich_wanner_scene_matches_published_values() {
    let (j, m0) = ([2.0, 1.0, 2.0 / 3.0], [1.1_f64.cos(), 0.0, 1.1_f64.sin()]);
    let (r, m) = exact_free_body(j, m0, ONE, 10.0);
    assert_vec(m, [0.407066136588, 0.283007426813, 0.868449167662], 1e-11);
    assert_rotor(
        r,
        [
            0.765111030829,
            -0.513722699054,
            0.102854131455,
            -0.374319551483,
        ],
        1e-11,
    );
    let orbit = free_body_orbit(j, m0);
    assert!((orbit.energy - 0.6471252793138).abs() < 1e-12);
    assert!((orbit.parameter - 0.259048532).abs() < 1e-9);
    assert!((orbit.period - 10.7314652349).abs() < 1e-9);
    // One period later m is back.
    let (_, mp) = exact_free_body(j, m0, ONE, orbit.period);
    assert_vec(mp, m0, 1e-13);
    assert_agrees(j, m0, ONE, 1e-12);
}

#[test]
fn hairer_vilmart_scene_matches_published_values() {
    let (j, m0) = ([0.6, 0.8, 1.0], [1.8, 0.4, -0.9]);
    let (r, m) = exact_free_body(j, m0, ONE, 10.0);
    assert_vec(m, [1.765962508518, -0.695464197033, 0.779554981482], 1e-11);
    assert_rotor(
        r,
        [
            0.736061364161,
            -0.206839086105,
            0.299388571831,
            -0.570786951240,
        ],
        1e-11,
    );
    let orbit = free_body_orbit(j, m0);
    assert!((orbit.energy - 3.205).abs() < 1e-12);
    assert!((orbit.parameter - 0.165454545).abs() < 1e-9);
    assert!((orbit.period - 6.8626161781).abs() < 1e-9);
    assert_agrees(j, m0, ONE, 1e-12);
}

#[test]
fn eulr_scene_matches_published_values() {
    let j = [0.5, 2.0, 3.0];
    let m0 = [0.5 * 1.0, 0.0, 3.0 * 0.9];
    let (_, m) = exact_free_body(j, m0, ONE, 20.0);
    assert_vec(m, [0.303101926982, 1.257494420900, 2.422155445727], 1e-11);
    let orbit = free_body_orbit(j, m0);
    assert!((orbit.parameter - 0.308641975).abs() < 1e-9);
    assert!((orbit.period - 4.8319003).abs() < 1e-7);
    assert_agrees(j, m0, ONE, 1e-12);
}

#[test]
fn dzhanibekov_scene_matches_published_values() {
    let (j, m0) = ([3.0, 5.0, 9.0], [0.0, 2.0, 0.01]);
    let (_, m) = exact_free_body(j, m0, ONE, 100.0);
    assert_vec(m, [0.209094262834, 1.972485481093, 0.256282297721], 1e-10);
    let orbit = free_body_orbit(j, m0);
    assert!((orbit.parameter - 0.999958335).abs() < 1e-9);
    assert!((orbit.complementary_parameter - 4.1665e-5).abs() < 1e-8);
    assert!((orbit.period - 118.11089).abs() < 1e-5);
    let (ea, em) = max_errors(j, m0, ONE, &[30.0, 59.06, 100.0, 118.11089]);
    assert!(ea < 1e-10 && em < 1e-10, "{ea:e} {em:e}");
}

#[test]
fn symmetric_short_fat_top_precesses_at_minus_14_over_9() {
    let (j, m0) = ([3.0, 3.0, 9.0], [0.0, 5.0, 7.0]);
    let omega = -14.0 / 9.0;
    for &t in &[0.5, 3.0, 17.0, 200.0] {
        let (_, m) = exact_free_body(j, m0, ONE, t);
        let want = [5.0 * (omega * t).sin(), 5.0 * (omega * t).cos(), 7.0];
        assert_vec(m, want, 1e-13 * (1.0 + t));
    }
    let orbit = free_body_orbit(j, m0);
    assert!((orbit.period - 2.0 * std::f64::consts::PI * 9.0 / 14.0).abs() < 1e-13);
    assert_agrees(j, m0, rotor(&mut Rng::new(3)), 1e-12);
    // The symmetric axis in every position, prolate and oblate.
    for &j in &[
        [1.0, 2.0, 2.0],
        [2.0, 1.0, 2.0],
        [3.0, 3.0, 1.0],
        [2.0, 5.0, 2.0],
    ] {
        assert_agrees(j, [0.3, -1.1, 0.8], rotor(&mut Rng::new(5)), 1e-12);
    }
}

#[test]
fn near_symmetric_bodies_agree_with_reference() {
    let r0 = rotor(&mut Rng::new(11));
    let gaps = [1e-9, 1e-12, 1e-15, 2.2e-16];
    for &g in &gaps {
        // i1 ~ i2 (orbit about axis 3, and the thin band about axis 1 near the equator).
        assert_agrees([1.0, 1.0 + g, 2.0], [0.6, -0.5, 0.9], r0, 1e-11);
        assert_agrees([1.0, 1.0 + g, 2.0], [0.6, -0.5, 1e-9], r0, 1e-11);
        // i2 ~ i3, and the pair in other slots.
        assert_agrees([1.0, 2.0, 2.0 * (1.0 + g)], [0.6, -0.5, 0.9], r0, 1e-11);
        assert_agrees([2.0, 1.0 + g, 1.0], [0.2, 1.3, -0.4], r0, 1e-11);
        // Nearly a sphere.
        assert_agrees([1.0, 1.0 + g, 1.0 + 2.0 * g], [0.2, 1.3, -0.4], r0, 1e-11);
    }
}

#[test]
fn spheres_spin_uniformly() {
    let (j, m0) = ([2.0, 2.0, 2.0], [0.3, -0.4, 1.2]);
    let r0 = rotor(&mut Rng::new(13));
    let (_, m) = exact_free_body(j, m0, r0, 7.0);
    assert_eq!(m, m0);
    assert_agrees(j, m0, r0, 1e-12);
}

#[test]
fn bodies_at_rest_stay_put() {
    let r0 = rotor(&mut Rng::new(17));
    for &j in &[[1.0, 2.0, 3.0], [1.0, 1.0, 1.0], [1.0, 1.0, 3.0]] {
        let (r, m) = exact_free_body(j, [0.0; 3], r0, 12.0);
        assert_eq!(m, [0.0; 3]);
        assert_rotor(r, r0, 1e-16);
    }
}

#[test]
fn steady_rotations_about_principal_axes_agree_with_reference() {
    let r0 = rotor(&mut Rng::new(19));
    let j = [1.0, 2.0, 3.0];
    for k in 0..3 {
        for &s in &[1.5, -0.7] {
            let mut m0 = [0.0; 3];
            m0[k] = s;
            let (_, m) = exact_free_body(j, m0, r0, 9.0);
            assert_eq!(m, m0);
            assert_agrees(j, m0, r0, 1e-12);
        }
    }
}

#[test]
fn nearly_steady_rotations_agree_with_reference() {
    // Tiny orbits about the stable axes, and a start next to the unstable middle axis
    // (near the saddle, so errors grow like exp(omega t) in any method).
    let r0 = rotor(&mut Rng::new(37));
    let j = [1.0, 2.0, 3.0];
    for &m0 in &[
        [1.0, 1e-7, -1e-7],
        [-1e-9, 1e-9, 1.0],
        [1e-12, -1.0, 1e-12],
        [1e-7, 1.0, -1e-7],
    ] {
        assert_agrees(j, m0, r0, 1e-11);
    }
}

#[test]
fn exact_separatrix_agrees_with_reference() {
    // Moments (2, 5, 8) scale to (1/4, 5/8, 1), where (i2 - i1)/i1 = 4 (i3 - i2)/i3
    // exactly, so m0 = (a, y, 2a) has 2E = |m|^2 / i2 in floating point too.
    let j = [2.0, 5.0, 8.0];
    let orbit = free_body_orbit(j, [1.0, 0.3, 2.0]);
    assert_eq!(orbit.complementary_parameter, 0.0);
    assert_eq!(orbit.period, f64::INFINITY);
    let r0 = rotor(&mut Rng::new(23));
    for &m0 in &[
        [1.0, 0.3, 2.0],
        [-1.0, 0.3, 2.0],
        [1.0, -0.3, -2.0],
        [-1.0, -4.0, -2.0],
        [0.5, 3.0, 1.0],
    ] {
        // The saddle amplifies the reference's own rounding by up to exp(0.7 * 20) = 1e6
        // for |m0| = 4.6 (high_precision_references_agree_to_1e_13 checks the exact flow
        // on the separatrix at 32 digits); elsewhere the agreement is 1e-12.
        assert_agrees(j, m0, r0, 1e-9);
    }
    // Approaching the saddle: u tends to the middle axis.
    let (_, m) = exact_free_body(j, [1.0, 0.3, 2.0], r0, 200.0);
    let size = norm([1.0, 0.3, 2.0]);
    assert!((m[1] - size).abs() < 1e-12 && m[0].abs() < 1e-12 && m[2].abs() < 1e-12);
}

#[test]
fn near_separatrix_agrees_with_reference() {
    let j = [2.0, 5.0, 8.0];
    let r0 = rotor(&mut Rng::new(29));
    for &eps in &[1e-12, -1e-12, 1e-8, -1e-8] {
        for &m0 in &[
            [1.0, 0.3, 2.0 * (1.0 + eps)],
            [-1.0, 2.0, 2.0 * (1.0 + eps)],
        ] {
            let orbit = free_body_orbit(j, m0);
            assert!(orbit.complementary_parameter > 0.0);
            assert!(orbit.complementary_parameter < 1e3 * eps.abs());
            assert_agrees(j, m0, r0, 1e-11);
        }
    }
}

#[test]
fn random_bodies_agree_with_reference() {
    let mut rng = Rng::new(0x9e37_79b9_7f4a_7c15);
    let mut worst = (0.0_f64, 0.0_f64);
    for _ in 0..40 {
        let j = [
            rng.uniform(0.2, 3.0),
            rng.uniform(0.2, 3.0),
            rng.uniform(0.2, 3.0),
        ];
        let m0 = [
            rng.uniform(-2.0, 2.0),
            rng.uniform(-2.0, 2.0),
            rng.uniform(-2.0, 2.0),
        ];
        let r0 = rotor(&mut rng);
        let (ea, em) = assert_agrees(j, m0, r0, 1e-10);
        worst = (worst.0.max(ea), worst.1.max(em));
    }
    println!(
        "random bodies: attitude {:e}, momentum {:e}",
        worst.0, worst.1
    );
}

#[test]
fn flow_is_a_one_parameter_group() {
    // phi(t1 + t2) = phi(t2) o phi(t1), and phi(-t) undoes phi(t), at long times too.
    let mut rng = Rng::new(31);
    for _ in 0..20 {
        let j = [
            rng.uniform(0.2, 3.0),
            rng.uniform(0.2, 3.0),
            rng.uniform(0.2, 3.0),
        ];
        let m0 = [
            rng.uniform(-2.0, 2.0),
            rng.uniform(-2.0, 2.0),
            rng.uniform(-2.0, 2.0),
        ];
        let r0 = rotor(&mut rng);
        let (t1, t2) = (rng.uniform(-50.0, 50.0), rng.uniform(-50.0, 50.0));
        let (ra, ma) = exact_free_body(j, m0, r0, t1 + t2);
        let (r1, m1) = exact_free_body(j, m0, r0, t1);
        let (rb, mb) = exact_free_body(j, m1, r1, t2);
        assert_rotor(ra, rb, 1e-11);
        assert_vec(ma, mb, 1e-11);
        let (rc, mc) = exact_free_body(j, m1, r1, -t1);
        assert_rotor(rc, r0, 1e-11);
        assert_vec(mc, m0, 1e-11);
    }
}

#[test]
fn invariants_are_kept_exactly() {
    // |m|, the energy and the space momentum R m ~R do not drift over long times.
    let (j, m0) = ([0.6, 0.8, 1.0], [1.8, 0.4, -0.9]);
    let l0 = [1.8, 0.4, -0.9];
    for &t in &[1e2, 1e3, 1e4] {
        let (r, m) = exact_free_body(j, m0, ONE, t);
        let rot = rotor_matrix(r);
        let l: Vec3 = [0, 1, 2].map(|i| (0..3).map(|k| rot[i][k] * m[k]).sum());
        assert_vec(l, l0, 1e-12 * t.max(1.0).sqrt() * 10.0);
        assert!((norm(m) - norm(m0)).abs() < 1e-14);
        let e = |v: Vec3| (0..3).map(|k| v[k] * v[k] / j[k]).sum::<f64>();
        assert!((e(m) - e(m0)).abs() < 1e-14);
    }
}

#[test]
fn invalid_input_gives_nan_without_panicking() {
    type Case = (Vec3, Vec3, [f64; 4], f64);
    let bad: [Case; 6] = [
        ([0.0, 1.0, 2.0], [1.0, 0.0, 0.0], ONE, 1.0),
        ([-1.0, 1.0, 2.0], [1.0, 0.0, 0.0], ONE, 1.0),
        ([1.0, 1.0, 2.0], [f64::NAN, 0.0, 0.0], ONE, 1.0),
        ([1.0, 2.0, 3.0], [1.0, 0.0, 0.5], [0.0; 4], 1.0),
        ([1.0, 2.0, 3.0], [1.0, 0.0, 0.5], ONE, f64::INFINITY),
        ([f64::INFINITY, 2.0, 3.0], [1.0, 0.0, 0.5], ONE, 1.0),
    ];
    for (j, m0, r0, t) in bad {
        let (r, m) = exact_free_body(j, m0, r0, t);
        assert!(r.iter().chain(m.iter()).all(|x| x.is_nan()));
    }
    // Extreme but valid input stays finite.
    let (r, m) = exact_free_body([1e-300, 2e-300, 3e-300], [1e-300, 0.0, 2e-300], ONE, 1.0);
    assert!(r.iter().chain(m.iter()).all(|x| x.is_finite()));
    let (r, m) = exact_free_body([1e200, 2e200, 3e200], [1e150, 3e150, 2e150], ONE, 1e40);
    assert!(r.iter().chain(m.iter()).all(|x| x.is_finite()));
    let (r, m) = exact_free_body([1.0, 2.0, 3.0], [1e-170, 1e-170, 1e-170], ONE, 1e3);
    assert!(r.iter().chain(m.iter()).all(|x| x.is_finite()));
}

/// Solutions of the same equations at 32 significant digits by mpmath 1.3.0's Taylor
/// integrator (`mpmath.odefun`), started from the exact binary values of the f64 inputs
/// and R(0) = 1 unless given: (name, moments, m0, r0, t, M(t) row by row, m(t)).
// The values are kept to the 20 digits mpmath printed; f64 rounds them on parsing.
#[allow(clippy::type_complexity, clippy::excessive_precision)]
const HIGH_PRECISION: [(&str, Vec3, Vec3, [f64; 4], f64, [f64; 9], Vec3); 9] = [
    (
        "Hairer-Lubich-Wanner",
        [2.0, 1.0, 2.0 / 3.0],
        [0.453_596_121_425_577_3, 0.0, 0.891_207_360_061_435_4],
        ONE,
        20.0,
        [
            -0.57064416408673889037,
            -0.10171892735255593347,
            0.81487330169296408799,
            0.55044695093006794006,
            -0.7837563235510303914,
            0.28763549764513409445,
            0.60940412880578549472,
            0.61268204242659014969,
            0.50323684551356490437,
        ],
        [
            0.28426346529965756078,
            0.49988743466536033866,
            0.81811174967697142233,
        ],
    ),
    (
        "separatrix (2, 5, 8), (1, 0.3, 2)",
        [2.0, 5.0, 8.0],
        [1.0, 0.3, 2.0],
        ONE,
        20.0,
        [
            -0.62565583517729900367,
            0.44265027452682624195,
            0.64235154733986733475,
            0.75382120279615217722,
            0.13113651291390176681,
            0.64386086167412326112,
            0.20076944519413026349,
            0.88705352118240725586,
            -0.41572548687124498486,
        ],
        [
            0.002029416049807168108,
            2.2560982707658112823,
            0.0040588320996143362161,
        ],
    ),
    (
        "separatrix (2, 5, 8), (-1, -4, -2)",
        [2.0, 5.0, 8.0],
        [-1.0, -4.0, -2.0],
        ONE,
        20.0,
        [
            0.1712377362020766213,
            -0.21822432041672631683,
            -0.96075792147608441319,
            0.40603114459001737257,
            -0.87286808082210462953,
            0.2706289398879141055,
            -0.89767273954560323599,
            -0.43643952554803487442,
            -0.060862083566846364811,
        ],
        [
            -0.000016835470939639598631,
            4.5825756948012145838,
            -0.000033670941879279197261,
        ],
    ),
    (
        "1e-12 off the separatrix",
        [2.0, 5.0, 8.0],
        [1.0, 0.3, 2.000_000_000_002],
        ONE,
        20.0,
        [
            -0.62565583522881905063,
            0.44265027431784947571,
            0.64235154743369415772,
            0.75382120277870012162,
            0.13113651285549039628,
            0.64386086170645259533,
            0.20076944509910540322,
            0.88705352129532432791,
            -0.41572548667619945488,
        ],
        [
            0.0020294158034033585281,
            2.2560982707669195137,
            0.0040588325923994945261,
        ],
    ),
    (
        "near-symmetric (1, 1 + 1e-9, 2), momentum near the equator",
        [1.0, 1.000000001, 2.0],
        [0.6, -0.5, 1e-9],
        ONE,
        20.0,
        [
            0.18189451955676529009,
            -0.98172661716188518119,
            -0.05592166763513815177,
            -0.98172661642003957479,
            -0.17807198846005379388,
            -0.067106017154521632332,
            0.055921680658524673412,
            0.067106006301699976021,
            -0.99617746890328843181,
        ],
        [
            0.60000002000000063807,
            -0.49999997599999818367,
            7.0000004574422158865e-9,
        ],
    ),
    (
        "near-symmetric (1, 1 + 1e-15, 2)",
        [1.0, 1.000_000_000_000_001, 2.0],
        [0.6, -0.5, 0.9],
        ONE,
        20.0,
        [
            -0.64907166180246277859,
            -0.33528891376427303807,
            0.68285234286173702726,
            0.64067170157896814163,
            -0.7249241979400619602,
            0.25303098236553455169,
            0.41017770373448990235,
            0.60171941263992118682,
            0.68533787273969420074,
        ],
        [
            -0.34061891450992080234,
            0.7028362220873962462,
            0.89999999999999972124,
        ],
    ),
    (
        "near-symmetric (1, 1 + 1e-15, 2), momentum near the equator",
        [1.0, 1.000_000_000_000_001, 2.0],
        [0.6, -0.5, 1e-9],
        ONE,
        20.0,
        [
            0.1818944895457809738,
            -0.98172662261871469439,
            -0.055921669454081195616,
            -0.98172662243325269638,
            -0.17807195900828559845,
            -0.067106007337265693857,
            0.055921672709938493622,
            0.067106004624051306436,
            -0.99617746946250462015,
        ],
        [
            0.60000000500001660114,
            -0.49999999399997999099,
            1.0000066613381356007e-9,
        ],
    ),
    (
        "Dzhanibekov at 100 s",
        [3.0, 5.0, 9.0],
        [0.0, 2.0, 0.01],
        ONE,
        100.0,
        [
            0.90360763519756924989,
            -0.040378815777717361307,
            -0.42645374057340120037,
            0.10246750613735214201,
            0.98701993422771327428,
            0.12366106753183179256,
            0.41592505550717705084,
            -0.15543873607794720332,
            0.89601626521388659649,
        ],
        [
            0.20909426282977605462,
            1.9724854810946470765,
            0.25628229771580245127,
        ],
    ),
    (
        // Integrated forward from (R0, -m0) by 7.3: time reversal maps (R(t), m(t)) to
        // (R(-t), -m(-t)).
        "Hairer-Vilmart backwards to -7.3 from a turned start",
        [0.6, 0.8, 1.0],
        [1.8, 0.4, -0.9],
        [0.5, 0.5, -0.5, 0.5],
        -7.3,
        [
            -0.26399063007789027378,
            0.25620025556202007592,
            -0.92987653819258935868,
            -0.67057024477753028359,
            0.64421186821039023499,
            0.36786766054640073892,
            0.69328529051904859705,
            0.72066115332161092178,
            0.0017343710917738873407,
        ],
        [
            1.7458304912029086602,
            0.81987949681435650147,
            -0.69990964180360344003,
        ],
    ),
];

#[test]
fn high_precision_references_agree_to_1e_13() {
    // Where the double-precision reference is limited by the conditioning of the problem
    // (the separatrix amplifies rounding by about exp(0.7 * 20) = 1e6), a 32-digit
    // solution shows that the exact flow itself stays at rounding level.
    for (name, j, m0, r0, t, rows, m_want) in HIGH_PRECISION {
        let (r, m) = exact_free_body(j, m0, r0, t);
        let want = [
            [rows[0], rows[1], rows[2]],
            [rows[3], rows[4], rows[5]],
            [rows[6], rows[7], rows[8]],
        ];
        let ea = mat_diff(&rotor_matrix(r), &want);
        let em = vec_diff(m, m_want) / norm(m0);
        println!("{name}: attitude {ea:e}, momentum {em:e}");
        assert!(ea < 1e-13 && em < 1e-13, "{name}: {ea:e} {em:e}");
    }
}

#[test]
fn extreme_but_valid_inputs_stay_finite_and_keep_invariants() {
    // Magnitudes from 1e-150 to 1e150, gaps down to one ulp, times up to 1e6: no panic,
    // finite output, |m| and |R| kept.
    let mut rng = Rng::new(41);
    let pow = |rng: &mut Rng, lo: f64, hi: f64| 10f64.powf(rng.uniform(lo, hi));
    for k in 0..3000 {
        let scale = pow(&mut rng, -150.0, 150.0);
        let mut j = [
            scale * rng.uniform(0.1, 1.0),
            scale * rng.uniform(0.1, 1.0),
            scale * rng.uniform(0.1, 1.0),
        ];
        match k % 5 {
            0 => j[1] = j[0] * (1.0 + f64::EPSILON),
            1 => j[2] = j[1] * (1.0 - f64::EPSILON / 2.0),
            2 => j[0] = scale * 1e-30,
            _ => {}
        }
        let size = pow(&mut rng, -100.0, 100.0);
        let mut m0 = [
            size * rng.uniform(-1.0, 1.0),
            size * rng.uniform(-1.0, 1.0),
            size * rng.uniform(-1.0, 1.0),
        ];
        if k % 7 == 0 {
            m0[k % 3] = 0.0;
        }
        if k % 11 == 0 {
            m0[(k + 1) % 3] = size * 1e-200;
        }
        // Keep |m| t / max(i) moderate so that the rotation angle is representable.
        let t = rng.uniform(-1e6, 1e6) * j[0].max(j[1]).max(j[2]) / norm(m0);
        let (r, m) = exact_free_body(j, m0, rotor(&mut rng), t);
        assert!(
            r.iter().chain(m.iter()).all(|x| x.is_finite()),
            "{j:?} {m0:?} {t}: {r:?} {m:?}"
        );
        let rn = r.iter().map(|x| x * x).sum::<f64>().sqrt();
        assert!((rn - 1.0).abs() < 1e-14, "{j:?} {m0:?} {t}: |R| = {rn}");
        assert!(
            (norm(m) - norm(m0)).abs() <= 1e-13 * norm(m0),
            "{j:?} {m0:?} {t}: {m:?}"
        );
    }
}
