//! Cover targets that must be reachable, and requirement checks that must have run.
//!
//! `cover!(condition, "message")` states that some execution of a harness body makes
//! `condition` true. Under Kani it is `kani::cover!`: Kani counts, per harness, every cover in
//! the code the harness can call, and the workflow fails a harness whose covers are not all
//! satisfied (one in a branch the harness never takes is unreachable, so it fails too).
//!
//! Under `cargo test` the same is counted per harness. Every function holding a `cover!` carries
//! `#[covers]` (proofs/macros; without it `cover!` does not compile), which declares all its covers
//! when the function is entered, taken branches or not; each evaluation then records whether the
//! condition held. Every Kani harness runs its body inside [`harness`], which fails with the
//! messages of the covers its runs declared but never satisfied (running the body again with fresh
//! random inputs while one is unsatisfied, up to [`HARNESS_ROUNDS`] times), and prints how often
//! each was satisfied. The concrete drivers run their bodies inside [`check_covers`] or
//! [`check_ids`] (or collect per worker thread with [`collect`] and merge with [`merge`]), which
//! fail the same way. So a premise that no case of a harness or driver reaches fails it instead of
//! passing vacuously. (What `cargo test` cannot see: a cover in a function that the harness could
//! call but its runs never enter; Kani counts that one too.)
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

/// Cover `$cond` with the message `$msg` (a string literal naming the requirement). Only in a
/// function marked `#[covers]`: "cannot find value `__COVERS_DECLARED`" means the attribute is
/// missing.
#[cfg(not(kani))]
macro_rules! cover {
    ($cond:expr, $msg:literal) => {{
        let _: () = __COVERS_DECLARED;
        $crate::cover::record($cond, $msg)
    }};
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

pub(crate) use plc_timers_proofs_macros::covers;
pub(crate) use {check, check_eq, cover};

/// What a driver's body recorded: each cover declared or evaluated with how often it held, and
/// the requirement IDs whose assertions were reached.
#[cfg(not(kani))]
#[derive(Debug, Default)]
pub struct Hits {
    /// Each cover declared (by `#[covers]` on entry to its function) or evaluated: how often it
    /// held.
    pub covers: BTreeMap<&'static str, u64>,
    /// Each cover evaluated: how often.
    pub evaluated: BTreeMap<&'static str, u64>,
    /// The IDs of the `check!`/`check_eq!` assertions reached.
    pub checked: BTreeSet<&'static str>,
}

#[cfg(not(kani))]
impl Hits {
    /// The covers declared or evaluated but never satisfied.
    pub fn unsatisfied(&self) -> Vec<&'static str> {
        self.covers
            .iter()
            .filter(|(_, &n)| n == 0)
            .map(|(m, _)| *m)
            .collect()
    }
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
        once_per_collection(&self.recorded_in, |hits| hits.checked.extend(ids(self.msg)));
    }
}

/// Runs `record` on this thread's collection, at most once per collection for one site:
/// `marker` holds the number of the last collection the site recorded into (0: none is open).
#[cfg(not(kani))]
fn once_per_collection(marker: &AtomicU64, record: impl FnOnce(&mut Hits)) {
    let c = COLLECTION.with(Cell::get);
    if c == 0 || marker.load(Ordering::Relaxed) == c {
        return;
    }
    marker.store(c, Ordering::Relaxed);
    HITS.with(|h| {
        if let Some(hits) = h.borrow_mut().as_mut() {
            record(hits);
        }
    });
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
            *hits.evaluated.entry(msg).or_insert(0) += 1;
        }
    });
}

/// The covers of one function marked `#[covers]` and the last collection they were declared
/// into.
#[cfg(not(kani))]
pub struct Declared {
    msgs: &'static [&'static str],
    declared_in: AtomicU64,
}

#[cfg(not(kani))]
impl Declared {
    /// The covers of a function, by their messages.
    pub const fn new(msgs: &'static [&'static str]) -> Declared {
        Declared {
            msgs,
            declared_in: AtomicU64::new(0),
        }
    }

    /// The function is entered: its covers go into this thread's collection, satisfied or not
    /// (once per collection, as [`Site::reached`]).
    pub fn enter(&self) {
        once_per_collection(&self.declared_in, |hits| {
            for &msg in self.msgs {
                hits.covers.entry(msg).or_insert(0);
            }
        });
    }
}

