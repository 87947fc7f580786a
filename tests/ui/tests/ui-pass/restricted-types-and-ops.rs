//! A module restricted to a few types and operations, with a user type, end to end.

ga_macros::algebra! {
    /// The planes through e1 in Euclidean 3D, and the rotors that turn them.
    pub mod g3 {
        signature: (3, 0, 0),
        scalar: f32,
        types: [Rotor, Vector, Plane = [e12, e13]],
        ops: [geometric, sandwich],
    }
}

use g3::*;

fn main() {
    let plane = Plane::new(1.0, 0.0);
    assert_eq!(Plane::LEN, 2);
    let x = Vector::E1;
    let y: Odd = x * plane;
    assert_eq!(y, Odd::new(0.0, 1.0, 0.0, 0.0));
    let half_turn: Even = Vector::E1 * Vector::E2;
    let turned: Vector = half_turn.sandwich(Vector::E1);
    assert_eq!(turned, Vector::new(-1.0, 0.0, 0.0));
    let rotor: Rotor = plane * plane;
    assert_eq!(rotor, Rotor::new(-1.0, 0.0, 0.0, 0.0));
}
