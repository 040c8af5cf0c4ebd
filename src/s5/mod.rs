//! S5 timers of S7-300/400: `S_PULSE`, `S_PEXT`, `S_ODT`, `S_ODTS`, `S_OFFDT` (LAD manual
//! §9.1-9.7, Berger §7).
//!
//! One interface, [`S5TimerOps`], two implementations:
//! - [`S5TimerRef`]: one timer as the manual describes it, one function per rule.
//! - [`S5Timer`]: the optimized timer, its whole state packed in the CPU's 16-bit timer word
//!   ([`TimerWord`]).
//!
//! and [`TimerMemory`], a timer memory area of N words whose time-base tick updates every
//! running timer in one pass, with the STL operations (`SP`/`SE`/`SD`/`SS`/`SF`, `R`, `FR`,
//! `L`, `LC`, `A`).
//!
//! Time follows the operating-system tick model (S5TMR-TICK-01): the tick of a base falls on
//! every whole multiple of the base on the CPU millisecond clock, and decrements each running
//! timer of that base by one unit; before a timer executes at `t`, every tick in `(t_prev, t]`
//! has been applied.
//!
//! ```
//! use plc_timers::s5::{S5Input, S5Kind, S5Timer, S5TimerOps, S5TimerRef};
//! use plc_timers::time::CpuTime;
//!
//! let tv = plc_timers::s5time!("S5T#50MS"); // 5 units of 10 ms
//! let at = CpuTime::from_millis;
//! let s = S5Input::new(true, false, tv);
//! let mut reference = S5TimerRef::new();
//! let mut optimized = S5Timer::new();
//! for timer in [&mut reference as &mut dyn S5TimerOps, &mut optimized] {
//!     assert!(!timer.call(S5Kind::SOdt, at(0), s).q); // rising S starts the on-delay
//!     assert_eq!(timer.call(S5Kind::SOdt, at(40), s).bi, 1); // 4 ticks: 1 unit left
//!     assert!(timer.call(S5Kind::SOdt, at(50), s).q); // 5th tick: run out, S = 1: Q = 1
//! }
//! assert_eq!(reference.state(), optimized.state());
//! ```

pub mod memory;
pub mod reference;
pub mod word;

pub use memory::TimerMemory;
pub use reference::S5TimerRef;
pub use word::{S5Timer, TimerWord};

use crate::time::{CpuTime, S5Time, TimeBase};

/// The five S5 timer kinds, with both mnemonic sets (watch the clash: English `SE` is the
/// extended pulse, German `SE` the on-delay).
///
/// ```
/// use plc_timers::s5::S5Kind;
/// assert_eq!(S5Kind::ALL.map(S5Kind::stl), ["SP", "SE", "SD", "SS", "SF"]);
/// assert!(S5Kind::SOffdt.starts_on_falling_edge());
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(kani, derive(kani::Arbitrary))]
#[cfg_attr(feature = "bolero", derive(bolero_generator::TypeGenerator))]
pub enum S5Kind {
    /// `S_PULSE`, STL `SP` (German `SI`): pulse, Q = 1 while running and S = 1 (LAD manual §9.3).
    #[doc(alias = "SP")]
    #[doc(alias = "SI")]
    SPulse,
    /// `S_PEXT`, STL `SE` (German `SV`): extended pulse, runs on when S falls (LAD manual §9.4).
    #[doc(alias = "SE")]
    #[doc(alias = "SV")]
    SPext,
    /// `S_ODT`, STL `SD` (German `SE`): on-delay, Q = 1 after the time while S = 1 (LAD manual §9.5).
    #[doc(alias = "SD")]
    SOdt,
    /// `S_ODTS`, STL `SS`: retentive on-delay, Q = 1 after the time until R (LAD manual §9.6).
    #[doc(alias = "SS")]
    SOdts,
    /// `S_OFFDT`, STL `SF` (German `SA`): off-delay, starts on a falling S (LAD manual §9.7).
    #[doc(alias = "SF")]
    #[doc(alias = "SA")]
    SOffdt,
}

impl S5Kind {
    /// All five, in manual order.
    pub const ALL: [S5Kind; 5] = [
        S5Kind::SPulse,
        S5Kind::SPext,
        S5Kind::SOdt,
        S5Kind::SOdts,
        S5Kind::SOffdt,
    ];

