//! Jacobi elliptic functions, elliptic integrals and Carlson's integrals against
//! published values (Abramowitz & Stegun, Carlson 1995), values from mpmath 1.3.0 at 40
//! digits (`mpmath.ellipfun`, `ellipk`, `ellipf`, `ellippi`, `elliprf/rd/rj`), the
//! end-to-end values of docs/references.md, limits and identities.

use ga_rigid::special::elliptic::{
    carlson_rd, carlson_rf, carlson_rj, ellip_f, ellip_k, ellip_pi, ellip_pi_jacobi, jacobi,
};

/// Assert `|got - want| <= tol`, printing the difference when it fails.
#[track_caller]
fn close(got: f64, want: f64, tol: f64) {
    let err = (got - want).abs();
    assert!(
        err <= tol,
        "got {got:e}, want {want:e}, |diff| = {err:e} > {tol:e}"
    );
}

/// Assert a relative error of at most `tol`.
#[track_caller]
fn close_rel(got: f64, want: f64, tol: f64) {
    let err = ((got - want) / want).abs();
    assert!(
        err <= tol,
        "got {got:e}, want {want:e}, relative diff {err:e} > {tol:e}"
    );
}

#[track_caller]
fn close3(got: (f64, f64, f64), want: (f64, f64, f64), tol: f64) {
    close(got.0, want.0, tol);
    close(got.1, want.1, tol);
    close(got.2, want.2, tol);
}

#[test]
fn jacobi_matches_reference_spot_values() {
    // docs/references.md, 10 digits.
    close3(
        jacobi(0.75, 0.5, 0.5),
        (0.6585147441, 0.7525678254, 0.8849741046),
        1e-10,
    );
    close3(
        jacobi(0.5, 0.25, 0.75),
        (0.4750829360, 0.8799410230, 0.9713773988),
        1e-10,
    );
    // mpmath, full precision.
    close3(
        jacobi(0.75, 0.5, 0.5),
        (
            0.658_514_744_129_996_7,
            0.752_567_825_357_558_7,
            0.884_974_104_639_058_1,
        ),
        4e-16,
    );
    close3(
        jacobi(3.0, 0.9, 0.1),
        (
            0.990_630_599_937_832_6,
            -0.136_568_717_013_853_34,
            0.341_739_539_737_691_07,
        ),
        2e-15,
    );
    close3(
        jacobi(-40.0, 0.3, 0.7),
        (
            0.880_653_697_940_564_4,
            0.473_760_555_875_654_5,
            0.875_976_437_634_644_8,
        ),
        2e-14,
    );
    close3(
        jacobi(100.0, 0.99, 0.01),
        (
            -0.999_759_109_358_704,
            0.021_948_194_784_326_194,
            0.102_356_758_554_322_27,
        ),
        2e-14,
    );
}

#[test]
fn jacobi_end_to_end_y12_matches_reference() {
    // y' = (y2 y3, -y1 y3, -0.51 y1 y2), y(0) = (0, 1, 1) is (sn, cn, dn)(t | 0.51).
    let want = (-0.705397809522572, -0.708811632467158, 0.863846690370222);
    close3(jacobi(12.0, 0.51, 0.49), want, 2e-15);
}

#[test]
fn jacobi_keeps_relative_precision_near_m_one() {
    // m1 passed exactly; m = 1 - m1 would have lost all of it.
    let (sn, cn, dn) = jacobi(1.0, 1.0 - 1e-10, 1e-10);
    close(sn, 0.761_594_155_964_305_4, 1e-15);
    close_rel(cn, 0.648_054_273_653_848_6, 1e-15);
    close_rel(dn, 0.648_054_273_698_599_9, 1e-15);
    let (sn, cn, dn) = jacobi(7.5, 1.0 - 1e-12, 1e-12);
    close(sn, 0.999_999_388_195_796_1, 2e-16);
    close_rel(cn, 0.001_106_168_175_913_165_8, 1e-13);
    close_rel(dn, 0.001_106_168_627_923_354_6, 1e-13);
    let (sn, cn, dn) = jacobi(25.0, 1.0, 1e-20);
    close(sn, 1.0, 2e-16);
    close_rel(cn, -6.223_023_644_180_43e-11, 1e-11);
    close_rel(dn, 1.177_820_119_016_603_8e-10, 1e-11);
    // Near the quarter period K(1 - 1e-10) = 12.899219826387599534..., where cn and dn
    // are small.
    let (sn, cn, dn) = jacobi(12.799_219_826_387_6, 1.0 - 1e-10, 1e-10);
    close(sn, 0.999_999_999_999_498_3, 2e-16);
    close_rel(cn, 1.001_667_500_198_105_6e-6, 1e-9);
    close_rel(dn, 1.005_004_168_055_301e-5, 1e-10);
}

