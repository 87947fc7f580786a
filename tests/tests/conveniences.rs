//! The conveniences every generated type gets (`Display`, indexing, iteration, array
//! conversions, `Sum`/`Product`, reference operators, division, precision casts), checked
//! by construction (what is printed parses back to the same value, an index reads the
//! field of that position) and, for division, against the reference algebra.

use ga_core::f64::g3::*;
use ga_tests::{assert_close, Algebra};

use ga_test_rng::Rng;

/// A value in [-4, 4), or about one time in seven an exact zero (which `Display` leaves
/// out), from the workspace's seeded generator.
fn value(rng: &mut Rng) -> f64 {
    if rng.next_u64().is_multiple_of(7) {
        0.0
    } else {
        rng.uniform(-4.0, 4.0)
    }
}

/// `N` values of [`value`].
fn array<const N: usize>(rng: &mut Rng) -> [f64; N] {
    std::array::from_fn(|_| value(rng))
}

/// Reads `Display`'s `1 + 2 e1 - 0.5 e12` back into (blade name, value) pairs: a space
/// separates each coefficient (in exponent notation below 1e-5 and from 1e16) from its blade.
fn parse_terms(text: &str) -> Vec<(String, f64)> {
    if text == "0" {
        return Vec::new();
    }
    let mut terms = Vec::new();
    let mut sign = 1.0;
    let mut rest = text;
    if let Some(stripped) = rest.strip_prefix('-') {
        sign = -1.0;
        rest = stripped;
    }
    loop {
        let (term, next) = match (rest.find(" + "), rest.find(" - ")) {
            (Some(p), Some(m)) if p < m => (&rest[..p], Some((1.0, &rest[p + 3..]))),
            (_, Some(m)) => (&rest[..m], Some((-1.0, &rest[m + 3..]))),
            (Some(p), None) => (&rest[..p], Some((1.0, &rest[p + 3..]))),
            (None, None) => (rest, None),
        };
        let (number, blade) = term.split_once(' ').unwrap_or((term, ""));
        let value: f64 = number.parse().expect("a decimal coefficient");
        terms.push((blade.to_owned(), sign * value));
        match next {
            Some((s, r)) => {
                sign = s;
                rest = r;
            }
            None => return terms,
        }
    }
}

fn g3_blade_names() -> [&'static str; 8] {
    ["", "e1", "e2", "e3", "e12", "e13", "e23", "e123"]
}

#[test]
fn display_writes_terms_in_canonical_order_with_signs() {
    let m = Multivector::from_array([1.0, 2.0, 0.0, 0.0, -0.5, 0.0, 0.0, 0.0]);
    assert_eq!(m.to_string(), "1 + 2 e1 - 0.5 e12");
    assert_eq!(Vector::new(-1.0, 0.0, 3.0).to_string(), "-1 e1 + 3 e3");
    assert_eq!(Multivector::ZERO.to_string(), "0");
    assert_eq!(Bivector::ZERO.to_string(), "0");
    assert_eq!(Even::ONE.to_string(), "1");
    assert_eq!(Trivector::new(-2.0).to_string(), "-2 e123");
}

#[test]
fn display_honours_precision_and_drops_terms_that_round_to_zero() {
    let v = Vector::new(1.0 / 3.0, -2.0 / 3.0, 1e-9);
    assert_eq!(format!("{v:.3}"), "0.333 e1 - 0.667 e2");
    assert_eq!(
        format!("{v:.12}"),
        "0.333333333333 e1 - 0.666666666667 e2 + 0.000000001000 e3"
    );
    assert_eq!(format!("{:.2}", Vector::new(1e-5, 0.0, 0.0)), "0");
    let g2 = ga_core::f32::g2::Even::new(0.5, -0.25);
    assert_eq!(format!("{g2:.1}"), "0.5 - 0.2 e12");
}

