//! The bodies of the exported functions, written once against the core's block interface
//! (`plc_timers::block::BlockOps`) and the IEC timer structure's operations
//! (`plc_timers::iec::IecTimerOps`), and the macro [`export!`] that registers an exported C
//! function on one of them in one line.
//!
//! cbindgen reads this crate macro-expanded (`[parse.expand]` in `cbindgen.toml`), so the
//! functions the macro writes, with their doc comments, are in the generated header.

use plc_timers::block::BlockOps;
use plc_timers::iec::IecTimerOps;
use plc_timers::time::clock::ClockWord;
use plc_timers::time::{CpuTime, IecDuration};

use crate::status::plc_timers_status;
use crate::{bit, on_state, on_state_only, Mirror};

/// A kind as C passes it (`int32_t`, a value of the family's kind enum), checked.
pub(crate) trait CKind: Sized {
    /// The kind `kind` stands for, or `PLC_TIMERS_INVALID_KIND`.
    fn from_c(kind: i32) -> Result<Self, plc_timers_status>;
}

/// An input struct as C passes it, turned into the library's inputs `I` (the input bytes as
/// bits, a preset checked).
pub(crate) trait CInput<I>: Copy {
    /// The library's inputs, or the status of a field that is not one.
    fn load(self) -> Result<I, plc_timers_status>;
}

/// A C state struct of a block: the library's type behind it has the block interface, and its
/// kinds cross as `int32_t`.
pub(crate) trait CBlock: Mirror<Core: BlockOps<Kind: CKind>> {}

impl<M: Mirror<Core: BlockOps<Kind: CKind>>> CBlock for M {}

/// The inputs of `M`'s block.
type In<M> = <<M as Mirror>::Core as BlockOps>::Input;
/// The outputs of `M`'s block.
type Out<M> = <<M as Mirror>::Core as BlockOps>::Output;

/// One call of the block behind `state`: the kind and the inputs checked, the call at CPU time
/// `now` (in the block's clock unit; counters ignore it), the outputs written to `out`.
///
/// # Safety
/// `state` and `out` are NULL or point to memory valid for reads and writes of their types.
pub(crate) unsafe fn call<M: CBlock, I: CInput<In<M>>, O: From<Out<M>>>(
    state: *mut M,
    kind: i32,
    now: u64,
    input: I,
    out: *mut O,
) -> plc_timers_status {
    // SAFETY: the caller's contract.
    unsafe {
        on_state(state, out, |block| {
            let kind = CKind::from_c(kind)?;
            let input = input.load()?;
            Ok(block.call(kind, CpuTime::from_ticks(now), input).into())
        })
    }
}

/// Writes the initial state (the library's `Default`, which is all zero in C) to `state`.
///
/// # Safety
/// `state` is NULL or points to memory valid for writes of `M`.
pub(crate) unsafe fn init<M: Mirror<Core: Default>>(state: *mut M) -> plc_timers_status {
    // SAFETY: the caller's contract.
    unsafe { crate::init(state, M::Core::default()) }
}

/// A C struct of an IEC timer structure (`IEC_TIMER`, `IEC_LTIMER`, either form): its clock
/// word and data type, for the structure operations below.
pub(crate) trait CIecTimer: Mirror<Core: IecTimerOps<Self::Clock, Self::Duration>> {
    /// The clock word (`u32` for TIME, `u64` for LTIME).
    type Clock: ClockWord;
    /// The data type of PT and ET.
    type Duration: IecDuration;
    /// A preset as C passes it (`int32_t` ms, `int64_t` ns).
    type Preset: Copy;
    /// The preset `pt` (negative taken as 0 by the timer).
    fn preset(pt: Self::Preset) -> Self::Duration;
}

/// Reads `Q` through the structure at `now` (the update first).
///
/// # Safety
/// `timer` and `q` are NULL or point to memory valid for reads and writes of their types.
pub(crate) unsafe fn read_q<M: CIecTimer>(
    timer: *mut M,
    now: u64,
    q: *mut bool,
) -> plc_timers_status {
    // SAFETY: the caller's contract.
    unsafe { on_state(timer, q, |t| Ok(t.read_q(CpuTime::from_ticks(now)))) }
}

/// Reads `ET` through the structure at `now` (the update first).
///
/// # Safety
/// `timer` and `et` are NULL or point to memory valid for reads and writes of their types.
pub(crate) unsafe fn read_et<M: CIecTimer>(
    timer: *mut M,
    now: u64,
    et: *mut M::Clock,
) -> plc_timers_status {
    // SAFETY: the caller's contract.
    unsafe { on_state(timer, et, |t| Ok(t.read_et(CpuTime::from_ticks(now)))) }
}

/// The `-(RT)-` coil.
///
/// # Safety
/// `timer` is NULL or points to memory valid for reads and writes of its type.
pub(crate) unsafe fn reset<M: CIecTimer>(timer: *mut M) -> plc_timers_status {
    // SAFETY: the caller's contract.
    unsafe {
        on_state_only(timer, |t| {
            t.reset_timer();
            Ok(())
        })
    }
}

