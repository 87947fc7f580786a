//! A body's inertia as the steps use it: principal moments in the free flow's axis order,
//! the principal frame for that order and the split's constants, checked and diagonalised
//! once.

use super::eigen::{principal_axes, quaternion_of};
use super::error::BodyError;
use super::real::Real;
use super::rotation::{Q, V};
use super::split::{split_order, Split};

/// Principal moments and the frame `p` (principal axes to the user's
/// body frame: a body-frame vector is `p v p*` of its principal components), the axes in
/// the free flow's split order (`split.rs`).
/// `repr(C)`: its fields in this order, so that the slice form reads the reference
/// moment and the split's constants as rows of four side by side (`slice.rs`).
#[derive(Clone, Copy, Debug)]
#[repr(C)]
pub(crate) struct Inertia<R: Real> {
    /// `(I1, I2, I3)`, in the split's order.
    pub(crate) moments: V<R>,
    /// The split's constants.
    pub(crate) split: Split<R>,
    /// `p`, for the split's order of the axes.
    pub(crate) frame: Q<R>,
    /// Whether `p` is not the identity (then the steps turn the orientation into the
    /// principal frame and back; otherwise they skip both products).
    pub(crate) turned: R::Mask,
    /// Which given principal axis each of the split's axes is (for the accessors; it
    /// fills what would be padding).
    pub(crate) order: Order,
}

/// Which given principal axis each of the split's axes is (`split::split_order`).
pub(crate) type Order = [u8; 3];

/// A tensor with an entry above this is diagonalised scaled by [`TENSOR_SCALE`].
const TENSOR_SCALE_ABOVE: f64 = 1e300;
/// `2^600`: brings any finite f64 below `2^424`, where the Jacobi sweeps cannot overflow.
const TENSOR_SCALE: f64 = 4.149_515_568_880_993e180;

/// The precisions a body description is built in.
pub(crate) trait Precision: Real<Mask = bool> + PartialOrd {
    /// The principal moments taken are `2^-MOMENT_LOG2 ..= 2^MOMENT_LOG2`
    /// ([`BodyError::OutOfRange`]): the squares of the inverse moments (the split's
    /// constants, `(h k)^2` in the turn about `L`) stay far from overflow, and `|L|^2` at
    /// `|w| = 1e-3` far from the subnormals, where the step would lose its precision.
    const MOMENT_LOG2: i32;
    /// `self` widened to f64 (exactly).
    fn wide(self) -> f64;
    /// Whether finite.
    fn finite(self) -> bool;
}

impl Precision for f32 {
    const MOMENT_LOG2: i32 = 50;
    fn wide(self) -> f64 {
        f64::from(self)
    }
    fn finite(self) -> bool {
        self.is_finite()
    }
}

