//! A strict RFC 4180 reader of traces that knows where it is: every record carries the line it
//! starts on, counted over LF and CRLF line ends, blank lines and `#` comment lines alike.
//!
//! Rules (spec/cli.md, "Input text"): fields are separated by `,`; records end at LF or CRLF;
//! a UTF-8 byte-order mark at the start is skipped; a line that is empty, blank (spaces and
//! tabs) or whose first non-blank character is `#` is skipped. A field may be quoted: blanks,
//! then `"`, the text with every `"` doubled (line ends allowed), `"`, then blanks. A quote
//! anywhere else (inside an unquoted field, or after the closing quote) and a quote left open at
//! the end of the input are errors. No record may be longer than [`MAX_RECORD`] bytes.
//!
//! The reader allocates only while its buffers grow: records are read into one buffer and
//! handed out as borrowed [`Record`]s.

use std::io::Read;

use super::error::{show, Location, TraceError};

/// The longest record the reader accepts, in bytes (a bound on its memory).
pub const MAX_RECORD: usize = 64 << 20;

const INITIAL_BUFFER: usize = 64 << 10;

/// How many recent records the reader keeps ([`Reader::recent`]).
pub const HISTORY: usize = 4;

/// The most bytes the records kept before the one being read may take at a refill.
pub const KEEP_LIMIT: usize = 16 << 10;

/// One field of the record: a range of the input buffer, or (quoted fields) of the unquoted copy.
#[derive(Clone, Copy, Debug)]
struct Field {
    start: usize,
    end: usize,
    quoted: bool,
}

/// A record of the trace, borrowed from the reader until the next read.
#[derive(Debug)]
pub struct Record<'a> {
    buf: &'a [u8],
    unquoted: &'a [u8],
    fields: &'a [Field],
    raw: (usize, usize),
    line: u64,
}

impl<'a> Record<'a> {
    /// The line the record starts on (1-based).
    pub fn line(&self) -> u64 {
        self.line
    }

    /// The number of fields.
    pub fn len(&self) -> usize {
        self.fields.len()
    }

    /// Whether the record has no field (never: an empty line is skipped).
    pub fn is_empty(&self) -> bool {
        self.fields.is_empty()
    }

    #[inline(always)]
    /// Field `i` (0-based) as its bytes, unquoted, blanks kept; empty when there is no such field.
    pub fn field(&self, i: usize) -> &'a [u8] {
        match self.fields.get(i) {
            Some(f) if f.quoted => &self.unquoted[f.start..f.end],
            Some(f) => &self.buf[f.start..f.end],
            None => &[],
        }
    }

    #[inline(always)]
    /// Field `i` without the blanks (spaces, tabs) around it.
    pub fn cell(&self, i: usize) -> &'a [u8] {
        trim(self.field(i))
    }

    /// The record's text as written, without its line end (quotes kept).
    pub fn raw(&self) -> &'a [u8] {
        &self.buf[self.raw.0..self.raw.1]
    }
}

/// `bytes` without leading and trailing spaces and tabs.
#[inline(always)]
pub fn trim(bytes: &[u8]) -> &[u8] {
    let blank = |b: &u8| *b == b' ' || *b == b'\t';
    let start = bytes.iter().position(|b| !blank(b)).unwrap_or(bytes.len());
    let end = bytes
        .iter()
        .rposition(|b| !blank(b))
        .map_or(start, |e| e + 1);
    &bytes[start..end]
}

/// Why a record could not be parsed from the bytes at hand.
enum Incomplete {
    /// More input is needed (a quoted field goes on past the buffered bytes).
    NeedMore,
    /// The record is malformed.
    Bad(TraceError),
}

/// Reads records from a byte stream.
pub struct Reader<R> {
    src: R,
    buf: Vec<u8>,
    /// The first byte not yet consumed.
    pos: usize,
    /// The end of the bytes read.
    end: usize,
    eof: bool,
    /// The line of `buf[pos]`.
    line: u64,
    at_start: bool,
    /// The longest record accepted.
    limit: usize,
    /// Whether the last [`Reader::scan_line`] stopped at a quote.
    quote_seen: bool,
    /// The spans (start, end, line) of the last records, a ring; `kept` of them are valid.
    history: [(usize, usize, u64); HISTORY],
    next_kept: usize,
    kept: usize,
    fields: Vec<Field>,
    unquoted: Vec<u8>,
}

