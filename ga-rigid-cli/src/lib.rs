//! The `ga-rigid` command line: argument parsing, scene loading, validation, output.
//!
//! Every failure ends the same way: nothing on standard output, one line on standard
//! error naming the field or argument and the rule it broke, no output file, and exit
//! status 2 for bad input (1 for a failed write or a missing feature). Every output file
//! is checked before any work (a regular file or missing, a symbolic link followed to
//! one; never a directory, FIFO, socket or device, the scene, its mesh or another output)
//! and written only when the command has succeeded: all to temporary files first, then
//! renamed into place together (`output::OutputPlan`).
//!
//! The command's manual follows (also `docs/command.md` in the repository).
#![doc = include_str!("../../docs/command.md")]

mod args;
pub mod error;
mod inertia_cmd;
mod output;
mod progress;
pub mod report;
mod report_cmd;
mod simulate;
mod simulate_nd;

use std::ffi::OsString;
use std::io::Write as _;
use std::path::PathBuf;
use std::process::ExitCode;

use clap::Parser;

pub use args::{Cli, Command, InertiaArgs, MethodArg, ReportArgs, SimulateArgs};
pub use inertia_cmd::describe as describe_inertia;

use ga_rigid::csv::to_csv;
use ga_rigid::error::Error as LibError;
use ga_rigid::limits::{Limits, StepSource};
use ga_rigid::run::run_simulation_with_progress;
use ga_rigid::scene::Scene;

use crate::error::Error;

/// Run the command line with the process's arguments; the body of `main`.
#[must_use]
pub fn main() -> ExitCode {
    ExitCode::from(run(std::env::args_os()))
}

/// Run the command line with the given arguments (the first is the program name) and
/// return the exit status, having printed the output or the one-line error.
pub fn run<I, T>(args: I) -> u8
where
    I: IntoIterator<Item = T>,
    T: Into<OsString> + Clone,
{
    match try_run(args) {
        Ok(()) => 0,
        Err(failure) => {
            eprintln!("{}", failure.message);
            failure.status
        }
    }
}

/// A command that failed: its exit status and the one line [`run`] prints on standard
/// error for it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Failure {
    /// 2 for bad input, 1 for a failed write or a missing feature ([`exit_code`]).
    pub status: u8,
    /// The error line, without its newline.
    pub message: String,
}

/// [`run`] that returns the error line instead of printing it, for callers that report
/// errors their own way (the Python package raises it). The output, help and progress are
/// printed as [`run`] prints them.
///
/// # Errors
/// [`Failure`] with the status and line of [`run`] whenever [`run`] returns a non-zero
/// status.
pub fn try_run<I, T>(args: I) -> Result<(), Failure>
where
    I: IntoIterator<Item = T>,
    T: Into<OsString> + Clone,
{
    let cli = match Cli::try_parse_from(args) {
        Ok(cli) => cli,
        Err(e) => return clap_exit(&e),
    };
    let result = match &cli.command {
        Command::Simulate(a) => simulate(a),
        Command::Inertia(a) => inertia(a),
        Command::Report(a) => report(a),
    };
    result.map_err(|e| Failure {
        status: exit_code(&e),
        message: e.to_string(),
    })
}

/// The process exit status for an error: 2 for bad input (the user can fix the command
/// line or the files), 1 for failures of the environment or of the program.
#[must_use]
pub fn exit_code(error: &Error) -> u8 {
    match error {
        Error::Write { .. } | Error::Library(LibError::NotAvailable { .. }) => 1,
        Error::Library(_) => 2,
    }
}

/// Help and version go to standard output with status 0; usage errors are cut to their
/// first paragraph, joined into one line (clap's own text, e.g. "error: unexpected
/// argument '--x' found"), so that, like every other error, they are one line on
/// standard error, with status 2.
fn clap_exit(e: &clap::Error) -> Result<(), Failure> {
    use clap::error::ErrorKind;
    let rendered = e.render().to_string();
    match e.kind() {
        ErrorKind::DisplayHelp | ErrorKind::DisplayVersion => {
            let _ = std::io::stdout().write_all(rendered.as_bytes());
            Ok(())
        }
        ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => {
            // clap would print the whole help here; keep the one-line rule for errors.
            Err(Failure {
                status: 2,
                message:
                    "error: a subcommand is required (simulate, inertia or report); try --help"
                        .to_string(),
            })
        }
        _ => {
            // The first paragraph is the error; some errors continue it on indented lines
            // (the list of missing arguments), so join them into one line.
            let first: Vec<&str> = rendered
                .lines()
                .map(str::trim)
                .skip_while(|l| l.is_empty())
                .take_while(|l| !l.is_empty())
                .collect();
            let line = if first.is_empty() {
                "error: invalid arguments".to_string()
            } else {
                cut_quoted(&without_possible_values(&first.join(" ")))
            };
            Err(Failure {
                status: 2,
                message: line,
            })
        }
    }
}

/// clap's message without its `[possible values: ...]` list, which for `--method` alone
/// would take the line past 200 characters: `--help` lists the values with their summaries.
fn without_possible_values(line: &str) -> String {
    match line.find(" [possible values:") {
        Some(start) => {
            let end = line[start..]
                .find(']')
                .map_or(line.len(), |i| start + i + 1);
            format!(
                "{}; see --help for the values{}",
                &line[..start],
                &line[end..]
            )
        }
        None => line.to_string(),
    }
}

