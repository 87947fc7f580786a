//! The `ga-rigid` command line: argument parsing, scene loading, validation, output.
//!
//! Every failure ends the same way: nothing on standard output, one line on standard
//! error naming the field or argument and the rule it broke, no output file, and exit
//! status 2 for bad input (1 for a failed write or a missing feature). Output is
//! buffered and written only when the command has succeeded; `--out FILE` is written to
//! a temporary file in the same directory and renamed into place.

mod args;
mod inertia_cmd;
mod report_cmd;
mod simulate;

use std::ffi::OsString;
use std::io::Write as _;
use std::path::{Path, PathBuf};
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
                first.join(" ")
            };
            eprintln!("{line}");
            2
        }
    }
}

/// `simulate`: validate the step control and the output path, load the scene, run the
/// method, write the CSV.
fn simulate(args: &SimulateArgs) -> Result<(), Error> {
    let step = step_control(args.method, args.dt, args.tol)?;
    if let Some(out) = &args.out {
        check_output_path("--out", out)?;
    }
    if let Some(plot) = &args.plot {
        check_output_path("--plot", plot)?;
    }
    let scene = Scene::load(&args.scene)?;
    let rows = run_simulation(&scene, args.method, step)?;
    if let Some(plot) = &args.plot {
        let title = format!("{}: {}", args.scene.display(), args.method.name());
        emit(
            "--plot",
            Some(plot),
            &crate::report::simulation_svg(&rows, &title)?,
        )?;
    }
    emit("--out", args.out.as_deref(), &to_csv(&rows))
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
                format!("the step size must be positive and finite, got {dt}"),
            ));
        }
    }
    if let Some(tol) = tol {
        if !(tol.is_finite() && tol > 0.0) {
            return Err(Error::invalid(
                "--tol",
                format!("the tolerance must be positive and finite, got {tol}"),
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
    emit("--out", None, &describe_inertia(&scene))
}

/// `report`: run the suite and write its files.
fn report(args: &ReportArgs) -> Result<(), Error> {
    report_cmd::run(args)
}

/// Fail early, before any work, if `out` cannot be created: its directory must exist and
/// `out` must not be a directory.
fn check_output_path(field: &str, out: &Path) -> Result<(), Error> {
    if out.is_dir() {
        return Err(Error::invalid(
            field,
            format!("{} is a directory, not a file", out.display()),
        ));
    }
    let dir = parent_dir(out);
    if !dir.is_dir() {
        return Err(Error::invalid(
            field,
            format!("the directory {} does not exist", dir.display()),
        ));
    }
    Ok(())
}

/// The directory a file path lives in (`.` for a bare file name).
fn parent_dir(path: &Path) -> PathBuf {
    match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    }
}

/// Write finished output to standard output, or atomically to `out`: into a temporary
/// file in the same directory, then renamed over `out`, so a failure leaves no partial
/// file behind.
fn emit(field: &str, out: Option<&Path>, text: &str) -> Result<(), Error> {
    let Some(out) = out else {
        let mut stdout = std::io::stdout().lock();
        return stdout
            .write_all(text.as_bytes())
            .and_then(|()| stdout.flush())
            .map_err(|source| Error::Write {
                field: "stdout".to_string(),
                path: PathBuf::from("-"),
                source,
            });
    };
    let name = out
        .file_name()
        .map_or_else(|| OsString::from("out"), std::ffi::OsStr::to_os_string);
    let mut tmp_name = OsString::from(".");
    tmp_name.push(&name);
    tmp_name.push(format!(".tmp-{}", std::process::id()));
    let tmp = parent_dir(out).join(tmp_name);
    let write_err = |source| Error::Write {
        field: field.to_string(),
        path: out.to_path_buf(),
        source,
    };
    let result = std::fs::write(&tmp, text).and_then(|()| std::fs::rename(&tmp, out));
    if let Err(source) = result {
        // Best effort: the temporary file may not exist if the write failed early.
        let _ = std::fs::remove_file(&tmp);
        return Err(write_err(source));
    }
    Ok(())
}