impl<R: Read> Reader<R> {
    /// A reader of `src`.
    pub fn new(src: R) -> Reader<R> {
        Reader::with_limit(src, MAX_RECORD)
    }

    /// A reader of `src` that accepts records of up to `limit` bytes (at least 64 KiB).
    pub fn with_limit(src: R, limit: usize) -> Reader<R> {
        Reader {
            src,
            limit: limit.max(INITIAL_BUFFER),
            buf: vec![0; INITIAL_BUFFER],
            pos: 0,
            end: 0,
            eof: false,
            line: 1,
            at_start: true,
            quote_seen: false,
            history: [(0, 0, 0); HISTORY],
            next_kept: 0,
            kept: 0,
            fields: Vec::new(),
            unquoted: Vec::new(),
        }
    }

    /// Reads more input after the unconsumed bytes; makes room first (moving the unconsumed
    /// bytes to the front, or growing the buffer up to [`MAX_RECORD`]).
    fn fill(&mut self) -> Result<(), TraceError> {
        // Keep the recent records in the buffer when they are small; drop them rather than
        // grow the buffer for them. The next record read takes the oldest of HISTORY kept
        // slots, so only the others are worth keeping.
        self.kept = self.kept.min(HISTORY - 1);
        let oldest = (self.kept > 0).then(|| self.history[self.kept_slot(0)].0);
        let keep = match oldest {
            Some(start) if self.pos - start <= KEEP_LIMIT => start,
            _ => {
                self.kept = 0;
                self.pos
            }
        };
        self.compact(keep);
        // Full even so: drop the kept records too (with none kept, `keep` was `pos` already).
        if self.end == self.buf.len() {
            self.kept = 0;
            self.compact(self.pos);
        }
        if self.end == self.buf.len() {
            if self.buf.len() >= self.limit {
                return Err(TraceError::new(
                    Location::Line(self.line),
                    format!("the record is longer than {} KiB", self.limit >> 10),
                ));
            }
            self.buf.resize((self.buf.len() * 2).min(self.limit), 0);
        }
        loop {
            match self.src.read(&mut self.buf[self.end..]) {
                Ok(0) => {
                    self.eof = true;
                    return Ok(());
                }
                Ok(n) => {
                    self.end += n;
                    return Ok(());
                }
                Err(e) if e.kind() == std::io::ErrorKind::Interrupted => {}
                Err(e) => {
                    return Err(TraceError::new(
                        Location::Line(self.line),
                        format!("cannot read the trace: {e}"),
                    ))
                }
            }
        }
    }

    /// Moves the bytes from `from` on to the front of the buffer.
    fn compact(&mut self, from: usize) {
        if from == 0 {
            return;
        }
        self.buf.copy_within(from..self.end, 0);
        self.end -= from;
        self.pos -= from;
        for h in &mut self.history {
            h.0 = h.0.saturating_sub(from);
            h.1 = h.1.saturating_sub(from);
        }
    }

    /// The last records read (up to [`HISTORY`], the most recent last), line and text as
    /// written: what `check` shows before a difference, kept in the buffer without copying
    /// each row. When the buffer is refilled, the records before the one being read are
    /// dropped if together they take more than [`KEEP_LIMIT`] bytes.
    pub fn recent(&self) -> impl Iterator<Item = (u64, &[u8])> {
        (0..self.kept).map(move |k| {
            let (start, end, line) = self.history[self.kept_slot(k)];
            (line, &self.buf[start..end])
        })
    }

    /// The slot of the `k`-th (0: the oldest) of the kept records in the ring.
    fn kept_slot(&self, k: usize) -> usize {
        (self.next_kept + HISTORY - self.kept + k) % HISTORY
    }

