use ga_core::f64::g3::{Bivector, Rotor};

/// The state of a rotating body: the attitude rotor (body to space, `y = R x ~R`) and the
/// body angular velocity bivector `Omega_B`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct State {
    /// The attitude: a unit rotor mapping body vectors to space vectors.
    pub rotor: Rotor,
    /// The angular velocity in the body frame, `Omega_B = sum_k w_k I e_k`.
    pub omega: Bivector,
}

/// `Omega_B = I w = w1 e23 - w2 e13 + w3 e12` from the angular velocity vector `w`.
#[must_use]
pub fn omega_from_vector(w: [f64; 3]) -> Bivector {
    Bivector::new(w[2], -w[1], w[0])
}

/// The components `[w1, w2, w3]` of `Omega_B = I w`.
#[must_use]
pub fn omega_to_vector(omega: Bivector) -> [f64; 3] {
    [omega.e23, -omega.e13, omega.e12]
}

#[cfg(test)]
mod tests {
    use super::*;
    use ga_core::f64::g3::{Trivector, Vector};

    #[test]
    fn omega_is_the_pseudoscalar_times_w() {
        let w = [0.3, -1.2, 2.5];
        let i = Trivector::new(1.0);
        let expected = i * Vector::new(w[0], w[1], w[2]);
        assert_eq!(omega_from_vector(w), expected);
        assert_eq!(omega_to_vector(expected), w);
    }
}
