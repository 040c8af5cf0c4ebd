//! The requirements as values: [`Rule`], one per ID of `spec/requirements/*.toml`, a set of
//! them ([`RuleSet`]), and [`Explained`], the outputs of one call with the rules that decided
//! them.
//!
//! The references explain their calls: `S5TimerRef::call_explained`, `IecTimerRef::call_explained`,
//! `CounterRef::call_explained`, `S5CounterRef::call_explained`, and the memory areas'
//! `call_explained` and STL operations `*_explained`. They run the same rule functions as the
//! plain `call`, with a recorder that `call` instantiates as a zero-sized no-op, so `call` keeps
//! its code and speed. What "decided" means is in [`Explained`].
//!
//! [`Rule`] is generated from the catalog (`src/rule/table.rs`, by `tests/rule_table.rs`; the
//! library has no build script): `PLC_TIMERS_BLESS=1 cargo test --test rule_table` regenerates
//! it after a requirement's ID or text changed.
//!
//! ```
//! use plc_timers::rule::{Rule, RuleSet};
//! let set = RuleSet::of(Rule::IEC_EXPIRY_01).with(Rule::IEC_PT0_01);
//! assert!(set.contains(Rule::IEC_PT0_01) && !set.contains(Rule::TON_IN_01));
//! let ids: Vec<&str> = set.iter().map(Rule::id).collect();
//! assert_eq!(ids, ["IEC-EXPIRY-01", "IEC-PT0-01"]); // catalog order
//! ```

use core::fmt;

// Generated: its layout is the generator's (`tests/rule_table.rs`), not rustfmt's.
#[rustfmt::skip]
mod table;

pub use table::Rule;

/// The words of a [`RuleSet`]: one bit per rule of the catalog, sized from it (the generated
/// `Rule::COUNT`), so a catalog that grows grows the set instead of overflowing it.
const WORDS: usize = Rule::COUNT.div_ceil(64);

impl Rule {
    /// The rule with ID `id`, if the catalog has it.
    ///
    /// ```
    /// use plc_timers::rule::Rule;
    /// assert_eq!(Rule::from_id("SC-SET-01"), Some(Rule::SC_SET_01));
    /// assert_eq!(Rule::from_id("SC-SET-99"), None);
    /// ```
    pub fn from_id(id: &str) -> Option<Rule> {
        Rule::ALL.iter().copied().find(|r| r.id() == id)
    }
}

impl fmt::Display for Rule {
    /// The ID.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.id())
    }
}

/// The word and the bit of `rule`.
#[inline(always)]
const fn place(rule: Rule) -> (usize, u64) {
    let i = rule as usize;
    (i / 64, 1 << (i % 64))
}

/// A set of [`Rule`]s: one bit per rule, `Copy`, no allocation; iteration is in catalog order.
///
/// ```
/// use plc_timers::rule::{Rule, RuleSet};
/// let mut a = RuleSet::EMPTY;
/// a.insert(Rule::CNT_PRIO_01);
/// let b = RuleSet::of(Rule::CNT_EDGE_01);
/// let both = a.union(b);
/// assert_eq!(both.len(), 2);
/// assert!(a.is_subset(both) && !both.is_subset(a));
/// assert_eq!(both.to_string(), "CNT-EDGE-01, CNT-PRIO-01");
/// assert_eq!(both.iter().collect::<RuleSet>(), both);
/// ```
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash)]
pub struct RuleSet([u64; WORDS]);

impl RuleSet {
    /// No rule.
    pub const EMPTY: RuleSet = RuleSet([0; WORDS]);

    /// The set of `rule` alone.
    #[inline]
    pub const fn of(rule: Rule) -> RuleSet {
        RuleSet::EMPTY.with(rule)
    }

    /// Whether `rule` is in the set.
    #[inline]
    pub const fn contains(self, rule: Rule) -> bool {
        let (w, bit) = place(rule);
        self.0[w] & bit != 0
    }

    /// Adds `rule`.
    #[inline]
    pub const fn insert(&mut self, rule: Rule) {
        let (w, bit) = place(rule);
        self.0[w] |= bit;
    }

    /// The set with `rule` added.
    #[inline]
    pub const fn with(mut self, rule: Rule) -> RuleSet {
        self.insert(rule);
        self
    }

    /// The set with `rule` added when `cond` holds.
    #[inline]
    pub const fn with_if(self, cond: bool, rule: Rule) -> RuleSet {
        if cond {
            self.with(rule)
        } else {
            self
        }
    }

