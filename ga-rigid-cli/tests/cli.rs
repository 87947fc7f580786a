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

fn scene(body: &str, initial: &str, run: &str) -> String {
    format!("{body}{initial}{run}")
}

const CUBE_OBJ: &str = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n\
f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 4 8 7 3\nf 4 1 5 8\n";

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
    assert!(
        stderr.starts_with("scene.toml: body.moments: moments must be positive, got 0"),
        "{stderr}"
    );
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
            "scene.toml: initial.omega: ",
            "overflow",
        );
    }
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
    expect_read_refused(
        &dir,
        "mesh.toml",
        "mesh.toml: body.mesh: ",
        "not a regular file",
    );
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
    expect_read_refused(
        &dir,
        "mesh.toml",
        "mesh.toml: body.mesh: ",
        "more than the limit",
    );
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
        "scene.toml: body.shape.kind: ",
        "(100000 characters)",
    );
    let s = scene(&format!("[body]\nmoments = \"{long}\"\n"), INITIAL, RUN);
    expect_short_rejection(
        "long_string",
        &s,
        &["--method", "exact"],
        "scene.toml: body.moments: ",
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
        "scene.toml: body.aaaa",
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
        "scene.toml: body.mesh: ",
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
    // The scene's path as the command found it, then the field and the rule.
    assert!(
        stderr.starts_with("--scenes: mine/bad.toml: body.moments: moments must be positive"),
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
    assert!(svg.contains("body angular velocity (rad/s)"));
    assert!(svg.contains("relative energy drift"));
    // The curves are the CSV's values: w1, w2 and w3 (one colour each, on one axis) hold
    // one point per sample, at the same abscissae, and every point's height is one
    // decreasing affine function of its w (the SVG's y grows downwards), to within the
    // pixel the plot rounds to.
    let csv = std::fs::read_to_string(dir.join("out.csv")).unwrap();
    let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
    let rows: Vec<Vec<f64>> = csv
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|c| c.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 11);
    let mut pairs = Vec::new();
    let mut abscissae = None;
    for (k, colour) in ["#D62728", "#2CA02C", "#1F77B4"].into_iter().enumerate() {
        let points = polyline(&svg, colour);
        assert_eq!(points.len(), rows.len(), "w{}: {points:?}", k + 1);
        let xs: Vec<f64> = points.iter().map(|p| p.0).collect();
        assert!(xs.windows(2).all(|w| w[1] > w[0]), "{xs:?}");
        assert_eq!(*abscissae.get_or_insert(xs.clone()), xs);
        let column = header
            .iter()
            .position(|c| *c == format!("w{}", k + 1))
            .unwrap();
        pairs.extend(rows.iter().zip(&points).map(|(row, p)| (row[column], p.1)));
    }
    let (low, high) = pairs.iter().fold((pairs[0], pairs[0]), |(lo, hi), &p| {
        (
            if p.0 < lo.0 { p } else { lo },
            if p.0 > hi.0 { p } else { hi },
        )
    });
    let slope = (high.1 - low.1) / (high.0 - low.0);
    assert!(slope < 0.0, "{low:?} {high:?}");
    for (w, y) in &pairs {
        let expected = low.1 + slope * (w - low.0);
        assert!(
            (y - expected).abs() <= 1.5,
            "w {w}: y {y}, expected {expected}"
        );
    }
}

