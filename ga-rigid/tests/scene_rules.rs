//! The scene rules, through the library's loaders (`Scene::load`, `NdScene::load`): each
//! bad scene gives the error kind a caller matches on, the field it names, and a one-line
//! message that starts with the scene file and then the field and states the rule. The
//! binary's side of the same failures (exit status 2, one line on standard error, no
//! output file) is `ga-rigid-cli/tests/cli.rs`'s contract tests.
//!
//! The reference is the rule itself, as docs/scenes.md states it: which field, which
//! bound, which words.

use std::path::{Path, PathBuf};

use ga_rigid::error::{echo_path, Error};
use ga_rigid::nd::scene::NdScene;
use ga_rigid::scene::Scene;

const BODY: &str = "[body]\nmoments = [1.0, 2.0, 2.5]\n";
const INITIAL: &str = "[initial]\nrotor = [1, 0, 0, 0]\nomega = [0.1, 1.0, 0.2]\n";
const RUN: &str = "[run]\nt_end = 10.0\nsamples = 11\n";

fn scene(body: &str, initial: &str, run: &str) -> String {
    format!("{body}{initial}{run}")
}

/// A fresh directory for one test holding `files`, under cargo's per-target temporary
/// directory.
fn write_files(name: &str, files: &[(&str, &str)]) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("scene-rules")
        .join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    for (file, text) in files {
        std::fs::write(dir.join(file), text).unwrap();
    }
    dir
}

/// The error's message, checked to be one line.
fn one_line(e: &Error) -> String {
    let message = e.to_string();
    assert_eq!(message.lines().count(), 1, "not one line: {message}");
    message
}

/// Load `scene.toml` of `files` (written to a fresh directory named `name`) and check the
/// error: its message is `<path>: <field>: ...` containing `rule`, `Error::field` is
/// `field`, and the error inside the file's (`Error::in_file_source`) is of the kind
/// `kind` accepts. Returns the error inside.
fn rejected(
    name: &str,
    files: &[(&str, &str)],
    field: &str,
    rule: &str,
    kind: fn(&Error) -> bool,
) -> Error {
    let dir = write_files(name, files);
    let path = dir.join("scene.toml");
    let e = match Scene::load(&path) {
        Ok(_) => panic!("{name}: the scene was accepted"),
        Err(e) => e,
    };
    checked(name, &path, e, field, rule, kind)
}

/// [`rejected`] for a 2D or 4D scene, read by `NdScene::load`.
fn rejected_nd(
    name: &str,
    scene: &str,
    field: &str,
    rule: &str,
    kind: fn(&Error) -> bool,
) -> Error {
    let dir = write_files(name, &[("scene.toml", scene)]);
    let path = dir.join("scene.toml");
    let e = match NdScene::load(&path) {
        Ok(_) => panic!("{name}: the scene was accepted"),
        Err(e) => e,
    };
    checked(name, &path, e, field, rule, kind)
}

/// The checks of [`rejected`] on the error `e` of loading `path`.
fn checked(
    name: &str,
    path: &Path,
    e: Error,
    field: &str,
    rule: &str,
    kind: fn(&Error) -> bool,
) -> Error {
    let message = one_line(&e);
    // The path as messages show it: cut to its end past `ECHO_LIMIT` characters.
    let prefix = format!("{}: {field}: ", echo_path(path));
    assert!(
        message.starts_with(&prefix),
        "{name}: expected {prefix:?} first: {message}"
    );
    assert!(
        message.contains(rule),
        "{name}: expected {rule:?} in: {message}"
    );
    assert_eq!(e.field(), Some(field), "{name}");
    let Error::InFile {
        path: in_file,
        source,
    } = e
    else {
        panic!("{name}: not an error in the file: {e:?}")
    };
    assert_eq!(in_file, path, "{name}");
    assert!(kind(&source), "{name}: unexpected kind: {source:?}");
    *source
}

