use ga_core::f64::g3::{Bivector, Commutator, Rotor, Sandwich};

use super::state::State;
use super::torque::Torque;
use crate::error::Error;
use crate::inertia::Inertia;

/// A rigid body in its principal frame: the moments `i1, i2, i3` about the body axes
/// e1, e2, e3 (so `I(I e_k) = i_k I e_k`), and an optional applied torque. Cloning is
/// cheap: the torque is shared.
#[derive(Clone)]
pub struct RigidBody {
    moments: [f64; 3],
    inverse_moments: [f64; 3],
    torque: Option<std::sync::Arc<dyn Torque + Send + Sync>>,
}

impl std::fmt::Debug for RigidBody {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("RigidBody")
            .field("moments", &self.moments)
            .field("torque", &self.torque.is_some())
            .finish()
    }
}

impl RigidBody {
    /// A torque-free body with principal moments `[i1, i2, i3]`: each finite and positive,
    /// and every pair at least the third (the triangle inequality of real bodies).
    pub fn new(moments: [f64; 3]) -> Result<Self, Error> {
        crate::inertia::Inertia::from_principal(moments)?;
        Ok(RigidBody {
            moments,
            inverse_moments: moments.map(|i| 1.0 / i),
            torque: None,
        })
    }

    /// A torque-free body whose moments need only be finite and positive: the numerical
    /// test problems of the literature (Hairer-Lubich-Wanner's (2, 1, 2/3)) break the
    /// triangle inequality that real mass distributions keep, and Euler's equations do not
    /// need it.
    pub fn new_unphysical(moments: [f64; 3]) -> Result<Self, Error> {
        crate::inertia::Inertia::from_principal_unphysical(moments)?;
        Ok(RigidBody {
            moments,
            inverse_moments: moments.map(|i| 1.0 / i),
            torque: None,
        })
    }

    /// The same body driven by `torque`.
    #[must_use]
    pub fn with_torque(mut self, torque: impl Torque + Send + Sync + 'static) -> Self {
        self.torque = Some(std::sync::Arc::new(torque));
        self
    }

    /// The principal moments.
    #[inline]
    #[must_use]
    pub fn moments(&self) -> [f64; 3] {
        self.moments
    }

    /// Whether an applied torque acts.
    #[inline]
    #[must_use]
    pub fn has_torque(&self) -> bool {
        self.torque.is_some()
    }

    /// The inertia map on bivectors, `I(B)`: the component on `I e_k` scaled by `i_k`.
    #[inline]
    #[must_use]
    pub fn inertia(&self, b: Bivector) -> Bivector {
        let [i1, i2, i3] = self.moments;
        Bivector::new(i3 * b.e12, i2 * b.e13, i1 * b.e23)
    }

    /// The inverse map `I^-1(B)`.
    #[inline]
    #[must_use]
    pub fn inertia_inverse(&self, b: Bivector) -> Bivector {
        let [j1, j2, j3] = self.inverse_moments;
        Bivector::new(j3 * b.e12, j2 * b.e13, j1 * b.e23)
    }

    /// The body-frame torque at this time and state (zero when none acts).
    #[inline]
    #[must_use]
    pub fn torque(&self, t: f64, state: &State) -> Bivector {
        match &self.torque {
            Some(torque) => torque.torque(t, state.rotor, state.omega),
            None => Bivector::ZERO,
        }
    }

    /// Euler's equations in the lecture's form: `dOmega/dt = I^-1(Omega x I(Omega) + T)`
    /// with `x` the commutator product.
    #[inline]
    #[must_use]
    pub fn omega_rate(&self, t: f64, state: &State) -> Bivector {
        let momentum = self.inertia(state.omega);
        self.inertia_inverse(state.omega.commutator(momentum) + self.torque(t, state))
    }

    /// The rotor equation `dR/dt = -1/2 R Omega_B`.
    #[inline]
    #[must_use]
    pub fn rotor_rate(state: &State) -> Rotor {
        state.rotor * state.omega * -0.5
    }

    /// The kinetic energy `-1/2 <Omega I(Omega)>_0 = 1/2 sum i_k w_k^2`.
    #[inline]
    #[must_use]
    pub fn energy(&self, omega: Bivector) -> f64 {
        -0.5 * (omega | self.inertia(omega))
    }

    /// The kinetic energy plus the torque's potential, conserved when the torque has one.
    #[must_use]
    pub fn total_energy(&self, t: f64, state: &State) -> f64 {
        let potential = self
            .torque
            .as_ref()
            .map_or(0.0, |torque| torque.potential(t, state.rotor));
        self.energy(state.omega) + potential
    }

    /// The body angular momentum bivector `I(Omega_B)`.
    #[inline]
    #[must_use]
    pub fn body_momentum(&self, omega: Bivector) -> Bivector {
        self.inertia(omega)
    }

    /// The space angular momentum `L = R I(Omega_B) ~R`.
    #[inline]
    #[must_use]
    pub fn space_momentum(&self, state: &State) -> Bivector {
        state.rotor.sandwich(self.inertia(state.omega))
    }

    /// The body angular velocity that carries body momentum `m` (a bivector): `I^-1(m)`.
    #[inline]
    #[must_use]
    pub fn omega_for_momentum(&self, m: Bivector) -> Bivector {
        self.inertia_inverse(m)
    }

    /// Whether two moments agree to `relative_tolerance`, and which axis is then the
    /// symmetry axis (0, 1 or 2): the one whose moment differs.
    #[must_use]
    pub fn symmetry_axis(&self, relative_tolerance: f64) -> Option<usize> {
        let [a, b, c] = self.moments;
        let close = |x: f64, y: f64| (x - y).abs() <= relative_tolerance * x.max(y);
        if close(a, b) {
            Some(2)
        } else if close(a, c) {
            Some(1)
        } else if close(b, c) {
            Some(0)
        } else {
            None
        }
    }
}

/// The torque-free body in the inertia's principal frame: its principal moments. The
/// principal rotor, mass and centre of mass are not part of a [`RigidBody`]; turn states
/// into the principal frame with [`Inertia::rotor`] (as the `simulate` command does).
impl From<&Inertia> for RigidBody {
    fn from(inertia: &Inertia) -> Self {
        // An `Inertia` holds finite positive moments, so no check can fail here.
        let moments = inertia.moments();
        RigidBody {
            moments,
            inverse_moments: moments.map(|i| 1.0 / i),
            torque: None,
        }
    }
}

impl From<Inertia> for RigidBody {
    fn from(inertia: Inertia) -> Self {
        RigidBody::from(&inertia)
    }
}

/// The body's inertia: its moments in its own (principal) frame, with no mass recorded
/// and the centre of mass at the origin; a torque is not part of an inertia.
impl From<&RigidBody> for Inertia {
    fn from(body: &RigidBody) -> Self {
        Inertia::new_unchecked(
            body.moments,
            Rotor::ONE,
            None,
            ga_core::f64::g3::Vector::ZERO,
        )
    }
}
