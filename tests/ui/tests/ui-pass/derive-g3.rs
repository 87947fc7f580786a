//! The derive form end to end: the marker `G3` gives a module `g3`.

#[derive(ga_macros::Algebra)]
#[algebra(metric = [1, 1, 1], scalar = f64)]
pub struct G3;

use g3::*;

fn main() {
    let _marker = G3;
    let a = Vector::new(1.0, 2.0, 3.0);
    let b = Vector::E2;
    let ab: Even = a * b;
    assert_eq!(ab, Even::new(2.0, 1.0, 0.0, -3.0));
    let outer: Bivector = a ^ b;
    assert_eq!(outer, Bivector::new(1.0, 0.0, -3.0));
    let inner: f64 = a | b;
    assert_eq!(inner, 2.0);
    let rotor = (Bivector::E12 * (-std::f64::consts::FRAC_PI_4)).exp();
    assert!((rotor.sandwich(Vector::E1) - Vector::E2).norm() < 1e-15);
}
