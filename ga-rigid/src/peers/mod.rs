//! The methods people use today, run through the same registry and harness as ours so that
//! the report can answer "is this better than what I use now?". Each is written from its
//! paper or its engine's documented update, cited in its file, and marked as a peer in
//! the registry ([`crate::integrators::MethodInfo::peer`]).
//!
//! - `dop853-quaternion`, `dopri5-quaternion`: ode_solvers' Dormand-Prince 8(5,3) and 5(4)
//!   on the seven-unknown form a physicist writes (body momentum and a unit quaternion),
//!   renormalised only at output (feature `peers`).
//! - `euler-gyro-explicit`: the explicit gyroscopic Euler step of game engines.
//! - `euler-gyro-implicit`: the implicit gyroscopic step with one Newton iteration of
//!   Bullet and Jolt.
//! - `buss-2`: Buss's augmented second-order rotation update.
//!
//! Two peers are not separate rows: implicit midpoint on the quaternion (the choice of
//! Genesis and Roblox) is our `midpoint` (the rotor is the quaternion, and the midpoint
//! rule on `dR/dt = -1/2 R Omega` is its Cayley form), and the discrete Moser-Veselov step
//! is not written yet.

mod buss;
mod gyroscopic_euler;
#[cfg(feature = "peers")]
mod quaternion_ode;

pub use buss::Buss;
pub use gyroscopic_euler::{ExplicitGyroscopicEuler, ImplicitGyroscopicEuler};
#[cfg(feature = "peers")]
pub use quaternion_ode::{QuaternionOde, QuaternionSolver};
