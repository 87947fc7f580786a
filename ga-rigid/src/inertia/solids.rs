//! Standard homogeneous solids, each centred on its centre of mass with its symmetry
//! axes along e1, e2, e3.
//!
//! Moments from any table of mass moments of inertia (e.g. Goldstein, *Classical
//! Mechanics*, or Beer & Johnston, *Vector Mechanics for Engineers*, inside back cover).
//! The cone's moments are about its centre of mass, which lies a quarter of the height
//! above the base: `3/80 m (4 r^2 + h^2)` across the axis, not the `3/20 m (r^2 + 4 h^2)`
//! about the apex.

use ga_core::f64::g3::*;
use serde::{Deserialize, Serialize};

use super::inertia::Inertia;
use crate::error::{positive, Error};

/// A homogeneous solid with its mass, as written in a scene's `shape = { kind = ... }`.
#[derive(Clone, Copy, Debug, PartialEq, Deserialize, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum Solid {
    /// A rectangular box with edge lengths `size = [a, b, c]` along e1, e2, e3.
    Box {
        /// The mass.
        mass: f64,
        /// Edge lengths along e1, e2, e3.
        size: [f64; 3],
    },
    /// A solid ball.
    Sphere {
        /// The mass.
        mass: f64,
        /// The radius.
        radius: f64,
    },
    /// A thin spherical shell.
    HollowSphere {
        /// The mass.
        mass: f64,
        /// The radius.
        radius: f64,
    },
    /// A solid circular cylinder with its axis along e3.
    Cylinder {
        /// The mass.
        mass: f64,
        /// The radius.
        radius: f64,
        /// The length along e3.
        height: f64,
    },
    /// A solid circular cone with its axis along e3, apex up: the base is at
    /// `-height/4` and the apex at `+3 height/4`, so the centre of mass is the origin.
    Cone {
        /// The mass.
        mass: f64,
        /// The radius of the base.
        radius: f64,
        /// The distance from base to apex.
        height: f64,
    },
    /// A solid ellipsoid with semi-axes `radii = [a, b, c]` along e1, e2, e3.
    Ellipsoid {
        /// The mass.
        mass: f64,
        /// Semi-axes along e1, e2, e3.
        radii: [f64; 3],
    },
}

impl Solid {
    /// The inertia about the centre of mass; errors name the solid's field (`mass`,
    /// `size`, `radius`, `height`, `radii`).
    pub fn inertia(&self) -> Result<Inertia, Error> {
        match *self {
            Solid::Box { mass, size } => Inertia::solid_box(mass, size),
            Solid::Sphere { mass, radius } => Inertia::solid_sphere(mass, radius),
            Solid::HollowSphere { mass, radius } => Inertia::hollow_sphere(mass, radius),
            Solid::Cylinder {
                mass,
                radius,
                height,
            } => Inertia::solid_cylinder(mass, radius, height),
            Solid::Cone {
                mass,
                radius,
                height,
            } => Inertia::solid_cone(mass, radius, height),
            Solid::Ellipsoid { mass, radii } => Inertia::solid_ellipsoid(mass, radii),
        }
    }

    /// The scene name of the kind (`box`, `hollow_sphere`, ...).
    #[must_use]
    pub fn kind(&self) -> &'static str {
        match self {
            Solid::Box { .. } => "box",
            Solid::Sphere { .. } => "sphere",
            Solid::HollowSphere { .. } => "hollow_sphere",
            Solid::Cylinder { .. } => "cylinder",
            Solid::Cone { .. } => "cone",
            Solid::Ellipsoid { .. } => "ellipsoid",
        }
    }
}

impl Inertia {
    /// A box of edge lengths `size = [a, b, c]`: `i1 = m (b^2 + c^2) / 12`, and cyclically.
    pub fn solid_box(mass: f64, size: [f64; 3]) -> Result<Self, Error> {
        let m = positive("mass", "mass", mass)?;
        let [a, b, c] = positive3("size", "edge lengths", size)?;
        centred(
            m,
            [
                m * (b * b + c * c) / 12.0,
                m * (a * a + c * c) / 12.0,
                m * (a * a + b * b) / 12.0,
            ],
            "size",
        )
    }

    /// A solid ball: `2/5 m r^2` about every axis.
    pub fn solid_sphere(mass: f64, radius: f64) -> Result<Self, Error> {
        let m = positive("mass", "mass", mass)?;
        let r = positive("radius", "radius", radius)?;
        centred(m, [0.4 * m * r * r; 3], "radius")
    }

    /// A thin spherical shell: `2/3 m r^2` about every axis.
    pub fn hollow_sphere(mass: f64, radius: f64) -> Result<Self, Error> {
        let m = positive("mass", "mass", mass)?;
        let r = positive("radius", "radius", radius)?;
        centred(m, [2.0 / 3.0 * m * r * r; 3], "radius")
    }

    /// A solid cylinder, axis e3: `m (3 r^2 + h^2) / 12` across, `m r^2 / 2` along.
    pub fn solid_cylinder(mass: f64, radius: f64, height: f64) -> Result<Self, Error> {
        let m = positive("mass", "mass", mass)?;
        let r = positive("radius", "radius", radius)?;
        let h = positive("height", "height", height)?;
        let across = m * (3.0 * r * r + h * h) / 12.0;
        centred(m, [across, across, 0.5 * m * r * r], "radius")
    }

    /// A solid cone, axis e3, about its centre of mass (a quarter of the height above
    /// the base): `3/80 m (4 r^2 + h^2)` across, `3/10 m r^2` along.
    pub fn solid_cone(mass: f64, radius: f64, height: f64) -> Result<Self, Error> {
        let m = positive("mass", "mass", mass)?;
        let r = positive("radius", "radius", radius)?;
        let h = positive("height", "height", height)?;
        let across = 3.0 / 80.0 * m * (4.0 * r * r + h * h);
        centred(m, [across, across, 0.3 * m * r * r], "radius")
    }

    /// A solid ellipsoid of semi-axes `[a, b, c]`: `i1 = m (b^2 + c^2) / 5`, and cyclically.
    pub fn solid_ellipsoid(mass: f64, radii: [f64; 3]) -> Result<Self, Error> {
        let m = positive("mass", "mass", mass)?;
        let [a, b, c] = positive3("radii", "semi-axes", radii)?;
        centred(
            m,
            [
                m * (b * b + c * c) / 5.0,
                m * (a * a + c * c) / 5.0,
                m * (a * a + b * b) / 5.0,
            ],
            "radii",
        )
    }
}

/// A solid centred on its centre of mass with principal axes e1, e2, e3. Positive
/// dimensions give positive moments that satisfy the triangle inequality (they come
/// from a real mass distribution); only overflow or underflow of the squares is left to
/// catch, and it is blamed on `dimension`.
fn centred(mass: f64, moments: [f64; 3], dimension: &str) -> Result<Inertia, Error> {
    if moments.iter().all(|i| i.is_finite() && *i > 0.0) {
        Ok(Inertia::new_unchecked(
            moments,
            Rotor::ONE,
            Some(mass),
            Vector::ZERO,
        ))
    } else {
        Err(Error::invalid(
            dimension,
            format!("the moments {moments:?} are out of floating-point range: rescale the units"),
        ))
    }
}

fn positive3(field: &str, what: &'static str, v: [f64; 3]) -> Result<[f64; 3], Error> {
    for x in v {
        positive(field, what, x)?;
    }
    Ok(v)
}