/// clap's message with each '...'-quoted piece of the user's text cut by
/// [`ga_rigid::error::echo`], so that a long argument does not make a long line.
fn cut_quoted(line: &str) -> String {
    let mut out = String::new();
    for (k, piece) in line.split('\'').enumerate() {
        if k > 0 {
            out.push('\'');
        }
        // Odd pieces are inside quotes.
        if k % 2 == 1 {
            out.push_str(&ga_rigid::error::echo(piece));
        } else {
            out.push_str(piece);
        }
    }
    out
}

/// The command's names for the library's run parameters, applied once to the library's
/// errors at this edge ([`LibError::renamed`]).
pub const FLAG_NAMES: [(&str, &str); 7] = [
    ("dt", "--dt"),
    ("tol", "--tol"),
    ("max_steps", "--max-steps"),
    ("max_output_mb", "--max-output-mb"),
    ("max_seconds", "--max-seconds"),
    ("max_phase_error", "--max-phase-error"),
    ("allow_unstable", "--allow-unstable"),
];

/// A library error of the run's rule book in the command's words.
fn in_flags(e: LibError) -> Error {
    Error::Library(e.renamed(&FLAG_NAMES))
}

/// `simulate`: validate the step control and every output path, load the scene, check
/// the run against its limits ([`ga_rigid::limits::plan`]), run the method, then write
/// the CSV, its sidecar record and the plot together (see [`output::OutputPlan`]): a
/// failure leaves every existing file as it was.
fn simulate(args: &SimulateArgs) -> Result<(), Error> {
    match ga_rigid::nd::scene::dimension_of(&args.scene) {
        3 => {}
        dimension => return simulate_nd::simulate(args, dimension),
    }
    let method = args.method.0;
    // Without --dt or --tol the step control comes from the scene (`limits::default_step`).
    let given = method.given_step(args.dt, args.tol).map_err(in_flags)?;
    let mut plan = output::OutputPlan::with_stdout_alternative();
    plan.input("the scene file", &args.scene)?;
    let sidecar = args.out.as_deref().map(simulate::sidecar_path);
    if let (Some(out), Some(sidecar)) = (&args.out, &sidecar) {
        plan.add("--out", out)?;
        plan.add("--out", sidecar)?;
    }
    if let Some(plot) = &args.plot {
        plan.add("--plot", plot)?;
    }
    let scene = Scene::load(&args.scene)?;
    if let ga_rigid::scene::BodySpec::Mesh { path, .. } = &scene.body {
        plan.input("the scene's mesh (body.mesh)", path)?;
    }
    let limits = Limits {
        max_steps: args.max_steps,
        max_output_mb: args.max_output_mb,
        max_seconds: args.max_seconds,
        max_phase_error: args.max_phase_error,
        allow_unstable: args.allow_unstable,
    };
    let run = ga_rigid::limits::plan(&scene, method, given, &limits).map_err(in_flags)?;
    let mut progress = progress::Progress::new(scene.run.t_end, run.work.steps);
    let rows = run_simulation_with_progress(&scene, method, run.step, limits.max_steps, &mut |t| {
        progress.update(t);
    });
    progress.finish();
    let rows = rows.map_err(in_flags)?;
    let plot = match &args.plot {
        Some(_) => {
            let title = format!(
                "{}: {}",
                ga_rigid::error::echo_path(&args.scene),
                method.name()
            );
            Some(crate::report::simulation_svg(&rows, &title)?)
        }
        None => None,
    };
    let csv = to_csv(&rows);
    let record = simulate::Record {
        scene: &args.scene,
        method,
        step: run.step,
        source: run.source,
        run: scene.run,
    };
    // The texts in the order the plan's outputs were added.
    let mut texts: Vec<String> = Vec::new();
    if let Some(out) = &args.out {
        texts.push(csv.clone());
        texts.push(record.to_json(out));
    } else if let StepSource::Default(_) = run.source {
        // Standard output carries only the CSV; say what was chosen on stderr.
        eprintln!("note: {}", record.describe_step());
    }
    texts.extend(plot);
    let texts: Vec<&str> = texts.iter().map(String::as_str).collect();
    let staged = plan.stage(&texts)?;
    if args.out.is_none() {
        emit_stdout(&csv)?;
    }
    staged.publish()
}

/// `inertia`: load the scene and print its body's mass properties.
fn inertia(args: &InertiaArgs) -> Result<(), Error> {
    if ga_rigid::nd::scene::dimension_of(&args.scene) != 3 {
        let scene = ga_rigid::nd::scene::NdScene::load(&args.scene)?;
        return emit_stdout(&simulate_nd::describe_inertia(&scene));
    }
    let scene = Scene::load(&args.scene)?;
    emit_stdout(&describe_inertia(&scene))
}

/// `report`: run the suite and write its files.
fn report(args: &ReportArgs) -> Result<(), Error> {
    report_cmd::run(args)
}

/// Write finished output to standard output.
fn emit_stdout(text: &str) -> Result<(), Error> {
    let mut stdout = std::io::stdout().lock();
    stdout
        .write_all(text.as_bytes())
        .and_then(|()| stdout.flush())
        .map_err(|source| Error::Write {
            field: "stdout".to_string(),
            path: PathBuf::from("-"),
            source,
        })
}
