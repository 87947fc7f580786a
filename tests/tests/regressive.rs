//! The regressive product (join) in 3D PGA with the null generator first,
//! `metric: [0, 1, 1, 1]` (the other test metrics, the null one last included, are
//! checked in `products_match_reference.rs`): every ordered pair of types against the
//! reference's `undual(dual(a) ^ dual(b))`, and the textbook incidences of the
//! projective constructors: the join of three points on a plane is that plane, up to
//! a factor, and `plane ^ point` is the plane's equation at the point times `I`.

use ga_tests::harness::{check_products, PairCase, PRODUCT_TOLERANCE};
use ga_tests::{Algebra, Product};

ga_macros::algebra! {
    /// 3D PGA with `e1` the null generator (`e0` in the literature).
    pub mod pga0 {
        metric: [0, 1, 1, 1],
        scalar: f64,
    }
}

use pga0::*;

ga_tests::embed_types!(
    f64;
    Vector,
    Bivector,
    Trivector,
    Quadvector,
    Even,
    Odd,
    Multivector
);

macro_rules! push_case {
    (($cases:ident), Scalar, Scalar) => {};
    (($cases:ident), $a:ident, $b:ident) => {
        $cases.push(PairCase {
            lhs: stringify!($a),
            rhs: stringify!($b),
            eval: |x, y| {
                use ga_tests::embed::Embed;
                let a = <$a as Embed<Multivector>>::from_reference(x);
                let b = <$b as Embed<Multivector>>::from_reference(y);
                let out = a.regressive(b);
                [
                    <$a as Embed<Multivector>>::to_reference(a),
                    <$b as Embed<Multivector>>::to_reference(b),
                    ga_tests::dense!(out),
                ]
            },
        });
    };
}

type Scalar = f64;

#[test]
fn regressive_product_of_every_type_pair_matches_the_reference_with_the_null_generator_first() {
    let mut cases = Vec::new();
    ga_tests::cartesian!(
        push_case!(cases);
        [Scalar, Vector, Bivector, Trivector, Quadvector, Even, Odd, Multivector];
        [Scalar, Vector, Bivector, Trivector, Quadvector, Even, Odd, Multivector]
    );
    check_products(
        &Algebra::new(&[0, 1, 1, 1]),
        Product::Regressive,
        &cases,
        PRODUCT_TOLERANCE,
    );
}

#[test]
fn plane_wedge_point_is_the_plane_equation_times_the_pseudoscalar() {
    let plane = Vector::plane(2.0, -3.0, 0.5, 4.0);
    let point = Trivector::point(1.0, 2.0, -6.0);
    // 2 - 6 - 3 + 4 = -3.
    assert_eq!(plane ^ point, Quadvector::new(-3.0));
}

#[test]
fn join_of_three_points_on_a_plane_is_that_plane() {
    let (a, b, c, d) = (1.0, 2.0, -2.0, 3.0);
    // Three points with x + 2y - 2z + 3 = 0.
    let p = Trivector::point(-3.0, 0.0, 0.0);
    let q = Trivector::point(1.0, -2.0, 0.0);
    let r = Trivector::point(0.0, 0.5, 2.0);
    let joined: Vector = p.regressive(q).regressive(r);
    let expected = Vector::plane(a, b, c, d);
    // Proportional: every 2x2 minor of the two coefficient lists vanishes.
    let (x, y) = (joined.to_array(), expected.to_array());
    let scale = x.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    assert!(
        scale > 0.0,
        "three points in general position join to a plane"
    );
    for i in 0..4 {
        for j in 0..4 {
            assert!(
                (x[i] * y[j] - x[j] * y[i]).abs() <= 1e-12 * scale,
                "{joined:?} is not a multiple of {expected:?}"
            );
        }
    }
    // The line through two points joins with either to nothing (no plane).
    let line = p.regressive(q);
    assert_eq!(line.regressive(p), Vector::ZERO);
    assert_eq!(line.regressive(q), Vector::ZERO);
    assert_ne!(line.regressive(r), Vector::ZERO);
}

#[test]
fn even_multivectors_widen_from_their_grades_and_the_scalar() {
    let b = Bivector::new(1.0, 2.0, 3.0, 4.0, 5.0, 6.0);
    let even: Even = b.into();
    assert_eq!(even, Even::ZERO + b);
    assert_eq!(Even::from(2.0), Even::ONE * 2.0);
    let odd: Odd = Vector::E2.into();
    assert_eq!(odd.e2, 1.0);
}
