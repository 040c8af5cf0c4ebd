//! Properties of the time formats: S5TIME decoding and encoding, literal round-trips for
//! S5TIME and TIME.

use crate::cover::{check, check_eq};
use plc_timers::time::{bcd3_decode, bcd3_encode, LTime, LiteralErrorKind, S5Time, Time, TimeBase};
use proptest::prelude::*;

/// S5T-WORD-01, S5T-BCD-01: a raw word decodes exactly when its three value digits are BCD
/// (bits 15-14 ignored); then the units are the decimal reading, at most 999, the duration at most
/// 9 990 s, and re-encoding gives the word without bits 15-14.
pub fn prop_word_decode(word: u16) {
    let digits = [(word >> 8) & 0xF, (word >> 4) & 0xF, word & 0xF];
    match S5Time::from_word(word) {
        Ok(t) => {
            check!(
                digits.iter().all(|&d| d <= 9),
                "S5T-BCD-01: W#16#{word:04X} accepted"
            );
            check_eq!(
                t.units(),
                digits[0] * 100 + digits[1] * 10 + digits[2],
                "S5T-WORD-01"
            );
            check_eq!(
                t.base().bits(),
                ((word >> 12) & 3) as u8,
                "S5T-WORD-01: base bits"
            );
            check!(t.as_millis() <= S5Time::MAX_MILLIS, "S5T-RANGE-01");
            check_eq!(
                t.to_word(),
                word & 0x3FFF,
                "S5T-WORD-01: bits 15-14 ignored, never produced"
            );
        }
        Err(_) => check!(
            digits.iter().any(|&d| d > 9),
            "S5T-BCD-01: W#16#{word:04X} rejected"
        ),
    }
}

/// S5T-AUTO-BASE-01: a duration up to 9 990 s encodes on the finest base whose rounded-down
/// value fits 999 units, rounded down (less than one unit lost); above it is an error.
pub fn prop_from_millis(ms: u64) {
    match S5Time::from_millis(ms) {
        Ok(t) => {
            let b = u64::from(t.base().millis());
            check!(
                u64::from(t.as_millis()) <= ms && ms - u64::from(t.as_millis()) < b,
                "S5T-AUTO-BASE-01: rounded down by less than one unit"
            );
            if let Some(finer) = TimeBase::ALL.get(usize::from(t.base().bits()).wrapping_sub(1)) {
                check!(
                    ms / u64::from(finer.millis()) > 999,
                    "S5T-AUTO-BASE-01: a finer base would fit"
                );
            }
        }
        Err(_) => check!(
            ms > u64::from(S5Time::MAX_MILLIS),
            "S5T-RANGE-01: {ms} ms rejected"
        ),
    }
}

/// The literal of `millis` as the rules spell it, computed here from the rule text and not by
/// the crate: the components from the largest unit down (`D` only when `days`), each a decimal
/// number and its upper-case unit, zero components left out, `sep` between two, and `0MS` for
/// zero (TIME-LIT-01: `T#2S_200MS`; S5T-LIT-01: `S5T#2M7S`, without underscores).
pub fn expected_components(millis: u64, days: bool, sep: &str) -> String {
    const UNITS: [(u64, &str); 5] = [
        (24 * 60 * 60 * 1_000, "D"),
        (60 * 60 * 1_000, "H"),
        (60 * 1_000, "M"),
        (1_000, "S"),
        (1, "MS"),
    ];
    spelled(millis, &UNITS[usize::from(!days)..], sep)
}

/// `value` spelled in `units` (size in the value's unit, symbol; largest first): each non-zero
/// component as a decimal number and its symbol, `sep` between two, `0` and the smallest unit
/// for zero.
fn spelled(value: u64, units: &[(u64, &str)], sep: &str) -> String {
    let mut parts = Vec::new();
    let mut rest = value;
    for (size, unit) in units {
        let n = rest / size;
        rest -= n * size;
        if n != 0 {
            parts.push(format!("{n}{unit}"));
        }
    }
    if parts.is_empty() {
        let smallest = units.last().map_or("", |(_, u)| u);
        parts.push(format!("0{smallest}"));
    }
    parts.join(sep)
}

/// The LTIME units with their length in nanoseconds, written from LTIME-LIT-01's text.
const LTIME_UNITS: [(u64, &str); 7] = [
    (86_400 * 1_000_000_000, "D"),
    (3_600 * 1_000_000_000, "H"),
    (60 * 1_000_000_000, "M"),
    (1_000_000_000, "S"),
    (1_000_000, "MS"),
    (1_000, "US"),
    (1, "NS"),
];

