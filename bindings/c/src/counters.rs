//! The counters: IEC counters (`CTU`, `CTD`, `CTUD`) over the eight integer types, and S5
//! counters (`S_CU`, `S_CD`, `S_CUD`), each in its reference and its optimized form.
//!
//! The IEC counters' structs are generic here and monomorphic in C: cbindgen writes one struct
//! per integer type (`plc_timers_counter_input_int16_t`, …) and the type names of the manual
//! as typedefs (`plc_timers_counter_int_input` for INT, …). The functions are registered per
//! type by one line (`iec_counter!`) on the generic bodies of `export` (C has no generics;
//! cbindgen reads the crate macro-expanded).

use plc_timers::block::BlockOps;
use plc_timers::counter::s5::{
    CounterPreset, S5Counter, S5CounterInput, S5CounterKind, S5CounterRef, S5CounterState,
};
use plc_timers::counter::{
    Counter, CounterInput, CounterInt, CounterKind, CounterOutput, CounterRef, CounterState,
};

use crate::export::{export, CInput, CKind};
use crate::status::plc_timers_status::{self, *};
use crate::{bit, flag, Mirror};

// ---------------------------------------------------------------------------------------------
// IEC counters

/// The IEC counter instructions. Passed as `int32_t`.
#[repr(i32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum plc_timers_counter_kind {
    /// `CTU`, count up (inputs CU, R; output QU as Q).
    PLC_TIMERS_CTU = 0,
    /// `CTD`, count down (inputs CD, LD; output QD as Q).
    PLC_TIMERS_CTD = 1,
    /// `CTUD`, count up and down (inputs CU, CD, R, LD; outputs QU, QD).
    PLC_TIMERS_CTUD = 2,
}

impl CKind for CounterKind {
    fn from_c(kind: i32) -> Result<CounterKind, plc_timers_status> {
        Ok(match kind {
            0 => CounterKind::Ctu,
            1 => CounterKind::Ctd,
            2 => CounterKind::Ctud,
            _ => return Err(PLC_TIMERS_INVALID_KIND),
        })
    }
}

/// The inputs of one call of an IEC counter over the integer type `T`. The inputs an
/// instruction lacks (CD and LD of CTU, CU and R of CTD) are ignored. The input bits are bytes:
/// 0 is FALSE, any other value TRUE.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct plc_timers_counter_input<T> {
    /// `CU`, count up on a rising edge.
    pub cu: u8,
    /// `CD`, count down on a rising edge.
    pub cd: u8,
    /// `R`, reset CV to 0 (level).
    pub r: u8,
    /// `LD`, load PV into CV (level).
    pub ld: u8,
    /// `PV`, the preset.
    pub pv: T,
}

/// The outputs of one call of an IEC counter over the integer type `T`. CTU's `Q` is `qu`,
/// CTD's `Q` is `qd`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct plc_timers_counter_output<T> {
    /// `QU`: CV >= PV.
    pub qu: bool,
    /// `QD`: CV <= 0.
    pub qd: bool,
    /// `CV`, the count; it stays at the type's limits, never wraps.
    pub cv: T,
}

/// The state of one IEC counter for the reference semantics (`plc_timers_counter_*_ref_*`).
/// All zero is a new counter. The edge memories have the type of CV so that the struct has no
/// padding: every byte of it is defined (a checksum over retentive instance data, `memcmp`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct plc_timers_counter_ref<T> {
    /// `CV`.
    pub cv: T,
    /// `CU` at the previous call (the edge memory), 0 or 1.
    pub cu_prev: T,
    /// `CD` at the previous call (the edge memory), 0 or 1.
    pub cd_prev: T,
}

/// The state of one IEC counter for the optimized implementation (`plc_timers_counter_*_*`):
/// CV and the edge memories, the size of the library's `Counter` (twice the integer type's) but
/// without its padding, so that every byte is defined. All zero is a new counter.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct plc_timers_counter<T> {
    /// `CV`.
    pub cv: T,
    /// Bit 0: `CU` at the previous call; bit 1: `CD` at the previous call; the other bits 0.
    pub edges: T,
}

/// 0 or 1 of the integer type `T` for `b`.
fn int_flag<T: CounterInt>(b: bool) -> T {
    // 0 and 1 are in every counter type's range; ZERO is the fallback no call reaches.
    T::from_i128(i128::from(b)).unwrap_or(T::ZERO)
}

