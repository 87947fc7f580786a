//! Rigid bodies in two, three and four dimensions: the lecture's dynamics written once over
//! the algebra.
//!
//! The inertia is a linear map on bivectors, `I(B) = integral rho x ^ (x . B)`, which in
//! the principal frame, with second moments `l_k = integral rho x_k^2`, is
//! `I(e_i e_j) = (l_i + l_j) e_i e_j` (in matrix terms `M = J Omega + Omega J`, `J =
//! diag(l)`). Euler's equations keep the lecture's commutator form
//! `I(dOmega/dt) - Omega x I(Omega) = T`, the attitude the rotor equation
//! `dR/dt = -1/2 R Omega_B`, and the space momentum `L = R I(Omega_B) ~R` is constant
//! without torque. The same code runs in [`G2`] (one plane: a constant rate), [`G3`] (the
//! 3D body of `crate::dynamics`, with moments `i_1 = l_2 + l_3` and so on) and [`G4`]
//! (six planes, non-simple rotations).
//!
//! References: M. ten Bosch, "N-Dimensional Rigid Body Dynamics", ACM Trans. Graph. 39(4),
//! 55 (2020) (bivector angular velocity and inertia on bivectors); S. V. Manakov, "Note on
//! the integration of Euler's equations of the dynamics of an n-dimensional rigid body",
//! Funct. Anal. Appl. 10 (1976) (the integrals `tr((M + lambda J^2)^k)`); T. Ratiu, "The
//! motion of the free n-dimensional rigid body", Indiana Univ. Math. J. 29 (1980). The
//! closed form of the symmetric 4D body is derived in
//! `docs/derivations/symmetric-body-4d.md`; test values are in `docs/references.md`.

mod algebra;
mod body;
mod closed_form;
mod eigen;
mod integrator;
mod lie_dop853;
mod lie_dopri5;
mod lie_rk4;
mod midpoint;
mod rk4;
pub mod run;
pub mod scene;
mod splitting;
mod state;
mod torque;

pub use algebra::{Algebra, G2, G3, G4, MAX_DIMENSION};
pub use body::{PrincipalFrame, RigidBody};
pub use closed_form::{planar, SymmetricBody4};
pub use eigen::{rotor_from_matrix, symmetric_eigen, Matrix};
pub use integrator::Integrator;
pub use lie_dop853::LieDop853;
pub use lie_dopri5::LieDopri5;
pub use lie_rk4::LieRk4;
pub use midpoint::ImplicitMidpoint;
pub use rk4::Rk4;
pub use splitting::PlaneSplitting;
pub use state::State;
pub use torque::{BodyTorque, SpaceTorque, Torque};