/// The points of the SVG's one polyline drawn in `colour` at width 2 (a data series).
fn polyline(svg: &str, colour: &str) -> Vec<(f64, f64)> {
    let marker = format!("stroke=\"{colour}\" stroke-width=\"2\" points=\"");
    assert_eq!(svg.matches(&marker).count(), 1, "{colour}");
    let start = svg.find(&marker).unwrap() + marker.len();
    let end = start + svg[start..].find('"').unwrap();
    svg[start..end]
        .split_whitespace()
        .map(|p| {
            let (x, y) = p.split_once(',').unwrap();
            (x.parse().unwrap(), y.parse().unwrap())
        })
        .collect()
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
    use ga_rigid::registry::{Method, StepKind};
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

// ---- Issue 22: outputs a failed run must not touch, bounded meshes and work, messages ----

/// A scene whose body is the mesh `obj` (a file beside it), at unit density.
fn mesh_scene(obj: &str) -> String {
    scene(
        &format!("[body]\nmesh = \"{obj}\"\ndensity = 1.0\n"),
        INITIAL,
        RUN,
    )
}

/// An axis-aligned cube from `low` with edge `size`, as OBJ lines whose vertex numbers start
/// after `base`, faces wound counter-clockwise seen from outside.
fn cube_obj(low: [f64; 3], size: f64, base: usize) -> String {
    let mut text = String::new();
    for x in [0.0, size] {
        for y in [0.0, size] {
            for z in [0.0, size] {
                text.push_str(&format!("v {} {} {}\n", low[0] + x, low[1] + y, low[2] + z));
            }
        }
    }
    // Vertex k + 1 sits at the corner with bits (x, y, z) = k.
    for face in [
        [1, 2, 4, 3],
        [5, 7, 8, 6],
        [1, 5, 6, 2],
        [3, 4, 8, 7],
        [1, 3, 7, 5],
        [2, 6, 8, 4],
    ] {
        let ids: Vec<String> = face.iter().map(|i| (i + base).to_string()).collect();
        text.push_str(&format!("f {}\n", ids.join(" ")));
    }
    text
}

/// The names in `dir` that look like our temporary files.
fn temporaries(dir: &Path) -> Vec<String> {
    std::fs::read_dir(dir)
        .unwrap()
        .filter_map(|e| e.ok())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| n.contains(".tmp-"))
        .collect()
}

/// Check the refusal contract of any command: status 2, nothing on stdout, one line on
/// stderr of at most 200 characters starting with `field` and containing `rule`.
fn expect_refusal(out: &Output, field: &str, rule: &str) -> String {
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(out.stdout.is_empty(), "stdout: {:?}", out.stdout);
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    let chars = stderr.trim_end().chars().count();
    assert!(chars <= 200, "a {chars}-character message: {stderr}");
    assert!(
        stderr.starts_with(field),
        "expected {field:?} first: {stderr}"
    );
    assert!(stderr.contains(rule), "expected {rule:?} in {stderr}");
    stderr
}

#[cfg(unix)]
#[test]
fn a_failed_write_replaces_and_deletes_nothing() {
    // Issue 22, finding 2: a CSV write that failed (a file size limit) deleted the old
    // sidecar and left the new plot in place of the old one.
    let dir = test_dir("failed_write_touches_nothing");
    write(&dir, "scene.toml", &scene(BODY, INITIAL, RUN));
    write(&dir, "o.csv", "old csv\n");
    write(&dir, "o.csv.json", "old record\n");
    write(&dir, "p.svg", "old plot\n");
    // `trap '' XFSZ` makes the write fail with EFBIG instead of killing the process, as
    // under a harness that ignores the signal; the 1-block limit is below the CSV's size.
    let script = format!(
        "trap '' XFSZ; ulimit -f 1; exec '{BIN}' simulate scene.toml --method rk4 --dt 1e-3 \
         --out o.csv --plot p.svg"
    );
    let out = Command::new("sh")
        .arg("-c")
        .arg(&script)
        .current_dir(&dir)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(stderr.starts_with("--out: cannot write"), "{stderr}");
    assert_eq!(
        std::fs::read_to_string(dir.join("o.csv")).unwrap(),
        "old csv\n"
    );
    assert_eq!(
        std::fs::read_to_string(dir.join("o.csv.json")).unwrap(),
        "old record\n"
    );
    assert_eq!(
        std::fs::read_to_string(dir.join("p.svg")).unwrap(),
        "old plot\n"
    );
    assert!(temporaries(&dir).is_empty(), "{:?}", temporaries(&dir));
}