/// S5T-LIT-01: `Display` gives `S5T#` and the duration without underscores ([`expected_components`]);
/// parsing it gives the same duration, and the automatic encoding of it.
pub fn prop_s5_literal_round_trip(t: S5Time) {
    let text = t.to_string();
    check_eq!(
        text,
        format!(
            "S5T#{}",
            expected_components(u64::from(t.as_millis()), false, "")
        ),
        "S5T-LIT-01: Display of {t:?}: S5T#, components from H down, no underscores"
    );
    let back: S5Time = text
        .parse()
        .unwrap_or_else(|e| panic!("S5T-LIT-01: {text} does not parse: {e}"));
    check_eq!(back.as_millis(), t.as_millis(), "S5T-LIT-01: {text}");
    check_eq!(
        Ok(back),
        S5Time::from_millis(u64::from(t.as_millis())),
        "S5T-LIT-01: automatic base"
    );
}

/// TIME-LIT-01: `Display` gives `T#`, a minus for a negative value, and the components from
/// days down separated by `_` ([`expected_components`]); parsing it gives the same TIME, for
/// every value of the range.
pub fn prop_time_literal_round_trip(ms: i32) {
    let t = Time::from_millis(ms);
    let text = t.to_string();
    let sign = if ms < 0 { "-" } else { "" };
    check_eq!(
        text,
        format!(
            "T#{sign}{}",
            expected_components(u64::from(ms.unsigned_abs()), true, "_")
        ),
        "TIME-LIT-01: Display of {ms} ms: T#, sign, components from D down joined by _"
    );
    check_eq!(text.parse::<Time>(), Ok(t), "TIME-LIT-01: {text}");
    check_eq!(
        ms.to_string().parse::<Time>(),
        Ok(t),
        "TIME-LIT-01: plain milliseconds"
    );
}

/// S5T-AUTO-BASE-01 as a round trip over words: the automatic encoding of a value's duration
/// (decode(encode(ms(w)))) has the same duration, a base no coarser, and is the value itself
/// exactly when the value's base is the automatic one. `to_automatic`/`is_automatic` agree.
pub fn prop_auto_encoding(t: S5Time) {
    let a = S5Time::from_millis(u64::from(t.as_millis()))
        .unwrap_or_else(|e| panic!("S5T-RANGE-01: {t:?} has no encoding: {e}"));
    check_eq!(
        a.as_millis(),
        t.as_millis(),
        "S5T-AUTO-BASE-01: same duration"
    );
    check!(
        a.base() <= t.base(),
        "S5T-AUTO-BASE-01: never a coarser base"
    );
    check_eq!(
        a == t,
        a.base() == t.base(),
        "S5T-AUTO-BASE-01: the value itself iff on the automatic base"
    );
    check_eq!(t.to_automatic(), a, "S5T-AUTO-BASE-01: to_automatic");
    check_eq!(t.is_automatic(), a == t, "S5T-AUTO-BASE-01: is_automatic");
    check_eq!(
        S5Time::from_word(a.to_word()),
        Ok(a),
        "S5T-WORD-01: the automatic word decodes to itself"
    );
}

/// S5T-BCD-01: the BCD helpers are inverse on 0..=999; the BCD field of a value is its word
/// without the base bits.
pub fn prop_bcd3(v: u16) {
    if v <= 999 {
        check_eq!(bcd3_decode(bcd3_encode(v)), Ok(v), "S5T-BCD-01: {v}");
        check!(bcd3_encode(v) <= 0x999, "S5T-BCD-01: three digits");
        let t = S5Time::new(v, TimeBase::S10).expect("units <= 999");
        check_eq!(t.bcd(), t.to_word() & 0x0FFF, "S5T-BCD-01: bcd field");
    } else {
        check!(
            S5Time::new(v, TimeBase::Ms10).is_err(),
            "S5T-WORD-01: {v} units"
        );
    }
}

/// TIME-ARITH-01: checked and saturating add/sub/neg agree with exact 64-bit arithmetic; the
/// checked forms fail exactly when the exact result leaves the TIME range.
pub fn prop_time_arith(a: i32, b: i32) {
    let (ta, tb) = (Time::from_millis(a), Time::from_millis(b));
    let exact = |v: i64| Time::from_millis_i64(v);
    let clamp =
        |v: i64| Time::from_millis(v.clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32);
    let (sum, diff) = (i64::from(a) + i64::from(b), i64::from(a) - i64::from(b));
    check_eq!(ta.checked_add(tb), exact(sum), "TIME-ARITH-01: {a} + {b}");
    check_eq!(ta.checked_sub(tb), exact(diff), "TIME-ARITH-01: {a} - {b}");
    check_eq!(
        ta.saturating_add(tb),
        clamp(sum),
        "TIME-ARITH-01: {a} +| {b}"
    );
    check_eq!(
        ta.saturating_sub(tb),
        clamp(diff),
        "TIME-ARITH-01: {a} -| {b}"
    );
    check_eq!(
        ta.checked_neg(),
        exact(-i64::from(a)),
        "TIME-ARITH-01: -{a}"
    );
}

