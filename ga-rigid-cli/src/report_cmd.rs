//! `report`: run the suite (with the user's scenes) and the four-dimensional scenes, write
//! `results.csv`, `nd_results.csv`, one SVG per scene and `index.html` into `--out DIR`,
//! and print a short summary.
//!
//! Everything that can refuse the run does so before the suite starts, with exit status
//! 2: `--out` that is not a directory or whose parent is missing, a file of the report in
//! it that cannot be replaced (a FIFO, a directory, a dangling link), a `--scenes` entry
//! that cannot be read, scenes whose estimated time is above `--max-seconds`. The files
//! are written together at the end ([`super::output::OutputPlan`]), and a missing `--out`
//! is created only then, so a refused or killed run leaves no empty directory.

use std::ffi::OsStr;
use std::io::{IsTerminal as _, Write as _};
use std::path::{Path, PathBuf};

use crate::output::{parent_dir, OutputPlan};
use crate::progress::Ticker;
use crate::ReportArgs;
use ga_rigid::error::{echo, echo_path, Error as LibError};
use ga_rigid::limits::seconds;

use crate::error::Error;
use crate::report::{self, Size, TestScene};
use ga_rigid::scene::Scene;

/// Run the report as `args` say.
pub fn run(args: &ReportArgs) -> Result<(), Error> {
    let size = if args.quick { Size::Quick } else { Size::Full };
    let exists = check_dir(&args.out)?;
    let mut scenes = report::suite()?;
    let mut inputs = Vec::new();
    if let Some(dir) = &args.scenes {
        let (mine, paths) = user_scenes(dir)?;
        inputs = paths;
        check_time(&mine, size, args.max_seconds)?;
        scenes.extend(mine);
    }
    let mut names: Vec<String> = scenes
        .iter()
        .enumerate()
        .map(|(i, s)| report::svg_name(i, &s.name))
        .collect();
    let plots = names.len();
    let nd_names: Vec<String> = report::nd::nd_scenes()?
        .iter()
        .enumerate()
        .map(|(i, s)| report::nd::nd_svg_name(i, &s.name))
        .collect();
    names.extend(nd_names.iter().cloned());
    names.extend(
        [
            "results.csv",
            "long_runs.csv",
            "engine_runs.csv",
            "nd_results.csv",
            "index.html",
        ]
        .map(String::from),
    );
    if exists {
        // Obstacles in the directory are found now, not after the suite.
        plan(&args.out, &names, &inputs)?;
    }

    let total = report::job_count(&scenes, size);
    let terminal = std::io::stderr().is_terminal();
    let bar = terminal.then(|| new_bar(total));
    let mut ticker = Ticker::new("report");
    let mut done = 0;
    let result = report::run(&scenes, size, &mut |scene, method| {
        done += 1;
        match &bar {
            Some(bar) => {
                bar.set_message(format!("{scene}: {method}"));
                bar.inc(1);
            }
            None => ticker.tick(done, total, &format!("{scene}: {method}")),
        }
    });
    if let Some(bar) = &bar {
        bar.finish_and_clear();
    }
    let mut report = result?;
    let scale = report::Scale::of(size);
    let long_total = report::long_run_count();
    let bar = terminal.then(|| new_bar(long_total));
    let mut done = 0;
    let result = report::long_runs(scale, &mut |method| {
        done += 1;
        match &bar {
            Some(bar) => {
                bar.set_message(format!("long runs: {method}"));
                bar.inc(1);
            }
            None => ticker.tick(done, long_total, &format!("long runs: {method}")),
        }
    });
    if let Some(bar) = &bar {
        bar.finish_and_clear();
    }
    report.long_runs = result?;
    report.engine_runs = report::engine_runs(size, &mut |_| {})?;
    let nd_total = report::nd::nd_job_count(size)?;
    let bar = terminal.then(|| new_bar(nd_total));
    let mut done = 0;
    let result = report::nd::run_nd(size, &mut |scene, method| {
        done += 1;
        match &bar {
            Some(bar) => {
                bar.set_message(format!("{scene}: {method}"));
                bar.inc(1);
            }
            None => ticker.tick(done, nd_total, &format!("{scene}: {method}")),
        }
    });
    if let Some(bar) = &bar {
        bar.finish_and_clear();
    }
    report.nd_scenes = result?;

    let mut texts = Vec::with_capacity(names.len());
    for scene in &report.scenes {
        texts.push(report::svg(scene)?);
    }
    for scene in &report.nd_scenes {
        texts.push(report::nd::nd_svg(scene)?);
    }
    texts.push(report::csv(&report));
    texts.push(report::long_runs_csv(&report.long_runs));
    texts.push(report::engine_runs_csv(&report.engine_runs));
    texts.push(report::nd::nd_csv(&report.nd_scenes));
    let html = report::html(&report, &names[..plots], &texts[..plots]);
    texts.push(html);
    write_files(&args.out, exists, &names, &inputs, &texts)?;

    let mut summary = report::summary(&report);
    summary.push_str(&format!(
        "wrote {} (results.csv, long_runs.csv, engine_runs.csv, nd_results.csv, {} plots, \
         index.html)\n",
        args.out.display(),
        plots + nd_names.len(),
    ));
    let mut stdout = std::io::stdout().lock();
    stdout
        .write_all(summary.as_bytes())
        .and_then(|()| stdout.flush())
        .map_err(|source| Error::Write {
            field: "stdout".to_string(),
            path: PathBuf::from("-"),
            source,
        })
}

