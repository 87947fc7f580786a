//! The n-dimensional rigid body: the inertia as a linear map on bivectors and Euler's
//! equations in commutator form, written once for G2, G3 and G4.

use std::sync::Arc;

use super::algebra::{Algebra, MAX_DIMENSION};
use super::eigen::{rotor_from_matrix, symmetric_eigen, Matrix};
use super::state::State;
use super::torque::Torque;
use crate::error::{self, Error};

/// A rigid body in its principal frame: the second moments `l_k = integral rho x_k^2`
/// along the body axes, which make the inertia map `I(e_i e_j) = (l_i + l_j) e_i e_j`, and
/// an optional applied torque. Cloning is cheap: the torque is shared.
#[derive(Clone)]
pub struct RigidBody<A: Algebra> {
    second_moments: [f64; MAX_DIMENSION],
    inertia: A::Bivector,
    torque: Option<Arc<dyn Torque<A> + Send + Sync>>,
}

impl<A: Algebra> std::fmt::Debug for RigidBody<A> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("RigidBody")
            .field("algebra", &A::NAME)
            .field("second_moments", &self.second_moments())
            .field("torque", &self.torque.is_some())
            .finish()
    }
}

/// Where the principal frame of a body given by point masses lies in the frame the points
/// were given in.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PrincipalFrame<A: Algebra> {
    /// The total mass.
    pub mass: f64,
    /// The centre of mass (first `n` components).
    pub centre: [f64; MAX_DIMENSION],
    /// The rotor taking principal axes to the given frame: `R e_k ~R` is the `k`-th
    /// principal axis, the second moments ascending in `k`.
    pub rotor: A::Rotor,
}

impl<A: Algebra> RigidBody<A> {
    /// A torque-free body with second moments `[l_1, ..., l_n]` along its axes: each finite
    /// and not negative, and the sum over each plane, `l_i + l_j`, positive (a body can be
    /// flat, but not a segment).
    pub fn new(second_moments: &[f64]) -> Result<Self, Error> {
        let n = A::DIMENSION;
        if second_moments.len() != n {
            return Err(Error::invalid(
                "second_moments",
                format!(
                    "a body in {} needs {n} second moments, got {}",
                    A::NAME,
                    second_moments.len()
                ),
            ));
        }
        let mut l = [0.0; MAX_DIMENSION];
        for (k, (&value, slot)) in second_moments.iter().zip(&mut l).enumerate() {
            let field = format!("second_moments[{k}]");
            error::finite(&field, "second moment", value)?;
            if value < 0.0 {
                return Err(Error::invalid(
                    field,
                    format!(
                        "second moments cannot be negative, got {}",
                        error::num(value)
                    ),
                ));
            }
            *slot = value;
        }
        let mut inertia = A::Bivector::default();
        for (k, &(i, j)) in A::PLANES.iter().enumerate() {
            inertia[k] = error::positive("second_moments", "l_i + l_j", l[i] + l[j])?;
        }
        Ok(RigidBody {
            second_moments: l,
            inertia,
            torque: None,
        })
    }

    /// A solid box of `mass` with edge lengths `sides` (one per axis, each positive):
    /// `l_k = mass s_k^2 / 12`.
    pub fn from_box(mass: f64, sides: &[f64]) -> Result<Self, Error> {
        error::positive("mass", "mass", mass)?;
        let mut l = Vec::with_capacity(sides.len());
        for (k, &s) in sides.iter().enumerate() {
            let s = error::positive(&format!("sides[{k}]"), "side", s)?;
            l.push(mass * s * s / 12.0);
        }
        Self::new(&l)
    }

    /// A solid ball of `mass` and `radius` (both positive): `l_k = mass r^2 / (n + 2)`, the
    /// mean of `x_k^2` over the n-ball.
    pub fn from_ball(mass: f64, radius: f64) -> Result<Self, Error> {
        error::positive("mass", "mass", mass)?;
        error::positive("radius", "radius", radius)?;
        let l = mass * radius * radius / (A::DIMENSION as f64 + 2.0);
        Self::new(&vec![l; A::DIMENSION])
    }