/// S5T-LIT-02: parsing any text never panics; an accepted S5TIME holds the invariant (units
/// <= 999, at most 9 990 000 ms) and a rejected one says where (an offset inside the text).
pub fn prop_s5_parse_total(text: &str) {
    match text.parse::<S5Time>() {
        Ok(t) => {
            check!(t.units() <= 999, "S5T-WORD-01: {text}");
            check!(t.as_millis() <= S5Time::MAX_MILLIS, "S5T-RANGE-01: {text}");
        }
        Err(e) => check!(e.position <= text.len(), "S5T-LIT-02: {text}: {e:?}"),
    }
    if let Err(e) = text.parse::<Time>() {
        check!(e.position <= text.len(), "TIME-LIT-01: {text}: {e:?}");
    }
    if let Err(e) = text.parse::<LTime>() {
        check!(e.position <= text.len(), "LTIME-LIT-01: {text}: {e:?}");
    }
}

/// S5T-LIT-01 from the components: the literal `S5T#{h}H_{m}M_{s}S_{ms}MS` (each component
/// present or not) is the automatic encoding of its exact total, rounded down; above 9 990 s it
/// is `OutOfRange`. `h`, `m`, `s`, `ms` are kept in range after the first present one.
pub fn prop_s5_literal_components(parts: [Option<u32>; 4], underscores: bool, lower: bool) {
    const UNITS: [(&str, u64); 4] = [("H", 3_600_000), ("M", 60_000), ("S", 1_000), ("MS", 1)];
    let mut text = String::from(if lower { "s5t#" } else { "S5T#" });
    let mut total = 0u64;
    let mut first = true;
    // The byte offset of the last component's unit, and the unit's index.
    let mut last = None;
    for (i, (part, (unit, ms))) in parts.iter().zip(UNITS).enumerate() {
        let Some(v) = *part else { continue };
        if !first && underscores {
            text.push('_');
        }
        first = false;
        total += u64::from(v) * ms;
        text.push_str(&v.to_string());
        last = Some((text.len(), i));
        text.push_str(&if lower {
            unit.to_ascii_lowercase()
        } else {
            unit.to_string()
        });
    }
    let parsed = text.parse::<S5Time>();
    // S5T-LIT-01: a sign is rejected with its own error, which points at the sign (S5T-LIT-02).
    let signed = format!("{}-{}", &text[..4], &text[4..]);
    check_eq!(
        signed.parse::<S5Time>().map_err(|e| (e.kind, e.position)),
        Err((LiteralErrorKind::Negative, 4)),
        "S5T-LIT-01: {signed}: an S5TIME is never negative, the error is at the sign"
    );
    if let Some((unit_at, i)) = last {
        prop_s5_literal_faults(&text, unit_at, i, underscores);
    }
    if first {
        check_eq!(
            parsed.map_err(|e| e.kind),
            Err(LiteralErrorKind::NoComponents),
            "{text}"
        );
    } else if total > u64::from(S5Time::MAX_MILLIS) {
        check_eq!(
            parsed.map_err(|e| (e.kind, e.position)),
            Err((LiteralErrorKind::OutOfRange, 4)),
            "S5T-RANGE-01: {text} is above 9 990 s; S5T-LIT-02: the error is at the value's start"
        );
    } else {
        check_eq!(
            parsed,
            S5Time::from_millis(total).map_err(|_| unreachable!()),
            "S5T-LIT-01: {text}"
        );
        let t = parsed.expect("checked above");
        check!(
            u64::from(t.as_millis()) <= total,
            "S5T-AUTO-BASE-01: rounded down: {text}"
        );
    }
}

/// S5T-LIT-02: an error points at the faulty token. `text` is a well-formed literal whose last
/// component's unit starts at byte `unit_at` (the unit's index `i` in H, M, S, MS); each fault is made at a place computed here, so the expected offset is
/// known independently of the parser: a fraction after that number (at the `.`), a component
/// `1H` appended (a unit out of order, at its letter), `1000MS` appended after a larger unit (a
/// later component out of its range, at its number) and `1X` appended (an unknown unit, at it).
pub fn prop_s5_literal_faults(text: &str, unit_at: usize, i: usize, sep: bool) {
    use plc_timers::time::Unit;
    let fault = |t: String, kind: LiteralErrorKind, at: usize, what: &str| {
        check_eq!(
            t.parse::<S5Time>().map_err(|e| (e.kind, e.position)),
            Err((kind, at)),
            "S5T-LIT-02: {t}: {what} at byte {at}"
        );
    };
    fault(
        format!("{}.5{}", &text[..unit_at], &text[unit_at..]),
        LiteralErrorKind::Fraction,
        unit_at,
        "a fraction, the error",
    );
    let joint = if sep { "_" } else { "" };
    let next = text.len() + joint.len();
    fault(
        format!("{text}{joint}1H"),
        LiteralErrorKind::UnitOrder(Unit::Hour),
        next + 1,
        "a unit out of order, the error at its letter",
    );
    fault(
        format!("{text}{joint}1X"),
        LiteralErrorKind::UnknownUnit,
        next + 1,
        "an unknown unit, the error at it",
    );
    if i < 3 {
        fault(
            format!("{text}{joint}1000MS"),
            LiteralErrorKind::ComponentRange(Unit::Milli, 1_000),
            next,
            "a later component above its range, the error at its number",
        );
    }
}

