//! The `ga-rigid` command line: argument parsing, scene loading, validation, output.
//!
//! Every failure ends the same way: nothing on standard output, one line on standard
//! error naming the field or argument and the rule it broke, no output file, and exit
//! status 2 for bad input (1 for a failed write or a missing feature). Every output file
//! is checked before any work (a regular file or missing, a symbolic link followed to
//! one; never a directory, FIFO, socket or device, the scene, its mesh or another output)
//! and written only when the command has succeeded: all to temporary files first, then
//! renamed into place together (`output::OutputPlan`; see the README).

mod args;
mod budget;
mod inertia_cmd;
mod output;
mod progress;
mod report_cmd;
mod simulate;

use std::ffi::OsString;
use std::io::Write as _;
use std::path::PathBuf;
use std::process::ExitCode;

use clap::Parser;

pub use crate::integrators::{Method, Step, StepKind};
pub use args::{Cli, Command, InertiaArgs, ReportArgs, SimulateArgs};
pub use inertia_cmd::describe as describe_inertia;
pub use simulate::{principal_body, run_simulation};

use crate::csv::to_csv;
use crate::error::Error;
use crate::scene::Scene;

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
    let cli = match Cli::try_parse_from(args) {
        Ok(cli) => cli,
        Err(e) => return clap_exit(&e),
    };
    let result = match &cli.command {
        Command::Simulate(a) => simulate(a),
        Command::Inertia(a) => inertia(a),
        Command::Report(a) => report(a),
    };
    match result {
        Ok(()) => 0,
        Err(e) => {
            eprintln!("{e}");
            exit_code(&e)
        }
    }
}

/// The process exit status for an error: 2 for bad input (the user can fix the command
/// line or the files), 1 for failures of the environment or of the program.
#[must_use]
pub fn exit_code(error: &Error) -> u8 {
    match error {
        Error::Write { .. } | Error::NotAvailable { .. } => 1,
        _ => 2,
    }
}

