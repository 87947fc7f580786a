use ga_core::f64::g3::{Bivector, Rotor, Sandwich, Vector};

/// An applied couple as a bivector in the body frame, `T_B(t, R, Omega_B)`.
pub trait Torque {
    /// The body-frame torque bivector at time `t` in state (`rotor`, `omega`).
    fn torque(&self, t: f64, rotor: Rotor, omega: Bivector) -> Bivector;

    /// The potential energy whose gradient the torque is, when it has one (zero otherwise),
    /// so that the total energy can be checked.
    fn potential(&self, _t: f64, _rotor: Rotor) -> f64 {
        0.0
    }
}

/// Uniform gravity on a body whose centre of mass sits at `com_offset` (body frame) from
/// the point the moments are taken about: the heavy top when that point is fixed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Gravity {
    /// The body's mass.
    pub mass: f64,
    /// The gravitational acceleration in the space frame.
    pub g: Vector,
    /// The centre of mass in the body frame, from the pivot.
    pub com_offset: Vector,
}

impl Torque for Gravity {
    /// `T_B = c ^ (m ~R g R)`: the space force pulled back into the body frame.
    fn torque(&self, _t: f64, rotor: Rotor, _omega: Bivector) -> Bivector {
        let force_body = rotor.reverse().sandwich(self.g * self.mass);
        self.com_offset ^ force_body
    }

    /// `-m g . (R c ~R)`: the height of the centre of mass against gravity.
    fn potential(&self, _t: f64, rotor: Rotor) -> f64 {
        -self.mass * (self.g | rotor.sandwich(self.com_offset))
    }
}