/// Runs `body` on this thread and returns what it recorded. Inside another collection (a
/// harness around a driver's `check_ids`), the records also go into the outer one.
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
    HITS.with(|h| {
        if let Some(outer) = h.borrow_mut().as_mut() {
            add(outer, &hits);
        }
    });
    (r, hits)
}

/// Adds the records of `hits` to `into`.
#[cfg(not(kani))]
fn add(into: &mut Hits, hits: &Hits) {
    for (&msg, &n) in &hits.covers {
        *into.covers.entry(msg).or_insert(0) += n;
    }
    for (&msg, &n) in &hits.evaluated {
        *into.evaluated.entry(msg).or_insert(0) += n;
    }
    into.checked.extend(&hits.checked);
}

/// Merges the records of several workers.
#[cfg(not(kani))]
pub fn merge(all: impl IntoIterator<Item = Hits>) -> Hits {
    let mut merged = Hits::default();
    for hits in all {
        add(&mut merged, &hits);
    }
    merged
}

/// Fails when a cover of `hits` was declared or evaluated but never true, or when none was
/// evaluated at all; returns the hits for further checks.
#[cfg(not(kani))]
pub fn require(hits: Hits) -> Hits {
    assert!(!hits.covers.is_empty(), "no cover was evaluated");
    let missed = hits.unsatisfied();
    assert!(missed.is_empty(), "covers never hit: {missed:#?}");
    hits
}

/// How many times [`harness`] runs a body whose runs leave a cover unsatisfied.
#[cfg(not(kani))]
pub const HARNESS_ROUNDS: u32 = 16;

#[cfg(not(kani))]
thread_local! {
    // The requirement IDs that drivers' `check_ids` inside the open harness leave to it (None:
    // no harness is open on this thread).
    static HARNESS_IDS: RefCell<Option<BTreeSet<String>>> = const { RefCell::new(None) };
}

/// Inside a [`harness`], leaves the check that `ids` were reached to the harness (which judges
/// all its rounds together) and returns true; outside one, returns false.
#[cfg(not(kani))]
fn leave_to_harness(ids: &[&str]) -> bool {
    HARNESS_IDS.with(|h| match h.borrow_mut().as_mut() {
        Some(open) => {
            open.extend(ids.iter().map(|id| id.to_string()));
            true
        }
        None => false,
    })
}

/// The body of the Kani harness `name` (`module::function`, as .ci/kani-harnesses lists it):
/// runs `body`, prints each cover it declared with how often it was satisfied and evaluated
/// (seen with `--nocapture`), and fails with the messages of those never satisfied, as the
/// harness's Kani job would.
///
/// A cover is existential: Kani finds it satisfied when some execution of the harness
/// satisfies it. Under `cargo test` a run of a body samples its executions (bolero's random
/// inputs), and a cover whose premise is rare can go unsatisfied in one run of a few thousand
/// inputs (IEC-WRAP-01's "the clock wrapped since START" on TONR: in about 1 run of 16 at
/// bolero's 2 000 inputs). So while a cover is unsatisfied, the harness runs its body again
/// with fresh inputs, up to [`HARNESS_ROUNDS`] runs, and fails only when none of them satisfied
/// it; every assertion of every run must hold. A cover that no input reaches fails after the
/// last run. The same holds for the requirement IDs of a driver's `check_ids` inside the body:
/// they count over all the runs.
#[cfg(not(kani))]
pub fn harness<R>(name: &str, mut body: impl FnMut() -> R) -> R {
    // `module_path!()` of the test crate starts with its name.
    let name = name.strip_prefix("proofs::").unwrap_or(name);
    let mut total = Hits::default();
    let mut ids = BTreeSet::new();
    let mut round = 0;
    loop {
        round += 1;
        let outer = HARNESS_IDS.with(|h| h.replace(Some(BTreeSet::new())));
        let (r, hits) = collect(&mut body);
        let left = HARNESS_IDS.with(|h| h.replace(outer)).unwrap_or_default();
        ids.extend(left);
        add(&mut total, &hits);
        let missed = total.unsatisfied();
        let unchecked = ids.iter().any(|id| !total.checked.contains(id.as_str()));
        if (missed.is_empty() && !unchecked) || round == HARNESS_ROUNDS {
            let runs = if round == 1 {
                String::new()
            } else {
                format!(" ({round} runs of the body)")
            };
            println!("{}{runs}", table(name, &total));
            assert!(
                missed.is_empty(),
                "harness {name}: covers never satisfied: {missed:#?} ({round} runs of the body)"
            );
            let ids: Vec<&str> = ids.iter().map(String::as_str).collect();
            require_checked(&ids, &total);
            return r;
        }
    }
}