/// `b` for 0 or 1 of `T`, `None` for any other value.
fn int_flag_value<T: CounterInt>(v: T) -> Option<bool> {
    match v.to_i128() {
        0 => Some(false),
        1 => Some(true),
        _ => None,
    }
}

impl<T: CounterInt> Mirror for plc_timers_counter_ref<T> {
    type Core = CounterRef<T>;

    fn load(&self) -> Option<CounterRef<T>> {
        Some(CounterRef::from_state(CounterState {
            cv: self.cv,
            cu_prev: int_flag_value(self.cu_prev)?,
            cd_prev: int_flag_value(self.cd_prev)?,
        }))
    }

    fn store(c: &CounterRef<T>) -> Self {
        let s = c.state();
        plc_timers_counter_ref {
            cv: s.cv,
            cu_prev: int_flag(s.cu_prev),
            cd_prev: int_flag(s.cd_prev),
        }
    }
}

/// The edge bits of `plc_timers_counter::edges`.
const CU_PREV: u8 = 1;
const CD_PREV: u8 = 2;

impl<T: CounterInt> Mirror for plc_timers_counter<T> {
    type Core = Counter<T>;

    fn load(&self) -> Option<Counter<T>> {
        let edges = u8::try_from(self.edges.to_i128()).ok()?;
        if edges & !(CU_PREV | CD_PREV) != 0 {
            return None;
        }
        Some(Counter::from_state(CounterState {
            cv: self.cv,
            cu_prev: edges & CU_PREV != 0,
            cd_prev: edges & CD_PREV != 0,
        }))
    }

    fn store(c: &Counter<T>) -> Self {
        let s = c.state();
        let edges = if s.cu_prev { CU_PREV } else { 0 } | if s.cd_prev { CD_PREV } else { 0 };
        plc_timers_counter {
            cv: s.cv,
            // 0 to 3 is in every counter type's range; ZERO is the fallback no call reaches.
            edges: T::from_i128(i128::from(edges)).unwrap_or(T::ZERO),
        }
    }
}

impl<T: CounterInt> CInput<CounterInput<T>> for plc_timers_counter_input<T> {
    fn load(self) -> Result<CounterInput<T>, plc_timers_status> {
        Ok(CounterInput {
            cu: bit(self.cu),
            cd: bit(self.cd),
            r: bit(self.r),
            ld: bit(self.ld),
            pv: self.pv,
        })
    }
}

impl<T: CounterInt> From<CounterOutput<T>> for plc_timers_counter_output<T> {
    fn from(o: CounterOutput<T>) -> Self {
        plc_timers_counter_output {
            qu: o.qu,
            qd: o.qd,
            cv: o.cv,
        }
    }
}

// ---------------------------------------------------------------------------------------------
// S5 counters

/// The S5 counter boxes. Passed as `int32_t`.
#[repr(i32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum plc_timers_s5_counter_kind {
    /// `S_CU` (German `Z_VORW`): count up.
    PLC_TIMERS_S_CU = 0,
    /// `S_CD` (German `Z_RUECK`): count down.
    PLC_TIMERS_S_CD = 1,
    /// `S_CUD` (German `ZAEHLER`): count up and down.
    PLC_TIMERS_S_CUD = 2,
}

/// The S5 counter kind `kind` stands for.
pub(crate) fn s5_counter_kind(kind: i32) -> Result<S5CounterKind, plc_timers_status> {
    Ok(match kind {
        0 => S5CounterKind::SCu,
        1 => S5CounterKind::SCd,
        2 => S5CounterKind::SCud,
        _ => return Err(PLC_TIMERS_INVALID_KIND),
    })
}

impl CKind for S5CounterKind {
    fn from_c(kind: i32) -> Result<S5CounterKind, plc_timers_status> {
        s5_counter_kind(kind)
    }
}

/// An S5 counter value or preset in binary: the count itself, 0 to 999 (`C#5` is 5, `C#123`
/// is 123). What `L C n` loads and what `plc_timers_counter_preset_parse` writes.
pub type plc_timers_s5_count = u16;

