//! The one error type of the crate.
//!
//! Every message is a single line that starts with the field or parameter at fault and
//! then states the rule it broke, e.g. `body.moments: moments must be positive, got -1`.
//! Library constructors name their own parameter (`moments`, `mass`, `points[2]`); the
//! scene loader prefixes the section with [`Error::within`], so the same check reads
//! `body.shape.mass: ...` when it comes from a scene file, and a scene read from a path
//! names the file first ([`Error::in_file`]): `scenes/top.toml: body.shape.mass: ...`.

use std::path::{Path, PathBuf};

/// Everything that can go wrong in `ga-rigid`, from a bad scene file to a run beyond its
/// limits.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// A number is NaN or infinite.
    #[error("{field}: {what} must be finite, got {}", num(*value))]
    NotFinite {
        /// The field or parameter at fault.
        field: String,
        /// What the number is (`mass`, `moments`, `coordinates`).
        what: &'static str,
        /// The offending value.
        value: f64,
    },

    /// A number that must be strictly positive is zero or negative.
    #[error("{field}: {what} must be positive, got {}", num(*value))]
    NotPositive {
        /// The field or parameter at fault.
        field: String,
        /// What the number is (`mass`, `moments`, `radius`).
        what: &'static str,
        /// The offending value.
        value: f64,
    },

    /// Principal moments that no mass distribution can have: i_a + i_b < i_c.
    #[error(
        "{field}: moments must satisfy the triangle inequality i_a + i_b >= i_c, \
         but {} + {} < {}; a test body may set allow_unphysical = true in [body]",
        num_short(*a), num_short(*b), num_short(*c)
    )]
    TriangleInequality {
        /// The field or parameter at fault.
        field: String,
        /// The smaller of the two moments on the left.
        a: f64,
        /// The larger of the two moments on the left.
        b: f64,
        /// The moment that exceeds their sum.
        c: f64,
    },

    /// A rotor with every component zero, which cannot be normalised.
    #[error("{field}: the rotor is zero")]
    ZeroRotor {
        /// The field or parameter at fault.
        field: String,
    },

    /// Input that describes no rigid body with an invertible inertia (collinear points,
    /// a flat mesh, an empty list).
    #[error("{field}: degenerate input: {reason}")]
    Degenerate {
        /// The field or parameter at fault.
        field: String,
        /// Why the input is degenerate.
        reason: String,
    },

    /// A time (or other number) outside the interval it must lie in, such as a sample
    /// time outside the step or run it is asked of.
    #[error(
        "{field}: {} lies outside the interval from {} to {}",
        num(*value), num(*start), num(*end)
    )]
    OutOfRange {
        /// The field or parameter at fault.
        field: String,
        /// The offending value.
        value: f64,
        /// One end of the interval (its start, which may be the larger end).
        start: f64,
        /// The other end.
        end: f64,
    },
    /// Any other broken rule: the message after the field states it.
    #[error("{field}: {rule}")]
    Invalid {
        /// The field or parameter at fault.
        field: String,
        /// The rule that was broken.
        rule: String,
    },

    /// A triangle mesh that is not a closed, consistently oriented surface.
    #[error("{field}: the mesh is not closed: {reason}")]
    OpenMesh {
        /// The field or parameter at fault.
        field: String,
        /// The first edge found that breaks the rule.
        reason: String,
    },

    /// A malformed line in a Wavefront OBJ file.
    #[error("{field}: {}:{line}: {message}", echo_path(path))]
    Obj {
        /// The field or parameter that named the file.
        field: String,
        /// The OBJ file.
        path: PathBuf,
        /// The 1-based line number.
        line: usize,
        /// What is wrong with the line.
        message: String,
    },

    /// A TOML syntax error (or a duplicated key), which has a position but no field yet.
    #[error("{}:{line}:{column}: {message}", echo_path(path))]
    Toml {
        /// The scene file.
        path: PathBuf,
        /// The 1-based line number.
        line: usize,
        /// The 1-based column number.
        column: usize,
        /// The parser's message, joined onto one line.
        message: String,
    },

    /// An input file that could not be read.
    #[error("{field}: cannot read {}: {source}", echo_path(path))]
    Read {
        /// The field or argument that named the file.
        field: String,
        /// The file.
        path: PathBuf,
        /// The operating system's reason.
        source: std::io::Error,
    },

    /// Any of the other errors, found in the scene file `path`: the message is the file's
    /// name and then the error's own (`scenes/top.toml: body.moments: ...`).
    #[error("{}: {source}", echo_path(path))]
    InFile {
        /// The scene file.
        path: PathBuf,
        /// What is wrong in it (never another `InFile`).
        source: Box<Error>,
    },

    /// A feature whose implementation has not landed yet.
    #[error("{what}: not available yet")]
    NotAvailable {
        /// The command or method that is missing.
        what: String,
    },
}

