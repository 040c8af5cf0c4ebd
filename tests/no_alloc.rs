//! No step of any block allocates: a counting global allocator around steps of every block kind,
//! reference and optimized, including the timer and counter memory areas and the counter bank.

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

use plc_timers::counter::packed::{BankInputs, CounterBank, PackedCounter};
use plc_timers::counter::reference::CounterRef;
use plc_timers::counter::s5::{
    CounterMemory, CounterPreset, S5CounterInput, S5CounterKind, S5CounterRef,
};
use plc_timers::counter::{CounterInput, CounterKind, CounterOps};
use plc_timers::iec::reference::Reference;
use plc_timers::iec::{IecInput, IecKind, IecTimer, IecTimerOps};
use plc_timers::s5::memory::TimerMemory;
use plc_timers::s5::reference::S5TimerRef;
use plc_timers::s5::{S5Input, S5Kind};
use plc_timers::time::{S5Time, Time, TimeBase};

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

#[test]
fn no_step_allocates() {
    let tv = S5Time::from_word(0x0005).expect("valid");
    let pt = Time::from_millis(30);
    let pv = CounterPreset::new(3).expect("valid");
    let mut s5_refs = S5Kind::ALL.map(S5TimerRef::new);
    let mut area = TimerMemory::<8>::new();
    let mut iec_ref = Reference::<u32>::new();
    let mut iec = IecTimer::new();
    let mut ctr_ref = CounterRef::<i64>::new(CounterKind::Ctud);
    let mut ctr = PackedCounter::<u64>::new();
    let mut bank = CounterBank::<i32, 2>::new();
    let mut s5c_ref = S5CounterRef::new(S5CounterKind::SCud);
    let mut s5c = CounterMemory::<4>::new();

    let before = ALLOCATIONS.load(Ordering::SeqCst);
    for i in 0..1_000u64 {
        let s = i % 7 < 4;
        let input = S5Input {
            s,
            r: i % 31 == 0,
            fr: i % 13 == 0,
            tv,
        };
        for (k, t) in s5_refs.iter_mut().enumerate() {
            t.call(i * 10, input);
            let _ = area.call(k, S5Kind::ALL[k], i * 10, input);
        }
        area.tick(TimeBase::Ms10, 1);
        let _ = (area.load(0), area.load_bcd(1), area.status(2));
        for kind in IecKind::ALL {
            let ii = IecInput {
                input: s,
                pt,
                reset: i % 17 == 0,
            };
            iec_ref.call(kind, i as u32 * 10, ii);
            iec.call(kind, i as u32 * 10, ii);
        }
        iec.read_q(i as u32);
        iec.reset_timer();
        let ci = CounterInput {
            cu: s,
            cd: i % 3 == 0,
            r: i % 29 == 0,
            ld: i % 37 == 0,
            pv: 5,
        };
        ctr_ref.call(ci);
        ctr.call(
            CounterKind::Ctud,
            CounterInput {
                cu: s,
                cd: i % 3 == 0,
                r: false,
                ld: false,
                pv: 5,
            },
        );
        let w = [i.wrapping_mul(0x9E37_79B9_7F4A_7C15); 2];
        bank.scan(
            BankInputs {
                cu: &w,
                cd: &[!w[0]; 2],
                r: &[0; 2],
                ld: &[0; 2],
            },
            7,
        );
        let sci = S5CounterInput {
            cu: s,
            cd: i % 3 == 0,
            s: i % 50 == 0,
            r: i % 71 == 0,
            pv,
        };
        s5c_ref.call(sci);
        let _ = s5c.call(1, S5CounterKind::SCud, sci);
    }
    let after = ALLOCATIONS.load(Ordering::SeqCst);
    assert_eq!(
        after - before,
        0,
        "steps allocated {} times",
        after - before
    );
}
