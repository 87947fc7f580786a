//! A crate that uses the geometric-algebra crates as a downstream user would: it defines
//! the space-time algebra, which ga-core does not ship, and asks the macro for serde and
//! bytemuck impls (the orphan rule leaves them to the crate that defines the types).
//!
//! `serde` names the crate this crate depends on (`::serde`); `bytemuck` is reached
//! through ga-core's re-export, so this crate does not list bytemuck itself.
#![deny(missing_docs)]

ga_macros::algebra! {
    /// Space-time algebra, G(1, 3, 0): e1 is the time direction (it squares to 1), e2, e3,
    /// e4 the space directions (they square to -1).
    pub mod sta {
        metric: [1, -1, -1, -1],
        scalar: f64,
        derive: [serde, bytemuck = ga_core::bytemuck],
    }
}

/// The boost by `rapidity` along the space direction `e2`: `R = exp(-e12 rapidity / 2)`.
/// `(e1 e2)^2 = +1`, so the exponential is hyperbolic and `R e1 ~R` is
/// `cosh(rapidity) e1 + sinh(rapidity) e2`.
#[must_use]
pub fn boost_e2(rapidity: f64) -> sta::Even {
    (sta::Bivector::E12 * (-rapidity / 2.0)).exp()
}

/// A Euclidean rotation from ga-core next to the user's own algebra: both come from the
/// same generator, each specialised to its own metric.
#[must_use]
pub fn quarter_turn() -> ga_core::f64::g3::Rotor {
    (ga_core::f64::g3::Bivector::E12 * (-std::f64::consts::FRAC_PI_4)).exp()
}