impl Error {
    /// Shorthand for [`Error::Invalid`].
    pub fn invalid(field: impl Into<String>, rule: impl Into<String>) -> Self {
        Error::Invalid {
            field: field.into(),
            rule: rule.into(),
        }
    }

    /// Shorthand for [`Error::Degenerate`].
    pub fn degenerate(field: impl Into<String>, reason: impl Into<String>) -> Self {
        Error::Degenerate {
            field: field.into(),
            reason: reason.into(),
        }
    }

    /// Prefix the field with the section it was read from: `mass` within `body.shape`
    /// becomes `body.shape.mass`; `points[2]` within `body` becomes `body.points[2]`.
    #[must_use]
    pub fn within(mut self, prefix: &str) -> Self {
        if let Some(field) = self.field_mut() {
            *field = if field.is_empty() {
                prefix.to_string()
            } else if field.starts_with('[') {
                format!("{prefix}{field}")
            } else {
                format!("{prefix}.{field}")
            };
        }
        self
    }

    /// Replace the field outright, for checks whose own parameter name means nothing to
    /// the user (a file read on behalf of `body.mesh`).
    #[must_use]
    pub fn at(mut self, field: &str) -> Self {
        if let Some(f) = self.field_mut() {
            *f = field.to_string();
        }
        self
    }

    /// The error as found in the scene file `path`, so that its message names the file
    /// first. Errors that name the file already (a TOML syntax error's position, a failed
    /// read of it, an error already in a file) are returned as they are; the field and the
    /// kind stay those of the error inside ([`Error::field`], [`Error::in_file_source`]).
    #[must_use]
    pub fn in_file(self, path: &Path) -> Self {
        match self {
            Error::Toml { .. } | Error::InFile { .. } => self,
            Error::Read { path: ref read, .. } if read == path => self,
            other => Error::InFile {
                path: path.to_path_buf(),
                source: Box::new(other),
            },
        }
    }

    /// The error without the file it was found in: the inside of an [`Error::InFile`],
    /// otherwise the error itself, for a caller that matches on the kind.
    #[must_use]
    pub fn in_file_source(&self) -> &Error {
        match self {
            Error::InFile { source, .. } => source,
            other => other,
        }
    }

    /// The error in a front end's words: each whole word of the field and the message
    /// that is a library parameter in `names` (`dt`, `max_steps`) becomes the front end's
    /// name for it (`--dt`, `--max-steps`), so that a command renames once, at its edge.
    /// Only the errors of numbers and rules are renamed; those that repeat user text (a
    /// path, a file's line) are returned as they are.
    #[must_use]
    pub fn renamed(self, names: &[(&str, &str)]) -> Self {
        if let Error::InFile { path, source } = self {
            return Error::InFile {
                path,
                source: Box::new(source.renamed(names)),
            };
        }
        match &self {
            Error::NotFinite { field, .. }
            | Error::NotPositive { field, .. }
            | Error::OutOfRange { field, .. }
            | Error::Invalid { field, .. } => {
                let message = self.to_string();
                let rule = message
                    .strip_prefix(field.as_str())
                    .and_then(|m| m.strip_prefix(": "))
                    .unwrap_or(&message);
                Error::Invalid {
                    field: rename_words(field, names),
                    rule: rename_words(rule, names),
                }
            }
            _ => self,
        }
    }

    /// The field or parameter the error names, if it names one.
    pub fn field(&self) -> Option<&str> {
        match self {
            Error::NotFinite { field, .. }
            | Error::NotPositive { field, .. }
            | Error::TriangleInequality { field, .. }
            | Error::ZeroRotor { field }
            | Error::Degenerate { field, .. }
            | Error::OutOfRange { field, .. }
            | Error::Invalid { field, .. }
            | Error::OpenMesh { field, .. }
            | Error::Obj { field, .. }
            | Error::Read { field, .. } => Some(field),
            Error::InFile { source, .. } => source.field(),
            Error::Toml { .. } | Error::NotAvailable { .. } => None,
        }
    }

    fn field_mut(&mut self) -> Option<&mut String> {
        match self {
            Error::NotFinite { field, .. }
            | Error::NotPositive { field, .. }
            | Error::TriangleInequality { field, .. }
            | Error::ZeroRotor { field }
            | Error::Degenerate { field, .. }
            | Error::OutOfRange { field, .. }
            | Error::Invalid { field, .. }
            | Error::OpenMesh { field, .. }
            | Error::Obj { field, .. }
            | Error::Read { field, .. } => Some(field),
            Error::InFile { source, .. } => source.field_mut(),
            Error::Toml { .. } | Error::NotAvailable { .. } => None,
        }
    }
}