/// Runs `body` (under Kani the harness is the proof: nothing is recorded).
#[cfg(kani)]
pub fn harness<R>(_name: &str, mut body: impl FnMut() -> R) -> R {
    body()
}

/// The covers of harness `name` with how often each was satisfied and evaluated, one line
/// each after a heading line.
#[cfg(not(kani))]
pub fn table(name: &str, hits: &Hits) -> String {
    let mut out = format!("covers of {name}: {}", hits.covers.len());
    for (msg, n) in &hits.covers {
        let evaluated = hits.evaluated.get(msg).copied().unwrap_or(0);
        out.push_str(&format!("\n  {n:>9} of {evaluated:>9}  {msg}"));
    }
    out
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
    // In a harness, its covers and these IDs count over all the runs of its body.
    if leave_to_harness(ids) {
        return r;
    }
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
        evaluated: hits.evaluated,
        checked: hits.checked,
    };
    require(mine);
    r
}

/// The per-harness check itself, on bodies with a dead cover, and the rule that every Kani
/// harness runs in its own scope.
#[cfg(all(test, not(kani)))]
mod tests {
    use super::{check_ids, collect, covers, harness, table, HARNESS_ROUNDS};

    /// A body with a cover per branch, as a harness body that branches on its inputs.
    #[covers]
    fn by_kind(kind: u8) {
        if kind == 0 {
            cover!(true, "TEST-BRANCH-01: kind 0");
        }
        cover!(kind == 1, "TEST-KIND-01: kind 1");
        cover!(kind > 5, "TEST-LARGE-01: a kind above 5");
    }

