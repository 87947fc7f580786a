//! `simulate` and `inertia` on 2D and 4D scenes, through the binary: the 4D test body of
//! docs/references.md (scipy DOP853 at rtol 1e-13) reached by `lie-dop853 --tol 1e-12`,
//! the CSV headers, the 2D closed form against `R(t) = exp(-w t e12 / 2)`, and the
//! failure contract on bad input (status 2, one line naming the field, no output file).

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

const BIN: &str = env!("CARGO_BIN_EXE_ga-rigid");

/// The 4D test body of docs/references.md: second moments (0.5, 0.9, 1.4, 2.0), R(0) = 1.
const FOUR: &str = "[body]\ndimension = 4\nsecond_moments = [0.5, 0.9, 1.4, 2.0]\n\n\
    [initial]\nrotor = [1, 0, 0, 0, 0, 0, 0, 0]\nomega = [1.0, 0, 0.4, -0.6, 0.2, 0.8]\n\n\
    [run]\nt_end = 10\nsamples = 11\n";

/// R(10) in the order s, e12, e13, e14, e23, e24, e34, e1234, and Omega_B(10)
/// (docs/references.md).
const R10: [f64; 8] = [
    -0.845752127571,
    -0.001654495749,
    0.054382309786,
    -0.187793734963,
    0.290305428646,
    -0.103803029126,
    -0.384930676753,
    0.057032816706,
];
const OMEGA10: [f64; 6] = [
    0.920363924980,
    -0.406450762844,
    0.521437788334,
    -0.488898046121,
    0.219223377642,
    0.776749436333,
];

const HEADER_4D: &str = "t,r_s,r_e12,r_e13,r_e14,r_e23,r_e24,r_e34,r_e1234,w_e12,w_e13,w_e14,\
    w_e23,w_e24,w_e34,energy,l_e12,l_e13,l_e14,l_e23,l_e24,l_e34";
const HEADER_2D: &str = "t,r_s,r_e12,w_e12,energy,l_e12";

