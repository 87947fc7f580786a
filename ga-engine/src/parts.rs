//! A body of a slice as the slice steps see it, and which step they take: the types the
//! slice driver (`slice.rs`), its dispatch (`dispatch.rs`) and the public API share.

use super::inertia::Inertia;
use super::real::Real;
use super::rotation::{Q, V};

/// Which of the splitting steps.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Order {
    /// `splitting::step2`.
    Two,
    /// `splitting::step4`.
    Four,
}

/// Inertia, orientation, world momentum and world torque of a body.
pub(crate) type BodyParts<'a, T> = (&'a Inertia<T>, Q<T>, V<T>, V<T>);

/// A body of a slice, as the generic steps see it.
pub(crate) trait Parts<T: Real> {
    /// Inertia, orientation, world momentum, world torque.
    fn parts(&self) -> BodyParts<'_, T>;
    /// Store the stepped orientation and momentum.
    fn store(&mut self, q: Q<T>, l: V<T>);
}
