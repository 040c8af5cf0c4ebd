//! # plc-timers for C: the Siemens S7 timers and counters behind a C ABI
//!
//! The library `plc_timers` (`libplc_timers.a`, `libplc_timers.so`) with the header
//! `include/plc_timers.h`, which cbindgen generates from this crate (`tests/header.rs` checks
//! that the committed header is the fresh one). It is for the soft-PLC runtimes written in C and
//! C++ (matiec/OpenPLC, 4diac FORTE, vendors' runtimes): they call the blocks of `plc-timers`
//! instead of re-implementing them.
//!
//! ## Conventions
//! - Every name starts with `plc_timers_` (types, functions) or `PLC_TIMERS_` (constants).
//! - **The caller owns the state.** Each block's state is a plain `#[repr(C)]` struct of fixed
//!   size that the runtime allocates in its own instance data (a function block's instance, a
//!   DB); there is no handle and no allocation. An all-zero struct is the initial state, as
//!   the `_init` functions write it, so zeroed instance memory needs no init call.
//! - **Two forms per family**: the reference semantics (`_ref_` in the name; written to be read
//!   against the manual) and the optimized implementation (the compact state a soft-PLC ships).
//!   Both give the same outputs; their state structs differ.
//! - **One call per execution**: `state`, the CPU time `now_ms` (milliseconds since the CPU
//!   started; timers only), the inputs as a struct passed by value, and a pointer the outputs
//!   are written to. A kind argument (`int32_t`) selects the instruction: a value of one of the
//!   enums `plc_timers_s5_kind`, `plc_timers_iec_kind`, `plc_timers_counter_kind`,
//!   `plc_timers_s5_counter_kind`.
//! - **Every function returns a status** (`plc_timers_status`): `PLC_TIMERS_OK` (0) or an error
//!   code; `plc_timers_status_message` names it. On an error nothing is written: neither the
//!   state nor the outputs change.
//!
//! ## Why no bad argument can crash the caller
//! - Every pointer is checked: NULL gives `PLC_TIMERS_NULL_POINTER`, a pointer not aligned for
//!   its type `PLC_TIMERS_MISALIGNED_POINTER`. (A pointer to memory the caller does not own
//!   cannot be detected by anyone; that stays the caller's contract, as with `memcpy`.)
//! - A kind, time base or operand number out of range is a status code, never an invalid Rust
//!   enum: kinds cross the boundary as `int32_t` and are matched here.
//! - The state structs hold only integers, so any bytes in them are a valid Rust value; each
//!   call converts the struct into the library's type with the checking constructor
//!   (`from_state`, `from_bits`, `from_bytes`) and answers `PLC_TIMERS_INVALID_STATE` when
//!   the bytes are not a state the block can be in (a corrupted or foreign instance).
//!
//! ## Why no Rust panic can cross the boundary
//! 1. The code of this crate has no path that panics: the lints at the top of this file deny
//!    `unwrap`, `expect`, `panic!`, indexing and slicing, and unchecked arithmetic, so that
//!    clippy (`-D warnings` in CI) rejects any such path.
//! 2. A call reaches the library's operations only with a state its checking constructor
//!    accepted and with inputs of their types (a kind, a checked S5TIME, a checked preset). On
//!    such values the operations are written to be total (saturating or wrapping arithmetic, no
//!    indexing out of a field's range); the proofs (`proofs/`, run by `cargo test` with overflow
//!    checks on) run them from exhaustively enumerated and random valid states, and the literal
//!    parsers are fuzz targets (`fuzz/`).
//! 3. Should 1 and 2 ever fail, every function body runs inside `std::panic::catch_unwind`
//!    (`guard`): a panic becomes `PLC_TIMERS_INTERNAL_ERROR` instead of an unwind into C. (That
//!    needs the default `panic = "unwind"`; a build with `panic = "abort"` would abort the
//!    process instead, which is still not undefined behaviour.)
#![deny(unsafe_op_in_unsafe_fn)]
#![deny(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::panic,
    clippy::indexing_slicing,
    clippy::arithmetic_side_effects,
    clippy::unreachable,
    clippy::todo,
    clippy::unimplemented
)]
// The names are the C names: the header is generated from them.
#![allow(non_camel_case_types)]