/// `text` with each whole word (a run of letters, digits and `_`) found in the first
/// column of `names` replaced by the second.
fn rename_words(text: &str, names: &[(&str, &str)]) -> String {
    let mut out = String::with_capacity(text.len());
    let mut word = String::new();
    let flush = |word: &mut String, out: &mut String| {
        let renamed = names.iter().find(|(from, _)| *from == word.as_str());
        out.push_str(renamed.map_or(word.as_str(), |(_, to)| to));
        word.clear();
    };
    for c in text.chars() {
        if c.is_ascii_alphanumeric() || c == '_' {
            word.push(c);
        } else {
            flush(&mut word, &mut out);
            out.push(c);
        }
    }
    flush(&mut word, &mut out);
    out
}

/// A number for a message: plain where that is short (`0.25`, `-3`, `1500`), scientific
/// otherwise (`1e-300`, not three hundred zeros), so that a message stays one short line.
#[must_use]
pub fn num(x: f64) -> String {
    let a = x.abs();
    if x == 0.0 || !x.is_finite() || (1e-4..1e16).contains(&a) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// [`num`], to six significant digits when it would be longer than twelve characters: for
/// messages that hold several numbers and must stay under 200 characters.
#[must_use]
pub fn num_short(x: f64) -> String {
    let full = num(x);
    if full.len() > 12 {
        format!("{x:.5e}")
    } else {
        full
    }
}

/// The most characters of user text (a string value, a path) a message repeats.
pub const ECHO_LIMIT: usize = 60;

/// User text for a message, cut to [`ECHO_LIMIT`] characters with its length stated, so
/// that a 100,000-character value does not become a 100,000-character message; line
/// breaks are shown as `\n` so that the message stays one line.
#[must_use]
pub fn echo(text: &str) -> String {
    let count = text.chars().count();
    let escape = |s: &str| s.replace('\n', "\\n").replace('\r', "\\r");
    if count <= ECHO_LIMIT {
        escape(text)
    } else {
        let head: String = text.chars().take(ECHO_LIMIT - 20).collect();
        format!("{}... ({count} characters)", escape(&head))
    }
}

/// A path for a message, cut like [`echo`] but keeping its end, which holds the file's
/// name: `.../scenes/top.toml (312 characters)`.
#[must_use]
pub fn echo_path(path: &std::path::Path) -> String {
    let text = path.display().to_string();
    let count = text.chars().count();
    if count <= ECHO_LIMIT {
        echo(&text)
    } else {
        let tail: String = text.chars().skip(count - (ECHO_LIMIT - 20)).collect();
        format!("...{} ({count} characters)", echo(&tail))
    }
}

/// Check that a number is finite.
pub fn finite(field: &str, what: &'static str, value: f64) -> Result<f64, Error> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::NotFinite {
            field: field.to_string(),
            what,
            value,
        })
    }
}

/// Check that a number is finite and strictly positive, and not subnormal: a subnormal
/// mass, moment, density or step has lost its precision already and turns into zero or
/// infinity in the first product or quotient.
pub fn positive(field: &str, what: &'static str, value: f64) -> Result<f64, Error> {
    finite(field, what, value)?;
    if value <= 0.0 {
        return Err(Error::NotPositive {
            field: field.to_string(),
            what,
            value,
        });
    }
    if value < f64::MIN_POSITIVE {
        return Err(Error::invalid(
            field,
            format!(
                "{what} must be at least {:e} (a normal number), got {value:e}",
                f64::MIN_POSITIVE
            ),
        ));
    }
    Ok(value)
}

/// Check that every component of a vector is finite.
pub(crate) fn finite3(field: &str, what: &'static str, v: [f64; 3]) -> Result<[f64; 3], Error> {
    for x in v {
        finite(field, what, x)?;
    }
    Ok(v)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn renamed_replaces_whole_words_in_field_and_message_only() {
        let names = [("dt", "--dt"), ("max_steps", "--max-steps")];
        let e =
            Error::invalid("dt", "a dt of 1 is too big for dtx; raise max_steps").renamed(&names);
        assert_eq!(
            e.to_string(),
            "--dt: a --dt of 1 is too big for dtx; raise --max-steps"
        );
        let e = positive("dt", "the step", -1.0)
            .unwrap_err()
            .renamed(&names);
        assert_eq!(e.to_string(), "--dt: the step must be positive, got -1");
        let read = Error::Read {
            field: "dt".into(),
            path: "dt/max_steps".into(),
            source: std::io::Error::other("x"),
        };
        assert!(read.renamed(&names).to_string().contains("dt/max_steps"));
    }

    #[test]
    fn within_prefixes_plain_and_indexed_fields() {
        let e = positive("moments", "moments", -1.0)
            .unwrap_err()
            .within("body");
        assert_eq!(
            e.to_string(),
            "body.moments: moments must be positive, got -1"
        );
        let e = Error::invalid("[2]", "x").within("body.points");
        assert_eq!(e.to_string(), "body.points[2]: x");
    }
}
