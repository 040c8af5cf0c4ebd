//! The C ABI (`bindings/c`) on arbitrary state bytes, kinds, input bytes, times and presets:
//! every function answers a status of the header's list, never `PLC_TIMERS_INTERNAL_ERROR` (a
//! caught panic); on an error it wrote nothing (state and outputs byte for byte as before); on
//! success the state it wrote is one the next call accepts; and an input byte other than 0 acts
//! exactly as 1 (issue 37: the same call with the input bits as 0/1 gives the same bytes).
#![no_main]

use libfuzzer_sys::fuzz_target;
use plc_timers_c::counters::*;
use plc_timers_c::memory::*;
use plc_timers_c::plc_timers_status::{self, *};
use plc_timers_c::timers::*;

/// Reads the fuzzer's bytes in order; past the end every read is 0.
struct Bytes<'a>(&'a [u8]);

impl Bytes<'_> {
    fn byte(&mut self) -> u8 {
        match self.0.split_first() {
            Some((&b, rest)) => {
                self.0 = rest;
                b
            }
            None => 0,
        }
    }
    fn fill(&mut self, out: &mut [u8]) {
        for b in out {
            *b = self.byte();
        }
    }
    fn u16(&mut self) -> u16 {
        u16::from_le_bytes([self.byte(), self.byte()])
    }
    fn u32(&mut self) -> u32 {
        u32::from_le_bytes([self.byte(), self.byte(), self.byte(), self.byte()])
    }
    fn u64(&mut self) -> u64 {
        u64::from(self.u32()) | u64::from(self.u32()) << 32
    }
    /// A kind: mostly a valid one, sometimes any `int32_t`.
    fn kind(&mut self) -> i32 {
        let k = self.byte();
        if k & 0x80 != 0 {
            self.u32() as i32
        } else {
            i32::from(k % 6)
        }
    }
}

/// All zero: the initial state of every state struct, and `false`/0 in every output.
fn zeroed<T: Copy>() -> T {
    // SAFETY: `T` is one of the header's structs (integers and `bool`s) or `()`: all zero is a
    // valid value of each.
    unsafe { std::mem::zeroed() }
}

/// A plain C struct of integers filled from the fuzzer's bytes (every bit pattern is a value).
fn from_bytes<T: Copy>(b: &mut Bytes) -> T {
    let mut v: T = zeroed();
    // SAFETY: `T` is one of the header's structs, integers only without padding, so every byte
    // pattern is a valid value and the slice covers exactly its bytes.
    let raw = unsafe {
        std::slice::from_raw_parts_mut((&mut v as *mut T).cast::<u8>(), std::mem::size_of::<T>())
    };
    b.fill(raw);
    v
}

/// The bytes of a state struct (integers only, no padding; the outputs, which have padding, are
/// compared as values).
fn bytes_of<T>(v: &T) -> Vec<u8> {
    // SAFETY: reading the initialized bytes of a value of a padding-free `#[repr(C)]` struct.
    unsafe {
        std::slice::from_raw_parts((v as *const T).cast::<u8>(), std::mem::size_of::<T>()).to_vec()
    }
}

const KNOWN: [plc_timers_status; 10] = [
    PLC_TIMERS_OK,
    PLC_TIMERS_NULL_POINTER,
    PLC_TIMERS_MISALIGNED_POINTER,
    PLC_TIMERS_INVALID_KIND,
    PLC_TIMERS_INVALID_STATE,
    PLC_TIMERS_INVALID_S5TIME,
    PLC_TIMERS_INVALID_PRESET,
    PLC_TIMERS_NO_SUCH_OPERAND,
    PLC_TIMERS_INVALID_TIME_BASE,
    PLC_TIMERS_INVALID_BCD_PRESET,
];

