//! Reference vs optimized, in the same run: what a soft-PLC pays per scan for its timers and
//! counters. `cargo bench`; the README's "Performance" table reports one run.

// criterion_group! generates an undocumented function.
#![allow(missing_docs)]

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use plc_timers::counter::packed::{BankInputs, CounterBank, PackedCounter};
use plc_timers::counter::reference::CounterRef;
use plc_timers::counter::s5::{
    CounterMemory, CounterPreset, S5CounterInput, S5CounterKind, S5CounterRef,
};
use plc_timers::counter::{CounterInput, CounterKind, CounterOps};
use plc_timers::iec::bank::TonBank;
use plc_timers::iec::reference::Reference;
use plc_timers::iec::{IecInput, IecKind, IecTimer, IecTimerOps};
use plc_timers::s5::cell::{Cell, PackedTimer};
use plc_timers::s5::memory::TimerMemory;
use plc_timers::s5::reference::S5TimerRef;
use plc_timers::s5::{S5Input, S5Kind};
use plc_timers::time::{S5Time, Time, TimeBase};

/// A small deterministic generator (xorshift), so both implementations see the same data.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
}

/// Steps per iteration of the one-step benchmarks: the inputs are drawn beforehand, so the
/// timed loop is only the block (and the per-step time is the iteration time / STEPS).
const STEPS: usize = 1024;

/// Random input bits with clustered edges: each bit keeps its value with probability 3/4.
fn input_bits(seed: u64) -> Vec<u8> {
    let mut rng = Rng(seed);
    let mut bits = 0u8;
    (0..STEPS)
        .map(|_| {
            let flip = (rng.next() & rng.next()) as u8; // each bit flips with p = 1/4
            bits ^= flip;
            bits
        })
        .collect()
}

fn one_step(c: &mut Criterion) {
    let mut g = c.benchmark_group("one step (per 1024 steps)");
    g.throughput(Throughput::Elements(STEPS as u64));
    let bits = input_bits(1);
    let tv = S5Time::from_word(0x0005).expect("valid");
    let s5_inputs: Vec<S5Input> = bits
        .iter()
        .map(|b| S5Input {
            s: b & 1 != 0,
            r: b & 0x70 == 0x70,
            fr: false,
            tv,
        })
        .collect();
    for kind in S5Kind::ALL {
        g.bench_function(BenchmarkId::new("reference", kind.name()), |b| {
            let mut t = S5TimerRef::new(kind);
            let mut now = 0u64;
            b.iter(|| {
                for &input in &s5_inputs {
                    now += 7;
                    black_box(t.call(now, input));
                }
            })
        });
        g.bench_function(BenchmarkId::new("optimized", kind.name()), |b| {
            let mut t = PackedTimer::new();
            let mut now = 0u64;
            b.iter(|| {
                for &input in &s5_inputs {
                    now += 7;
                    black_box(t.call(kind, now, input));
                }
            })
        });
    }
    let pt = Time::from_millis(30);
    let iec_inputs: Vec<IecInput> = bits
        .iter()
        .map(|b| IecInput {
            input: b & 1 != 0,
            pt,
            reset: b & 0x70 == 0x70,
        })
        .collect();
    for kind in IecKind::ALL {
        g.bench_function(BenchmarkId::new("reference", kind.name()), |b| {
            let mut t = Reference::<u32>::new();
            let mut now = 0u32;
            b.iter(|| {
                for &input in &iec_inputs {
                    now = now.wrapping_add(7);
                    black_box(t.call(kind, now, input));
                }
            })
        });
        g.bench_function(BenchmarkId::new("optimized", kind.name()), |b| {
            let mut t = IecTimer::new();
            let mut now = 0u32;
            b.iter(|| {
                for &input in &iec_inputs {
                    now = now.wrapping_add(7);
                    black_box(t.call(kind, now, input));
                }
            })
        });
    }
    let ctr_inputs: Vec<CounterInput<i16>> = bits
        .iter()
        .map(|b| CounterInput {
            cu: b & 1 != 0,
            cd: b & 2 != 0,
            r: b & 0x70 == 0x70,
            ld: b & 0x0C == 0x0C,
            pv: 10,
        })
        .collect();
    for kind in CounterKind::ALL {
        g.bench_function(BenchmarkId::new("reference", kind.name()), |b| {
            let mut ctr = CounterRef::<i16>::new(kind);
            b.iter(|| {
                for &input in &ctr_inputs {
                    black_box(ctr.call(input));
                }
            })
        });
        g.bench_function(BenchmarkId::new("optimized", kind.name()), |b| {
            let mut ctr = PackedCounter::<i16>::new();
            b.iter(|| {
                for &input in &ctr_inputs {
                    black_box(ctr.call(kind, input));
                }
            })
        });
    }
    let pv = CounterPreset::new(5).expect("valid");
    let s5c_inputs: Vec<S5CounterInput> = bits
        .iter()
        .map(|b| S5CounterInput {
            cu: b & 1 != 0,
            cd: b & 2 != 0,
            s: b & 0x0C == 0x0C,
            r: b & 0x70 == 0x70,
            pv,
        })
        .collect();
    for kind in S5CounterKind::ALL {
        g.bench_function(BenchmarkId::new("reference", kind.name()), |b| {
            let mut ctr = S5CounterRef::new(kind);
            b.iter(|| {
                for &input in &s5c_inputs {
                    black_box(ctr.call(input));
                }
            })
        });
        g.bench_function(BenchmarkId::new("optimized", kind.name()), |b| {
            let mut area = CounterMemory::<1>::new();
            b.iter(|| {
                for &input in &s5c_inputs {
                    let _ = black_box(area.call(0, kind, input));
                }
            })
        });
    }
    g.finish();
}

