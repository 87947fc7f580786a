//! `Even::log` returns `Option`: `None` off the rotors, and a chosen logarithm where it is
//! not unique (see docs/derivations/exp-log.md): `log(-1) = pi e12`, and in G4
//! `log(e1234) = pi/2 (e12 + e34)`, `log(-e1234) = pi/2 (e12 - e34)`. Before, all three
//! returned 0, and a non-unit value returned the log of its direction silently.

use std::f64::consts::{FRAC_PI_2, PI};

fn off(x: &[f64], y: &[f64]) -> f64 {
    x.iter()
        .zip(y)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max)
}

const U: f64 = f64::EPSILON;

#[test]
fn log_of_minus_one_is_a_full_turn_in_e12() {
    use ga_core::f64::g2;
    let b = (g2::Even::ONE * -1.0).log().expect("-1 is a rotor");
    assert_eq!(b, g2::Bivector::E12 * PI);
    assert!(off(&b.exp().to_array(), &[-1.0, 0.0]) <= 4.0 * U);
    use ga_core::f64::g3;
    let b = (g3::Even::ONE * -1.0).log().expect("-1 is a rotor");
    assert_eq!(b, g3::Bivector::E12 * PI);
    assert!(off(&b.exp().to_array(), &(g3::Even::ONE * -1.0).to_array()) <= 4.0 * U);
    use ga_core::f64::g4;
    let b = (g4::Even::ONE * -1.0).log().expect("-1 is a rotor");
    assert!(
        off(&b.to_array(), &(g4::Bivector::E12 * PI).to_array()) <= 4.0 * U,
        "{b:?}"
    );
}

#[test]
fn log_near_minus_one_keeps_the_plane_of_a_tiny_bivector_part() {
    use ga_core::f64::g3;
    for tiny in [1e-10, 1e-170, 1e-300] {
        let r = g3::Even::new(-1.0, 0.0, 0.0, tiny);
        let b = r.log().expect("a rotor");
        assert!((b.e23 - (PI - tiny)).abs() <= 4.0 * U, "{tiny}: {b:?}");
        assert_eq!((b.e12, b.e13), (0.0, 0.0));
    }
}

#[test]
fn log_of_plus_and_minus_e1234_inverts_exp_in_g4() {
    use ga_core::f64::g4;
    for (sign, expected) in [
        (
            1.0,
            g4::Bivector::new(FRAC_PI_2, 0.0, 0.0, 0.0, 0.0, FRAC_PI_2),
        ),
        (
            -1.0,
            g4::Bivector::new(FRAC_PI_2, 0.0, 0.0, 0.0, 0.0, -FRAC_PI_2),
        ),
    ] {
        let r = g4::Even {
            e1234: sign,
            ..g4::Even::ZERO
        };
        let b = r.log().expect("a rotor");
        assert!(off(&b.to_array(), &expected.to_array()) <= 4.0 * U, "{b:?}");
        assert!(off(&b.exp().to_array(), &r.to_array()) <= 4.0 * U, "{b:?}");
    }
}

#[test]
fn log_on_the_g4_boundary_a_plus_b_equal_pi_inverts_exp() {
    use ga_core::f64::g4;
    for a in [0.3, 1.0, 2.0, 3.0] {
        let r = g4::Bivector::new(a, 0.0, 0.0, 0.0, 0.0, PI - a).exp();
        let back = r.log().expect("a rotor").exp();
        assert!(
            off(&back.to_array(), &r.to_array()) <= 16.0 * U,
            "{a}: {back:?} {r:?}"
        );
    }
}

#[test]
fn log_of_a_value_that_is_not_a_rotor_is_none() {
    use ga_core::f64::{g2, g3, g4};
    assert_eq!((g2::Even::ONE * 2.0).log(), None);
    assert_eq!((g3::Even::ONE * 2.0).log(), None);
    assert_eq!(g3::Even::ZERO.log(), None);
    assert_eq!(g3::Even::new(f64::NAN, 0.0, 0.0, 0.0).log(), None);
    let r = (g3::Bivector::E12 * 0.4).exp();
    assert_eq!((r * 1.01).log(), None);
    assert!(
        (r * (1.0 + 1e-12)).log().is_some(),
        "rounding drift is accepted"
    );
    assert_eq!((g4::Even::ONE * 0.5).log(), None);
    // Unit scalar part sum but not a rotor: R ~R has a grade-4 part.
    let not_rotor = g4::Even {
        s: 0.6,
        e1234: 0.8,
        ..g4::Even::ZERO
    };
    assert_eq!(not_rotor.log(), None);
    use ga_core::f32::g3 as g;
    assert_eq!((g::Even::ONE * 2.0).log(), None);
    assert_eq!(
        (g::Even::ONE * -1.0).log(),
        Some(g::Bivector::E12 * std::f32::consts::PI)
    );
}