/// An S5 counter value or preset as the PLC holds a `C#` constant: three BCD digits in bits
/// 11-0, bits 15-12 zero (`C#5` is `W#16#0005`, `C#123` is `W#16#0123`). What `LC C n` loads and
/// what `S C n` takes from ACCU 1. The `_bcd` functions take it and check every digit; it is
/// never taken for a count (0x0123 is 123, not 291).
pub type plc_timers_bcd_word = u16;

/// The S5 counter preset of the count `pv`.
pub(crate) fn counter_preset(pv: plc_timers_s5_count) -> Result<CounterPreset, plc_timers_status> {
    CounterPreset::new(pv).map_err(|_| PLC_TIMERS_INVALID_PRESET)
}

/// The S5 counter preset of the BCD word `pv_bcd` (SC-BCD-01: each digit checked).
pub(crate) fn counter_preset_bcd(
    pv_bcd: plc_timers_bcd_word,
) -> Result<CounterPreset, plc_timers_status> {
    CounterPreset::from_bcd(pv_bcd).map_err(|_| PLC_TIMERS_INVALID_BCD_PRESET)
}

/// The inputs of one S5 counter box call, the preset as a count (binary). The inputs a box
/// lacks (CD of S_CU, CU of S_CD) are ignored. The input bits are bytes: 0 is FALSE, any other
/// value TRUE. `plc_timers_s5_counter_input_bcd` is the same with the preset as a BCD word.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct plc_timers_s5_counter_input {
    /// `CU` (`ZV`), count up on a rising edge.
    pub cu: u8,
    /// `CD` (`ZR`), count down on a rising edge.
    pub cd: u8,
    /// `S`, set CV to PV on a rising edge.
    pub s: u8,
    /// `R`, reset CV to 0 (level).
    pub r: u8,
    /// `FR`, the enable (STL `FR C n`; the LAD boxes have none: 0).
    pub fr: u8,
    /// `PV`, the preset as a count 0 to 999 (binary: `C#5` is 5, `C#123` is 123), e.g. from
    /// `plc_timers_counter_preset_parse`; above 999 is `PLC_TIMERS_INVALID_PRESET`.
    pub pv: plc_timers_s5_count,
}

/// The inputs of one S5 counter box call with the preset as the PLC holds it, a BCD word
/// (`C#123` is `W#16#0123`); otherwise as `plc_timers_s5_counter_input`. A word with a digit
/// above 9 or bits 15-12 set is `PLC_TIMERS_INVALID_BCD_PRESET`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct plc_timers_s5_counter_input_bcd {
    /// `CU` (`ZV`), count up on a rising edge.
    pub cu: u8,
    /// `CD` (`ZR`), count down on a rising edge.
    pub cd: u8,
    /// `S`, set CV to PV on a rising edge.
    pub s: u8,
    /// `R`, reset CV to 0 (level).
    pub r: u8,
    /// `FR`, the enable (STL `FR C n`; the LAD boxes have none: 0).
    pub fr: u8,
    /// `PV`, the preset as a BCD word (`W#16#0000` to `W#16#0999`).
    pub pv_bcd: plc_timers_bcd_word,
}

impl CInput<S5CounterInput> for plc_timers_s5_counter_input {
    fn load(self) -> Result<S5CounterInput, plc_timers_status> {
        Ok(S5CounterInput {
            cu: bit(self.cu),
            cd: bit(self.cd),
            s: bit(self.s),
            r: bit(self.r),
            fr: bit(self.fr),
            pv: counter_preset(self.pv)?,
        })
    }
}

impl CInput<S5CounterInput> for plc_timers_s5_counter_input_bcd {
    fn load(self) -> Result<S5CounterInput, plc_timers_status> {
        Ok(S5CounterInput {
            cu: bit(self.cu),
            cd: bit(self.cd),
            s: bit(self.s),
            r: bit(self.r),
            fr: bit(self.fr),
            pv: counter_preset_bcd(self.pv_bcd)?,
        })
    }
}

/// The outputs of one S5 counter box call.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct plc_timers_s5_counter_output {
    /// `Q`: CV != 0.
    pub q: bool,
    /// `CV` (`DUAL`), the count in binary, 0 to 999.
    pub cv: plc_timers_s5_count,
    /// `CV_BCD` (`DEZ`), the count as three BCD digits.
    pub cv_bcd: plc_timers_bcd_word,
}