#[test]
fn display_rounds_like_the_formatter_and_keeps_exponents_apart_from_blades() {
    // Each failed before: `{:.1}` of 0.05 printed "0" (0.05 rounds up to 0.1), a
    // subnormal printed about 330 digits, and `1e12` read as ten to the twelfth.
    assert_eq!(format!("{:.1}", Vector::new(0.05, 0.0, 0.0)), "0.1 e1");
    assert_eq!(format!("{:.1}", Vector::new(0.04, 0.0, 0.0)), "0");
    assert_eq!(
        format!("{:.1}", ga_core::f32::g3::Vector::new(0.05, 0.0, 0.0)),
        "0.1 e1"
    );
    assert_eq!(Vector::new(5e-324, 0.0, 0.0).to_string(), "5e-324 e1");
    assert_eq!(Vector::new(-1e-7, 0.0, 0.0).to_string(), "-1e-7 e1");
    assert_eq!(format!("{:.3}", Vector::new(1e-7, 0.0, 0.0)), "0");
    assert_eq!(Vector::new(1e300, 0.0, 0.0).to_string(), "1e300 e1");
    assert_eq!(
        format!("{:.2}", Vector::new(1e300, 0.0, 0.0)),
        "1.00e300 e1"
    );
    assert_eq!(
        Even::new(1.0, 1e12, 0.0, 0.0).to_string(),
        "1 + 1000000000000 e12"
    );
    assert_eq!(Bivector::new(1.0, 0.0, 0.0).to_string(), "1 e12");
    assert_eq!(
        format!("{:.2}", Vector::new(f64::INFINITY, 0.0, 0.0)),
        "inf e1"
    );
}

#[test]
fn display_keeps_non_finite_components() {
    let v = Vector::new(f64::NAN, f64::NEG_INFINITY, 0.0);
    assert_eq!(v.to_string(), "NaN e1 - inf e2");
}

#[test]
fn display_parses_back_to_the_same_value() {
    let mut values = Rng::new(1);
    let names = g3_blade_names();
    for _ in 0..500 {
        let m = Multivector::from_array(array(&mut values));
        let mut parsed = [0.0; 8];
        for (blade, value) in parse_terms(&m.to_string()) {
            let i = names.iter().position(|&n| n == blade).expect("a G3 blade");
            assert_eq!(parsed[i], 0.0, "blade {blade} written twice in {m}");
            parsed[i] = value;
        }
        assert_eq!(parsed, m.to_array(), "{m}");
    }
}

#[test]
fn index_reads_and_writes_the_component_at_its_canonical_position() {
    let mut values = Rng::new(2);
    let mut m = Multivector::from_array(array(&mut values));
    let fields = [m.s, m.e1, m.e2, m.e3, m.e12, m.e13, m.e23, m.e123];
    for (i, field) in fields.iter().enumerate() {
        assert_eq!(m[i], *field);
    }
    m[5] = 42.0;
    assert_eq!(m.e13, 42.0);
    let mut r = Rotor::ONE;
    r[3] = -1.0;
    assert_eq!(r.e23, -1.0);
    assert_eq!(Vector::new(1.0, 2.0, 3.0)[2], 3.0);
}

#[test]
#[should_panic(expected = "index 3 out of range for `Vector` (3 components)")]
fn index_past_the_last_component_panics_like_an_array() {
    let _ = Vector::ZERO[3];
}

#[test]
fn iteration_and_array_conversions_follow_canonical_order() {
    let mut values = Rng::new(3);
    let a: [f64; 4] = array(&mut values);
    let r = Rotor::from(a);
    assert_eq!(r, Rotor::from_array(a));
    assert_eq!(<[f64; 4]>::from(r), a);
    assert_eq!(r.iter().collect::<Vec<_>>(), a.to_vec());
    assert_eq!(r.into_iter().collect::<Vec<_>>(), a.to_vec());
    let mut total = 0.0;
    for c in Vector::new(1.0, 2.0, 3.0) {
        total += c;
    }
    assert_eq!(total, 6.0);
}

