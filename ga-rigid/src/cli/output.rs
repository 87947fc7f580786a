//! Where `--out` may write, and the atomic write itself.
//!
//! The rule: output goes only to a regular file, never through it to something else.
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

use std::ffi::OsString;
use std::fs::{File, OpenOptions};
use std::io::Write as _;
use std::path::{Path, PathBuf};

use crate::error::Error;

/// The file `emit` will replace: `out` itself, or the final target of a symbolic link.
///
/// Errors (exit status 2, before any work): `out` names a directory, FIFO, socket or
/// device, directly or through a link; the link dangles; the directory does not exist.
pub fn output_target(field: &str, out: &Path) -> Result<PathBuf, Error> {
    let meta = match std::fs::symlink_metadata(out) {
        Ok(meta) => meta,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            let dir = parent_dir(out);
            if !dir.is_dir() {
                return Err(Error::invalid(
                    field,
                    format!("the directory {} does not exist", dir.display()),
                ));
            }
            return Ok(out.to_path_buf());
        }
        Err(source) => {
            return Err(Error::Read {
                field: field.to_string(),
                path: out.to_path_buf(),
                source,
            })
        }
    };
    if meta.file_type().is_symlink() {
        let target = std::fs::canonicalize(out).map_err(|_| {
            Error::invalid(
                field,
                format!(
                    "{} is a symbolic link to a missing file; give the file's own path",
                    out.display()
                ),
            )
        })?;
        let meta = std::fs::symlink_metadata(&target).map_err(|source| Error::Read {
            field: field.to_string(),
            path: target.clone(),
            source,
        })?;
        if !meta.file_type().is_file() {
            return Err(not_a_file(field, out, &meta.file_type()));
        }
        return Ok(target);
    }
    if !meta.file_type().is_file() {
        return Err(not_a_file(field, out, &meta.file_type()));
    }
    Ok(out.to_path_buf())
}

fn not_a_file(field: &str, out: &Path, kind: &std::fs::FileType) -> Error {
    Error::invalid(
        field,
        format!(
            "{} is {}, not a regular file; write to standard output to reach it",
            out.display(),
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

/// Write `text` to `out` by temporary file and rename (see the module documentation),
/// re-checking just before the rename that the target is still a regular file or absent.
pub fn write_atomically(field: &str, out: &Path, text: &str) -> Result<(), Error> {
    let target = output_target(field, out)?;
    let name = target
        .file_name()
        .map_or_else(|| OsString::from("out"), std::ffi::OsStr::to_os_string);
    let write_err = |source| Error::Write {
        field: field.to_string(),
        path: out.to_path_buf(),
        source,
    };
    let dir = parent_dir(&target);
    let (tmp, mut file) = create_temporary(&dir, &name).map_err(write_err)?;
    let written = file
        .write_all(text.as_bytes())
        .and_then(|()| file.sync_all());
    drop(file);
    let result = match written {
        Ok(()) => match output_target(field, out) {
            Ok(again) if again == target => std::fs::rename(&tmp, &target).map_err(write_err),
            Ok(_) => Err(Error::invalid(
                field,
                format!("{} changed while the output was written", out.display()),
            )),
            Err(e) => Err(e),
        },
        Err(source) => Err(write_err(source)),
    };
    if result.is_err() {
        // Best effort: the rename did not happen, so the temporary file is still ours.
        let _ = std::fs::remove_file(&tmp);
    }
    result
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