impl From<plc_timers::counter::s5::S5CounterOutput> for plc_timers_s5_counter_output {
    fn from(o: plc_timers::counter::s5::S5CounterOutput) -> Self {
        plc_timers_s5_counter_output {
            q: o.q,
            cv: o.cv,
            cv_bcd: o.cv_bcd,
        }
    }
}

/// The state of one S5 counter for the reference semantics (`plc_timers_s5_counter_ref_*`).
/// 6 bytes, alignment 2; all zero is a cleared counter.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct plc_timers_s5_counter_ref {
    /// `CV`, 0 to 999.
    pub cv: u16,
    /// `CU` at the previous call (edge memory), 0 or 1.
    pub cu_prev: u8,
    /// `CD` at the previous call (edge memory), 0 or 1.
    pub cd_prev: u8,
    /// `S` at the previous call (edge memory), 0 or 1.
    pub s_prev: u8,
    /// `FR` at the previous call (edge memory), 0 or 1.
    pub fr_prev: u8,
}

impl Mirror for plc_timers_s5_counter_ref {
    type Core = S5CounterRef;

    fn load(&self) -> Option<S5CounterRef> {
        S5CounterRef::from_state(S5CounterState {
            cv: self.cv,
            cu_prev: flag(self.cu_prev)?,
            cd_prev: flag(self.cd_prev)?,
            s_prev: flag(self.s_prev)?,
            fr_prev: flag(self.fr_prev)?,
        })
    }

    fn store(c: &S5CounterRef) -> Self {
        let s = c.state();
        plc_timers_s5_counter_ref {
            cv: s.cv,
            cu_prev: s.cu_prev.into(),
            cd_prev: s.cd_prev.into(),
            s_prev: s.s_prev.into(),
            fr_prev: s.fr_prev.into(),
        }
    }
}

/// The state of one S5 counter for the optimized implementation (`plc_timers_s5_counter_*`): the
/// CPU's 16-bit counter word. All zero is a cleared counter.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct plc_timers_s5_counter {
    /// The counter word: bits 9-0 CV (binary, 0 to 999), bits 12-15 the edge memories of CU,
    /// CD, S and FR; the other bits 0.
    pub word: u16,
}

impl Mirror for plc_timers_s5_counter {
    type Core = S5Counter;

    fn load(&self) -> Option<S5Counter> {
        S5Counter::from_bits(self.word)
    }

    fn store(c: &S5Counter) -> Self {
        plc_timers_s5_counter { word: c.bits() }
    }
}

const _: () = assert!(core::mem::size_of::<plc_timers_s5_counter_ref>() == 6);
const _: () = assert!(core::mem::size_of::<plc_timers_s5_counter>() == 2);
// The optimized counter is as large as the library's (whose padding it fills with edges' type).
const _: () =
    assert!(core::mem::size_of::<plc_timers_counter<i8>>() == core::mem::size_of::<Counter<i8>>());
const _: () = assert!(
    core::mem::size_of::<plc_timers_counter<i16>>() == core::mem::size_of::<Counter<i16>>()
);
const _: () = assert!(
    core::mem::size_of::<plc_timers_counter<i32>>() == core::mem::size_of::<Counter<i32>>()
);
const _: () = assert!(
    core::mem::size_of::<plc_timers_counter<u64>>() == core::mem::size_of::<Counter<u64>>()
);

// ---------------------------------------------------------------------------------------------
// The IEC counters per integer type: one line each, registering the four functions and naming
// the four structs after the manual's type

