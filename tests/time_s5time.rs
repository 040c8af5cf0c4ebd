//! The S5TIME word against the manuals' examples: per-base ranges, the automatic base, BCD and
//! binary readings, and the canonical literal (the CLI contract's `s5time` line).

use plc_timers::time::{bcd3_decode, S5Time, S5TimeError, Time, TimeBase};

fn word(w: u16) -> S5Time {
    S5Time::from_word(w).unwrap_or_else(|e| panic!("W#16#{w:04X}: {e}"))
}

/// LAD manual §9.1, Table 9-2: the smallest and largest value of each base, as words, durations
/// and canonical literals. 10 ms: 10MS..9S_990MS; 100 ms: 100MS..1M_39S_900MS; 1 s: 1S..16M_39S;
/// 10 s: 10S..2H_46M_30S.
#[test]
fn s5t_lad_table_9_2_per_base_range_ends() {
    let cases = [
        (0x0001, TimeBase::Ms10, 10, "S5T#10MS"),
        (0x0999, TimeBase::Ms10, 9_990, "S5T#9S990MS"),
        (0x1001, TimeBase::Ms100, 100, "S5T#100MS"),
        (0x1999, TimeBase::Ms100, 99_900, "S5T#1M39S900MS"),
        (0x2001, TimeBase::S1, 1_000, "S5T#1S"),
        (0x2999, TimeBase::S1, 999_000, "S5T#16M39S"),
        (0x3001, TimeBase::S10, 10_000, "S5T#10S"),
        (0x3999, TimeBase::S10, 9_990_000, "S5T#2H46M30S"),
    ];
    for (w, base, ms, literal) in cases {
        let t = word(w);
        assert_eq!((t.base(), t.as_millis()), (base, ms), "W#16#{w:04X}");
        assert_eq!(t.to_string(), literal, "W#16#{w:04X}");
        assert_eq!(
            literal.parse::<S5Time>().map(S5Time::as_millis),
            Ok(ms),
            "{literal}"
        );
    }
    // The per-base maxima are their own automatic encodings (999 units never fit a finer base).
    for w in [0x0999, 0x1999, 0x2999, 0x3999] {
        assert!(word(w).is_automatic(), "W#16#{w:04X}");
    }
}

/// LAD manual §9.1 / Table 9-2: the maximum 9 990 s is `S5T#2H_46M_30S` = `W#16#3999`, and is
/// `S5Time::MAX`; one millisecond more is an error, not a clamp.
#[test]
fn s5t_lad_max_9990s_is_w16_3999() {
    assert_eq!(S5Time::from_millis(9_990_000), Ok(S5Time::MAX));
    assert_eq!(S5Time::MAX.to_word(), 0x3999);
    assert_eq!("S5T#2H_46M_30S".parse::<S5Time>(), Ok(S5Time::MAX));
    assert_eq!(
        S5Time::from_millis(9_990_001),
        Err(S5TimeError::DurationOutOfRange { millis: 9_990_001 })
    );
}

/// LAD manual §9.1, Fig. 9-1: `W#16#2127` is 127 units of 1 s; DUAL/BI reads the units in
/// binary (127), DEZ/BCD reads the value field in BCD (0x127).
#[test]
fn s5t_lad_fig_9_1_bcd_and_binary_readings() {
    let t = word(0x2127);
    assert_eq!(t.units(), 127);
    assert_eq!(t.bcd(), 0x127);
    assert_eq!(bcd3_decode(t.bcd()), Ok(127));
    assert_eq!(Time::from(t), Time::from_millis(127_000));
}