    /// The next record, or `None` at the end of the input.
    #[inline(always)]
    pub fn next_record(&mut self) -> Result<Option<Record<'_>>, Box<TraceError>> {
        loop {
            if self.at_start {
                while self.end - self.pos < 3 && !self.eof {
                    self.fill()?;
                }
                if self.buf[self.pos..self.end].starts_with(b"\xef\xbb\xbf") {
                    self.pos += 3;
                }
                self.at_start = false;
            }
            // The common case first: one pass over a line without quotes, splitting at commas.
            match self.scan_line() {
                Some((line_end, next)) => {
                    if self.is_skipped(line_end) {
                        self.pos = next;
                        self.line += 1;
                        continue;
                    }
                    return Ok(Some(self.emit(line_end, next, 1)));
                }
                None if self.pos == self.end && self.eof => return Ok(None),
                None if self.quote_seen => {}
                None => {
                    self.fill()?;
                    continue;
                }
            }
            // A line with a quote (or a blank or comment line that has one).
            let newline = memchr::memchr(b'\n', &self.buf[self.pos..self.end]);
            let Some(newline) = newline.map(|n| self.pos + n).or_else(|| {
                // The last line may have no line end.
                (self.eof && self.pos < self.end).then_some(self.end)
            }) else {
                self.fill()?;
                continue;
            };
            if blank_or_comment(&self.buf[self.pos..newline]) {
                self.pos = (newline + 1).min(self.end);
                self.line += 1;
                continue;
            }
            self.fields.clear();
            self.unquoted.clear();
            match self.parse_quoted() {
                Ok((raw_end, next, lines)) => {
                    return Ok(Some(self.emit(raw_end, next, lines)));
                }
                Err(Incomplete::Bad(e)) => return Err(Box::new(e)),
                // `parse_quoted` asks for more only before the end of the input (there, a
                // quote left open is an error of its own), so each refill reads or ends.
                Err(Incomplete::NeedMore) => self.fill()?,
            }
        }
    }

    /// The record read at `self.pos`, its text ending at `raw_end`; the next one starts at
    /// `next`, `lines` lines further.
    #[inline(always)]
    fn emit(&mut self, raw_end: usize, next: usize, lines: u64) -> Record<'_> {
        let (start, line) = (self.pos, self.line);
        self.history[self.next_kept] = (start, raw_end, line);
        self.next_kept = (self.next_kept + 1) % HISTORY;
        self.kept = (self.kept + 1).min(HISTORY);
        self.pos = next;
        self.line += lines;
        Record {
            buf: &self.buf,
            unquoted: &self.unquoted,
            fields: &self.fields,
            raw: (start, raw_end),
            line,
        }
    }

    /// Splits the line at `self.pos` into fields if it is complete in the buffer and has no
    /// quote: returns the end of its text (CR excluded) and the start of the next line. `None`
    /// when it needs more input, or (with `quote_seen`) when it has a quote.
    #[inline(always)]
    fn scan_line(&mut self) -> Option<(usize, usize)> {
        self.quote_seen = false;
        self.fields.clear();
        let buf = &self.buf[..self.end];
        let mut start = self.pos;
        let mut i = self.pos;
        while i < buf.len() {
            match buf[i] {
                b',' => {
                    self.fields.push(Field {
                        start,
                        end: i,
                        quoted: false,
                    });
                    start = i + 1;
                }
                b'\n' => break,
                b'"' => {
                    self.quote_seen = true;
                    return None;
                }
                _ => {}
            }
            i += 1;
        }
        if i == buf.len() && !self.eof {
            return None;
        }
        if i == self.pos && i == buf.len() {
            return None;
        }
        let end = if i > start && buf[i - 1] == b'\r' {
            i - 1
        } else {
            i
        };
        let line_end = if i > self.pos && buf[i - 1] == b'\r' {
            i - 1
        } else {
            i
        };
        self.fields.push(Field {
            start,
            end: end.max(start),
            quoted: false,
        });
        Some((line_end, (i + 1).min(buf.len())))
    }

    /// Whether the line at `self.pos` ending at `line_end` is blank or a comment.
    #[inline]
    fn is_skipped(&self, line_end: usize) -> bool {
        match self.buf.get(self.pos) {
            None => true,
            Some(b' ' | b'\t' | b'#' | b'\r' | b'\n') => {
                blank_or_comment(&self.buf[self.pos..line_end])
            }
            Some(_) => false,
        }
    }

    /// The general case: a record with quotes, which may span lines.
    fn parse_quoted(&mut self) -> Result<(usize, usize, u64), Incomplete> {
        let buf = &self.buf[..self.end];
        let mut i = self.pos;
        let mut lines = 0u64;
        let column = |fields: &Vec<Field>| fields.len() + 1;
        loop {
            // At the start of a field.
            let field_start = i;
            while i < buf.len() && (buf[i] == b' ' || buf[i] == b'\t') {
                i += 1;
            }
            if i < buf.len() && buf[i] == b'"' {
                let open_line = self.line + lines;
                let start = self.unquoted.len();
                i += 1;
                loop {
                    match memchr::memchr(b'"', &buf[i..]) {
                        None => {
                            if self.eof {
                                return Err(field_error(
                                    open_line,
                                    column(&self.fields),
                                    "the quote opened here is never closed; a quoted cell ends \
                                     with `\"` (write a quote inside it as `\"\"`)",
                                ));
                            }
                            return Err(Incomplete::NeedMore);
                        }
                        Some(q) => {
                            let chunk = &buf[i..i + q];
                            lines += memchr::memchr_iter(b'\n', chunk).count() as u64;
                            self.unquoted.extend_from_slice(chunk);
                            i += q + 1;
                            if i < buf.len() && buf[i] == b'"' {
                                self.unquoted.push(b'"');
                                i += 1;
                            } else if i == buf.len() && !self.eof {
                                return Err(Incomplete::NeedMore);
                            } else {
                                break;
                            }
                        }
                    }
                }
                self.fields.push(Field {
                    start,
                    end: self.unquoted.len(),
                    quoted: true,
                });
                while i < buf.len() && (buf[i] == b' ' || buf[i] == b'\t') {
                    i += 1;
                }
                match buf.get(i) {
                    Some(b',') => i += 1,
                    Some(b'\n') => return Ok((i, i + 1, lines + 1)),
                    Some(b'\r') if buf.get(i + 1) == Some(&b'\n') => {
                        return Ok((i, i + 2, lines + 1))
                    }
                    Some(b'\r') if i + 1 == buf.len() && !self.eof => {
                        return Err(Incomplete::NeedMore)
                    }
                    None if self.eof => return Ok((i, i, lines + 1)),
                    None => return Err(Incomplete::NeedMore),
                    Some(_) => {
                        let n = self.fields.len();
                        let end = memchr::memchr3(b',', b'\n', b'\r', &buf[i..])
                            .map_or(buf.len(), |e| i + e);
                        return Err(field_error(
                            self.line + lines,
                            n,
                            format!(
                                "`{}` after the closing quote; a quoted cell ends at its \
                                 closing `\"` (write a quote inside it as `\"\"`)",
                                show(&buf[i..end])
                            ),
                        ));
                    }
                }
            } else {
                // An unquoted field: up to the next comma or line end; no quote inside.
                let end =
                    memchr::memchr3(b',', b'\n', b'"', &buf[i..]).map_or(buf.len(), |e| i + e);
                if end == buf.len() && !self.eof {
                    return Err(Incomplete::NeedMore);
                }
                match buf.get(end) {
                    Some(b'"') => {
                        let col = column(&self.fields);
                        let stop = memchr::memchr2(b',', b'\n', &buf[field_start..])
                            .map_or(buf.len(), |e| field_start + e);
                        return Err(field_error(
                            self.line + lines,
                            col,
                            format!(
                                "stray quote in `{}`; a quote may only open a cell (blanks \
                                 before it allowed) and close it",
                                show(trim(strip_cr(&buf[field_start..stop])))
                            ),
                        ));
                    }
                    Some(b',') => {
                        push_copy(&mut self.unquoted, &mut self.fields, &buf[field_start..end]);
                        i = end + 1;
                    }
                    _ => {
                        // A line end or the end of the input.
                        let text = strip_cr(&buf[field_start..end]);
                        push_copy(&mut self.unquoted, &mut self.fields, text);
                        let next = (end + 1).min(buf.len());
                        return Ok((field_start + text.len(), next, lines + 1));
                    }
                }
            }
        }
    }
}

