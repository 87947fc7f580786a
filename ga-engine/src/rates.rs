//! One free flow's per-step constants, shared by both forms of the turns: the body's
//! split constants (`split.rs`) times `h`, and each turn's `e` from `h^2 |L|^2`.

use super::inertia::Inertia;
use super::real::Real;

/// One free flow's per-step constants, from the body's [`Split`](super::split::Split),
/// `h` and `|L|^2`: each turn's `b` is its rate times the body momentum's component, its
/// `lambda b` the cubic rate times it, and its `p = e - lambda b^2`.
#[derive(Clone, Copy)]
pub(crate) struct Rates<R> {
    /// `h alpha / 4`.
    pub(crate) outer: R,
    /// `lambda_o h alpha / 4`.
    pub(crate) outer_cubic: R,
    /// `1 - h^2 |L|^2 alpha beta / 12`.
    pub(crate) outer_e: R,
    /// `h beta / 2`.
    pub(crate) middle: R,
    /// `lambda_m h beta / 2`.
    pub(crate) middle_cubic: R,
    /// `1 + h^2 |L|^2 alpha beta / 6`.
    pub(crate) middle_e: R,
    /// `h k_r / 2`: the turn about `L` is `(1 - w^2/3) + (h k_r / 2) L`, `w^2` its
    /// square times `|L|^2`.
    pub(crate) casimir: R,
}

impl<R: Real> Rates<R> {
    /// For a step of `h` with `hh_l2 = h^2 |L|^2`; with `LIMIT`, each `e` limited to
    /// `[0.5, 1.5]` (NaN to 1.5), which only the divided form's far range reaches (in
    /// the projective range `|1 - e| <= 0.05`, and the limit changes no bit).
    #[inline(always)]
    pub(crate) fn new<const LIMIT: bool>(inertia: &Inertia<R>, h: R, hh_l2: R) -> Self {
        let split = &inertia.split;
        let (outer, middle) = (h * split.outer_rate, h * split.middle_rate);
        let half = R::splat(0.5);
        let e = |eps: R| {
            R::splat(1.0)
                - if LIMIT {
                    eps.min_or(half).max_or(-half)
                } else {
                    eps
                }
        };
        // The middle turn's `h^2 |L|^2 (-2 shift)` as `-(eps + eps)`: the same bits (a
        // product by -2 is exact), one instruction fewer on the one-body step.
        let eps = hh_l2 * split.shift;
        Rates {
            outer,
            outer_cubic: split.outer_cubic * outer,
            outer_e: e(eps),
            middle,
            middle_cubic: split.middle_cubic * middle,
            middle_e: e(-(eps + eps)),
            // `0.5 / I_r` is `(1 / I_r) / 2` exactly: off the chain, a division.
            casimir: h * (R::splat(0.5) / inertia.moments.z),
        }
    }
}