#[test]
fn jacobi_limits_are_trigonometric_and_hyperbolic() {
    for k in 0..200 {
        let u = -25.0 + 0.25 * f64::from(k);
        close3(jacobi(u, 0.0, 1.0), (u.sin(), u.cos(), 1.0), 1e-15);
        let sech = 1.0 / u.cosh();
        close3(jacobi(u, 1.0, 0.0), (u.tanh(), sech, sech), 1e-16);
        // Just inside the limits, continuity.
        close3(jacobi(u, 1e-300, 1.0), (u.sin(), u.cos(), 1.0), 1e-14);
    }
}

#[test]
fn jacobi_satisfies_pythagorean_identities() {
    for &(m, m1) in &[
        (0.1, 0.9),
        (0.5, 0.5),
        (0.9, 0.1),
        (0.999, 0.001),
        (1.0 - 1e-9, 1e-9),
        (1.0, 1e-15),
    ] {
        for k in 0..400 {
            let u = -50.0 + 0.25 * f64::from(k) + 0.01;
            let (sn, cn, dn) = jacobi(u, m, m1);
            // m + m1 = 1 holds only to rounding for (1.0, 1e-15), hence a few ulps.
            close(sn * sn + cn * cn, 1.0, 2e-15);
            // dn^2 + m sn^2 = 1, in the cancellation-free form dn^2 = m1 + m cn^2.
            close(dn * dn, m1 + m * cn * cn, 1e-15);
        }
    }
}

#[test]
fn jacobi_derivatives_match_the_defining_ode() {
    // d sn/du = cn dn, d cn/du = -sn dn, d dn/du = -m sn cn, by central differences.
    let h = 1e-5;
    for &(m, m1) in &[(0.3, 0.7), (0.95, 0.05), (1.0 - 1e-8, 1e-8)] {
        for k in 0..60 {
            let u = -15.0 + 0.5 * f64::from(k) + 0.013;
            let p = jacobi(u + h, m, m1);
            let q = jacobi(u - h, m, m1);
            let (sn, cn, dn) = jacobi(u, m, m1);
            close((p.0 - q.0) / (2.0 * h), cn * dn, 1e-9);
            close((p.1 - q.1) / (2.0 * h), -sn * dn, 1e-9);
            close((p.2 - q.2) / (2.0 * h), -m * sn * cn, 1e-9);
        }
    }
}

#[test]
fn jacobi_non_finite_arguments_give_nan_not_panic() {
    let (s, c, d) = jacobi(f64::NAN, 0.5, 0.5);
    assert!(s.is_nan() && c.is_nan() && d.is_nan());
    let (s, _, _) = jacobi(f64::INFINITY, 0.5, 0.5);
    assert!(s.is_nan());
    let (s, c, d) = jacobi(1e300, 0.5, 0.5);
    assert!(s.is_finite() && c.is_finite() && d.is_finite());
    let (s, c, d) = jacobi(5e-324, 0.5, 0.5);
    assert_eq!((s, c, d), (5e-324, 1.0, 1.0));
}

#[test]
fn complete_k_matches_reference() {
    close(ellip_k(0.49), 1.862_640_802_332_739, 1e-15);
    close(ellip_k(1.0), std::f64::consts::FRAC_PI_2, 0.0);
    close(ellip_k(1e-12), 15.201_804_919_087_715, 4e-15);
    assert_eq!(ellip_k(0.0), f64::INFINITY);
    // K(m) = RF(0, 1 - m, 1).
    for &m1 in &[1e-10, 0.01, 0.3, 0.99] {
        close_rel(ellip_k(m1), carlson_rf(0.0, m1, 1.0), 4e-16);
    }
}

#[test]
fn incomplete_f_matches_mpmath_and_inverts_sn() {
    close(ellip_f(0.7, 0.5, 0.5), 0.728_770_305_718_190_3, 4e-16);
    close(ellip_f(4.0, 0.8, 0.2), 5.467_873_527_678_046, 4e-15);
    close(
        ellip_f(1.2, 1.0 - 1e-14, 1e-14),
        1.673_699_249_558_229_5,
        1e-15,
    );
    // F(am u) = u: am u = atan2(sn, cn) for |u| < K.
    for k in 0..20 {
        let u = -1.5 + 0.15 * f64::from(k);
        let (sn, cn, _) = jacobi(u, 0.7, 0.3);
        close(ellip_f(sn.atan2(cn), 0.7, 0.3), u, 1e-15);
    }
}