#[test]
fn missing_field_is_named() {
    let s = scene(BODY, INITIAL, "[run]\nsamples = 11\n");
    rejected(
        "missing_field",
        &[("scene.toml", &s)],
        "run.t_end",
        "missing field",
        |e| matches!(e, Error::Invalid { .. }),
    );
}

#[test]
fn missing_section_is_named() {
    let s = format!("{BODY}{RUN}");
    rejected(
        "missing_section",
        &[("scene.toml", &s)],
        "initial",
        "missing section",
        |e| matches!(e, Error::Invalid { .. }),
    );
}

#[test]
fn unknown_field_is_named() {
    let s = scene("[body]\nmoments = [1, 2, 2.5]\ncolour = 3\n", INITIAL, RUN);
    rejected(
        "unknown_field",
        &[("scene.toml", &s)],
        "body.colour",
        "unknown field",
        |e| matches!(e, Error::Invalid { .. }),
    );
}

#[test]
fn unknown_field_in_an_inline_table_is_named() {
    let s = scene(
        "[body]\nshape = { kind = \"box\", mass = 1, size = [1, 2, 3], colour = 3 }\n",
        INITIAL,
        RUN,
    );
    rejected(
        "unknown_inline_field",
        &[("scene.toml", &s)],
        "body.shape.colour",
        "unknown field",
        |e| matches!(e, Error::Invalid { .. }),
    );
}

#[test]
fn unknown_section_is_named() {
    let s = format!("{}[extra]\nx = 1\n", scene(BODY, INITIAL, RUN));
    rejected(
        "unknown_section",
        &[("scene.toml", &s)],
        "extra",
        "unknown section",
        |e| matches!(e, Error::Invalid { .. }),
    );
}

#[test]
fn duplicated_field_is_named() {
    let s = scene(
        "[body]\nmoments = [1, 2, 2.5]\nmoments = [1, 2, 2.5]\n",
        INITIAL,
        RUN,
    );
    rejected(
        "duplicated_field",
        &[("scene.toml", &s)],
        "body.moments",
        "duplicated key",
        |e| matches!(e, Error::Invalid { .. }),
    );
}

#[test]
fn duplicated_field_in_an_inline_table_is_named() {
    let s = scene(
        "[body]\nshape = { kind = \"box\", mass = 1, size = [1, 2, 3], mass = 2 }\n",
        INITIAL,
        RUN,
    );
    rejected(
        "duplicated_inline",
        &[("scene.toml", &s)],
        "body.shape.mass",
        "duplicated key",
        |e| matches!(e, Error::Invalid { .. }),
    );
}

#[test]
fn duplicated_section_is_named() {
    let s = format!("{}[run]\nt_end = 1\n", scene(BODY, INITIAL, RUN));
    rejected(
        "duplicated_section",
        &[("scene.toml", &s)],
        "run",
        "duplicated key",
        |e| matches!(e, Error::Invalid { .. }),
    );
}

#[test]
fn toml_syntax_error_gives_the_position() {
    let s = scene("[body]\nmoments = [1, 2, 2.5\n", INITIAL, RUN);
    let dir = write_files("syntax_error", &[("scene.toml", &s)]);
    let path = dir.join("scene.toml");
    let e = Scene::load(&path).unwrap_err();
    let message = one_line(&e);
    assert!(
        message.starts_with(&format!("{}:3:", echo_path(&path))),
        "{message}"
    );
    assert!(message.contains("expected"), "{message}");
    assert!(matches!(e, Error::Toml { line: 3, .. }), "{e:?}");
    assert_eq!(e.field(), None);
}

#[test]
fn wrong_type_is_named() {
    let s = scene("[body]\nmoments = \"heavy\"\n", INITIAL, RUN);
    rejected(
        "wrong_type",
        &[("scene.toml", &s)],
        "body.moments",
        "invalid type",
        |e| matches!(e, Error::Invalid { .. }),
    );
}

