//! Cover targets that must be reachable, and requirement checks that must have run.
//!
//! `cover!(condition, "message")` states that some execution of a harness body makes
//! `condition` true. Under Kani it is `kani::cover!` (the workflow fails a harness whose covers
//! are not all satisfied). Under `cargo test` it records, per thread, every cover evaluated and
//! whether it was ever true; the concrete drivers run their bodies inside [`check_covers`] or
//! [`check_ids`] (or collect per worker thread with [`collect`] and merge with [`merge`]), which
//! fail when a cover was evaluated but never hit. So a premise that no case of a driver's domain
//! reaches fails the driver instead of passing vacuously.
//!
//! `check!(condition, "ID: message", ..)` and `check_eq!(a, b, "ID: message", ..)` are
//! `assert!` and `assert_eq!` that also record, under `cargo test`, the requirement IDs their
//! message starts with (`"SE-RUN-ON-01 / SS-Q-01: …"` records both) each time the assertion is
//! reached, that is, with its premise true. [`check_ids`] fails when one of the IDs a driver
//! names was never recorded in its run, and `tests/spec_catalog.rs` requires every behavioural
//! requirement of `spec/requirements/*.toml` to be named by a `check_ids` driver: a requirement
//! counts only when a driver run by `cargo test` executed one of its assertions.

#[cfg(not(kani))]
use std::cell::{Cell, RefCell};
#[cfg(not(kani))]
use std::collections::{BTreeMap, BTreeSet};
#[cfg(not(kani))]
use std::sync::atomic::{AtomicU64, Ordering};

/// Cover `$cond` with the message `$msg` (a string literal naming the requirement).
#[cfg(kani)]
macro_rules! cover {
    ($cond:expr, $msg:literal) => {
        kani::cover!($cond, $msg)
    };
}

/// Cover `$cond` with the message `$msg` (a string literal naming the requirement).
#[cfg(not(kani))]
macro_rules! cover {
    ($cond:expr, $msg:literal) => {
        $crate::cover::record($cond, $msg)
    };
}

/// `assert!`, recording the requirement IDs the message starts with when it is reached.
#[cfg(not(kani))]
macro_rules! check {
    ($cond:expr $(,)?) => {
        assert!($cond)
    };
    ($cond:expr, $msg:literal $(, $arg:expr)* $(,)?) => {{
        static SITE: $crate::cover::Site = $crate::cover::Site::new($msg);
        SITE.reached();
        assert!($cond, $msg $(, $arg)*);
    }};
}

/// `assert_eq!`, recording the requirement IDs the message starts with when it is reached.
#[cfg(not(kani))]
macro_rules! check_eq {
    ($a:expr, $b:expr $(,)?) => {
        assert_eq!($a, $b)
    };
    ($a:expr, $b:expr, $msg:literal $(, $arg:expr)* $(,)?) => {{
        static SITE: $crate::cover::Site = $crate::cover::Site::new($msg);
        SITE.reached();
        assert_eq!($a, $b, $msg $(, $arg)*);
    }};
}

/// `assert!` (under Kani every assertion is a proof obligation; nothing is recorded).
#[cfg(kani)]
macro_rules! check {
    ($($t:tt)*) => {
        assert!($($t)*)
    };
}

/// `assert_eq!` (under Kani every assertion is a proof obligation; nothing is recorded).
#[cfg(kani)]
macro_rules! check_eq {
    ($($t:tt)*) => {
        assert_eq!($($t)*)
    };
}

pub(crate) use {check, check_eq, cover};

/// What a driver's body recorded: each cover evaluated with how often it held, and the
/// requirement IDs whose assertions were reached.
#[cfg(not(kani))]
#[derive(Debug, Default)]
pub struct Hits {
    /// Each cover evaluated: how often it held.
    pub covers: BTreeMap<&'static str, u64>,
    /// The IDs of the `check!`/`check_eq!` assertions reached.
    pub checked: BTreeSet<&'static str>,
}

#[cfg(not(kani))]
thread_local! {
    static HITS: RefCell<Option<Hits>> = const { RefCell::new(None) };
    // The collection this thread records into (0: none). Unique per `collect` call, so that an
    // assertion site can tell cheaply whether the current collection already has its IDs.
    static COLLECTION: Cell<u64> = const { Cell::new(0) };
}

#[cfg(not(kani))]
static NEXT_COLLECTION: AtomicU64 = AtomicU64::new(1);

/// One `check!`/`check_eq!` call site: its message and the last collection it recorded into.
#[cfg(not(kani))]
pub struct Site {
    msg: &'static str,
    recorded_in: AtomicU64,
}

#[cfg(not(kani))]
impl Site {
    /// The site of an assertion with this message.
    pub const fn new(msg: &'static str) -> Site {
        Site {
            msg,
            recorded_in: AtomicU64::new(0),
        }
    }

    /// The assertion is reached: its IDs go into this thread's collection (once per collection;
    /// a site only ever holds the number of a collection it has recorded into).
    pub fn reached(&self) {
        let c = COLLECTION.with(Cell::get);
        if c == 0 || self.recorded_in.load(Ordering::Relaxed) == c {
            return;
        }
        self.recorded_in.store(c, Ordering::Relaxed);
        HITS.with(|h| {
            if let Some(hits) = h.borrow_mut().as_mut() {
                hits.checked.extend(ids(self.msg));
            }
        });
    }
}