    /// The body of point masses `(m, x)` with `x` its `n` coordinates in any frame: the
    /// second-moment matrix `sum m (x - c)(x - c)^T` about the centre of mass `c`,
    /// diagonalised once (Jacobi). Returns the body in its principal frame (second moments
    /// ascending) and where that frame lies in the given one.
    pub fn from_point_masses<P: AsRef<[f64]>>(
        points: &[(f64, P)],
    ) -> Result<(Self, PrincipalFrame<A>), Error> {
        let n = A::DIMENSION;
        if points.is_empty() {
            return Err(Error::invalid(
                "points",
                "a body needs at least one point mass",
            ));
        }
        let mut mass = 0.0;
        let mut moment = [0.0; MAX_DIMENSION];
        for (k, (m, x)) in points.iter().enumerate() {
            let field = format!("points[{k}]");
            error::positive(&field, "mass", *m)?;
            let x = x.as_ref();
            if x.len() != n {
                return Err(Error::invalid(
                    field,
                    format!(
                        "a point in {} has {n} coordinates, got {}",
                        A::NAME,
                        x.len()
                    ),
                ));
            }
            for (i, &xi) in x.iter().enumerate() {
                error::finite(&field, "coordinates", xi)?;
                moment[i] += m * xi;
            }
            mass += m;
        }
        let centre = moment.map(|s| s / mass);
        let mut second: Matrix = [[0.0; MAX_DIMENSION]; MAX_DIMENSION];
        for (m, x) in points {
            let x = x.as_ref();
            for i in 0..n {
                for j in 0..n {
                    second[i][j] += m * (x[i] - centre[i]) * (x[j] - centre[j]);
                }
            }
        }
        let (values, vectors) = symmetric_eigen(&second, n);
        // Rounding can leave a vanishing second moment slightly negative.
        let l: Vec<f64> = values[..n].iter().map(|&v| v.max(0.0)).collect();
        let body = Self::new(&l).map_err(|e| e.within("points"))?;
        let frame = PrincipalFrame {
            mass,
            centre,
            rotor: rotor_from_matrix::<A>(&vectors),
        };
        Ok((body, frame))
    }

    /// The same body driven by `torque` (a body-frame bivector, see [`Torque`]).
    #[must_use]
    pub fn with_torque(mut self, torque: impl Torque<A> + Send + Sync + 'static) -> Self {
        self.torque = Some(Arc::new(torque));
        self
    }

    /// Whether an applied torque acts.
    #[must_use]
    pub fn has_torque(&self) -> bool {
        self.torque.is_some()
    }

    /// The second moments `l_k`, one per axis.
    #[must_use]
    pub fn second_moments(&self) -> &[f64] {
        &self.second_moments[..A::DIMENSION]
    }

    /// The moment of each plane, `l_i + l_j`, as the components of a bivector.
    #[must_use]
    pub fn plane_moments(&self) -> A::Bivector {
        self.inertia
    }

    /// The inertia map `I(B)`: the component on `e_i e_j` scaled by `l_i + l_j`.
    #[inline]
    #[must_use]
    pub fn inertia(&self, b: A::Bivector) -> A::Bivector {
        let mut out = b;
        for k in 0..A::PLANES.len() {
            out[k] *= self.inertia[k];
        }
        out
    }

    /// The inverse map `I^-1(B)`.
    #[inline]
    #[must_use]
    pub fn inertia_inverse(&self, b: A::Bivector) -> A::Bivector {
        let mut out = b;
        for k in 0..A::PLANES.len() {
            out[k] /= self.inertia[k];
        }
        out
    }

    /// The body-frame torque at this time and state (zero when none acts).
    #[inline]
    #[must_use]
    pub fn torque(&self, t: f64, state: &State<A>) -> A::Bivector {
        match &self.torque {
            Some(torque) => torque.torque(t, state),
            None => A::Bivector::default(),
        }
    }

    /// Euler's equations in the lecture's form: `dOmega/dt = I^-1(Omega x I(Omega) + T)`
    /// with `x` the commutator product.
    #[inline]
    #[must_use]
    pub fn omega_rate(&self, t: f64, state: &State<A>) -> A::Bivector {
        let momentum = self.inertia(state.omega);
        self.inertia_inverse(A::commutator(state.omega, momentum) + self.torque(t, state))
    }

    /// The rotor equation `dR/dt = -1/2 R Omega_B`.
    #[inline]
    #[must_use]
    pub fn rotor_rate(state: &State<A>) -> A::Rotor {
        state.rotor * state.omega * -0.5
    }

    /// The kinetic energy `-1/2 <Omega I(Omega)>_0 = 1/2 sum (l_i + l_j) w_ij^2`.
    #[must_use]
    pub fn energy(&self, omega: A::Bivector) -> f64 {
        0.5 * (0..A::PLANES.len())
            .map(|k| self.inertia[k] * omega[k] * omega[k])
            .sum::<f64>()
    }

    /// The body angular momentum `M = I(Omega_B)`.
    #[must_use]
    pub fn body_momentum(&self, omega: A::Bivector) -> A::Bivector {
        self.inertia(omega)
    }

    /// The space angular momentum `L = R I(Omega_B) ~R`, constant without torque.
    #[must_use]
    pub fn space_momentum(&self, state: &State<A>) -> A::Bivector {
        A::sandwich(state.rotor, self.inertia(state.omega))
    }
}