impl Precision for f64 {
    const MOMENT_LOG2: i32 = 500;
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
        // A tensor near f64::MAX would overflow in the Jacobi sweeps: diagonalise it
        // scaled by a power of two (exact), and scale the moments back, where one that
        // overflows is out of range rather than "not finite".
        let largest = a
            .iter()
            .flatten()
            .fold(0.0f64, |m, x| m.max(libm::fabs(*x)));
        let scale = if largest > TENSOR_SCALE_ABOVE {
            TENSOR_SCALE
        } else {
            1.0
        };
        let (d, p, _) = principal_axes(&a.map(|row| row.map(|x| x / scale)));
        Self::checked(d.map(|m| R::splat(m * scale)), p)
    }

    /// From principal moments and the frame `p` (any non-zero quaternion; normalised).
    pub(crate) fn from_principal(moments: [R; 3], frame: Q<R>) -> Result<Self, BodyError> {
        let parts = [frame.x, frame.y, frame.z, frame.w];
        if !moments.iter().chain(&parts).all(|x| x.finite()) {
            return Err(BodyError::NotFinite);
        }
        let wide = parts.map(R::wide);
        let largest = wide.iter().fold(0.0f64, |m, x| m.max(libm::fabs(*x)));
        if largest == 0.0 {
            return Err(BodyError::ZeroFrame);
        }
        // Where the squared norm could overflow or underflow (a frame of size 1e200 or
        // 1e-200 in f64), divided by its largest component first; elsewhere as it is.
        let n2 = wide.iter().map(|x| x * x).sum::<f64>();
        let wide = if (1e-200..=1e200).contains(&n2) {
            wide
        } else {
            wide.map(|x| x / largest)
        };
        let n2 = wide.iter().map(|x| x * x).sum::<f64>();
        let inv = 1.0 / libm::sqrt(n2);
        let unit = wide.map(|x| x * inv);
        Self::checked(moments, unit)
    }

    /// Checks the moments (positive, in the precision's range), puts the axes in the
    /// split's order and keeps both orders; `frame` is unit, `[x, y, z, w]`.
    fn checked(moments: [R; 3], frame: [f64; 4]) -> Result<Self, BodyError> {
        let (min, max) = (
            libm::ldexp(1.0, -R::MOMENT_LOG2),
            libm::ldexp(1.0, R::MOMENT_LOG2),
        );
        for (axis, &m) in moments.iter().enumerate() {
            let m = m.wide();
            if m.is_nan() {
                return Err(BodyError::NotFinite);
            }
            if m <= 0.0 {
                return Err(BodyError::NotPositive { axis });
            }
            // An infinite moment here comes from a finite tensor that overflowed.
            if !(min..=max).contains(&m) {
                return Err(BodyError::OutOfRange {
                    axis,
                    min_log2: -R::MOMENT_LOG2,
                    max_log2: R::MOMENT_LOG2,
                });
            }
        }
        let order = split_order(moments.map(|m| 1.0 / m.wide()));
        let ordered = order.map(|k| moments[k]);
        let turn = hamilton(frame, permutation(order));
        let identity = turn == [0.0, 0.0, 0.0, 1.0] || turn == [0.0, 0.0, 0.0, -1.0];
        let quaternion = |p: [f64; 4]| Q {
            x: R::splat(p[0]),
            y: R::splat(p[1]),
            z: R::splat(p[2]),
            w: R::splat(p[3]),
        };
        Ok(Inertia {
            moments: V {
                x: ordered[0],
                y: ordered[1],
                z: ordered[2],
            },
            split: Split::new(ordered.map(|m| 1.0 / m.wide())),
            frame: quaternion(turn),
            turned: !identity,
            // Axis indices below 3 fit a byte: the body description stays small.
            order: order.map(|k| k as u8),
        })
    }

    /// The principal moments and frame in the given order of the axes (as the body was
    /// described): the moments put back, the frame `p s*` for the split's `s`.
    pub(crate) fn given(&self) -> (V<R>, Q<R>) {
        let order = self.order;
        let ordered = [self.moments.x, self.moments.y, self.moments.z];
        let mut moments = ordered;
        for (split_axis, &given_axis) in order.iter().enumerate() {
            moments[usize::from(given_axis)] = ordered[split_axis];
        }
        let frame = if order == [0, 1, 2] {
            self.frame
        } else {
            let p = [self.frame.x, self.frame.y, self.frame.z, self.frame.w].map(R::wide);
            let [x, y, z, w] = permutation(order.map(usize::from));
            let [x, y, z, w] = hamilton(p, [-x, -y, -z, w]);
            Q {
                x: R::splat(x),
                y: R::splat(y),
                z: R::splat(z),
                w: R::splat(w),
            }
        };
        let [x, y, z] = moments;
        (V { x, y, z }, frame)
    }
}

/// The rotation `[x, y, z, w]` that takes `e_x, e_y, e_z` to the given axes
/// `order[0], order[1]` and `+-order[2]` (the sign that keeps it a rotation).
fn permutation(order: [usize; 3]) -> [f64; 4] {
    let mut m = [[0.0; 3]; 3];
    let even = matches!(order, [0, 1, 2] | [1, 2, 0] | [2, 0, 1]);
    m[order[0]][0] = 1.0;
    m[order[1]][1] = 1.0;
    m[order[2]][2] = if even { 1.0 } else { -1.0 };
    quaternion_of(&m)
}

/// The Hamilton product `a b` of `[x, y, z, w]` quaternions.
fn hamilton(a: [f64; 4], b: [f64; 4]) -> [f64; 4] {
    let [ax, ay, az, aw] = a;
    let [bx, by, bz, bw] = b;
    [
        aw * bx + ax * bw + ay * bz - az * by,
        aw * by - ax * bz + ay * bw + az * bx,
        aw * bz + ax * by - ay * bx + az * bw,
        aw * bw - ax * bx - ay * by - az * bz,
    ]
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
        q_p.rotate(q_p.rotate_inv(l).divide(self.moments))
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
        R::splat(0.5) * b.dot(b.divide(self.moments))
    }
}