    /// The word-wise union of two sets, or with `union` false the difference (a `while` loop:
    /// iterators are not `const`).
    #[inline(always)]
    const fn zip(self, other: RuleSet, union: bool) -> RuleSet {
        let mut out = [0; WORDS];
        let mut i = 0;
        while i < WORDS {
            out[i] = if union {
                self.0[i] | other.0[i]
            } else {
                self.0[i] & !other.0[i]
            };
            i += 1;
        }
        RuleSet(out)
    }

    /// The rules in either set.
    #[inline]
    pub const fn union(self, other: RuleSet) -> RuleSet {
        self.zip(other, true)
    }

    /// The rules of `self` not in `other`.
    #[inline]
    pub const fn difference(self, other: RuleSet) -> RuleSet {
        self.zip(other, false)
    }

    /// Whether every rule of `self` is in `other`.
    #[inline]
    pub const fn is_subset(self, other: RuleSet) -> bool {
        self.difference(other).is_empty()
    }

    /// Whether the set is empty.
    #[inline]
    pub const fn is_empty(self) -> bool {
        let mut any = 0;
        let mut i = 0;
        while i < WORDS {
            any |= self.0[i];
            i += 1;
        }
        any == 0
    }

    /// The number of rules.
    #[inline]
    pub const fn len(self) -> usize {
        let mut n = 0;
        let mut i = 0;
        while i < WORDS {
            n += self.0[i].count_ones() as usize;
            i += 1;
        }
        n
    }

    /// The rules, in catalog order.
    #[inline]
    pub const fn iter(self) -> RuleSetIter {
        RuleSetIter(self)
    }
}

/// The rules of a [`RuleSet`], in catalog order ([`RuleSet::iter`]).
///
/// ```
/// use plc_timers::rule::{Rule, RuleSet};
/// let mut it = RuleSet::of(Rule::SC_SET_01).with(Rule::S5T_WORD_01).iter();
/// assert_eq!((it.next(), it.next(), it.next()), (Some(Rule::S5T_WORD_01), Some(Rule::SC_SET_01), None));
/// ```
#[derive(Clone, Copy, Debug)]
pub struct RuleSetIter(RuleSet);

impl Iterator for RuleSetIter {
    type Item = Rule;

    fn next(&mut self) -> Option<Rule> {
        // The lowest set bit of the first non-empty word is the next rule in catalog order.
        let w = self.0 .0.iter().position(|&word| word != 0)?;
        let word = &mut self.0 .0[w];
        let i = w * 64 + word.trailing_zeros() as usize;
        *word &= *word - 1;
        // Only bits of rules are ever set, so the index is in range.
        Rule::ALL.get(i).copied()
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        let n = self.0.len();
        (n, Some(n))
    }
}

impl ExactSizeIterator for RuleSetIter {}

impl IntoIterator for RuleSet {
    type Item = Rule;
    type IntoIter = RuleSetIter;
    fn into_iter(self) -> RuleSetIter {
        self.iter()
    }
}

impl FromIterator<Rule> for RuleSet {
    fn from_iter<I: IntoIterator<Item = Rule>>(iter: I) -> RuleSet {
        iter.into_iter().fold(RuleSet::EMPTY, RuleSet::with)
    }
}

impl From<Rule> for RuleSet {
    fn from(rule: Rule) -> RuleSet {
        RuleSet::of(rule)
    }
}

impl fmt::Debug for RuleSet {
    /// The IDs, as a set.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_set().entries(self.iter().map(Rule::id)).finish()
    }
}

impl fmt::Display for RuleSet {
    /// The IDs separated by `, `, in catalog order.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, r) in self.iter().enumerate() {
            if i > 0 {
                f.write_str(", ")?;
            }
            f.write_str(r.id())?;
        }
        Ok(())
    }
}

/// The most outputs a block has (S5 timers: Q, BI, BCD; CTUD: QU, QD, CV; S5 counters: Q, CV,
/// CV_BCD).
pub const MAX_OUTPUTS: usize = 3;