/// The typedefs and the functions of the IEC counters over one integer type: the manual's name
/// of the type, its Rust type, the four typedef names and the four function names.
macro_rules! iec_counter {
    ($t:literal $int:ty: $input:ident $output:ident $sref:ident $sopt:ident, $ref_init:ident $init:ident $ref_call:ident $call:ident) => {
        #[doc = concat!(" The inputs of an IEC counter of type ", $t, " (`", stringify!($int), "` in Rust).")]
        pub type $input = plc_timers_counter_input<$int>;
        #[doc = concat!(" The outputs of an IEC counter of type ", $t, ".")]
        pub type $output = plc_timers_counter_output<$int>;
        #[doc = concat!(" The state of an IEC counter of type ", $t, ", reference form.")]
        pub type $sref = plc_timers_counter_ref<$int>;
        #[doc = concat!(" The state of an IEC counter of type ", $t, ", optimized form.")]
        pub type $sopt = plc_timers_counter<$int>;
        export!(
            #[doc = concat!(" Initializes an IEC counter of type ", $t, " (reference form): CV = 0, no edge seen (the same as zeroing the struct).")]
            init $ref_init(counter: $sref)
        );
        export!(
            #[doc = concat!(" Initializes an IEC counter of type ", $t, " (optimized form): CV = 0, no edge seen (the same as zeroing the struct).")]
            init $init(counter: $sopt)
        );
        export!(
            #[doc = concat!(" One call of the IEC counter instruction `kind` (`plc_timers_counter_kind`) on a counter of type ", $t, ", by the reference semantics: edges of CU and CD, then R before LD before counting; CV stays at the type's limits. The outputs are written to `out`.")]
            ///
            /// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`
            /// (`counter` or `out`); `PLC_TIMERS_INVALID_KIND`; `PLC_TIMERS_INVALID_STATE` (`*counter`).
            call $ref_call(counter: $sref, kind, input: $input, out: $output)
        );
        export!(
            #[doc = concat!(" One call of the IEC counter instruction `kind` on a counter of type ", $t, ", by the optimized implementation: the same as `", stringify!($ref_call), "`.")]
            ///
            /// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`
            /// (`counter` or `out`); `PLC_TIMERS_INVALID_KIND`; `PLC_TIMERS_INVALID_STATE` (`*counter`).
            call $call(counter: $sopt, kind, input: $input, out: $output)
        );
    };
}

iec_counter!("SINT" i8: plc_timers_counter_sint_input plc_timers_counter_sint_output plc_timers_counter_sint_ref plc_timers_counter_sint, plc_timers_counter_sint_ref_init plc_timers_counter_sint_init plc_timers_counter_sint_ref_call plc_timers_counter_sint_call);
iec_counter!("INT" i16: plc_timers_counter_int_input plc_timers_counter_int_output plc_timers_counter_int_ref plc_timers_counter_int, plc_timers_counter_int_ref_init plc_timers_counter_int_init plc_timers_counter_int_ref_call plc_timers_counter_int_call);
iec_counter!("DINT" i32: plc_timers_counter_dint_input plc_timers_counter_dint_output plc_timers_counter_dint_ref plc_timers_counter_dint, plc_timers_counter_dint_ref_init plc_timers_counter_dint_init plc_timers_counter_dint_ref_call plc_timers_counter_dint_call);
iec_counter!("LINT" i64: plc_timers_counter_lint_input plc_timers_counter_lint_output plc_timers_counter_lint_ref plc_timers_counter_lint, plc_timers_counter_lint_ref_init plc_timers_counter_lint_init plc_timers_counter_lint_ref_call plc_timers_counter_lint_call);
iec_counter!("USINT" u8: plc_timers_counter_usint_input plc_timers_counter_usint_output plc_timers_counter_usint_ref plc_timers_counter_usint, plc_timers_counter_usint_ref_init plc_timers_counter_usint_init plc_timers_counter_usint_ref_call plc_timers_counter_usint_call);
iec_counter!("UINT" u16: plc_timers_counter_uint_input plc_timers_counter_uint_output plc_timers_counter_uint_ref plc_timers_counter_uint, plc_timers_counter_uint_ref_init plc_timers_counter_uint_init plc_timers_counter_uint_ref_call plc_timers_counter_uint_call);
iec_counter!("UDINT" u32: plc_timers_counter_udint_input plc_timers_counter_udint_output plc_timers_counter_udint_ref plc_timers_counter_udint, plc_timers_counter_udint_ref_init plc_timers_counter_udint_init plc_timers_counter_udint_ref_call plc_timers_counter_udint_call);
iec_counter!("ULINT" u64: plc_timers_counter_ulint_input plc_timers_counter_ulint_output plc_timers_counter_ulint_ref plc_timers_counter_ulint, plc_timers_counter_ulint_ref_init plc_timers_counter_ulint_init plc_timers_counter_ulint_ref_call plc_timers_counter_ulint_call);

