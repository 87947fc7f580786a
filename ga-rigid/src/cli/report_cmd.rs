//! `report`: run the suite (with the user's scenes), write `results.csv`, one SVG per
//! scene and `index.html` into `--out DIR`, and print a short summary.

use std::ffi::OsStr;
use std::io::{IsTerminal as _, Write as _};
use std::path::{Path, PathBuf};

use super::ReportArgs;
use crate::error::Error;
use crate::report::{self, Size, TestScene};
use crate::scene::Scene;

/// Run the report as `args` say.
pub fn run(args: &ReportArgs) -> Result<(), Error> {
    let size = if args.quick { Size::Quick } else { Size::Full };
    let mut scenes = report::suite()?;
    if let Some(dir) = &args.scenes {
        scenes.extend(user_scenes(dir)?);
    }
    prepare_dir(&args.out)?;
    let total = report::job_count(&scenes, size);
    let mut report = if std::io::stderr().is_terminal() {
        let bar = indicatif::ProgressBar::new(total);
        bar.set_style(
            indicatif::ProgressStyle::with_template("{bar:40} {pos}/{len} {elapsed} {msg}")
                .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
        );
        let result = report::run(&scenes, size, &mut |scene, method| {
            bar.set_message(format!("{scene}: {method}"));
            bar.inc(1);
        });
        bar.finish_and_clear();
        result?
    } else {
        report::run(&scenes, size, &mut |_, _| {})?
    };
    let scale = report::Scale::of(size);
    report.long_runs = if std::io::stderr().is_terminal() {
        let bar = indicatif::ProgressBar::new(report::long_run_count());
        bar.set_style(
            indicatif::ProgressStyle::with_template("{bar:40} {pos}/{len} {elapsed} {msg}")
                .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
        );
        let result = report::long_runs(scale, &mut |method| {
            bar.set_message(format!("long runs: {method}"));
            bar.inc(1);
        });
        bar.finish_and_clear();
        result?
    } else {
        report::long_runs(scale, &mut |_| {})?
    };

    report.engine_runs = report::engine_runs(size, &mut |_| {})?;

    let names: Vec<String> = report
        .scenes
        .iter()
        .enumerate()
        .map(|(i, s)| report::svg_name(i, &s.name))
        .collect();
    for (scene, name) in report.scenes.iter().zip(&names) {
        write_file(&args.out, name, &report::svg(scene)?)?;
    }
    write_file(&args.out, "results.csv", &report::csv(&report))?;
    write_file(
        &args.out,
        "long_runs.csv",
        &report::long_runs_csv(&report.long_runs),
    )?;
    write_file(
        &args.out,
        "engine_runs.csv",
        &report::engine_runs_csv(&report.engine_runs),
    )?;
    write_file(&args.out, "index.html", &report::html(&report, &names))?;
    let mut summary = report::summary(&report);
    summary.push_str(&format!(
        "wrote {} (results.csv, long_runs.csv, engine_runs.csv, {} plots, index.html)\n",
        args.out.display(),
        names.len()
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

/// Make sure `dir` is a directory we can write into: create it (not its parents) if
/// missing, and refuse anything else that is already there.
fn prepare_dir(dir: &Path) -> Result<(), Error> {
    if dir.is_dir() {
        return Ok(());
    }
    if dir.exists() || dir.symlink_metadata().is_ok() {
        return Err(Error::invalid(
            "--out",
            format!("{} exists and is not a directory", dir.display()),
        ));
    }
    std::fs::create_dir(dir).map_err(|source| Error::Write {
        field: "--out".to_string(),
        path: dir.to_path_buf(),
        source,
    })
}

/// The `*.toml` files of `dir`, in name order, as scenes named after their files.
fn user_scenes(dir: &Path) -> Result<Vec<TestScene>, Error> {
    let read_err = |source| Error::Read {
        field: "--scenes".to_string(),
        path: dir.to_path_buf(),
        source,
    };
    let mut paths: Vec<PathBuf> = std::fs::read_dir(dir)
        .map_err(read_err)?
        .filter_map(|entry| Some(entry.ok()?.path()))
        .filter(|p| p.extension() == Some(OsStr::new("toml")) && p.is_file())
        .collect();
    paths.sort();
    if paths.is_empty() {
        return Err(Error::invalid(
            "--scenes",
            format!("{} holds no .toml scene files", dir.display()),
        ));
    }
    paths
        .iter()
        .map(|path| {
            let scene = Scene::load(path)
                .map_err(|e| Error::invalid("--scenes", format!("{}: {e}", path.display())))?;
            let name = path
                .file_stem()
                .map_or_else(|| "scene".into(), |s| s.to_string_lossy().into_owned());
            TestScene::from_scene(&name, &scene)
        })
        .collect()
}

/// Write `text` to `dir/name` through a temporary file in `dir` and a rename, so that a
/// reader never sees a half-written file.
fn write_file(dir: &Path, name: &str, text: &str) -> Result<(), Error> {
    let target = dir.join(name);
    let tmp = dir.join(format!(".{name}.tmp-{}", std::process::id()));
    let result = std::fs::write(&tmp, text).and_then(|()| std::fs::rename(&tmp, &target));
    if let Err(source) = result {
        // Best effort: the temporary file may not exist if the write failed early.
        let _ = std::fs::remove_file(&tmp);
        return Err(Error::Write {
            field: "--out".to_string(),
            path: target,
            source,
        });
    }
    Ok(())
}
