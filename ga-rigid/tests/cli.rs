//! The command line on bad input: exit status 2, one line on standard error naming the
//! field, nothing on standard output, and no `--out` file. And `inertia` on good input.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

const BIN: &str = env!("CARGO_BIN_EXE_ga-rigid");

const BODY: &str = "[body]\nmoments = [1.0, 2.0, 2.5]\n";
const INITIAL: &str = "[initial]\nrotor = [1, 0, 0, 0]\nomega = [0.1, 1.0, 0.2]\n";
const RUN: &str = "[run]\nt_end = 10.0\nsamples = 11\n";

/// A fresh directory for one test, under cargo's per-target temporary directory.
fn test_dir(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("ga-rigid-cli")
        .join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn write(dir: &Path, file: &str, text: &str) -> PathBuf {
    let path = dir.join(file);
    std::fs::write(&path, text).unwrap();
    path
}

fn run(dir: &Path, args: &[&str]) -> Output {
    Command::new(BIN)
        .args(args)
        .current_dir(dir)
        .output()
        .unwrap()
}

/// Run `simulate` on `scene` with `extra` arguments and check the failure contract:
/// status 2, empty stdout, one stderr line starting with `field`, containing `rule`,
/// and no output file.
fn expect_rejected_with(name: &str, scene: &str, extra: &[&str], field: &str, rule: &str) {
    expect_rejected_in(name, &[("scene.toml", scene)], extra, field, rule);
}

/// `expect_rejected_with` for a scene (`scene.toml`) with other files beside it.
fn expect_rejected_in(name: &str, files: &[(&str, &str)], extra: &[&str], field: &str, rule: &str) {
    let dir = test_dir(name);
    for (file, text) in files {
        write(&dir, file, text);
    }
    let mut args = vec!["simulate", "scene.toml"];
    args.extend_from_slice(extra);
    args.extend_from_slice(&["--out", "out.csv"]);
    let out = run(&dir, &args);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{name}: stderr {stderr}");
    assert!(out.stdout.is_empty(), "{name}: stdout not empty");
    assert_eq!(stderr.lines().count(), 1, "{name}: not one line: {stderr}");
    assert!(stderr.ends_with('\n'), "{name}: {stderr}");
    assert!(
        stderr.starts_with(field),
        "{name}: expected the field {field:?} first: {stderr}"
    );
    assert!(
        stderr.contains(rule),
        "{name}: expected {rule:?} in: {stderr}"
    );
    assert!(!dir.join("out.csv").exists(), "{name}: --out was written");
    let leftovers: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(|e| e.ok())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| !files.iter().any(|(f, _)| f == n))
        .collect();
    assert!(
        leftovers.is_empty(),
        "{name}: files left behind: {leftovers:?}"
    );
}

/// `expect_rejected_with` with a fixed-step method.
fn expect_rejected(name: &str, scene: &str, field: &str, rule: &str) {
    expect_rejected_with(
        name,
        scene,
        &["--method", "rk4", "--dt", "0.01"],
        field,
        rule,
    );
}

fn scene(body: &str, initial: &str, run: &str) -> String {
    format!("{body}{initial}{run}")
}

#[test]
fn missing_field_is_named() {
    let s = scene(BODY, INITIAL, "[run]\nsamples = 11\n");
    expect_rejected("missing_field", &s, "run.t_end: ", "missing field");
}

#[test]
fn missing_section_is_named() {
    let s = format!("{BODY}{RUN}");
    expect_rejected("missing_section", &s, "initial: ", "missing section");
}

#[test]
fn unknown_field_is_named() {
    let s = scene("[body]\nmoments = [1, 2, 2.5]\ncolour = 3\n", INITIAL, RUN);
    expect_rejected("unknown_field", &s, "body.colour: ", "unknown field");
}

#[test]
fn unknown_field_in_an_inline_table_is_named() {
    let s = scene(
        "[body]\nshape = { kind = \"box\", mass = 1, size = [1, 2, 3], colour = 3 }\n",
        INITIAL,
        RUN,
    );
    expect_rejected(
        "unknown_inline_field",
        &s,
        "body.shape.colour: ",
        "unknown field",
    );
}

#[test]
fn unknown_section_is_named() {
    let s = format!("{}[extra]\nx = 1\n", scene(BODY, INITIAL, RUN));
    expect_rejected("unknown_section", &s, "extra: ", "unknown section");
}

#[test]
fn duplicated_field_is_named() {
    let s = scene(
        "[body]\nmoments = [1, 2, 2.5]\nmoments = [1, 2, 2.5]\n",
        INITIAL,
        RUN,
    );
    expect_rejected("duplicated_field", &s, "body.moments: ", "duplicated key");
}

#[test]
fn duplicated_field_in_an_inline_table_is_named() {
    let s = scene(
        "[body]\nshape = { kind = \"box\", mass = 1, size = [1, 2, 3], mass = 2 }\n",
        INITIAL,
        RUN,
    );
    expect_rejected(
        "duplicated_inline",
        &s,
        "body.shape.mass: ",
        "duplicated key",
    );
}

#[test]
fn duplicated_section_is_named() {
    let s = format!("{}[run]\nt_end = 1\n", scene(BODY, INITIAL, RUN));
    expect_rejected("duplicated_section", &s, "run: ", "duplicated key");
}

#[test]
fn toml_syntax_error_gives_the_position() {
    let s = scene("[body]\nmoments = [1, 2, 2.5\n", INITIAL, RUN);
    expect_rejected("syntax_error", &s, "scene.toml:3:", "expected");
}

#[test]
fn wrong_type_is_named() {
    let s = scene("[body]\nmoments = \"heavy\"\n", INITIAL, RUN);
    expect_rejected("wrong_type", &s, "body.moments: ", "invalid type");
}

#[test]
fn wrong_array_length_is_named() {
    let s = scene("[body]\nmoments = [1, 2]\n", INITIAL, RUN);
    expect_rejected("wrong_length", &s, "body.moments: ", "invalid length 2");
}

#[test]
fn non_finite_moment_is_rejected() {
    let s = scene("[body]\nmoments = [1, nan, 2]\n", INITIAL, RUN);
    expect_rejected(
        "nan_moment",
        &s,
        "body.moments: ",
        "must be finite, got NaN",
    );
}

#[test]
fn non_finite_omega_is_rejected() {
    let s = scene(
        BODY,
        "[initial]\nrotor = [1, 0, 0, 0]\nomega = [inf, 0, 0]\n",
        RUN,
    );
    expect_rejected(
        "inf_omega",
        &s,
        "initial.omega: ",
        "must be finite, got inf",
    );
}

