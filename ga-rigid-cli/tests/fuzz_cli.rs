//! The command's contract under generated and mutated input (issue 12): for any scene text
//! and any argument list, `simulate` either exits 0 having written a CSV of finite numbers
//! under the fixed header, or exits 2 with exactly one short line on standard error, nothing
//! on standard output and no output file. Never a panic, a hang, `inf` in a CSV, or a
//! half-written file.
//!
//! Brief by default (64 cases, a few seconds); `PROPTEST_CASES=5000` for a longer hunt.
//! The cases that found bugs are kept in `regressions_keep_the_contract` below.

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::{Duration, Instant};

use proptest::prelude::*;

const BIN: &str = env!("CARGO_BIN_EXE_ga-rigid");
const HEADER: &str = "t,r_s,r_e12,r_e13,r_e23,w1,w2,w3,energy,l1,l2,l3";

/// Every run gets these, so that no generated case runs for minutes in a debug build; the
/// refusal above them is part of what is tested.
const LIMITS: [&str; 4] = ["--max-steps", "200000", "--max-output-mb", "2"];

fn case_dir() -> PathBuf {
    static NEXT: AtomicUsize = AtomicUsize::new(0);
    let k = NEXT.fetch_add(1, Ordering::Relaxed);
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("ga-rigid-fuzz")
        .join(format!("{}-{k}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn run_with_deadline(dir: &Path, args: &[String]) -> Output {
    let mut child = Command::new(BIN)
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let start = Instant::now();
    // Output is small (the CSV goes to a file), so the pipes cannot fill up and block.
    while child.try_wait().unwrap().is_none() {
        if start.elapsed() > Duration::from_secs(60) {
            child.kill().unwrap();
            let _ = child.wait();
            panic!("{args:?} ran for more than 60 s");
        }
        std::thread::sleep(Duration::from_millis(5));
    }
    child.wait_with_output().unwrap()
}

/// Run `simulate scene.toml ARGS --out out.csv` and check the contract; `Err` says how it
/// was broken.
fn check_contract(scene: &str, args: &[String]) -> Result<(), String> {
    check_contract_with(scene, &[], args)
}

/// [`check_contract`] with other input files (a mesh) beside the scene.
fn check_contract_with(scene: &str, files: &[(&str, &str)], args: &[String]) -> Result<(), String> {
    let dir = case_dir();
    std::fs::write(dir.join("scene.toml"), scene).unwrap();
    for (name, text) in files {
        std::fs::write(dir.join(name), text).unwrap();
    }
    let mut all: Vec<String> = vec!["simulate".into(), "scene.toml".into()];
    all.extend(args.iter().cloned());
    all.extend(LIMITS.iter().map(|s| s.to_string()));
    all.extend(["--out".to_string(), "out.csv".to_string()]);
    let out = run_with_deadline(&dir, &all);
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    let leftovers: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(|e| e.ok())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| n != "scene.toml" && n != "out.csv")
        .filter(|n| !files.iter().any(|(f, _)| f == n))
        .filter(|n| !(n == "out.csv.json" && out.status.code() == Some(0)))
        .collect();
    let result = match out.status.code() {
        Some(0) => check_csv(&dir.join("out.csv"), &stderr, &out.stdout),
        Some(2) => {
            let chars = stderr.trim_end().chars().count();
            if !out.stdout.is_empty() {
                Err("exit 2 with standard output".to_string())
            } else if stderr.lines().count() != 1 || !stderr.ends_with('\n') {
                Err(format!("exit 2 without exactly one line: {stderr:?}"))
            } else if chars > 200 {
                Err(format!("a {chars}-character message: {stderr}"))
            } else if dir.join("out.csv").exists() {
                Err(format!("exit 2 but out.csv was written: {stderr}"))
            } else {
                Ok(())
            }
        }
        code => Err(format!("exit status {code:?}: {stderr}")),
    }
    .and_then(|()| {
        if leftovers.is_empty() {
            Ok(())
        } else {
            Err(format!("files left behind: {leftovers:?}"))
        }
    });
    if result.is_ok() {
        let _ = std::fs::remove_dir_all(&dir);
    }
    result.map_err(|e| format!("{e}\nargs: {all:?}\nscene:\n{scene}"))
}

fn check_csv(path: &Path, stderr: &str, stdout: &[u8]) -> Result<(), String> {
    if !stderr.is_empty() || !stdout.is_empty() {
        return Err(format!("exit 0 with output on the terminal: {stderr}"));
    }
    let text = std::fs::read_to_string(path).map_err(|e| format!("exit 0, no CSV: {e}"))?;
    let mut lines = text.lines().filter(|l| !l.starts_with('#'));
    if lines.next() != Some(HEADER) {
        return Err("exit 0, CSV without the header".to_string());
    }
    let mut rows = 0;
    for line in lines {
        rows += 1;
        let values: Vec<&str> = line.split(',').collect();
        if values.len() != 12 {
            return Err(format!("a row of {} values: {line}", values.len()));
        }
        for v in values {
            match v.parse::<f64>() {
                Ok(x) if x.is_finite() => {}
                _ => return Err(format!("exit 0 with a non-finite value {v:?} in {line}")),
            }
        }
    }
    if rows < 2 {
        return Err(format!("exit 0 with {rows} rows"));
    }
    Ok(())
}

/// Numbers a user, or a user's typo, might write: mostly ordinary ones, and the edges of
/// f64.
fn number() -> impl Strategy<Value = String> {
    prop_oneof![
        6 => (0.5f64..3.0).prop_map(|x| format!("{x}")),
        2 => (-3.0f64..3.0).prop_map(|x| format!("{x}")),
        2 => prop::sample::select(vec![
            "0", "-0", "1", "-1", "1e-320", "5e-324", "2.2250738585072014e-308", "1e-200",
            "1e200", "1e308", "1.7976931348623157e308", "nan", "inf", "-inf", "1e-9", "1e12",
            "3", "\"3\"", "true", "[1]", "2.5",
        ])
        .prop_map(str::to_string),
    ]
}

fn array(n: usize) -> impl Strategy<Value = String> {
    prop::collection::vec(number(), n).prop_map(|v| format!("[{}]", v.join(", ")))
}

/// Moments that are mostly a real body's (the triangle inequality holds), sometimes not.
fn moments() -> impl Strategy<Value = String> {
    prop_oneof![
        3 => (0.5f64..3.0, 0.5f64..3.0, 0.0f64..1.0).prop_map(|(a, b, t)| {
            let c = (a - b).abs() + t * (a + b - (a - b).abs());
            format!("[{a}, {b}, {}]", c.max(1e-3))
        }),
        2 => array(3),
    ]
}

fn body() -> impl Strategy<Value = String> {
    prop_oneof![
        4 => moments().prop_map(|m| format!("[body]\nmoments = {m}\n")),
        1 => array(3).prop_map(|m| format!("[body]\nmoments = {m}\nallow_unphysical = true\n")),
        1 => ("[1-2]", number(), array(3)).prop_map(|(k, m, s)| {
            let kind = if k == "1" { "box" } else { "ellipsoid" };
            let key = if k == "1" { "size" } else { "radii" };
            format!("[body]\nshape = {{ kind = \"{kind}\", mass = {m}, {key} = {s} }}\n")
        }),
        1 => prop::collection::vec(array(4), 1..5)
            .prop_map(|p| format!("[body]\npoints = [{}]\n", p.join(", "))),
    ]
}

fn scene() -> impl Strategy<Value = String> {
    let rotor = prop_oneof![
        3 => Just("[1, 0, 0, 0]".to_string()),
        2 => array(4),
    ];
    let t_end = prop_oneof![
        3 => (0.1f64..5.0).prop_map(|x| format!("{x}")),
        1 => number(),
    ];
    (
        body(),
        rotor,
        array(3),
        t_end,
        prop_oneof![
            4 => prop::sample::select(vec!["2", "3", "11", "101"]),
            1 => prop::sample::select(vec!["0", "-1", "1000", "100000", "1e3", "1.5"]),
        ],
        prop::option::weighted(0.25, (array(3), array(3))),
    )
        .prop_map(|(body, rotor, omega, t_end, samples, torque)| {
            let mut s = format!(
                "{body}[initial]\nrotor = {rotor}\nomega = {omega}\n\
                 [run]\nt_end = {t_end}\nsamples = {samples}\n"
            );
            if let Some((g, c)) = torque {
                s.push_str(&format!("[torque]\ng = {g}\ncom_offset = {c}\n"));
            }
            s
        })
}

/// A valid, quick scene, for the mutations to start from.
const GOOD: &str = "[body]\nmoments = [1.0, 2.0, 2.5]\n[initial]\nrotor = [1, 0, 0, 0]\n\
                    omega = [0.1, 1.0, 0.2]\n[run]\nt_end = 2.0\nsamples = 5\n";

/// Edits at random places: deletions, insertions of TOML-ish fragments, byte flips.
fn mutated() -> impl Strategy<Value = String> {
    let edit = (
        0usize..200,
        0usize..8,
        prop::sample::select(vec![
            "",
            "=",
            "[",
            "]",
            "\"",
            "{",
            "}",
            ",",
            "\n",
            "#",
            "nan",
            "1e308",
            "-",
            "5e-324",
            "[body]",
            "[run]",
            "moments = [1, 1, 1]\n",
            "a = ",
            "\u{e9}",
            "\0",
            "'''",
        ]),
    );
    prop::collection::vec(edit, 0..3).prop_map(|edits| {
        let mut text = GOOD.as_bytes().to_vec();
        for (at, cut, insert) in edits {
            let at = at % (text.len() + 1);
            let end = (at + cut).min(text.len());
            text.splice(at..end, insert.bytes());
        }
        String::from_utf8_lossy(&text).into_owned()
    })
}

/// A method and its step flags: mostly the flag the method takes with a sensible value,
/// sometimes none (the default), the wrong one, both, or a strange value.
fn arguments() -> impl Strategy<Value = Vec<String>> {
    let method = prop_oneof![
        8 => prop::sample::select(vec![
            "closed-form", "rk4", "lie-rk4", "midpoint", "splitting", "dopri", "exact",
        ]),
        1 => prop::sample::select(vec!["euler", "", "RK4", "--dt"]),
    ];
    let strange = prop_oneof![
        number(),
        prop::sample::select(vec!["-1e-6", "-inf", "--out", "", "1e-300", "0x10"])
            .prop_map(str::to_string),
    ];
    let flags = prop_oneof![
        4 => Just(None),
        4 => prop::sample::select(vec!["0.01", "0.05", "1e-8", "1e-6"]).prop_map(|v| Some((None, v.to_string()))),
        2 => (prop::sample::select(vec!["--dt", "--tol"]), strange.clone())
            .prop_map(|(f, v)| Some((Some(f), v))),
        1 => (strange.clone(), strange).prop_map(|(a, b)| Some((Some("both"), format!("{a} {b}")))),
    ];
    (method, flags).prop_map(|(method, flags)| {
        let mut args = vec!["--method".to_string(), method.to_string()];
        match flags {
            None => {}
            // The flag the method takes.
            Some((None, value)) => {
                let flag = if method == "dopri" { "--tol" } else { "--dt" };
                if !matches!(method, "exact" | "closed-form") {
                    args.extend([flag.to_string(), value]);
                }
            }
            Some((Some("both"), values)) => {
                let (dt, tol) = values.split_once(' ').unwrap_or((&values, ""));
                args.extend(["--dt".into(), dt.into(), "--tol".into(), tol.into()]);
            }
            Some((Some(flag), value)) => args.extend([flag.to_string(), value]),
        }
        args
    })
}

fn config() -> ProptestConfig {
    let cases = std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(64);
    ProptestConfig {
        cases,
        // A failing case is shrunk by re-running the command; keep that bounded.
        max_shrink_iters: 200,
        ..ProptestConfig::default()
    }
}

/// An axis-aligned cube from `low` with edge `size` as OBJ lines, vertex numbers after
/// `base`, wound counter-clockwise seen from outside.
fn cube(low: [f64; 3], size: f64, base: usize) -> String {
    let mut text = String::new();
    for x in [0.0, size] {
        for y in [0.0, size] {
            for z in [0.0, size] {
                text.push_str(&format!("v {} {} {}\n", low[0] + x, low[1] + y, low[2] + z));
            }
        }
    }
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

/// Meshes as issue 22 found them: shells nested or overlapping (or apart), long polygons
/// that repeat their vertices, long polygons of distinct vertices (a flat, two-sided
/// disc), and a cube with edits at random places.
fn mesh_text() -> impl Strategy<Value = String> {
    let offset = prop::array::uniform3(-1.5f64..1.5);
    prop_oneof![
        1 => Just(cube([0.0; 3], 1.0, 0)),
        2 => (prop::array::uniform3(0.05f64..1.0), 0.1f64..0.9)
            .prop_map(|(low, size)| cube([0.0; 3], 2.0, 0) + &cube(low, size, 8)),
        2 => offset.prop_map(|low| cube([0.0; 3], 1.0, 0) + &cube(low, 1.0, 8)),
        1 => (4usize..3000).prop_map(|n| {
            let mut text = String::from("v 0 0 0\nv 1 0 0\nv 0 1 0\nf");
            for k in 0..n {
                text.push_str(&format!(" {}", k % 3 + 1));
            }
            text + "\n"
        }),
        1 => (3usize..2000).prop_map(|n| {
            let mut text = String::new();
            for k in 0..n {
                let a = std::f64::consts::TAU * k as f64 / n as f64;
                text.push_str(&format!("v {} {} 0\n", a.cos(), a.sin()));
            }
            let up: Vec<String> = (1..=n).map(|k| k.to_string()).collect();
            let down: Vec<String> = (1..=n).rev().map(|k| k.to_string()).collect();
            format!("{text}f {}\nf {}\n", up.join(" "), down.join(" "))
        }),
        3 => prop::collection::vec(
            (
                0usize..400,
                0usize..12,
                prop::sample::select(vec![
                    "", "f 1 2 3\n", "v 0 0 0\n", "-1", "0", "1e308", "nan", "/", " 9", "\n",
                    "f 1 1 1\n", "v 1e-320 0 0\n", "#", "f -9223372036854775808 1 2\n",
                ]),
            ),
            0..4,
        )
        .prop_map(|edits| {
            let mut text = cube([0.0; 3], 1.0, 0).into_bytes();
            for (at, cut, insert) in edits {
                let at = at % (text.len() + 1);
                let end = (at + cut).min(text.len());
                text.splice(at..end, insert.bytes());
            }
            String::from_utf8_lossy(&text).into_owned()
        }),
    ]
}

/// What a name in a case directory is before the run.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Node {
    Missing,
    File,
    Fifo,
    Dir,
    LinkToFile,
    Dangling,
    LinkLoop,
}

fn node() -> impl Strategy<Value = Node> {
    prop_oneof![
        3 => Just(Node::Missing),
        2 => Just(Node::File),
        1 => Just(Node::Fifo),
        1 => Just(Node::Dir),
        1 => Just(Node::LinkToFile),
        1 => Just(Node::Dangling),
        1 => Just(Node::LinkLoop),
    ]
}

/// Make `node` at `dir/name`; FIFOs and links only inside the case's own directory.
fn make(dir: &Path, name: &str, node: Node) {
    let path = dir.join(name);
    match node {
        Node::Missing => {}
        Node::File => std::fs::write(&path, format!("old {name}\n")).unwrap(),
        Node::Fifo => {
            let status = Command::new("mkfifo").arg(&path).status().unwrap();
            assert!(status.success(), "mkfifo failed");
        }
        Node::Dir => std::fs::create_dir(&path).unwrap(),
        Node::LinkToFile => {
            let target = format!("{name}.target");
            std::fs::write(dir.join(&target), "old target\n").unwrap();
            std::os::unix::fs::symlink(target, &path).unwrap();
        }
        Node::Dangling => std::os::unix::fs::symlink("nowhere", &path).unwrap(),
        Node::LinkLoop => std::os::unix::fs::symlink(name, &path).unwrap(),
    }
}

/// Every name in `dir` with its kind and, for regular files, its text.
fn snapshot(dir: &Path) -> Vec<(String, String)> {
    let mut all: Vec<(String, String)> = std::fs::read_dir(dir)
        .unwrap()
        .filter_map(|e| e.ok())
        .map(|e| {
            let name = e.file_name().to_string_lossy().into_owned();
            let kind = e.file_type().unwrap();
            let what = if kind.is_symlink() {
                format!("link to {:?}", std::fs::read_link(e.path()).unwrap())
            } else if kind.is_file() {
                std::fs::read_to_string(e.path()).unwrap_or_default()
            } else {
                format!("{kind:?}")
            };
            (name, what)
        })
        .collect();
    all.sort();
    all
}

/// `simulate --method exact` with `--out` and `--plot` aimed at prepared names: a refusal
/// (exit 2, one short line) leaves every name exactly as it was; a success leaves the
/// scene, the FIFOs, directories and links in place, writes each output whole and no
/// two outputs into one file; nothing else is an acceptable ending.
fn check_outputs(nodes: &[Node; 4], out: Option<&str>, plot: Option<&str>) -> Result<(), String> {
    let dir = case_dir();
    std::fs::write(dir.join("scene.toml"), GOOD).unwrap();
    for (name, node) in ["a.csv", "a.csv.json", "b.svg", "c"].iter().zip(nodes) {
        make(&dir, name, *node);
    }
    let before = snapshot(&dir);
    let mut args: Vec<String> = ["simulate", "scene.toml", "--method", "exact"]
        .map(String::from)
        .to_vec();
    if let Some(out) = out {
        args.extend(["--out".to_string(), out.to_string()]);
    }
    if let Some(plot) = plot {
        args.extend(["--plot".to_string(), plot.to_string()]);
    }
    let result = run_with_deadline(&dir, &args);
    let stderr = String::from_utf8_lossy(&result.stderr).into_owned();
    let after = snapshot(&dir);
    let temporaries: Vec<&String> = after
        .iter()
        .map(|(n, _)| n)
        .filter(|n| n.contains(".tmp-"))
        .collect();
    let verdict = if !temporaries.is_empty() {
        Err(format!("temporary files left: {temporaries:?}"))
    } else {
        match result.status.code() {
            Some(2) => {
                let chars = stderr.trim_end().chars().count();
                if stderr.lines().count() != 1 || chars > 200 || !result.stdout.is_empty() {
                    Err(format!("a refusal that is not one short line: {stderr:?}"))
                } else if after != before {
                    Err(format!(
                        "a refusal changed the directory: {before:?} -> {after:?}"
                    ))
                } else {
                    Ok(())
                }
            }
            Some(0) => {
                let kept = before.iter().all(|(name, what)| {
                    !(what.starts_with("link") || what.starts_with("FileType"))
                        || after.iter().any(|(n, w)| n == name && w == what)
                });
                let text = |p: &str| std::fs::read_to_string(dir.join(p)).unwrap_or_default();
                let whole = out.is_none_or(|o| {
                    text(o).starts_with(HEADER) && text(&format!("{o}.json")).starts_with('{')
                }) && plot.is_none_or(|p| text(p).starts_with("<svg"));
                if text("scene.toml") != GOOD {
                    Err("the scene was overwritten".to_string())
                } else if !kept {
                    Err(format!("a FIFO, directory or link was replaced: {after:?}"))
                } else if !whole {
                    Err(format!("an output is not whole: {after:?}"))
                } else {
                    Ok(())
                }
            }
            code => Err(format!("exit status {code:?}: {stderr}")),
        }
    };
    if verdict.is_ok() {
        let _ = std::fs::remove_dir_all(&dir);
    }
    verdict.map_err(|e| format!("{e}\nnodes: {nodes:?}\nargs: {args:?}\nstderr: {stderr}"))
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn generated_scenes_keep_the_contract(scene in scene(), args in arguments()) {
        check_contract(&scene, &args).map_err(TestCaseError::fail)?;
    }

    #[test]
    fn mutated_scenes_keep_the_contract(scene in mutated(), args in arguments()) {
        check_contract(&scene, &args).map_err(TestCaseError::fail)?;
    }

    #[test]
    fn generated_meshes_keep_the_contract(mesh in mesh_text(), symmetric in any::<bool>()) {
        let scene = GOOD.replace(
            "moments = [1.0, 2.0, 2.5]",
            "mesh = \"body.obj\"\ndensity = 1.0",
        );
        // `exact` for a free body, `rk4` sometimes, so that a fixed step runs on a mesh too.
        let args: Vec<String> = if symmetric {
            vec!["--method".into(), "exact".into()]
        } else {
            vec!["--method".into(), "rk4".into(), "--dt".into(), "0.05".into()]
        };
        check_contract_with(&scene, &[("body.obj", &mesh)], &args)
            .map_err(TestCaseError::fail)?;
    }

    #[cfg(unix)]
    #[test]
    fn output_paths_keep_the_contract(
        nodes in prop::array::uniform4(node()),
        out in prop::option::weighted(0.8, prop::sample::select(vec![
            "a.csv", "./a.csv", "scene.toml", "./scene.toml", "b.svg", "c",
        ])),
        plot in prop::option::weighted(0.6, prop::sample::select(vec![
            "b.svg", "./b.svg", "a.csv", "a.csv.json", "scene.toml", "c",
        ])),
    ) {
        check_outputs(&nodes, out, plot).map_err(TestCaseError::fail)?;
    }
}

/// The inputs of issue 12 and those the fuzzing found, each once through the contract.
#[test]
fn regressions_keep_the_contract() {
    let with = |body: &str, omega: &str, run: &str| {
        format!("{body}[initial]\nrotor = [1, 0, 0, 0]\nomega = {omega}\n{run}")
    };
    let run = "[run]\nt_end = 1\nsamples = 3\n";
    let long = "a".repeat(300);
    let long_flag = format!("--{long}");
    let cases: Vec<(String, Vec<&str>)> = vec![
        (
            with("[body]\nmoments = [1, 1, 1]\n", "[0, 0, 1e200]", run),
            vec!["--method", "exact"],
        ),
        (
            with("[body]\nmoments = [1, 1, 1]\n", "[0, 0, 1e200]", run),
            vec!["--method", "splitting", "--dt", "0.01"],
        ),
        (
            with(
                "[body]\nmoments = [1e-320, 1e-320, 1e-320]\n",
                "[1, 0, 0]",
                run,
            ),
            vec!["--method", "splitting", "--dt", "0.01"],
        ),
        (
            with(
                "[body]\nmoments = [1, 2, 2.5]\n",
                "[1e153, 1e153, 1e153]",
                "[run]\nt_end = 1e-150\nsamples = 3\n",
            ),
            vec!["--method", "midpoint", "--dt", "1e-152"],
        ),
        (
            with(
                "[body]\nmoments = [1, 2, 2.5]\n",
                "[1, 0, 0]",
                "[run]\nt_end = 1e12\nsamples = 3\n",
            ),
            vec!["--method", "rk4", "--dt", "0.01"],
        ),
        ("a = ".to_string(), vec!["--method", "exact"]),
        (
            GOOD.to_string(),
            vec!["--method", "dopri", "--tol", "5e-324"],
        ),
        (GOOD.to_string(), vec!["--method", "rk4", "--dt", "1e-300"]),
        (GOOD.to_string(), vec!["--method", "rk4", "--dt", "-inf"]),
        (
            GOOD.to_string(),
            vec!["--method", "dopri", "--tol", "-1e-6"],
        ),
        (GOOD.to_string(), vec!["--method", &long]),
        (GOOD.to_string(), vec!["--method", "rk4", "--dt", &long]),
        (GOOD.to_string(), vec!["--method", "rk4", &long_flag]),
    ];
    for (scene, args) in cases {
        let args: Vec<String> = args.into_iter().map(str::to_string).collect();
        if let Err(e) = check_contract(&scene, &args) {
            panic!("{e}");
        }
    }
}