/// The outputs of one explained call, with the rules that decided them.
///
/// - `outputs[i]` are the rules that determined output `i` in this call, `i` being the
///   output's index in the catalog ([`crate::catalog::Block::outputs`]: `Q, BI, BCD` for the
///   S5 timers, `Q, ET` for the IEC timers, `Q, CV` for CTU and CTD, `QU, QD, CV` for CTUD,
///   `Q, CV, CV_BCD` for the S5 counters). A rule determines an output when its premise held in
///   this call and the output's value follows from it, whether the value changed or stayed:
///   the last rule that wrote the state the output is read from (an R after a start decides
///   alone), with the rules that chose that write (the edge that started it, PT = 0, an FR
///   edge); a rule whose premise held and that keeps the value (a running S5 timer's value and
///   status are S5TMR-TICK-01's at every call, also when no tick fell; a running IEC timer's Q
///   is IEC-EXPIRY-01's while ET < PT; PT <= 0 at the box is IEC-PT0-01's); and the rule that
///   derives the output from the state (Q = CV >= PV, `L`/`LC` of the timer word). An output
///   with no rule kept the value an earlier call gave it, and no rule's premise bears on it
///   in this call (a stopped timer's value).
/// - `written` has bit `i` set when a rule's action in this call wrote the state output `i` is
///   read from (a start, a tick, an update of ET, a count, a set, R), even to the same value;
///   an output not written carries the value of the latest call that wrote it. `check` names
///   that call as the earlier row of a difference (see `spec/cli.md`).
/// - `state` are the rules that acted on the state in this call (every rule whose action
///   changed it is there; an edge memory that takes a new value is its edge rule's action).
///
/// All are proven sound (a rule given acted or kept: its premise held), complete (a rule that
/// acted and changed an output or the state is given, and a rule whose premise held and that
/// determines an output's value is given for that output) and faithful (the explained call
/// gives the outputs and state of `call`), for every family, in `proofs/explain.rs`.
///
/// ```
/// use plc_timers::counter::s5::{S5CounterInput, S5CounterKind, S5CounterRef};
/// use plc_timers::rule::Rule;
/// let mut c = S5CounterRef::new();
/// let up = S5CounterInput { cu: true, ..Default::default() };
/// let e = c.call_explained(S5CounterKind::SCu, up);
/// assert_eq!(e.output.cv, 1);
/// assert!(e.outputs[1].contains(Rule::SC_EDGE_01)); // CV: the rising CU counted
/// assert!(e.state.contains(Rule::SC_EDGE_01));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Explained<O> {
    /// The outputs, as `call` gives them.
    pub output: O,
    /// Per output, in catalog order, the rules that decided it in this call (unused entries
    /// are empty).
    pub outputs: [RuleSet; MAX_OUTPUTS],
    /// The rules that acted on the state in this call.
    pub state: RuleSet,
    /// Bit `i`: a rule's action in this call wrote the state that output `i` is read from.
    pub written: u8,
}

impl<O> Explained<O> {
    /// Whether a rule's action in this call wrote output `i` (see [`Explained`]).
    ///
    /// ```
    /// use plc_timers::counter::{CounterInput, CounterKind, CounterRef};
    /// let mut ctu = CounterRef::<i16>::new();
    /// let e = ctu.call_explained(CounterKind::Ctu, CounterInput { cu: true, ..Default::default() });
    /// assert!(e.wrote(1)); // CV: counted
    /// let e = ctu.call_explained(CounterKind::Ctu, CounterInput { cu: true, ..Default::default() });
    /// assert!(!e.wrote(1)); // CU held: CV carried
    /// ```
    pub const fn wrote(&self, i: usize) -> bool {
        i < MAX_OUTPUTS && self.written & (1 << i) != 0
    }

    /// Every rule given: of the outputs and of the state.
    ///
    /// ```
    /// use plc_timers::counter::{CounterInput, CounterKind, CounterRef};
    /// use plc_timers::rule::Rule;
    /// let e = CounterRef::<i16>::new().call_explained(CounterKind::Ctu, CounterInput { r: true, ..Default::default() });
    /// assert!(e.rules().contains(Rule::CNT_PRIO_01));
    /// ```
    pub fn rules(&self) -> RuleSet {
        self.outputs.iter().fold(self.state, |all, o| all.union(*o))
    }