/// Exhaustive: all 65 536 raw words.
#[test]
fn exhaustive_all_words() {
    crate::cover::check_ids(&["S5T-WORD-01", "S5T-BCD-01", "S5T-RANGE-01"], || {
        let valid = (0..=u16::MAX)
            .filter(|&w| S5Time::from_word(w).is_ok())
            .count();
        (0..=u16::MAX).for_each(prop_word_decode);
        check_eq!(
            valid,
            4 * 4_000,
            "4 000 valid value fields x the 4 ignored values of bits 15-14"
        );
    });
}

/// Exhaustive: every duration from 0 to 10 000 000 ms (past the 9 990 000 maximum): the
/// automatic base and rounding.
#[test]
fn exhaustive_from_millis() {
    crate::cover::check_ids(&["S5T-AUTO-BASE-01"], || {
        (0..=10_000_000u64).for_each(prop_from_millis);
        prop_from_millis(u64::MAX);
    });
}

/// Exhaustive: the literal round-trip of all 4 000 valid words (word -> literal -> S5TIME has the
/// same duration; when the word's base is the automatic one, it is the same word).
#[test]
fn exhaustive_s5_literal_round_trip() {
    let mut same_word = 0;
    for word in 0..=0x3FFFu16 {
        let Ok(t) = S5Time::from_word(word) else {
            continue;
        };
        prop_s5_literal_round_trip(t);
        if S5Time::from_millis(u64::from(t.as_millis())) == Ok(t) {
            same_word += 1;
            check_eq!(
                t.to_string().parse::<S5Time>().map(S5Time::to_word),
                Ok(word)
            );
        }
    }
    check!(
        same_word >= 1_000,
        "{same_word} words are their own automatic encoding"
    );
}

/// TIME round-trips at the range ends, at every unit boundary, and over the first 2 million ms
/// on both sides of 0.
#[test]
fn exhaustive_time_round_trip_near_zero_and_ends() {
    crate::cover::check_ids(&["TIME-LIT-01"], || {
        (-2_000_000..=2_000_000).for_each(prop_time_literal_round_trip);
        for ms in [
            i32::MIN,
            i32::MIN + 1,
            i32::MAX - 1,
            i32::MAX,
            86_400_000,
            -86_400_000,
            3_600_000,
            59_999,
            60_000,
        ] {
            prop_time_literal_round_trip(ms);
        }
    });
}

/// Exhaustive: the automatic-encoding round trip of all 4 000 valid words (bits 15-14 zero; they
/// are ignored, so the other 12 000 decodable words give the same values). A value is automatic
/// iff its base is 10 ms or it has at least 100 units (fewer would fit ten times as many units
/// of the next finer base): 1 000 + 3 x 900 = 3 700 words, counted independently here.
#[test]
fn exhaustive_auto_encoding_all_valid_words() {
    let (mut valid, mut automatic) = (0, 0);
    for word in 0..=0x3FFFu16 {
        let Ok(t) = S5Time::from_word(word) else {
            continue;
        };
        valid += 1;
        prop_auto_encoding(t);
        if t.is_automatic() {
            automatic += 1;
        }
        check_eq!(
            t.is_automatic(),
            t.base() == TimeBase::Ms10 || t.units() >= 100,
            "W#16#{word:04X}"
        );
    }
    check_eq!((valid, automatic), (4_000, 3_700));
}

/// Exhaustive: the BCD helpers on every u16 (0..=999 round-trip, above rejected by `new`).
#[test]
fn exhaustive_bcd3() {
    (0..=u16::MAX).for_each(prop_bcd3);
}

/// TIME arithmetic at the ends: every pair from a set of values around 0 and both range ends
/// (where the checked forms switch between Some and None).
#[test]
fn time_arith_edges() {
    crate::cover::check_ids(&["TIME-ARITH-01"], || {
        let edges = [
            i32::MIN,
            i32::MIN + 1,
            i32::MIN + 2,
            -2,
            -1,
            0,
            1,
            2,
            i32::MAX - 2,
            i32::MAX - 1,
            i32::MAX,
            i32::MIN / 2,
            i32::MAX / 2,
            i32::MAX / 2 + 1,
        ];
        for a in edges {
            for b in edges {
                prop_time_arith(a, b);
            }
        }
    });
}

