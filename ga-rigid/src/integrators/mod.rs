//! Time-stepping methods for the rigid body of [`crate::dynamics`]: one file per method,
//! each citing the paper it follows, all behind the one [`Integrator`] trait.

pub mod adams;
mod casimir_splitting;
mod closed_form;
mod composed_splitting;
mod composition;
mod corrected_splitting;
mod dopri;
mod exact;
mod exact_splitting;
mod integrator;
pub(crate) mod lie_dop853;
mod lie_rk4;
mod midpoint;
mod rk4;
mod splitting;

pub use adams::Adams;
pub use casimir_splitting::CasimirSplitting;
pub use closed_form::ClosedForm;
pub use composed_splitting::ComposedSplitting;
pub use composition::{Composition, Nystrom};
pub use corrected_splitting::CorrectedSplitting;
pub use dopri::{DormandPrince, DormandPrinceStats};
pub use exact::ExactFreeBody;
pub use exact_splitting::ExactSplitting;
pub(crate) use integrator::check_finite;
/// The sub-step rule of the fixed-step methods, for `gradients`' second instantiation.
pub(crate) use integrator::substeps;
pub use integrator::Integrator;
pub(crate) use integrator::{check_step, fixed_steps};
// Re-exported only for the quaternion-form peers (feature `peers`); without them a
// `default-features = false` user (the rapier example) warned of an unused import.
#[cfg(feature = "peers")]
pub(crate) use integrator::step_limit_reached;
pub use lie_dop853::{DenseStep, LieDop853, LieDop853Stats};
pub use lie_rk4::LieRk4;
pub use midpoint::ImplicitMidpoint;
pub use rk4::Rk4;
pub use splitting::Splitting;
