//! The `serde`, `bytemuck`, `approx` and `mint` features: values survive a round trip,
//! bytes are the components in canonical order, tolerances compare component-wise, and
//! mint's quaternions and matrices agree with glam's conversions and hand-computed values.
//! Run with `cargo test -p ga-core --all-features`.

#[cfg(all(feature = "serde", feature = "f64", feature = "f32", feature = "g3"))]
mod serde_round_trip {
    use std::collections::BTreeMap;

    use ga_core::f64::g3::{Bivector, Multivector, Rotor, Vector};

    #[test]
    fn json_is_a_struct_of_named_blades_and_reads_back() {
        let v = Vector::new(1.0, -2.5, 3.0);
        let json = serde_json::to_string(&v).unwrap();
        assert_eq!(json, r#"{"e1":1.0,"e2":-2.5,"e3":3.0}"#);
        assert_eq!(serde_json::from_str::<Vector>(&json).unwrap(), v);

        let r = (Bivector::new(0.3, -0.2, 0.7) * -0.5).exp();
        let json = serde_json::to_string(&r).unwrap();
        assert!(json.starts_with(r#"{"s":"#) && json.contains(r#""e23":"#));
        assert_eq!(serde_json::from_str::<Rotor>(&json).unwrap(), r);

        let m = Multivector::from_array([1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0]);
        let back: Multivector = serde_json::from_str(&serde_json::to_string(&m).unwrap()).unwrap();
        assert_eq!(back, m);
    }

    #[test]
    fn blades_in_any_order_or_as_a_sequence_in_canonical_order() {
        let v: Vector = serde_json::from_str(r#"{"e3":3.0,"e1":1.0,"e2":2.0}"#).unwrap();
        assert_eq!(v, Vector::new(1.0, 2.0, 3.0));
        let v: Vector = serde_json::from_str("[1.0, 2.0, 3.0]").unwrap();
        assert_eq!(v, Vector::new(1.0, 2.0, 3.0));
    }

    #[test]
    fn unknown_repeated_and_missing_blades_are_errors_naming_the_blade() {
        let unknown = serde_json::from_str::<Vector>(r#"{"e1":1,"e2":2,"e4":3}"#).unwrap_err();
        assert!(
            unknown.to_string().contains("unknown field `e4`"),
            "{unknown}"
        );
        let repeated = serde_json::from_str::<Vector>(r#"{"e1":1,"e1":2,"e3":3}"#).unwrap_err();
        assert!(
            repeated.to_string().contains("duplicate field `e1`"),
            "{repeated}"
        );
        let missing = serde_json::from_str::<Vector>(r#"{"e1":1,"e3":3}"#).unwrap_err();
        assert!(
            missing.to_string().contains("missing field `e2`"),
            "{missing}"
        );
        let short = serde_json::from_str::<Vector>("[1.0, 2.0]").unwrap_err();
        assert!(short.to_string().contains("invalid length 2"), "{short}");
    }

    #[test]
    fn a_scene_of_rotors_round_trips_through_toml() {
        let mut scene = BTreeMap::new();
        scene.insert("body".to_owned(), (Bivector::E12 * -0.4).exp());
        scene.insert(
            "wheel".to_owned(),
            (Bivector::new(1.0, 2.0, -1.0) * 0.1).exp(),
        );
        let text = toml::to_string(&scene).unwrap();
        assert!(text.contains("[body]\ns = "), "{text}");
        let back: BTreeMap<String, Rotor> = toml::from_str(&text).unwrap();
        assert_eq!(back, scene);

        let v: Vector = toml::from_str("e1 = 0.5\ne2 = 1.5\ne3 = -2.0\n").unwrap();
        assert_eq!(v, Vector::new(0.5, 1.5, -2.0));
    }

    #[test]
    fn single_precision_round_trips() {
        let r = ga_core::f32::g3::Rotor::new(0.5, 0.5, -0.5, 0.5);
        let json = serde_json::to_string(&r).unwrap();
        assert_eq!(json, r#"{"s":0.5,"e12":0.5,"e13":-0.5,"e23":0.5}"#);
        assert_eq!(
            serde_json::from_str::<ga_core::f32::g3::Rotor>(&json).unwrap(),
            r
        );
    }
}

#[cfg(all(feature = "bytemuck", feature = "f64", feature = "f32", feature = "g3"))]
mod bytemuck_casts {
    use ga_core::f64::g3::Vector;

    #[test]
    fn a_slice_of_vectors_is_its_components_in_order() {
        let vectors = [Vector::new(1.0, 2.0, 3.0), Vector::new(-4.0, 5.5, 0.25)];
        let bytes: &[u8] = bytemuck::cast_slice(&vectors);
        let expected: Vec<u8> = [1.0f64, 2.0, 3.0, -4.0, 5.5, 0.25]
            .iter()
            .flat_map(|x| x.to_ne_bytes())
            .collect();
        assert_eq!(bytes, expected.as_slice());

        let floats = [0.5f32, 0.5, -0.5, 0.5, 1.0, 0.0, 0.0, 0.0];
        let rotors: &[ga_core::f32::g3::Rotor] = bytemuck::cast_slice(&floats);
        assert_eq!(rotors.len(), 2);
        assert_eq!(rotors[0], ga_core::f32::g3::Rotor::new(0.5, 0.5, -0.5, 0.5));
        assert_eq!(rotors[1], ga_core::f32::g3::Rotor::ONE);
        let zero: ga_core::f64::g3::Multivector = bytemuck::Zeroable::zeroed();
        assert_eq!(zero, ga_core::f64::g3::Multivector::ZERO);
    }
}

#[cfg(all(feature = "approx", feature = "f64", feature = "g3"))]
mod approx_comparisons {
    use approx::{abs_diff_eq, assert_relative_eq, assert_ulps_eq, relative_ne};
    use ga_core::f64::g3::{Bivector, Sandwich, Vector};

    #[test]
    fn a_quarter_turn_is_close_to_but_not_exactly_the_hand_value() {
        let r = (Bivector::E12 * (-std::f64::consts::FRAC_PI_4)).exp();
        let y = r.sandwich(Vector::new(1.0, 0.0, 2.0));
        // e1 turns to e2, e3 stays: (0, 1, 2) up to rounding.
        assert_relative_eq!(y, Vector::new(0.0, 1.0, 2.0), epsilon = 1e-15);
        assert_ulps_eq!(y.e3, 2.0);
        assert!(abs_diff_eq!(y, Vector::new(0.0, 1.0, 2.0), epsilon = 1e-12));
        // One component off by 1e-6 is outside the default tolerances.
        assert!(relative_ne!(y, Vector::new(1e-6, 1.0, 2.0)));
        assert!(!abs_diff_eq!(y, Vector::new(0.0, 1.0, 2.0 + 1e-6)));
    }
}

#[cfg(all(
    feature = "mint",
    feature = "glam",
    feature = "f64",
    feature = "f32",
    feature = "g3"
))]
mod mint_conversions {
    use ga_core::f64::g3::{Bivector, Rotor, Vector};
    use ga_core::glam;

    #[test]
    fn vectors_both_ways() {
        let m: mint::Vector3<f64> = Vector::new(1.0, 2.0, 3.0).into();
        assert_eq!((m.x, m.y, m.z), (1.0, 2.0, 3.0));
        assert_eq!(Vector::from(m), Vector::new(1.0, 2.0, 3.0));
        let m32 = mint::Vector3 {
            x: 1.0f32,
            y: -1.0,
            z: 0.5,
        };
        assert_eq!(
            ga_core::f32::g3::Vector::from(m32).to_array(),
            [1.0, -1.0, 0.5]
        );
    }

    #[test]
    fn quaternions_match_glam_and_round_trip() {
        let r = (Bivector::new(0.3, -1.1, 0.4) * -0.35).exp();
        let q: mint::Quaternion<f64> = r.into();
        let g: glam::DQuat = r.into();
        assert_eq!([q.v.x, q.v.y, q.v.z, q.s], g.to_array());
        assert_eq!(Rotor::from(q), r);
        // Through glam's own mint support: the same rotation.
        let via_glam: glam::DQuat = glam::DQuat::from_xyzw(q.v.x, q.v.y, q.v.z, q.s);
        assert_eq!(Rotor::from(via_glam), r);
    }

    #[test]
    fn the_rotation_matrix_matches_glam_and_the_hand_value() {
        let r = (Bivector::new(0.3, -1.1, 0.4) * -0.35).exp();
        let m: mint::ColumnMatrix3<f64> = r.into();
        let g: glam::DMat3 = r.into();
        let ours = [m.x, m.y, m.z].map(|c| [c.x, c.y, c.z]);
        for (column, expected) in ours.iter().zip(g.to_cols_array_2d()) {
            for (a, b) in column.iter().zip(expected) {
                assert!((a - b).abs() < 1e-15, "{ours:?} against {g:?}");
            }
        }
        // A quarter turn in e12 sends e1 to e2 and e2 to -e1.
        let quarter = (Bivector::E12 * (-std::f64::consts::FRAC_PI_4)).exp();
        let m: mint::ColumnMatrix3<f64> = quarter.into();
        let rounded = [m.x, m.y, m.z].map(|c| [c.x, c.y, c.z].map(|v| v.round()));
        assert_eq!(
            rounded,
            [[0.0, 1.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]
        );
    }
}