/// S5T-LIT-01 on a grid of component values: each component absent, zero, typical or at its
/// range end, the first present one also far beyond its range (`S5T#90H`, `S5T#9991S`) and
/// across the 9 990 s maximum; with and without underscores, upper and lower case.
#[test]
fn exhaustive_s5_literal_components_small() {
    crate::cover::check_ids(&["S5T-LIT-01", "S5T-LIT-02"], || {
        let firsts = [
            None,
            Some(0),
            Some(1),
            Some(2),
            Some(3),
            Some(90),
            Some(166),
            Some(167),
            Some(9_990),
            Some(9_991),
        ];
        let mids = [None, Some(0), Some(7), Some(46), Some(59)];
        let mss = [None, Some(0), Some(5), Some(10), Some(990), Some(999)];
        for underscores in [false, true] {
            for lower in [false, true] {
                for h in firsts {
                    for m in mids {
                        for s in mids {
                            for ms in mss {
                                // Keep later components in range; the first present may be large.
                                let parts = [h, m, s, ms];
                                let first = parts.iter().position(Option::is_some);
                                let ok = parts.iter().enumerate().all(|(i, p)| match (p, first) {
                                    (Some(v), Some(f)) if i > f => *v < [24, 60, 60, 1_000][i],
                                    _ => true,
                                });
                                if ok {
                                    prop_s5_literal_components(parts, underscores, lower);
                                }
                            }
                        }
                    }
                }
            }
        }
        // LAD manual §9.1, Table 9-2's maximum, spelled as in the manual.
        prop_s5_literal_components([Some(2), Some(46), Some(30), None], true, false);
    });
}

#[cfg(not(kani))]
proptest! {
    #![proptest_config(ProptestConfig::with_cases(50_000))]

    /// TIME-ARITH-01 over the whole 32-bit range.
    #[test]
    fn proptest_time_arith(a in any::<i32>(), b in any::<i32>()) {
        prop_time_arith(a, b);
    }

    /// S5T-LIT-02: arbitrary texts over the literal alphabet never panic the parsers.
    #[test]
    fn proptest_s5_parse_total(text in "[sStT5#wW16_0-9hHmMdD.,+ -]{0,16}") {
        prop_s5_parse_total(&text);
    }

    /// S5T-LIT-01 over the whole component ranges (first component up to 10 000 units; later
    /// ones reduced into their range, since out-of-range later components are errors by rule).
    #[test]
    fn proptest_s5_literal_components(
        h in proptest::option::of(0u32..4), m in proptest::option::of(0u32..200),
        s in proptest::option::of(0u32..12_000), ms in proptest::option::of(0u32..1_000),
        underscores: bool, lower: bool,
    ) {
        let mut parts = [h, m, s, ms];
        if let Some(f) = parts.iter().position(Option::is_some) {
            for (i, p) in parts.iter_mut().enumerate().skip(f + 1) {
                *p = p.map(|v| v % [24, 60, 60, 1_000][i]);
            }
        }
        prop_s5_literal_components(parts, underscores, lower);
    }

    /// TIME-LIT-01 over the whole 32-bit range.
    #[test]
    fn proptest_time_round_trip(ms in any::<i32>()) {
        prop_time_literal_round_trip(ms);
    }
}

/// TIME-RANGE-01: TIME is a signed 32-bit count of milliseconds: the literals of both ends
/// parse to `i32::MIN` and `i32::MAX` ms, one past either end is `OutOfRange`, and a value
/// `ms` exists (`from_millis_i64`) exactly when it is within the 32-bit range.
pub fn prop_time_range(ms: i64) {
    let inside = (-(1i64 << 31)..=(1i64 << 31) - 1).contains(&ms);
    check_eq!(
        Time::from_millis_i64(ms).map(|t| i64::from(t.as_millis())),
        inside.then_some(ms),
        "TIME-RANGE-01: {ms} ms is a TIME exactly when it fits 32 bits"
    );
    let text = format!("T#{ms}MS");
    match text.parse::<Time>() {
        Ok(t) => check!(
            inside && i64::from(t.as_millis()) == ms,
            "TIME-RANGE-01: {text} parses to itself"
        ),
        Err(e) => check!(
            !inside && e.kind == LiteralErrorKind::OutOfRange,
            "TIME-RANGE-01: {text}: {e:?}"
        ),
    }
}

/// TIME-RANGE-01 at the ends, spelled as the manual does.
#[test]
fn time_range_ends() {
    crate::cover::check_ids(&["TIME-RANGE-01"], || {
        check_eq!(
            "T#-24D_20H_31M_23S_648MS"
                .parse::<Time>()
                .map(Time::as_millis),
            Ok(i32::MIN),
            "TIME-RANGE-01: the lower end"
        );
        check_eq!(
            "T#24D_20H_31M_23S_647MS"
                .parse::<Time>()
                .map(Time::as_millis),
            Ok(i32::MAX),
            "TIME-RANGE-01: the upper end"
        );
        for past in ["T#-24D_20H_31M_23S_649MS", "T#24D_20H_31M_23S_648MS"] {
            check_eq!(
                past.parse::<Time>().map_err(|e| e.kind),
                Err(LiteralErrorKind::OutOfRange),
                "TIME-RANGE-01: {past} is one past an end"
            );
        }
        for ms in [
            i64::from(i32::MIN) - 1,
            i64::from(i32::MIN),
            -1,
            0,
            i64::from(i32::MAX),
            i64::from(i32::MAX) + 1,
        ] {
            prop_time_range(ms);
        }
    });
}

