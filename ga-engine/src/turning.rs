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
    /// The world momentum in the form the turns read it.
    type Momentum: Momentum<R>;
    /// `w self` for `w = p + k l` (a turn about the world momentum `l`), as [`Q::mul`]
    /// of `Q { x: k l.x, y: k l.y, z: k l.z, w: p }`.
    fn turned_about_momentum(self, p: R, k: R, l: Self::Momentum) -> Self;
    /// `self b`, as [`Q::mul`].
    // Only the register forms' steps (x86-64) call it.
    #[cfg(target_arch = "x86_64")]
    fn times(self, b: Q<R>) -> Self;
    /// `self b*`, as [`Q::mul`] of [`Q::conj`].
    // Only the register forms' steps (x86-64) call it.
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    fn times_conj(self, b: Q<R>) -> Self {
        self.times(b.conj())
    }
    /// As [`Q::normalized_by`].
    fn normalized_by(self, norm2: R, reference: Self) -> Self;
    /// As [`Q::divided_by_norm`].
    fn divided_by_norm(self, norm2: R) -> Self;
    /// As [`Q::dot`].
    fn dot(self, b: Self) -> R;
    /// As [`Q::rotate_inv`].
    fn rotate_inv(self, v: Self::Momentum) -> V<R>;
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
    type Momentum = V<R>;
    #[inline(always)]
    fn turned_about_momentum(self, p: R, k: R, l: V<R>) -> Self {
        let w = Q {
            x: k * l.x,
            y: k * l.y,
            z: k * l.z,
            w: p,
        };
        w.mul(self)
    }
    #[cfg(target_arch = "x86_64")]
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

/// The world momentum as the free flow reads it: in components ([`V`]), or, for one
/// `f32` body on x86-64, in one SSE register (`sse.rs`), where the kick, `|L|^2` and the
/// turn about `L` take fewer instructions. Both do the same IEEE operations on each
/// component.
pub(crate) trait Momentum<R: Real>: Copy {
    /// From components.
    fn pack(v: V<R>) -> Self;
    /// To components.
    fn unpack(self) -> V<R>;
    /// `self + s t`, as [`V::add_scaled`].
    // Only the register forms' steps (x86-64) call it.
    #[cfg(target_arch = "x86_64")]
    fn add_scaled(self, s: R, t: Self) -> Self;
    /// `|self|^2`, as [`V::dot`].
    fn norm2(self) -> R;
    /// `s self`, as [`V::scale_all`].
    // Only the register forms' steps (x86-64) call it.
    #[cfg(target_arch = "x86_64")]
    fn scaled(self, s: R) -> Self;
}

impl<R: Real> Momentum<R> for V<R> {
    #[inline(always)]
    fn pack(v: V<R>) -> Self {
        v
    }
    #[inline(always)]
    fn unpack(self) -> V<R> {
        self
    }
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    fn add_scaled(self, s: R, t: Self) -> Self {
        V::add_scaled(self, s, t)
    }
    #[inline(always)]
    fn norm2(self) -> R {
        self.dot(self)
    }
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    fn scaled(self, s: R) -> Self {
        self.scale_all(s)
    }
}