#[test]
fn wrong_array_length_is_named() {
    let s = scene("[body]\nmoments = [1, 2]\n", INITIAL, RUN);
    rejected(
        "wrong_length",
        &[("scene.toml", &s)],
        "body.moments",
        "invalid length 2",
        |e| matches!(e, Error::Invalid { .. }),
    );
}

#[test]
fn non_finite_moment_is_rejected() {
    let s = scene("[body]\nmoments = [1, nan, 2]\n", INITIAL, RUN);
    rejected(
        "nan_moment",
        &[("scene.toml", &s)],
        "body.moments",
        "must be finite, got NaN",
        |e| matches!(e, Error::NotFinite { .. }),
    );
}

#[test]
fn non_finite_omega_is_rejected() {
    let s = scene(
        BODY,
        "[initial]\nrotor = [1, 0, 0, 0]\nomega = [inf, 0, 0]\n",
        RUN,
    );
    rejected(
        "inf_omega",
        &[("scene.toml", &s)],
        "initial.omega",
        "must be finite, got inf",
        |e| matches!(e, Error::NotFinite { .. }),
    );
}

#[test]
fn non_finite_t_end_is_rejected() {
    let s = scene(BODY, INITIAL, "[run]\nt_end = nan\nsamples = 11\n");
    rejected(
        "nan_t_end",
        &[("scene.toml", &s)],
        "run.t_end",
        "must be finite",
        |e| matches!(e, Error::NotFinite { .. }),
    );
}

#[test]
fn non_finite_gravity_is_rejected() {
    let s = format!(
        "{}[torque]\ng = [0, 0, -inf]\ncom_offset = [0, 0, 1]\n",
        scene(BODY, INITIAL, RUN)
    );
    rejected(
        "inf_gravity",
        &[("scene.toml", &s)],
        "torque.g",
        "must be finite",
        |e| matches!(e, Error::NotFinite { .. }),
    );
}

#[test]
fn negative_moment_is_rejected() {
    let s = scene("[body]\nmoments = [1, -1, 2]\n", INITIAL, RUN);
    rejected(
        "negative_moment",
        &[("scene.toml", &s)],
        "body.moments",
        "moments must be positive, got -1",
        |e| matches!(e, Error::NotPositive { .. }),
    );
}

#[test]
fn zero_moment_is_rejected() {
    let s = scene("[body]\nmoments = [1, 1, 0]\n", INITIAL, RUN);
    rejected(
        "zero_moment",
        &[("scene.toml", &s)],
        "body.moments",
        "moments must be positive, got 0",
        |e| matches!(e, Error::NotPositive { .. }),
    );
}

#[test]
fn triangle_inequality_is_enforced() {
    let s = scene("[body]\nmoments = [1, 2, 3.5]\n", INITIAL, RUN);
    rejected(
        "triangle",
        &[("scene.toml", &s)],
        "body.moments",
        "triangle inequality",
        |e| matches!(e, Error::TriangleInequality { .. }),
    );
}

#[test]
fn negative_shape_mass_is_rejected() {
    let s = scene(
        "[body]\nshape = { kind = \"box\", mass = -2, size = [1, 2, 3] }\n",
        INITIAL,
        RUN,
    );
    rejected(
        "negative_mass",
        &[("scene.toml", &s)],
        "body.shape.mass",
        "mass must be positive, got -2",
        |e| matches!(e, Error::NotPositive { .. }),
    );
}

#[test]
fn zero_shape_dimension_is_rejected() {
    let s = scene(
        "[body]\nshape = { kind = \"cone\", mass = 1, radius = 0, height = 1 }\n",
        INITIAL,
        RUN,
    );
    rejected(
        "zero_radius",
        &[("scene.toml", &s)],
        "body.shape.radius",
        "must be positive, got 0",
        |e| matches!(e, Error::NotPositive { .. }),
    );
}