/// The bolero harnesses of the time formats: random under `cargo test`, every value under
/// Kani. Symbolic: the 16-bit word. No loops but the BCD digit loop (3 digits) and the base
/// loop (4 bases) of `from_millis`: `#[kani::unwind(5)]` (4 iterations and the exit).
#[test]
#[cfg_attr(kani, kani::proof, kani::unwind(5))]
fn kani_word_decode() {
    crate::cover::harness(
        concat!(module_path!(), "::", stringify!(kani_word_decode)),
        || {
            bolero::check!()
                .with_type::<u16>()
                .with_iterations(20_000)
                .for_each(|&w| {
                    prop_word_decode(w);
                    prop_bcd3(w);
                });
        },
    );
}

/// S5T-AUTO-BASE-01 and S5T-RANGE-01 for every duration (`from_millis` divides by the four
/// constant bases only). Symbolic: the duration (`u32` ms) and an S5TIME (any valid one).
/// `#[kani::unwind(5)]`: `from_millis`'s loop over the 4 bases and its exit.
#[test]
#[cfg_attr(kani, kani::proof, kani::unwind(5))]
fn kani_from_millis() {
    crate::cover::harness(
        concat!(module_path!(), "::", stringify!(kani_from_millis)),
        || {
            bolero::check!()
                .with_type::<(u32, S5Time)>()
                .with_iterations(20_000)
                .for_each(|&(ms, t)| {
                    prop_from_millis(u64::from(ms));
                    prop_auto_encoding(t);
                });
        },
    );
}

/// TIME-ARITH-01 and TIME-RANGE-01 for every pair. Symbolic: two `i32` durations. No loop.
#[test]
#[cfg_attr(kani, kani::proof)]
fn kani_time_arith() {
    crate::cover::harness(
        concat!(module_path!(), "::", stringify!(kani_time_arith)),
        || {
            bolero::check!()
                .with_type::<(i32, i32)>()
                .with_iterations(20_000)
                .for_each(|&(a, b)| prop_time_arith(a, b));
        },
    );
}

/// The literal alphabet: every byte the parsers treat specially, plus one of each other class.
const LITERAL_BYTES: &[u8] = b"sStT5#wWcC16_09hHmMdD.,+- eAxI\xC3lLuUnN";

/// S5T-LIT-02 (and the counter preset parser's totality, SC-BCD-01): no panic on any text of
/// up to 16 bytes, an accepted S5TIME within range, an error position inside the text. The
/// bytes are drawn from the literal alphabet (and, under Kani, are any bytes that form UTF-8).
pub fn prop_parse_bytes(bytes: &[u8]) {
    if let Ok(text) = core::str::from_utf8(bytes) {
        prop_s5_parse_total(text);
        if let Ok(pv) = plc_timers::counter::s5::CounterPreset::parse(text) {
            check!(pv.value() <= 999, "SC-BCD-01: {text}: a preset above 999");
        }
    }
}

/// The parsers over literals of 12 bytes, every byte any of [`LITERAL_BYTES`] under `cargo
/// test` and any byte under Kani. Symbolic: 12 bytes and the length (0..=12).
/// `#[kani::unwind(14)]`: the parsers' per-byte loops (at most 12 iterations each, nested loops
/// advancing the same index, and the exit: 13) and `from_utf8`'s loop over 12 bytes; 14 leaves
/// one for the prefix comparison's loop over the longest prefix, `S5TIME#` (7 bytes).
#[test]
#[cfg_attr(kani, kani::proof, kani::unwind(14))]
fn kani_parse_12_bytes() {
    crate::cover::harness(
        concat!(module_path!(), "::", stringify!(kani_parse_12_bytes)),
        || {
            bolero::check!()
                .with_type::<([u8; 12], u8)>()
                .with_iterations(50_000)
                .for_each(|(bytes, len)| {
                    let len = usize::from(*len) % 13;
                    #[cfg(not(kani))]
                    let bytes = bytes.map(|b| LITERAL_BYTES[usize::from(b) % LITERAL_BYTES.len()]);
                    prop_parse_bytes(&bytes[..len]);
                });
        },
    );
}

