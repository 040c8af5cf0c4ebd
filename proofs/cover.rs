//! Cover targets that must be reachable.
//!
//! `cover!(condition, "message")` states that some execution of a harness body makes
//! `condition` true. Under Kani it is `kani::cover!`, and the workflow runs Kani with
//! `--fail-uncoverable`, so an unsatisfiable cover fails the proof. Under `cargo test` it
//! records, per thread, every cover evaluated and whether it was ever true; the concrete drivers
//! run their bodies inside [`check`] (or collect per worker thread with [`collect`] and merge
//! with [`require`]), which fails when a cover was evaluated but never hit. So a premise that no
//! case of a driver's domain reaches fails the driver instead of passing vacuously.

#[cfg(not(kani))]
use std::cell::RefCell;
#[cfg(not(kani))]
use std::collections::BTreeMap;

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

pub(crate) use cover;

/// Each cover evaluated: how often it held.
#[cfg(not(kani))]
pub type Hits = BTreeMap<&'static str, u64>;

#[cfg(not(kani))]
thread_local! {
    static HITS: RefCell<Option<Hits>> = const { RefCell::new(None) };
}

/// Records one evaluation of a cover (a no-op outside [`collect`]).
#[cfg(not(kani))]
pub fn record(cond: bool, msg: &'static str) {
    HITS.with(|h| {
        if let Some(hits) = h.borrow_mut().as_mut() {
            *hits.entry(msg).or_insert(0) += u64::from(cond);
        }
    });
}

/// Runs `body` on this thread and returns the covers it evaluated with their hit counts.
#[cfg(not(kani))]
pub fn collect<R>(body: impl FnOnce() -> R) -> (R, Hits) {
    let outer = HITS.with(|h| h.borrow_mut().replace(Hits::new()));
    let r = body();
    let hits = HITS
        .with(|h| std::mem::replace(&mut *h.borrow_mut(), outer))
        .unwrap_or_default();
    (r, hits)
}

/// Merges the hits of several workers.
#[cfg(not(kani))]
pub fn merge(all: impl IntoIterator<Item = Hits>) -> Hits {
    let mut merged = Hits::new();
    for hits in all {
        for (msg, n) in hits {
            *merged.entry(msg).or_insert(0) += n;
        }
    }
    merged
}

/// Fails when a cover of `hits` was evaluated but never true, or when none was evaluated at
/// all; returns the hits for further checks.
#[cfg(not(kani))]
pub fn require(hits: Hits) -> Hits {
    assert!(!hits.is_empty(), "no cover was evaluated");
    let missed: Vec<&str> = hits
        .iter()
        .filter(|(_, &n)| n == 0)
        .map(|(m, _)| *m)
        .collect();
    assert!(missed.is_empty(), "covers never hit: {missed:#?}");
    hits
}

/// Runs `body` and fails when one of the covers it evaluated was never hit.
#[cfg(not(kani))]
pub fn check<R>(body: impl FnOnce() -> R) -> R {
    let (r, hits) = collect(body);
    require(hits);
    r
}

/// Runs `body` and fails when one of the covers it evaluated whose message starts with one of
/// `ids` was never hit (for a driver whose domain is meant to reach only those requirements).
#[cfg(not(kani))]
pub fn check_only<R>(ids: &[&str], body: impl FnOnce() -> R) -> R {
    let (r, hits) = collect(body);
    let mine: Hits = hits
        .into_iter()
        .filter(|(m, _)| ids.iter().any(|id| m.starts_with(id)))
        .collect();
    require(mine);
    r
}
