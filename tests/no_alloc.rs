//! No step of any block allocates: a counting global allocator around steps of every block kind,
//! reference and optimized, and of every container: the S5 timer memory (box calls, the OS tick,
//! `advance_to`, the STL operations), the TON bank, the counter bank and the S5 counter memory.

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

use plc_timers::counter::s5::{
    CounterMemory, CounterPreset, S5Counter, S5CounterInput, S5CounterKind, S5CounterOps,
    S5CounterRef,
};
use plc_timers::counter::{
    ArrayOutputs, BankInputs, Counter, CounterBank, CounterInput, CounterKind, CounterOps,
    CounterRef,
};
use plc_timers::iec::{IecInput, IecKind, IecTimer, IecTimerOps, IecTimerRef, TonBank};
use plc_timers::s5::{S5Input, S5Kind, S5Timer, S5TimerOps, S5TimerRef, TimerMemory};
use plc_timers::time::{CpuTime, S5Time, Time, TimeBase};

struct Counting;

static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

// SAFETY: forwards every call to the system allocator unchanged; only counts.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::SeqCst);
        // SAFETY: the caller's contract is passed through.
        unsafe { System.alloc(layout) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: the caller's contract is passed through.
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

/// Everything the test steps, made before the counting starts.
struct Blocks {
    s5_refs: [S5TimerRef; 5],
    s5: [S5Timer; 5],
    area: TimerMemory<8>,
    iec_refs: [IecTimerRef; 4],
    iec: [IecTimer; 4],
    ton_bank: TonBank<3>,
    /// 20: one group of the array form and a padded last one.
    ton_array: [IecTimer; 20],
    ctr_refs: [CounterRef<i64>; 3],
    ctrs: [Counter<u64>; 3],
    ctr_bank: CounterBank<i32, 3>,
    ctr_array: [Counter<i16>; 20],
    s5c_refs: [S5CounterRef; 3],
    s5c: [S5Counter; 3],
    s5c_area: CounterMemory<4>,
}

/// CD of the array of counters at step `i`.
fn ins_down(i: u64) -> [bool; 20] {
    core::array::from_fn(|k| (i + k as u64) % 6 < 2)
}

/// One step of everything at step `i`; the results are summed so that none is optimized away.
fn step_all(b: &mut Blocks, i: u64, tv: S5Time, pt: Time, pv: CounterPreset) -> u64 {
    let mut sum = 0u64;
    let now = CpuTime::from_millis(i * 7);
    let s = i % 7 < 4;
    let input = S5Input {
        s,
        r: i.is_multiple_of(31),
        fr: i.is_multiple_of(13),
        tv,
    };
    for (k, kind) in S5Kind::ALL.into_iter().enumerate() {
        sum += u64::from(b.s5_refs[k].call(kind, now, input).bi);
        sum += u64::from(b.s5[k].call(kind, now, input).bcd);
        sum += u64::from(b.area.call(k, kind, now, input).map_or(0, |o| o.bi));
    }
    b.area.tick(TimeBase::Ms10, 1);
    b.area.tick(TimeBase::Ms100, 3);
    b.area.advance_to(CpuTime::from_millis(i * 7 + 3));
    b.area.fr(5, s).expect("T 5 exists");
    b.area.start(6, S5Kind::SPext, s, tv).expect("T 6 exists");
    b.area.reset(7, i.is_multiple_of(11)).expect("T 7 exists");
    let loads = (b.area.load(0), b.area.load_bcd(1), b.area.status(2));
    sum += u64::from(loads.0.unwrap_or(0)) + u64::from(loads.2.unwrap_or(false));
    sum += b.area.outputs().map(|o| u64::from(o.bi)).sum::<u64>();

    let ii = IecInput {
        input: s,
        pt,
        reset: i.is_multiple_of(17),
    };
    for (k, kind) in IecKind::ALL.into_iter().enumerate() {
        sum += u64::from(b.iec_refs[k].call(kind, now, ii).et);
        sum += u64::from(b.iec[k].call(kind, now, ii).et);
        sum += u64::from(b.iec_refs[k].read_q(now)) + u64::from(b.iec[k].read_et(now));
        if i.is_multiple_of(19) {
            b.iec_refs[k].reset_timer();
            b.iec[k].reset_timer();
            b.iec_refs[k].preset_timer(pt);
            b.iec[k].preset_timer(pt);
        }
        if i.is_multiple_of(97) {
            b.iec_refs[k].run_stop_run(k.is_multiple_of(2));
            b.iec[k].run_stop_run(k.is_multiple_of(2));
        }
    }
    b.ton_bank
        .scan(now, &[s, !s, i.is_multiple_of(3)], &[pt; 3]);
    sum += b.ton_bank.outputs().map(|o| u64::from(o.et)).sum::<u64>();
    if let Ok(state) = b.ton_bank.get(1) {
        assert_eq!(b.ton_bank.set_state(2, state), Ok(true));
    }
    let ins: [bool; 20] = core::array::from_fn(|k| (i + k as u64) % 5 < 3);
    let (mut q, mut et) = ([false; 20], [0u32; 20]);
    IecTimer::ton_array(&mut b.ton_array, now, &ins, &[pt; 20], &mut q, &mut et);
    sum += et.iter().map(|&e| u64::from(e)).sum::<u64>() + q.iter().filter(|&&q| q).count() as u64;

    let ci = CounterInput {
        cu: s,
        cd: i.is_multiple_of(3),
        r: i.is_multiple_of(29),
        ld: i.is_multiple_of(37),
        pv: 5,
    };
    for (k, kind) in CounterKind::ALL.into_iter().enumerate() {
        sum += b.ctr_refs[k].call(kind, ci).cv.unsigned_abs();
        let unsigned = CounterInput {
            cu: ci.cu,
            cd: ci.cd,
            r: ci.r,
            ld: ci.ld,
            pv: 5u64,
        };
        sum += b.ctrs[k].call(kind, unsigned).cv;
    }
    let (cu, cd) = ([s, !s, i.is_multiple_of(5)], [i.is_multiple_of(3); 3]);
    let none = [false; 3];
    b.ctr_bank.scan(
        &BankInputs {
            cu: &cu,
            cd: &cd,
            r: &[i.is_multiple_of(29); 3],
            ld: &none,
        },
        7,
    );
    sum += b
        .ctr_bank
        .outputs(7)
        .map(|o| o.cv.unsigned_abs() as u64)
        .sum::<u64>();
    if let Ok(state) = b.ctr_bank.get(0) {
        assert_eq!(b.ctr_bank.set_state(1, state), Ok(()));
    }
    let up: [bool; 20] = core::array::from_fn(|k| (i + k as u64) % 4 < 2);
    let off = [false; 20];
    let (mut qu, mut qd, mut cv) = ([false; 20], [false; 20], [0i16; 20]);
    for kind in CounterKind::ALL {
        Counter::call_array(
            &mut b.ctr_array,
            kind,
            &BankInputs {
                cu: &up,
                cd: &ins_down(i),
                r: &off,
                ld: &off,
            },
            &[9; 20],
            &mut ArrayOutputs {
                qu: &mut qu,
                qd: &mut qd,
                cv: &mut cv,
            },
        );
        sum += cv.iter().map(|c| c.unsigned_abs() as u64).sum::<u64>();
        sum += (qu.iter().chain(&qd)).filter(|&&q| q).count() as u64;
    }

    let sci = S5CounterInput {
        cu: s,
        cd: i.is_multiple_of(3),
        s: i.is_multiple_of(50),
        r: i.is_multiple_of(71),
        fr: i.is_multiple_of(23),
        pv,
    };
    for (k, kind) in S5CounterKind::ALL.into_iter().enumerate() {
        sum += u64::from(b.s5c_refs[k].call(kind, sci).cv);
        sum += u64::from(b.s5c[k].call(kind, sci).cv_bcd);
        sum += u64::from(b.s5c_area.call(k, kind, sci).map_or(0, |o| o.cv));
    }
    b.s5c_area.fr(3, s).expect("C 3 exists");
    b.s5c_area.cu(3, s).expect("C 3 exists");
    b.s5c_area.cd(3, i.is_multiple_of(3)).expect("C 3 exists");
    b.s5c_area
        .set(3, i.is_multiple_of(40), pv)
        .expect("C 3 exists");
    b.s5c_area
        .reset(3, i.is_multiple_of(90))
        .expect("C 3 exists");
    sum += u64::from(b.s5c_area.load(3).unwrap_or(0) + b.s5c_area.load_bcd(3).unwrap_or(0));
    sum += u64::from(b.s5c_area.status(3).unwrap_or(false));
    sum
}

#[test]
fn no_step_allocates() {
    let tv = S5Time::from_word(0x0005).expect("valid");
    let pt = Time::from_millis(30);
    let pv = CounterPreset::new(3).expect("valid");
    let mut blocks = Blocks {
        s5_refs: [S5TimerRef::new(); 5],
        s5: [S5Timer::new(); 5],
        area: TimerMemory::new(),
        iec_refs: [IecTimerRef::new(); 4],
        iec: [IecTimer::new(); 4],
        ton_bank: TonBank::new(),
        ton_array: [IecTimer::new(); 20],
        ctr_refs: [CounterRef::new(); 3],
        ctrs: [Counter::new(); 3],
        ctr_bank: CounterBank::new(),
        ctr_array: [Counter::new(); 20],
        s5c_refs: [S5CounterRef::new(); 3],
        s5c: [S5Counter::new(); 3],
        s5c_area: CounterMemory::new(),
    };

    let before = ALLOCATIONS.load(Ordering::SeqCst);
    let mut sum = 0u64;
    for i in 0..2_000u64 {
        sum = sum.wrapping_add(step_all(&mut blocks, i, tv, pt, pv));
    }
    let after = ALLOCATIONS.load(Ordering::SeqCst);
    assert_eq!(
        after - before,
        0,
        "steps allocated {} times",
        after - before
    );
    assert_ne!(sum, 0, "the steps ran");
}
