//! Where the outputs may go, and how they are written together.
//!
//! The rule: output goes only to a regular file, never through it to something else, and
//! never onto an input or onto another output of the same command ([`OutputPlan`]).
//!
//! - A missing path, or an existing regular file, is written by creating a fresh
//!   temporary file beside it (`O_EXCL`, so a planted file or link at the temporary name
//!   is never followed) and renaming it over the target: a failure leaves no partial file.
//! - A symbolic link is followed (all the way, `realpath`-style) and its final target is
//!   written the same way, in the target's own directory: the link stays a link, and the
//!   file it points to is replaced. A dangling link is refused, since writing it would
//!   create a file somewhere the user did not name.
//! - Anything else (a directory, a FIFO, a socket, a character or block device) is
//!   refused with exit status 2 before any work is done, and checked again just before
//!   the rename. Renaming onto such a path would replace the node itself (run as root,
//!   `--out /dev/null` would turn the device into a regular file); streaming into it
//!   instead would make the command's success depend on a reader at the other end. To
//!   write into a pipe or device, use standard output and the shell's redirection.
//! - A command's outputs (`simulate`'s CSV, record and plot; every file of the report)
//!   are all written to their temporary files before any is renamed, so a failed write
//!   leaves every existing file as it was.

use std::ffi::OsString;
use std::fs::{File, OpenOptions};
use std::io::Write as _;
use std::path::{Path, PathBuf};

use ga_rigid::error::{echo_path, Error as LibError};

use crate::error::Error;

/// The file `emit` will replace: `out` itself, or the final target of a symbolic link.
///
/// Errors (exit status 2, before any work): `out` names a directory, FIFO, socket or
/// device, directly or through a link; the link dangles; the directory does not exist.
pub fn output_target(field: &str, out: &Path) -> Result<PathBuf, Error> {
    checked_target(field, out, field == "--out")
}

/// [`output_target`]; `stdout_hint` adds, to the refusal of a pipe or device, that
/// standard output reaches it (true only for `simulate --out`, the one output that has
/// standard output as its alternative).
fn checked_target(field: &str, out: &Path, stdout_hint: bool) -> Result<PathBuf, Error> {
    let meta = match std::fs::symlink_metadata(out) {
        Ok(meta) => meta,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            let dir = parent_dir(out);
            if !dir.is_dir() {
                return Err(Error::invalid(
                    field,
                    format!("the directory {} does not exist", echo_path(&dir)),
                ));
            }
            return Ok(out.to_path_buf());
        }
        Err(source) => {
            return Err(LibError::Read {
                field: field.to_string(),
                path: out.to_path_buf(),
                source,
            }
            .into())
        }
    };
    if meta.file_type().is_symlink() {
        let target = std::fs::canonicalize(out).map_err(|_| {
            Error::invalid(
                field,
                format!(
                    "{} is a symbolic link to a missing file; give the file's own path",
                    echo_path(out)
                ),
            )
        })?;
        let meta = std::fs::symlink_metadata(&target).map_err(|source| LibError::Read {
            field: field.to_string(),
            path: target.clone(),
            source,
        })?;
        if !meta.file_type().is_file() {
            return Err(not_a_file(field, out, &meta.file_type(), stdout_hint));
        }
        return Ok(target);
    }
    if !meta.file_type().is_file() {
        return Err(not_a_file(field, out, &meta.file_type(), stdout_hint));
    }
    Ok(out.to_path_buf())
}

fn not_a_file(field: &str, out: &Path, kind: &std::fs::FileType, stdout_hint: bool) -> Error {
    let hint = if stdout_hint && !kind.is_dir() {
        "; write to standard output to reach it"
    } else {
        ""
    };
    Error::invalid(
        field,
        format!(
            "{} is {}, not a regular file{hint}",
            echo_path(out),
            kind_name(kind)
        ),
    )
}