// ---------------------------------------------------------------------------------------------
// The S5 counters

export!(
    /// Initializes an S5 counter (reference form): CV = 0, edge memories 0 (the same as zeroing
    /// the struct).
    init plc_timers_s5_counter_ref_init(counter: plc_timers_s5_counter_ref)
);
export!(
    /// One call of the S5 counter box `kind` (`plc_timers_s5_counter_kind`), by the reference
    /// semantics: `FR`, `CU`, `CD`, `S`, `R` in the order the box compiles to STL; CV
    /// stays in 0 to 999. The outputs are written to `out`.
    ///
    /// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`
    /// (`counter` or `out`); `PLC_TIMERS_INVALID_KIND`; `PLC_TIMERS_INVALID_PRESET` (`input.pv`
    /// above 999); `PLC_TIMERS_INVALID_STATE` (`*counter`).
    call plc_timers_s5_counter_ref_call(counter: plc_timers_s5_counter_ref, kind, input: plc_timers_s5_counter_input, out: plc_timers_s5_counter_output)
);
export!(
    /// Initializes an S5 counter (optimized form): CV = 0, edge memories 0 (the same as zeroing
    /// the struct).
    init plc_timers_s5_counter_init(counter: plc_timers_s5_counter)
);
export!(
    /// One call of the S5 counter box `kind` (`plc_timers_s5_counter_kind`), by the optimized
    /// implementation: `FR`, `CU`, `CD`, `S`, `R` in the order the box compiles to STL; CV
    /// stays in 0 to 999. The outputs are written to `out`.
    ///
    /// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`
    /// (`counter` or `out`); `PLC_TIMERS_INVALID_KIND`; `PLC_TIMERS_INVALID_PRESET` (`input.pv`
    /// above 999); `PLC_TIMERS_INVALID_STATE` (`*counter`).
    call plc_timers_s5_counter_call(counter: plc_timers_s5_counter, kind, input: plc_timers_s5_counter_input, out: plc_timers_s5_counter_output)
);
export!(
    /// `plc_timers_s5_counter_ref_call` with the preset as a BCD word (`input.pv_bcd`, as the PLC
    /// holds `C#n`).
    ///
    /// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`
    /// (`counter` or `out`); `PLC_TIMERS_INVALID_KIND`; `PLC_TIMERS_INVALID_BCD_PRESET`
    /// (`input.pv_bcd`); `PLC_TIMERS_INVALID_STATE` (`*counter`).
    call plc_timers_s5_counter_ref_call_bcd(counter: plc_timers_s5_counter_ref, kind, input: plc_timers_s5_counter_input_bcd, out: plc_timers_s5_counter_output)
);
export!(
    /// `plc_timers_s5_counter_call` with the preset as a BCD word (`input.pv_bcd`, as the PLC
    /// holds `C#n`).
    ///
    /// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`
    /// (`counter` or `out`); `PLC_TIMERS_INVALID_KIND`; `PLC_TIMERS_INVALID_BCD_PRESET`
    /// (`input.pv_bcd`); `PLC_TIMERS_INVALID_STATE` (`*counter`).
    call plc_timers_s5_counter_call_bcd(counter: plc_timers_s5_counter, kind, input: plc_timers_s5_counter_input_bcd, out: plc_timers_s5_counter_output)
);

/// The count of the S5 counter preset BCD word `pv_bcd` (`C#123`, held as `W#16#0123`, gives
/// 123), written to `count`: the one conversion between the two representations, checked.
///
/// Returns `PLC_TIMERS_OK`; `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`
/// (`count`); `PLC_TIMERS_INVALID_BCD_PRESET` (a digit above 9 or bits 15-12 set).
///
/// # Safety
/// `count` is NULL or points to memory valid for writes of its type.
#[no_mangle]
pub unsafe extern "C" fn plc_timers_s5_count_from_bcd(
    pv_bcd: plc_timers_bcd_word,
    count: *mut plc_timers_s5_count,
) -> plc_timers_status {
    crate::guard(|| {
        let count = crate::checked_mut(count)?;
        let value = counter_preset_bcd(pv_bcd)?.value();
        // SAFETY: checked non-NULL and aligned; `write` does not read the old value.
        unsafe { count.write(value) };
        Ok(())
    })
}