/// A fresh directory for one test, under cargo's per-target temporary directory.
fn test_dir(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("ga-rigid-cli-nd")
        .join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Run the binary in a fresh directory holding `scene.toml`.
fn run(name: &str, scene: &str, args: &[&str]) -> (PathBuf, Output) {
    let dir = test_dir(name);
    std::fs::write(dir.join("scene.toml"), scene).unwrap();
    let out = Command::new(BIN)
        .args(args)
        .current_dir(&dir)
        .output()
        .unwrap();
    (dir, out)
}

fn stdout(out: &Output) -> String {
    assert_eq!(
        out.status.code(),
        Some(0),
        "stderr: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout.clone()).unwrap()
}

fn last_row(csv: &str) -> Vec<f64> {
    csv.lines()
        .last()
        .unwrap()
        .split(',')
        .map(|x| x.parse().unwrap())
        .collect()
}

fn max_difference(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

/// Status 2, nothing on stdout, one stderr line starting with `start`, no `out.csv`.
fn expect_rejected(name: &str, scene: &str, args: &[&str], start: &str) {
    let mut all = vec!["simulate", "scene.toml"];
    all.extend_from_slice(args);
    all.extend_from_slice(&["--out", "out.csv"]);
    let (dir, out) = run(name, scene, &all);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{name}: {stderr}");
    assert!(out.stdout.is_empty(), "{name}: stdout not empty");
    assert_eq!(stderr.lines().count(), 1, "{name}: not one line: {stderr}");
    assert!(stderr.starts_with(start), "{name}: {stderr}");
    assert!(!dir.join("out.csv").exists(), "{name}: out.csv written");
}

#[test]
fn lie_dop853_reaches_the_4d_reference_state_at_t_10() {
    let (_, out) = run(
        "reference",
        FOUR,
        &[
            "simulate",
            "scene.toml",
            "--method",
            "lie-dop853",
            "--tol",
            "1e-12",
        ],
    );
    let csv = stdout(&out);
    assert_eq!(csv.lines().next(), Some(HEADER_4D));
    assert_eq!(csv.lines().count(), 1 + 11);
    let row = last_row(&csv);
    assert_eq!(row.len(), HEADER_4D.split(',').count());
    assert_eq!(row[0], 10.0);
    let (dr, dw) = (
        max_difference(&row[1..9], &R10),
        max_difference(&row[9..15], &OMEGA10),
    );
    assert!(dr < 1e-10 && dw < 1e-10, "{dr:e} {dw:e}");
    // The energy and the space momentum L = M(0) (R(0) = 1) of the reference body.
    assert!((row[15] - 2.46).abs() < 1e-10, "{}", row[15]);
    let m0 = [1.4, 0.0, 1.0, -1.38, 0.58, 2.72];
    assert!(max_difference(&row[16..22], &m0) < 1e-10);
}

#[test]
fn every_4d_method_runs_and_writes_the_header_and_sidecar() {
    for method in ["rk4", "lie-rk4", "midpoint", "splitting", "lie-dop853"] {
        let (dir, out) = run(
            &format!("methods-{method}"),
            FOUR,
            &[
                "simulate",
                "scene.toml",
                "--method",
                method,
                "--out",
                "out.csv",
            ],
        );
        assert!(stdout(&out).is_empty());
        let csv = std::fs::read_to_string(dir.join("out.csv")).unwrap();
        assert_eq!(csv.lines().next(), Some(HEADER_4D), "{method}");
        let row = last_row(&csv);
        // The default step is 1/200 of the fastest period: enough for 1e-3 everywhere.
        assert!(
            max_difference(&row[9..15], &OMEGA10) < 1e-3,
            "{method}: {row:?}"
        );
        let json = std::fs::read_to_string(dir.join("out.csv.json")).unwrap();
        assert!(
            json.contains(&format!("\"method\": \"{method}\"")),
            "{json}"
        );
    }
}

#[test]
fn a_3d_only_method_is_refused_in_4d_and_2d_with_one_line() {
    expect_rejected(
        "3d-only",
        FOUR,
        &["--method", "euler-gyro-explicit"],
        "--method: euler-gyro-explicit is 3D-only; dimension 4 takes closed-form, rk4, lie-rk4, \
         midpoint, splitting, lie-dop853",
    );
    let two = FOUR
        .replace("dimension = 4", "dimension = 2")
        .replace("[0.5, 0.9, 1.4, 2.0]", "[0.5, 0.9]")
        .replace("[1, 0, 0, 0, 0, 0, 0, 0]", "[1, 0]")
        .replace("[1.0, 0, 0.4, -0.6, 0.2, 0.8]", "[1.0]");
    expect_rejected(
        "3d-only-2d",
        &two,
        &["--method", "exact"],
        "--method: exact is 3D-only; dimension 2",
    );
}

/// The method rules of a 4D run, in the command's words (the scene rules are library
/// tests: ga-rigid/tests/scene_rules.rs).
#[test]
fn bad_4d_method_settings_name_their_field() {
    // The 3D closed form's body is not the 4D one's: (a, a, b, b) is required.
    expect_rejected(
        "closed-form-asymmetric",
        FOUR,
        &["--method", "closed-form"],
        "body.second_moments: the closed form needs second moments (a, a, b, b)",
    );
    // And a step control the method does not take, in the command's words.
    expect_rejected(
        "tol-for-rk4",
        FOUR,
        &["--method", "rk4", "--tol", "1e-9"],
        "--tol: method rk4 takes a fixed step",
    );
}

#[test]
fn the_4d_closed_form_matches_lie_dop853_on_a_symmetric_body() {
    let scene = FOUR.replace("[0.5, 0.9, 1.4, 2.0]", "[0.6, 0.6, 1.7, 1.7]");
    let (_, closed) = run(
        "symmetric-closed",
        &scene,
        &["simulate", "scene.toml", "--method", "closed-form"],
    );
    let (_, adaptive) = run(
        "symmetric-dop853",
        &scene,
        &[
            "simulate",
            "scene.toml",
            "--method",
            "lie-dop853",
            "--tol",
            "1e-12",
        ],
    );
    let (a, b) = (last_row(&stdout(&closed)), last_row(&stdout(&adaptive)));
    assert!(max_difference(&a, &b) < 1e-9, "{a:?} {b:?}");
}

#[test]
fn the_2d_closed_form_turns_at_the_constant_rate() {
    let scene =
        "[body]\ndimension = 2\nshape = { kind = \"box\", mass = 3.0, size = [1.0, 2.0] }\n\
        [initial]\nrotor = [1, 0]\nomega = [0.7]\n[run]\nt_end = 4\nsamples = 5\n";
    let (_, out) = run(
        "planar",
        scene,
        &["simulate", "scene.toml", "--method", "closed-form"],
    );
    let csv = stdout(&out);
    assert_eq!(csv.lines().next(), Some(HEADER_2D));
    let row = last_row(&csv);
    // R = exp(-w t e12 / 2) = cos(w t / 2) - sin(w t / 2) e12; plane moment m (1 + 4) / 12.
    let half: f64 = 0.5 * 0.7 * 4.0;
    let moment = 3.0 * 5.0 / 12.0;
    let expected = [
        4.0,
        half.cos(),
        -half.sin(),
        0.7,
        0.5 * moment * 0.49,
        moment * 0.7,
    ];
    assert!(max_difference(&row, &expected) < 1e-14, "{row:?}");
}

#[test]
fn inertia_of_a_4d_body_of_points_gives_moments_and_the_principal_rotor() {
    let scene = "[body]\ndimension = 4\n\
        points = [[1, 1, 0, 0, 0], [1, -1, 0, 0, 0], [2, 0, 0.5, 0, 0], [2, 0, -0.5, 0, 0], \
        [1, 0, 0, 0.5, 0], [1, 0, 0, -0.5, 0]]\n\
        [initial]\nrotor = [1, 0, 0, 0, 0, 0, 0, 0]\nomega = [0, 0, 0, 0, 0, 1]\n\
        [run]\nt_end = 1\nsamples = 2\n";
    let (_, out) = run("inertia", scene, &["inertia", "scene.toml"]);
    let text = stdout(&out);
    assert!(text.contains("dimension: 4\nmass: 8\n"), "{text}");
    assert!(text.contains("centre_of_mass: [0, 0, 0, 0]"), "{text}");
    // Second moments 0 (along e4), 0.5 (e3), 1 (e2), 2 (e1), ascending.
    assert!(text.contains("second_moments: [0, 0.5, 1, 2]"), "{text}");
    assert!(
        text.contains("plane_moments: [0.5, 1, 2, 1.5, 2.5, 3]"),
        "{text}"
    );
    assert!(text.lines().any(|l| l.starts_with("rotor: [")), "{text}");
}