    /// This operation followed by `next` on the same instance in the same scan (the RT coil
    /// before the box, a read after it), as one explanation: an output `next` wrote is decided
    /// by `next`'s rules alone; one it did not write keeps what decided it here, with
    /// `next`'s rules that kept it. `next`'s outputs are the result's.
    ///
    /// ```
    /// use plc_timers::iec::{IecInput, IecKind, IecTimerRef};
    /// use plc_timers::rule::Rule;
    /// use plc_timers::time::CpuTime;
    /// let pt = plc_timers::time!("T#100MS");
    /// let mut ton = IecTimerRef::<u32>::new();
    /// ton.call_explained(IecKind::Ton, CpuTime::ZERO, IecInput::new(true, pt));
    /// let rt = ton.reset_timer_explained();
    /// let e = rt.then(ton.call_explained(IecKind::Ton, CpuTime::from_millis(10), IecInput::new(false, pt)));
    /// assert!(e.outputs[0].contains(Rule::TON_IN_01) && !e.outputs[0].contains(Rule::IEC_RT_01));
    /// assert!(e.state.contains(Rule::IEC_RT_01));
    /// ```
    pub fn then<P>(self, next: Explained<P>) -> Explained<P> {
        let mut outputs = next.outputs;
        for (i, o) in outputs.iter_mut().enumerate() {
            if !next.wrote(i) {
                *o = o.union(self.outputs[i]);
            }
        }
        Explained {
            output: next.output,
            outputs,
            state: self.state.union(next.state),
            written: self.written | next.written,
        }
    }
}

/// Output masks: bit `i` is catalog output `i`.
pub(crate) mod out {
    /// Output 0 (Q, QU).
    pub const O0: u8 = 1;
    /// Output 1 (BI, ET, CV of CTU/CTD, QD, CV of S5 counters).
    pub const O1: u8 = 2;
    /// Output 2 (BCD, CV of CTUD, CV_BCD).
    pub const O2: u8 = 4;

    // Distinct bits: masks combine them with `|` (or `^`, or `+`: the same).
    const _: () = assert!(O0 & O1 == 0 && O0 & O2 == 0 && O1 & O2 == 0);
}

/// What the rule functions of a reference report as they act. `()` records nothing and is what
/// the plain `call` uses; [`Explanation`] collects an [`Explained`].
pub(crate) trait Recorder {
    /// `rules` acted on the state and now decide the outputs of `outputs` (a mask of
    /// [`out`]), replacing what decided them before in this call.
    fn write(&mut self, rules: RuleSet, outputs: u8);
    /// `rules` also decide the outputs of `outputs` (a premise of a write, a rule that keeps
    /// their value, or a derivation of the output from the state), beside what decides them
    /// already.
    fn add(&mut self, rules: RuleSet, outputs: u8);
    /// `rules` acted on the state and updated the outputs of `outputs` (ET following the
    /// clock), beside what decides them already.
    fn update(&mut self, rules: RuleSet, outputs: u8);
    /// `rules` acted on the state, deciding no output.
    fn state(&mut self, rules: RuleSet);
}

impl Recorder for () {
    #[inline(always)]
    fn write(&mut self, _: RuleSet, _: u8) {}
    #[inline(always)]
    fn add(&mut self, _: RuleSet, _: u8) {}
    #[inline(always)]
    fn update(&mut self, _: RuleSet, _: u8) {}
    #[inline(always)]
    fn state(&mut self, _: RuleSet) {}
}

/// The recorder of an explained call.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Explanation {
    pub outputs: [RuleSet; MAX_OUTPUTS],
    pub state: RuleSet,
    pub written: u8,
}

impl Explanation {
    /// The outputs of `mask` that are also in the catalog order's first `n`.
    fn each(mask: u8, mut f: impl FnMut(usize)) {
        for i in 0..MAX_OUTPUTS {
            if mask & (1 << i) != 0 {
                f(i);
            }
        }
    }

    /// The explanation of a call that gave `output`.
    pub fn finish<O>(self, output: O) -> Explained<O> {
        Explained {
            output,
            outputs: self.outputs,
            state: self.state,
            written: self.written,
        }
    }
}

impl Recorder for Explanation {
    fn write(&mut self, rules: RuleSet, outputs: u8) {
        self.state = self.state.union(rules);
        self.written |= outputs;
        Self::each(outputs, |i| self.outputs[i] = rules);
    }
    fn add(&mut self, rules: RuleSet, outputs: u8) {
        Self::each(outputs, |i| self.outputs[i] = self.outputs[i].union(rules));
    }
    fn update(&mut self, rules: RuleSet, outputs: u8) {
        self.state = self.state.union(rules);
        self.written |= outputs;
        self.add(rules, outputs);
    }
    fn state(&mut self, rules: RuleSet) {
        self.state = self.state.union(rules);
    }
}