#[test]
fn outputs_may_name_neither_the_scene_nor_each_other() {
    // Issue 22, finding 8: each of these exited 0, overwriting the scene or one output
    // with another.
    let dir = test_dir("outputs_distinct");
    let text = scene(BODY, INITIAL, RUN);
    write(&dir, "scene.toml", &text);
    let base = ["simulate", "scene.toml", "--method", "exact"];
    let cases: [(&[&str], &str, &str); 5] = [
        (&["--out", "scene.toml"], "--out: ", "is the scene file"),
        (&["--out", "./scene.toml"], "--out: ", "is the scene file"),
        (&["--plot", "scene.toml"], "--plot: ", "is the scene file"),
        (
            &["--out", "o.csv", "--plot", "o.csv"],
            "--plot: ",
            "is also where --out writes",
        ),
        (
            &["--out", "o.csv", "--plot", "o.csv.json"],
            "--plot: ",
            "is also where --out writes",
        ),
    ];
    for (extra, field, rule) in cases {
        let mut args = base.to_vec();
        args.extend_from_slice(extra);
        expect_refusal(&run(&dir, &args), field, rule);
        assert_eq!(
            std::fs::read_to_string(dir.join("scene.toml")).unwrap(),
            text
        );
        assert!(!dir.join("o.csv").exists(), "{extra:?}");
        assert!(!dir.join("o.csv.json").exists(), "{extra:?}");
    }
    // The mesh a scene reads is an input too.
    write(&dir, "cube.obj", &cube_obj([0.0; 3], 1.0, 0));
    write(&dir, "mesh.toml", &mesh_scene("cube.obj"));
    let out = run(
        &dir,
        &[
            "simulate",
            "mesh.toml",
            "--method",
            "exact",
            "--plot",
            "cube.obj",
        ],
    );
    expect_refusal(&out, "--plot: ", "is the scene's mesh (body.mesh)");
    assert!(std::fs::read_to_string(dir.join("cube.obj"))
        .unwrap()
        .starts_with("v 0 0 0\n"));
}

#[cfg(unix)]
#[test]
fn plot_onto_a_fifo_is_refused_without_pointing_at_standard_output() {
    // Issue 22, finding 11: `--plot` was told to use standard output, which it cannot.
    let dir = test_dir("plot_fifo");
    write(&dir, "scene.toml", &scene(BODY, INITIAL, RUN));
    make_fifo(&dir.join("p.svg"));
    let out = run_with_deadline(
        &dir,
        &[
            "simulate",
            "scene.toml",
            "--method",
            "exact",
            "--plot",
            "p.svg",
        ],
    );
    let stderr = expect_refusal(&out, "--plot: ", "p.svg is a FIFO, not a regular file");
    assert!(!stderr.contains("standard output"), "{stderr}");
}

#[cfg(unix)]
#[test]
fn report_finds_obstacles_in_its_directory_before_the_suite() {
    // Issue 22, findings 3 and 7: a FIFO or link in --out was replaced by a regular file,
    // and a directory where long_runs.csv goes was found after the suite had written the
    // SVGs and results.csv.
    use std::os::unix::fs::FileTypeExt as _;
    let dir = test_dir("report_obstacles");
    let r = dir.join("r");
    std::fs::create_dir(&r).unwrap();
    make_fifo(&r.join("results.csv"));
    let out = run_with_deadline(&dir, &["report", "--quick", "--out", "r"]);
    expect_refusal(&out, "--out: ", "results.csv is a FIFO, not a regular file");
    assert!(std::fs::symlink_metadata(r.join("results.csv"))
        .unwrap()
        .file_type()
        .is_fifo());
    std::fs::remove_file(r.join("results.csv")).unwrap();

    std::os::unix::fs::symlink("nowhere.html", r.join("index.html")).unwrap();
    let out = run_with_deadline(&dir, &["report", "--quick", "--out", "r"]);
    expect_refusal(&out, "--out: ", "symbolic link to a missing file");
    std::fs::remove_file(r.join("index.html")).unwrap();

    std::fs::create_dir(r.join("long_runs.csv")).unwrap();
    let out = run_with_deadline(&dir, &["report", "--quick", "--out", "r"]);
    expect_refusal(&out, "--out: ", "long_runs.csv is a directory");
    let names: Vec<_> = std::fs::read_dir(&r)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert_eq!(names, ["long_runs.csv"], "files written before the refusal");
}