/// A realistic timer area: a third stopped, the rest running on a mix of bases and values.
fn timer_states(n: usize) -> Vec<S5TimerRef> {
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let kinds = S5Kind::ALL;
    (0..n)
        .map(|i| {
            let kind = kinds[i % 5];
            let mut t = S5TimerRef::new(kind);
            if rng.next() % 3 != 0 {
                let units = (rng.next() % 999 + 1) as u16;
                let base = TimeBase::from_bits((rng.next() % 4) as u8);
                let tv = S5Time::new(units, base).expect("units <= 999");
                let s = !kind.starts_on_falling_edge();
                if !s {
                    t.execute(S5Input::new(true, false, tv));
                }
                t.execute(S5Input::new(s, false, tv));
            }
            t
        })
        .collect()
}

fn area_tick<const N: usize>(c: &mut Criterion, name: &str) {
    let refs = timer_states(N);
    let mut cells = Box::new([Cell::RESET; N]);
    for (cell, r) in cells.iter_mut().zip(&refs) {
        *cell = Cell::from_state(r.state).expect("valid state");
    }
    let mut g = c.benchmark_group(format!("timer area tick, {name} timers"));
    g.throughput(Throughput::Bytes((N * 2) as u64));
    g.bench_function("reference", |b| {
        let mut refs = refs.clone();
        b.iter(|| {
            // The OS tick of the 10 ms base: every timer on that base loses one unit.
            for t in refs.iter_mut() {
                if t.state.base == TimeBase::Ms10 {
                    t.tick(1);
                }
            }
            black_box(&refs);
        })
    });
    g.bench_function("optimized", |b| {
        let mut area = Box::new(TimerMemory::<N>::from_cells(*cells, 0));
        b.iter(|| {
            area.tick(TimeBase::Ms10, 1);
            black_box(&area);
        })
    });
    g.bench_function("copy of the area (baseline)", |b| {
        let src = cells.clone();
        let mut dst = Box::new([Cell::RESET; N]);
        b.iter(|| {
            dst.copy_from_slice(black_box(&src[..]));
            black_box(&dst);
        })
    });
    g.finish();
}

fn area_ticks(c: &mut Criterion) {
    area_tick::<256>(c, "256");
    area_tick::<65_536>(c, "65 536");
}

/// 157 words of 64: the bank's size, and the same number of single structures.
const TON_WORDS: usize = 157;
const TONS: usize = 64 * TON_WORDS;