#[test]
fn sum_and_product_fold_like_the_operators() {
    let mut values = Rng::new(4);
    let vectors: Vec<Vector> = (0..5)
        .map(|_| Vector::from_array(array(&mut values)))
        .collect();
    let by_hand = vectors.iter().fold(Vector::ZERO, |a, &b| a + b);
    assert_eq!(vectors.iter().sum::<Vector>(), by_hand);
    assert_eq!(vectors.iter().copied().sum::<Vector>(), by_hand);
    assert_eq!(Vec::<Even>::new().into_iter().sum::<Even>(), Even::ZERO);

    let rotors: Vec<Rotor> = (0..4)
        .map(|_| Rotor::from_array(array(&mut values)))
        .collect();
    let product = rotors[0] * rotors[1] * rotors[2] * rotors[3];
    assert_eq!(rotors.iter().product::<Rotor>(), product);
    assert_eq!(rotors.iter().copied().product::<Rotor>(), product);
    assert_eq!(
        Vec::<Multivector>::new()
            .into_iter()
            .product::<Multivector>(),
        Multivector::ONE
    );

    let mut chained = rotors[0];
    chained *= rotors[1];
    assert_eq!(chained, rotors[0] * rotors[1]);
}

#[test]
// Taking references the compiler does not need is the point: it exercises `&a * &b`.
#[allow(clippy::op_ref)]
fn operators_on_references_match_the_by_value_operators() {
    let mut values = Rng::new(5);
    let a = Vector::from_array(array(&mut values));
    let b = Bivector::from_array(array(&mut values));
    let r = Rotor::from_array(array(&mut values));
    let m = Multivector::from_array(array(&mut values));
    let s = value(&mut values);
    assert_eq!(&a * &b, a * b);
    assert_eq!(&a ^ &b, a ^ b);
    assert_eq!(&a | &b, a | b);
    assert_eq!(&r * &r, r * r);
    assert_eq!(&m + &r, m + r);
    assert_eq!(&m - &a, m - a);
    assert_eq!(&s * &m, s * m);
    assert_eq!(&a * &s, a * s);
    assert_eq!(-&m, -m);
    let batch = ga_core::f32::g3::x4::Vector::splat(ga_core::f32::g3::Vector::E1);
    assert_eq!((&batch * &batch).to_items(), (batch * batch).to_items());
}

#[test]
fn finiteness_checks_look_at_every_component() {
    assert!(Multivector::ONE.is_finite());
    assert!(!Multivector::ONE.is_nan());
    let mut m = Multivector::ONE;
    m.e123 = f64::INFINITY;
    assert!(!m.is_finite());
    assert!(!m.is_nan());
    m.e2 = f64::NAN;
    assert!(m.is_nan());
}

fn dense(value: impl Into<Multivector>) -> Vec<f64> {
    Algebra::new(&[1, 1, 1]).from_canonical(&value.into().to_array())
}

#[test]
fn division_multiplies_by_the_reference_inverse() {
    let algebra = Algebra::new(&[1, 1, 1]);
    let mut values = Rng::new(6);
    for _ in 0..50 {
        let m = Multivector::from_array(array(&mut values));
        let v = Vector::from_array(array(&mut values));
        let b = Bivector::from_array(array(&mut values));
        let r = Rotor::from_array(array(&mut values));
        // The stream has exact zeros; a zero divisor is the other test's case.
        if v.norm() == 0.0 || b.norm() == 0.0 || r.norm() == 0.0 {
            continue;
        }
        let expected = |lhs: Vec<f64>, divisor: Vec<f64>| {
            let inverse = algebra.inverse(&divisor).expect("invertible divisor");
            algebra.to_canonical(&algebra.geometric(&lhs, &inverse))
        };
        let one = algebra.scalar(1.0);
        let cases = [
            ((m / v).to_array().to_vec(), expected(dense(m), dense(v))),
            ((m / b).to_array().to_vec(), expected(dense(m), dense(b))),
            ((m / r).to_array().to_vec(), expected(dense(m), dense(r))),
            (dense_array(v / b), expected(dense(v), dense(b))),
            (dense_array(b / v), expected(dense(b), dense(v))),
            (
                dense_array(r / r.reverse()),
                expected(dense(r), dense(r.reverse())),
            ),
            (dense_array(1.0 / v), expected(one.clone(), dense(v))),
        ];
        for (actual, expected) in cases {
            assert_close!(actual, expected, rel = 1e-12);
        }
    }
}

