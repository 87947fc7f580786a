//! The test metrics over dual numbers, generated here once with a user's `scalar:` path
//! (`num_dual::Dual64`, as a crate depending on num-dual writes it), and G3 over
//! `num_dual::HyperDual64` for second derivatives. G3 over `Dual64` is ga-core's own
//! (`ga_core::dual64::g3`, feature `dual`). G1, 2D PGA and a restricted G3 are here so that
//! the smallest, a degenerate odd-dimensional and a restricted module are compiled too.

ga_macros::algebra! {
    /// The Euclidean plane over `Dual64`.
    pub mod g2 { metric: [1, 1], scalar: num_dual::Dual64 }
}

ga_macros::algebra! {
    /// Euclidean four-space over `Dual64`.
    pub mod g4 { metric: [1, 1, 1, 1], scalar: num_dual::Dual64 }
}

ga_macros::algebra! {
    /// The space-time algebra over `Dual64` (`e1` the time axis).
    pub mod sta { metric: [1, -1, -1, -1], scalar: num_dual::Dual64 }
}

ga_macros::algebra! {
    /// 3D projective geometric algebra over `Dual64` (`e4` null).
    pub mod pga { metric: [1, 1, 1, 0], scalar: num_dual::Dual64 }
}

ga_macros::algebra! {
    /// 3D conformal geometric algebra over `Dual64` (`e5` squares to -1).
    pub mod cga { metric: [1, 1, 1, 1, -1], scalar: num_dual::Dual64 }
}

ga_macros::algebra! {
    /// Euclidean space over `HyperDual64`: two first derivatives and the mixed second.
    pub mod g3_hyper { metric: [1, 1, 1], scalar: num_dual::HyperDual64 }
}

ga_macros::algebra! {
    /// A restricted G3 over `Dual64` (rotors, vectors and bivectors; the operations a
    /// rotation estimator needs), as a user would write one.
    pub mod g3_rotors {
        metric: [1, 1, 1],
        scalar: num_dual::Dual64,
        types: [Rotor, Vector, Bivector],
        ops: [geometric, sandwich, reverse, norm, exp, log, add],
    }
}

ga_macros::algebra! {
    /// The line over `Dual64` (no bivectors: no exp or log), to compile the smallest case.
    pub mod g1 { metric: [1], scalar: num_dual::Dual64 }
}

ga_macros::algebra! {
    /// 2D projective geometric algebra over `Dual64` (`e3` null), to compile a degenerate
    /// three-dimensional metric.
    pub mod pga2 { metric: [1, 1, 0], scalar: num_dual::Dual64 }
}