/// A file type in words, for messages.
fn kind_name(kind: &std::fs::FileType) -> &'static str {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt as _;
        if kind.is_fifo() {
            return "a FIFO";
        }
        if kind.is_socket() {
            return "a socket";
        }
        if kind.is_char_device() || kind.is_block_device() {
            return "a device";
        }
    }
    if kind.is_dir() {
        "a directory"
    } else {
        "a special file"
    }
}

/// The directory a file path lives in (`.` for a bare file name).
pub fn parent_dir(path: &Path) -> PathBuf {
    match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    }
}

/// The outputs of one command, checked together before any work and published together
/// at the end: every file is first written to a temporary file beside its target, and only
/// when all of them are written are they renamed into place. A failed run therefore
/// replaces nothing and deletes nothing, and no output may name an input or another output.
#[derive(Debug, Default)]
pub struct OutputPlan {
    /// The inputs no output may replace: (field, canonical path).
    inputs: Vec<(String, PathBuf)>,
    /// The outputs, in the order they were added.
    outputs: Vec<Planned>,
    /// Whether `--out` could have been standard output (see [`output_target`]).
    stdout_hint: bool,
}

/// One output of an [`OutputPlan`].
#[derive(Debug)]
struct Planned {
    /// The argument that named it (`--out`, `--plot`).
    field: String,
    /// The path as the user gave it, for messages.
    given: PathBuf,
    /// The file that will be replaced (a link's final target).
    target: PathBuf,
    /// `target` with its directory made canonical: two outputs with the same identity are
    /// the same file however they were spelt.
    identity: PathBuf,
}

/// Where a path leads once its directory is made canonical (the file itself too when it
/// exists), so that `a.csv`, `./a.csv` and a link to it compare equal.
fn identity(path: &Path) -> PathBuf {
    if let Ok(real) = std::fs::canonicalize(path) {
        return real;
    }
    let dir = std::fs::canonicalize(parent_dir(path)).unwrap_or_else(|_| parent_dir(path));
    match path.file_name() {
        Some(name) => dir.join(name),
        None => dir,
    }
}

impl OutputPlan {
    /// An empty plan.
    #[must_use]
    pub fn new() -> Self {
        OutputPlan::default()
    }

    /// A plan whose `--out` could have been standard output: the refusal of a pipe or
    /// device says so.
    #[must_use]
    pub fn with_stdout_alternative() -> Self {
        OutputPlan {
            stdout_hint: true,
            ..OutputPlan::default()
        }
    }

    fn target(&self, field: &str, path: &Path) -> Result<PathBuf, Error> {
        checked_target(field, path, self.stdout_hint && field == "--out")
    }

    /// Declare an input file (`field` names it, e.g. `SCENE` or `body.mesh`): no output may
    /// be the same file. An input that cannot be resolved is left to its reader to report.
    pub fn input(&mut self, field: &str, path: &Path) -> Result<(), Error> {
        let Ok(real) = std::fs::canonicalize(path) else {
            return Ok(());
        };
        if let Some(out) = self.outputs.iter().find(|o| o.identity == real) {
            return Err(names_input(&out.field, &out.given, field));
        }
        self.inputs.push((field.to_string(), real));
        Ok(())
    }

    /// Add an output: checked now (see [`output_target`]), and against the inputs and the
    /// other outputs. Errors have exit status 2 and name `field`.
    pub fn add(&mut self, field: &str, path: &Path) -> Result<(), Error> {
        let target = self.target(field, path)?;
        let id = identity(&target);
        if let Some((input, _)) = self.inputs.iter().find(|(_, real)| *real == id) {
            return Err(names_input(field, path, input));
        }
        if let Some(other) = self.outputs.iter().find(|o| o.identity == id) {
            return Err(Error::invalid(
                field,
                format!(
                    "{} is also where {} writes; give each output its own path",
                    echo_path(path),
                    other.field
                ),
            ));
        }
        self.outputs.push(Planned {
            field: field.to_string(),
            given: path.to_path_buf(),
            target,
            identity: id,
        });
        Ok(())
    }