/// One call `f(state, input, out)` checked: a known status; nothing written on an error; with
/// OK, the state written accepted by the next call (`again`); and the same call with the input
/// bits as 0/1 (`normalized`) giving the same bytes.
fn exercise<S: Copy, I: Copy, O: Copy + PartialEq + std::fmt::Debug>(
    state: S,
    input: I,
    normalized: I,
    f: impl Fn(&mut S, I, &mut O) -> plc_timers_status,
) {
    let (mut s1, mut o1) = (state, zeroed::<O>());
    let status = f(&mut s1, input, &mut o1);
    assert!(KNOWN.contains(&status), "unknown status {status:?}");
    if status != PLC_TIMERS_OK {
        assert_eq!(
            bytes_of(&s1),
            bytes_of(&state),
            "{status:?}: the state changed"
        );
        assert_eq!(o1, zeroed::<O>(), "{status:?}: out was written");
    }
    let (mut s2, mut o2) = (state, zeroed::<O>());
    assert_eq!(
        f(&mut s2, normalized, &mut o2),
        status,
        "issue 37: a byte other than 0 is 1"
    );
    assert_eq!(bytes_of(&s2), bytes_of(&s1), "issue 37: state");
    assert_eq!(o2, o1, "issue 37: outputs");
    if status == PLC_TIMERS_OK {
        let again = f(&mut s1, normalized, &mut o1);
        assert!(
            again != PLC_TIMERS_INVALID_STATE && KNOWN.contains(&again),
            "the state written is refused: {again:?}"
        );
    }
}

fn one(b: u8) -> u8 {
    u8::from(b != 0)
}

macro_rules! iec_counter {
    ($b:expr, $t:ty, $call_ref:ident, $call:ident) => {{
        let b = $b;
        let kind = b.kind();
        let raw: [u8; 4] = [b.byte(), b.byte(), b.byte(), b.byte()];
        let pv: $t = from_bytes(b);
        let input = plc_timers_counter_input::<$t> {
            cu: raw[0],
            cd: raw[1],
            r: raw[2],
            ld: raw[3],
            pv,
        };
        let norm = plc_timers_counter_input::<$t> {
            cu: one(raw[0]),
            cd: one(raw[1]),
            r: one(raw[2]),
            ld: one(raw[3]),
            pv,
        };
        let (sr, so) = (from_bytes(b), from_bytes(b));
        // SAFETY: valid pointers to local values.
        exercise(sr, input, norm, |s, i, o| unsafe {
            $call_ref(s, kind, i, o)
        });
        exercise(so, input, norm, |s, i, o| unsafe { $call(s, kind, i, o) });
    }};
}

