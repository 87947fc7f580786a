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
    /// The fixed step size, for fixed-step methods.
    // Negative numbers must reach our own check (with its message), not be taken for flags.
    #[arg(
        long,
        value_name = "DT",
        allow_negative_numbers = true,
        conflicts_with = "tol"
    )]
    pub dt: Option<f64>,
    /// The error tolerance, for adaptive methods.
    #[arg(long, value_name = "TOL", allow_negative_numbers = true)]
    pub tol: Option<f64>,
    /// Write the CSV to this file instead of standard output (created only on success).
    #[arg(long, value_name = "FILE")]
    pub out: Option<PathBuf>,
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
    /// Write the report to this file instead of standard output (created only on success).
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
    /// Torque kick, exact free flow, torque kick (Celledoni-Fassò-Säfström-Zanna), order 2.
    ExactSplitting,
    /// The exact-flow splitting composed to order 4 (Suzuki).
    #[value(name = "exact-splitting-4")]
    ExactSplitting4,
    /// The exact-flow splitting composed to order 6 (Kahan-Li).
    #[value(name = "exact-splitting-6")]
    ExactSplitting6,
    /// The exact-flow splitting composed to order 8 (Kahan-Li).
    #[value(name = "exact-splitting-8")]
    ExactSplitting8,
    /// The DLM splitting composed to order 4 (Suzuki).
    #[value(name = "splitting-4")]
    Splitting4,
    /// The DLM splitting composed to order 6 (Kahan-Li).
    #[value(name = "splitting-6")]
    Splitting6,
    /// The DLM splitting composed to order 8 (Kahan-Li).
    #[value(name = "splitting-8")]
    Splitting8,
    /// Adaptive Runge-Kutta-Munthe-Kaas with the Dormand-Prince 8(5,3) pair.
    #[value(name = "lie-dop853")]
    LieDop853,
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
            Method::ExactSplitting => "exact-splitting",
            Method::ExactSplitting4 => "exact-splitting-4",
            Method::ExactSplitting6 => "exact-splitting-6",
            Method::ExactSplitting8 => "exact-splitting-8",
            Method::Splitting4 => "splitting-4",
            Method::Splitting6 => "splitting-6",
            Method::Splitting8 => "splitting-8",
            Method::LieDop853 => "lie-dop853",
        }
    }

    /// The step control the method takes.
    #[must_use]
    pub fn step_kind(self) -> StepKind {
        match self {
            Method::Rk4 | Method::LieRk4 | Method::Midpoint | Method::Splitting => StepKind::Fixed,
            Method::ExactSplitting
            | Method::ExactSplitting4
            | Method::ExactSplitting6
            | Method::ExactSplitting8
            | Method::Splitting4
            | Method::Splitting6
            | Method::Splitting8 => StepKind::Fixed,
            Method::Dopri | Method::LieDop853 => StepKind::Adaptive,
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