    /// A cover in a branch the harness's inputs never take is declared on entry and fails the
    /// harness, although it is never evaluated.
    #[test]
    #[should_panic(
        expected = "harness test::unreached_branch: covers never satisfied: [\n    \"TEST-BRANCH-01: kind 0\",\n    \"TEST-LARGE-01: a kind above 5\",\n]"
    )]
    fn a_cover_in_a_branch_never_taken_fails_its_harness() {
        harness("test::unreached_branch", || (1..=5).for_each(by_kind));
    }

    /// A cover evaluated on every run but never true fails the harness.
    #[test]
    #[should_panic(
        expected = "harness test::never_true: covers never satisfied: [\n    \"TEST-LARGE-01: a kind above 5\",\n]"
    )]
    fn a_cover_never_true_fails_its_harness() {
        harness("test::never_true", || (0..=5).for_each(by_kind));
    }

    /// Every cover satisfied: the harness passes, and its table counts, per cover, the runs that
    /// satisfied it and those that evaluated it (kinds 0..=7: kind 0 once in its branch, kind 1
    /// once of 8, kinds 6 and 7 of 8).
    #[test]
    fn covers_all_satisfied_pass_and_are_counted_per_harness() {
        harness("test::all", || (0..=7).for_each(by_kind));
        let ((), hits) = collect(|| (0..=7).for_each(by_kind));
        assert_eq!(
            table("test::all", &hits),
            "covers of test::all: 3\n\
             \x20         1 of         1  TEST-BRANCH-01: kind 0\n\
             \x20         1 of         8  TEST-KIND-01: kind 1\n\
             \x20         2 of         8  TEST-LARGE-01: a kind above 5"
        );
    }

    /// Two harnesses count apart: one that satisfies a cover does not help another that
    /// does not (the counting per driver that hid the IEC per-kind harnesses' dead covers).
    #[test]
    #[should_panic(expected = "harness test::second: covers never satisfied")]
    fn harnesses_count_apart() {
        harness("test::first", || (0..=7).for_each(by_kind));
        harness("test::second", || (1..=5).for_each(by_kind));
    }

    /// A scope inside a harness (a driver's `check_ids`) also records into the harness.
    #[test]
    #[should_panic(expected = "harness test::nested: covers never satisfied")]
    fn a_nested_scope_records_into_its_harness() {
        harness("test::nested", || {
            let ((), inner) = collect(|| by_kind(3));
            assert_eq!(inner.covers.len(), 3, "the inner scope has its own records");
        });
    }

    /// A cover that one run of a random body misses and a later run satisfies: the harness
    /// runs the body again until it is, and passes.
    #[test]
    fn a_cover_satisfied_in_a_later_run_passes_its_harness() {
        let mut runs = 0;
        harness("test::later", || {
            runs += 1;
            // Kinds 0 and 1 in every run, a kind above 5 from the third run on.
            [0, 1, if runs >= 3 { 7 } else { 2 }]
                .into_iter()
                .for_each(by_kind);
        });
        assert_eq!(
            runs, 3,
            "the harness stops at the first run that satisfies every cover"
        );
    }

    /// A cover that no run satisfies fails the harness after [`HARNESS_ROUNDS`] runs.
    #[test]
    fn a_cover_never_true_fails_after_the_last_run() {
        let mut runs = 0;
        let failed = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            harness("test::never_true_rounds", || {
                runs += 1;
                (0..=5).for_each(by_kind);
            })
        }));
        assert!(failed.is_err(), "a cover never true fails the harness");
        assert_eq!(runs, HARNESS_ROUNDS);
    }

    /// A driver's `check_ids` inside a harness: its IDs count over the harness's runs, and
    /// one never reached in any run fails the harness.
    #[test]
    fn a_nested_drivers_ids_count_over_the_runs() {
        // Not requirement IDs: lists in variables, which tests/spec_catalog.rs's scan of the
        // drivers' literal lists does not take for a driver's.
        let (reached, never) = (["TEST-ID-01"], ["TEST-ID-02"]);
        let mut runs = 0;
        harness("test::nested_ids", || {
            runs += 1;
            by_kind(if runs >= 2 { 7 } else { 0 });
            by_kind(1);
            by_kind(0);
            check_ids(&reached, || {
                if runs >= 2 {
                    check!(runs >= 2, "TEST-ID-01: reached from the second run on");
                }
            });
        });
        assert_eq!(runs, 2);
        let failed = std::panic::catch_unwind(move || {
            harness("test::nested_ids_never", || {
                (0..=7).for_each(by_kind);
                check_ids(&never, || ());
            })
        });
        let message = failed.expect_err("an ID never reached fails the harness");
        let message = message
            .downcast_ref::<String>()
            .expect("a formatted panic message");
        assert!(
            message.contains("never reached: [\"TEST-ID-02\"]"),
            "{message}"
        );
    }

    /// Every function marked as a Kani harness in proofs/ runs its body in [`harness`], first
    /// thing, so that `cargo test` checks its covers as its Kani job would.
    #[test]
    fn every_kani_harness_runs_in_its_own_scope() {
        let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/proofs");
        let mut harnesses = 0;
        for entry in std::fs::read_dir(dir).expect("proofs/") {
            let path = entry.expect("an entry").path();
            // This file names the attribute in the test itself.
            if path.extension().is_none_or(|e| e != "rs") || path.ends_with("cover.rs") {
                continue;
            }
            let text = std::fs::read_to_string(&path).expect("a source file");
            for (at, _) in text.match_indices("#[cfg_attr(kani, kani::proof") {
                let rest = &text[at..];
                let body = rest
                    .find("\n")
                    .and_then(|nl| rest[nl..].find("fn ").map(|f| nl + f))
                    .and_then(|f| rest[f..].find('{').map(|b| &rest[f + b + 1..]))
                    .expect("the harness's body");
                assert!(
                    body.trim_start().starts_with("crate::cover::harness("),
                    "{}: the harness at byte {at} does not run in crate::cover::harness",
                    path.display()
                );
                harnesses += 1;
            }
        }
        // 26 marked functions, 48 harnesses once the harness macros have expanded.
        assert!(harnesses >= 26, "only {harnesses} harnesses found");
    }
}