    /// The LAD box name (`S_PULSE`, …).
    pub const fn name(self) -> &'static str {
        match self {
            S5Kind::SPulse => "S_PULSE",
            S5Kind::SPext => "S_PEXT",
            S5Kind::SOdt => "S_ODT",
            S5Kind::SOdts => "S_ODTS",
            S5Kind::SOffdt => "S_OFFDT",
        }
    }

    /// The international STL mnemonic (`SP`, `SE`, `SD`, `SS`, `SF`).
    pub const fn stl(self) -> &'static str {
        match self {
            S5Kind::SPulse => "SP",
            S5Kind::SPext => "SE",
            S5Kind::SOdt => "SD",
            S5Kind::SOdts => "SS",
            S5Kind::SOffdt => "SF",
        }
    }

    /// Whether the timer starts on a falling edge of S (only `S_OFFDT`).
    pub const fn starts_on_falling_edge(self) -> bool {
        matches!(self, S5Kind::SOffdt)
    }
}

/// The inputs of one execution of an S5 timer box.
///
/// ```
/// use plc_timers::s5::S5Input;
/// let input = S5Input::new(true, false, plc_timers::s5time!("S5T#1S")).with_fr(true);
/// assert!(input.s && input.fr && !input.r);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "bolero", derive(bolero_generator::TypeGenerator))]
pub struct S5Input {
    /// `S`, the start input.
    pub s: bool,
    /// `R`, the reset input.
    pub r: bool,
    /// `FR`, the enable input (STL `FR T n`; the LAD boxes have none: false there).
    pub fr: bool,
    /// `TV` (`TW`), the time value loaded on a start.
    pub tv: S5Time,
}

/// Every input 0, `TV` = `S5T#0MS`: the inputs of a box that nothing drives.
///
/// ```
/// use plc_timers::s5::S5Input;
/// use plc_timers::time::S5Time;
/// assert_eq!(S5Input::default(), S5Input::new(false, false, S5Time::ZERO));
/// ```
impl Default for S5Input {
    fn default() -> S5Input {
        S5Input::new(false, false, S5Time::ZERO)
    }
}

impl S5Input {
    /// `S`, `R` and `TV`, with `FR` = 0.
    ///
    /// ```
    /// use plc_timers::s5::S5Input;
    /// let input = S5Input::new(true, false, plc_timers::s5time!("S5T#5S"));
    /// assert!(input.s && !input.fr);
    /// ```
    pub const fn new(s: bool, r: bool, tv: S5Time) -> S5Input {
        S5Input {
            s,
            r,
            fr: false,
            tv,
        }
    }

    /// These inputs with `R` = `r`.
    #[must_use]
    pub const fn with_r(self, r: bool) -> S5Input {
        S5Input { r, ..self }
    }

    /// These inputs with `FR` = `fr`.
    #[must_use]
    pub const fn with_fr(self, fr: bool) -> S5Input {
        S5Input { fr, ..self }
    }
}

/// The outputs of one execution.
///
/// ```
/// use plc_timers::s5::{S5Output, S5State};
/// use plc_timers::time::TimeBase;
/// let running = S5State { running: true, value: 127, base: TimeBase::S1, q: true, ..S5State::RESET };
/// assert_eq!(running.output(), S5Output { q: true, bi: 127, bcd: 0x2127 });
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct S5Output {
    /// `Q`, the timer status.
    pub q: bool,
    /// `BI` (`DUAL`): the remaining value in units, binary.
    pub bi: u16,
    /// `BCD` (`DEZ`): the remaining value as three BCD digits with the base in bits 13-12.
    pub bcd: u16,
}