/// Whether `token` looks like a requirement ID: upper-case words and digits joined by `-`, at
/// least three parts, ending in two digits (`S5TMR-TICK-01`, `SE-RUN-ON-01`).
#[cfg(not(kani))]
pub fn is_id(token: &str) -> bool {
    let parts: Vec<&str> = token.split('-').collect();
    parts.len() >= 3
        && parts.iter().all(|p| {
            !p.is_empty()
                && p.chars()
                    .all(|c| c.is_ascii_uppercase() || c.is_ascii_digit())
        })
        && parts
            .last()
            .is_some_and(|n| n.len() == 2 && n.chars().all(|c| c.is_ascii_digit()))
}

/// The requirement IDs a message starts with: IDs separated by ` / `, up to the first token
/// that is not one (`"SE-RUN-ON-01 / SS-Q-01: runs on"` gives both).
#[cfg(not(kani))]
pub fn ids(msg: &'static str) -> impl Iterator<Item = &'static str> {
    msg.split(' ')
        .map(|t| t.trim_end_matches([':', ',']))
        .take_while(|t| *t == "/" || is_id(t))
        .filter(|t| *t != "/")
}

/// Records one evaluation of a cover (a no-op outside [`collect`]).
#[cfg(not(kani))]
pub fn record(cond: bool, msg: &'static str) {
    HITS.with(|h| {
        if let Some(hits) = h.borrow_mut().as_mut() {
            *hits.covers.entry(msg).or_insert(0) += u64::from(cond);
        }
    });
}

/// Runs `body` on this thread and returns what it recorded.
#[cfg(not(kani))]
pub fn collect<R>(body: impl FnOnce() -> R) -> (R, Hits) {
    let outer = HITS.with(|h| h.borrow_mut().replace(Hits::default()));
    let fresh = NEXT_COLLECTION.fetch_add(1, Ordering::Relaxed);
    let outer_collection = COLLECTION.with(|c| c.replace(fresh));
    let r = body();
    COLLECTION.with(|c| c.set(outer_collection));
    let hits = HITS
        .with(|h| std::mem::replace(&mut *h.borrow_mut(), outer))
        .unwrap_or_default();
    (r, hits)
}

/// Merges the records of several workers.
#[cfg(not(kani))]
pub fn merge(all: impl IntoIterator<Item = Hits>) -> Hits {
    let mut merged = Hits::default();
    for hits in all {
        for (msg, n) in hits.covers {
            *merged.covers.entry(msg).or_insert(0) += n;
        }
        merged.checked.extend(hits.checked);
    }
    merged
}

/// Fails when a cover of `hits` was evaluated but never true, or when none was evaluated at
/// all; returns the hits for further checks.
#[cfg(not(kani))]
pub fn require(hits: Hits) -> Hits {
    assert!(!hits.covers.is_empty(), "no cover was evaluated");
    let missed: Vec<&str> = hits
        .covers
        .iter()
        .filter(|(_, &n)| n == 0)
        .map(|(m, _)| *m)
        .collect();
    assert!(missed.is_empty(), "covers never hit: {missed:#?}");
    hits
}

/// Fails when one of `ids` had no assertion reached (no `check!`/`check_eq!` with its ID ran
/// with its premise true) in `hits`.
#[cfg(not(kani))]
pub fn require_checked(ids: &[&str], hits: &Hits) {
    let missed: Vec<&str> = ids
        .iter()
        .filter(|id| !hits.checked.contains(**id))
        .copied()
        .collect();
    assert!(
        missed.is_empty(),
        "requirements whose assertions this driver never reached: {missed:?} (reached: {:?})",
        hits.checked
    );
}

/// Runs `body` and fails when one of the covers it evaluated was never hit.
#[cfg(not(kani))]
pub fn check_covers<R>(body: impl FnOnce() -> R) -> R {
    let (r, hits) = collect(body);
    require(hits);
    r
}

/// Runs `body` and fails when one of the covers it evaluated was never hit (if it evaluated
/// any) or when one of `ids` was never checked: the driver checks these requirements.
#[cfg(not(kani))]
pub fn check_ids<R>(ids: &[&str], body: impl FnOnce() -> R) -> R {
    let (r, hits) = collect(body);
    require_checked(ids, &hits);
    if !hits.covers.is_empty() {
        require(hits);
    }
    r
}

/// Runs `body` (under Kani nothing is recorded: every assertion is a proof obligation).
#[cfg(kani)]
pub fn check_ids<R>(_ids: &[&str], body: impl FnOnce() -> R) -> R {
    body()
}

/// Runs `body` and fails when one of the covers it evaluated whose message starts with one of
/// `ids` was never hit (for a driver whose domain is meant to reach only those requirements),
/// or when one of `ids` was never checked.
#[cfg(not(kani))]
pub fn check_only<R>(ids: &[&str], body: impl FnOnce() -> R) -> R {
    let (r, hits) = collect(body);
    require_checked(ids, &hits);
    let mine = Hits {
        covers: hits
            .covers
            .into_iter()
            .filter(|(m, _)| ids.iter().any(|id| m.starts_with(id)))
            .collect(),
        checked: hits.checked,
    };
    require(mine);
    r
}
