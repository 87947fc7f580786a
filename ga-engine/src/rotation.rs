//! Quaternions and vectors in components, generic over [`Real`], in glam's conventions.
//!
//! `Q { x, y, z, w }` is glam's quaternion: it turns a vector by `v -> q v q*`, and the
//! rotor of the lecture's convention is `s = w, e23 = -x, e13 = y, e12 = -z` (README,
//! "Conventions"). Every formula is written out once here, with a fixed order of
//! operations, so that the scalar and the lane forms round alike (see `real.rs`).

use super::real::Real;

/// How far (in ulps of the precision, `R::EPSILON`) a squared norm may be from 1 for
/// the quaternion to be taken as unit as it is ([`Q::unit`]): the steps return
/// orientations within 6 ulps of it (measured over 2e5 random bodies and states in f32
/// and f64), glam's `normalize` within about 2. An orientation within it turns the body
/// momentum with a relative error below twice this, the size of rounding.
pub(crate) const UNIT_SLACK: f64 = 16.0;

/// A quaternion `w + x i + y j + z k`; `repr(C)`: `x, y, z, w` in this order (see
/// [`Inertia`](super::inertia::Inertia)).
#[derive(Clone, Copy, Debug)]
#[repr(C)]
pub(crate) struct Q<R> {
    pub(crate) x: R,
    pub(crate) y: R,
    pub(crate) z: R,
    pub(crate) w: R,
}

/// A 3-vector.
/// `repr(C)`: `x, y, z` in this order (see [`Inertia`](super::inertia::Inertia)).
#[derive(Clone, Copy, Debug)]
#[repr(C)]
pub(crate) struct V<R> {
    pub(crate) x: R,
    pub(crate) y: R,
    pub(crate) z: R,
}

impl<R: Real> V<R> {
    /// The vector's component `k` (0, 1 or 2).
    #[inline(always)]
    pub(crate) fn get(self, k: usize) -> R {
        match k {
            0 => self.x,
            1 => self.y,
            _ => self.z,
        }
    }

    /// `s self`.
    #[inline(always)]
    pub(crate) fn scale_all(self, s: R) -> V<R> {
        V {
            x: s * self.x,
            y: s * self.y,
            z: s * self.z,
        }
    }

    /// `self + s v`.
    #[inline(always)]
    pub(crate) fn add_scaled(self, s: R, v: V<R>) -> V<R> {
        V {
            x: self.x + s * v.x,
            y: self.y + s * v.y,
            z: self.z + s * v.z,
        }
    }

    /// Component by component, `self / k`.
    #[inline(always)]
    pub(crate) fn divide(self, k: V<R>) -> V<R> {
        V {
            x: self.x / k.x,
            y: self.y / k.y,
            z: self.z / k.z,
        }
    }

    /// Component by component, `self * k`.
    #[inline(always)]
    pub(crate) fn scale(self, k: V<R>) -> V<R> {
        V {
            x: self.x * k.x,
            y: self.y * k.y,
            z: self.z * k.z,
        }
    }

    /// `self x v`.
    #[inline(always)]
    pub(crate) fn cross(self, v: V<R>) -> V<R> {
        V {
            x: self.y * v.z - self.z * v.y,
            y: self.z * v.x - self.x * v.z,
            z: self.x * v.y - self.y * v.x,
        }
    }

    /// `self . v`.
    #[inline(always)]
    pub(crate) fn dot(self, v: V<R>) -> R {
        self.x * v.x + self.y * v.y + self.z * v.z
    }

    /// `self - v`.
    #[inline(always)]
    pub(crate) fn sub(self, v: V<R>) -> V<R> {
        V {
            x: self.x - v.x,
            y: self.y - v.y,
            z: self.z - v.z,
        }
    }
}

