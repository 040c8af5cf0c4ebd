//! # plc-timers
//!
//! The executable, formally checked specification of Siemens S7 PLC timers and counters.
//!
//! Every block comes twice: a **reference semantics** written to be read line by line against
//! the manual, and an **optimized implementation** of the kind a soft-PLC would ship (compact
//! state, no allocation, `no_std`). Proofs (Kani harnesses and exhaustive concrete drivers, in
//! `proofs/`) show the two equivalent and check the invariants; `spec/` states every rule with an
//! ID and its source.
//!
//! ## Map
//! Every family has the same shape: a kind enum, input and output structs, a state struct that
//! both implementations map to, the reference, the optimized form, and a container of many.
//! Each family describes itself once as a [`block::Family`], and both of its implementations
//! are [`block::BlockOps`]: the one interface the command-line tool, the bindings, the
//! benchmarks and the proofs' shared drivers are written against ([`block::Instruction::visit`]
//! is the only place that lists the families).
//!
//! | family | [`block::Family`] | reference | optimized | many |
//! |---|---|---|---|---|
//! | [`s5`] timers (`S_PULSE` … `S_OFFDT`) | [`s5::S5Timers`] | [`s5::S5TimerRef`] | [`s5::S5Timer`] | [`s5::TimerMemory`] |
//! | [`iec`] timers (`TP`, `TON`, `TOF`, `TONR`) on `TIME` | [`iec::IecTimers`] | [`iec::IecTimerRef`] | [`iec::IecTimer`] | [`iec::TonBank`] |
//! | [`iec`] timers on `LTIME` (S7-1500) | [`iec::IecTimers`]`<u64, LTime>` | [`iec::IecLTimerRef`] | [`iec::IecLTimer`] | |
//! | [`counter`]s (`CTU`, `CTD`, `CTUD`) | [`counter::Counters`] | [`counter::CounterRef`] | [`counter::Counter`] | [`counter::CounterBank`] |
//! | [`counter::s5`] counters (`S_CU`, `S_CD`, `S_CUD`) | [`counter::s5::S5Counters`] | [`counter::s5::S5CounterRef`] | [`counter::s5::S5Counter`] | [`counter::s5::CounterMemory`] |
//!
//! Every call takes the CPU time it runs at, a [`time::CpuTime`] whose unit is in its type
//! (milliseconds, or nanoseconds for `LTIME`): `call(kind, now, input)`; a counter ignores it
//! (its own `call(kind, input)` has none). [`mod@time`] has the S5TIME word, IEC `TIME` and
//! `LTIME` with their literals; [`catalog`] names every block with its inputs, outputs and
//! data types.
//!
//! ## Quick start, per family
//!
//! ```
//! use plc_timers::time::CpuTime;
//!
//! // S5 timers: an S_ODT on-delay of 50 ms.
//! use plc_timers::s5::{S5Input, S5Kind, S5Timer, S5TimerOps};
//! let mut sd = S5Timer::new();
//! let on = S5Input::new(true, false, plc_timers::s5time!("S5T#50MS"));
//! sd.call(S5Kind::SOdt, CpuTime::from_millis(0), on);
//! assert!(sd.call(S5Kind::SOdt, CpuTime::from_millis(50), on).q);
//!
//! // IEC timers: a TON of 500 ms; on LTIME (S7-1500), one of 1.5 ms in nanoseconds.
//! use plc_timers::iec::{IecInput, IecKind, IecTimer, IecTimerOps};
//! let mut ton = IecTimer::new();
//! let on = IecInput::new(true, plc_timers::time!("T#500MS"));
//! ton.call(IecKind::Ton, CpuTime::from_millis(1_000), on);
//! assert!(ton.call(IecKind::Ton, CpuTime::from_millis(1_500), on).q);
//! use plc_timers::iec::IecLTimer;
//! let mut lton = IecLTimer::new();
//! let on = IecInput::new(true, plc_timers::ltime!("LT#1MS_500US"));
//! lton.call(IecKind::Ton, CpuTime::from_nanos(0), on);
//! assert!(lton.call(IecKind::Ton, CpuTime::from_nanos(1_500_000), on).q);
//!
//! // IEC counters: a CTU of type INT counting to 2.
//! use plc_timers::counter::{Counter, CounterInput, CounterKind, CounterOps};
//! let mut ctu = Counter::<i16>::new();
//! for cu in [true, false, true] {
//!     ctu.call(CounterKind::Ctu, CounterInput::new(cu, false, 2));
//! }
//! assert!(ctu.call(CounterKind::Ctu, CounterInput::new(false, false, 2)).qu);
//!
//! // S5 counters: an S_CD loaded with C#1 and counted down to 0.
//! use plc_timers::counter::s5::{CounterPreset, S5Counter, S5CounterInput, S5CounterKind, S5CounterOps};
//! let mut scd = S5Counter::new();
//! let pv = CounterPreset::new(1).expect("0..=999");
//! scd.call(S5CounterKind::SCd, S5CounterInput::new(false, false, pv).with_s(true));
//! assert!(!scd.call(S5CounterKind::SCd, S5CounterInput::new(false, true, pv)).q);
//! ```
//!
//! ## Time is an input
//! No block reads a clock: every call takes the CPU time it runs at, so every behaviour is
//! deterministic, replayable from a trace, and checkable symbolically.
//!
//! ## Features
//! - `std`: `std::error::Error` for the error types. Without it the crate is `no_std` and
//!   allocation-free.
//! - `simd-dispatch` (implies `std`): the bulk loops ([`counter::CounterBank::scan`],
//!   [`iec::TonBank::scan`], [`s5::TimerMemory::tick`]) run compiled for AVX2 or AVX-512 when
//!   the CPU has them (x86-64; detected at run time), instead of the build's target (SSE2 for
//!   the default x86-64 target). The only `unsafe` of the crate, two calls, is behind it.
//! - `bolero`: generators (`bolero_generator::TypeGenerator`) beside the kinds, inputs and states,
//!   generating only valid values; the proofs use them as property tests, Kani proofs and fuzz
//!   targets. Off by default: without it the crate has no dependency at all.
#![no_std]
// Without `simd-dispatch` no line of the crate is `unsafe`; with it, the two calls of
// `simd::run` into code compiled for a detected vector extension are (see there why).
#![cfg_attr(not(feature = "simd-dispatch"), forbid(unsafe_code))]
#![cfg_attr(feature = "simd-dispatch", deny(unsafe_code))]
#![cfg_attr(docsrs, feature(doc_cfg))]

#[cfg(feature = "std")]
extern crate std;

pub mod block;
pub mod catalog;
pub mod counter;
pub mod iec;
mod operand;
pub mod rule;
pub mod s5;
mod simd;
pub mod time;

pub use operand::{NoSuchOperand, Operand};

// The README's Rust examples are doc tests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
