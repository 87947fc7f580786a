//! The quaternion the free flow's turns build up, as one trait ([`Turning`]) that both
//! forms of the turns (`divided.rs`, `projective.rs`) are written against.

use super::real::Real;
use super::rotation::{Q, V};

/// The quaternion the turns build up: in components ([`Q`]), or, for one `f32` body on
/// x86-64, in one SSE register (`sse.rs`), where a turn is seven instructions instead of
/// twelve. Both do the same IEEE operations on each component, so they give the same bits.
pub(crate) trait Turning<R: Real>: Copy {
    /// From components.
    fn pack(q: Q<R>) -> Self;
    /// To components.
    fn unpack(self) -> Q<R>;
    /// `self (c + s e_K)`, as [`Q::turn_about`].
    fn turned_about<const K: usize>(self, c: R, s: R) -> Self;
    /// `w self`, as [`Q::mul`].
    fn turned_by(self, w: Q<R>) -> Self;
    /// `self b`, as [`Q::mul`].
    fn times(self, b: Q<R>) -> Self;
    /// As [`Q::normalized_by`].
    fn normalized_by(self, norm2: R, reference: Self) -> Self;
    /// As [`Q::divided_by_norm`].
    fn divided_by_norm(self, norm2: R) -> Self;
    /// As [`Q::dot`].
    fn dot(self, b: Self) -> R;
    /// As [`Q::rotate_inv`].
    fn rotate_inv(self, v: V<R>) -> V<R>;
    /// As [`Q::select`].
    fn select(mask: R::Mask, yes: Self, no: Self) -> Self;
}

impl<R: Real> Turning<R> for Q<R> {
    #[inline(always)]
    fn pack(q: Q<R>) -> Self {
        q
    }
    #[inline(always)]
    fn unpack(self) -> Q<R> {
        self
    }
    #[inline(always)]
    fn turned_about<const K: usize>(self, c: R, s: R) -> Self {
        self.turn_about(K, c, s)
    }
    #[inline(always)]
    fn turned_by(self, w: Q<R>) -> Self {
        w.mul(self)
    }
    #[inline(always)]
    fn times(self, b: Q<R>) -> Self {
        self.mul(b)
    }
    #[inline(always)]
    fn normalized_by(self, norm2: R, reference: Self) -> Self {
        Q::normalized_by(self, norm2, reference)
    }
    #[inline(always)]
    fn divided_by_norm(self, norm2: R) -> Self {
        Q::divided_by_norm(self, norm2)
    }
    #[inline(always)]
    fn dot(self, b: Self) -> R {
        Q::dot(self, b)
    }
    #[inline(always)]
    fn rotate_inv(self, v: V<R>) -> V<R> {
        Q::rotate_inv(self, v)
    }
    #[inline(always)]
    fn select(mask: R::Mask, yes: Self, no: Self) -> Self {
        Q::select(mask, yes, no)
    }
}