impl<R: Real> Q<R> {
    /// The Hamilton product `self b`.
    #[inline(always)]
    pub(crate) fn mul(self, b: Q<R>) -> Q<R> {
        let a = self;
        Q {
            w: (a.w * b.w - a.x * b.x) - (a.y * b.y + a.z * b.z),
            x: (a.w * b.x + a.x * b.w) + (a.y * b.z - a.z * b.y),
            y: (a.w * b.y - a.x * b.z) + (a.y * b.w + a.z * b.x),
            z: (a.w * b.z + a.x * b.y) - (a.y * b.x - a.z * b.w),
        }
    }

    /// The conjugate (the inverse of a unit quaternion).
    #[inline(always)]
    pub(crate) fn conj(self) -> Q<R> {
        Q {
            x: -self.x,
            y: -self.y,
            z: -self.z,
            w: self.w,
        }
    }

    /// `q v q*` for a unit `q`: `v + w t + u x t` with `t = 2 u x v`, `u` the vector part.
    /// `t` is `(2u) x v`: the doubling is done on `q`, before `v` is known, not after the
    /// cross product on the way to the result.
    #[inline(always)]
    pub(crate) fn rotate(self, v: V<R>) -> V<R> {
        let u = V {
            x: self.x,
            y: self.y,
            z: self.z,
        };
        let u2 = V {
            x: u.x + u.x,
            y: u.y + u.y,
            z: u.z + u.z,
        };
        let t = u2.cross(v);
        v.add_scaled(self.w, t)
            .add_scaled(R::splat(1.0), u.cross(t))
    }

    /// `q* v q`: the inverse rotation.
    #[inline(always)]
    pub(crate) fn rotate_inv(self, v: V<R>) -> V<R> {
        self.conj().rotate(v)
    }

    /// `self q_k`, where `q_k = c + s e_k` turns about the body axis `k` (by `2 atan2(s,
    /// c)`, and scaled by `|q_k|` when that is not 1).
    #[inline(always)]
    pub(crate) fn turn_about(self, k: usize, c: R, s: R) -> Q<R> {
        let Q { x, y, z, w } = self;
        match k {
            0 => Q {
                w: w * c - x * s,
                x: w * s + x * c,
                y: y * c + z * s,
                z: z * c - y * s,
            },
            1 => Q {
                w: w * c - y * s,
                x: x * c - z * s,
                y: w * s + y * c,
                z: z * c + x * s,
            },
            _ => Q {
                w: w * c - z * s,
                x: x * c + y * s,
                y: y * c - x * s,
                z: w * s + z * c,
            },
        }
    }

    /// `self . b` as 4-vectors.
    #[inline(always)]
    pub(crate) fn dot(self, b: Q<R>) -> R {
        (self.x * b.x + self.y * b.y) + (self.z * b.z + self.w * b.w)
    }

    /// `self / |self|`, then negated if that puts it in the other hemisphere from
    /// `reference`: the same rotation, continuous from step to step.
    #[inline(always)]
    pub(crate) fn normalized_near(self, reference: Q<R>) -> Q<R> {
        self.normalized_by(self.dot(self), reference)
    }

    /// `self` divided by `sqrt(norm2)`, its squared norm known beforehand, then negated if
    /// that puts it in the other hemisphere from `reference`. Each component is divided
    /// by the norm (one rounding, and one operation after the square root where a
    /// reciprocal and a product would be two).
    #[inline(always)]
    pub(crate) fn normalized_by(self, norm2: R, reference: Q<R>) -> Q<R> {
        let norm = norm2.sqrt();
        let k = R::select(self.dot(reference).lt(R::splat(0.0)), -norm, norm);
        Q {
            x: self.x / k,
            y: self.y / k,
            z: self.z / k,
            w: self.w / k,
        }
    }

    /// `self` divided by `sqrt(norm2)`, its squared norm known beforehand, with no choice
    /// of sign: for a quaternion the caller knows to be in the hemisphere it wants, where
    /// [`Q::normalized_by`] would negate nothing (the same bits, without the dot product
    /// and the select on the step's critical path).
    #[inline(always)]
    pub(crate) fn divided_by_norm(self, norm2: R) -> Q<R> {
        let norm = norm2.sqrt();
        Q {
            x: self.x / norm,
            y: self.y / norm,
            z: self.z / norm,
            w: self.w / norm,
        }
    }

