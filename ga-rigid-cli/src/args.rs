//! The command line, as clap derive types.

use std::path::PathBuf;

use clap::builder::PossibleValue;
use clap::{Args, Parser, Subcommand, ValueEnum};

use ga_rigid::limits;
use ga_rigid::registry::Method;

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
    pub method: MethodArg,
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
    /// Write the CSV to this regular file instead of standard output (and a record to
    /// FILE.json), only on success, by temporary file and rename; a symbolic link is
    /// followed and its target replaced; a directory, FIFO, socket or device, the scene or
    /// another output is refused (use standard output to reach a pipe or device).
    #[arg(long, value_name = "FILE")]
    pub out: Option<PathBuf>,
    /// Refuse runs estimated to take more steps than this (t_end / dt plus one per
    /// sample for fixed steps; a rough estimate for the adaptive methods), and stop an
    /// adaptive method, peers included, that takes more (accepted and rejected).
    #[arg(long, value_name = "N", default_value_t = limits::DEFAULT_MAX_STEPS)]
    pub max_steps: u64,
    /// Refuse runs whose attitude at t_end rounding alone would put further off than this
    /// many radians (about |w|max t_end 2.2e-16, for every method, the exact ones too); inf
    /// turns the check off.
    #[arg(long, value_name = "RAD", default_value_t = limits::DEFAULT_MAX_PHASE_ERROR, allow_hyphen_values = true)]
    pub max_phase_error: f64,
    /// Run a fixed step beyond the method's stability limit h |w|max (see --help of
    /// --method for the limits) instead of refusing it.
    #[arg(long)]
    pub allow_unstable: bool,
    /// Refuse runs estimated to take longer than this many seconds in a release build (the
    /// step estimate times the method's cost per step, from the registry).
    #[arg(long, value_name = "S", default_value_t = limits::DEFAULT_MAX_SECONDS)]
    pub max_seconds: u64,
    /// Refuse runs whose CSV may be larger than this many megabytes (300 bytes a row).
    #[arg(long, value_name = "MB", default_value_t = limits::DEFAULT_MAX_OUTPUT_MB)]
    pub max_output_mb: u64,
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
    /// The directory to write results.csv, long_runs.csv, one SVG per scene and index.html into
    /// (created if missing; files are replaced only when complete).
    #[arg(long, value_name = "DIR", default_value = "report")]
    pub out: PathBuf,
    /// Fewer steps and tolerances per method: well under a minute.
    #[arg(long)]
    pub quick: bool,
    /// Add every `*.toml` scene (the `simulate` format) in this directory to the suite.
    #[arg(long, value_name = "DIR")]
    pub scenes: Option<PathBuf>,
    /// Refuse `--scenes` whose runs are estimated to take longer than this many seconds
    /// together (steps times each method's cost per step, the timing repeats included).
    #[arg(long, value_name = "S", default_value_t = limits::DEFAULT_REPORT_MAX_SECONDS)]
    pub max_seconds: u64,
}

/// A registry method as a command-line value (clap's trait on the library's type).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MethodArg(pub Method);

/// Every registry method, in the registry's order, as [`MethodArg`]s.
const METHOD_ARGS: [MethodArg; Method::ALL.len()] = {
    let mut all = [MethodArg(Method::ALL[0]); Method::ALL.len()];
    let mut k = 0;
    while k < all.len() {
        all[k] = MethodArg(Method::ALL[k]);
        k += 1;
    }
    all
};

// clap learns the method names from the library's registry: one table, one name each.
impl ValueEnum for MethodArg {
    fn value_variants<'a>() -> &'a [Self] {
        &METHOD_ARGS
    }

    fn to_possible_value(&self) -> Option<PossibleValue> {
        Some(PossibleValue::new(self.0.name()).help(self.0.info().summary))
    }
}
