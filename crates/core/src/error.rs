//! Typed library errors; the command line (`run_command_line`) maps them to exit codes.

use std::fmt;
use std::path::PathBuf;

/// A malformed formula transcription.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub struct ParseError {
    /// Character offset into the text (`usize::MAX`: at its end, or nowhere in particular).
    pub position: usize,
    /// What is wrong.
    pub message: String,
}

impl fmt::Display for ParseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // a position only where there is one: the sentinel says "past the last character"
        match self.position {
            usize::MAX => write!(f, "at the end: {}", self.message),
            p => write!(f, "at character {p}: {}", self.message),
        }
    }
}

/// Where in an input file something is wrong.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct InputLocation {
    /// The file.
    pub file: PathBuf,
    /// 1-based line, when known.
    pub line: Option<u64>,
    /// 1-based column, when known.
    pub column: Option<u64>,
    /// The field (a dotted path such as `check.dof_count.examples[0].frames`).
    pub field: Option<String>,
}

impl InputLocation {
    /// A whole file: no line, column or field.
    pub fn file(path: &std::path::Path) -> InputLocation {
        InputLocation {
            file: path.to_path_buf(),
            line: None,
            column: None,
            field: None,
        }
    }
}

impl fmt::Display for InputLocation {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.file.display())?;
        if let Some(line) = self.line {
            write!(f, ":{line}")?;
            if let Some(col) = self.column {
                write!(f, ":{col}")?;
            }
        }
        if let Some(field) = &self.field {
            write!(f, ": field `{field}`")?;
        }
        Ok(())
    }
}

/// Every error the library reports.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// A file could not be read.
    #[error("{}: cannot read: {source}", path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
    /// A file or folder could not be written.
    #[error("{}: cannot write: {message}", path.display())]
    Write {
        /// The file or folder.
        path: PathBuf,
        /// The cause.
        message: String,
    },
    /// Standard output was closed by its reader (a pipe into `head`): not a failure.
    #[error("standard output closed")]
    ClosedOutput,
    /// A case or tracks file is malformed.
    #[error("{location}: {message}")]
    Input {
        /// Where.
        location: InputLocation,
        /// What is wrong.
        message: String,
    },
    /// Input that is well-formed but unusable (wrong counts, NaN, too few points).
    #[error("invalid input: {0}")]
    InvalidInput(String),
    /// A formula transcription does not parse.
    #[error("formula `{formula}`: {source}")]
    Formula {
        /// The text.
        formula: String,
        /// The cause.
        source: ParseError,
    },
    /// The paper's source disagrees with the transcription: the claims concerned were judged
    /// `inconclusive`, and these are the places (one per line).
    #[error(
        "the paper's source disagrees with the transcription; those claims are inconclusive:{0}"
    )]
    Unverified(String),
    /// A result was printed in full, but with warnings that it may be wrong (one per line).
    #[error(
        "the result was printed with {} warning(s): it may be wrong{}",
        .0.len(),
        .0.iter().map(|w| format!("\n  {w}")).collect::<String>()
    )]
    Warned(Vec<String>),
    /// A numerical method failed where it should not (reported, never a panic).
    #[error("numerical failure: {0}")]
    Numerical(String),
}

/// Library result type.
pub type Result<T, E = Error> = std::result::Result<T, E>;