#[test]
fn report_out_with_missing_parents_is_status_2_and_creates_nothing() {
    // Issue 22, finding 7: status 1 here, where simulate gives 2.
    let dir = test_dir("report_missing_parents");
    let out = run_with_deadline(&dir, &["report", "--quick", "--out", "a/b/c"]);
    expect_refusal(&out, "--out: ", "the directory a/b does not exist");
    assert!(!dir.join("a").exists());
}

/// A `--scenes` directory `mine` in `dir` holding one cheap scene.
fn scenes_dir(dir: &Path) -> PathBuf {
    let mine = dir.join("mine");
    std::fs::create_dir(&mine).unwrap();
    write(&mine, "cheap.toml", &scene(BODY, INITIAL, RUN));
    mine
}

#[test]
fn report_scenes_are_estimated_and_refused_above_max_seconds() {
    // Issue 22, finding 5: one scene with w = 1e6 ran past 15 minutes.
    let dir = test_dir("report_scenes_estimate");
    let mine = scenes_dir(&dir);
    write(
        &mine,
        "spin.toml",
        &scene(
            BODY,
            "[initial]\nrotor = [1, 0, 0, 0]\nomega = [0.1, 1e6, 0.2]\n",
            RUN,
        ),
    );
    let out = run_with_deadline(
        &dir,
        &["report", "--quick", "--out", "r", "--scenes", "mine"],
    );
    let stderr = expect_refusal(&out, "--scenes: ", "raise it with --max-seconds");
    assert!(stderr.contains("spin.toml alone"), "{stderr}");
    assert!(
        !dir.join("r").exists(),
        "a refused run left its --out behind"
    );
    // The bound is the user's: at 0 s even the cheap scene is refused.
    std::fs::remove_file(mine.join("spin.toml")).unwrap();
    let out = run_with_deadline(
        &dir,
        &[
            "report",
            "--quick",
            "--out",
            "r",
            "--scenes",
            "mine",
            "--max-seconds",
            "0",
        ],
    );
    expect_refusal(&out, "--scenes: ", "above the limit of 0 s");
    assert!(!dir.join("r").exists());
}

#[cfg(unix)]
#[test]
fn report_scenes_refuse_unreadable_entries_by_name() {
    // Issue 22, finding 5: these were skipped in silence.
    let dir = test_dir("report_scenes_unreadable");
    let mine = scenes_dir(&dir);
    let loop_link = |p: &Path| std::os::unix::fs::symlink("loop.toml", p).unwrap();
    let folder = |p: &Path| std::fs::create_dir(p).unwrap();
    type Make<'a> = &'a dyn Fn(&Path);
    let setups: [(&str, Make); 3] = [
        ("loop.toml", &loop_link),
        ("pipe.toml", &make_fifo),
        ("folder.toml", &folder),
    ];
    for (name, make) in setups {
        let path = mine.join(name);
        make(&path);
        let out = run_with_deadline(
            &dir,
            &["report", "--quick", "--out", "r", "--scenes", "mine"],
        );
        expect_refusal(&out, "--scenes: ", name);
        assert!(!dir.join("r").exists());
        if path.is_dir() {
            std::fs::remove_dir(&path).unwrap();
        } else {
            std::fs::remove_file(&path).unwrap();
        }
    }
}