/// The `-(PT)-` coil.
///
/// # Safety
/// `timer` is NULL or points to memory valid for reads and writes of its type.
pub(crate) unsafe fn preset<M: CIecTimer>(timer: *mut M, pt: M::Preset) -> plc_timers_status {
    // SAFETY: the caller's contract.
    unsafe {
        on_state_only(timer, |t| {
            t.preset_timer(M::preset(pt));
            Ok(())
        })
    }
}

/// A RUN-STOP-RUN transition; `retentive` an input byte (0 FALSE, any other TRUE).
///
/// # Safety
/// `timer` is NULL or points to memory valid for reads and writes of its type.
pub(crate) unsafe fn run_stop_run<M: CIecTimer>(timer: *mut M, retentive: u8) -> plc_timers_status {
    // SAFETY: the caller's contract.
    unsafe {
        on_state_only(timer, |t| {
            t.run_stop_run(bit(retentive));
            Ok(())
        })
    }
}

/// Registers one exported C function on a body of this module: the doc comment (attributes),
/// then the body's name, the C function's name and its parameters as the header shows them
/// (`name: type`; a `*mut` is written by the macro). The parameters are passed to the body in
/// order; `now = 0` stands for the clock argument of a block without a clock (counters).
///
/// ```ignore
/// export!(/** docs */ call plc_timers_iec_timer_call(timer: plc_timers_iec_timer, kind, now_ms, input: plc_timers_iec_input, out: plc_timers_iec_output));
/// ```
macro_rules! export {
    ($(#[$doc:meta])* init $name:ident($state:ident: $ty:ty)) => {
        $(#[$doc])*
        ///
        /// Returns `PLC_TIMERS_OK`, or `PLC_TIMERS_NULL_POINTER` / `PLC_TIMERS_MISALIGNED_POINTER`.
        ///
        /// # Safety
        #[doc = concat!(" `", stringify!($state), "` is NULL or points to writable memory for its type.")]
        #[no_mangle]
        pub unsafe extern "C" fn $name($state: *mut $ty) -> $crate::status::plc_timers_status {
            // SAFETY: the caller's contract.
            unsafe { $crate::export::init($state) }
        }
    };
    ($(#[$doc:meta])* call $name:ident($state:ident: $ty:ty, $kind:ident, $now:ident, $input:ident: $in:ty, $out:ident: $o:ty)) => {
        $(#[$doc])*
        ///
        /// # Safety
        #[doc = concat!(" `", stringify!($state), "` and `", stringify!($out), "` are NULL or point to memory valid for reads and writes of their types.")]
        #[no_mangle]
        pub unsafe extern "C" fn $name(
            $state: *mut $ty,
            $kind: i32,
            $now: u64,
            $input: $in,
            $out: *mut $o,
        ) -> $crate::status::plc_timers_status {
            // SAFETY: the caller's contract.
            unsafe { $crate::export::call($state, $kind, $now, $input, $out) }
        }
    };
    ($(#[$doc:meta])* call $name:ident($state:ident: $ty:ty, $kind:ident, $input:ident: $in:ty, $out:ident: $o:ty)) => {
        $(#[$doc])*
        ///
        /// # Safety
        #[doc = concat!(" `", stringify!($state), "` and `", stringify!($out), "` are NULL or point to memory valid for reads and writes of their types.")]
        #[no_mangle]
        pub unsafe extern "C" fn $name(
            $state: *mut $ty,
            $kind: i32,
            $input: $in,
            $out: *mut $o,
        ) -> $crate::status::plc_timers_status {
            // SAFETY: the caller's contract; a counter has no clock.
            unsafe { $crate::export::call($state, $kind, 0, $input, $out) }
        }
    };
    ($(#[$doc:meta])* $body:ident $name:ident($state:ident: $ty:ty, $now:ident, $res:ident: $r:ty)) => {
        $(#[$doc])*
        ///
        /// # Safety
        #[doc = concat!(" `", stringify!($state), "` and `", stringify!($res), "` are NULL or point to memory valid for reads and writes of their types.")]
        #[no_mangle]
        pub unsafe extern "C" fn $name(
            $state: *mut $ty,
            $now: u64,
            $res: *mut $r,
        ) -> $crate::status::plc_timers_status {
            // SAFETY: the caller's contract.
            unsafe { $crate::export::$body($state, $now, $res) }
        }
    };
    ($(#[$doc:meta])* $body:ident $name:ident($state:ident: $ty:ty $(, $arg:ident: $a:ty)?)) => {
        $(#[$doc])*
        ///
        /// # Safety
        #[doc = concat!(" `", stringify!($state), "` is NULL or points to memory valid for reads and writes of its type.")]
        #[no_mangle]
        pub unsafe extern "C" fn $name(
            $state: *mut $ty,
            $($arg: $a,)?
        ) -> $crate::status::plc_timers_status {
            // SAFETY: the caller's contract.
            unsafe { $crate::export::$body($state $(, $arg)?) }
        }
    };
}
pub(crate) use export;
