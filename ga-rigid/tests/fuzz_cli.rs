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
    let dir = case_dir();
    std::fs::write(dir.join("scene.toml"), scene).unwrap();
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