/// The state of one S5 timer as the reference names it: what both implementations show through
/// [`S5TimerOps::state`] and accept in their `from_state` constructors.
///
/// A plain description: any combination of fields can be written here, and
/// [`S5State::is_valid`] says whether it is a state a timer can be in. The types that hold a
/// timer ([`S5TimerRef`], [`S5Timer`], [`TimerWord`]) take a state only through `from_state`,
/// which checks it, so none of them can hold an invalid one.
///
/// ```
/// use plc_timers::s5::S5State;
/// assert!(S5State::RESET.is_valid());
/// assert!(!S5State { value: 1000, ..S5State::RESET }.is_valid());
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct S5State {
    /// Whether the time is running (being decremented by the OS).
    pub running: bool,
    /// The remaining value in units, 0..=999 (binary, LAD manual §9.1 "bits 0-9").
    pub value: u16,
    /// The time base of the running or last value.
    pub base: TimeBase,
    /// The timer status `Q` (what `A T n` scans).
    pub q: bool,
    /// The status the timer takes when its running time runs out (Berger §7: the CPU changes
    /// the status "to 0 or 1, depending on the timer type"): 1 after an on-delay start (SD, SS),
    /// 0 after a pulse or off-delay start (SP, SE, SF). Meaningful only while running; 0 when
    /// stopped.
    pub q_on_expiry: bool,
    /// `S` at the previous execution: the edge memory for starts.
    pub s_prev: bool,
    /// `FR` at the previous execution: the edge memory of the enable.
    pub fr_prev: bool,
}

/// Any valid state ([`S5State::is_valid`]): value 0..=999, any base and flags, an expiry
/// status only on a running timer (feature `bolero`).
#[cfg(feature = "bolero")]
impl bolero_generator::TypeGenerator for S5State {
    fn generate<D: bolero_generator::Driver>(driver: &mut D) -> Option<S5State> {
        use bolero_generator::ValueGenerator;
        let running: bool = driver.produce()?;
        let q_on_expiry: bool = driver.produce()?;
        Some(S5State {
            running,
            value: (0u16..=999).generate(driver)?,
            base: driver.produce()?,
            q: driver.produce()?,
            q_on_expiry: running && q_on_expiry,
            s_prev: driver.produce()?,
            fr_prev: driver.produce()?,
        })
    }
}

impl S5State {
    /// A cleared timer: stopped, value and base 0, Q = 0, edge memories 0.
    pub const RESET: S5State = S5State {
        running: false,
        value: 0,
        base: TimeBase::Ms10,
        q: false,
        q_on_expiry: false,
        s_prev: false,
        fr_prev: false,
    };

    /// The invariant of every reachable state: the value fits its 10 bits and three BCD
    /// digits (0..=999), and a stopped timer has no pending expiry status.
    pub const fn is_valid(&self) -> bool {
        self.value <= 999 && (self.running || !self.q_on_expiry)
    }

    /// The outputs this state shows.
    pub const fn output(&self) -> S5Output {
        S5Output {
            q: self.q,
            bi: self.value,
            bcd: (self.base.bits() as u16) << 12 | crate::time::bcd3_encode(self.value),
        }
    }
}

/// What both S5 timer implementations offer: the box call and the state it leaves.
///
/// `call` executes the box `kind` at CPU time `now` (not before the previous call): the OS
/// ticks of the timer's base since its previous call are applied first (S5TMR-TICK-01), then
/// `FR`, the start logic of the kind and `R`, as the box compiles to STL.
///
/// ```
/// use plc_timers::s5::{S5Input, S5Kind, S5Timer, S5TimerOps, S5TimerRef};
/// use plc_timers::time::CpuTime;
/// fn pulse_length(t: &mut dyn S5TimerOps) -> u64 {
///     let on = S5Input::new(true, false, plc_timers::s5time!("S5T#30MS"));
///     (0..10u64).map(|ms| t.call(S5Kind::SPulse, CpuTime::from_millis(10 * ms), on).q as u64).sum()
/// }
/// assert_eq!(pulse_length(&mut S5TimerRef::new()), 3); // Q = 1 at 0, 10 and 20 ms
/// assert_eq!(pulse_length(&mut S5Timer::new()), 3);
/// ```
pub trait S5TimerOps {
    /// One execution of the box `kind` at `now`. `now` must not go back; a call at an earlier
    /// time than one before it applies no tick and leaves the timer's clock at the latest time,
    /// as a timer memory area does (S5TMR-CLOCK-01).
    fn call(&mut self, kind: S5Kind, now: CpuTime, input: S5Input) -> S5Output;
    /// The state, as the reference names it.
    fn state(&self) -> S5State;
}

