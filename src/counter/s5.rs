//! The S5 counters of S7-300/400: `S_CU`, `S_CD`, `S_CUD` (STL `CU`/`CD`/`S`/`R`/`L C`/`LC C`,
//! German `ZV`/`ZR`/`S`/`R`/`L Z`/`LC Z`), the same family as the S5 timers (semantics brief §4).
//!
//! CV is 0..=999 and saturates at both ends; the preset is `C#0`..`C#999`, loaded as three BCD
//! digits; Q = CV != 0. [`S5CounterRef`] states the rules; [`S5CounterCell`] packs a counter in
//! one 16-bit word, and [`CounterMemory`] is a counter memory area with the STL operations.

use core::fmt;

use crate::time::bcd3_encode;

/// Which S5 counter box.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(kani, derive(kani::Arbitrary))]
pub enum S5CounterKind {
    /// `S_CU` (German `Z_VORW`): up counter (no CD input).
    #[doc(alias = "Z_VORW")]
    SCu,
    /// `S_CD` (German `Z_RUECK`): down counter (no CU input).
    #[doc(alias = "Z_RUECK")]
    SCd,
    /// `S_CUD` (German `ZAEHLER`): up-down counter.
    #[doc(alias = "ZAEHLER")]
    SCud,
}

impl S5CounterKind {
    /// All three.
    pub const ALL: [S5CounterKind; 3] =
        [S5CounterKind::SCu, S5CounterKind::SCd, S5CounterKind::SCud];

    /// The box name.
    pub const fn name(self) -> &'static str {
        match self {
            S5CounterKind::SCu => "S_CU",
            S5CounterKind::SCd => "S_CD",
            S5CounterKind::SCud => "S_CUD",
        }
    }

    /// The inputs this box has: S_CU has no CD, S_CD no CU (SC-INPUTS-01).
    pub const fn mask(self, input: S5CounterInput) -> S5CounterInput {
        match self {
            S5CounterKind::SCu => S5CounterInput { cd: false, ..input },
            S5CounterKind::SCd => S5CounterInput { cu: false, ..input },
            S5CounterKind::SCud => input,
        }
    }
}

/// The largest counter value.
pub const CV_MAX: u16 = 999;

/// A counter preset `PV`: 0..=999 (a `C#` value).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct CounterPreset(u16);

/// What was wrong with a counter preset.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CounterPresetError {
    /// Not `C#n`, a whole number or `W#16#xyz`.
    Syntax,
    /// Above 999 (the value given, saturated at `u32::MAX`).
    OutOfRange(u32),
    /// A BCD digit above 9 in a `W#16#` word (the word).
    BcdDigit(u16),
}

impl fmt::Display for CounterPresetError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            CounterPresetError::Syntax => {
                write!(
                    f,
                    "not a counter preset; write C#0 to C#999, 0 to 999, or W#16#0000 to W#16#0999"
                )
            }
            CounterPresetError::OutOfRange(v) => {
                write!(f, "{v} is above the S5 counter maximum of 999")
            }
            CounterPresetError::BcdDigit(w) => write!(
                f,
                "W#16#{w:04X} is not a BCD count: every digit must be 0-9 and the value at most 999"
            ),
        }
    }
}

#[cfg(feature = "std")]
impl std::error::Error for CounterPresetError {}

impl CounterPreset {
    /// The preset `n`, 0..=999.
    pub const fn new(n: u16) -> Result<CounterPreset, CounterPresetError> {
        if n > CV_MAX {
            Err(CounterPresetError::OutOfRange(n as u32))
        } else {
            Ok(CounterPreset(n))
        }
    }

    /// The preset from its BCD word as `S C n` takes it from ACCU 1 (SC-BCD-01): three BCD
    /// digits, each checked; bits 15-12 must be 0.
    pub const fn from_bcd(word: u16) -> Result<CounterPreset, CounterPresetError> {
        let (h, t, o) = ((word >> 8) & 0xF, (word >> 4) & 0xF, word & 0xF);
        if word > 0x0999 || h > 9 || t > 9 || o > 9 {
            return Err(CounterPresetError::BcdDigit(word));
        }
        Ok(CounterPreset(h * 100 + t * 10 + o))
    }

