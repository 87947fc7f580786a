//! The free flow's split, chosen once per body: which principal axis is the Casimir's
//! reference, which two turn, and the constants of the corrected turns
//! (docs/derivations/corrected-splitting.md has the derivation).
//!
//! With the inverse moments `k_o, k_m, k_r` of the outer, middle and reference axes,
//! `alpha = k_o - k_r` and `beta = k_m - k_r` are the coefficients of the two turns.
//! The reference is the largest moment and the outer axis the smallest, so both
//! coefficients are positive.

use super::real::Real;

/// The largest `|lambda|` a turn takes: beyond it the cubic term belongs to a turn too
/// small to matter (`lambda` grows as `alpha / beta` where `beta` tends to zero, and the
/// turn's angle shrinks with `beta`).
const MAX_CUBIC: f64 = 1e6;

/// The largest `|b|` a turn takes in the divided form: beyond it `b^2` could overflow
/// (and a NaN, from an overflowed momentum, lands here too, so the output stays finite).
pub(crate) const MAX_HALF_ANGLE: f64 = 64.0;

/// The largest `|lambda| b^2` a turn takes in the divided form, so that each turn's
/// squared norm stays below about `2e6` and the three turns' product far from overflow.
const MAX_CUBIC_TERM: f64 = 1365.0;

/// The per-body constants of the free flow for the principal axes in the split's order:
/// outer `x`, middle `y`, reference `z` (the turn about `L` takes its rate from the
/// inverse moments, `k_r / 2`). Kept small: a slice of bodies streams them every step.
/// `repr(C)`: the fields in this order (see [`Inertia`](super::inertia::Inertia)).
#[derive(Clone, Copy, Debug)]
#[repr(C)]
pub(crate) struct Split<R> {
    /// `alpha / 4`: times `h`, the rate of the outer turns (over `h/2` each).
    pub(crate) outer_rate: R,
    /// `beta / 2`: times `h`, the rate of the middle turn (over `h`).
    pub(crate) middle_rate: R,
    /// `lambda_o = (alpha - 8 beta) / 3 alpha`: the outer turn's quaternion is
    /// `(e - lambda_o b^2) + b e_x`.
    pub(crate) outer_cubic: R,
    /// `lambda_m = (beta + 4 alpha) / 3 beta`.
    pub(crate) middle_cubic: R,
    /// `alpha beta / 12`: times `h^2 |L|^2`, `1 - e_o`; the middle turn's `1 - e_m` is
    /// `-2` times it.
    pub(crate) shift: R,
    /// Times `h^2 |L|^2`, the largest of the projective form's range quotients
    /// (`range::RANGE`): below 1, every turn is in its range.
    pub(crate) reach: R,
}

/// The principal axes in the split's order `[outer, middle, reference]`, from the
/// inverse moments in their given order: the smallest moment outer, the largest the
/// reference (a stable sort, so moments given in ascending order keep their axes and
/// need no frame).
pub(crate) fn split_order(inverse: [f64; 3]) -> [usize; 3] {
    // Descending inverse moments by insertion (stable: an axis moves only past a
    // strictly smaller inverse moment).
    let mut order = [0, 1, 2];
    for i in 1..3 {
        let mut j = i;
        while j > 0 && inverse[order[j]] > inverse[order[j - 1]] {
            order.swap(j, j - 1);
            j -= 1;
        }
    }
    order
}

/// `x` limited to `[-MAX_CUBIC, MAX_CUBIC]`; a NaN (a zero coefficient over zero) to
/// `1/3`, the plain rational turn (its turn does not move then).
fn cubic(x: f64) -> f64 {
    if x.is_nan() {
        1.0 / 3.0
    } else {
        x.clamp(-MAX_CUBIC, MAX_CUBIC)
    }
}

impl<R: Real> Split<R> {
    /// From the inverse moments in the split's order.
    pub(crate) fn new(inverse: [f64; 3]) -> Self {
        let alpha = inverse[0] - inverse[2];
        let beta = inverse[1] - inverse[2];
        let (outer_cubic, middle_cubic) = (
            cubic((alpha - 8.0 * beta) / (3.0 * alpha)),
            cubic((beta + 4.0 * alpha) / (3.0 * beta)),
        );
        let (outer_rate, middle_rate) = (alpha / 4.0, beta / 2.0);
        let casimir_rate = inverse[2] / 2.0;
        let shift = libm::fabs(alpha * beta) / 6.0;
        let [b, cubic_term, e, w] = super::range::RANGE;
        let reach = [
            outer_rate * outer_rate / b,
            middle_rate * middle_rate / b,
            libm::fabs(outer_cubic) * outer_rate * outer_rate / cubic_term,
            libm::fabs(middle_cubic) * middle_rate * middle_rate / cubic_term,
            shift / e,
            casimir_rate * casimir_rate / w,
        ]
        .into_iter()
        .fold(0.0, f64::max);
        Split {
            outer_rate: R::splat(outer_rate),
            middle_rate: R::splat(middle_rate),
            outer_cubic: R::splat(outer_cubic),
            middle_cubic: R::splat(middle_cubic),
            shift: R::splat(alpha * beta / 12.0),
            reach: R::splat(reach),
        }
    }

    /// The largest `|b|` of the outer and middle turns in the divided form
    /// (`divided.rs`): 64, or less where `|lambda| b^2` would pass `MAX_CUBIC_TERM`.
    #[inline(always)]
    pub(crate) fn limits(&self) -> (R, R) {
        let limit = |lambda: R| {
            let size = lambda.max_or(-lambda);
            R::sqrt(R::splat(MAX_CUBIC_TERM) / size).min_or(R::splat(MAX_HALF_ANGLE))
        };
        (limit(self.outer_cubic), limit(self.middle_cubic))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_order_runs_from_the_smallest_moment_to_the_largest_and_keeps_ties() {
        // The T-handle 1 : 2 : 3, as given and the other way round.
        assert_eq!(split_order([1.0, 0.5, 1.0 / 3.0]), [0, 1, 2]);
        assert_eq!(split_order([1.0 / 3.0, 0.5, 1.0]), [2, 1, 0]);
        assert_eq!(split_order([0.5, 1.0, 1.0 / 3.0]), [1, 0, 2]);
        // A sphere and a symmetric top keep their given order where they tie.
        assert_eq!(split_order([1.0, 1.0, 1.0]), [0, 1, 2]);
        assert_eq!(split_order([1.0, 1.0, 2.5]), [2, 0, 1]);
    }

    #[test]
    fn degenerate_coefficients_give_finite_constants() {
        for inverse in [[1.0, 1.0, 1.0], [1.0, 1.0, 2.5], [2.5, 1.0, 1.0]] {
            let s = Split::<f64>::new(inverse);
            let (outer, middle) = s.limits();
            for x in [
                s.outer_cubic,
                s.middle_cubic,
                s.shift,
                s.reach,
                outer,
                middle,
            ] {
                assert!(x.is_finite(), "{inverse:?}: {s:?}");
            }
        }
    }
}
