//! The state of a turning body in G2, G3 or G4.

use super::algebra::Algebra;

/// The attitude rotor (body to space, `y = R x ~R`) and the body angular velocity
/// bivector `Omega_B`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct State<A: Algebra> {
    /// The attitude: a unit rotor mapping body vectors to space vectors.
    pub rotor: A::Rotor,
    /// The angular velocity in the body frame.
    pub omega: A::Bivector,
}

impl<A: Algebra> State<A> {
    /// The state with attitude `rotor` and body angular velocity `omega`.
    #[must_use]
    pub fn new(rotor: A::Rotor, omega: A::Bivector) -> Self {
        State { rotor, omega }
    }

    /// Whether every component is finite.
    #[must_use]
    pub fn is_finite(&self) -> bool {
        (0..A::ROTOR_LEN).all(|k| self.rotor[k].is_finite())
            && (0..A::PLANES.len()).all(|k| self.omega[k].is_finite())
    }
}
