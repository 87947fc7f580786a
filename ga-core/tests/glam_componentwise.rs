//! glam's component-wise `Vec3` names on G3's `Vector` (`glam_componentwise.rs`), checked
//! against glam itself, bit for bit (NaN against NaN, and the sign of zero), on edge
//! cases in f32 and f64: glam 0.32 for its names, glam 0.33 for the names it added (with
//! the feature `glam-0-33`, as CI's `--all-features` run has it). `slerp` takes its angle
//! from `atan2` where glam uses a polynomial `acos`, so it is held to a tolerance.

macro_rules! componentwise_tests {
    ($name:ident, $s:ident, $vec3:ident, $tol:expr) => {
        mod $name {
            use ga_core::glam::$vec3;
            use ga_core::$s::g3::*;
            use ga_test_rng::Rng;

            /// The same bits in every component, any NaN matching any NaN.
            fn same(a: Vector, b: $vec3) -> bool {
                a.to_array()
                    .iter()
                    .zip(b.to_array().iter())
                    .all(|(x, y)| x.to_bits() == y.to_bits() || (x.is_nan() && y.is_nan()))
            }

            fn same_scalar(a: $s, b: $s) -> bool {
                a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan())
            }

            /// Zeros of both signs, halves (where rounding modes differ), integers,
            /// infinities, NaN, the largest and a subnormal, and seeded vectors.
            fn vectors(rng: &mut Rng) -> Vec<Vector> {
                let mut v = vec![
                    Vector::ZERO,
                    Vector::new(-0.0, 0.0, -0.0),
                    Vector::new(2.5, -2.5, 0.5),
                    Vector::new(-1.5, 3.0, -7.0),
                    Vector::new(0.49999997, -0.49999997, 1e-3),
                    Vector::new($s::INFINITY, $s::NEG_INFINITY, 1.0),
                    Vector::new($s::NAN, -1.0, 2.0),
                    Vector::splat($s::MAX),
                    Vector::new($s::MIN_POSITIVE / 4.0, -1e-30, 1e30),
                    Vector::X,
                    -Vector::Y,
                ];
                for scale in [0.1, 1.0, 7.0, 1e4] {
                    v.extend((0..10).map(|_| {
                        Vector::new(rng.signed() as $s, rng.signed() as $s, rng.signed() as $s)
                            * scale
                    }));
                }
                v
            }

            #[test]
            fn unary_functions_are_glams_bit_for_bit() {
                let mut rng = Rng::new(0x51ed_2701);
                for a in vectors(&mut rng) {
                    let g = $vec3::from(a);
                    let cases: [(&str, Vector, $vec3); 20] = [
                        ("floor", a.floor(), g.floor()),
                        ("ceil", a.ceil(), g.ceil()),
                        ("round", a.round(), g.round()),
                        ("trunc", a.trunc(), g.trunc()),
                        ("fract", a.fract(), g.fract()),
                        ("fract_gl", a.fract_gl(), g.fract_gl()),
                        ("signum", a.signum(), g.signum()),
                        ("recip", a.recip(), g.recip()),
                        ("sqrt", a.sqrt(), g.sqrt()),
                        ("exp", a.exp(), g.exp()),
                        ("exp2", a.exp2(), g.exp2()),
                        ("ln", a.ln(), g.ln()),
                        ("log2", a.log2(), g.log2()),
                        ("powf", a.powf(1.7), g.powf(1.7)),
                        ("sin", a.sin(), g.sin()),
                        ("cos", a.cos(), g.cos()),
                        ("saturate", a.saturate(), g.saturate()),
                        ("map", a.map(|c| c * 3.0 - 1.0), g.map(|c| c * 3.0 - 1.0)),
                        ("with_y", a.with_y(-4.0), g.with_y(-4.0)),
                        (
                            "with_x z",
                            a.with_x(9.0).with_z(0.25),
                            g.with_x(9.0).with_z(0.25),
                        ),
                    ];
                    for (name, ours, theirs) in cases {
                        assert!(
                            same(ours, theirs),
                            "{name} of {a:?}: {ours:?} vs {theirs:?}"
                        );
                    }
                    let (s, c) = a.sin_cos();
                    let (gs, gc) = g.sin_cos();
                    assert!(same(s, gs) && same(c, gc), "sin_cos of {a:?}");
                    assert!(same_scalar(a.element_sum(), g.element_sum()), "{a:?}");
                    assert!(
                        same_scalar(a.element_product(), g.element_product()),
                        "{a:?}"
                    );
                    assert_eq!(a.max_position(), g.max_position(), "{a:?}");
                    assert_eq!(a.min_position(), g.min_position(), "{a:?}");
                    assert_eq!(a.is_negative_bitmask(), g.is_negative_bitmask(), "{a:?}");
                    assert_eq!(a.is_nan_mask(), g.is_nan_mask(), "{a:?}");
                    assert_eq!(a.is_finite_mask(), g.is_finite_mask(), "{a:?}");
                    assert_eq!(a.try_normalize().is_some(), g.try_normalize().is_some());
                    if let (Some(ours), Some(theirs)) = (a.try_normalize(), g.try_normalize()) {
                        assert!(same(ours, theirs), "try_normalize of {a:?}");
                    }
                    let (n, l) = a.normalize_and_length();
                    let (gn, gl) = g.normalize_and_length();
                    assert!(
                        same(n, gn) && same_scalar(l, gl),
                        "normalize_and_length {a:?}"
                    );
                    for limit in [0.0, 0.5, 3.0, 1e6] {
                        let (ours, theirs) = (a.clamp_length_max(limit), g.clamp_length_max(limit));
                        assert!(same(ours, theirs), "clamp_length_max {a:?} {limit}");
                        let (ours, theirs) = (a.clamp_length_min(limit), g.clamp_length_min(limit));
                        assert!(same(ours, theirs), "clamp_length_min {a:?} {limit}");
                        let (ours, theirs) = (
                            a.clamp_length(limit, 2.0 * limit),
                            g.clamp_length(limit, 2.0 * limit),
                        );
                        assert!(same(ours, theirs), "clamp_length {a:?} {limit}");
                    }
                    let (t, gt) = (a.truncate(), g.truncate());
                    assert!(same(
                        Vector::new(t.x, t.y, 0.0),
                        $vec3::new(gt.x, gt.y, 0.0)
                    ));
                    let (h, gh) = (a.to_homogeneous(), g.to_homogeneous());
                    assert!(same(
                        Vector::new(h.x, h.y, h.w),
                        $vec3::new(gh.x, gh.y, gh.w)
                    ));
                    let h = g.extend(-2.0);
                    assert!(same(
                        Vector::from_homogeneous(h),
                        $vec3::from_homogeneous(h)
                    ));
                }
            }

            #[test]
            fn binary_functions_are_glams_bit_for_bit() {
                let mut rng = Rng::new(0x7a11_05e3);
                let all = vectors(&mut rng);
                for &a in &all {
                    for &b in &all {
                        let (ga, gb) = ($vec3::from(a), $vec3::from(b));
                        let c = b * 0.5 - Vector::ONE;
                        let gc = $vec3::from(c);
                        let cases: [(&str, Vector, $vec3); 11] = [
                            ("copysign", a.copysign(b), ga.copysign(gb)),
                            ("rem_euclid", a.rem_euclid(b), ga.rem_euclid(gb)),
                            ("div_euclid", a.div_euclid(b), ga.div_euclid(gb)),
                            ("mul_add", a.mul_add(b, c), ga.mul_add(gb, gc)),
                            ("midpoint", a.midpoint(b), ga.midpoint(gb)),
                            (
                                "move_towards",
                                a.move_towards(b, 0.75),
                                ga.move_towards(gb, 0.75),
                            ),
                            ("dot_into_vec", a.dot_into_vec(b), ga.dot_into_vec(gb)),
                            ("step", a.step(b), ga.step(gb)),
                            ("clamp", a.clamp(c, c + Vector::ONE), {
                                // glam asserts `min <= max` only with `glam-assert`.
                                ga.clamp(gc, gc + $vec3::ONE)
                            }),
                            (
                                "select",
                                Vector::select(a.cmplt(b), a, b),
                                $vec3::select(ga.cmplt(gb), ga, gb),
                            ),
                            ("refract", a.refract(b, 0.8), ga.refract(gb, 0.8)),
                        ];
                        for (name, ours, theirs) in cases {
                            assert!(
                                same(ours, theirs),
                                "{name} of {a:?}, {b:?}: {ours:?} vs {theirs:?}"
                            );
                        }
                        assert_eq!(a.cmpeq(b), ga.cmpeq(gb));
                        assert_eq!(a.cmpne(b), ga.cmpne(gb));
                        assert_eq!(a.cmpge(b), ga.cmpge(gb));
                        assert_eq!(a.cmpgt(b), ga.cmpgt(gb));
                        assert_eq!(a.cmple(b), ga.cmple(gb));
                    }
                }
            }

            /// glam's `slerp`: its length goes linearly and its direction along the arc,
            /// the opposite case turns about glam's axis. Held to glam's f64 `slerp` of
            /// the same inputs: within `TOL` of their lengths, or no farther from it
            /// than glam's own result in this precision (near opposite vectors glam's
            /// polynomial `acos` is the less accurate of the two).
            #[test]
            fn slerp_is_glams_to_its_acos_approximation() {
                use ga_core::glam::DVec3;
                let tol: $s = $tol;
                let mut rng = Rng::new(0x5e1e_7f00);
                let mut pairs = vec![
                    (Vector::X, Vector::Y),
                    (Vector::X * 2.0, -Vector::X),
                    (Vector::new(1.0, 1e-4, 0.0), -Vector::X * 3.0),
                    (Vector::Z, Vector::Z * 5.0),
                    (Vector::ZERO, Vector::Y),
                ];
                for _ in 0..200 {
                    let mut v =
                        || Vector::new(rng.signed() as $s, rng.signed() as $s, rng.signed() as $s);
                    let (a, b) = (v(), v());
                    pairs.push((a, b));
                }
                let wide = |v: Vector| DVec3::new(v.e1 as f64, v.e2 as f64, v.e3 as f64);
                let distance = |a: DVec3, b: DVec3| {
                    let d = (a - b).length();
                    if d.is_nan() {
                        f64::INFINITY
                    } else {
                        d
                    }
                };
                for (a, b) in pairs {
                    for s in [0.0, 0.3, 0.5, 1.0, 1.5] {
                        let ours = a.slerp(b, s);
                        let theirs = $vec3::from(a).slerp($vec3::from(b), s);
                        let reference = wide(a).slerp(wide(b), s as f64);
                        let scale = (1.0 + a.length() + b.length()) as f64;
                        let gap = distance(wide(ours), reference);
                        let glam_gap = distance(wide(Vector::from(theirs)), reference);
                        assert!(
                            gap <= (tol as f64 * scale).max(glam_gap)
                                || (ours.is_nan() && theirs.is_nan()),
                            "{a:?} {b:?} {s}: {ours:?} vs {theirs:?}, reference {reference:?}"
                        );
                    }
                }
                // The arc: halfway between perpendicular unit vectors, unit length.
                let half = Vector::X.slerp(Vector::Y, 0.5);
                assert!((half.length() - 1.0).abs() < tol && (half.x - half.y).abs() < tol);
            }

            /// The names glam 0.33 added, against glam 0.33.
            #[cfg(feature = "glam-0-33")]
            #[test]
            fn glam_0_33_names_are_its_own() {
                use ga_core::glam_0_33::$vec3 as New;
                let mut rng = Rng::new(0x0033_0033);
                let all = vectors(&mut rng);
                let new = |v: Vector| New::new(v.e1, v.e2, v.e3);
                let same_new = |a: Vector, b: New| same(a, $vec3::from_array(b.to_array()));
                for &a in &all {
                    assert_eq!(
                        a.is_negative_mask().bitmask(),
                        new(a).is_negative_mask().bitmask()
                    );
                    for &b in &all {
                        for s in [0.0, 0.25, 1.0, -2.0] {
                            let ours = a.lerp_monotonic(b, s);
                            assert!(
                                same_new(ours, new(a).lerp_monotonic(new(b), s)),
                                "{a:?} {b:?}"
                            );
                        }
                        let (lo, hi) = (b.min(b * 2.0), b.max(b * 2.0) + Vector::ONE);
                        assert!(same_new(
                            a.smoothstep(lo, hi),
                            new(a).smoothstep(new(lo), new(hi))
                        ));
                        let axis = a.cross(b).normalize_or(Vector::Z);
                        let (ours, theirs) =
                            (a.angle_to(b, axis), new(a).angle_to(new(b), new(axis)));
                        assert!(same_scalar(ours, theirs), "{a:?} {b:?}: {ours} vs {theirs}");
                    }
                }
            }
        }
    };
}

componentwise_tests!(f32_componentwise, f32, Vec3, 2e-6);
componentwise_tests!(f64_componentwise, f64, DVec3, 1e-13);