#[test]
fn non_finite_t_end_is_rejected() {
    let s = scene(BODY, INITIAL, "[run]\nt_end = nan\nsamples = 11\n");
    expect_rejected("nan_t_end", &s, "run.t_end: ", "must be finite");
}

#[test]
fn non_finite_gravity_is_rejected() {
    let s = format!(
        "{}[torque]\ng = [0, 0, -inf]\ncom_offset = [0, 0, 1]\n",
        scene(BODY, INITIAL, RUN)
    );
    expect_rejected("inf_gravity", &s, "torque.g: ", "must be finite");
}

#[test]
fn negative_moment_is_rejected() {
    let s = scene("[body]\nmoments = [1, -1, 2]\n", INITIAL, RUN);
    expect_rejected(
        "negative_moment",
        &s,
        "body.moments: ",
        "moments must be positive, got -1",
    );
}

#[test]
fn zero_moment_is_rejected() {
    let s = scene("[body]\nmoments = [1, 1, 0]\n", INITIAL, RUN);
    expect_rejected(
        "zero_moment",
        &s,
        "body.moments: ",
        "moments must be positive, got 0",
    );
}

#[test]
fn triangle_inequality_is_enforced() {
    let s = scene("[body]\nmoments = [1, 2, 3.5]\n", INITIAL, RUN);
    expect_rejected("triangle", &s, "body.moments: ", "triangle inequality");
}