/// Help and version go to standard output with status 0; usage errors are cut to their
/// first paragraph, joined into one line (clap's own text, e.g. "error: unexpected
/// argument '--x' found"), so that, like every other error, they are one line on
/// standard error, with status 2.
fn clap_exit(e: &clap::Error) -> u8 {
    use clap::error::ErrorKind;
    let rendered = e.render().to_string();
    match e.kind() {
        ErrorKind::DisplayHelp | ErrorKind::DisplayVersion => {
            let _ = std::io::stdout().write_all(rendered.as_bytes());
            0
        }
        ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => {
            // clap would print the whole help here; keep the one-line rule for errors.
            eprintln!("error: a subcommand is required (simulate, inertia or report); try --help");
            2
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
            eprintln!("{line}");
            2
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
/// [`crate::error::echo`], so that a long argument does not make a long line.
fn cut_quoted(line: &str) -> String {
    let mut out = String::new();
    for (k, piece) in line.split('\'').enumerate() {
        if k > 0 {
            out.push('\'');
        }
        // Odd pieces are inside quotes.
        if k % 2 == 1 {
            out.push_str(&crate::error::echo(piece));
        } else {
            out.push_str(piece);
        }
    }
    out
}

/// `simulate`: validate the step control and every output path, load the scene, run the
/// method, then write the CSV, its sidecar record and the plot together (see
/// [`output::OutputPlan`]): a failure leaves every existing file as it was.
fn simulate(args: &SimulateArgs) -> Result<(), Error> {
    // Without --dt or --tol the step control comes from the scene (see `default_step`).
    let given = match (args.method.step_kind(), args.dt, args.tol) {
        (StepKind::Fixed | StepKind::Adaptive, None, None) => None,
        _ => Some(step_control(args.method, args.dt, args.tol)?),
    };
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
    if let crate::scene::BodySpec::Mesh { path, .. } = &scene.body {
        plan.input("the scene's mesh (body.mesh)", path)?;
    }
    let (step, source) = match given {
        Some(step) => (step, simulate::StepSource::Given),
        None => simulate::default_step(&scene, args.method),
    };
    crate::error::positive("--max-phase-error", "the bound", args.max_phase_error)?;
    simulate::check_phase_error(&scene, args.max_phase_error)?;
    if !args.allow_unstable {
        simulate::check_stability(&scene, args.method, step)?;
    }
    let work = simulate::check_work(&scene, step, args.max_steps, args.max_output_mb)?;
    budget::check_seconds(args.method, step, work.steps, args.max_seconds)?;
    let mut progress = progress::Progress::new(scene.run.t_end, work.steps);
    let rows = simulate::run_simulation_with_progress(&scene, args.method, step, &mut |t| {
        progress.update(t);
    });
    progress.finish();
    let rows = rows?;
    let plot = match &args.plot {
        Some(_) => {
            let title = format!(
                "{}: {}",
                crate::error::echo_path(&args.scene),
                args.method.name()
            );
            Some(crate::report::simulation_svg(&rows, &title)?)
        }
        None => None,
    };
    let csv = to_csv(&rows);
    let record = simulate::Record {
        scene: &args.scene,
        method: args.method,
        step,
        source,
        run: scene.run,
    };
    // The texts in the order the plan's outputs were added.
    let mut texts: Vec<String> = Vec::new();
    if let Some(out) = &args.out {
        texts.push(csv.clone());
        texts.push(record.to_json(out));
    } else if let simulate::StepSource::Default(_) = source {
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

/// Check `--dt` and `--tol` and match them to the method: fixed-step methods need
/// `--dt`, adaptive ones `--tol`, and methods that evaluate a solution at the sample
/// times take neither. Both values must be finite and positive, and at most one given.
pub fn step_control(method: Method, dt: Option<f64>, tol: Option<f64>) -> Result<Step, Error> {
    if dt.is_some() && tol.is_some() {
        return Err(Error::invalid(
            "--dt",
            "--dt and --tol are mutually exclusive: give one",
        ));
    }
    if let Some(dt) = dt {
        if !(dt.is_finite() && dt > 0.0) {
            return Err(Error::invalid(
                "--dt",
                format!(
                    "the step size must be positive and finite, got {}",
                    crate::error::num(dt)
                ),
            ));
        }
    }
    if let Some(tol) = tol {
        if !(tol.is_finite() && tol > 0.0) {
            return Err(Error::invalid(
                "--tol",
                format!(
                    "the tolerance must be positive and finite, got {}",
                    crate::error::num(tol)
                ),
            ));
        }
        // Below about 1e-14 the rounding error of a step exceeds the tolerance and the
        // step size shrinks without end; above 1 a "relative" tolerance means nothing.
        if !(1e-14..=1.0).contains(&tol) {
            return Err(Error::invalid(
                "--tol",
                format!(
                    "the tolerance must be between 1e-14 and 1, got {}",
                    crate::error::num(tol)
                ),
            ));
        }
    }
    let name = method.name();
    match (method.step_kind(), dt, tol) {
        (StepKind::Fixed, Some(dt), None) => Ok(Step::Fixed(dt)),
        (StepKind::Fixed, None, Some(_)) => Err(Error::invalid(
            "--tol",
            format!("method {name} takes a fixed step: give --dt, not --tol"),
        )),
        (StepKind::Fixed, None, None) => Err(Error::invalid(
            "--dt",
            format!("method {name} takes a fixed step: give --dt"),
        )),
        (StepKind::Adaptive, None, Some(tol)) => Ok(Step::Tolerance(tol)),
        (StepKind::Adaptive, Some(_), None) => Err(Error::invalid(
            "--dt",
            format!("method {name} is adaptive: give --tol, not --dt"),
        )),
        (StepKind::Adaptive, None, None) => Err(Error::invalid(
            "--tol",
            format!("method {name} is adaptive: give --tol"),
        )),
        (StepKind::AtSamples, None, None) => Ok(Step::AtSamples),
        (StepKind::AtSamples, Some(_), _) => Err(Error::invalid(
            "--dt",
            format!("method {name} evaluates its solution at the sample times and takes no --dt"),
        )),
        (StepKind::AtSamples, None, Some(_)) => Err(Error::invalid(
            "--tol",
            format!("method {name} evaluates its solution at the sample times and takes no --tol"),
        )),
        // Both given was rejected above.
        (_, Some(_), Some(_)) => Err(Error::invalid(
            "--dt",
            "--dt and --tol are mutually exclusive: give one",
        )),
    }
}

/// `inertia`: load the scene and print its body's mass properties.
fn inertia(args: &InertiaArgs) -> Result<(), Error> {
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
