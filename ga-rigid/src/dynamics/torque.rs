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

/// The gravity-gradient torque on a satellite in a circular orbit, the standard attitude
/// problem (Hughes, *Spacecraft Attitude Dynamics*, Wiley 1986, section 8.2): with `c` the
/// body-frame unit vector toward the planet's centre and `n` the orbital rate,
/// `tau = 3 n^2 c x (J c)`, as a bivector `T = 3 n^2 c ^ (J c)`, from the potential
/// `V = 3/2 n^2 c . (J c)` (up to a constant). The orbit lies in the space e1e2 plane and
/// starts on e1: the direction to the planet is `-(cos nt, sin nt, 0)`. The potential
/// turns with the orbit, so the energy is not conserved.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GravityGradient {
    /// The orbital rate `n` (rad per unit time).
    pub orbit_rate: f64,
    /// The body's principal moments, in the body frame the torque is computed in.
    pub moments: [f64; 3],
}

impl GravityGradient {
    /// The body-frame unit vector toward the planet at time `t` for attitude `rotor`.
    fn nadir(&self, t: f64, rotor: Rotor) -> Vector {
        let (sin, cos) = (self.orbit_rate * t).sin_cos();
        rotor.reverse().sandwich(Vector::new(-cos, -sin, 0.0))
    }

    /// `J c` for a body-frame vector.
    fn inertia_times(&self, c: Vector) -> Vector {
        let [i1, i2, i3] = self.moments;
        Vector::new(i1 * c.e1, i2 * c.e2, i3 * c.e3)
    }
}

impl Torque for GravityGradient {
    fn torque(&self, t: f64, rotor: Rotor, _omega: Bivector) -> Bivector {
        let c = self.nadir(t, rotor);
        let n2 = self.orbit_rate * self.orbit_rate;
        (c ^ self.inertia_times(c)) * (3.0 * n2)
    }

    fn potential(&self, t: f64, rotor: Rotor) -> f64 {
        let c = self.nadir(t, rotor);
        1.5 * self.orbit_rate * self.orbit_rate * (c | self.inertia_times(c))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dynamics::omega_from_vector;

    /// The torque is minus the potential's gradient: turning the body by a small angle
    /// `d` about its axis `k` (`R exp(-d I e_k / 2)`, the turn a body rate `w_k` makes)
    /// changes the potential by `-tau_k d`.
    #[test]
    fn gravity_gradient_torque_is_the_potential_gradient() {
        let torque = GravityGradient {
            orbit_rate: 1.3,
            moments: [1.0, 1.4, 0.6],
        };
        let rotor = Bivector::new(0.3, -0.5, 0.2).exp();
        let t = 0.7;
        let tau = crate::dynamics::omega_to_vector(torque.torque(t, rotor, Bivector::ZERO));
        let d = 1e-6;
        for k in 0..3 {
            let mut axis = [0.0; 3];
            axis[k] = 1.0;
            let turn = |a: f64| rotor * (omega_from_vector(axis) * (-0.5 * a)).exp();
            let slope = (torque.potential(t, turn(d)) - torque.potential(t, turn(-d))) / (2.0 * d);
            assert!(
                (slope + tau[k]).abs() < 1e-8,
                "axis {k}: {slope} vs {}",
                -tau[k]
            );
        }
    }
}
