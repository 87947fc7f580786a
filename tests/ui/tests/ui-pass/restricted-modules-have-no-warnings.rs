// Whatever an `ops:` list leaves out, the emitted module compiles without a warning.
#![deny(warnings)]

ga_macros::algebra! { pub mod a { metric: [1, 1, 1], types: [Multivector], ops: [geometric] } }
ga_macros::algebra! { pub mod b { metric: [1, 1, 1, 1], types: [Bivector], ops: [exp] } }
ga_macros::algebra! { pub mod c { metric: [1, -1, -1, -1], types: [Rotor], ops: [log] } }
ga_macros::algebra! { pub mod d { metric: [1, 1, 0], types: [Vector, Rotor], ops: [reflect, factor, inverse] } }
ga_macros::algebra! { pub mod e { metric: [1, 1, 1], scalar: f32, types: [Rotor], ops: [sandwich], lanes: [4] } }

fn main() {
    let m = a::Multivector::ONE * a::Multivector::E12;
    assert_eq!(m.e12, 1.0);
    let r = (b::Bivector::E12 * 0.5).exp();
    assert!((r.s - 0.5f64.cos()).abs() < 1e-15);
}
