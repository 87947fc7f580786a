//! The `inertia` command: the mass properties of a scene's body.

use std::fmt::Write as _;

use crate::scene::Scene;

/// The text `inertia` prints: one `key: value` line each for the mass, the centre of
/// mass, the principal moments and the principal rotor, numbers round-trip exact.
#[must_use]
pub fn describe(scene: &Scene) -> String {
    let inertia = &scene.inertia;
    let mut out = String::new();
    // Writing to a String cannot fail.
    let _ = match inertia.mass() {
        Some(m) => writeln!(out, "mass: {m}"),
        None => writeln!(out, "mass: unknown (the scene gives moments only)"),
    };
    let c = inertia.centre_of_mass();
    let _ = writeln!(out, "centre_of_mass: [{}, {}, {}]", c.e1, c.e2, c.e3);
    let [i1, i2, i3] = inertia.moments();
    let _ = writeln!(out, "moments: [{i1}, {i2}, {i3}]");
    let r = inertia.rotor();
    let _ = writeln!(out, "rotor: [{}, {}, {}, {}]", r.s, r.e12, r.e13, r.e23);
    out
}