    /// Write every output's text (`texts[k]` for the `k`-th output added) to its temporary
    /// file. Nothing is replaced yet: [`Staged::publish`] renames them all, and dropping the
    /// [`Staged`] instead removes them.
    pub fn stage(&self, texts: &[&str]) -> Result<Staged, Error> {
        debug_assert_eq!(texts.len(), self.outputs.len(), "one text per output");
        let mut staged = Staged {
            files: Vec::with_capacity(self.outputs.len()),
        };
        for (planned, text) in self.outputs.iter().zip(texts) {
            let write_err = |source| Error::Write {
                field: planned.field.clone(),
                path: planned.given.clone(),
                source,
            };
            let name = planned
                .target
                .file_name()
                .map_or_else(|| OsString::from("out"), std::ffi::OsStr::to_os_string);
            let (tmp, mut file) =
                create_temporary(&parent_dir(&planned.target), &name).map_err(write_err)?;
            // Registered before writing, so that a failed write is cleaned up too.
            staged.files.push(StagedFile {
                field: planned.field.clone(),
                given: planned.given.clone(),
                target: planned.target.clone(),
                tmp,
            });
            file.write_all(text.as_bytes())
                .and_then(|()| file.sync_all())
                .map_err(write_err)?;
        }
        Ok(staged)
    }

    /// [`OutputPlan::stage`] then [`Staged::publish`].
    pub fn write_all(&self, texts: &[&str]) -> Result<(), Error> {
        self.stage(texts)?.publish()
    }
}

fn names_input(field: &str, path: &Path, input: &str) -> Error {
    Error::invalid(
        field,
        format!(
            "{} is {input}; writing it would replace it: give another path",
            echo_path(path)
        ),
    )
}

/// Outputs written to their temporary files and not yet renamed into place.
#[derive(Debug)]
pub struct Staged {
    files: Vec<StagedFile>,
}

#[derive(Debug)]
struct StagedFile {
    field: String,
    given: PathBuf,
    target: PathBuf,
    tmp: PathBuf,
}

impl Staged {
    /// Rename every temporary file over its target, each target checked again just
    /// before (it must still be the regular file, or the absence, it was when checked).
    pub fn publish(mut self) -> Result<(), Error> {
        for file in &self.files {
            match output_target(&file.field, &file.given) {
                Ok(again) if again == file.target => {}
                Ok(_) => {
                    return Err(Error::invalid(
                        &file.field,
                        format!(
                            "{} changed while the output was written",
                            echo_path(&file.given)
                        ),
                    ))
                }
                Err(e) => return Err(e),
            }
        }
        let files = std::mem::take(&mut self.files);
        let mut result = Ok(());
        for file in &files {
            if result.is_ok() {
                result = std::fs::rename(&file.tmp, &file.target).map_err(|source| Error::Write {
                    field: file.field.clone(),
                    path: file.given.clone(),
                    source,
                });
            }
            if result.is_err() {
                // Best effort: this temporary file was not renamed, so it is still ours.
                let _ = std::fs::remove_file(&file.tmp);
            }
        }
        result
    }
}

impl Drop for Staged {
    fn drop(&mut self) {
        for file in &self.files {
            // Best effort: nothing was published, and the temporaries are ours.
            let _ = std::fs::remove_file(&file.tmp);
        }
    }
}

/// A new file `.NAME.tmp-PID-K` in `dir`, created exclusively: an existing file or link
/// of that name is never opened, the next `K` is tried instead.
fn create_temporary(dir: &Path, name: &OsString) -> std::io::Result<(PathBuf, File)> {
    let mut last = None;
    for k in 0..16 {
        let mut tmp_name = OsString::from(".");
        tmp_name.push(name);
        tmp_name.push(format!(".tmp-{}-{k}", std::process::id()));
        let tmp = dir.join(tmp_name);
        match OpenOptions::new().write(true).create_new(true).open(&tmp) {
            Ok(file) => return Ok((tmp, file)),
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => last = Some(e),
            Err(e) => return Err(e),
        }
    }
    Err(last.unwrap_or_else(|| std::io::Error::other("no free temporary name")))
}
