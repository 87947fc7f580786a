//! The command's error: the library's (bad input, a run beyond its limits), or an output
//! that could not be written, which only the command has.

use std::path::PathBuf;

use ga_rigid::error::echo_path;

/// Everything that can stop the command.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// Bad input or a run beyond its limits, as the library words it.
    #[error(transparent)]
    Library(#[from] ga_rigid::error::Error),

    /// An output file or stream that could not be written.
    #[error("{field}: cannot write {}: {source}", echo_path(path))]
    Write {
        /// The argument that named the output.
        field: String,
        /// The file (`-` for standard output).
        path: PathBuf,
        /// The operating system's reason.
        source: std::io::Error,
    },
}

impl Error {
    /// The library's [`ga_rigid::error::Error::invalid`]: `field` broke `rule`.
    pub fn invalid(field: impl Into<String>, rule: impl Into<String>) -> Self {
        Error::Library(ga_rigid::error::Error::invalid(field, rule))
    }
}