fn dense_array(value: impl Into<Multivector>) -> Vec<f64> {
    value.into().to_array().to_vec()
}

#[test]
fn division_by_zero_is_non_finite_like_scalar_division() {
    assert!(!(Vector::E1 / Vector::ZERO).is_finite());
    assert!(!(Rotor::ONE / Rotor::ZERO).is_finite());
}

#[test]
fn precision_casts_round_to_nearest_and_widen_exactly() {
    let mut values = Rng::new(7);
    let m = Multivector::from_array(array(&mut values));
    let single = m.as_f32();
    for (narrow, wide) in single.to_array().iter().zip(m.to_array()) {
        assert_eq!(*narrow, wide as f32);
    }
    assert_eq!(single.as_f64().as_f32(), single);
    let g4 = ga_core::f32::g4::Quadvector::new(0.1);
    assert_eq!(g4.as_f64().e1234, f64::from(0.1f32));
    let g2 = ga_core::f64::g2::Even::new(1.0, 2.0);
    assert_eq!(g2.as_f32(), ga_core::f32::g2::Even::new(1.0, 2.0));
}

/// Display, indexing, iteration and reference operators on every type of every algebra
/// under test, including the STA, PGA and CGA generated in `tests/`: what the macro
/// gives a user's own algebra.
macro_rules! every_type_of_every_algebra {
    (
        $name:ident, $path:path,
        dim = $dim:expr,
        metric = $metric:expr,
        types = [$($all:ident),*],
        grade_types = [$($grade:ident),*],
        projections = [$($projection:tt)*],
    ) => {
        #[test]
        fn $name() {
            use ga_tests::embed::Embed;
            use $path as algebra;
            let mut values = Rng::new($dim);
            $(
                every_type_of_every_algebra!(@type algebra, algebra::$grade, values);
            )*
            every_type_of_every_algebra!(@type algebra, algebra::Even, values);
            every_type_of_every_algebra!(@type algebra, algebra::Odd, values);
            every_type_of_every_algebra!(@type algebra, algebra::Multivector, values);
        }
    };
    (@type $algebra:ident, $ty:path, $values:ident) => {{
        let blades = <$ty as Embed<$algebra::Multivector>>::blades();
        for _ in 0..20 {
            let mut components = <$ty>::ZERO.to_array();
            for c in components.iter_mut() {
                *c = value(&mut $values);
            }
            let x = <$ty>::from(components);
            for (i, c) in components.iter().enumerate() {
                assert_eq!(x[i], *c);
            }
            assert_eq!(x.into_iter().collect::<Vec<_>>(), components.to_vec());
            let expected: Vec<(String, f64)> = blades
                .iter()
                .zip(components)
                .filter(|(_, c)| *c != 0.0)
                .map(|(&b, c)| {
                    let name = if b == 0 { String::new() } else { ga_tests::blade::blade_name(b) };
                    (name, c)
                })
                .collect();
            assert_eq!(parse_terms(&x.to_string()), expected, "{x}");
            assert!(x.is_finite() && !x.is_nan());
            assert_eq!(&x + &x, x + x);
            assert_eq!(&x * &x, x * x);
            assert_eq!(-&x, -x);
            assert_eq!([x, x].iter().sum::<$ty>(), x + x);
        }
    }};
}

ga_tests::for_each_algebra!(every_type_of_every_algebra);

#[test]
fn division_in_a_non_euclidean_metric_multiplies_by_the_reference_inverse() {
    use ga_tests::algebras::sta;
    let algebra = Algebra::new(&[1, -1, -1, -1]);
    let mut values = Rng::new(8);
    let dense = |m: sta::Multivector| algebra.from_canonical(&m.to_array());
    for _ in 0..50 {
        let m = sta::Multivector::from_array(array(&mut values));
        let v = sta::Vector::from_array(array(&mut values));
        // A four-dimensional bivector has no `/` (B ~B has a grade-4 part); a trivector
        // has.
        let t = sta::Trivector::from_array(array(&mut values));
        for (divisor, quotient) in [
            (sta::Multivector::from(v), m / v),
            (sta::Multivector::from(t), m / t),
        ] {
            // A null or nearly null divisor has no (well-conditioned) inverse.
            if divisor.norm_squared().abs() < 1e-3 {
                continue;
            }
            let inverse = algebra.inverse(&dense(divisor)).expect("invertible");
            let expected = algebra.to_canonical(&algebra.geometric(&dense(m), &inverse));
            assert_close!(quotient.to_array(), expected, rel = 1e-10);
        }
    }
}

