//! The `inertia` command: the mass properties of a scene's body.

use std::fmt::Write as _;

use ga_rigid::scene::Scene;

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
    // Which point the moments are about: a heavy top built from a solid turns about its
    // fixed point, and its moments were shifted there.
    let _ = match (&scene.body, scene.torque) {
        (ga_rigid::scene::BodySpec::Moments(_), Some(_)) => {
            writeln!(out, "about: the fixed point (moments as given)")
        }
        (_, Some(t)) => {
            let c = t.com_offset;
            writeln!(
                out,
                "about: the fixed point, at -com_offset = [{}, {}, {}] from the centre of mass",
                -c.e1, -c.e2, -c.e3
            )
        }
        (_, None) => writeln!(out, "about: the centre of mass"),
    };
    let c = inertia.centre_of_mass();
    let _ = writeln!(out, "centre_of_mass: [{}, {}, {}]", c.e1, c.e2, c.e3);
    let [i1, i2, i3] = inertia.moments();
    let _ = writeln!(out, "moments: [{i1}, {i2}, {i3}]");
    let r = inertia.rotor();
    let _ = writeln!(out, "rotor: [{}, {}, {}, {}]", r.s, r.e12, r.e13, r.e23);
    out
}