/// Records an unquoted field of a record with quotes (copied beside the quoted ones, so that
/// every field of such a record is read from the same place).
fn push_copy(unquoted: &mut Vec<u8>, fields: &mut Vec<Field>, text: &[u8]) {
    let start = unquoted.len();
    unquoted.extend_from_slice(text);
    fields.push(Field {
        start,
        end: unquoted.len(),
        quoted: true,
    });
}

/// A malformed field: its line and column, and what is wrong (the header is not known to the
/// reader, so the column is named by its number).
fn field_error(line: u64, column: usize, message: impl Into<String>) -> Incomplete {
    Incomplete::Bad(TraceError::new(
        Location::Cell {
            line,
            column,
            name: format!("field {column}"),
        },
        message,
    ))
}

/// Whether a line (its line end excluded or not) is blank or a `#` comment.
fn blank_or_comment(line: &[u8]) -> bool {
    let content = trim(strip_cr(line));
    content.is_empty() || content[0] == b'#'
}

fn strip_cr(b: &[u8]) -> &[u8] {
    b.strip_suffix(b"\r").unwrap_or(b)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A source that hands out at most `.1` bytes per read, so that records cross refills.
    struct Chunks<'a>(&'a [u8], usize);

    impl Read for Chunks<'_> {
        fn read(&mut self, out: &mut [u8]) -> std::io::Result<usize> {
            let n = self.0.len().min(self.1).min(out.len());
            out[..n].copy_from_slice(&self.0[..n]);
            self.0 = &self.0[n..];
            Ok(n)
        }
    }

    /// Every record as (line, fields, raw), read through a reader that gets `chunk` bytes at a
    /// time, so that records cross buffer refills.
    fn records(input: &[u8], chunk: usize) -> Result<Vec<(u64, Vec<String>, String)>, TraceError> {
        let mut r = Reader::new(Chunks(input, chunk));
        let mut out = Vec::new();
        while let Some(rec) = r.next_record()? {
            let fields = (0..rec.len())
                .map(|i| String::from_utf8_lossy(rec.field(i)).into_owned())
                .collect();
            out.push((
                rec.line(),
                fields,
                String::from_utf8_lossy(rec.raw()).into_owned(),
            ));
        }
        Ok(out)
    }

    fn lines(input: &[u8]) -> Vec<u64> {
        let all = records(input, 1 << 20).expect("valid");
        for chunk in [1, 2, 3, 7] {
            assert_eq!(records(input, chunk).expect("valid"), all, "chunk {chunk}");
        }
        all.into_iter().map(|r| r.0).collect()
    }

    #[test]
    fn line_numbers_lf_crlf_blank_and_comments() {
        assert_eq!(lines(b"a,b\n1,2\n3,4\n"), [1, 2, 3]);
        assert_eq!(lines(b"a,b\r\n1,2\r\n3,4\r\n"), [1, 2, 3]);
        assert_eq!(
            lines(b"# c\r\na,b\r\n\r\n  \r\n1,2\r\n# x\r\n3,4"),
            [2, 5, 7]
        );
        assert_eq!(lines(b"\xef\xbb\xbf#c\n\na\n\t\n1\n"), [3, 5]);
        assert_eq!(lines(b"a\n\"x\ny\"\n2\n"), [1, 2, 4]);
        assert_eq!(lines(b"a\r\n\"x\r\ny\"\r\n2\r\n"), [1, 2, 4]);
        // Comment lines with a quote in them take the quoted path: one line each.
        assert_eq!(lines(b"a\n# say \"hi\"\n1\n#\"\n2\n"), [1, 3, 5]);
        assert_eq!(lines(b"a\r\n# \"\r\n1\r\n"), [1, 3]);
    }

    #[test]
    fn fields_and_raw_text() {
        let r = records(b" a , \"b,\"\"c\"\" \" ,\r\n,\n", 4).expect("valid");
        assert_eq!(r[0].1, [" a ", "b,\"c\" ", ""]);
        assert_eq!(r[0].2, " a , \"b,\"\"c\"\" \" ,");
        assert_eq!(r[1].1, ["", ""]);
        let r = records(b"x,\"y\"", 1).expect("valid");
        assert_eq!(r[0].1, ["x", "y"]);
        assert_eq!(trim(b" \t a b\t "), b"a b");
    }

    #[test]
    fn strict_quotes() {
        for (input, line, column) in [
            (&b"a,b\n1,2\"\n"[..], 2, 2),
            (b"a,b\n1,\"2\"x\n", 2, 2),
            (b"a,b\r\n\r\n1,\"2\n\n", 3, 2),
            (b"a\n\"\"\"\n", 2, 1),
            // A CR after a closing quote that does not end the line.
            (b"a\n\"x\"\ry\n", 2, 1),
            (b"a\n\"x\"\r", 2, 1),
            // After a quoted cell spanning two lines: the quote left open, the stray quote, on
            // the record's second line.
            (b"a,b\n\"x\ny\",\"open\n", 3, 2),
            (b"a,b\n\"x\ny\",a\"b\n", 3, 2),
        ] {
            for chunk in [1, 5, 1 << 20] {
                let e = records(input, chunk).expect_err("bad quotes");
                match e.location {
                    Location::Cell {
                        line: l, column: c, ..
                    } => {
                        assert_eq!((l, c), (line, column), "{e}")
                    }
                    _ => panic!("{e}"),
                }
            }
        }
    }

    /// A record with a quoted cell followed by unquoted ones is one line; the rows after it are
    /// read one at a time, not gathered into one record: the bytes after a quoted record may
    /// be many times the record limit.
    #[test]
    fn quoted_records_end_at_their_line() {
        assert_eq!(lines(b"a,b\n\"x\",1\n2,3\n"), [1, 2, 3]);
        assert_eq!(lines(b"a,b\r\n\"x\",1\r\n2,3\r\n"), [1, 2, 3]);
        // Blanks after the closing quote of a cell spanning lines, the input split right after
        // them (chunk 1): the record goes on.
        assert_eq!(lines(b"a,b\n\"x\ny\" ,1\n2,3\n"), [1, 2, 4]);
        // The same as the last line, with no line end.
        assert_eq!(lines(b"a,b\n\"x\",1"), [1, 2]);
        let limit = 64 << 10;
        let mut input = b"a,b\n\"x\",1\n".to_vec();
        for i in 0..(4 * limit / 8) {
            input.extend_from_slice(format!("{:07},\n", i % 10_000_000).as_bytes());
        }
        let mut r = Reader::with_limit(&input[..], limit);
        let mut n = 0;
        while r
            .next_record()
            .expect("records far below the limit")
            .is_some()
        {
            n += 1;
        }
        assert_eq!(n, 2 + 4 * limit / 8);
    }

    /// A quote opened and never closed: the input ends inside the record; the error names the
    /// cell the quote opens (not a wait for more input that never comes).
    #[test]
    fn unclosed_quote_at_the_end_of_the_input() {
        let e = records(b"a,b\n1,\"open\n2,3\n", 1 << 20).expect_err("open quote");
        assert_eq!(e.to_string().lines().next(), Some("line 2, column 2 (field 2): the quote opened here is never closed; a quoted cell ends with `\"` (write a quote inside it as `\"\"`)"), "{e}");
    }

    /// A read interrupted by a signal is retried; any other read error is reported, with the
    /// line the reader had reached.
    #[test]
    fn read_errors() {
        struct Flaky(u8);
        impl Read for Flaky {
            fn read(&mut self, out: &mut [u8]) -> std::io::Result<usize> {
                self.0 += 1;
                match self.0 {
                    1 => Err(std::io::ErrorKind::Interrupted.into()),
                    2 => {
                        out[..4].copy_from_slice(b"a\n1\n");
                        Ok(4)
                    }
                    _ => Err(std::io::Error::other("disk gone")),
                }
            }
        }
        let mut r = Reader::new(Flaky(0));
        assert_eq!(
            r.next_record()
                .expect("after the interruption")
                .map(|h| h.line()),
            Some(1)
        );
        assert_eq!(r.next_record().expect("the row").map(|h| h.line()), Some(2));
        let e = r.next_record().expect_err("the error");
        assert!(
            e.message.contains("cannot read the trace: disk gone"),
            "{e}"
        );
    }

    /// `n` records of `len` bytes each (`i,xxx...`), each with its line end.
    fn records_of(len: usize, n: usize) -> Vec<u8> {
        (0..n)
            .flat_map(|i| {
                let mut r = format!("{i:04},").into_bytes();
                r.resize(len, b'x');
                r.push(b'\n');
                r
            })
            .collect()
    }

    /// After each record: how many records `recent()` shows, and the bytes (line ends
    /// included) of those before the current one.
    fn recent_counts(input: &[u8]) -> Vec<(usize, usize)> {
        let mut r = Reader::new(Chunks(input, 997));
        let mut counts = Vec::new();
        while r.next_record().expect("valid").is_some() {
            let recent: Vec<usize> = r.recent().map(|(_, t)| t.len() + 1).collect();
            let before: usize = recent[..recent.len() - 1].iter().sum();
            counts.push((recent.len(), before));
        }
        counts
    }

    /// Records of 5 000 bytes: the three before the current one take 15 003 bytes, within
    /// KEEP_LIMIT (16 KiB), so `recent()` always has the last HISTORY (4) of them.
    #[test]
    fn recent_records_kept_while_within_keep_limit() {
        let counts = recent_counts(&records_of(5000, 12));
        let shown: Vec<usize> = counts.iter().map(|c| c.0).collect();
        assert_eq!(shown, [1, 2, 3, 4, 4, 4, 4, 4, 4, 4, 4, 4]);
    }

    /// Records of 6 000 bytes: three before the current one would take 18 003 bytes, more
    /// than KEEP_LIMIT; those are dropped at a refill rather than kept, so the records shown
    /// before the current one never take more than KEEP_LIMIT bytes (two of them do fit).
    #[test]
    fn recent_records_dropped_beyond_keep_limit() {
        let counts = recent_counts(&records_of(6000, 12));
        assert!(counts.iter().all(|c| c.1 <= KEEP_LIMIT), "{counts:?}");
        assert!(counts.iter().any(|c| c.0 == 3), "{counts:?}");
    }

    /// Blank and comment lines before the first record do not count against the record
    /// limit: 10 KiB of comments, then a header of 60 KiB under a 64 KiB limit.
    #[test]
    fn leading_comments_do_not_count_against_the_limit() {
        let mut input = Vec::new();
        for _ in 0..40 {
            input.push(b'#');
            input.extend(std::iter::repeat_n(b'c', 254));
            input.push(b'\n');
        }
        input.extend(std::iter::repeat_n(b'h', 60 << 10));
        input.push(b'\n');
        let mut r = Reader::with_limit(Chunks(&input, 4096), 64 << 10);
        let header = r
            .next_record()
            .expect("within the limit")
            .expect("a record");
        assert_eq!((header.line(), header.raw().len()), (41, 60 << 10));
        assert!(!header.is_empty());
    }

    /// The recent records stay readable across refills of the buffer.
    #[test]
    fn recent_records_survive_refills() {
        let input: Vec<u8> = (0..50)
            .flat_map(|i| format!("{i},x{i}\n").into_bytes())
            .collect();
        let mut r = Reader::new(Chunks(&input, 3));
        let mut n = 0u64;
        while r.next_record().expect("valid").is_some() {
            n += 1;
            let recent: Vec<(u64, Vec<u8>)> = r.recent().map(|(l, t)| (l, t.to_vec())).collect();
            assert_eq!(recent.len() as u64, n.min(HISTORY as u64));
            for (line, text) in recent {
                assert_eq!(text, format!("{},x{}", line - 1, line - 1).into_bytes());
            }
        }
        assert_eq!(n, 50);
    }

    #[test]
    fn long_records_are_bounded() {
        let limit = 256 << 10;
        for (extra, ok) in [(0, true), (1, false), (100_000, false)] {
            // A record of `limit + extra - 1` bytes and its line end.
            let mut long = b"a\n".to_vec();
            long.extend(std::iter::repeat_n(b'x', limit + extra - 1));
            long.push(b'\n');
            let mut r = Reader::with_limit(&long[..], limit);
            let first = r.next_record().expect("the header").map(|h| h.line());
            assert_eq!(first, Some(1));
            match r.next_record() {
                Ok(Some(rec)) => assert!(ok && rec.raw().len() == limit - 1),
                Err(e) => {
                    assert!(!ok);
                    assert_eq!(e.location, Location::Line(2));
                    assert!(e.message.contains("longer than 256 KiB"), "{e}");
                }
                Ok(None) => panic!("a record"),
            }
        }
        assert_eq!(Reader::new(&b""[..]).limit, MAX_RECORD);
    }
}