ga_macros::algebra! {
    /// A restricted algebra with a user type, as a user would write it.
    pub mod planes {
        metric: [1, 1, 1],
        scalar: f64,
        types: [Rotor, Vector, Plane = [e12, e13]],
    }
}

#[test]
// `&r * &p` is taken on purpose: it exercises the reference impls.
#[allow(clippy::op_ref)]
fn a_user_type_gets_the_conveniences_too() {
    use planes::*;
    let p = Plane::new(2.0, -0.5);
    assert_eq!(p.to_string(), "2 e12 - 0.5 e13");
    assert_eq!(format!("{:.2}", Plane::new(1.0 / 3.0, 0.0)), "0.33 e12");
    assert_eq!((p[0], p[1]), (2.0, -0.5));
    assert_eq!(<[f64; 2]>::from(p), [2.0, -0.5]);
    assert_eq!([p, p].iter().sum::<Plane>(), p + p);
    let r = Rotor::new(0.5, 0.5, -0.5, 0.5);
    assert_eq!(&r * &p, r * p);
    // P ~P = |P|^2 is a scalar, so `/ Plane` exists; against the reference inverse.
    let algebra = Algebra::new(&[1, 1, 1]);
    let dense_p = algebra.from_components(&[0b011, 0b101], &[2.0, -0.5]);
    let dense_r = algebra.from_components(&[0, 0b011, 0b101, 0b110], &[0.5, 0.5, -0.5, 0.5]);
    let expected = algebra.geometric(&dense_r, &algebra.inverse(&dense_p).expect("invertible"));
    let quotient = r / p;
    let actual = algebra.from_components(&[0, 0b011, 0b101, 0b110], &quotient.to_array());
    assert_close!(actual, expected, rel = 1e-14);
}

#[test]
#[allow(clippy::op_ref)]
fn mixed_reference_operators_forward_to_the_by_value_ones() {
    // glam's forms: `&a + b`, `a * &b`, `a += &b`, the scalar `/` by and of references,
    // and `Sandwich<&Vector>`. The values are exact in binary, so `==` is fair.
    let (a, b) = (Vector::new(1.0, 2.0, 3.0), Vector::new(-0.5, 0.25, 2.0));
    let r = Even::new(0.8, 0.6, 0.0, 0.0);
    assert_eq!(&a + b, a + b);
    assert_eq!(a - &b, a - b);
    assert_eq!(&a * b, a * b);
    assert_eq!(a ^ &b, a ^ b);
    assert_eq!(&a | b, a | b);
    assert_eq!(r * &a, r * a);
    assert_eq!(2.0 * &a, 2.0 * a);
    assert_eq!(&a * 2.0, a * 2.0);
    assert_eq!(&a / 2.0, a / 2.0);
    assert_eq!(a / &2.0, a / 2.0);
    assert_eq!(&a / &2.0, a / 2.0);
    let mut c = a;
    c += &b;
    assert_eq!(c, a + b);
    c -= &b;
    assert_eq!(c, a);
    c *= &2.0;
    assert_eq!(c, a * 2.0);
    c /= &2.0;
    assert_eq!(c, a);
    let mut q = r;
    q *= &r;
    assert_eq!(q, r * r);
    let mut m = Multivector::ZERO;
    m += &a;
    assert_eq!(m, Multivector::from(a));
    assert_eq!(r.sandwich(&a), r.sandwich(a));
    assert_eq!((&r).sandwich(a), r.sandwich(a));
    assert_eq!((&r).sandwich(&a), r.sandwich(a));
}