pub mod counters;
mod export;
pub mod literal;
pub mod memory;
pub mod status;
pub mod timers;

pub use status::plc_timers_status;
use status::plc_timers_status::*;

/// The major version of the library this header belongs to (`PLC_TIMERS_VERSION_MAJOR`).
pub const PLC_TIMERS_VERSION_MAJOR: u32 = 0;
/// The minor version of the library this header belongs to.
pub const PLC_TIMERS_VERSION_MINOR: u32 = 1;
/// The patch version of the library this header belongs to.
pub const PLC_TIMERS_VERSION_PATCH: u32 = 0;
/// The version of the library this header belongs to, as one number: major * 10000 + minor *
/// 100 + patch (0.1.0 is 100), as `plc_timers_version` returns it for the library linked.
pub const PLC_TIMERS_VERSION: u32 = 100;

/// This library's version, `major * 10000 + minor * 100 + patch`, from Cargo's version of the
/// crate (`version_macros_are_cargos_version` checks the header's macros against it).
const VERSION: u32 = version_number(&[
    env!("CARGO_PKG_VERSION_MAJOR").as_bytes(),
    env!("CARGO_PKG_VERSION_MINOR").as_bytes(),
    env!("CARGO_PKG_VERSION_PATCH").as_bytes(),
]);

/// `parts` (decimal digits each) as one number, two decimal places per part after the first.
/// Evaluated at compile time only, where an overflow is a build error.
#[allow(clippy::arithmetic_side_effects, clippy::indexing_slicing)]
const fn version_number(parts: &[&[u8]]) -> u32 {
    let mut v: u32 = 0;
    let mut i = 0;
    while i < parts.len() {
        let mut n: u32 = 0;
        let mut j = 0;
        while j < parts[i].len() {
            n = n * 10 + (parts[i][j] - b'0') as u32;
            j += 1;
        }
        v = v * 100 + n;
        i += 1;
    }
    v
}

/// The version of the library linked, `major * 10000 + minor * 100 + patch`: compare it with
/// the header's `PLC_TIMERS_VERSION` to detect a header used with another library. Within one
/// `0.minor` series (one soname, `libplc_timers.so.0.minor`) the ABI does not change, so
/// `plc_timers_version() / 100 == PLC_TIMERS_VERSION / 100` is the compatibility check.
#[no_mangle]
pub extern "C" fn plc_timers_version() -> u32 {
    VERSION
}

/// Runs `body`, turning its error into the status it carries and a panic (which no path of
/// `body` should have, see the crate docs) into `PLC_TIMERS_INTERNAL_ERROR`, so that no unwind
/// reaches the C caller.
pub(crate) fn guard(body: impl FnOnce() -> Result<(), plc_timers_status>) -> plc_timers_status {
    // `AssertUnwindSafe`: after a panic the caller's state has not been written (every body
    // writes only at its end), so nothing half-updated is observed.
    match std::panic::catch_unwind(std::panic::AssertUnwindSafe(body)) {
        Ok(Ok(())) => PLC_TIMERS_OK,
        Ok(Err(status)) => status,
        Err(_) => PLC_TIMERS_INTERNAL_ERROR,
    }
}

/// A pointer the caller passed, checked: not NULL and aligned for `T`.
pub(crate) fn checked<T>(p: *const T) -> Result<*const T, plc_timers_status> {
    if p.is_null() {
        Err(PLC_TIMERS_NULL_POINTER)
    } else if !p.is_aligned() {
        Err(PLC_TIMERS_MISALIGNED_POINTER)
    } else {
        Ok(p)
    }
}

/// [`checked`] for a pointer written through.
pub(crate) fn checked_mut<T>(p: *mut T) -> Result<*mut T, plc_timers_status> {
    checked(p.cast_const()).map(<*const T>::cast_mut)
}