#[test]
fn allow_unphysical_admits_the_literature_test_bodies() {
    let dir = test_dir("unphysical");
    let s = scene(
        "[body]\nmoments = [2, 1, 0.6666666666666666]\nallow_unphysical = true\n",
        INITIAL,
        RUN,
    );
    write(&dir, "scene.toml", &s);
    let out = run(&dir, &["inertia", "scene.toml"]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let s = scene(
        "[body]\nshape = { kind = \"sphere\", mass = 1, radius = 1 }\nallow_unphysical = true\n",
        INITIAL,
        RUN,
    );
    expect_rejected(
        "unphysical_shape",
        &s,
        "body.allow_unphysical: ",
        "only used with",
    );
}

#[test]
fn negative_shape_mass_is_rejected() {
    let s = scene(
        "[body]\nshape = { kind = \"box\", mass = -2, size = [1, 2, 3] }\n",
        INITIAL,
        RUN,
    );
    expect_rejected(
        "negative_mass",
        &s,
        "body.shape.mass: ",
        "mass must be positive, got -2",
    );
}

#[test]
fn zero_shape_dimension_is_rejected() {
    let s = scene(
        "[body]\nshape = { kind = \"cone\", mass = 1, radius = 0, height = 1 }\n",
        INITIAL,
        RUN,
    );
    expect_rejected(
        "zero_radius",
        &s,
        "body.shape.radius: ",
        "must be positive, got 0",
    );
}

#[test]
fn unknown_shape_kind_is_named() {
    let s = scene(
        "[body]\nshape = { kind = \"cube\", mass = 1, size = [1, 2, 3] }\n",
        INITIAL,
        RUN,
    );
    expect_rejected(
        "unknown_kind",
        &s,
        "body.shape.kind: ",
        "unknown variant `cube`",
    );
}

#[test]
fn missing_shape_field_is_named() {
    let s = scene(
        "[body]\nshape = { kind = \"cylinder\", mass = 1, radius = 1 }\n",
        INITIAL,
        RUN,
    );
    expect_rejected("missing_height", &s, "body.shape.height: ", "missing field");
}

#[test]
fn negative_point_mass_is_rejected() {
    let s = scene(
        "[body]\npoints = [[1, 0, 0, 1], [-1, 0, 1, 0], [1, 1, 0, 0]]\n",
        INITIAL,
        RUN,
    );
    expect_rejected(
        "negative_point_mass",
        &s,
        "body.points[1]: ",
        "mass must be positive, got -1",
    );
}

#[test]
fn collinear_points_are_degenerate() {
    let s = scene(
        "[body]\npoints = [[1, 0, 0, 0], [1, 0, 0, 1], [1, 0, 0, 2]]\n",
        INITIAL,
        RUN,
    );
    expect_rejected("collinear_points", &s, "body.points: ", "degenerate");
}

#[test]
fn two_body_descriptions_are_rejected() {
    let s = scene(
        "[body]\nmoments = [1, 2, 2.5]\nshape = { kind = \"sphere\", mass = 1, radius = 1 }\n",
        INITIAL,
        RUN,
    );
    expect_rejected("two_bodies", &s, "body: ", "exactly one of");
}

#[test]
fn no_body_description_is_rejected() {
    let s = scene("[body]\n", INITIAL, RUN);
    expect_rejected("no_body", &s, "body: ", "got none");
}

#[test]
fn density_without_mesh_is_rejected() {
    let s = scene("[body]\nmoments = [1, 2, 2.5]\ndensity = 3\n", INITIAL, RUN);
    expect_rejected(
        "density_without_mesh",
        &s,
        "body.density: ",
        "only used with",
    );
}

#[test]
fn zero_rotor_is_rejected() {
    let s = scene(
        BODY,
        "[initial]\nrotor = [0, 0, 0, 0]\nomega = [1, 0, 0]\n",
        RUN,
    );
    expect_rejected("zero_rotor", &s, "initial.rotor: ", "the rotor is zero");
}

#[test]
fn too_few_samples_are_rejected() {
    let s = scene(BODY, INITIAL, "[run]\nt_end = 1\nsamples = 1\n");
    expect_rejected("one_sample", &s, "run.samples: ", "at least 2, got 1");
    let s = scene(BODY, INITIAL, "[run]\nt_end = 1\nsamples = -5\n");
    expect_rejected(
        "negative_samples",
        &s,
        "run.samples: ",
        "at least 2, got -5",
    );
}

#[test]
fn absurd_sample_count_is_rejected() {
    let s = scene(BODY, INITIAL, "[run]\nt_end = 1\nsamples = 100000000000\n");
    expect_rejected("huge_samples", &s, "run.samples: ", "at most");
}

#[test]
fn non_positive_t_end_is_rejected() {
    let s = scene(BODY, INITIAL, "[run]\nt_end = 0\nsamples = 11\n");
    expect_rejected("zero_t_end", &s, "run.t_end: ", "must be positive, got 0");
    let s = scene(BODY, INITIAL, "[run]\nt_end = -1\nsamples = 11\n");
    expect_rejected(
        "negative_t_end",
        &s,
        "run.t_end: ",
        "must be positive, got -1",
    );
}

const CUBE_OBJ: &str = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n\
f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 4 8 7 3\nf 4 1 5 8\n";

#[test]
fn open_mesh_is_rejected() {
    let open = CUBE_OBJ.replace("f 4 1 5 8\n", "");
    let s = scene("[body]\nmesh = \"open.obj\"\ndensity = 1\n", INITIAL, RUN);
    expect_rejected_in(
        "open_mesh",
        &[("scene.toml", &s), ("open.obj", &open)],
        &["--method", "rk4", "--dt", "0.1"],
        "body.mesh: ",
        "the mesh is not closed",
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
    expect_rejected_in(
        "inside_out_mesh",
        &[("scene.toml", &s), ("inside_out.obj", &flipped)],
        &["--method", "rk4", "--dt", "0.1"],
        "body.mesh: ",
        "volume must be positive",
    );
}

#[test]
fn bad_obj_line_is_named() {
    let bad = CUBE_OBJ.replace("f 4 1 5 8", "f 4 1 5 0");
    let s = scene("[body]\nmesh = \"bad.obj\"\ndensity = 1\n", INITIAL, RUN);
    expect_rejected_in(
        "bad_obj_line",
        &[("scene.toml", &s), ("bad.obj", &bad)],
        &["--method", "rk4", "--dt", "0.1"],
        "body.mesh: ",
        ":14: vertex index 0",
    );
}

#[test]
fn non_positive_density_is_rejected() {
    let s = scene("[body]\nmesh = \"cube.obj\"\ndensity = -1\n", INITIAL, RUN);
    expect_rejected_in(
        "negative_density",
        &[("scene.toml", &s), ("cube.obj", CUBE_OBJ)],
        &["--method", "rk4", "--dt", "0.1"],
        "body.density: ",
        "must be positive, got -1",
    );
}

#[test]
fn missing_mesh_file_is_named() {
    let s = scene(
        "[body]\nmesh = \"nowhere.obj\"\ndensity = 1\n",
        INITIAL,
        RUN,
    );
    expect_rejected("missing_mesh", &s, "body.mesh: ", "cannot read");
}

#[test]
fn mesh_without_density_is_rejected() {
    let s = scene("[body]\nmesh = \"cube.obj\"\n", INITIAL, RUN);
    expect_rejected(
        "mesh_without_density",
        &s,
        "body.density: ",
        "needs a `density`",
    );
}

#[test]
fn mesh_scene_resolves_the_obj_next_to_the_scene_file() {
    let dir = test_dir("mesh_relative");
    std::fs::create_dir_all(dir.join("scenes")).unwrap();
    write(&dir, "scenes/cube.obj", CUBE_OBJ);
    let s = scene("[body]\nmesh = \"cube.obj\"\ndensity = 6\n", INITIAL, RUN);
    write(&dir, "scenes/scene.toml", &s);
    let out = run(&dir, &["inertia", "scenes/scene.toml"]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(stdout.contains("mass: 6\n"), "{stdout}");
    assert!(
        stdout.contains("centre_of_mass: [0.5, 0.5, 0.5]"),
        "{stdout}"
    );
    // A unit cube of mass 6: 6 (1 + 1) / 12 = 1 about every axis.
    let moments = parse_list(&stdout, "moments: ");
    for m in moments {
        assert!((m - 1.0).abs() < 1e-13, "{stdout}");
    }
}

#[test]
fn negative_dt_is_rejected() {
    let s = scene(BODY, INITIAL, RUN);
    expect_rejected_with(
        "negative_dt",
        &s,
        &["--method", "rk4", "--dt", "-0.1"],
        "--dt: ",
        "positive",
    );
}

#[test]
fn zero_dt_is_rejected() {
    let s = scene(BODY, INITIAL, RUN);
    expect_rejected_with(
        "zero_dt",
        &s,
        &["--method", "splitting", "--dt", "0"],
        "--dt: ",
        "got 0",
    );
}

#[test]
fn zero_tol_is_rejected() {
    let s = scene(BODY, INITIAL, RUN);
    expect_rejected_with(
        "zero_tol",
        &s,
        &["--method", "dopri", "--tol", "0"],
        "--tol: ",
        "positive",
    );
}

#[test]
fn nan_dt_is_rejected() {
    let s = scene(BODY, INITIAL, RUN);
    expect_rejected_with(
        "nan_dt",
        &s,
        &["--method", "rk4", "--dt", "NaN"],
        "--dt: ",
        "finite",
    );
}

#[test]
fn dt_and_tol_are_exclusive() {
    let s = scene(BODY, INITIAL, RUN);
    expect_rejected_with(
        "dt_and_tol",
        &s,
        &["--method", "dopri", "--dt", "0.1", "--tol", "1e-8"],
        "error: ",
        "--tol",
    );
}

#[test]
fn fixed_step_method_needs_dt() {
    let s = scene(BODY, INITIAL, RUN);
    expect_rejected_with(
        "rk4_with_tol",
        &s,
        &["--method", "lie-rk4", "--tol", "1e-9"],
        "--tol: ",
        "give --dt",
    );
}

#[test]
fn adaptive_method_needs_tol() {
    let s = scene(BODY, INITIAL, RUN);
    expect_rejected_with(
        "dopri_with_dt",
        &s,
        &["--method", "dopri", "--dt", "0.1"],
        "--dt: ",
        "give --tol",
    );
}

#[test]
fn exact_method_takes_no_step() {
    let s = scene(BODY, INITIAL, RUN);
    expect_rejected_with(
        "exact_with_dt",
        &s,
        &["--method", "exact", "--dt", "0.1"],
        "--dt: ",
        "no --dt",
    );
}

#[test]
fn unknown_method_is_a_usage_error() {
    let s = scene(BODY, INITIAL, RUN);
    expect_rejected_with(
        "unknown_method",
        &s,
        &["--method", "euler"],
        "error: ",
        "--method",
    );
}

#[test]
fn missing_scene_file_is_named() {
    let dir = test_dir("missing_scene");
    let out = run(
        &dir,
        &[
            "simulate",
            "nowhere.toml",
            "--method",
            "rk4",
            "--dt",
            "0.1",
            "--out",
            "out.csv",
        ],
    );
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(out.stdout.is_empty());
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(
        stderr.starts_with("SCENE: cannot read nowhere.toml"),
        "{stderr}"
    );
    assert!(!dir.join("out.csv").exists());
}

#[test]
fn out_in_a_missing_directory_is_rejected() {
    let dir = test_dir("missing_out_dir");
    write(&dir, "scene.toml", &scene(BODY, INITIAL, RUN));
    let out = run(
        &dir,
        &[
            "simulate",
            "scene.toml",
            "--method",
            "rk4",
            "--dt",
            "0.1",
            "--out",
            "no/such/out.csv",
        ],
    );
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(out.stdout.is_empty());
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(stderr.starts_with("--out: "), "{stderr}");
}

#[test]
fn missing_arguments_are_one_line_usage_errors() {
    let dir = test_dir("missing_args");
    for args in [
        &["simulate"][..],
        &[][..],
        &["inertia"][..],
        &["frobnicate"][..],
    ] {
        let out = run(&dir, args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(out.stdout.is_empty(), "{args:?}");
        assert_eq!(stderr.lines().count(), 1, "{args:?}: {stderr}");
    }
}

fn parse_list(stdout: &str, prefix: &str) -> Vec<f64> {
    let line = stdout
        .lines()
        .find_map(|l| l.strip_prefix(prefix))
        .unwrap_or_else(|| panic!("no {prefix:?} line in {stdout}"));
    line.trim_matches(|c| c == '[' || c == ']')
        .split(", ")
        .map(|x| x.parse().unwrap())
        .collect()
}

#[test]
fn inertia_prints_the_box_moments() {
    let dir = test_dir("inertia_box");
    let s = scene(
        "[body]\nshape = { kind = \"box\", mass = 2.0, size = [1, 2, 3] }\n",
        INITIAL,
        RUN,
    );
    write(&dir, "scene.toml", &s);
    let out = run(&dir, &["inertia", "scene.toml"]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(out.stderr.is_empty());
    assert!(stdout.contains("mass: 2\n"), "{stdout}");
    assert!(stdout.contains("centre_of_mass: [0, 0, 0]\n"), "{stdout}");
    let moments = parse_list(&stdout, "moments: ");
    let expected = [
        2.0 * (4.0 + 9.0) / 12.0,
        2.0 * (1.0 + 9.0) / 12.0,
        2.0 * (1.0 + 4.0) / 12.0,
    ];
    assert_eq!(moments.len(), 3);
    for (m, e) in moments.iter().zip(expected) {
        assert!((m - e).abs() <= 1e-15 * e, "{stdout}");
    }
    assert_eq!(parse_list(&stdout, "rotor: "), vec![1.0, 0.0, 0.0, 0.0]);
}

#[test]
fn inertia_of_bad_scene_fails_the_same_way() {
    let dir = test_dir("inertia_bad");
    write(
        &dir,
        "scene.toml",
        &scene("[body]\nmoments = [1, 1, 0]\n", INITIAL, RUN),
    );
    let out = run(&dir, &["inertia", "scene.toml"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(out.stdout.is_empty());
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(stderr.starts_with("body.moments: "), "{stderr}");
}

/// `simulate ... --out out.csv` in `dir` (a good scene already there), expecting the
/// refusal contract: status 2, one line starting `--out: ` and containing `rule`.
fn expect_out_refused(dir: &Path, rule: &str) {
    let out = run(
        dir,
        &[
            "simulate",
            "scene.toml",
            "--method",
            "exact",
            "--out",
            "out.csv",
        ],
    );
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(out.stdout.is_empty());
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(stderr.starts_with("--out: "), "{stderr}");
    assert!(stderr.contains(rule), "expected {rule:?} in {stderr}");
    let temporaries: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .filter_map(|e| e.ok())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| n.contains(".tmp-"))
        .collect();
    assert!(temporaries.is_empty(), "{temporaries:?}");
}

fn make_fifo(path: &Path) {
    let status = Command::new("mkfifo").arg(path).status().unwrap();
    assert!(status.success(), "mkfifo failed");
}

#[cfg(unix)]
#[test]
fn out_onto_a_fifo_is_refused_and_the_fifo_kept() {
    use std::os::unix::fs::FileTypeExt as _;
    let dir = test_dir("out_fifo");
    write(&dir, "scene.toml", &scene(BODY, INITIAL, RUN));
    make_fifo(&dir.join("out.csv"));
    expect_out_refused(&dir, "is a FIFO, not a regular file");
    let kind = std::fs::symlink_metadata(dir.join("out.csv"))
        .unwrap()
        .file_type();
    assert!(kind.is_fifo(), "the FIFO was replaced");
}

#[test]
fn out_onto_a_directory_is_refused() {
    let dir = test_dir("out_dir");
    write(&dir, "scene.toml", &scene(BODY, INITIAL, RUN));
    std::fs::create_dir(dir.join("out.csv")).unwrap();
    expect_out_refused(&dir, "is a directory");
    assert!(dir.join("out.csv").is_dir());
}

#[cfg(unix)]
#[test]
fn out_through_a_symlink_to_a_fifo_is_refused() {
    use std::os::unix::fs::FileTypeExt as _;
    let dir = test_dir("out_link_fifo");
    write(&dir, "scene.toml", &scene(BODY, INITIAL, RUN));
    make_fifo(&dir.join("pipe"));
    std::os::unix::fs::symlink("pipe", dir.join("out.csv")).unwrap();
    expect_out_refused(&dir, "is a FIFO");
    assert!(std::fs::symlink_metadata(dir.join("out.csv"))
        .unwrap()
        .file_type()
        .is_symlink());
    assert!(std::fs::symlink_metadata(dir.join("pipe"))
        .unwrap()
        .file_type()
        .is_fifo());
}

#[cfg(unix)]
#[test]
fn out_through_a_dangling_symlink_is_refused() {
    let dir = test_dir("out_link_dangling");
    write(&dir, "scene.toml", &scene(BODY, INITIAL, RUN));
    std::os::unix::fs::symlink("nowhere.csv", dir.join("out.csv")).unwrap();
    expect_out_refused(&dir, "symbolic link to a missing file");
    assert!(!dir.join("nowhere.csv").exists());
}

#[cfg(unix)]
#[test]
fn out_through_a_symlink_replaces_its_target_and_keeps_the_link() {
    let dir = test_dir("out_link_file");
    write(&dir, "scene.toml", &scene(BODY, INITIAL, RUN));
    std::fs::create_dir(dir.join("data")).unwrap();
    write(&dir, "data/target.csv", "old contents\n");
    std::os::unix::fs::symlink("data/target.csv", dir.join("out.csv")).unwrap();
    let out = run(
        &dir,
        &[
            "simulate",
            "scene.toml",
            "--method",
            "exact",
            "--out",
            "out.csv",
        ],
    );
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(std::fs::symlink_metadata(dir.join("out.csv"))
        .unwrap()
        .file_type()
        .is_symlink());
    let text = std::fs::read_to_string(dir.join("data/target.csv")).unwrap();
    assert!(text.contains("t,r_s,r_e12,r_e13,r_e23,w1,w2,w3,energy,l1,l2,l3\n"));
    let names: Vec<_> = std::fs::read_dir(dir.join("data"))
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(names.len(), 1, "temporary file left behind: {names:?}");
}

#[test]
fn out_replaces_a_regular_file_and_creates_a_missing_one() {
    let dir = test_dir("out_regular");
    write(&dir, "scene.toml", &scene(BODY, INITIAL, RUN));
    write(&dir, "old.csv", "old contents\n");
    for name in ["old.csv", "new.csv"] {
        let out = run(
            &dir,
            &["simulate", "scene.toml", "--method", "exact", "--out", name],
        );
        assert_eq!(
            out.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        assert!(out.stdout.is_empty());
        let text = std::fs::read_to_string(dir.join(name)).unwrap();
        assert!(text.contains("t,r_s,r_e12,r_e13,r_e23,w1,w2,w3,energy,l1,l2,l3\n"));
    }
}

#[test]
fn overflowing_energy_is_rejected_for_every_method() {
    // Issue 12: `exact` and `splitting` wrote `energy = inf` here and exited 0.
    let s = scene(
        "[body]\nmoments = [1, 1, 1]\n",
        "[initial]\nrotor = [1, 0, 0, 0]\nomega = [0, 0, 1e200]\n",
        RUN,
    );
    for (k, method) in [
        &["--method", "exact"][..],
        &["--method", "splitting", "--dt", "0.01"][..],
        &["--method", "closed-form"][..],
        &["--method", "rk4", "--dt", "0.01"][..],
        &["--method", "dopri", "--tol", "1e-8"][..],
    ]
    .iter()
    .enumerate()
    {
        expect_rejected_with(
            &format!("overflowing_energy_{k}"),
            &s,
            method,
            "initial.omega: ",
            "overflow",
        );
    }
}

#[test]
fn subnormal_moments_mass_and_density_are_rejected_naming_the_field() {
    let subnormal_moments = scene("[body]\nmoments = [1e-320, 1e-320, 1e-320]\n", INITIAL, RUN);
    expect_rejected_with(
        "subnormal_moments",
        &subnormal_moments,
        &["--method", "splitting", "--dt", "0.01"],
        "body.moments: ",
        "normal number",
    );
    let subnormal_mass = scene(
        "[body]\nshape = { kind = \"box\", mass = 1e-320, size = [1, 2, 3] }\n",
        INITIAL,
        RUN,
    );
    expect_rejected(
        "subnormal_mass",
        &subnormal_mass,
        "body.shape.mass: ",
        "normal number",
    );
    let subnormal_point = scene(
        "[body]\npoints = [[1e-320, 1, 0, 0], [1, 0, 1, 0], [1, 0, 0, 1]]\n",
        INITIAL,
        RUN,
    );
    expect_rejected(
        "subnormal_point",
        &subnormal_point,
        "body.points[0]: ",
        "normal number",
    );
    let s = scene(
        "[body]\nmesh = \"cube.obj\"\ndensity = 5e-324\n",
        INITIAL,
        RUN,
    );
    expect_rejected_in(
        "subnormal_density",
        &[("scene.toml", &s), ("cube.obj", CUBE_OBJ)],
        &["--method", "rk4", "--dt", "0.1"],
        "body.density: ",
        "normal number",
    );
}

#[test]
fn moments_whose_products_underflow_are_rejected() {
    let tiny = scene("[body]\nmoments = [1e-200, 1e-200, 1e-200]\n", INITIAL, RUN);
    expect_rejected("tiny_moments", &tiny, "body.moments: ", "between 1e-100");
    let tiny_box = scene(
        "[body]\nshape = { kind = \"box\", mass = 1e-250, size = [1, 2, 3] }\n",
        INITIAL,
        RUN,
    );
    expect_rejected("tiny_box", &tiny_box, "body.shape: ", "between 1e-100");
}

/// `expect_rejected_with`, and the line is at most 200 characters.
fn expect_short_rejection(name: &str, scene: &str, extra: &[&str], field: &str, rule: &str) {
    expect_rejected_with(name, scene, extra, field, rule);
    let dir = test_dir(name);
    write(&dir, "scene.toml", scene);
    let mut args = vec!["simulate", "scene.toml"];
    args.extend_from_slice(extra);
    let out = run(&dir, &args);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.trim_end().chars().count() <= 200,
        "{name}: {} characters: {stderr}",
        stderr.trim_end().chars().count()
    );
}

#[test]
fn runs_that_cannot_finish_are_refused_up_front() {
    // Issue 12: 10^14 steps started and ran for months, printing nothing.
    let long = scene(BODY, INITIAL, "[run]\nt_end = 1e12\nsamples = 11\n");
    expect_short_rejection(
        "long_run",
        &long,
        &["--method", "rk4", "--dt", "0.01"],
        "--dt: ",
        "above the limit 100000000; raise it with --max-steps",
    );
    let s = scene(BODY, INITIAL, RUN);
    expect_short_rejection(
        "tiny_dt",
        &s,
        &["--method", "splitting", "--dt", "1e-9"],
        "--dt: ",
        "--max-steps",
    );
    expect_short_rejection(
        "tiny_dt_300",
        &s,
        &["--method", "midpoint", "--dt", "1e-300"],
        "--dt: ",
        "--max-steps",
    );
    expect_short_rejection(
        "lowered_limit",
        &s,
        &["--method", "rk4", "--dt", "0.001", "--max-steps", "1000"],
        "--dt: ",
        "above the limit 1000",
    );
    expect_short_rejection(
        "long_dopri",
        &long,
        &["--method", "dopri", "--tol", "1e-10"],
        "--tol: ",
        "--max-steps",
    );
    let many_rows = scene(BODY, INITIAL, "[run]\nt_end = 1\nsamples = 10000000\n");
    expect_short_rejection(
        "big_output",
        &many_rows,
        &["--method", "exact"],
        "run.samples: ",
        "--max-output-mb",
    );
}

#[test]
fn max_steps_raises_the_limit() {
    let dir = test_dir("max_steps_raised");
    write(
        &dir,
        "scene.toml",
        &scene(BODY, INITIAL, "[run]\nt_end = 1\nsamples = 3\n"),
    );
    let base = ["simulate", "scene.toml", "--method", "rk4", "--dt", "1e-4"];
    let refused = run(&dir, &[&base[..], &["--max-steps", "100"]].concat());
    assert_eq!(refused.status.code(), Some(2));
    let allowed = run(&dir, &[&base[..], &["--max-steps", "20000"]].concat());
    assert_eq!(
        allowed.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&allowed.stderr)
    );
    assert_eq!(String::from_utf8_lossy(&allowed.stdout).lines().count(), 4);
}

/// Run with a deadline: a command that blocks on a FIFO or reads without end is killed
/// and the test fails instead of hanging.
fn run_with_deadline(dir: &Path, args: &[&str]) -> Output {
    use std::time::{Duration, Instant};
    let mut child = Command::new(BIN)
        .args(args)
        .current_dir(dir)
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let start = Instant::now();
    while child.try_wait().unwrap().is_none() {
        if start.elapsed() > Duration::from_secs(20) {
            child.kill().unwrap();
            let _ = child.wait();
            panic!("{args:?} did not finish in 20 s");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    child.wait_with_output().unwrap()
}

fn expect_read_refused(dir: &Path, scene: &str, field: &str, rule: &str) {
    let out = run_with_deadline(dir, &["simulate", scene, "--method", "exact"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(out.stdout.is_empty());
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(stderr.starts_with(field), "{stderr}");
    assert!(stderr.contains(rule), "expected {rule:?} in {stderr}");
}

#[cfg(unix)]
#[test]
fn a_fifo_scene_or_mesh_is_refused_without_blocking() {
    let dir = test_dir("fifo_inputs");
    make_fifo(&dir.join("scene.toml"));
    expect_read_refused(&dir, "scene.toml", "SCENE: ", "not a regular file");
    write(
        &dir,
        "mesh.toml",
        &scene("[body]\nmesh = \"body.obj\"\ndensity = 1\n", INITIAL, RUN),
    );
    make_fifo(&dir.join("body.obj"));
    expect_read_refused(&dir, "mesh.toml", "body.mesh: ", "not a regular file");
}

#[test]
fn a_directory_scene_is_refused() {
    let dir = test_dir("dir_scene");
    std::fs::create_dir(dir.join("scene.toml")).unwrap();
    expect_read_refused(&dir, "scene.toml", "SCENE: ", "not a regular file");
}

#[test]
fn oversized_scene_and_mesh_files_are_refused_before_reading() {
    let dir = test_dir("big_inputs");
    // Sparse files: the size is there, the disk blocks are not.
    let big_scene = std::fs::File::create(dir.join("scene.toml")).unwrap();
    big_scene
        .set_len(ga_rigid::scene::MAX_SCENE_BYTES + 1)
        .unwrap();
    expect_read_refused(&dir, "scene.toml", "SCENE: ", "more than the limit");
    write(
        &dir,
        "mesh.toml",
        &scene("[body]\nmesh = \"body.obj\"\ndensity = 1\n", INITIAL, RUN),
    );
    let big_mesh = std::fs::File::create(dir.join("body.obj")).unwrap();
    big_mesh
        .set_len(ga_rigid::inertia::MAX_MESH_BYTES + 1)
        .unwrap();
    expect_read_refused(&dir, "mesh.toml", "body.mesh: ", "more than the limit");
}

#[test]
fn a_value_missing_at_the_end_of_the_file_has_a_message() {
    // Issue 12: the line was `empty_value.toml:1:5: ` and nothing after.
    expect_short_rejection(
        "empty_value",
        "a = ",
        &["--method", "exact"],
        "scene.toml:1:5: ",
        "the file ends where a value was expected",
    );
}

#[test]
fn a_subnormal_tolerance_blames_tol_not_atol() {
    let s = scene(BODY, INITIAL, RUN);
    expect_short_rejection(
        "subnormal_tol",
        &s,
        &["--method", "dopri", "--tol", "5e-324"],
        "--tol: ",
        "between 1e-14 and 1, got 5e-324",
    );
}

#[test]
fn negative_infinite_and_exponent_values_reach_our_own_check() {
    // Issue 12: clap answered "unexpected argument '-i' found".
    let s = scene(BODY, INITIAL, RUN);
    expect_short_rejection(
        "minus_inf_dt",
        &s,
        &["--method", "rk4", "--dt", "-inf"],
        "--dt: ",
        "positive and finite, got -inf",
    );
    expect_short_rejection(
        "negative_exponent_tol",
        &s,
        &["--method", "dopri", "--tol", "-1e-6"],
        "--tol: ",
        "positive and finite, got -1e-6",
    );
}

#[test]
fn closed_form_on_a_box_or_mesh_names_what_the_scene_wrote() {
    let boxed = scene(
        "[body]\nshape = { kind = \"box\", mass = 2.0, size = [1, 2, 3] }\n",
        INITIAL,
        RUN,
    );
    expect_short_rejection(
        "closed_form_box",
        &boxed,
        &["--method", "closed-form"],
        "body.shape: ",
        "symmetric",
    );
    let brick = CUBE_OBJ.replace("v 1 1 1", "v 1 1 2");
    let meshed = scene("[body]\nmesh = \"brick.obj\"\ndensity = 1\n", INITIAL, RUN);
    expect_rejected_in(
        "closed_form_mesh",
        &[("scene.toml", &meshed), ("brick.obj", &brick)],
        &["--method", "closed-form"],
        "body.mesh: ",
        "symmetric",
    );
}

#[test]
fn long_values_are_echoed_cut() {
    let long = "a".repeat(100_000);
    let s = scene(
        &format!("[body]\nshape = {{ kind = \"{long}\", mass = 2.0, size = [1, 2, 3] }}\n"),
        INITIAL,
        RUN,
    );
    expect_short_rejection(
        "long_kind",
        &s,
        &["--method", "exact"],
        "body.shape.kind: ",
        "(100000 characters)",
    );
    let s = scene(&format!("[body]\nmoments = \"{long}\"\n"), INITIAL, RUN);
    expect_short_rejection(
        "long_string",
        &s,
        &["--method", "exact"],
        "body.moments: ",
        "(100000 characters)",
    );
    let s = scene(
        &format!("[body]\nmoments = [1, 2, 2.5]\n{long} = 1\n"),
        INITIAL,
        RUN,
    );
    expect_short_rejection(
        "long_key",
        &s,
        &["--method", "exact"],
        "body.aaaa",
        "unknown field",
    );
    let s = scene(
        &format!("[body]\nmesh = \"{long}.obj\"\ndensity = 1\n"),
        INITIAL,
        RUN,
    );
    expect_short_rejection(
        "long_mesh_path",
        &s,
        &["--method", "exact"],
        "body.mesh: ",
        "characters)",
    );
}

#[test]
fn csv_numbers_are_plain_decimal_without_exponent_shorthand() {
    // Issue 9: `0e0`, `-0e0` and `1e1` were written for 0, -0 and 10.
    let dir = test_dir("csv_format");
    write(
        &dir,
        "scene.toml",
        &scene(
            BODY,
            "[initial]\nrotor = [1, 0, 0, 0]\nomega = [0, 0, -1]\n",
            RUN,
        ),
    );
    let out = run(&dir, &["simulate", "scene.toml", "--method", "exact"]);
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8(out.stdout).unwrap();
    let mut lines = text.lines().filter(|l| !l.starts_with('#'));
    assert_eq!(
        lines.next(),
        Some("t,r_s,r_e12,r_e13,r_e23,w1,w2,w3,energy,l1,l2,l3")
    );
    let rows: Vec<&str> = lines.collect();
    assert_eq!(rows.len(), 11);
    for row in &rows {
        for value in row.split(',') {
            assert!(!value.contains('e'), "{value} in {row}");
            assert!(!value.starts_with("-0.000000"), "{value} in {row}");
            let digits = value.chars().filter(char::is_ascii_digit).count();
            let leading = value
                .trim_start_matches('-')
                .chars()
                .take_while(|c| *c == '0' || *c == '.')
                .filter(|c| *c == '0')
                .count();
            let significant = if value.trim_start_matches(['-', '0', '.']).is_empty() {
                digits
            } else {
                digits - leading
            };
            assert_eq!(significant, 17, "{value} in {row}");
        }
    }
    assert!(rows[10].starts_with("10.000000000000000,"), "{}", rows[10]);
}

/// The sidecar JSON of `simulate ... --out out.csv`, as (key, raw value) pairs.
fn sidecar(dir: &Path) -> Vec<(String, String)> {
    let text = std::fs::read_to_string(dir.join("out.csv.json")).unwrap();
    text.lines()
        .filter_map(|l| l.trim().trim_end_matches(',').split_once(": "))
        .map(|(k, v)| (k.trim_matches('"').to_string(), v.to_string()))
        .collect()
}

fn value<'a>(pairs: &'a [(String, String)], key: &str) -> &'a str {
    pairs
        .iter()
        .find(|(k, _)| k == key)
        .map(|(_, v)| v.as_str())
        .unwrap_or_else(|| panic!("no {key} in {pairs:?}"))
}

#[test]
fn default_dt_is_a_two_hundredth_of_the_fastest_period_and_recorded() {
    let dir = test_dir("default_dt");
    // Moments (1, 2, 2.5), w = (0, 0, 2): a steady spin about the major axis, so the
    // fastest rate the body reaches is 2 (|L| / i_min = 5 would take steps 2.5 x smaller).
    write(
        &dir,
        "scene.toml",
        &scene(
            BODY,
            "[initial]\nrotor = [1, 0, 0, 0]\nomega = [0, 0, 2]\n",
            RUN,
        ),
    );
    let out = run(
        &dir,
        &[
            "simulate",
            "scene.toml",
            "--method",
            "rk4",
            "--out",
            "out.csv",
        ],
    );
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(out.stderr.is_empty());
    let record = sidecar(&dir);
    let dt: f64 = value(&record, "dt").parse().unwrap();
    let expected = 2.0 * std::f64::consts::PI / 2.0 / 200.0;
    assert!((dt - expected).abs() < 1e-15, "{dt} vs {expected}");
    assert_eq!(value(&record, "method"), "\"rk4\"");
    assert_eq!(value(&record, "scene"), "\"scene.toml\"");
    assert_eq!(value(&record, "csv"), "\"out.csv\"");
    assert_eq!(value(&record, "tol"), "null");
    assert!(value(&record, "step_source").contains("period"));

    // On standard output the CSV stays alone; the choice is a note on standard error.
    let out = run(&dir, &["simulate", "scene.toml", "--method", "dopri"]);
    assert_eq!(out.status.code(), Some(0));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(stderr.starts_with("note: --tol 1e-9"), "{stderr}");
    assert!(String::from_utf8_lossy(&out.stdout).starts_with("t,r_s,"));
}

#[test]
fn given_step_and_method_are_recorded_beside_the_csv() {
    let dir = test_dir("sidecar_given");
    write(&dir, "scene.toml", &scene(BODY, INITIAL, RUN));
    let out = run(
        &dir,
        &[
            "simulate",
            "scene.toml",
            "--method",
            "splitting",
            "--dt",
            "0.01",
            "--out",
            "out.csv",
        ],
    );
    assert_eq!(out.status.code(), Some(0));
    let record = sidecar(&dir);
    assert_eq!(value(&record, "dt"), "0.01");
    assert_eq!(value(&record, "method"), "\"splitting\"");
    assert_eq!(value(&record, "step_source"), "\"given\"");
    assert_eq!(value(&record, "samples"), "11");
}

#[test]
fn report_out_that_is_a_file_is_rejected() {
    let dir = test_dir("report_out_file");
    write(&dir, "taken", "x");
    let out = run(&dir, &["report", "--quick", "--out", "taken"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(out.stdout.is_empty());
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(stderr.starts_with("--out: "), "{stderr}");
    assert_eq!(std::fs::read_to_string(dir.join("taken")).unwrap(), "x");
}

#[test]
fn report_scenes_without_toml_files_are_rejected() {
    let dir = test_dir("report_no_scenes");
    std::fs::create_dir(dir.join("empty")).unwrap();
    let out = run(
        &dir,
        &["report", "--quick", "--out", "r", "--scenes", "empty"],
    );
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(stderr.starts_with("--scenes: "), "{stderr}");
    assert!(!dir.join("r").join("results.csv").exists());
}

#[test]
fn report_scene_with_a_bad_field_is_named() {
    let dir = test_dir("report_bad_scene");
    std::fs::create_dir(dir.join("mine")).unwrap();
    write(
        &dir.join("mine"),
        "bad.toml",
        &scene("[body]\nmoments = [1.0, -2.0, 2.5]\n", INITIAL, RUN),
    );
    let out = run(
        &dir,
        &["report", "--quick", "--out", "r", "--scenes", "mine"],
    );
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(stderr.starts_with("--scenes: "), "{stderr}");
    assert!(
        stderr.contains("bad.toml") && stderr.contains("body.moments"),
        "{stderr}"
    );
}

#[test]
fn simulate_plot_writes_an_svg_of_omega_and_energy_drift() {
    let dir = test_dir("simulate_plot");
    write(&dir, "scene.toml", &scene(BODY, INITIAL, RUN));
    let out = run(
        &dir,
        &[
            "simulate",
            "scene.toml",
            "--method",
            "rk4",
            "--dt",
            "0.01",
            "--out",
            "out.csv",
            "--plot",
            "plot.svg",
        ],
    );
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let svg = std::fs::read_to_string(dir.join("plot.svg")).unwrap();
    assert!(svg.starts_with("<svg"), "{}", &svg[..svg.len().min(80)]);
    assert!(svg.contains("body angular velocity (rad/s)"));
    assert!(svg.contains("relative energy drift"));
    assert!(dir.join("out.csv").is_file());
}

#[test]
fn simulate_plot_into_a_missing_directory_is_rejected() {
    let dir = test_dir("simulate_plot_missing_dir");
    write(&dir, "scene.toml", &scene(BODY, INITIAL, RUN));
    let out = run(
        &dir,
        &[
            "simulate",
            "scene.toml",
            "--method",
            "rk4",
            "--dt",
            "0.01",
            "--out",
            "out.csv",
            "--plot",
            "nowhere/plot.svg",
        ],
    );
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(stderr.starts_with("--plot: "), "{stderr}");
    assert!(!dir.join("out.csv").exists());
}

#[test]
fn every_registry_name_is_a_method_on_the_command_line() {
    use ga_rigid::integrators::{Method, StepKind};
    let dir = test_dir("registry_names");
    // A symmetric body, so that the closed form applies too.
    write(
        &dir,
        "scene.toml",
        &scene("[body]\nmoments = [1.0, 1.0, 1.5]\n", INITIAL, RUN),
    );
    for method in Method::ALL {
        let mut args = vec!["simulate", "scene.toml", "--method", method.name()];
        match method.step_kind() {
            StepKind::Fixed => args.extend_from_slice(&["--dt", "0.01"]),
            StepKind::Adaptive => args.extend_from_slice(&["--tol", "1e-8"]),
            StepKind::AtSamples => {}
        }
        let out = run(&dir, &args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(0), "{}: {stderr}", method.name());
        assert_eq!(String::from_utf8_lossy(&out.stdout).lines().count(), 12);
    }
}

/// The README's symmetric top.
const README_TOP: &str = "[body]\nmoments = [2.0, 2.0, 1.0]\n[initial]\nrotor = [1, 0, 0, 0]\n\
                          omega = [0.3, 0.0, 5.0]\n";

/// `exact` and `closed-form` take no steps, so no step limit stopped them; at t_end = 1e16
/// their attitudes were random (2.9 rad apart) and printed with 17 digits, exit 0. Rounding
/// alone costs about |w|max t_end eps rad, so such runs are refused, naming t_end and the
/// bound, and the bound can be raised.
#[test]
fn runs_whose_phase_rounding_exceeds_the_bound_are_refused() {
    let far = format!("{README_TOP}[run]\nt_end = 1e16\nsamples = 3\n");
    for method in ["exact", "closed-form", "lie-dop853"] {
        expect_short_rejection(
            &format!("phase_{method}"),
            &far,
            &["--method", method],
            "run.t_end: ",
            "above the bound 0.001",
        );
    }
    let dir = test_dir("phase_raised");
    write(
        &dir,
        "scene.toml",
        &format!("{README_TOP}[run]\nt_end = 1e12\nsamples = 3\n"),
    );
    // 5 rad/s for 1e12 s: about 1.1e-3 rad of rounding.
    let refused = run(&dir, &["simulate", "scene.toml", "--method", "exact"]);
    assert_eq!(refused.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&refused.stderr);
    assert!(
        stderr.contains("t_end = 1.00e12") && stderr.contains("--max-phase-error"),
        "{stderr}"
    );
    let allowed = run(
        &dir,
        &[
            "simulate",
            "scene.toml",
            "--method",
            "exact",
            "--max-phase-error",
            "0.01",
        ],
    );
    assert_eq!(
        allowed.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&allowed.stderr)
    );
    let bad = run(
        &dir,
        &[
            "simulate",
            "scene.toml",
            "--method",
            "exact",
            "--max-phase-error",
            "-1",
        ],
    );
    assert_eq!(bad.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&bad.stderr).starts_with("--max-phase-error: "));
}

/// `rk4 --dt 1e308` ran to energy 9.6e12 and exited 0; a step past a method's measured
/// stability limit (the registry's `h |w|max`) is refused naming the limit, unless
/// `--allow-unstable` is given.
#[test]
fn steps_past_the_stability_limit_are_refused() {
    let top = format!("{README_TOP}[run]\nt_end = 10\nsamples = 3\n");
    expect_short_rejection(
        "unstable_rk4",
        &top,
        &["--method", "rk4", "--dt", "1e308"],
        "--dt: ",
        "beyond rk4's stability limit 2",
    );
    expect_short_rejection(
        "unstable_splitting",
        &top,
        &["--method", "splitting", "--dt", "1e308"],
        "--dt: ",
        "beyond splitting's stability limit 3",
    );
    // |w|max = 5 for this top (|w| is constant): h = 0.45 is h |w| = 2.25 > 2.
    expect_short_rejection(
        "unstable_lie_rk4",
        &top,
        &["--method", "lie-rk4", "--dt", "0.45"],
        "--dt: ",
        "take dt <= 0.399 or pass --allow-unstable",
    );
    let dir = test_dir("allow_unstable");
    write(&dir, "scene.toml", &top);
    let allowed = run(
        &dir,
        &[
            "simulate",
            "scene.toml",
            "--method",
            "lie-rk4",
            "--dt",
            "0.45",
            "--allow-unstable",
        ],
    );
    assert_eq!(
        allowed.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&allowed.stderr)
    );
    // At the limit itself the step is taken.
    let at_limit = run(
        &dir,
        &["simulate", "scene.toml", "--method", "rk4", "--dt", "0.39"],
    );
    assert_eq!(at_limit.status.code(), Some(0));
}

/// A needle (moments 1, 1, 1e-6) turning slowly: its rates stay near 5 rad/s, but
/// `|L| / i_min` put |w|max at 5e6 and the default step at 1.3e-9, and a 1 s run was
/// refused as 1.6e8 steps. The default step now follows the rates the body reaches.
#[test]
fn a_slow_needle_gets_a_step_from_the_rates_it_reaches() {
    let dir = test_dir("slow_needle");
    write(
        &dir,
        "scene.toml",
        "[body]\nmoments = [1.0, 1.0, 1e-6]\n[initial]\nrotor = [1, 0, 0, 0]\n\
         omega = [3.0, 4.0, 0.0]\n[run]\nt_end = 1.0\nsamples = 3\n",
    );
    let out = run(
        &dir,
        &[
            "simulate",
            "scene.toml",
            "--method",
            "rk4",
            "--out",
            "out.csv",
        ],
    );
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let dt: f64 = value(&sidecar(&dir), "dt").parse().unwrap();
    // |w| = 5 stays 5 (w3 = 0 and i1 = i2: the needle turns end over end).
    let expected = 2.0 * std::f64::consts::PI / 5.0 / 200.0;
    assert!(
        (dt - expected).abs() < 1e-12 * expected,
        "{dt} vs {expected}"
    );
}
