//! Properties of the time formats: S5TIME decoding and encoding, literal round-trips for
//! S5TIME and TIME.

use plc_timers::time::{S5Time, Time, TimeBase};
use proptest::prelude::*;

/// S5T-WORD-01, S5T-BCD-01: a raw word decodes exactly when its three value digits are BCD
/// (bits 15-14 ignored); then the units are the decimal reading, at most 999, the duration at most
/// 9 990 s, and re-encoding gives the word without bits 15-14.
pub fn prop_word_decode(word: u16) {
    let digits = [(word >> 8) & 0xF, (word >> 4) & 0xF, word & 0xF];
    match S5Time::from_word(word) {
        Ok(t) => {
            assert!(
                digits.iter().all(|&d| d <= 9),
                "S5T-BCD-01: W#16#{word:04X} accepted"
            );
            assert_eq!(
                t.units(),
                digits[0] * 100 + digits[1] * 10 + digits[2],
                "S5T-WORD-01"
            );
            assert_eq!(
                t.base().bits(),
                ((word >> 12) & 3) as u8,
                "S5T-WORD-01: base bits"
            );
            assert!(t.as_millis() <= S5Time::MAX_MILLIS, "S5T-RANGE-01");
            assert_eq!(
                t.to_word(),
                word & 0x3FFF,
                "S5T-WORD-01: bits 15-14 ignored, never produced"
            );
        }
        Err(_) => assert!(
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
            assert!(
                u64::from(t.as_millis()) <= ms && ms - u64::from(t.as_millis()) < b,
                "S5T-AUTO-BASE-01: rounded down by less than one unit"
            );
            if let Some(finer) = TimeBase::ALL.get(usize::from(t.base().bits()).wrapping_sub(1)) {
                assert!(
                    ms / u64::from(finer.millis()) > 999,
                    "S5T-AUTO-BASE-01: a finer base would fit"
                );
            }
        }
        Err(_) => assert!(
            ms > u64::from(S5Time::MAX_MILLIS),
            "S5T-RANGE-01: {ms} ms rejected"
        ),
    }
}

/// S5T-LIT-01: `Display` then parse gives the same duration, and the automatic encoding of it.
pub fn prop_s5_literal_round_trip(t: S5Time) {
    let text = t.to_string();
    let back: S5Time = text
        .parse()
        .unwrap_or_else(|e| panic!("S5T-LIT-01: {text} does not parse: {e}"));
    assert_eq!(back.as_millis(), t.as_millis(), "S5T-LIT-01: {text}");
    assert_eq!(
        Ok(back),
        S5Time::from_millis(u64::from(t.as_millis())),
        "S5T-LIT-01: automatic base"
    );
}

/// TIME-LIT-01: `Display` then parse gives the same TIME, for every value of the range.
pub fn prop_time_literal_round_trip(ms: i32) {
    let t = Time::from_millis(ms);
    let text = t.to_string();
    assert_eq!(text.parse::<Time>(), Ok(t), "TIME-LIT-01: {text}");
    assert_eq!(
        ms.to_string().parse::<Time>(),
        Ok(t),
        "TIME-LIT-01: plain milliseconds"
    );
}

/// Exhaustive: all 65 536 raw words.
#[test]
fn exhaustive_all_words() {
    let valid = (0..=u16::MAX)
        .filter(|&w| S5Time::from_word(w).is_ok())
        .count();
    (0..=u16::MAX).for_each(prop_word_decode);
    assert_eq!(
        valid,
        4 * 4_000,
        "4 000 valid value fields x the 4 ignored values of bits 15-14"
    );
}

/// Exhaustive: every duration from 0 to 10 000 000 ms (past the 9 990 000 maximum): the
/// automatic base and rounding.
#[test]
fn exhaustive_from_millis() {
    (0..=10_000_000u64).for_each(prop_from_millis);
    prop_from_millis(u64::MAX);
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
            assert_eq!(
                t.to_string().parse::<S5Time>().map(S5Time::to_word),
                Ok(word)
            );
        }
    }
    assert!(
        same_word >= 1_000,
        "{same_word} words are their own automatic encoding"
    );
}

/// TIME round-trips at the range ends, at every unit boundary, and over the first 2 million ms
/// on both sides of 0.
#[test]
fn exhaustive_time_round_trip_near_zero_and_ends() {
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
}

#[cfg(not(kani))]
proptest! {
    #![proptest_config(ProptestConfig::with_cases(50_000))]

    /// TIME-LIT-01 over the whole 32-bit range.
    #[test]
    fn proptest_time_round_trip(ms in any::<i32>()) {
        prop_time_literal_round_trip(ms);
    }
}

#[cfg(kani)]
mod kani_harnesses {
    use super::*;

    /// S5T-WORD-01, S5T-BCD-01 for every word.
    #[kani::proof]
    fn kani_word_decode() {
        prop_word_decode(kani::any());
    }

    /// S5T-AUTO-BASE-01 for every duration that fits 32 bits (division by constants only).
    #[kani::proof]
    fn kani_from_millis() {
        let ms: u32 = kani::any();
        prop_from_millis(u64::from(ms));
    }
}
