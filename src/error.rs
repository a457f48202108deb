//! The failures a command can end with, and the exit code of each (docs/contracts.md).

use crate::problem::{Problems, one_line};
use std::fmt;

/// Why a command did not succeed.
#[derive(Debug)]
pub enum Error {
    /// Bad input in one or more sources, every problem listed (exit 2).
    Input(Vec<Problems>),
    /// A bad command-line value that is not tied to a JSON path (exit 2).
    Usage(String),
    /// Reading or writing a file failed (exit 2).
    Io {
        /// The file or stream.
        path: String,
        /// The underlying error.
        source: std::io::Error,
    },
    /// A numerical routine did not converge (exit 2).
    Numerics(String),
    /// The run worked but a check failed its tolerance (exit 1); the report is already printed.
    CheckFailed(String),
}

impl Error {
    /// The process exit code: 1 for a failed check, 2 for everything else.
    pub fn exit_code(&self) -> u8 {
        match self {
            Error::CheckFailed(_) => 1,
            _ => 2,
        }
    }

    /// Input problems from a single source.
    pub fn input(problems: Problems) -> Error {
        Error::Input(vec![problems])
    }

    /// The error named by the option `flag` it came through (`--theta: notes.txt: No such file
    /// or directory`): a read of `@FILE` says which option named the file.
    pub fn for_option(self, flag: &str) -> Error {
        match self {
            Error::Io { path, source } => Error::Io {
                path: format!("{flag}: {path}"),
                source,
            },
            other => other,
        }
    }

    /// An I/O error on `path`.
    pub fn io(path: impl Into<String>, source: std::io::Error) -> Error {
        Error::Io {
            path: path.into(),
            source,
        }
    }
}

impl fmt::Display for Error {
    /// One `error: …` line per problem.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Input(all) => {
                let lines: Vec<String> = all.iter().map(ToString::to_string).collect();
                f.write_str(&lines.join("\n"))
            }
            Error::Usage(message) | Error::Numerics(message) => {
                write!(f, "error: {}", one_line(message))
            }
            Error::Io { path, source } => write!(
                f,
                "error: {}: {}",
                one_line(path),
                one_line(&source.to_string())
            ),
            Error::CheckFailed(message) => write!(f, "{message}"),
        }
    }
}

impl std::error::Error for Error {}

/// Result of a command.
pub type Result<T> = std::result::Result<T, Error>;
