//! A `#![no_std]` library that uses ga-core without its `std` feature and generates its
//! own algebra with `math: libm`: if any emitted or ga-core code reached for `std` (the
//! float methods `sqrt`, `sin_cos`, `atan2`, ...), this crate would not build. CI builds
//! it with `cargo build -p no-std-check`.
#![no_std]
#![deny(missing_docs)]

ga_macros::algebra! {
    /// Space-time algebra in `f64`, its functions from the `libm` crate this crate depends on.
    pub mod sta { metric: [1, -1, -1, -1], scalar: f64, math: libm }
}

ga_macros::algebra! {
    /// G3 in `f32`, its functions through ga-core's re-export of `libm`.
    pub mod g3 { metric: [1, 1, 1], scalar: f32, math: libm(::ga_core::libm) }
}

/// A quarter turn of `e1` in ga-core's G3 (no `std`): exp, sandwich, log and norms.
#[must_use]
pub fn quarter_turn() -> Option<[f64; 3]> {
    use ga_core::f64::g3::*;
    let rotor = (Bivector::E12 * (-core::f64::consts::FRAC_PI_4)).exp();
    let turned = rotor.sandwich(Vector::E1);
    let _ = rotor.log()?;
    let unit = turned.try_normalized()?;
    let _ = unit.inverse()?;
    Some([unit.e1, unit.e2, turned.norm()])
}

/// The same in this crate's own algebras: exp, log, norms and inverses through `libm`.
#[must_use]
pub fn own_algebras() -> Option<[f64; 2]> {
    let boost = sta::Bivector::new(0.5, 0.0, 0.0, 0.0, 0.0, 0.2).exp();
    let back = boost.log()?;
    let v = g3::Vector::new(3.0, 4.0, 0.0);
    let rotor = (g3::Bivector::E12 * 0.3).exp();
    let _ = rotor.log()?;
    Some([
        back.norm() + f64::from(v.normalized().norm()),
        f64::from(v.inverse()?.e1),
    ])
}