    /// The count, 0..=999.
    pub const fn value(self) -> u16 {
        self.0
    }

    /// The BCD word (`W#16#0xyz`).
    pub const fn to_bcd(self) -> u16 {
        bcd3_encode(self.0)
    }
}

impl core::str::FromStr for CounterPreset {
    type Err = CounterPresetError;

    /// `C#n` (n decimal, 0..=999), a whole number 0..=999, or `W#16#xyz` (BCD checked).
    ///
    /// ```
    /// use plc_timers::counter::s5::CounterPreset;
    /// assert_eq!("C#5".parse::<CounterPreset>().map(|p| p.value()), Ok(5));
    /// assert!("C#1000".parse::<CounterPreset>().is_err());
    /// assert!("W#16#00A1".parse::<CounterPreset>().is_err());
    /// ```
    fn from_str(text: &str) -> Result<CounterPreset, CounterPresetError> {
        let t = text.trim();
        let upper_prefix = |p: &str| {
            t.len() >= p.len()
                && t.is_char_boundary(p.len())
                && t[..p.len()].eq_ignore_ascii_case(p)
        };
        if upper_prefix("W#16#") {
            let hex = &t[5..];
            if hex.is_empty() || hex.len() > 4 {
                return Err(CounterPresetError::Syntax);
            }
            let word = u16::from_str_radix(hex, 16).map_err(|_| CounterPresetError::Syntax)?;
            return CounterPreset::from_bcd(word);
        }
        let digits = if upper_prefix("C#") { &t[2..] } else { t };
        if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
            return Err(CounterPresetError::Syntax);
        }
        let n: u32 = digits.parse().unwrap_or(u32::MAX);
        if n > u32::from(CV_MAX) {
            return Err(CounterPresetError::OutOfRange(n));
        }
        CounterPreset::new(n as u16)
    }
}

/// The inputs of one S5 counter box call.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct S5CounterInput {
    /// `CU` (`ZV`), count up on a rising edge.
    pub cu: bool,
    /// `CD` (`ZR`), count down on a rising edge.
    pub cd: bool,
    /// `S`, set CV to PV on a rising edge.
    pub s: bool,
    /// `R`, reset CV to 0 (level).
    pub r: bool,
    /// `PV`.
    pub pv: CounterPreset,
}

/// The outputs of one S5 counter box call.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct S5CounterOutput {
    /// `Q`: CV != 0.
    pub q: bool,
    /// `CV` (`DUAL`), binary.
    pub cv: u16,
    /// `CV_BCD` (`DEZ`), three BCD digits.
    pub cv_bcd: u16,
}

/// The state of an S5 counter as the reference names it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct S5CounterState {
    /// `CV`, 0..=999.
    pub cv: u16,
    /// Edge memory of CU.
    pub cu_prev: bool,
    /// Edge memory of CD.
    pub cd_prev: bool,
    /// Edge memory of S.
    pub s_prev: bool,
}

impl S5CounterState {
    /// The invariant: CV <= 999 (SC-RANGE-01).
    pub const fn is_valid(&self) -> bool {
        self.cv <= CV_MAX
    }

    /// The outputs this state shows (SC-Q-01: Q = CV != 0).
    pub const fn output(&self) -> S5CounterOutput {
        S5CounterOutput {
            q: self.cv != 0,
            cv: self.cv,
            cv_bcd: bcd3_encode(self.cv),
        }
    }
}

/// The reference S5 counter.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct S5CounterRef {
    /// The box.
    pub kind: S5CounterKind,
    /// The state.
    pub state: S5CounterState,
}

