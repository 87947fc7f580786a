//! `simulate` end to end through the library entry point: the methods agree with each
//! other through the scene-frame/principal-frame conversions, and rows are well formed.

use std::path::Path;

use ga_rigid::registry::{Method, Step};
use ga_rigid::run::run_simulation;
use ga_rigid::scene::Scene;

fn scene(text: &str) -> Scene {
    Scene::parse(text, Path::new("inline.toml")).expect("valid scene")
}

const SYMMETRIC_TOP: &str = r#"
[body]
moments = [2.0, 2.0, 1.0]
[initial]
rotor = [0.9, 0.1, -0.3, 0.2]
omega = [0.3, -0.4, 5.0]
[run]
t_end = 10.0
samples = 11
"#;

fn max_row_difference(a: &[ga_rigid::csv::Row], b: &[ga_rigid::csv::Row]) -> f64 {
    a.iter()
        .zip(b)
        .flat_map(|(x, y)| {
            let sign = if (x.rotor.to_array()[0] * y.rotor.to_array()[0]) < 0.0 {
                -1.0
            } else {
                1.0
            };
            let (xv, yv) = (x.values(), y.values());
            (0..12).map(move |k| {
                let factor = if (1..5).contains(&k) { sign } else { 1.0 };
                (xv[k] - factor * yv[k]).abs()
            })
        })
        .fold(0.0, f64::max)
}

#[test]
fn closed_form_exact_and_dopri_rows_agree_for_a_symmetric_top() {
    let scene = scene(SYMMETRIC_TOP);
    let closed = run_simulation(&scene, Method::ClosedForm, Step::AtSamples).unwrap();
    let exact = run_simulation(&scene, Method::Exact, Step::AtSamples).unwrap();
    let dopri = run_simulation(&scene, Method::Dopri, Step::Tolerance(1e-12)).unwrap();
    assert_eq!(closed.len(), 11);
    assert_eq!(closed[0].t, 0.0);
    assert_eq!(closed[10].t, 10.0);
    assert!(
        max_row_difference(&closed, &exact) < 1e-12,
        "{}",
        max_row_difference(&closed, &exact)
    );
    assert!(
        max_row_difference(&closed, &dopri) < 1e-9,
        "{}",
        max_row_difference(&closed, &dopri)
    );
}

#[test]
fn a_box_in_its_own_frame_moves_like_its_principal_moments() {
    // A box's principal frame is its own frame up to the axis order the eigen-solve picks;
    // the scene frame's rows must not depend on that choice: compare with the same box
    // given by its moments directly.
    let by_shape = scene(
        r#"
[body]
shape = { kind = "box", mass = 12.0, size = [1.0, 2.0, 3.0] }
[initial]
rotor = [1.0, 0.2, 0.0, -0.1]
omega = [0.5, 1.0, -2.0]
[run]
t_end = 5.0
samples = 6
"#,
    );
    // m (b^2 + c^2)/12 and so on with m = 12: (13, 10, 5).
    let by_moments = scene(
        r#"
[body]
moments = [13.0, 10.0, 5.0]
[initial]
rotor = [1.0, 0.2, 0.0, -0.1]
omega = [0.5, 1.0, -2.0]
[run]
t_end = 5.0
samples = 6
"#,
    );
    let a = run_simulation(&by_shape, Method::Exact, Step::AtSamples).unwrap();
    let b = run_simulation(&by_moments, Method::Exact, Step::AtSamples).unwrap();
    assert!(
        max_row_difference(&a, &b) < 1e-10,
        "{}",
        max_row_difference(&a, &b)
    );
}

#[test]
fn exact_refuses_a_torque_and_closed_form_an_asymmetric_body() {
    let asymmetric = scene(&SYMMETRIC_TOP.replace("[2.0, 2.0, 1.0]", "[2.0, 1.5, 1.0]"));
    let error = run_simulation(&asymmetric, Method::ClosedForm, Step::AtSamples).unwrap_err();
    assert!(error.to_string().starts_with("body.moments:"), "{error}");
    let heavy = scene(&format!(
        "{SYMMETRIC_TOP}\n[torque]\ng = [0.0, 0.0, -9.81]\ncom_offset = [0.0, 0.0, 0.5]\n"
    ));
    assert!(run_simulation(&heavy, Method::Exact, Step::AtSamples).is_err());
    let rows = run_simulation(&heavy, Method::Rk4, Step::Fixed(1e-3)).unwrap();
    let drift = (rows[10].energy - rows[0].energy).abs() / rows[0].energy.abs();
    assert!(
        drift < 1e-9,
        "the heavy top's total energy drifts by {drift}"
    );
}

