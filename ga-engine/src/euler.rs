//! The steps engines use today, kept as baselines: explicit and implicit gyroscopic Euler.
//!
//! Both hold the world angular velocity `w`, update it from Euler's equations in the
//! principal frame, `J w' = T - w x J w`, then turn the orientation by the new velocity
//! (`q += h/2 (0, w) q`, normalised), as Bullet, Jolt, PhysX and avian do.
//!
//! - Explicit: `w += h J^-1 (T - w x J w)`. Neither energy nor `|L|` is kept: a body
//!   spinning about its intermediate axis spins up and stops flipping.
//! - Implicit (Catto, "Numerical Methods", GDC 2015; Bullet's
//!   `btRigidBody::computeGyroscopicImpulseImplicit_Body`): one Newton iteration on
//!   `f(w') = J (w' - w) + h w' x J w' = 0` from `w' = w`, with the Jacobian
//!   `J + h ([w]x J - [J w]x)`, then the torque's `h J^-1 T`. It does not keep the
//!   energy either: at small steps it damps the rotation (the energy falls), at large
//!   ones (`h |w|` near 2) the energy grows (`examples/step_sizes.rs` measures it; the
//!   test `step_order4_is_the_better_choice_only_for_small_steps` holds it). A singular
//!   Jacobian (never for positive moments and a
//!   moderate step) leaves the gyroscopic term out rather than divide by zero.
//!
//! Jolt's explicit step additionally rescales the new body momentum to the old length;
//! that variant is not here.

use super::inertia::Inertia;
use super::real::Real;
use super::rotation::{Q, V};

/// The orientation turned by the world angular velocity `w` over `h` (first order),
/// normalised: `q + h/2 (0, w) q`.
#[inline(always)]
fn turn_by_velocity<R: Real>(q: Q<R>, w: V<R>, h: R) -> Q<R> {
    let half = h * R::splat(0.5);
    let dq = Q {
        x: w.x,
        y: w.y,
        z: w.z,
        w: R::splat(0.0),
    }
    .mul(q);
    let next = Q {
        x: q.x + half * dq.x,
        y: q.y + half * dq.y,
        z: q.z + half * dq.z,
        w: q.w + half * dq.w,
    };
    next.normalized_near(q)
}

/// Explicit gyroscopic Euler: orientation `q`, world angular velocity `w`, world torque
/// `t`, step `h`; returns the new `(q, w)`.
#[inline(always)]
pub(crate) fn explicit<R: Real>(
    inertia: &Inertia<R>,
    q: Q<R>,
    w: V<R>,
    t: V<R>,
    h: R,
) -> (Q<R>, V<R>) {
    let q = q.unit();
    let q_p = inertia.principal_orientation(q);
    let wb = q_p.rotate_inv(w);
    let tb = q_p.rotate_inv(t);
    let gyro = wb.cross(wb.scale(inertia.moments));
    let wb = wb.add_scaled(h, tb.sub(gyro).divide(inertia.moments));
    let w = q_p.rotate(wb);
    (turn_by_velocity(q, w, h), w)
}

/// Implicit gyroscopic Euler with one Newton iteration (Catto 2015, Bullet).
#[inline(always)]
pub(crate) fn implicit<R: Real>(
    inertia: &Inertia<R>,
    q: Q<R>,
    w: V<R>,
    t: V<R>,
    h: R,
) -> (Q<R>, V<R>) {
    let q = q.unit();
    let q_p = inertia.principal_orientation(q);
    let wb = q_p.rotate_inv(w);
    let tb = q_p.rotate_inv(t);
    let i = inertia.moments;
    let jw = wb.scale(i);
    let f = wb.cross(jw);
    let f = V {
        x: h * f.x,
        y: h * f.y,
        z: h * f.z,
    };
    // J = diag(i) + h ([w]x diag(i) - [J w]x), [a]x = [[0,-a3,a2],[a3,0,-a1],[-a2,a1,0]].
    let zero = R::splat(0.0);
    let m = [
        [i.x, h * (-wb.z * i.y + jw.z), h * (wb.y * i.z - jw.y)],
        [h * (wb.z * i.x - jw.z), i.y, h * (-wb.x * i.z + jw.x)],
        [h * (-wb.y * i.x + jw.y), h * (wb.x * i.y - jw.x), i.z],
    ];
    let cof = [
        m[1][1] * m[2][2] - m[1][2] * m[2][1],
        m[1][2] * m[2][0] - m[1][0] * m[2][2],
        m[1][0] * m[2][1] - m[1][1] * m[2][0],
    ];
    let det = m[0][0] * cof[0] + m[0][1] * cof[1] + m[0][2] * cof[2];
    // Cramer's rule for J x = f.
    let x = V {
        x: f.x * cof[0]
            + f.y * (m[0][2] * m[2][1] - m[0][1] * m[2][2])
            + f.z * (m[0][1] * m[1][2] - m[0][2] * m[1][1]),
        y: f.x * cof[1]
            + f.y * (m[0][0] * m[2][2] - m[0][2] * m[2][0])
            + f.z * (m[0][2] * m[1][0] - m[0][0] * m[1][2]),
        z: f.x * cof[2]
            + f.y * (m[0][1] * m[2][0] - m[0][0] * m[2][1])
            + f.z * (m[0][0] * m[1][1] - m[0][1] * m[1][0]),
    };
    let usable = zero.lt(det * det);
    let inv_det = R::select(usable, R::splat(1.0) / det, zero);
    let wb = wb.add_scaled(-inv_det, x);
    let wb = wb.add_scaled(h, tb.divide(inertia.moments));
    let w = q_p.rotate(wb);
    (turn_by_velocity(q, w, h), w)
}