impl S5CounterRef {
    /// A new counter: CV = 0.
    pub const fn new(kind: S5CounterKind) -> S5CounterRef {
        S5CounterRef {
            kind,
            state: S5CounterState {
                cv: 0,
                cu_prev: false,
                cd_prev: false,
                s_prev: false,
            },
        }
    }

    /// One box call. SC-EDGE-01: CU, CD and S act on rising edges, their memories updated on
    /// every call; SC-SAT-01: CV stays within 0..=999; SC-SIMUL-01: rising CU and CD together
    /// leave CV unchanged; SC-PRIO-01: R (level) over S over counting.
    pub fn call(&mut self, input: S5CounterInput) -> S5CounterOutput {
        let i = self.kind.mask(input);
        let s = &mut self.state;
        let up = i.cu && !s.cu_prev;
        let down = i.cd && !s.cd_prev;
        let set = i.s && !s.s_prev;
        s.cu_prev = i.cu;
        s.cd_prev = i.cd;
        s.s_prev = i.s;
        if up && !down && s.cv < CV_MAX {
            s.cv += 1;
        }
        if down && !up && s.cv > 0 {
            s.cv -= 1;
        }
        if set {
            s.cv = i.pv.value();
        }
        if i.r {
            s.cv = 0;
        }
        s.output()
    }
}

const CV: u16 = 0x03FF;
const CU_PREV: u16 = 1 << 12;
const CD_PREV: u16 = 1 << 13;
const S_PREV: u16 = 1 << 14;
// The four fields are disjoint (their sum is their union), so `|` of two of them is `^` and `+`.
const _: () = assert!(CV + CU_PREV + CD_PREV + S_PREV == CV | CU_PREV | CD_PREV | S_PREV);

/// The optimized S5 counter: CV in bits 9-0, the edge memories of CU, CD and S in bits 12-14.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[repr(transparent)]
pub struct S5CounterCell(pub u16);

impl S5CounterCell {
    /// The cell holding `state`, if CV <= 999.
    pub const fn from_state(state: S5CounterState) -> Option<S5CounterCell> {
        if !state.is_valid() {
            return None;
        }
        Some(S5CounterCell(
            state.cv
                | ((state.cu_prev as u16) * CU_PREV)
                | ((state.cd_prev as u16) * CD_PREV)
                | ((state.s_prev as u16) * S_PREV),
        ))
    }

    /// The abstraction function.
    pub const fn abstraction(self) -> S5CounterState {
        S5CounterState {
            cv: self.0 & CV,
            cu_prev: self.0 & CU_PREV != 0,
            cd_prev: self.0 & CD_PREV != 0,
            s_prev: self.0 & S_PREV != 0,
        }
    }

    /// One box call (the inputs already masked for the kind).
    #[inline]
    pub const fn step(self, i: S5CounterInput) -> S5CounterCell {
        let w = self.0;
        let now = ((i.cu as u16) * CU_PREV) | ((i.cd as u16) * CD_PREV) | ((i.s as u16) * S_PREV);
        let rising = now & !w;
        let cv = w & CV;
        let cv = match rising & (CU_PREV | CD_PREV) {
            CU_PREV => cv + (cv < CV_MAX) as u16,
            CD_PREV => cv - (cv > 0) as u16,
            _ => cv,
        };
        let cv = if rising & S_PREV != 0 {
            i.pv.value()
        } else {
            cv
        };
        let cv = if i.r { 0 } else { cv };
        S5CounterCell(now | cv)
    }

    /// The outputs (BCD by table lookup).
    pub const fn output(self) -> S5CounterOutput {
        let cv = self.0 & CV;
        S5CounterOutput {
            q: cv != 0,
            cv,
            cv_bcd: crate::s5::cell::BCD_TABLE[cv as usize],
        }
    }
}

/// An STL operation named a counter the area does not have.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NoSuchCounter {
    /// The number given.
    pub index: usize,
    /// How many counters the area has.
    pub count: usize,
}

impl fmt::Display for NoSuchCounter {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "no counter C {}: this area has C 0 to C {}",
            self.index,
            self.count.saturating_sub(1)
        )
    }
}

