//! The methods people use today, run through the same registry and harness as ours so that
//! the report can answer "is this better than what I use now?". Each is written from its
//! paper or its engine's documented update, cited in its file, and marked as a peer in
//! the registry ([`crate::registry::MethodInfo::peer`]).
//!
//! - `dop853-quaternion`, `dopri5-quaternion`: ode_solvers' Dormand-Prince 8(5,3) and 5(4)
//!   on the seven-unknown form a physicist writes (body momentum and a unit quaternion),
//!   renormalised only at output (feature `peers`).
//! - `euler-gyro-explicit`: the explicit gyroscopic Euler step of game engines.
//! - `euler-gyro-implicit`: the implicit gyroscopic step with one Newton iteration of
//!   Bullet and Jolt.
//! - `buss-2`: Buss's augmented second-order rotation update.
//! - `midpoint-quaternion`: the implicit midpoint rule on the seven-unknown quaternion
//!   form, solved by Newton's method (named in issue 18 as Genesis's and Roblox's step);
//!   our `midpoint` is the same rule with its attitude part in closed form.
//! - `moser-veselov`: the discrete Moser-Veselov step (RATTLE on the rotation matrix),
//!   with torque kicks in a Strang splitting under a torque.
//! - `spiers-velocity`, `spiers-momentum`: Spiers's gyroscopic step ("A better way to
//!   spin", avian's pull request #993) in the article's two forms, a velocity update before
//!   the engine's orientation update and the momentum-first split.

mod buss;
mod gyroscopic_euler;
mod midpoint_quaternion;
mod moser_veselov;
#[cfg(feature = "peers")]
mod quaternion_ode;
mod spiers;

pub use buss::Buss;
pub use gyroscopic_euler::{ExplicitGyroscopicEuler, ImplicitGyroscopicEuler};
pub use midpoint_quaternion::QuaternionMidpoint;
pub use moser_veselov::MoserVeselov;
#[cfg(feature = "peers")]
pub use quaternion_ode::{QuaternionOde, QuaternionSolver};
pub use spiers::{Spiers, SpiersForm};
