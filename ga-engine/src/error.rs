//! Why a body description was refused.

use core::fmt;

/// A body's inertia that the engine cannot step: the field it concerns and what is wrong.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum BodyError {
    /// An entry of the tensor, a moment or a frame component is NaN or infinite.
    NotFinite,
    /// Principal moment `axis` (0, 1 or 2, in the body description's order) is not
    /// positive, or so small that its reciprocal overflows in the step's precision.
    NotPositive {
        /// Which principal moment.
        axis: usize,
    },
    /// The principal frame quaternion is zero (or too small to normalise).
    ZeroFrame,
}

impl fmt::Display for BodyError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            BodyError::NotFinite => f.write_str("inertia: a component is not finite"),
            BodyError::NotPositive { axis } => write!(
                f,
                "inertia: principal moment {axis} is not positive (or its reciprocal overflows)"
            ),
            BodyError::ZeroFrame => f.write_str("inertia: the principal frame quaternion is zero"),
        }
    }
}

impl core::error::Error for BodyError {}