#[test]
fn unknown_shape_kind_is_named() {
    let s = scene(
        "[body]\nshape = { kind = \"cube\", mass = 1, size = [1, 2, 3] }\n",
        INITIAL,
        RUN,
    );
    rejected(
        "unknown_kind",
        &[("scene.toml", &s)],
        "body.shape.kind",
        "unknown variant `cube`",
        |e| matches!(e, Error::Invalid { .. }),
    );
}

#[test]
fn missing_shape_field_is_named() {
    let s = scene(
        "[body]\nshape = { kind = \"cylinder\", mass = 1, radius = 1 }\n",
        INITIAL,
        RUN,
    );
    rejected(
        "missing_height",
        &[("scene.toml", &s)],
        "body.shape.height",
        "missing field",
        |e| matches!(e, Error::Invalid { .. }),
    );
}

#[test]
fn negative_point_mass_is_rejected() {
    let s = scene(
        "[body]\npoints = [[1, 0, 0, 1], [-1, 0, 1, 0], [1, 1, 0, 0]]\n",
        INITIAL,
        RUN,
    );
    rejected(
        "negative_point_mass",
        &[("scene.toml", &s)],
        "body.points[1]",
        "mass must be positive, got -1",
        |e| matches!(e, Error::NotPositive { .. }),
    );
}

#[test]
fn collinear_points_are_degenerate() {
    let s = scene(
        "[body]\npoints = [[1, 0, 0, 0], [1, 0, 0, 1], [1, 0, 0, 2]]\n",
        INITIAL,
        RUN,
    );
    rejected(
        "collinear_points",
        &[("scene.toml", &s)],
        "body.points",
        "degenerate",
        |e| matches!(e, Error::Degenerate { .. }),
    );
}

#[test]
fn two_body_descriptions_are_rejected() {
    let s = scene(
        "[body]\nmoments = [1, 2, 2.5]\nshape = { kind = \"sphere\", mass = 1, radius = 1 }\n",
        INITIAL,
        RUN,
    );
    rejected(
        "two_bodies",
        &[("scene.toml", &s)],
        "body",
        "exactly one of",
        |e| matches!(e, Error::Invalid { .. }),
    );
}

#[test]
fn no_body_description_is_rejected() {
    let s = scene("[body]\n", INITIAL, RUN);
    rejected("no_body", &[("scene.toml", &s)], "body", "got none", |e| {
        matches!(e, Error::Invalid { .. })
    });
}

#[test]
fn density_without_mesh_is_rejected() {
    let s = scene("[body]\nmoments = [1, 2, 2.5]\ndensity = 3\n", INITIAL, RUN);
    rejected(
        "density_without_mesh",
        &[("scene.toml", &s)],
        "body.density",
        "only used with",
        |e| matches!(e, Error::Invalid { .. }),
    );
}

#[test]
fn zero_rotor_is_rejected() {
    let s = scene(
        BODY,
        "[initial]\nrotor = [0, 0, 0, 0]\nomega = [1, 0, 0]\n",
        RUN,
    );
    rejected(
        "zero_rotor",
        &[("scene.toml", &s)],
        "initial.rotor",
        "the rotor is zero",
        |e| matches!(e, Error::ZeroRotor { .. }),
    );
}

#[test]
fn too_few_samples_are_rejected() {
    let s = scene(BODY, INITIAL, "[run]\nt_end = 1\nsamples = 1\n");
    rejected(
        "one_sample",
        &[("scene.toml", &s)],
        "run.samples",
        "at least 2, got 1",
        |e| matches!(e, Error::Invalid { .. }),
    );
    let s = scene(BODY, INITIAL, "[run]\nt_end = 1\nsamples = -5\n");
    rejected(
        "negative_samples",
        &[("scene.toml", &s)],
        "run.samples",
        "at least 2, got -5",
        |e| matches!(e, Error::Invalid { .. }),
    );
}

#[test]
fn absurd_sample_count_is_rejected() {
    let s = scene(BODY, INITIAL, "[run]\nt_end = 1\nsamples = 100000000000\n");
    rejected(
        "huge_samples",
        &[("scene.toml", &s)],
        "run.samples",
        "at most",
        |e| matches!(e, Error::Invalid { .. }),
    );
}

