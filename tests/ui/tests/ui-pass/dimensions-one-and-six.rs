// The smallest and the largest supported dimensions compile and compute.
ga_macros::algebra! {
    /// A line.
    pub mod g1 { metric: [1], scalar: f32 }
}

ga_macros::algebra! {
    /// Six Euclidean dimensions, in full.
    pub mod g6 { signature: (6, 0, 0), scalar: f64 }
}

fn main() {
    let v = g1::Vector::E1 * 3.0;
    // In one dimension a vector squares to a plain scalar, and the pseudoscalar is e1.
    let square: f32 = v * v;
    assert_eq!(square, 9.0);
    let _: g1::Pseudoscalar = v;

    let a = g6::Vector::new(1.0, 0.0, 2.0, 0.0, 0.0, -1.0);
    let b = g6::Vector::new(0.0, 3.0, 0.0, 1.0, 1.0, 0.0);
    let ab: g6::Even = a * b;
    assert_eq!(ab.s, 0.0);
    assert_eq!(ab.e12, 3.0);
    let i = g6::Hexavector::new(1.0);
    // e1..e6 squared: (-1)^(6*5/2) = -1.
    let i2: f64 = i * i;
    assert_eq!(i2, -1.0);
    let rotor = (g6::Bivector::E12 * -0.25 + g6::Bivector::E56 * 0.5).exp();
    let rotated = g6::Sandwich::sandwich(rotor, a);
    assert!((rotated.norm() - a.norm()).abs() < 1e-12);
    assert_eq!(g6::grade_dimension(3), 20);
}
