//! The rotation exponential's own `sin_cos` (one reduction by pi/2 and two series, emitted
//! into each algebra) against the standard library's `sin` and `cos`: `exp(t e12)` is
//! `cos t + sin t e12`, at random angles, next to every multiple of pi/2 up to the
//! reduction's limit of 2^19, where the reduced angle is tiny and the quadrant changes,
//! and beyond it, where the library's own reduction takes over.

/// The ulps between `a` and `b`, measured at the larger of the two, and never at less
/// than 1/2: a rotor's components are measured against its norm, 1, so near a zero of
/// `cos` or `sin` an error counts in ulps of 1/2 (the series of the small angles is exact
/// to rounding in that sense, not relative to the tiny value itself).
fn ulps64(a: f64, b: f64) -> f64 {
    let scale = a.abs().max(b.abs()).max(0.5);
    (a - b).abs() / (scale * f64::EPSILON)
}

fn ulps32(a: f32, b: f32) -> f32 {
    let scale = a.abs().max(b.abs()).max(0.5);
    (a - b).abs() / (scale * f32::EPSILON)
}

/// Angles that stress the reduction: random ones in [-20, 20], both sides of k pi/2 for
/// k up to past the limit, tiny ones, and huge ones.
fn angles() -> Vec<f64> {
    let mut rng = ga_test_rng::Rng::new(0x9E37_79B9_7F4A_7C15);
    let mut out: Vec<f64> = (0..20_000).map(|_| rng.uniform(-20.0, 20.0)).collect();
    let mut k = 1.0_f64;
    while k < 1.5e6 {
        let centre = k * core::f64::consts::FRAC_PI_2;
        let mut x = centre;
        for _ in 0..4 {
            out.extend([x, -x]);
            x = f64::from_bits(x.to_bits() + 1);
        }
        let mut x = centre;
        for _ in 0..4 {
            x = f64::from_bits(x.to_bits() - 1);
            out.extend([x, -x]);
        }
        k = (k * 1.37).ceil();
    }
    out.extend([
        0.0, -0.0, 1e-300, 1e-20, 1e-9, 0.5, 524_287.9, 524_288.0, 524_288.1, 1e7, 1e15, 1e300,
    ]);
    out
}

#[test]
fn f64_exp_of_a_plane_angle_is_cos_plus_sin() {
    use ga_core::f64::g3::Bivector;
    let mut worst = (0.0_f64, 0.0_f64);
    for t in angles() {
        let r = (Bivector::E12 * t).exp();
        let (cos, sin) = (t.cos(), t.sin());
        let (dc, ds) = (ulps64(r.s, cos), ulps64(r.e12, sin));
        assert!(
            dc <= 2.0,
            "cos({t:e}): {:e} against {cos:e} ({dc} ulp)",
            r.s
        );
        assert!(
            ds <= 4.0,
            "sin({t:e}): {:e} against {sin:e} ({ds} ulp)",
            r.e12
        );
        assert!(r.e13 == 0.0 && r.e23 == 0.0);
        worst = (worst.0.max(dc), worst.1.max(ds));
    }
    // The series and the reduction are good to about an ulp; a wrong coefficient or a
    // wrong piece of pi/2 would show as thousands.
    assert!(worst.0 <= 2.0 && worst.1 <= 4.0, "{worst:?}");
}

#[test]
fn f32_exp_of_a_plane_angle_is_cos_plus_sin() {
    use ga_core::f32::g3::Bivector;
    // 1e300 and friends overflow to infinity in f32: not an angle.
    for t in angles()
        .into_iter()
        .map(|t| t as f32)
        .filter(|t| t.is_finite())
    {
        let r = (Bivector::E12 * t).exp();
        // The reference in f64, rounded once.
        let (cos, sin) = (f64::from(t).cos() as f32, f64::from(t).sin() as f32);
        let (dc, ds) = (ulps32(r.s, cos), ulps32(r.e12, sin));
        assert!(
            dc <= 1.0,
            "cos({t:e}): {:e} against {cos:e} ({dc} ulp)",
            r.s
        );
        assert!(
            ds <= 2.0,
            "sin({t:e}): {:e} against {sin:e} ({ds} ulp)",
            r.e12
        );
    }
}

#[test]
fn exp_is_unit_in_every_plane_at_every_angle() {
    use ga_core::f64::g3::Bivector;
    for t in angles() {
        for plane in [
            Bivector::new(0.6, 0.0, 0.8),
            Bivector::new(0.48, -0.6, 0.64),
        ] {
            let r = (plane * t).exp();
            let norm = (r.s * r.s + r.e12 * r.e12) + (r.e13 * r.e13 + r.e23 * r.e23);
            assert!(
                (norm - 1.0).abs() <= 6.0 * f64::EPSILON,
                "t = {t:e}: {norm}"
            );
        }
    }
}