#[test]
fn non_positive_t_end_is_rejected() {
    let s = scene(BODY, INITIAL, "[run]\nt_end = 0\nsamples = 11\n");
    rejected(
        "zero_t_end",
        &[("scene.toml", &s)],
        "run.t_end",
        "must be positive, got 0",
        |e| matches!(e, Error::NotPositive { .. }),
    );
    let s = scene(BODY, INITIAL, "[run]\nt_end = -1\nsamples = 11\n");
    rejected(
        "negative_t_end",
        &[("scene.toml", &s)],
        "run.t_end",
        "must be positive, got -1",
        |e| matches!(e, Error::NotPositive { .. }),
    );
}

const CUBE_OBJ: &str = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n\
f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 4 8 7 3\nf 4 1 5 8\n";

#[test]
fn open_mesh_is_rejected() {
    let open = CUBE_OBJ.replace("f 4 1 5 8\n", "");
    let s = scene("[body]\nmesh = \"open.obj\"\ndensity = 1\n", INITIAL, RUN);
    rejected(
        "open_mesh",
        &[("scene.toml", &s), ("open.obj", &open)],
        "body.mesh",
        "the mesh is not closed",
        |e| matches!(e, Error::OpenMesh { .. }),
    );
}

#[test]
fn inside_out_mesh_is_rejected() {
    let flipped: String = CUBE_OBJ
        .lines()
        .map(|l| match l.strip_prefix("f ") {
            Some(rest) => {
                let mut refs: Vec<&str> = rest.split_whitespace().collect();
                refs.reverse();
                format!("f {}\n", refs.join(" "))
            }
            None => format!("{l}\n"),
        })
        .collect();
    let s = scene(
        "[body]\nmesh = \"inside_out.obj\"\ndensity = 1\n",
        INITIAL,
        RUN,
    );
    rejected(
        "inside_out_mesh",
        &[("scene.toml", &s), ("inside_out.obj", &flipped)],
        "body.mesh",
        "volume must be positive",
        |e| matches!(e, Error::Invalid { .. }),
    );
}

#[test]
fn bad_obj_line_is_named() {
    let bad = CUBE_OBJ.replace("f 4 1 5 8", "f 4 1 5 0");
    let s = scene("[body]\nmesh = \"bad.obj\"\ndensity = 1\n", INITIAL, RUN);
    rejected(
        "bad_obj_line",
        &[("scene.toml", &s), ("bad.obj", &bad)],
        "body.mesh",
        ":14: vertex index 0",
        |e| matches!(e, Error::Obj { .. }),
    );
}

#[test]
fn non_positive_density_is_rejected() {
    let s = scene("[body]\nmesh = \"cube.obj\"\ndensity = -1\n", INITIAL, RUN);
    rejected(
        "negative_density",
        &[("scene.toml", &s), ("cube.obj", CUBE_OBJ)],
        "body.density",
        "must be positive, got -1",
        |e| matches!(e, Error::NotPositive { .. }),
    );
}

#[test]
fn missing_mesh_file_is_named() {
    let s = scene(
        "[body]\nmesh = \"nowhere.obj\"\ndensity = 1\n",
        INITIAL,
        RUN,
    );
    rejected(
        "missing_mesh",
        &[("scene.toml", &s)],
        "body.mesh",
        "cannot read",
        |e| matches!(e, Error::Read { .. }),
    );
}

#[test]
fn mesh_without_density_is_rejected() {
    let s = scene("[body]\nmesh = \"cube.obj\"\n", INITIAL, RUN);
    rejected(
        "mesh_without_density",
        &[("scene.toml", &s)],
        "body.density",
        "needs a `density`",
        |e| matches!(e, Error::Invalid { .. }),
    );
}

