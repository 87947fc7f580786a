//! The command line, as clap derive types.

use std::path::PathBuf;

use clap::builder::PossibleValue;
use clap::{Args, Parser, Subcommand, ValueEnum};

use crate::integrators::Method;

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
    /// Also draw the body angular velocity and the relative energy drift against time
    /// into this SVG file.
    #[arg(long, value_name = "FILE.svg")]
    pub plot: Option<PathBuf>,
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
    /// The directory to write results.csv, one SVG per scene and index.html into
    /// (created if missing; files are replaced only when complete).
    #[arg(long, value_name = "DIR", default_value = "report")]
    pub out: PathBuf,
    /// Fewer steps and tolerances per method: well under a minute.
    #[arg(long)]
    pub quick: bool,
    /// Add every `*.toml` scene (the `simulate` format) in this directory to the suite.
    #[arg(long, value_name = "DIR")]
    pub scenes: Option<PathBuf>,
}

// clap learns the method names from the library's registry: one table, one name each.
impl ValueEnum for Method {
    fn value_variants<'a>() -> &'a [Self] {
        &Method::ALL
    }

    fn to_possible_value(&self) -> Option<PossibleValue> {
        Some(PossibleValue::new(self.name()).help(self.info().summary))
    }
}