fuzz_target!(|data: &[u8]| {
    let mut b = Bytes(data);
    let family = b.byte();
    match family % 8 {
        0 => {
            let kind = b.kind();
            let now = b.u64();
            let raw = [b.byte(), b.byte(), b.byte()];
            let tv = b.u16();
            let input = plc_timers_s5_input {
                s: raw[0],
                r: raw[1],
                fr: raw[2],
                tv,
            };
            let norm = plc_timers_s5_input {
                s: one(raw[0]),
                r: one(raw[1]),
                fr: one(raw[2]),
                tv,
            };
            let (sr, so) = (from_bytes(&mut b), from_bytes(&mut b));
            // SAFETY: valid pointers to local values.
            exercise(sr, input, norm, |s, i, o| unsafe {
                plc_timers_s5_timer_ref_call(s, kind, now, i, o)
            });
            exercise(so, input, norm, |s, i, o| unsafe {
                plc_timers_s5_timer_call(s, kind, now, i, o)
            });
        }
        1 => {
            let kind = b.kind();
            let now = b.u64();
            let raw = [b.byte(), b.byte()];
            let pt = b.u32() as i32;
            let input = plc_timers_iec_input {
                r#in: raw[0],
                r: raw[1],
                pt,
            };
            let norm = plc_timers_iec_input {
                r#in: one(raw[0]),
                r: one(raw[1]),
                pt,
            };
            let (sr, so) = (from_bytes(&mut b), from_bytes(&mut b));
            // SAFETY: valid pointers to local values.
            exercise(sr, input, norm, |s, i, o| unsafe {
                plc_timers_iec_timer_ref_call(s, kind, now, i, o)
            });
            exercise(so, input, norm, |s, i, o| unsafe {
                plc_timers_iec_timer_call(s, kind, now, i, o)
            });
            // The same on LTIME (IEC_LTIMER), from the bytes after the TIME ones (so that the
            // inputs of the corpus keep their meaning above).
            let pt_ns = b.u64() as i64;
            let input = plc_timers_iec_ltime_input {
                r#in: raw[0],
                r: raw[1],
                pt_ns,
            };
            let norm = plc_timers_iec_ltime_input {
                r#in: one(raw[0]),
                r: one(raw[1]),
                pt_ns,
            };
            let (sr, so): (plc_timers_iec_ltimer_ref, plc_timers_iec_ltimer) =
                (from_bytes(&mut b), from_bytes(&mut b));
            // SAFETY: valid pointers to local values.
            exercise(sr, input, norm, |s, i, o| unsafe {
                plc_timers_iec_ltimer_ref_call(s, kind, now, i, o)
            });
            exercise(so, input, norm, |s, i, o| unsafe {
                plc_timers_iec_ltimer_call(s, kind, now, i, o)
            });
        }
        2 => {
            // The IEC timers' structure operations; RUN-STOP-RUN's flag is a byte.
            let op = b.byte();
            let now = b.u64();
            let pt = b.u32() as i32;
            let retentive = b.byte();
            let (sr, so): (plc_timers_iec_timer_ref, plc_timers_iec_timer) =
                (from_bytes(&mut b), from_bytes(&mut b));
            // SAFETY (every closure): valid pointers to local values.
            match op % 4 {
                0 => {
                    exercise(sr, (), (), |s, (), o: &mut bool| unsafe {
                        plc_timers_iec_timer_ref_read_q(s, now, o)
                    });
                    exercise(so, (), (), |s, (), o: &mut u32| unsafe {
                        plc_timers_iec_timer_read_et(s, now, o)
                    });
                }
                1 => {
                    exercise(sr, (), (), |s, (), _: &mut ()| unsafe {
                        plc_timers_iec_timer_ref_reset(s)
                    });
                    exercise(so, (), (), |s, (), _: &mut ()| unsafe {
                        plc_timers_iec_timer_reset(s)
                    });
                }
                2 => {
                    exercise(sr, (), (), |s, (), _: &mut ()| unsafe {
                        plc_timers_iec_timer_ref_preset(s, pt)
                    });
                    exercise(so, (), (), |s, (), _: &mut ()| unsafe {
                        plc_timers_iec_timer_preset(s, pt)
                    });
                }
                _ => {
                    let n = one(retentive);
                    exercise(sr, retentive, n, |s, r, _: &mut ()| unsafe {
                        plc_timers_iec_timer_ref_run_stop_run(s, r)
                    });
                    exercise(so, retentive, n, |s, r, _: &mut ()| unsafe {
                        plc_timers_iec_timer_run_stop_run(s, r)
                    });
                }
            }
            // The same operations on LTIME (IEC_LTIMER), from the bytes after the TIME ones.
            let pt_ns = b.u64() as i64;
            let (sr, so): (plc_timers_iec_ltimer_ref, plc_timers_iec_ltimer) =
                (from_bytes(&mut b), from_bytes(&mut b));
            // SAFETY (every closure): valid pointers to local values.
            match op % 4 {
                0 => {
                    exercise(sr, (), (), |s, (), o: &mut u64| unsafe {
                        plc_timers_iec_ltimer_ref_read_et(s, now, o)
                    });
                    exercise(so, (), (), |s, (), o: &mut bool| unsafe {
                        plc_timers_iec_ltimer_read_q(s, now, o)
                    });
                }
                1 => {
                    exercise(sr, (), (), |s, (), _: &mut ()| unsafe {
                        plc_timers_iec_ltimer_ref_reset(s)
                    });
                    exercise(so, (), (), |s, (), _: &mut ()| unsafe {
                        plc_timers_iec_ltimer_reset(s)
                    });
                }
                2 => {
                    exercise(sr, (), (), |s, (), _: &mut ()| unsafe {
                        plc_timers_iec_ltimer_ref_preset(s, pt_ns)
                    });
                    exercise(so, (), (), |s, (), _: &mut ()| unsafe {
                        plc_timers_iec_ltimer_preset(s, pt_ns)
                    });
                }
                _ => {
                    let n = one(retentive);
                    exercise(sr, retentive, n, |s, r, _: &mut ()| unsafe {
                        plc_timers_iec_ltimer_ref_run_stop_run(s, r)
                    });
                    exercise(so, retentive, n, |s, r, _: &mut ()| unsafe {
                        plc_timers_iec_ltimer_run_stop_run(s, r)
                    });
                }
            }
        }
        3 => match b.byte() % 4 {
            0 => iec_counter!(
                &mut b,
                i8,
                plc_timers_counter_sint_ref_call,
                plc_timers_counter_sint_call
            ),
            1 => iec_counter!(
                &mut b,
                i16,
                plc_timers_counter_int_ref_call,
                plc_timers_counter_int_call
            ),
            2 => iec_counter!(
                &mut b,
                u32,
                plc_timers_counter_udint_ref_call,
                plc_timers_counter_udint_call
            ),
            _ => iec_counter!(
                &mut b,
                i64,
                plc_timers_counter_lint_ref_call,
                plc_timers_counter_lint_call
            ),
        },
        4 | 5 => {
            let kind = b.kind();
            let raw = [b.byte(), b.byte(), b.byte(), b.byte(), b.byte()];
            let pv = b.u16();
            let (sr, so) = (from_bytes(&mut b), from_bytes(&mut b));
            // SAFETY (every closure): valid pointers to local values.
            if family % 8 == 4 {
                let input = plc_timers_s5_counter_input {
                    cu: raw[0],
                    cd: raw[1],
                    s: raw[2],
                    r: raw[3],
                    fr: raw[4],
                    pv,
                };
                let norm = plc_timers_s5_counter_input {
                    cu: one(raw[0]),
                    cd: one(raw[1]),
                    s: one(raw[2]),
                    r: one(raw[3]),
                    fr: one(raw[4]),
                    pv,
                };
                exercise(sr, input, norm, |s, i, o| unsafe {
                    plc_timers_s5_counter_ref_call(s, kind, i, o)
                });
                exercise(so, input, norm, |s, i, o| unsafe {
                    plc_timers_s5_counter_call(s, kind, i, o)
                });
            } else {
                let input = plc_timers_s5_counter_input_bcd {
                    cu: raw[0],
                    cd: raw[1],
                    s: raw[2],
                    r: raw[3],
                    fr: raw[4],
                    pv_bcd: pv,
                };
                let norm = plc_timers_s5_counter_input_bcd {
                    cu: one(raw[0]),
                    cd: one(raw[1]),
                    s: one(raw[2]),
                    r: one(raw[3]),
                    fr: one(raw[4]),
                    pv_bcd: pv,
                };
                exercise(sr, input, norm, |s, i, o| unsafe {
                    plc_timers_s5_counter_ref_call_bcd(s, kind, i, o)
                });
                exercise(so, input, norm, |s, i, o| unsafe {
                    plc_timers_s5_counter_call_bcd(s, kind, i, o)
                });
            }
        }
        6 => {
            // The timer memory area: one word or the clock from the fuzzer, the rest cleared
            // or all fuzzed; the box and the STL start with a byte RLO.
            let index = usize::from(b.byte());
            let kind = b.kind();
            let now = b.u64();
            let raw = [b.byte(), b.byte(), b.byte()];
            let tv = b.u16();
            let mut area: plc_timers_timer_memory = zeroed();
            area.now_ms = b.u64();
            if let Some(w) = area.words.get_mut(usize::from(b.byte())) {
                *w = b.u32();
            }
            let input = plc_timers_s5_input {
                s: raw[0],
                r: raw[1],
                fr: raw[2],
                tv,
            };
            let norm = plc_timers_s5_input {
                s: one(raw[0]),
                r: one(raw[1]),
                fr: one(raw[2]),
                tv,
            };
            // SAFETY (every closure): valid pointers to local values.
            exercise(area, input, norm, |s, i, o| unsafe {
                plc_timers_timer_memory_call(s, index, kind, now, i, o)
            });
            exercise(area, raw[0], one(raw[0]), |s, r, _: &mut ()| unsafe {
                plc_timers_timer_memory_start(s, index, kind, r, tv)
            });
        }
        _ => {
            let index = usize::from(b.byte());
            let kind = b.kind();
            let raw = [b.byte(), b.byte(), b.byte(), b.byte(), b.byte()];
            let pv = b.u16();
            let mut area: plc_timers_counter_memory = zeroed();
            if let Some(w) = area.words.get_mut(usize::from(b.byte())) {
                *w = b.u16();
            }
            let input = plc_timers_s5_counter_input_bcd {
                cu: raw[0],
                cd: raw[1],
                s: raw[2],
                r: raw[3],
                fr: raw[4],
                pv_bcd: pv,
            };
            let norm = plc_timers_s5_counter_input_bcd {
                cu: one(raw[0]),
                cd: one(raw[1]),
                s: one(raw[2]),
                r: one(raw[3]),
                fr: one(raw[4]),
                pv_bcd: pv,
            };
            // SAFETY (every closure): valid pointers to local values.
            exercise(area, input, norm, |s, i, o| unsafe {
                plc_timers_counter_memory_call_bcd(s, index, kind, i, o)
            });
            exercise(area, raw[2], one(raw[2]), |s, r, _: &mut ()| unsafe {
                plc_timers_counter_memory_set(s, index, r, pv)
            });
        }
    }
});