/// Each TON's IN follows its own square wave (period 20..=200 scans, duty 25..75 %) and its PT
/// is 100..=2 000 ms; a scan every 10 ms. So at any scan some timers are timing, some have
/// expired, some are off, and some see an edge.
fn ton_scan(c: &mut Criterion) {
    let mut rng = Rng(42);
    let waves: Vec<(u32, u32, u32)> = (0..TONS)
        .map(|_| {
            let period = (rng.next() % 181 + 20) as u32;
            let on = period * (rng.next() % 51 + 25) as u32 / 100;
            (period, on, (rng.next() % u64::from(period)) as u32)
        })
        .collect();
    let pts: Vec<Time> = (0..TONS)
        .map(|_| Time::from_millis((rng.next() % 1_901 + 100) as i32))
        .collect();
    // The inputs of 200 successive scans, drawn beforehand so that only the timers are timed.
    let scans: Vec<Vec<bool>> = (0..200u32)
        .map(|scan| {
            waves
                .iter()
                .map(|&(period, on, phase)| (scan + phase) % period < on)
                .collect()
        })
        .collect();
    let mut g = c.benchmark_group("scan of 10 048 TON");
    g.throughput(Throughput::Elements(TONS as u64));
    g.bench_function("reference", |b| {
        let mut timers = vec![Reference::<u32>::new(); TONS];
        let mut scan = 0usize;
        b.iter(|| {
            scan += 1;
            let now = (scan as u32).wrapping_mul(10);
            let inputs = &scans[scan % scans.len()];
            for ((t, &input), &pt) in timers.iter_mut().zip(inputs).zip(&pts) {
                black_box(t.call(IecKind::Ton, now, IecInput::new(input, pt)));
            }
        })
    });
    g.bench_function("optimized", |b| {
        let mut timers = vec![IecTimer::new(); TONS];
        let mut scan = 0usize;
        b.iter(|| {
            scan += 1;
            let now = (scan as u32).wrapping_mul(10);
            let inputs = &scans[scan % scans.len()];
            for ((t, &input), &pt) in timers.iter_mut().zip(inputs).zip(&pts) {
                black_box(t.call(IecKind::Ton, now, IecInput::new(input, pt)));
            }
        })
    });
    let bits: Vec<[u64; TON_WORDS]> = scans
        .iter()
        .map(|inputs| {
            let mut w = [0u64; TON_WORDS];
            for (i, &b) in inputs.iter().enumerate() {
                w[i / 64] |= u64::from(b) << (i % 64);
            }
            w
        })
        .collect();
    let mut pt_words = Box::new([[Time::ZERO; 64]; TON_WORDS]);
    for (i, &pt) in pts.iter().enumerate() {
        pt_words[i / 64][i % 64] = pt;
    }
    g.bench_function("optimized bank (TonBank)", |b| {
        let mut bank = Box::new(TonBank::<TON_WORDS>::new());
        let mut scan = 0usize;
        b.iter(|| {
            scan += 1;
            let now = (scan as u32).wrapping_mul(10);
            bank.scan(now, &bits[scan % bits.len()], &pt_words);
            black_box(&bank);
        })
    });
    g.finish();
}

const WORDS: usize = 157; // 10 048 counters

fn counter_bank(c: &mut Criterion) {
    let mut rng = Rng(7);
    // 64 scans of random edges: every input bit random, R and LD rare.
    let scans: Vec<[[u64; WORDS]; 4]> = (0..64)
        .map(|_| {
            let mut s = [[0u64; WORDS]; 4];
            for (k, words) in s.iter_mut().enumerate() {
                for word in words.iter_mut() {
                    // CU and CD: every bit random; R and LD: each bit set with p = 1/16.
                    *word = if k < 2 {
                        rng.next()
                    } else {
                        rng.next() & rng.next() & rng.next() & rng.next()
                    };
                }
            }
            s
        })
        .collect();
    let n = 64 * WORDS;
    let mut g = c.benchmark_group("bank of 10 048 CTUD INT");
    g.throughput(Throughput::Elements(n as u64));
    g.bench_function("reference", |b| {
        let mut counters = vec![CounterRef::<i16>::new(CounterKind::Ctud); n];
        let mut k = 0;
        b.iter(|| {
            let s = &scans[k % scans.len()];
            k += 1;
            for (i, ctr) in counters.iter_mut().enumerate() {
                let bit = |w: &[u64; WORDS]| w[i / 64] >> (i % 64) & 1 != 0;
                black_box(ctr.call(CounterInput {
                    cu: bit(&s[0]),
                    cd: bit(&s[1]),
                    r: bit(&s[2]),
                    ld: bit(&s[3]),
                    pv: 100,
                }));
            }
        })
    });
    g.bench_function("optimized", |b| {
        let mut bank = Box::new(CounterBank::<i16, WORDS>::new());
        let mut k = 0;
        b.iter(|| {
            let s = &scans[k % scans.len()];
            k += 1;
            bank.scan(
                BankInputs {
                    cu: &s[0],
                    cd: &s[1],
                    r: &s[2],
                    ld: &s[3],
                },
                100,
            );
            black_box(&bank);
        })
    });
    g.finish();
}

criterion_group!(benches, one_step, area_ticks, ton_scan, counter_bank);
criterion_main!(benches);