#[test]
fn subnormal_moments_mass_and_density_are_rejected_naming_the_field() {
    let subnormal_moments = scene("[body]\nmoments = [1e-320, 1e-320, 1e-320]\n", INITIAL, RUN);
    rejected(
        "subnormal_moments",
        &[("scene.toml", &subnormal_moments)],
        "body.moments",
        "normal number",
        |e| matches!(e, Error::Invalid { .. }),
    );
    let subnormal_mass = scene(
        "[body]\nshape = { kind = \"box\", mass = 1e-320, size = [1, 2, 3] }\n",
        INITIAL,
        RUN,
    );
    rejected(
        "subnormal_mass",
        &[("scene.toml", &subnormal_mass)],
        "body.shape.mass",
        "normal number",
        |e| matches!(e, Error::Invalid { .. }),
    );
    let subnormal_point = scene(
        "[body]\npoints = [[1e-320, 1, 0, 0], [1, 0, 1, 0], [1, 0, 0, 1]]\n",
        INITIAL,
        RUN,
    );
    rejected(
        "subnormal_point",
        &[("scene.toml", &subnormal_point)],
        "body.points[0]",
        "normal number",
        |e| matches!(e, Error::Invalid { .. }),
    );
    let s = scene(
        "[body]\nmesh = \"cube.obj\"\ndensity = 5e-324\n",
        INITIAL,
        RUN,
    );
    rejected(
        "subnormal_density",
        &[("scene.toml", &s), ("cube.obj", CUBE_OBJ)],
        "body.density",
        "normal number",
        |e| matches!(e, Error::Invalid { .. }),
    );
}

#[test]
fn moments_whose_products_underflow_are_rejected() {
    let tiny = scene("[body]\nmoments = [1e-200, 1e-200, 1e-200]\n", INITIAL, RUN);
    rejected(
        "tiny_moments",
        &[("scene.toml", &tiny)],
        "body.moments",
        "between 1e-100",
        |e| matches!(e, Error::Invalid { .. }),
    );
    let tiny_box = scene(
        "[body]\nshape = { kind = \"box\", mass = 1e-250, size = [1, 2, 3] }\n",
        INITIAL,
        RUN,
    );
    rejected(
        "tiny_box",
        &[("scene.toml", &tiny_box)],
        "body.shape",
        "between 1e-100",
        |e| matches!(e, Error::Invalid { .. }),
    );
}

/// The 4D test body of docs/references.md: second moments (0.5, 0.9, 1.4, 2.0), R(0) = 1.
const FOUR: &str = "[body]\ndimension = 4\nsecond_moments = [0.5, 0.9, 1.4, 2.0]\n\n\
    [initial]\nrotor = [1, 0, 0, 0, 0, 0, 0, 0]\nomega = [1.0, 0, 0.4, -0.6, 0.2, 0.8]\n\n\
    [run]\nt_end = 10\nsamples = 11\n";

#[test]
fn bad_4d_input_names_its_field() {
    let is_invalid: fn(&Error) -> bool = |e| matches!(e, Error::Invalid { .. });
    let cases = [
        (
            "short-rotor",
            FOUR.replace("[1, 0, 0, 0, 0, 0, 0, 0]", "[1, 0, 0, 0]"),
            "initial.rotor",
            "4D rotors have 8 components",
            is_invalid,
        ),
        (
            "not-a-rotor",
            FOUR.replace("[1, 0, 0, 0, 0, 0, 0, 0]", "[1, 0, 0, 0, 0, 0, 0, 1]"),
            "initial.rotor",
            "not a rotor",
            is_invalid,
        ),
        (
            "3d-key",
            FOUR.replace("second_moments", "moments"),
            "body.moments",
            "unknown field",
            is_invalid,
        ),
        (
            "negative-moment",
            FOUR.replace("[0.5, 0.9, 1.4, 2.0]", "[0.5, -0.9, 1.4, 2.0]"),
            "body.second_moments[1]",
            "second moments cannot be negative, got -0.9",
            is_invalid,
        ),
        (
            "short-omega",
            FOUR.replace("[1.0, 0, 0.4, -0.6, 0.2, 0.8]", "[1.0, 0, 0.4]"),
            "initial.omega",
            "4D angular velocities have 6 components",
            is_invalid,
        ),
    ];
    for (name, scene, field, rule, kind) in cases {
        rejected_nd(name, &scene, field, rule, kind);
    }
}

