//! The lecture's worked examples in G3 and G4: the geometric product of two vectors, a
//! reflection, a rotation by `exp`, and the blade test of `e12 + e34` with a
//! factorisation. Run with `cargo run -p ga-core --example lecture`; every claim is
//! asserted, so the run fails if one is false.

use ga_core::f64::{g3, g4};

fn main() {
    geometric_product_of_two_vectors();
    reflection();
    rotation_by_exp();
    blades_in_four_dimensions();
}

/// `ab = a.b + a^b`: a scalar plus a bivector, and `ba` flips the bivector.
fn geometric_product_of_two_vectors() {
    use g3::*;
    let a = Vector::new(1.0, 2.0, 0.0);
    let b = Vector::new(3.0, -1.0, 1.0);
    let ab = a * b;
    println!("a = {a}, b = {b}");
    println!("ab = {ab}   (a.b = {}, a^b = {})", a | b, a ^ b);
    assert_eq!(ab.s, a | b);
    assert_eq!(ab.grade2(), a ^ b);
    let ba = b * a;
    assert_eq!(ba.grade2(), -(a ^ b));
    // a.b = (ab + ba) / 2 and a^b = (ab - ba) / 2, the lecture's definitions.
    assert_eq!((ab + ba) * 0.5, Even::ONE * (a | b));
    println!("ba = {ba}");
}

/// The reflection of `a` in the plane orthogonal to the unit vector `n`: `-n a n`.
fn reflection() {
    use g3::*;
    let n = Vector::new(1.0, 1.0, 0.0).normalized();
    let a = Vector::new(2.0, 0.0, 1.0);
    let by_hand = -(n * a * n).grade1();
    let reflected = a.reflect(n);
    println!("reflect {a} in the plane orthogonal to {n:.4}: {reflected:.4}");
    assert!((reflected - by_hand).norm() < 1e-15);
    // The component along n flips, the rest stays.
    assert!(((reflected | n) + (a | n)).abs() < 1e-15);
    assert!((reflected.norm() - a.norm()).abs() < 1e-15);
}

/// `R = exp(-B theta / 2)` rotates by theta in the plane of `B`; `y = R x ~R`.
fn rotation_by_exp() {
    use g3::*;
    let theta = std::f64::consts::FRAC_PI_3;
    let r = (Bivector::E12 * (-theta / 2.0)).exp();
    let y = r.sandwich(Vector::E1);
    println!("R = exp(-e12 pi/6) = {r:.4}; R e1 ~R = {y:.4}");
    assert!((y - Vector::new(theta.cos(), theta.sin(), 0.0)).norm() < 1e-15);
    // Two half rotations in the same plane compose into one, and e3 is untouched.
    let half = (Bivector::E12 * (-theta / 4.0)).exp();
    assert!((half * half - r).norm() < 1e-15);
    assert!((r.sandwich(Vector::E3) - Vector::E3).norm() < 1e-15);
    // The same rotor with glam's names: about e3 by the right-hand rule.
    assert!((Rotor::from_axis_angle(Vector::E3, theta) - r).norm() < 1e-15);
}

/// `e12 + e34` is a bivector but no blade (`B ^ B = 2 e1234`), while `a ^ b` factors
/// into orthogonal vectors, `a ^ b = a b'` with `b' = a^-1 (a ^ b)`.
fn blades_in_four_dimensions() {
    use g4::*;
    let b = Bivector::E12 + Bivector::E34;
    #[allow(clippy::eq_op)] // B ^ B is the lecture's blade test, not a typo
    let square = b ^ b;
    println!("B = {b}; B ^ B = {square}; blade: {}", b.is_blade());
    assert_eq!(square.e1234, 2.0);
    assert!(!b.is_blade());
    assert!(b.factor().is_none());

    let a = Vector::new(1.0, 2.0, 0.0, 1.0);
    let c = Vector::new(0.0, 1.0, 3.0, -1.0);
    let blade = a ^ c;
    assert!(blade.is_blade());
    let b_prime = (a.inverse().expect("a is not null") * blade).grade1();
    println!("a ^ c = {blade:.4}; b' = a^-1 (a ^ c) = {b_prime:.4}");
    assert!((a | b_prime).abs() < 1e-14);
    assert!(((a * b_prime).grade2() - blade).norm() < 1e-14);
    let [f1, f2] = blade.factor().expect("a ^ c is a blade");
    println!("factor(a ^ c) = [{f1:.4}, {f2:.4}]");
    assert!((f1 | f2).abs() < 1e-14);
    assert!(((f1 * f2).grade2() - blade).norm() < 1e-14);
}
