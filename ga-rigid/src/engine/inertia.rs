//! A body's inertia as the steps use it: principal moments, their reciprocals and the
//! principal frame, checked and diagonalised once.

use super::eigen::principal_axes;
use super::error::BodyError;
use super::real::Real;
use super::rotation::{Q, V};

/// Principal moments, their reciprocals and the frame `p` (principal axes to the user's
/// body frame: a body-frame vector is `p v p*` of its principal components).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Inertia<R: Real> {
    /// `(I1, I2, I3)`.
    pub(crate) moments: V<R>,
    /// `(1/I1, 1/I2, 1/I3)`.
    pub(crate) inverse: V<R>,
    /// `max_k (1/I_k)^2 / 12`: times `h^2 |L|^2`, the bound on every turn's `b^2` that
    /// picks the form of the turns (`splitting::free_flow_normalized`), kept here so
    /// that a step does not take the largest of three squares.
    pub(crate) reach: R,
    /// `p`.
    pub(crate) frame: Q<R>,
    /// Whether `p` is not the identity (then the steps turn the orientation into the
    /// principal frame and back; otherwise they skip both products).
    pub(crate) turned: R::Mask,
}

/// The precisions a body description is built in.
pub(crate) trait Precision: Real<Mask = bool> + PartialOrd {
    /// `self` widened to f64 (exactly).
    fn wide(self) -> f64;
    /// Whether finite.
    fn finite(self) -> bool;
}

impl Precision for f32 {
    fn wide(self) -> f64 {
        f64::from(self)
    }
    fn finite(self) -> bool {
        self.is_finite()
    }
}

impl Precision for f64 {
    fn wide(self) -> f64 {
        self
    }
    fn finite(self) -> bool {
        self.is_finite()
    }
}

impl<R: Precision> Inertia<R> {
    /// From a symmetric tensor in the body frame, `t[column][row]` (glam's layout; the
    /// symmetric part is used), diagonalised in f64.
    pub(crate) fn from_tensor(t: [[R; 3]; 3]) -> Result<Self, BodyError> {
        if !t.iter().flatten().all(|x| x.finite()) {
            return Err(BodyError::NotFinite);
        }
        let a = [0, 1, 2].map(|i| [0, 1, 2].map(|j| t[j][i].wide()));
        let (d, p, diagonal) = principal_axes(&a);
        let frame = Q {
            x: R::splat(p[0]),
            y: R::splat(p[1]),
            z: R::splat(p[2]),
            w: R::splat(p[3]),
        };
        Self::checked(d.map(R::splat), frame, !diagonal)
    }

    /// From principal moments and the frame `p` (any non-zero quaternion; normalised).
    pub(crate) fn from_principal(moments: [R; 3], frame: Q<R>) -> Result<Self, BodyError> {
        let parts = [frame.x, frame.y, frame.z, frame.w];
        if !moments.iter().chain(&parts).all(|x| x.finite()) {
            return Err(BodyError::NotFinite);
        }
        let wide = parts.map(R::wide);
        let n2 = wide.iter().map(|x| x * x).sum::<f64>();
        if n2.partial_cmp(&1e-30) != Some(core::cmp::Ordering::Greater) || !n2.is_finite() {
            return Err(BodyError::ZeroFrame);
        }
        let inv = 1.0 / libm::sqrt(n2);
        let unit = wide.map(|x| x * inv);
        let identity = unit == [0.0, 0.0, 0.0, 1.0] || unit == [0.0, 0.0, 0.0, -1.0];
        let frame = Q {
            x: R::splat(unit[0]),
            y: R::splat(unit[1]),
            z: R::splat(unit[2]),
            w: R::splat(unit[3]),
        };
        Self::checked(moments, frame, !identity)
    }

    /// Checks the moments (positive, reciprocals finite) and keeps them.
    fn checked(moments: [R; 3], frame: Q<R>, turned: bool) -> Result<Self, BodyError> {
        for (axis, &m) in moments.iter().enumerate() {
            if !m.finite() {
                return Err(BodyError::NotFinite);
            }
            let inv = R::splat(1.0) / m;
            if m.partial_cmp(&R::splat(0.0)) != Some(core::cmp::Ordering::Greater) || !inv.finite()
            {
                return Err(BodyError::NotPositive { axis });
            }
        }
        let one = R::splat(1.0);
        let inverse2 = moments.map(|m| (one / m) * (one / m));
        let widest = inverse2[0].max_or(inverse2[1]).max_or(inverse2[2]);
        Ok(Inertia {
            moments: V {
                x: moments[0],
                y: moments[1],
                z: moments[2],
            },
            inverse: V {
                x: one / moments[0],
                y: one / moments[1],
                z: one / moments[2],
            },
            reach: widest * R::splat(1.0 / 12.0),
            frame,
            turned,
        })
    }
}

impl<R: Real> Inertia<R> {
    /// The orientation of the principal axes, `q p`, from the body's `q`.
    #[inline(always)]
    pub(crate) fn principal_orientation(&self, q: Q<R>) -> Q<R> {
        if R::any(self.turned) {
            Q::select(self.turned, q.mul(self.frame), q)
        } else {
            q
        }
    }

    /// The body's orientation `q_p p*` from the principal axes' `q_p`.
    #[inline(always)]
    pub(crate) fn body_orientation(&self, q: Q<R>) -> Q<R> {
        if R::any(self.turned) {
            Q::select(self.turned, q.mul(self.frame.conj()), q)
        } else {
            q
        }
    }

    /// World angular velocity `R J^-1 R^T L` from world momentum, `q_p` principal.
    #[inline(always)]
    pub(crate) fn velocity(&self, q_p: Q<R>, l: V<R>) -> V<R> {
        q_p.rotate(q_p.rotate_inv(l).scale(self.inverse))
    }

    /// World angular momentum `R J R^T w` from world angular velocity, `q_p` principal.
    #[inline(always)]
    pub(crate) fn momentum(&self, q_p: Q<R>, w: V<R>) -> V<R> {
        q_p.rotate(q_p.rotate_inv(w).scale(self.moments))
    }

    /// Kinetic energy `L . w / 2`, `q_p` principal.
    #[inline(always)]
    pub(crate) fn energy(&self, q_p: Q<R>, l: V<R>) -> R {
        let b = q_p.rotate_inv(l);
        R::splat(0.5) * b.dot(b.scale(self.inverse))
    }
}
