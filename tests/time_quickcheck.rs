//! quickcheck properties of the literal parsers and the time arithmetic. Shrinking gives the
//! smallest failing literal or number.

use plc_timers::counter::s5::CounterPreset;
use plc_timers::s5::ticks_between;
use plc_timers::time::clock::ClockWord;
use plc_timers::time::{CpuTime, S5Time, Time, TimeBase};
use quickcheck::{quickcheck, TestResult};

quickcheck! {
    /// A CPU time made from milliseconds, either way, gives them back.
    fn cpu_time_millis_round_trip(ms: u64) -> bool {
        CpuTime::from(ms).as_millis() == ms && CpuTime::from_millis(ms) == CpuTime::from(ms)
    }

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

    /// S5T-AUTO-BASE-01: any duration up to 9 990 s parses from its exact `MS` literal to the
    /// automatic encoding: rounded down by less than one unit of the chosen base.
    fn s5time_ms_literal_rounds_down(ms: u32) -> bool {
        let ms = ms % (S5Time::MAX_MILLIS + 1);
        let Ok(t) = format!("S5T#{ms}MS").parse::<S5Time>() else { return false };
        t.as_millis() <= ms && ms - t.as_millis() < t.base().millis() && t.is_automatic()
    }

    /// S5T-LIT-01: a `W#16#` literal of any word parses exactly as `from_word` decodes it.
    fn s5time_word_literal_is_from_word(word: u16) -> bool {
        let parsed = format!("W#16#{word:04X}").parse::<S5Time>();
        match S5Time::from_word(word) {
            Ok(t) => parsed == Ok(t),
            Err(_) => parsed.is_err(),
        }
    }

    /// TIME-LIT-01: a TIME literal built from components (days..ms, each in range) parses to
    /// their sum, or is out of range exactly when the sum leaves the 32-bit range.
    fn time_literal_from_components(neg: bool, d: u8, h: u8, m: u8, s: u8, ms: u16) -> bool {
        let (d, h, m, s, ms) = (u64::from(d % 30), u64::from(h % 24), u64::from(m % 60), u64::from(s % 60), u64::from(ms % 1000));
        let text = format!("T#{}{d}d_{h}h_{m}m_{s}s_{ms}ms", if neg { "-" } else { "" });
        let magnitude = (((d * 24 + h) * 60 + m) * 60 + s) * 1000 + ms;
        let exact = if neg { -(magnitude as i64) } else { magnitude as i64 };
        text.parse::<Time>().ok() == Time::from_millis_i64(exact)
    }

    /// TIME-ARITH-01: checked add/sub agree with 64-bit arithmetic; saturating ones clamp it.
    fn time_arith_matches_i64(a: i32, b: i32) -> bool {
        let (ta, tb) = (Time::from_millis(a), Time::from_millis(b));
        let clamp = |v: i64| Time::from_millis(v.clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32);
        let (sum, diff) = (i64::from(a) + i64::from(b), i64::from(a) - i64::from(b));
        ta.checked_add(tb) == Time::from_millis_i64(sum)
            && ta.checked_sub(tb) == Time::from_millis_i64(diff)
            && ta.saturating_add(tb) == clamp(sum)
            && ta.saturating_sub(tb) == clamp(diff)
    }

    /// S5TMR-TICK-01: tick counts are additive over consecutive intervals (no tick is lost or
    /// counted twice when a trace is split at any execution).
    fn ticks_additive(a: u64, b: u64, c: u64, base: u8) -> bool {
        let mut t = [a, b, c];
        t.sort_unstable();
        let base = TimeBase::from_bits(base);
        let [a, b, c] = t.map(CpuTime::from_millis);
        ticks_between(a, c, base) == ticks_between(a, b, base) + ticks_between(b, c, base)
    }

    /// IEC-WRAP-01: on the 32-bit clock, elapsed time is exact across the wrap for any start
    /// and any duration below 2^32 ms.
    fn clock_elapsed_across_wrap(start: u32, d: u32) -> bool {
        start.advance(d).elapsed_since(start) == d
            && u32::from_u64_wrapping(u64::from(start) + (1 << 32)) == start
    }
}
