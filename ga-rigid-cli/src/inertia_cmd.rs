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
                // `+ 0.0` turns the -0 of a zero component into 0.
                -c.e1 + 0.0,
                -c.e2 + 0.0,
                -c.e3 + 0.0
            )
        }
        (_, None) => writeln!(out, "about: the centre of mass"),
    };
    // Moments alone say nothing of where the mass is: the origin is a convention there.
    let c = inertia.centre_of_mass();
    let _ = match inertia.mass() {
        Some(_) => writeln!(out, "centre_of_mass: [{}, {}, {}]", c.e1, c.e2, c.e3),
        None => writeln!(
            out,
            "centre_of_mass: unknown (the scene gives moments only)"
        ),
    };
    let [i1, i2, i3] = inertia.moments();
    let _ = writeln!(out, "moments: [{i1}, {i2}, {i3}]");
    let r = inertia.rotor();
    let _ = writeln!(out, "rotor: [{}, {}, {}, {}]", r.s, r.e12, r.e13, r.e23);
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::Path;

    const RUN: &str = "[initial]\nrotor = [1, 0, 0, 0]\nomega = [0.1, 0.2, 3]\n\
                       [run]\nt_end = 1.0\nsamples = 3\n";

    /// A scene of moments alone has no known mass, and no known centre of mass either.
    #[test]
    fn moments_alone_give_no_centre_of_mass() {
        let text = format!("[body]\nmoments = [1.0, 2.0, 2.5]\n{RUN}");
        let scene = Scene::parse(&text, Path::new("m.toml")).unwrap();
        let out = describe(&scene);
        assert!(out.contains("mass: unknown"), "{out}");
        assert!(out.contains("centre_of_mass: unknown"), "{out}");
    }

    /// The cone of docs/scenes.md about its apex: the textbook moments (Meriam and Kraige,
    /// *Engineering Mechanics: Dynamics*, table D/4) `3/10 m r^2 = 0.075` about its axis
    /// and `3/5 m (r^2/4 + h^2) = 0.6375` across it, printed ascending (the principal
    /// frame's order), and the rotor turning the principal e1 onto the cone's axis e3.
    #[test]
    fn the_cone_about_its_apex_has_the_textbook_moments() {
        let text = format!(
            "[body]\nshape = {{ kind = \"cone\", mass = 1.0, radius = 0.5, height = 1.0 }}\n\
             [torque]\ng = [0, 0, -9.81]\ncom_offset = [0, 0, 0.75]\n{RUN}"
        );
        let scene = Scene::parse(&text, Path::new("cone.toml")).unwrap();
        let [a, b, c] = scene.inertia.moments();
        let (axial, across) = (0.3 * 0.25, 0.6 * (0.25 / 4.0 + 1.0));
        assert!((a - axial).abs() < 1e-12, "{a}");
        assert!(
            (b - across).abs() < 1e-12 && (c - across).abs() < 1e-12,
            "{b} {c}"
        );
        use ga_core::f64::g3::{Sandwich, Vector};
        let axis = scene.inertia.rotor().sandwich(Vector::new(1.0, 0.0, 0.0));
        assert!((axis.e3.abs() - 1.0).abs() < 1e-12, "{axis:?}");
        let out = describe(&scene);
        assert!(out.contains("from the centre of mass"), "{out}");
        assert!(!out.contains("-0,"), "{out}");
    }
}