#[test]
fn a_run_estimated_past_max_seconds_is_refused_naming_the_estimate() {
    // Issue 22, finding 6: just under 10^8 steps of splitting-8 on a heavy top passed the
    // step limit and ran about 9 minutes.
    let dir = test_dir("max_seconds");
    let heavy = scene(
        "[body]\nmoments = [1.0, 1.0, 0.5]\n",
        "[initial]\nrotor = [1, 0, 0, 0]\nomega = [0.3, 0.0, 5.0]\n",
        "[run]\nt_end = 10.0\nsamples = 3\n[torque]\ng = [0.0, 0.0, -9.81]\n\
         com_offset = [0.0, 0.0, 0.1]\n",
    );
    write(&dir, "heavy.toml", &heavy);
    let args = [
        "simulate",
        "heavy.toml",
        "--method",
        "splitting-8",
        "--dt",
        "1.0000001e-7",
    ];
    let stderr = expect_refusal(
        &run_with_deadline(&dir, &args),
        "--dt: ",
        "raise it with --max-seconds",
    );
    assert!(
        stderr.contains("1.0e8 steps of splitting-8") && stderr.contains(" s at "),
        "{stderr}"
    );
    // A larger limit moves the refusal to the step limit, which still holds here.
    let mut raised = args.to_vec();
    raised.extend_from_slice(&["--max-seconds", "1000000", "--max-steps", "1000"]);
    expect_refusal(
        &run_with_deadline(&dir, &raised),
        "--dt: ",
        "raise it with --max-steps",
    );
}

