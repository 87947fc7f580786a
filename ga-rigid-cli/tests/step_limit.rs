//! The run's step limit (`--max-steps`) reaches the methods that choose their own steps:
//! ode_solvers' pairs stopped at their own 100000 steps per integration, whatever the
//! limit, after the command had checked the run against `--max-steps` and started it.

use std::path::Path;
use std::process::Command;

const BIN: &str = env!("CARGO_BIN_EXE_ga-rigid");

/// Moments (1, 2, 3) spinning near the middle axis: `dopri5-quaternion` at `tol` 1e-10
/// takes about 53 steps per unit time here (it stopped at t = 1870 with ode_solvers' own
/// limit), so t_end = 2000 needs a few thousand steps more than 100000, and the
/// estimate (about 1e6) is well under the default limit of 10^8.
const SCENE: &str = "[body]\nmoments = [1.0, 2.0, 3.0]\n\
                     [initial]\nrotor = [1, 0, 0, 0]\nomega = [0.5, 4.0, 0.3]\n\
                     [run]\nt_end = 2000.0\nsamples = 2\n";

#[test]
fn an_adaptive_peer_runs_past_100000_steps_under_the_default_limit() {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("ga-rigid-cli")
        .join("step-limit");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("scene.toml"), SCENE).unwrap();
    let out = Command::new(BIN)
        .args([
            "simulate",
            "scene.toml",
            "--method",
            "dopri5-quaternion",
            "--tol",
            "1e-10",
        ])
        .current_dir(&dir)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    let csv = String::from_utf8_lossy(&out.stdout);
    let last = csv.lines().last().unwrap();
    assert!(last.starts_with("2000.0"), "{last}");
}