    /// The orientation a step works on: `self` where its squared norm is 1 to within
    /// [`UNIT_SLACK`] ulps (what the steps return, and what `normalize` gives), so
    /// that a unit input keeps its bits; else `self / |self|` ([`Q::rescaled`]). Every
    /// formula downstream (`rotate`, above all) assumes a unit quaternion: used as it is,
    /// `2 q` would turn the momentum into the body frame four times too long, less the
    /// rotation.
    #[inline(always)]
    pub(crate) fn unit(self) -> Q<R> {
        self.unit_and_norm2().0
    }

    /// [`Q::unit`] and its squared norm (`dot(self, self)`, computed once: the free flow
    /// needs it too).
    #[inline(always)]
    pub(crate) fn unit_and_norm2(self) -> (Q<R>, R) {
        let norm2 = self.dot(self);
        let near = Q::unit_norm2(norm2);
        if R::all(near) {
            (self, norm2)
        } else {
            let q = Q::select(near, self, self.rescaled());
            (q, q.dot(q))
        }
    }

    /// Whether a quaternion whose squared norm is `norm2` is taken as unit (within
    /// [`UNIT_SLACK`] rounding errors of 1); false where `norm2` is NaN, so that a
    /// non-finite orientation is rescaled too.
    #[inline(always)]
    pub(crate) fn unit_norm2(norm2: R) -> R::Mask {
        let off = norm2 - R::splat(1.0);
        let slack = R::splat(UNIT_SLACK * R::EPSILON);
        R::and(off.lt(slack), (-off).lt(slack))
    }

    /// `self / |self|`, divided first by its largest component's size so that the
    /// squared norm neither overflows nor underflows (any finite non-zero `self`, from
    /// the smallest subnormal to the largest float); NaN for a zero or non-finite one.
    #[inline(always)]
    pub(crate) fn rescaled(self) -> Q<R> {
        // `|a|`; where `a` is NaN, `max_or` skips it, and the division below gives NaN.
        let size = |a: R| a.max_or(-a);
        let largest = size(self.x)
            .max_or(size(self.y))
            .max_or(size(self.z).max_or(size(self.w)));
        let s = Q {
            x: self.x / largest,
            y: self.y / largest,
            z: self.z / largest,
            w: self.w / largest,
        };
        s.divided_by_norm(s.dot(s))
    }

    /// `yes` where `mask` holds, `no` elsewhere.
    #[inline(always)]
    pub(crate) fn select(mask: R::Mask, yes: Q<R>, no: Q<R>) -> Q<R> {
        Q {
            x: R::select(mask, yes.x, no.x),
            y: R::select(mask, yes.y, no.y),
            z: R::select(mask, yes.z, no.z),
            w: R::select(mask, yes.w, no.w),
        }
    }
}

impl<R: Real> Q<R> {
    /// The identity.
    #[inline(always)]
    pub(crate) fn identity() -> Q<R> {
        let (zero, one) = (R::splat(0.0), R::splat(1.0));
        Q {
            x: zero,
            y: zero,
            z: zero,
            w: one,
        }
    }
}

/// `L_b` seen from a body turned about its axis `k` by the angle whose cosine and sine
/// are `c` and `s`: the body momentum after the turn.
#[inline(always)]
pub(crate) fn turn_body_about<R: Real>(k: usize, c: R, s: R, l: V<R>) -> V<R> {
    match k {
        0 => V {
            x: l.x,
            y: c * l.y + s * l.z,
            z: c * l.z - s * l.y,
        },
        1 => V {
            x: c * l.x - s * l.z,
            y: l.y,
            z: c * l.z + s * l.x,
        },
        _ => V {
            x: c * l.x + s * l.y,
            y: c * l.y - s * l.x,
            z: l.z,
        },
    }
}