/// A heavy top written as a solid turns about its fixed point, not its centre of mass:
/// the cone of mass 1, radius 0.5, height 1 with `com_offset = [0, 0, 0.75]` has moments
/// 0.075 about its centre of mass in every direction and 0.075 + 0.75^2 = 0.6375 about
/// the transverse axes through the point (parallel-axis theorem). Before the shift it was
/// integrated with 0.075 and its trajectory had nothing to do with its twin's.
#[test]
fn a_cone_on_its_pivot_moves_like_its_pivot_moment_twin() {
    let rest = r#"
[initial]
rotor = [0.98, 0.0, 0.0, 0.2]
omega = [0.3, -0.2, 20.0]
[run]
t_end = 1.0
samples = 11
[torque]
g = [0.0, 0.0, -9.81]
com_offset = [0.0, 0.0, 0.75]
"#;
    let solid = scene(&format!(
        "[body]\nshape = {{ kind = \"cone\", mass = 1.0, radius = 0.5, height = 1.0 }}\n{rest}"
    ));
    let twin = scene(&format!(
        "[body]\nmoments = [0.6375, 0.6375, 0.075]\n{rest}"
    ));
    let mut moments = solid.inertia.moments();
    moments.sort_by(f64::total_cmp);
    for (i, expected) in moments.iter().zip([0.075, 0.6375, 0.6375]) {
        assert!((i - expected).abs() < 1e-15, "{moments:?}");
    }
    for method in [Method::Rk4, Method::ExactSplitting4] {
        let a = run_simulation(&solid, method, Step::Fixed(1e-3)).unwrap();
        let b = run_simulation(&twin, method, Step::Fixed(1e-3)).unwrap();
        let difference = max_row_difference(&a, &b);
        assert!(
            difference < 1e-12,
            "{method}: rows differ by {difference:e}"
        );
    }
}

/// An offset off every principal axis: the inertia about the fixed point equals
/// `J_c + m (|c|^2 1 - c c^T)` computed here on matrices, its principal frame turns, and
/// the centre of mass seen from the principal frame is still `com_offset` in the scene's.
#[test]
fn an_off_axis_pivot_gets_the_parallel_axis_matrix() {
    let (mass, [a, b, c]) = (2.0, [1.0, 2.0, 3.0]);
    let offset = [0.1, -0.2, 0.3];
    let solid = scene(&format!(
        "[body]\nshape = {{ kind = \"box\", mass = {mass:?}, size = [{a:?}, {b:?}, {c:?}] }}\n\
         [initial]\nrotor = [1, 0, 0, 0]\nomega = [0.1, 0.2, 3.0]\n[run]\nt_end = 1.0\n\
         samples = 3\n[torque]\ng = [0, 0, -9.81]\ncom_offset = {offset:?}\n"
    ));
    // A box's moments about its centre: m/12 (b^2 + c^2), ...
    let centre = [b * b + c * c, a * a + c * c, a * a + b * b].map(|x| mass * x / 12.0);
    let squared: f64 = offset.iter().map(|x| x * x).sum();
    // glam's DMat3, column-major: `row(r)[k]` is J_rk.
    let j = solid.inertia.matrix();
    for r in 0..3 {
        for k in 0..3 {
            let mut expected = mass * (if r == k { squared } else { 0.0 } - offset[r] * offset[k]);
            if r == k {
                expected += centre[r];
            }
            assert!(
                (j.row(r)[k] - expected).abs() < 1e-13,
                "J[{r}][{k}] = {}, expected {expected}",
                j.row(r)[k]
            );
        }
    }
    assert_ne!(solid.inertia.rotor(), ga_core::f64::g3::Rotor::ONE);
    // At the scene's start (attitude 1) gravity's torque about the pivot is
    // `c ^ (m g)` in the scene frame, whatever principal frame the equations run in.
    use ga_core::f64::g3::{Sandwich, Vector};
    let body = solid.principal_body().unwrap();
    let start = solid.principal_state();
    let torque = solid.inertia.rotor().sandwich(body.torque(0.0, &start));
    let c = Vector::new(offset[0], offset[1], offset[2]);
    let expected = c ^ (Vector::new(0.0, 0.0, -9.81) * mass);
    assert!(
        (torque - expected).norm() < 1e-14,
        "{torque:?} vs {expected:?}"
    );
}
