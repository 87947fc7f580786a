//! A `#![no_std]` crate of the kind an engine is: its own glam (without `std`) and
//! ga-engine without default features, stepping rigid bodies in `f32` and `f64`. If
//! anything in `ga_engine` reached for the standard library this crate would not
//! build (`cargo build -p ga-engine-user`); its tests (`cargo test -p ga-engine-user`)
//! check what it computes.
#![no_std]
#![deny(missing_docs)]

use ga_engine::{f32 as e32, f64 as e64, BodyError};
use glam::{DMat3, DQuat, DVec3, Mat3, Quat, Vec3};

/// A box-shaped body (moments of a 1 x 2 x 3 box of unit mass), tilted in its own frame so
/// that its tensor is not diagonal: the engine finds the principal axes.
#[must_use]
pub fn tilted_box_tensor() -> DMat3 {
    let (a, b, c) = (1.0, 2.0, 3.0);
    let d = DMat3::from_diagonal(DVec3::new(b * b + c * c, a * a + c * c, a * a + b * b) / 12.0);
    let r = DMat3::from_quat(DQuat::from_rotation_y(0.3) * DQuat::from_rotation_x(0.2));
    r * d * r.transpose()
}

/// `steps` steps of a free tumbling body in f64 by the fourth-order step; returns the
/// final orientation and world angular momentum.
///
/// # Errors
/// Only if the tensor were invalid (it is not).
pub fn tumble_f64(steps: usize, dt: f64) -> Result<(DQuat, DVec3), BodyError> {
    let body = e64::Body::from_tensor(tilted_box_tensor())?;
    let mut q = DQuat::IDENTITY;
    let mut l = body.angular_momentum(q, DVec3::new(0.1, 4.0, 0.05));
    for _ in 0..steps {
        (q, l) = e64::step_order4(&body, q, l, DVec3::ZERO, dt);
    }
    Ok((q, l))
}

/// The same body in f32, stepped as a slice of eight copies with a constant world torque
/// on odd ones; returns the states.
///
/// # Errors
/// Only if the tensor were invalid.
pub fn tumble_slice_f32(steps: usize, dt: f32) -> Result<[e32::BodyState; 8], BodyError> {
    let body = e32::Body::from_tensor(tilted_box_tensor().as_mat3())?;
    let mut states = [e32::BodyState::new(body, Quat::IDENTITY, Vec3::new(0.1, 1.0, 0.05)); 8];
    for (i, s) in states.iter_mut().enumerate() {
        if i % 2 == 1 {
            s.torque = Vec3::new(0.0, 0.0, 0.5);
        }
    }
    for _ in 0..steps {
        e32::step_slice(&mut states, dt);
    }
    Ok(states)
}

/// [`tumble_slice_f32`]'s bodies kept in `BodyColumns` (which allocates, through `alloc`,
/// without `std`) and stepped there; returns the states.
///
/// # Errors
/// Only if the tensor were invalid.
pub fn tumble_columns_f32(steps: usize, dt: f32) -> Result<[e32::BodyState; 8], BodyError> {
    let mut columns: e32::BodyColumns = tumble_slice_f32(0, dt)?.into_iter().collect();
    for _ in 0..steps {
        columns.step(dt);
    }
    let mut states = tumble_slice_f32(0, dt)?;
    for (state, stepped) in states.iter_mut().zip(columns.iter()) {
        *state = stepped;
    }
    Ok(states)
}

/// The principal moments the engine found for [`tilted_box_tensor`], ascending.
///
/// # Errors
/// Only if the tensor were invalid.
pub fn principal_moments_f32() -> Result<Vec3, BodyError> {
    let body = e32::Body::from_tensor(Mat3::from_cols_array(
        &tilted_box_tensor().as_mat3().to_cols_array(),
    ))?;
    let m = body.principal_moments();
    let (lo, hi) = (m.min_element(), m.max_element());
    Ok(Vec3::new(lo, m.x + m.y + m.z - lo - hi, hi))
}