#[test]
fn nested_and_overlapping_shells_are_refused() {
    // Issue 22, finding 9: a cube in a cube weighed 9 (the solid is 8), two overlapping
    // unit cubes 2 (the union is 1.58).
    let dir = test_dir("mesh_shells");
    let nested = cube_obj([0.0; 3], 2.0, 0) + &cube_obj([0.5; 3], 1.0, 8);
    let overlapping = cube_obj([0.0; 3], 1.0, 0) + &cube_obj([0.5; 3], 1.0, 8);
    for (name, text) in [("nested.obj", nested), ("overlapping.obj", overlapping)] {
        write(&dir, name, &text);
        write(&dir, "scene.toml", &mesh_scene(name));
        let out = run(&dir, &["inertia", "scene.toml"]);
        expect_refusal(
            &out,
            "scene.toml: body.mesh: ",
            "the shells of triangles 1 and 13 overlap (nested or intersecting)",
        );
    }
    // Two cubes side by side (touching along a face) are two shells that do not overlap.
    write(
        &dir,
        "apart.obj",
        &(cube_obj([0.0; 3], 1.0, 0) + &cube_obj([1.0, 0.0, 0.0], 1.0, 8)),
    );
    write(&dir, "scene.toml", &mesh_scene("apart.obj"));
    let out = run(&dir, &["inertia", "scene.toml"]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(stdout.starts_with("mass: 2\n"), "{stdout}");
}

#[test]
fn a_long_polygon_that_repeats_vertices_is_refused_at_its_line() {
    // Issue 22, finding 4: `f 1 2 3 1 2 3 ...` was fan-triangulated whole (130 M
    // triangles for 250 MiB) before the repeat was found. Now it is refused at the fourth
    // vertex of the face, by line.
    let dir = test_dir("mesh_long_polygon");
    let mut text = String::from("v 0 0 0\nv 1 0 0\nv 0 1 0\n# a comment\nf");
    for _ in 0..300_000 {
        text.push_str(" 1 2 3");
    }
    text.push('\n');
    write(&dir, "long.obj", &text);
    write(&dir, "scene.toml", &mesh_scene("long.obj"));
    let out = run_with_deadline(&dir, &["inertia", "scene.toml"]);
    expect_refusal(
        &out,
        "scene.toml: body.mesh: long.obj:5: ",
        "the face repeats vertex 1 (vertex 4 of the face)",
    );
}

#[test]
fn messages_name_what_was_written_and_stay_short() {
    // Issue 22, finding 11.
    let dir = test_dir("messages_22");
    // `[[run]]` gave "expected f64".
    write(
        &dir,
        "array.toml",
        &format!("{BODY}{INITIAL}[[run]]\nt_end = 1\nsamples = 3\n"),
    );
    expect_refusal(
        &run(&dir, &["inertia", "array.toml"]),
        "array.toml: run: ",
        "a section must be one table [run], got an array of tables [[run]]",
    );
    // A point at 1e308 gave "entries must be finite, got NaN".
    write(
        &dir,
        "far.toml",
        &scene(
            "[body]\npoints = [[1, 1e308, 0, 0], [1, -1e308, 0, 0], [1, 0, 1, 0], [1, 0, 0, 1]]\n",
            INITIAL,
            RUN,
        ),
    );
    let stderr = expect_refusal(
        &run(&dir, &["inertia", "far.toml"]),
        "far.toml: body.points",
        "overflow",
    );
    assert!(!stderr.contains("NaN"), "{stderr}");
    // A needle-thin mesh printed its moments in full decimal.
    write(
        &dir,
        "needle.obj",
        "v 0 0 0\nv 1 0 0\nv 0 1e-9 0\nv 0 0 1e-9\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n",
    );
    write(&dir, "needle.toml", &mesh_scene("needle.obj"));
    expect_refusal(
        &run(&dir, &["inertia", "needle.toml"]),
        "needle.toml: body.mesh: ",
        "moments",
    );
    // A long --out directory (237 characters) and a long --scenes path (311).
    let long = "d".repeat(240);
    let out = run(
        &dir,
        &["report", "--quick", "--out", &format!("{long}/{long}/r")],
    );
    expect_refusal(&out, "--out: ", "does not exist");
    let deep = dir.join("x".repeat(150)).join("y".repeat(150));
    std::fs::create_dir_all(&deep).unwrap();
    write(
        &deep,
        "bad.toml",
        &scene("[body]\nmoments = [1.0, -2.0, 2.5]\n", INITIAL, RUN),
    );
    let out = run(
        &dir,
        &[
            "report",
            "--quick",
            "--out",
            "r",
            "--scenes",
            deep.to_str().unwrap(),
        ],
    );
    // The path cut to its end, which names the file, then the field.
    let stderr = expect_refusal(&out, "--scenes: ...", "/bad.toml (");
    assert!(stderr.contains(" characters): body.moments: "), "{stderr}");
}

#[test]
fn t_end_at_the_largest_double_is_not_blamed_on_dt() {
    // Issue 22, finding 11: "dt: time step must be finite" for a t_end the user wrote
    // (the sample times overflowed). Either it runs, or a refusal names run.t_end.
    let dir = test_dir("t_end_max");
    write(
        &dir,
        "scene.toml",
        &scene(
            BODY,
            INITIAL,
            "[run]\nt_end = 1.7976931348623157e308\nsamples = 11\n",
        ),
    );
    let out = run(&dir, &["simulate", "scene.toml", "--method", "exact"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!stderr.contains("time step"), "{stderr}");
    match out.status.code() {
        Some(0) => {
            let stdout = String::from_utf8_lossy(&out.stdout);
            assert_eq!(stdout.lines().count(), 12);
            assert!(stdout
                .lines()
                .last()
                .unwrap()
                .starts_with("1.7976931348623157e308,"));
        }
        _ => {
            expect_refusal(&out, "", "t_end");
        }
    }
}

#[test]
fn adaptive_methods_take_a_first_step_for_huge_angular_velocity() {
    // Issue 22, finding 11: a valid scene with |w| = 1e80 was refused as "step size
    // underflow (0e0)": the squares in the first-step estimate overflowed.
    let dir = test_dir("adaptive_huge_w");
    write(
        &dir,
        "scene.toml",
        &scene(
            BODY,
            "[initial]\nrotor = [1, 0, 0, 0]\nomega = [1e80, 1e80, 0.2]\n",
            "[run]\nt_end = 1e-90\nsamples = 3\n",
        ),
    );
    for method in ["dopri", "lie-dop853"] {
        let out = run(
            &dir,
            &[
                "simulate",
                "scene.toml",
                "--method",
                method,
                "--tol",
                "1e-6",
            ],
        );
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(0), "{method}: {stderr}");
        let stdout = String::from_utf8_lossy(&out.stdout);
        let last: Vec<f64> = stdout
            .lines()
            .last()
            .unwrap()
            .split(',')
            .map(|v| v.parse().unwrap())
            .collect();
        assert!(last.iter().all(|x| x.is_finite()), "{method}: {stdout}");
        // Over 1e-90 the angular velocity barely moves.
        assert!((last[5] / 1e80 - 1.0).abs() < 1e-6, "{method}: {stdout}");
    }
}

#[cfg(unix)]
#[test]
fn report_files_may_not_lead_to_a_scene_it_reads() {
    // Issue 22, finding 8, for the report: a link in --out to a --scenes file would have
    // been followed and the scene replaced by results.csv.
    let dir = test_dir("report_link_to_scene");
    let mine = scenes_dir(&dir);
    let text = std::fs::read_to_string(mine.join("cheap.toml")).unwrap();
    std::fs::create_dir(dir.join("r")).unwrap();
    std::os::unix::fs::symlink("../mine/cheap.toml", dir.join("r/results.csv")).unwrap();
    let out = run_with_deadline(
        &dir,
        &["report", "--quick", "--out", "r", "--scenes", "mine"],
    );
    expect_refusal(&out, "--out: ", "r/results.csv is a --scenes file");
    assert_eq!(
        std::fs::read_to_string(mine.join("cheap.toml")).unwrap(),
        text
    );
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
    let with_bound = |bound: &str| {
        run(
            &dir,
            &[
                "simulate",
                "scene.toml",
                "--method",
                "exact",
                "--max-phase-error",
                bound,
            ],
        )
    };
    // A raised bound lets the run through, and infinity turns the check off (it was
    // refused as not finite, so the check could not be turned off at all).
    for bound in ["0.01", "inf"] {
        let allowed = with_bound(bound);
        assert_eq!(
            allowed.status.code(),
            Some(0),
            "{bound}: {}",
            String::from_utf8_lossy(&allowed.stderr)
        );
    }
    for bound in ["-1", "NaN"] {
        let bad = with_bound(bound);
        assert_eq!(bad.status.code(), Some(2), "{bound}");
        assert!(String::from_utf8_lossy(&bad.stderr).starts_with("--max-phase-error: "));
    }
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
        "take --dt <= 0.399 or pass --allow-unstable",
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

/// `try_run` (the library entry the Python package raises from) fails with the status and
/// the line the binary prints, for each kind of error: a usage error, a missing
/// subcommand, a bad scene, a refused `--out`; and succeeds where the binary does.
#[test]
fn try_run_returns_the_status_and_line_the_command_prints() {
    let dir = test_dir("try_run");
    let good = write(&dir, "good.toml", &scene(BODY, INITIAL, RUN));
    let bad = write(
        &dir,
        "bad.toml",
        &scene(BODY, INITIAL, "[run]\nt_end = 10.0\n"),
    );
    let file = write(&dir, "file", "x");
    let (good, bad, file) = (
        good.to_str().unwrap(),
        bad.to_str().unwrap(),
        file.to_str().unwrap(),
    );
    let out_file = format!("--out={file}");
    let cases: [&[&str]; 5] = [
        &["simulate", "--no-such-flag"],
        &[],
        &["simulate", bad, "--method", "rk4", "--dt", "0.01"],
        &["report", &out_file, "--quick"],
        &["inertia", good],
    ];
    for (i, args) in cases.into_iter().enumerate() {
        let binary = run(&dir, args);
        let library =
            ga_rigid_cli::try_run(std::iter::once("ga-rigid").chain(args.iter().copied()));
        assert_eq!(library.is_err(), i < 4, "{args:?}: {library:?}");
        match library {
            Ok(()) => assert_eq!(binary.status.code(), Some(0), "{args:?}"),
            Err(failure) => {
                assert_eq!(
                    binary.status.code(),
                    Some(i32::from(failure.status)),
                    "{args:?}"
                );
                let stderr = String::from_utf8_lossy(&binary.stderr);
                assert_eq!(stderr, format!("{}\n", failure.message), "{args:?}");
                assert!(
                    failure.status == 2 && !failure.message.is_empty(),
                    "{args:?}"
                );
            }
        }
    }
}