/// Berger §7: 1 s is `W#16#2001`, `W#16#1010` or `W#16#0100`; all three normalise to the
/// automatic `W#16#0100`, and only that one is automatic.
#[test]
fn s5t_berger_one_second_normalises_to_w16_0100() {
    for (w, automatic) in [(0x2001, false), (0x1010, false), (0x0100, true)] {
        let t = word(w);
        assert_eq!(t.is_automatic(), automatic, "W#16#{w:04X}");
        assert_eq!(t.to_automatic().to_word(), 0x0100, "W#16#{w:04X}");
        assert_eq!(t.to_string(), "S5T#1S", "W#16#{w:04X}");
    }
}

/// The CLI contract (shared trace-format, `plc-timers s5time`): 127 s is `W#16#2127 127000
/// S5T#2M7S`; and the canonical literals of 10 ms, 0 and 9 990 s.
#[test]
fn s5t_cli_contract_canonical_literals() {
    let t: S5Time = "S5T#2M7S".parse().expect("contract example");
    assert_eq!(
        format!("W#16#{:04X} {} {}", t.to_word(), t.as_millis(), t),
        "W#16#2127 127000 S5T#2M7S"
    );
    assert_eq!(word(0x0001).to_string(), "S5T#10MS");
    assert_eq!(S5Time::ZERO.to_string(), "S5T#0MS");
    assert_eq!(S5Time::MAX.to_string(), "S5T#2H46M30S");
}

/// LAD manual §9.1 ("rounded down to the nearest smaller number with this base"): `S5T#10S5MS`
/// is 10 005 ms; 10 ms would need 1 000 units, so the base is 100 ms and the value 100 units
/// (10 s), 5 ms lost. `S5T#16M39S999MS` (999 999 ms) lands on the 1 s base as 999 units.
#[test]
fn s5t_lad_9_1_rounding_down_examples() {
    let t: S5Time = "S5T#10S5MS".parse().expect("in range");
    assert_eq!(
        (t.base(), t.units(), t.to_word()),
        (TimeBase::Ms100, 100, 0x1100)
    );
    let t: S5Time = "S5T#16M39S999MS".parse().expect("in range");
    assert_eq!(
        (t.base(), t.units(), t.to_word()),
        (TimeBase::S1, 999, 0x2999)
    );
    let t: S5Time = "S5T#9S999MS".parse().expect("in range");
    assert_eq!((t.base(), t.units()), (TimeBase::Ms10, 999));
}

/// S5T-WORD-01: bits 15-14 are ignored on load and never produced; a unit count above 999 is a
/// typed error.
#[test]
fn s5t_high_bits_ignored_and_units_checked() {
    for high in [0x4000, 0x8000, 0xC000] {
        assert_eq!(word(0x2127 | high), word(0x2127));
        assert_eq!(word(0x2127 | high).to_word(), 0x2127);
    }
    assert_eq!(
        S5Time::new(1_000, TimeBase::S1),
        Err(S5TimeError::UnitsOutOfRange { units: 1_000 })
    );
    assert_eq!(
        S5Time::from_word(0x20A1),
        Err(S5TimeError::BcdDigit {
            word: 0x20A1,
            position: 1,
            digit: 0xA
        })
    );
}

/// Error messages say what was wrong and what is allowed.
#[test]
fn s5t_error_messages_name_the_rule() {
    let msg = S5Time::from_word(0x2F00).unwrap_err().to_string();
    assert!(msg.contains("hundreds") && msg.contains("0-9"), "{msg}");
    let msg = S5Time::from_millis(10_000_000).unwrap_err().to_string();
    assert!(msg.contains("9 990 000"), "{msg}");
    let msg = "S5T#3H".parse::<S5Time>().unwrap_err().to_string();
    assert!(msg.contains("S5T#2H46M30S"), "{msg}");
    let msg = "W#16#20A1".parse::<S5Time>().unwrap_err().to_string();
    assert!(
        msg.contains("BCD digit A") && msg.contains("byte 7"),
        "{msg}"
    );
    let msg = "S5T#1S_1M".parse::<S5Time>().unwrap_err().to_string();
    assert!(msg.contains("largest to smallest"), "{msg}");
}
