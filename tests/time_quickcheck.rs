//! quickcheck properties of the literal parsers and the time arithmetic. Shrinking gives the
//! smallest failing literal or number.

use plc_timers::counter::s5::CounterPreset;
use plc_timers::s5::ticks_between;
use plc_timers::time::clock::ClockWord;
use plc_timers::time::{S5Time, Time, TimeBase};
use quickcheck::{quickcheck, TestResult};

quickcheck! {
    /// S5T-LIT-01: any valid word formats to a literal that parses to the same duration.
    fn s5time_literal_round_trip(word: u16) -> TestResult {
        let Ok(t) = S5Time::from_word(word) else { return TestResult::discard() };
        let back = t.to_string().parse::<S5Time>();
        TestResult::from_bool(back.map(S5Time::as_millis) == Ok(t.as_millis()))
    }

    /// TIME-LIT-01: every TIME formats to a literal that parses back to itself.
    fn time_literal_round_trip(ms: i32) -> bool {
        let t = Time::from_millis(ms);
        t.to_string().parse::<Time>() == Ok(t)
    }

    /// The parsers never panic, and an accepted text is within range.
    fn parsers_total(text: String) -> bool {
        let s5_ok = text.parse::<S5Time>().map_or(true, |t| t.as_millis() <= S5Time::MAX_MILLIS);
        let _ = text.parse::<Time>();
        let pv_ok = text.parse::<CounterPreset>().map_or(true, |p| p.value() <= 999);
        s5_ok && pv_ok
    }

    /// Lower-case and underscore-free spellings parse to the same TIME as the canonical form.
    fn time_literal_spellings(ms: i32) -> bool {
        let canonical = Time::from_millis(ms).to_string();
        let lower = canonical.to_ascii_lowercase();
        let compact = canonical.replace('_', "");
        lower.parse::<Time>() == Ok(Time::from_millis(ms)) && compact.parse::<Time>() == Ok(Time::from_millis(ms))
    }

    /// S5TMR-TICK-01: tick counts are additive over consecutive intervals (no tick is lost or
    /// counted twice when a trace is split at any execution).
    fn ticks_additive(a: u64, b: u64, c: u64, base: u8) -> bool {
        let mut t = [a, b, c];
        t.sort_unstable();
        let base = TimeBase::from_bits(base);
        ticks_between(t[0], t[2], base) == ticks_between(t[0], t[1], base) + ticks_between(t[1], t[2], base)
    }

    /// IEC-WRAP-01: on the 32-bit clock, elapsed time is exact across the wrap for any start
    /// and any duration below 2^32 ms.
    fn clock_elapsed_across_wrap(start: u32, d: u32) -> bool {
        start.advance(d).elapsed_since(start) == d
            && u32::from_u64_wrapping(u64::from(start) + (1 << 32)) == start
    }
}
