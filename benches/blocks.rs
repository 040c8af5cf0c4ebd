//! Reference vs optimized on what the peers benchmark (`benches/peers/main.rs`) leaves out: the
//! IEC counters over every integer type, the small 256-timer area, the LAD box calls on the timer
//! area, and the S5 counter memory's STL operations. `cargo bench --bench blocks`; the figures of
//! the README come from the peers benchmark, not from this one.

// criterion_group! generates an undocumented function.
#![allow(missing_docs)]

#[path = "common/mod.rs"]
mod common;

use std::hint::black_box;

use common::STEPS;
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use plc_timers::counter::s5::{CounterMemory, CounterPreset};
use plc_timers::counter::{Counter, CounterInput, CounterInt, CounterKind, CounterOps, CounterRef};
use plc_timers::s5::{S5Input, S5Kind, S5State, TimerMemory, TimerWord};
use plc_timers::time::{CpuTime, S5Time, TimeBase};

/// CTUD over one integer type: reference and optimized on the one-step stream.
fn ctud_of<T: CounterInt + From<i8>>(c: &mut Criterion) {
    let stream = common::step_stream(1);
    let pv = T::from(10);
    let inputs: Vec<CounterInput<T>> = stream
        .iter()
        .map(|s| CounterInput {
            cu: s.bit(0),
            cd: s.bit(1),
            r: s.bit(2),
            ld: s.bit(3),
            pv,
        })
        .collect();
    let mut g = c.benchmark_group("CTUD by type (per 1024 steps)");
    g.throughput(Throughput::Elements(STEPS as u64));
    g.bench_function(BenchmarkId::new("reference", T::NAME), |b| {
        let mut t = CounterRef::<T>::new();
        b.iter(|| {
            for &i in &inputs {
                black_box(t.call(CounterKind::Ctud, i));
            }
        })
    });
    g.bench_function(BenchmarkId::new("optimized", T::NAME), |b| {
        let mut t = Counter::<T>::new();
        b.iter(|| {
            for &i in &inputs {
                black_box(t.call(CounterKind::Ctud, i));
            }
        })
    });
    g.finish();
}

fn counters_by_type(c: &mut Criterion) {
    ctud_of::<i8>(c);
    ctud_of::<i16>(c);
    ctud_of::<i32>(c);
    ctud_of::<i64>(c);
}

/// The 256-timer area (the number LAD addresses): one 10 ms tick, and a scan of 256 LAD boxes.
fn small_area(c: &mut Criterion) {
    const N: usize = 256;
    let mut words = [TimerWord::RESET; N];
    for (w, content) in words.iter_mut().zip(common::area_contents(N)) {
        if let Some((value, base)) = content {
            let state = S5State {
                running: true,
                value,
                base: TimeBase::from_bits(base),
                q: true,
                s_prev: true,
                ..S5State::RESET
            };
            *w = TimerWord::from_state(state).expect("a valid state");
        }
    }
    let area = TimerMemory::<N>::from_words(words, CpuTime::ZERO);
    let mut g = c.benchmark_group("timer area of 256");
    g.bench_function("one 10 ms tick", |b| {
        let mut a = area.clone();
        b.iter(|| {
            a.tick(TimeBase::Ms10, 1);
            black_box(&mut a);
        })
    });
    let tv = S5Time::from_word(0x0005).expect("a valid S5TIME word");
    g.bench_function("a scan of 256 S_ODT boxes, 10 ms apart", |b| {
        let mut a = area.clone();
        let mut scan = 0u64;
        b.iter(|| {
            scan += 1;
            let now = CpuTime::from_millis(10 * scan);
            for t in 0..N {
                let s = (scan + t as u64) % 7 < 4;
                let _ = black_box(a.call(t, S5Kind::SOdt, now, S5Input::new(s, false, tv)));
            }
        })
    });
    g.finish();
}

/// The S5 counter memory: the STL sequence FR, CU, CD, S, R on each of 256 counters.
fn counter_memory(c: &mut Criterion) {
    let pv = CounterPreset::new(5).expect("0..=999");
    let stream = common::step_stream(2);
    c.bench_function("S5 counter memory of 256, one STL scan", |b| {
        let mut m = CounterMemory::<256>::new();
        let mut k = 0usize;
        b.iter(|| {
            for n in 0..256 {
                let s = stream[(k + n) % STEPS];
                let _ = m.fr(n, false);
                let _ = m.cu(n, s.bit(0));
                let _ = m.cd(n, s.bit(1));
                let _ = m.set(n, s.bit(3), pv);
                let _ = m.reset(n, s.bit(2));
            }
            k += 1;
            black_box(&mut m);
        })
    });
}

criterion_group!(benches, counters_by_type, small_area, counter_memory);
criterion_main!(benches);