/// A C state struct that stands for a state of the library's type `Core`.
///
/// The C structs hold only integers (any bytes are a valid value of them); `load` is where a
/// state the block cannot be in is refused.
pub(crate) trait Mirror: Sized {
    /// The library's type.
    type Core;
    /// The library's value this struct holds, or `None` when it holds no valid state.
    fn load(&self) -> Option<Self::Core>;
    /// The struct holding `core`.
    fn store(core: &Self::Core) -> Self;
}

/// The common body of the functions on one state: checks `state` and `out`, loads the state,
/// runs `f` on it, then stores the state and writes the result (nothing is written on an error).
///
/// # Safety
/// `state` and `out` are NULL or point to memory valid for reads and writes of their type.
pub(crate) unsafe fn on_state<M: Mirror, R>(
    state: *mut M,
    out: *mut R,
    f: impl FnOnce(&mut M::Core) -> Result<R, plc_timers_status>,
) -> plc_timers_status {
    guard(|| {
        let state = checked_mut(state)?;
        let out = checked_mut(out)?;
        // SAFETY: checked non-NULL and aligned; valid memory is the caller's contract; every
        // bit pattern is a value of `M` (integers only).
        let mirror = unsafe { &mut *state };
        let mut core = mirror.load().ok_or(PLC_TIMERS_INVALID_STATE)?;
        let result = f(&mut core)?;
        *mirror = M::store(&core);
        // SAFETY: checked non-NULL and aligned; `write` does not read the old value, so `out`
        // may be uninitialized.
        unsafe { out.write(result) };
        Ok(())
    })
}

/// The common body of the functions that read a state: checks `state` and `out`, loads the
/// state, writes `f`'s result to `out` (nothing on an error).
///
/// # Safety
/// `state` is NULL or points to memory valid for reads of `M`; `out` is NULL or points to
/// memory valid for writes of `R`.
pub(crate) unsafe fn read_state<M: Mirror, R>(
    state: *const M,
    out: *mut R,
    f: impl FnOnce(&M::Core) -> Result<R, plc_timers_status>,
) -> plc_timers_status {
    guard(|| {
        let state = checked(state)?;
        let out = checked_mut(out)?;
        // SAFETY: checked non-NULL and aligned; valid memory is the caller's contract; every
        // bit pattern is a value of `M` (integers only).
        let core = unsafe { &*state }.load().ok_or(PLC_TIMERS_INVALID_STATE)?;
        let result = f(&core)?;
        // SAFETY: checked non-NULL and aligned; `write` does not read the old value.
        unsafe { out.write(result) };
        Ok(())
    })
}

/// [`on_state`] for an operation without a result.
///
/// # Safety
/// `state` is NULL or points to memory valid for reads and writes of `M`.
pub(crate) unsafe fn on_state_only<M: Mirror>(
    state: *mut M,
    f: impl FnOnce(&mut M::Core) -> Result<(), plc_timers_status>,
) -> plc_timers_status {
    let mut unit = ();
    // SAFETY: the caller's contract for `state`; `&mut unit` is a valid pointer.
    unsafe { on_state(state, &mut unit, f) }
}

/// Writes the initial state `M::store(&initial)` to `state`.
///
/// # Safety
/// `state` is NULL or points to memory valid for writes of `M`.
pub(crate) unsafe fn init<M: Mirror>(state: *mut M, initial: M::Core) -> plc_timers_status {
    guard(|| {
        let state = checked_mut(state)?;
        // SAFETY: checked non-NULL and aligned; `write` does not read the (possibly
        // uninitialized) old contents.
        unsafe { state.write(M::store(&initial)) };
        Ok(())
    })
}

/// An input bit as C passes it (a struct field or a flag parameter, `uint8_t`): 0 is FALSE,
/// any other byte TRUE, as a runtime's process-image byte means. A C `bool` would make any
/// byte but 0 and 1 undefined behaviour on this side, so no input crosses as `bool`.
pub(crate) const fn bit(byte: u8) -> bool {
    byte != 0
}

