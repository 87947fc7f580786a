//! The command line, as clap derive types.

use std::path::PathBuf;

use clap::{Args, Parser, Subcommand, ValueEnum};

/// Rigid-body dynamics in geometric algebra.
#[derive(Debug, Parser)]
#[command(name = "ga-rigid", version, about)]
pub struct Cli {
    /// The command to run.
    #[command(subcommand)]
    pub command: Command,
}

/// The subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Integrate a scene and write the samples as CSV.
    Simulate(SimulateArgs),
    /// Print the mass, centre of mass, principal moments and principal rotor of a scene's body.
    Inertia(InertiaArgs),
    /// Produce the report.
    Report(ReportArgs),
}

/// Arguments of `simulate`.
#[derive(Debug, Args)]
pub struct SimulateArgs {
    /// The scene file (TOML).
    #[arg(value_name = "SCENE")]
    pub scene: PathBuf,
    /// The integration method.
    #[arg(long, value_enum)]
    pub method: Method,
    /// The fixed step size, for fixed-step methods; by default 1/200 of the period
    /// 2 pi / |w|max of the fastest rotation the scene's body can reach.
    // Negative numbers (`-1e-6`, `-inf`) must reach our own check (with its message), not
    // be taken for flags: clap's negative-number test misses exponents and `inf`.
    #[arg(
        long,
        value_name = "DT",
        allow_hyphen_values = true,
        conflicts_with = "tol"
    )]
    pub dt: Option<f64>,
    /// The relative error tolerance, for adaptive methods: between 1e-14 and 1; by
    /// default 1e-9.
    #[arg(long, value_name = "TOL", allow_hyphen_values = true)]
    pub tol: Option<f64>,
    /// Write the CSV to this regular file instead of standard output, only on success, by
    /// temporary file and rename; a symbolic link is followed and its target replaced; a
    /// directory, FIFO, socket or device is refused (use standard output to reach one).
    #[arg(long, value_name = "FILE")]
    pub out: Option<PathBuf>,
    /// Refuse runs estimated to take more steps than this (t_end / dt plus one per
    /// sample for fixed steps; a rough estimate for dopri).
    #[arg(long, value_name = "N", default_value_t = super::simulate::DEFAULT_MAX_STEPS)]
    pub max_steps: u64,
    /// Refuse runs whose CSV may be larger than this many megabytes (300 bytes a row).
    #[arg(long, value_name = "MB", default_value_t = super::simulate::DEFAULT_MAX_OUTPUT_MB)]
    pub max_output_mb: u64,
}

/// Arguments of `inertia`.
#[derive(Debug, Args)]
pub struct InertiaArgs {
    /// The scene file (TOML).
    #[arg(value_name = "SCENE")]
    pub scene: PathBuf,
}

/// Arguments of `report`.
#[derive(Debug, Args)]
pub struct ReportArgs {
    /// Write the report to this regular file instead of standard output, only on success,
    /// with the same rules as `simulate --out`.
    #[arg(long, value_name = "FILE")]
    pub out: Option<PathBuf>,
    /// Three settings per method and one timing run instead of nine and the best of three.
    #[arg(long)]
    pub quick: bool,
}

/// The integration methods `simulate` offers.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, ValueEnum)]
pub enum Method {
    /// The closed-form solution (symmetric top).
    ClosedForm,
    /// Classical fourth-order Runge–Kutta on the rotor and angular velocity.
    Rk4,
    /// Fourth-order Runge–Kutta on the rotor group (a Lie group method).
    LieRk4,
    /// The midpoint rule.
    Midpoint,
    /// Splitting into exact rotations (Dullweber–Leimkuhler–McLachlan).
    Splitting,
    /// Adaptive Dormand–Prince 5(4).
    Dopri,
    /// The exact flow through Jacobi elliptic functions.
    Exact,
}

/// What step control a method takes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StepKind {
    /// A fixed step size: `--dt`.
    Fixed,
    /// An error tolerance: `--tol`.
    Adaptive,
    /// Neither: the solution is evaluated at the sample times.
    AtSamples,
}

impl Method {
    /// The name on the command line.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Method::ClosedForm => "closed-form",
            Method::Rk4 => "rk4",
            Method::LieRk4 => "lie-rk4",
            Method::Midpoint => "midpoint",
            Method::Splitting => "splitting",
            Method::Dopri => "dopri",
            Method::Exact => "exact",
        }
    }

    /// The step control the method takes.
    #[must_use]
    pub fn step_kind(self) -> StepKind {
        match self {
            Method::Rk4 | Method::LieRk4 | Method::Midpoint | Method::Splitting => StepKind::Fixed,
            Method::Dopri => StepKind::Adaptive,
            Method::ClosedForm | Method::Exact => StepKind::AtSamples,
        }
    }
}

/// The validated step control handed to a simulation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Step {
    /// A fixed step size, finite and positive.
    Fixed(f64),
    /// An error tolerance, finite and positive.
    Tolerance(f64),
    /// No step control: the method evaluates its solution at the sample times.
    AtSamples,
}