#[test]
fn incomplete_pi_matches_mpmath() {
    close(
        ellip_pi(-0.7, 1.1, 0.3, 0.7),
        0.963_112_109_332_581_2,
        4e-16,
    );
    close(ellip_pi(0.4, -5.0, 0.6, 0.4), -8.503_228_434_036_353, 1e-14);
    close(
        ellip_pi(-30.0, 1.5, 0.9, 0.1),
        0.318_731_750_981_621_3,
        1e-15,
    );
    close(
        ellip_pi(-0.5, std::f64::consts::FRAC_PI_2, 0.7, 0.3),
        1.645_042_868_400_853,
        1e-15,
    );
    // Large negative characteristic, where Pi is far smaller than F.
    close_rel(
        ellip_pi(-1e6, 0.7, 0.9, 0.1),
        0.001_569_962_110_327_638,
        1e-14,
    );
    close_rel(
        ellip_pi(-3.0, -1.3, 0.0, 1.0),
        -0.716_434_917_731_311_6,
        1e-15,
    );
    assert!(ellip_pi(1.5, 0.3, 0.5, 0.5).is_nan());
}

#[test]
fn pi_in_jacobi_form_matches_quadrature() {
    // integral_0^u dv / (1 - n sn^2 v) by composite Gauss-Legendre (5 points) on 2000
    // panels, against the closed form, across several half periods.
    let nodes = [
        (0.0, 0.568_888_888_888_888_9),
        (-0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
        (0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
        (-0.906_179_845_938_664, 0.236_926_885_056_189_08),
        (0.906_179_845_938_664, 0.236_926_885_056_189_08),
    ];
    for &(n, m, m1, u) in &[
        (-0.8, 0.5, 0.5, 9.3),
        (-40.0, 0.9, 0.1, -7.1),
        (0.6, 0.2, 0.8, 5.0),
        (-2.0, 1.0 - 1e-6, 1e-6, 31.0),
        (-3.0, 1.0, 0.0, 6.0),
    ] {
        let panels = 2000;
        let h = u / f64::from(panels);
        let mut sum = 0.0;
        for p in 0..panels {
            let mid = (f64::from(p) + 0.5) * h;
            for &(x, w) in &nodes {
                let (sn, _, _) = jacobi(mid + 0.5 * h * x, m, m1);
                sum += 0.5 * h * w / (1.0 - n * sn * sn);
            }
        }
        close_rel(ellip_pi_jacobi(n, u, m, m1), sum, 1e-13);
    }
}

#[test]
fn carlson_integrals_match_carlson_1995_tables() {
    // Carlson (1995), section 3 test values, and mpmath for the extreme arguments.
    close(carlson_rf(1.0, 2.0, 0.0), 1.311_028_777_146_059_9, 4e-16);
    close(carlson_rf(2.0, 3.0, 4.0), 0.584_082_841_677_151_7, 2e-16);
    close_rel(carlson_rf(1e-30, 1e-20, 1.0), 24.412_135_291_110_347, 4e-16);
    close(carlson_rd(0.0, 2.0, 1.0), 1.797_210_352_103_388_3, 1e-15);
    close(carlson_rd(2.0, 3.0, 4.0), 0.165_105_272_942_610_53, 2e-16);
    close_rel(carlson_rd(1e-3, 5.0, 0.2), 6.054_853_823_635_226, 4e-16);
    close(
        carlson_rj(0.0, 1.0, 2.0, 3.0),
        0.776_886_237_785_823_3,
        4e-16,
    );
    close(
        carlson_rj(2.0, 3.0, 4.0, 5.0),
        0.142_975_796_671_567_54,
        2e-16,
    );
    // Small p: the RC terms lose a few digits to cancellation.
    close_rel(
        carlson_rj(2.0, 3.0, 4.0, 1e-3),
        2.245_320_511_585_673,
        1e-14,
    );
    close_rel(
        carlson_rj(0.5, 1.0, 2.0, 1000.0),
        0.002_763_690_091_738_657_4,
        1e-15,
    );
    // RD is RJ with p = z, and RF(x, x, x) = 1/sqrt(x).
    close_rel(
        carlson_rd(0.3, 1.7, 2.9),
        carlson_rj(0.3, 1.7, 2.9, 2.9),
        4e-16,
    );
    close_rel(carlson_rf(4.0, 4.0, 4.0), 0.5, 2e-16);
    assert_eq!(carlson_rf(0.0, 0.0, 1.0), f64::INFINITY);
    assert!(carlson_rf(-1.0, 1.0, 1.0).is_nan());
    assert!(carlson_rj(1.0, 1.0, 1.0, -1.0).is_nan());
}
