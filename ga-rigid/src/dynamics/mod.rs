//! The rigid body's equations of motion in the lecture's form, apart from the methods that
//! integrate them (`crate::integrators`).

mod body;
mod state;
mod symmetric_top;
mod torque;

pub use body::RigidBody;
pub use state::{omega_from_vector, omega_to_vector, State};
pub use symmetric_top::{SymmetricTop, DEFAULT_SYMMETRY_TOLERANCE};
pub use torque::{Gravity, GravityGradient, Torque};