/// The number of ticks of `base` in the interval `(from, to]` of the CPU millisecond clock:
/// ticks fall on whole multiples of the base (S5TMR-TICK-01); none when `to` is not after `from`.
///
/// ```
/// use plc_timers::s5::ticks_between;
/// use plc_timers::time::{CpuTime, TimeBase};
/// let at = CpuTime::from_millis;
/// assert_eq!(ticks_between(at(5), at(35), TimeBase::Ms10), 3); // ticks at 10, 20, 30
/// assert_eq!(ticks_between(at(10), at(19), TimeBase::Ms10), 0);
/// ```
pub const fn ticks_between(from: CpuTime, to: CpuTime, base: TimeBase) -> u64 {
    let b = base.millis() as u64;
    (to.as_millis() / b).saturating_sub(from.as_millis() / b)
}

/// The S5 timers as one [`Family`](crate::block::Family) of the block interface: `S`, `R`,
/// `FR` and `TV` in; `Q`, `BI` and `BCD` out; the millisecond clock.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct S5Timers;

impl crate::block::Family for S5Timers {
    type Kind = S5Kind;
    type Input = S5Input;
    type Output = S5Output;
    type State = S5State;
    type Preset = S5Time;
    type PresetError = crate::time::LiteralError;
    type Unit = crate::time::Millis;

    fn kind(block: crate::catalog::Block) -> Option<S5Kind> {
        match block.kind() {
            crate::catalog::Kind::S5Timer(k) => Some(k),
            _ => None,
        }
    }

    #[inline]
    fn input(signals: crate::block::Signals, tv: S5Time) -> S5Input {
        use crate::catalog::Port;
        S5Input::new(signals.get(Port::S), signals.get(Port::R), tv).with_fr(signals.get(Port::Fr))
    }

    #[inline]
    fn values(_: S5Kind, o: &S5Output) -> crate::block::Outputs {
        use crate::block::{Outputs, Value};
        Outputs::three(
            Value::Bool(o.q),
            Value::Int(i128::from(o.bi)),
            Value::Word(o.bcd),
        )
    }

    fn parse_preset(text: &str) -> Result<S5Time, crate::time::LiteralError> {
        S5Time::parse(text.trim())
    }

    fn preset_units(tv: S5Time) -> i128 {
        i128::from(tv.units())
    }

    fn ramp(o: &S5Output) -> Option<u64> {
        // The time base is in bits 13-12 of the BCD output (the word's own layout).
        Some(u64::from(
            crate::time::TimeBase::from_bits((o.bcd >> 12 & 3) as u8).millis(),
        ))
    }

    fn state_fields(s: &S5State) -> crate::block::Fields {
        use crate::block::{Fields, Value};
        Fields::of([
            Value::Bool(s.running),
            Value::Int(i128::from(s.value)),
            Value::Int(i128::from(s.base.millis())),
            Value::Bool(s.q),
            Value::Bool(s.q_on_expiry),
            Value::Bool(s.s_prev),
            Value::Bool(s.fr_prev),
        ])
    }

    fn state_from_fields(fields: &[crate::block::Value]) -> Option<S5State> {
        let [running, value, base, q, q_on_expiry, s_prev, fr_prev] = *fields else {
            return None;
        };
        let base_ms = base.as_int()?;
        Some(S5State {
            running: running.as_bool()?,
            value: u16::try_from(value.as_int()?).ok()?,
            base: crate::time::TimeBase::ALL
                .into_iter()
                .find(|b| i128::from(b.millis()) == base_ms)?,
            q: q.as_bool()?,
            q_on_expiry: q_on_expiry.as_bool()?,
            s_prev: s_prev.as_bool()?,
            fr_prev: fr_prev.as_bool()?,
        })
    }
}

crate::block::block_ops! {
    impl[] S5TimerRef: S5Timers,
    call: |t, kind, now, input| S5TimerOps::call(t, kind, now, input),
    state: S5TimerOps::state,
    from_state: |state, last_call| S5TimerRef::from_state(state, last_call),
    last_call: S5TimerRef::last_call,
    explains: |t, kind, now, input| t.call_explained(kind, now, input),
}

crate::block::block_ops! {
    impl[] S5Timer: S5Timers,
    call: |t, kind, now, input| S5TimerOps::call(t, kind, now, input),
    state: S5TimerOps::state,
    from_state: |state, last_call| S5Timer::from_state(state, last_call),
    last_call: S5Timer::last_call,
}
