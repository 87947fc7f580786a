//! Reading input files with a size limit, and only regular files: a FIFO or device
//! (`/dev/zero`, `/dev/urandom`) would otherwise be read until memory runs out, and
//! opening a FIFO blocks until a writer appears, so the type is checked before opening.

use std::io::Read as _;
use std::path::Path;

use crate::error::{echo_path, Error};

/// The text of the regular file at `path` (a symbolic link is followed), if it is at most
/// `limit` bytes; errors name `field`.
pub(crate) fn read_text(field: &str, path: &Path, limit: u64) -> Result<String, Error> {
    let read_err = |source| Error::Read {
        field: field.to_string(),
        path: path.to_path_buf(),
        source,
    };
    let meta = std::fs::metadata(path).map_err(read_err)?;
    if !meta.is_file() {
        return Err(Error::invalid(
            field,
            format!(
                "{} is not a regular file; only regular files are read",
                echo_path(path)
            ),
        ));
    }
    let too_big = |size: u64| {
        Error::invalid(
            field,
            format!(
                "{} is {size} bytes, more than the limit of {limit} bytes",
                echo_path(path)
            ),
        )
    };
    if meta.len() > limit {
        return Err(too_big(meta.len()));
    }
    let file = std::fs::File::open(path).map_err(read_err)?;
    let mut bytes = Vec::new();
    // One byte past the limit tells a file that grew after the check from one that fits.
    file.take(limit + 1)
        .read_to_end(&mut bytes)
        .map_err(read_err)?;
    if bytes.len() as u64 > limit {
        return Err(too_big(bytes.len() as u64));
    }
    String::from_utf8(bytes)
        .map_err(|_| Error::invalid(field, format!("{} is not UTF-8 text", echo_path(path))))
}

/// The regular file at `path` (a symbolic link is followed), opened, if it is at most
/// `limit` bytes now; the caller reads at most `limit + 1` bytes of it to notice growth.
pub(crate) fn open_regular(field: &str, path: &Path, limit: u64) -> Result<std::fs::File, Error> {
    let read_err = |source| Error::Read {
        field: field.to_string(),
        path: path.to_path_buf(),
        source,
    };
    let meta = std::fs::metadata(path).map_err(read_err)?;
    if !meta.is_file() {
        return Err(Error::invalid(
            field,
            format!(
                "{} is not a regular file; only regular files are read",
                echo_path(path)
            ),
        ));
    }
    if meta.len() > limit {
        return Err(Error::invalid(
            field,
            format!(
                "{} is {} bytes, more than the limit of {limit} bytes",
                echo_path(path),
                meta.len()
            ),
        ));
    }
    std::fs::File::open(path).map_err(read_err)
}
