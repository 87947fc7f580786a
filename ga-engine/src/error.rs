//! Why a body description was refused.

use core::fmt;

/// A body's inertia that the engine cannot step: the field it concerns and what is wrong.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum BodyError {
    /// An entry of the tensor, a moment or a frame component is NaN or infinite.
    NotFinite,
    /// Principal moment `axis` (0, 1 or 2, in the body description's order) is not
    /// positive.
    NotPositive {
        /// Which principal moment.
        axis: usize,
    },
    /// Principal moment `axis` is positive but outside `2^min_log2 ..= 2^max_log2`, the
    /// range the step's precision carries: `f32` 2^-50 to 2^50 (8.9e-16 to 1.1e15),
    /// `f64` 2^-500 to 2^500 (3.1e-151 to 3.3e150). Beyond it the free flow's constants
    /// (squares of the inverse moments) or `|L|^2` at an ordinary angular velocity
    /// overflow or underflow, and the step would return NaN or a wrong turn. A tensor
    /// whose moment overflows the precision lands here too. Describe the body in other
    /// units (grams and centimetres rather than kilograms and metres) to bring it in.
    OutOfRange {
        /// Which principal moment.
        axis: usize,
        /// The smallest moment taken is `2^min_log2`.
        min_log2: i32,
        /// The largest moment taken is `2^max_log2`.
        max_log2: i32,
    },
    /// The principal frame quaternion is zero.
    ZeroFrame,
}

impl fmt::Display for BodyError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            BodyError::NotFinite => f.write_str("inertia: a component is not finite"),
            BodyError::NotPositive { axis } => {
                write!(f, "inertia: principal moment {axis} is not positive")
            }
            BodyError::OutOfRange {
                axis,
                min_log2,
                max_log2,
            } => write!(
                f,
                "inertia: principal moment {axis} is outside 2^{min_log2} ..= 2^{max_log2} \
                 ({:e} to {:e}), the range this precision steps; change the units",
                libm::ldexp(1.0, *min_log2),
                libm::ldexp(1.0, *max_log2),
            ),
            BodyError::ZeroFrame => f.write_str("inertia: the principal frame quaternion is zero"),
        }
    }
}

impl core::error::Error for BodyError {}