/// A flag byte of a C state struct: 0 or 1, anything else is not a state.
pub(crate) fn flag(byte: u8) -> Option<bool> {
    match byte {
        0 => Some(false),
        1 => Some(true),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use crate::status::plc_timers_status::*;
    use crate::timers::{
        plc_timers_iec_input, plc_timers_iec_output, plc_timers_iec_timer,
        plc_timers_iec_timer_call, plc_timers_iec_timer_init,
    };

    /// The header's version macros are the crate's version, which `plc_timers_version`
    /// returns (Cargo's, not a copy of the macros).
    #[test]
    fn version_macros_are_cargos_version() {
        use crate::{
            PLC_TIMERS_VERSION, PLC_TIMERS_VERSION_MAJOR, PLC_TIMERS_VERSION_MINOR,
            PLC_TIMERS_VERSION_PATCH,
        };
        assert_eq!(
            env!("CARGO_PKG_VERSION"),
            format!(
                "{PLC_TIMERS_VERSION_MAJOR}.{PLC_TIMERS_VERSION_MINOR}.{PLC_TIMERS_VERSION_PATCH}"
            )
        );
        assert_eq!(
            PLC_TIMERS_VERSION,
            PLC_TIMERS_VERSION_MAJOR * 10000
                + PLC_TIMERS_VERSION_MINOR * 100
                + PLC_TIMERS_VERSION_PATCH
        );
        assert_eq!(crate::plc_timers_version(), PLC_TIMERS_VERSION);
    }

    /// `plc_timers_iec_ltimer` holds the bytes of the library's `IecLTimer` (LTIMER-STRUCT-01:
    /// the header's struct is the structure's memory layout), and loads back to it, in every
    /// phase of a TON and a TONR on LTIME.
    #[test]
    fn ltimer_struct_is_the_librarys_structure() {
        use crate::timers::plc_timers_iec_ltimer;
        use crate::Mirror;
        use plc_timers::iec::{IecInput, IecKind, IecLTimer, IecTimerOps};
        use plc_timers::time::{CpuTime, LTime};
        let pt = LTime::from_nanos(1_000_000_007);
        for kind in [IecKind::Ton, IecKind::Tonr] {
            let mut t = IecLTimer::new();
            for (now, on) in [
                (5, true),
                (400_000_000, true),
                (2_000_000_000, true),
                (2_000_000_001, false),
            ] {
                t.call(kind, CpuTime::from_nanos(now), IecInput::new(on, pt));
                let c = plc_timers_iec_ltimer::store(&t);
                // SAFETY: the struct is 32 bytes without padding (3 x u64, u8, [u8; 7]).
                let bytes: [u8; 32] = unsafe { core::mem::transmute(c) };
                assert_eq!(
                    bytes,
                    t.to_bytes(),
                    "LTIMER-STRUCT-01: the library's bytes at {now} ns"
                );
                assert_eq!(
                    c.load(),
                    Some(t),
                    "LTIMER-STRUCT-01: loads back at {now} ns"
                );
            }
        }
    }

    /// A misaligned pointer (which C cannot form without undefined behaviour, so the C tests
    /// cannot pass one) is refused with `PLC_TIMERS_MISALIGNED_POINTER`, before any access.
    #[test]
    fn misaligned_pointers_are_refused() {
        let mut buffer = [0u64; 8];
        let base = buffer.as_mut_ptr().cast::<u8>();
        let timer = base.wrapping_add(1).cast::<plc_timers_iec_timer>();
        let out = base.wrapping_add(33).cast::<plc_timers_iec_output>();
        let mut aligned_timer = plc_timers_iec_timer::default();
        let mut aligned_out = plc_timers_iec_output::default();
        let input = plc_timers_iec_input::default();
        // SAFETY: the pointers point into `buffer`; the functions refuse them before any access.
        unsafe {
            assert_eq!(
                plc_timers_iec_timer_init(timer),
                PLC_TIMERS_MISALIGNED_POINTER
            );
            assert_eq!(
                plc_timers_iec_timer_call(timer, 1, 0, input, &mut aligned_out),
                PLC_TIMERS_MISALIGNED_POINTER
            );
            assert_eq!(
                plc_timers_iec_timer_call(&mut aligned_timer, 1, 0, input, out),
                PLC_TIMERS_MISALIGNED_POINTER
            );
        }
        assert_eq!(buffer, [0; 8]);
    }
}