#[cfg(feature = "std")]
impl std::error::Error for NoSuchCounter {}

/// A counter memory area of `N` S5 counters (256 by default).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CounterMemory<const N: usize = 256> {
    cells: [S5CounterCell; N],
}

impl<const N: usize> Default for CounterMemory<N> {
    fn default() -> Self {
        CounterMemory::new()
    }
}

impl<const N: usize> CounterMemory<N> {
    /// An area of cleared counters.
    pub const fn new() -> CounterMemory<N> {
        CounterMemory {
            cells: [S5CounterCell(0); N],
        }
    }

    fn cell(&mut self, index: usize) -> Result<&mut S5CounterCell, NoSuchCounter> {
        self.cells
            .get_mut(index)
            .ok_or(NoSuchCounter { index, count: N })
    }

    fn read(&self, index: usize) -> Result<S5CounterCell, NoSuchCounter> {
        self.cells
            .get(index)
            .copied()
            .ok_or(NoSuchCounter { index, count: N })
    }

    /// Applies one STL operation to counter `index`: only the input it names changes; the other
    /// edge memories keep their value (the operation does not see those inputs).
    fn op(
        &mut self,
        index: usize,
        f: impl Fn(S5CounterState) -> S5CounterInput,
    ) -> Result<(), NoSuchCounter> {
        let c = self.cell(index)?;
        *c = c.step(f(c.abstraction()));
        Ok(())
    }

    /// `CU C n` (`ZV Z n`) with RLO `rlo`: count up on a rising RLO.
    pub fn cu(&mut self, index: usize, rlo: bool) -> Result<(), NoSuchCounter> {
        self.op(index, |s| S5CounterInput {
            cu: rlo,
            cd: s.cd_prev,
            s: s.s_prev,
            ..Default::default()
        })
    }

    /// `CD C n` (`ZR Z n`) with RLO `rlo`: count down on a rising RLO.
    pub fn cd(&mut self, index: usize, rlo: bool) -> Result<(), NoSuchCounter> {
        self.op(index, |s| S5CounterInput {
            cu: s.cu_prev,
            cd: rlo,
            s: s.s_prev,
            ..Default::default()
        })
    }

    /// `S C n` with RLO `rlo` and the preset in ACCU 1: set CV to PV on a rising RLO.
    pub fn set(&mut self, index: usize, rlo: bool, pv: CounterPreset) -> Result<(), NoSuchCounter> {
        self.op(index, |s| S5CounterInput {
            cu: s.cu_prev,
            cd: s.cd_prev,
            s: rlo,
            r: false,
            pv,
        })
    }

    /// `R C n` with RLO `rlo`: CV = 0 while 1.
    pub fn reset(&mut self, index: usize, rlo: bool) -> Result<(), NoSuchCounter> {
        self.op(index, |s| S5CounterInput {
            cu: s.cu_prev,
            cd: s.cd_prev,
            s: s.s_prev,
            r: rlo,
            ..Default::default()
        })
    }

    /// `L C n`: CV in binary.
    pub fn load(&self, index: usize) -> Result<u16, NoSuchCounter> {
        self.read(index).map(|c| c.output().cv)
    }

    /// `LC C n`: CV in BCD.
    pub fn load_bcd(&self, index: usize) -> Result<u16, NoSuchCounter> {
        self.read(index).map(|c| c.output().cv_bcd)
    }

    /// `A C n`: Q = CV != 0.
    pub fn status(&self, index: usize) -> Result<bool, NoSuchCounter> {
        self.read(index).map(|c| c.output().q)
    }

    /// The box `kind` on counter `index`: all inputs in one step.
    pub fn call(
        &mut self,
        index: usize,
        kind: S5CounterKind,
        input: S5CounterInput,
    ) -> Result<S5CounterOutput, NoSuchCounter> {
        let c = self.cell(index)?;
        *c = c.step(kind.mask(input));
        Ok(c.output())
    }
}
