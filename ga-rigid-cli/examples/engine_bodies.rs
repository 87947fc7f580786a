//! The engine table's runs on two bodies: the T-handle (the report's `engine_runs.csv`
//! body) and a near-symmetric body (`NEAR_SYMMETRIC`), at `h |w(0)|` = 0.1, 0.2 and 0.5,
//! for Spiers's two forms (avian's pull request #993), ours (`splitting-corrected`, the
//! step of `ga_engine`, and `splitting-casimir`), Buss's update and the engines' Euler
//! steps. Each run takes `STEPS` steps; the table gives the largest relative energy and
//! space-momentum errors and the flip period's error against the exact flow (Jacobi
//! elliptic functions). Run with
//! `cargo run --release -p ga-rigid-cli --example engine_bodies [steps]`.

use ga_rigid::registry::Method;
use ga_rigid_cli::report::{engine_run_on, NEAR_SYMMETRIC, T_HANDLE};

/// Steps per run unless given: the full report's.
const STEPS: u64 = 100_000;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let steps = match std::env::args().nth(1) {
        Some(arg) => arg.parse::<u64>()?,
        None => STEPS,
    };
    let methods = [
        Method::SpiersVelocity,
        Method::SpiersMomentum,
        Method::SplittingCorrected,
        Method::SplittingCasimir,
        Method::Buss2,
        Method::EulerGyroImplicit,
        Method::EulerGyroExplicit,
    ];
    println!("{steps} steps a run");
    println!(
        "| body | h \\|w\\| | method | energy rel. max | L rel. max | flips | flip period error |"
    );
    println!("|---|---:|---|---:|---:|---:|---:|");
    for body in [T_HANDLE, NEAR_SYMMETRIC] {
        for rate in [0.1, 0.2, 0.5] {
            for method in methods {
                let run = engine_run_on(body, method, rate, steps)?;
                let flip = run
                    .flip_error()
                    .map_or("no flips".to_string(), |e| format!("{:+.3}%", 100.0 * e));
                let status = run
                    .failure
                    .as_deref()
                    .map_or(String::new(), |f| format!(" ({f})"));
                println!(
                    "| {} | {rate} | {} | {:.1e} | {:.1e} | {} | {flip}{status} |",
                    body.name,
                    method.name(),
                    run.energy_max,
                    run.momentum_max,
                    run.flips,
                );
            }
        }
    }
    Ok(())
}
