//! Errors that say what was wrong, what is allowed, and where: the line and column of the trace,
//! a command-line option, or the command itself.

use std::fmt;

/// The longest part of a cell that a message shows, in characters; a longer cell is cut there
/// and ends with `…`.
pub const SHOWN_CHARS: usize = 60;

/// Where a problem is.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Location {
    /// Not tied to the trace: an unknown block, a bad `--type`, a file that cannot be opened.
    Command,
    /// A command-line option such as `--tv` (without the dashes).
    Option(&'static str),
    /// A whole line of the trace (1-based; the header is the first line that is not blank or a
    /// comment).
    Line(u64),
    /// A cell: 1-based line, 1-based column and the column's name as the header writes it.
    Cell {
        /// The line, 1-based.
        line: u64,
        /// The column (field number), 1-based.
        column: usize,
        /// The column's name as written in the header (`field N` while the header is read).
        name: String,
    },
}

/// Bad input: what was wrong and what is allowed, and where.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TraceError {
    /// Where the problem is.
    pub location: Location,
    /// What was wrong and what is allowed.
    pub message: String,
}

impl TraceError {
    /// An error at `location`.
    pub fn new(location: Location, message: impl Into<String>) -> TraceError {
        TraceError {
            location,
            message: message.into(),
        }
    }

    /// An error in the cell at `line`, `column` (1-based) called `name`.
    pub fn cell(line: u64, column: usize, name: &str, message: impl Into<String>) -> TraceError {
        TraceError::new(
            Location::Cell {
                line,
                column,
                name: show(name.as_bytes()),
            },
            message,
        )
    }
}

impl fmt::Display for TraceError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.location {
            Location::Command => write!(f, "{}", self.message),
            Location::Option(o) => write!(f, "option --{o}: {}", self.message),
            Location::Line(l) => write!(f, "line {l}: {}", self.message),
            Location::Cell { line, column, name } => {
                write!(f, "line {line}, column {column} ({name}): {}", self.message)
            }
        }
    }
}

impl std::error::Error for TraceError {}

/// A cell's text as a message shows it: invalid UTF-8 replaced by `\u{FFFD}`, control
/// characters escaped, at most [`SHOWN_CHARS`] characters and then `…`.
///
/// ```
/// use plc_timers_trace::error::SHOWN_CHARS;
/// use plc_timers_trace::show;
///
/// assert_eq!(show(b"T#5\xFFs"), "T#5\u{FFFD}s");
/// let long = show("x".repeat(1_000).as_bytes());
/// assert_eq!(long, format!("{}…", "x".repeat(SHOWN_CHARS)));
/// ```
pub fn show(bytes: &[u8]) -> String {
    // Never decode more than a small prefix: a 10 MB cell must not make a 10 MB message. A
    // character takes at most 4 bytes (and the lossy decoding turns a cut one into one
    // replacement character), so a prefix of this length holds at least SHOWN_CHARS + 1
    // characters whenever it is shorter than the cell: the loop below then always stops at the
    // limit and adds the `…`.
    let prefix = &bytes[..bytes.len().min(SHOWN_CHARS * 4 + 4)];
    let text = String::from_utf8_lossy(prefix);
    let mut out = String::new();
    for (chars, c) in text.chars().enumerate() {
        if chars == SHOWN_CHARS {
            out.push('…');
            return out;
        }
        if c.is_control() {
            out.extend(c.escape_default());
        } else {
            out.push(c);
        }
    }
    out
}

/// An error of a command that reads a trace: bad input, or the output could not be written.
#[derive(Debug)]
pub enum Error {
    /// The trace or the options are bad input.
    Input(TraceError),
    /// Writing the output failed (a closed pipe, a full disk).
    Output(std::io::Error),
}

impl From<Box<TraceError>> for TraceError {
    fn from(e: Box<TraceError>) -> TraceError {
        *e
    }
}

impl From<Box<TraceError>> for Error {
    fn from(e: Box<TraceError>) -> Error {
        Error::Input(*e)
    }
}

impl From<TraceError> for Error {
    fn from(e: TraceError) -> Error {
        Error::Input(e)
    }
}

impl From<std::io::Error> for Error {
    fn from(e: std::io::Error) -> Error {
        Error::Output(e)
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Input(e) => e.fmt(f),
            Error::Output(e) => write!(f, "cannot write the output: {e}"),
        }
    }
}

impl std::error::Error for Error {}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn show_cuts_long_cells_and_escapes_controls() {
        assert_eq!(show(b"abc"), "abc");
        let long = vec![b'x'; 10_000_000];
        let s = show(&long);
        assert_eq!(s.chars().count(), SHOWN_CHARS + 1);
        assert!(s.ends_with('…'));
        assert_eq!(show(&[b'x'; SHOWN_CHARS]), "x".repeat(SHOWN_CHARS));
        assert_eq!(show(b"a\tb"), "a\\tb");
        assert_eq!(show(b"\xff"), "\u{FFFD}");
        // Four-byte characters: 60 are shown whole, the 61st becomes the `…`.
        let wide = "\u{1F600}".repeat(SHOWN_CHARS);
        assert_eq!(show(wide.as_bytes()), wide);
        let wider = "\u{1F600}".repeat(SHOWN_CHARS + 1);
        assert_eq!(show(wider.as_bytes()), format!("{wide}…"));
        // A cell cut inside a character: still 60 characters and the `…`.
        let mut cut = "\u{1F600}".repeat(2 * SHOWN_CHARS).into_bytes();
        cut.truncate(SHOWN_CHARS * 4 + 2);
        assert_eq!(show(&cut), format!("{wide}…"));
    }
}