/// A progress bar for a terminal.
fn new_bar(total: u64) -> indicatif::ProgressBar {
    let bar = indicatif::ProgressBar::new(total);
    bar.set_style(
        indicatif::ProgressStyle::with_template("{bar:40} {pos}/{len} {elapsed} {msg}")
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
    );
    bar
}

/// Whether `dir` exists as a directory (a link to one counts); a missing `dir` is fine when
/// its parent exists (it is created at the end). Anything else is refused with status 2.
fn check_dir(dir: &Path) -> Result<bool, Error> {
    match std::fs::symlink_metadata(dir) {
        Ok(_) if dir.is_dir() => Ok(true),
        Ok(_) => Err(Error::invalid(
            "--out",
            format!("{} exists and is not a directory", echo_path(dir)),
        )),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            let parent = parent_dir(dir);
            if parent.is_dir() {
                Ok(false)
            } else {
                Err(Error::invalid(
                    "--out",
                    format!(
                        "the directory {} does not exist (only the last part of --out is created)",
                        echo_path(&parent)
                    ),
                ))
            }
        }
        Err(source) => Err(LibError::Read {
            field: "--out".to_string(),
            path: dir.to_path_buf(),
            source,
        }
        .into()),
    }
}

/// The report's files in `dir`, checked (see [`OutputPlan::add`]): none may lead to one of
/// the `inputs` (a link named `results.csv` to a scene file).
fn plan(dir: &Path, names: &[String], inputs: &[PathBuf]) -> Result<OutputPlan, Error> {
    let mut plan = OutputPlan::new();
    for input in inputs {
        plan.input("a --scenes file", input)?;
    }
    for name in names {
        plan.add("--out", &dir.join(name))?;
    }
    Ok(plan)
}

/// Write every file at once: a missing `dir` is created now, and removed again if the
/// write fails.
fn write_files(
    dir: &Path,
    exists: bool,
    names: &[String],
    inputs: &[PathBuf],
    texts: &[String],
) -> Result<(), Error> {
    if !exists {
        std::fs::create_dir(dir).map_err(|source| Error::Write {
            field: "--out".to_string(),
            path: dir.to_path_buf(),
            source,
        })?;
    }
    let texts: Vec<&str> = texts.iter().map(String::as_str).collect();
    let result = plan(dir, names, inputs).and_then(|plan| plan.write_all(&texts));
    if result.is_err() && !exists {
        // Best effort: the directory is ours and, the write having failed, empty.
        let _ = std::fs::remove_dir(dir);
    }
    result
}

/// Refuse user scenes whose runs would take more than `max_seconds` together, naming the
/// dearest one.
fn check_time(scenes: &[TestScene], size: Size, max_seconds: u64) -> Result<(), Error> {
    let estimates: Vec<f64> = scenes
        .iter()
        .map(|s| report::scene_seconds(s, size))
        .collect();
    let total: f64 = estimates.iter().sum();
    if total.is_nan() || total > max_seconds as f64 {
        let (dearest, most) = scenes
            .iter()
            .zip(&estimates)
            .max_by(|a, b| a.1.total_cmp(b.1))
            .map_or(("?".to_string(), 0.0), |(s, &e)| (echo(&s.name), e));
        return Err(Error::invalid(
            "--scenes",
            format!(
                "{} would take about {} ({dearest}.toml alone {}), above the limit \
                 of {max_seconds} s; raise it with --max-seconds",
                match scenes.len() {
                    1 => "1 scene".to_string(),
                    n => format!("{n} scenes"),
                },
                seconds(total),
                seconds(most)
            ),
        ));
    }
    Ok(())
}

/// The `*.toml` entries of `dir`, in name order, as scenes named after their files. An
/// entry that cannot be read as a regular file (a directory, a FIFO, a dangling link or
/// a link loop) is refused by name rather than skipped. The paths come back too.
fn user_scenes(dir: &Path) -> Result<(Vec<TestScene>, Vec<PathBuf>), Error> {
    let read_err = |path: &Path, source| LibError::Read {
        field: "--scenes".to_string(),
        path: path.to_path_buf(),
        source,
    };
    let mut paths = Vec::new();
    for entry in std::fs::read_dir(dir).map_err(|e| read_err(dir, e))? {
        let path = entry.map_err(|e| read_err(dir, e))?.path();
        if path.extension() != Some(OsStr::new("toml")) {
            continue;
        }
        // Following links: a loop or a dangling link is an error here.
        let meta = std::fs::metadata(&path).map_err(|e| read_err(&path, e))?;
        if !meta.is_file() {
            let kind = if meta.is_dir() {
                "a directory"
            } else {
                "not a regular file"
            };
            return Err(Error::invalid(
                "--scenes",
                format!(
                    "{} is {kind}; a .toml entry must be a scene file",
                    echo_path(&path)
                ),
            ));
        }
        paths.push(path);
    }
    paths.sort();
    if paths.is_empty() {
        return Err(Error::invalid(
            "--scenes",
            format!("{} holds no .toml scene files", echo_path(dir)),
        ));
    }
    let scenes = paths
        .iter()
        .map(|path| {
            // `Scene::load`'s errors start with the scene's path already.
            let scene = Scene::load(path).map_err(|e| Error::invalid("--scenes", e.to_string()))?;
            let name = path
                .file_stem()
                .map_or_else(|| "scene".into(), |s| s.to_string_lossy().into_owned());
            TestScene::from_scene(&name, &scene)
                .map_err(|e| Error::invalid("--scenes", format!("{}: {e}", echo_path(path))))
        })
        .collect::<Result<Vec<_>, Error>>()?;
    Ok((scenes, paths))
}