/// S5T-LIT-01, S5T-LIT-02 by grammar: every literal `S5T#` + up to 8 tokens from a small
/// alphabet that reaches every branch of the component lexer (digits, each unit in both cases,
/// `_`, a fraction point, a sign, an unknown letter): literals of 4 to 12 bytes, and each
/// accepted one is checked against the value of its components, computed here.
#[test]
fn exhaustive_s5_literal_grammar_12_bytes() {
    const TOKENS: [&str; 10] = ["1", "9", "0", "H", "m", "S", "MS", "_", ".", "X"];
    let mut n = 0u64;
    let mut accepted = 0u64;
    let mut stack = vec![String::from("S5T#")];
    while let Some(text) = stack.pop() {
        n += 1;
        prop_s5_parse_total(&text);
        if let Ok(t) = text.parse::<S5Time>() {
            accepted += 1;
            let total = components_total(&text[4..]).expect("accepted literals are well-formed");
            check_eq!(
                Ok(t),
                S5Time::from_millis(total),
                "S5T-LIT-01: {text} is the automatic encoding of its components"
            );
        }
        if text.len() < 12 {
            for tok in TOKENS {
                if text.len() + tok.len() <= 12 {
                    stack.push(format!("{text}{tok}"));
                }
            }
        }
    }
    check!(
        n > 1_000_000 && accepted > 1_000,
        "{n} literals, {accepted} accepted"
    );
}

/// The total of `1H9M` … written as components, if it is a well-formed component list (digits
/// then a unit, units in decreasing order, `_` between components).
fn components_total(s: &str) -> Option<u64> {
    let units = [("H", 3_600_000u64), ("M", 60_000), ("S", 1_000), ("MS", 1)];
    let mut rest = s;
    let mut total = 0u64;
    let mut last = None;
    let mut first = true;
    while !rest.is_empty() {
        if !first {
            rest = rest.strip_prefix('_').unwrap_or(rest);
        }
        let digits = rest.bytes().take_while(u8::is_ascii_digit).count();
        let value: u64 = rest[..digits].parse().ok()?;
        rest = &rest[digits..];
        let (i, (u, ms)) = units.iter().enumerate().rev().find(|(_, (u, _))| {
            rest.len() >= u.len()
                && rest[..u.len()].eq_ignore_ascii_case(u)
                && !rest[u.len()..].starts_with(|c: char| c.is_ascii_alphabetic())
        })?;
        if last.is_some_and(|l| i <= l) {
            return None;
        }
        if !first && value >= [24, 60, 60, 1_000][i] {
            return None;
        }
        last = Some(i);
        first = false;
        total += value * ms;
        rest = &rest[u.len()..];
    }
    (!first).then_some(total)
}

/// LTIME-LIT-01: `Display` gives `LT#`, a minus for a negative value, and the components from
/// days down to nanoseconds separated by `_` (spelled here from the rule's units, `0NS` for
/// zero); parsing it, and the plain number of nanoseconds, give the same LTIME.
pub fn prop_ltime_literal_round_trip(ns: i64) {
    let t = LTime::from_nanos(ns);
    let text = t.to_string();
    let sign = if ns < 0 { "-" } else { "" };
    check_eq!(
        text,
        format!("LT#{sign}{}", spelled(ns.unsigned_abs(), &LTIME_UNITS, "_")),
        "LTIME-LIT-01: Display of {ns} ns: LT#, sign, components from D down to NS joined by _"
    );
    check_eq!(text.parse::<LTime>(), Ok(t), "LTIME-LIT-01: {text}");
    check_eq!(
        ns.to_string().parse::<LTime>(),
        Ok(t),
        "LTIME-LIT-01: plain nanoseconds"
    );
}

/// LTIME-LIT-01 from the components: `LT#` (or `ltime#`) with each of D, H, M, S, MS, US, NS
/// present or not, the first present one any `u32` and the later ones below their unit's limit
/// (24, 60, 60, 1 000, 1 000, 1 000), `_` between them or not, is its exact total computed here
/// in 128 bits: accepted when the total fits LTIME, `OutOfRange` when it does not but fits 64
/// unsigned bits, `Overflow` beyond.
pub fn prop_ltime_literal_components(parts: [Option<u32>; 7], underscores: bool, lower: bool) {
    const LIMITS: [u32; 7] = [u32::MAX, 24, 60, 60, 1_000, 1_000, 1_000];
    let mut text = String::from(if lower { "ltime#" } else { "LT#" });
    let mut total: i128 = 0;
    let mut first = true;
    for (i, part) in parts.iter().enumerate() {
        let Some(v) = *part else { continue };
        let v = if first { v } else { v % LIMITS[i] };
        if !first && underscores {
            text.push('_');
        }
        let unit = LTIME_UNITS[i].1;
        text.push_str(&format!("{v}"));
        text.push_str(&if lower {
            unit.to_lowercase()
        } else {
            unit.to_owned()
        });
        total += i128::from(v) * i128::from(LTIME_UNITS[i].0);
        first = false;
    }
    let parsed = text.parse::<LTime>();
    if first {
        check_eq!(
            parsed.map_err(|e| e.kind),
            Err(LiteralErrorKind::NoComponents),
            "LTIME-LIT-01: {text} has no value"
        );
    } else if total <= i128::from(i64::MAX) {
        check_eq!(
            parsed.map(LTime::as_nanos).map(i128::from),
            Ok(total),
            "LTIME-LIT-01: {text} is the sum of its components"
        );
    } else {
        let kind = if total <= i128::from(u64::MAX) {
            LiteralErrorKind::OutOfRange
        } else {
            LiteralErrorKind::Overflow
        };
        check_eq!(
            parsed.map_err(|e| e.kind),
            Err(kind),
            "LTIME-RANGE-01: {text} totals {total} ns"
        );
    }
}