#[test]
fn allow_unphysical_admits_the_literature_test_bodies() {
    let s = scene(
        "[body]\nmoments = [2, 1, 0.6666666666666666]\nallow_unphysical = true\n",
        INITIAL,
        RUN,
    );
    let scene_read = Scene::parse(&s, Path::new("scene.toml")).unwrap();
    let body = scene_read.principal_body().unwrap();
    let mut moments = body.moments();
    moments.sort_by(f64::total_cmp);
    assert_eq!(moments, [0.6666666666666666, 1.0, 2.0]);
    let s = scene(
        "[body]\nshape = { kind = \"sphere\", mass = 1, radius = 1 }\nallow_unphysical = true\n",
        INITIAL,
        RUN,
    );
    rejected(
        "unphysical_shape",
        &[("scene.toml", &s)],
        "body.allow_unphysical",
        "only used with",
        |e| matches!(e, Error::Invalid { .. }),
    );
}

#[test]
fn the_triangle_inequality_message_names_allow_unphysical_and_stays_short() {
    let s = scene("[body]\nmoments = [3.0, 5.0, 9.0]\n", INITIAL, RUN);
    let e = rejected(
        "dzhanibekov_moments",
        &[("scene.toml", &s)],
        "body.moments",
        "allow_unphysical = true",
        |e| {
            matches!(
                e,
                Error::TriangleInequality {
                    a: 3.0,
                    b: 5.0,
                    c: 9.0,
                    ..
                }
            )
        },
    );
    let count = e.to_string().chars().count();
    assert!(count <= 200, "{count} characters: {e}");
}

/// An attitude as an axis and an angle (glam's `Quat::from_axis_angle`): a quarter turn
/// about e3 is the rotor `exp(-e12 pi/4)`; an axis with a rotor, an axis without an angle
/// and a zero axis are refused.
#[test]
fn an_attitude_may_be_an_axis_and_an_angle() {
    let text = format!(
        "{BODY}[initial]\naxis = [0, 0, 2]\nangle = {}\nomega = [0, 0, 1]\n{RUN}",
        std::f64::consts::FRAC_PI_2
    );
    let rotor = Scene::parse(&text, Path::new("scene.toml"))
        .unwrap()
        .initial
        .rotor;
    let h = std::f64::consts::FRAC_1_SQRT_2;
    for (got, expected) in rotor.to_array().into_iter().zip([h, -h, 0.0, 0.0]) {
        assert!((got - expected).abs() < 1e-15, "{rotor:?}");
    }
    let is_invalid: fn(&Error) -> bool = |e| matches!(e, Error::Invalid { .. });
    let both = format!(
        "{BODY}[initial]\nrotor = [1, 0, 0, 0]\naxis = [0, 0, 1]\nangle = 1\nomega = [0, 0, 1]\n{RUN}"
    );
    rejected(
        "axis_and_rotor",
        &[("scene.toml", &both)],
        "initial.rotor",
        "not both",
        is_invalid,
    );
    let no_angle = format!("{BODY}[initial]\naxis = [0, 0, 1]\nomega = [0, 0, 1]\n{RUN}");
    rejected(
        "axis_no_angle",
        &[("scene.toml", &no_angle)],
        "initial.angle",
        "needs an `angle`",
        is_invalid,
    );
    let zero = format!("{BODY}[initial]\naxis = [0, 0, 0]\nangle = 1\nomega = [0, 0, 1]\n{RUN}");
    rejected(
        "zero_axis",
        &[("scene.toml", &zero)],
        "initial.axis",
        "must not be zero",
        is_invalid,
    );
}