/// LTIME-RANGE-01: LTIME is a signed 64-bit count of nanoseconds: a value exists
/// (`from_nanos_i128`) exactly when it fits 64 bits, and `LT#{ns}NS` parses to it exactly then,
/// else it is `OutOfRange` (below 2^64 in magnitude) or `Overflow`.
pub fn prop_ltime_range(ns: i128) {
    let inside = (i128::from(i64::MIN)..=i128::from(i64::MAX)).contains(&ns);
    check_eq!(
        LTime::from_nanos_i128(ns).map(|t| i128::from(t.as_nanos())),
        inside.then_some(ns),
        "LTIME-RANGE-01: {ns} ns is an LTIME exactly when it fits 64 bits"
    );
    let text = if ns < 0 {
        format!("LT#-{}NS", ns.unsigned_abs())
    } else {
        format!("LT#{ns}NS")
    };
    match text.parse::<LTime>() {
        Ok(t) => check!(
            inside && i128::from(t.as_nanos()) == ns,
            "LTIME-RANGE-01: {text} parses to itself"
        ),
        Err(e) => check!(
            !inside
                && e.kind
                    == if ns.unsigned_abs() <= u128::from(u64::MAX) {
                        LiteralErrorKind::OutOfRange
                    } else {
                        LiteralErrorKind::Overflow
                    },
            "LTIME-RANGE-01: {text}: {e:?}"
        ),
    }
}

/// LTIME-RANGE-01 at the ends, spelled as the PLCopen data type description does, one past
/// each end, and the values around both ends and 2^64.
#[test]
fn ltime_range_ends() {
    crate::cover::check_ids(&["LTIME-RANGE-01"], || {
        check_eq!(
            "LT#-106751D_23H_47M_16S_854MS_775US_808NS".parse::<LTime>(),
            Ok(LTime::MIN),
            "LTIME-RANGE-01: the lower end"
        );
        check_eq!(
            "LT#106751D_23H_47M_16S_854MS_775US_807NS".parse::<LTime>(),
            Ok(LTime::MAX),
            "LTIME-RANGE-01: the upper end"
        );
        for past in [
            "LT#-106751D_23H_47M_16S_854MS_775US_809NS",
            "LT#106751D_23H_47M_16S_854MS_775US_808NS",
            "LT#106752D",
        ] {
            check_eq!(
                past.parse::<LTime>().map_err(|e| e.kind),
                Err(LiteralErrorKind::OutOfRange),
                "LTIME-RANGE-01: {past} is past an end"
            );
        }
        let ends = [i128::from(i64::MIN), i128::from(i64::MAX), 1 << 64];
        for end in ends {
            for d in -3..=3 {
                prop_ltime_range(end + d);
                prop_ltime_range(-(end + d));
            }
        }
        for ns in [0, 1, -1, 1_000_000_000] {
            prop_ltime_range(ns);
        }
    });
}

/// LTIME round-trips at the range ends, at every unit boundary (one below, at, one above, on
/// both sides of 0), and over the first 2 million ns on both sides of 0.
#[test]
fn exhaustive_ltime_round_trip_near_zero_and_ends() {
    crate::cover::check_ids(&["LTIME-LIT-01"], || {
        (-2_000_000..=2_000_000).for_each(prop_ltime_literal_round_trip);
        for ns in [i64::MIN, i64::MIN + 1, i64::MAX - 1, i64::MAX] {
            prop_ltime_literal_round_trip(ns);
        }
        for (size, _) in LTIME_UNITS {
            let size = i64::try_from(size).expect("a unit fits LTIME");
            for ns in [size - 1, size, size + 1] {
                prop_ltime_literal_round_trip(ns);
                prop_ltime_literal_round_trip(-ns);
            }
        }
    });
}

/// LTIME-LIT-01 and LTIME-RANGE-01 on random values and component lists (bolero; random under
/// `cargo test`). Not a Kani harness: the formatting machinery of `Display` is beyond a useful
/// CBMC bound; the parser's totality over any bytes is `kani_parse_12_bytes`.
#[test]
fn random_ltime_literals() {
    crate::cover::check_ids(&["LTIME-LIT-01", "LTIME-RANGE-01"], || {
        bolero::check!()
            .with_type::<(i64, [Option<u32>; 7], bool, bool, i128)>()
            .with_iterations(20_000)
            .for_each(|(ns, parts, underscores, lower, wide)| {
                prop_ltime_literal_round_trip(*ns);
                prop_ltime_literal_components(*parts, *underscores, *lower);
                // Half of the wide values near the 64-bit range, where the ends are.
                let wide = if wide & 1 == 0 { *wide >> 62 } else { *wide };
                prop_ltime_range(wide);
            });
    });
}
