//! Literal parsing and formatting of S5TIME, TIME and LTIME, against the manuals' examples.

use plc_timers::time::{LTime, LiteralErrorKind, S5Time, Time, TimeBase, Unit};

fn s5(text: &str) -> S5Time {
    match text.parse() {
        Ok(t) => t,
        Err(e) => panic!("{text}: {e}"),
    }
}

fn s5_err(text: &str) -> LiteralErrorKind {
    match text.parse::<S5Time>() {
        Ok(t) => panic!("{text} parsed as {t:?}"),
        Err(e) => e.kind,
    }
}

fn time(text: &str) -> i32 {
    match text.parse::<Time>() {
        Ok(t) => t.as_millis(),
        Err(e) => panic!("{text}: {e}"),
    }
}

fn time_err(text: &str) -> LiteralErrorKind {
    match text.parse::<Time>() {
        Ok(t) => panic!("{text} parsed as {t:?}"),
        Err(e) => e.kind,
    }
}

/// LAD manual §9.1, Fig. 9-1: 127 s on the 1 s base is `W#16#2127`.
#[test]
fn s5t_lad_fig_9_1_127s_on_1s_base() {
    let t = s5("W#16#2127");
    assert_eq!(
        (t.units(), t.base(), t.as_millis()),
        (127, TimeBase::S1, 127_000)
    );
    assert_eq!(s5("S5T#2M7S"), t);
    assert_eq!(t.to_string(), "S5T#2M7S");
}

/// Berger §7: 1 s as `W#16#2001`, `W#16#1010` or `W#16#0100`; the automatic (preferred)
/// encoding is the finest base, `W#16#0100`.
#[test]
fn s5t_berger_three_encodings_of_one_second() {
    for w in ["W#16#2001", "W#16#1010", "W#16#0100"] {
        assert_eq!(s5(w).as_millis(), 1_000, "{w}");
    }
    assert_eq!(s5("S5T#1S").to_word(), 0x0100);
    assert_eq!(S5Time::from_millis(1_000).map(S5Time::to_word), Ok(0x0100));
}

/// LAD manual §9.1, Table 9-2: the range of each base, and the maximum `2H_46M_30S` = 9 990 s.
#[test]
fn s5t_lad_table_9_2_base_ranges() {
    let cases = [
        ("S5T#10MS", 0x0001),
        ("S5T#9S_990MS", 0x0999),
        ("S5T#100MS", 0x0010), // automatic: 100 ms is 10 units of 10 ms
        ("S5T#1M_39S_900MS", 0x1999),
        ("S5T#16M_39S", 0x2999),
        ("S5T#2H_46M_30S", 0x3999),
    ];
    for (lit, word) in cases {
        assert_eq!(s5(lit).to_word(), word, "{lit}");
    }
    assert_eq!(s5("S5T#2H_46M_30S"), S5Time::MAX);
    assert_eq!(s5_err("S5T#2H_46M_31S"), LiteralErrorKind::OutOfRange);
    assert_eq!(s5_err("S5T#2H_46M_30S_1MS"), LiteralErrorKind::OutOfRange);
}

/// LAD manual §9.1: "the value is rounded down to the nearest smaller number with this base".
#[test]
fn s5t_lad_9_1_rounds_down() {
    assert_eq!(s5("S5T#10S5MS").to_word(), 0x1100); // 10.005 s -> 100 x 100 ms
    assert_eq!(s5("S5T#9MS").to_word(), 0x0000);
    assert_eq!(s5("S5T#1H").to_word(), 0x3360);
}

#[test]
fn s5t_literal_forms() {
    assert_eq!(s5("s5time#2m7s"), s5("S5T#2M_7S"));
    assert_eq!(s5("S5T#120S").as_millis(), 120_000);
    assert_eq!(s5("W#16#C127"), s5("W#16#0127"), "bits 15-14 are ignored");
    assert_eq!(s5("w#16#1"), S5Time::new(1, TimeBase::Ms10).unwrap());
}

#[test]
fn s5t_malformed() {
    use LiteralErrorKind::*;
    let cases: &[(&str, LiteralErrorKind)] = &[
        ("", Empty),
        ("2M7S", Prefix),
        ("T#2S", Prefix),
        ("S5T#", NoComponents),
        ("S5T#2", MissingUnit),
        ("S5T#2X", UnknownUnit),
        ("S5T#2D", UnknownUnit),
        ("S5T#S", MissingDigits),
        ("S5T#2S3M", UnitOrder(plc_timers::time::Unit::Minute)),
        ("S5T#2S3S", UnitOrder(plc_timers::time::Unit::Second)),
        (
            "S5T#1M75S",
            ComponentRange(plc_timers::time::Unit::Second, 75),
        ),
        ("S5T#1.5S", Fraction),
        ("S5T#2S__3MS", UnexpectedChar('_')),
        ("S5T#_2S", UnexpectedChar('_')),
        ("S5T#2S_", UnexpectedChar('_')),
        ("S5T#2S ", UnexpectedChar(' ')),
        ("S5T#-2S", Negative),
        ("S5T#99999999999999999999999S", Overflow),
        ("W#16#", HexDigits),
        ("W#16#12345", HexDigits),
        ("W#16#12G4", HexDigits),
        ("W#16#20A1", BcdDigit(0xA)),
        ("W#16#0F00", BcdDigit(0xF)),
    ];
    for (text, kind) in cases {
        assert_eq!(s5_err(text), *kind, "{text}");
    }
}

/// S7-1200 manual, Table 8-21: T#-24d_20h_31m_23s_648ms ..= T#24d_20h_31m_23s_647ms, stored as
/// -2 147 483 648 ..= 2 147 483 647 ms; one past either end is an error.
#[test]
fn time_s7_1200_table_8_21_range_ends() {
    assert_eq!(time("T#-24d_20h_31m_23s_648ms"), i32::MIN);
    assert_eq!(time("T#24d_20h_31m_23s_647ms"), i32::MAX);
    assert_eq!(
        time_err("T#-24d_20h_31m_23s_649ms"),
        LiteralErrorKind::OutOfRange
    );
    assert_eq!(
        time_err("T#24d_20h_31m_23s_648ms"),
        LiteralErrorKind::OutOfRange
    );
    assert_eq!(time_err("2147483648"), LiteralErrorKind::OutOfRange);
    assert_eq!(time("-2147483648"), i32::MIN);
    assert_eq!(Time::MIN.to_string(), "T#-24D_20H_31M_23S_648MS");
    assert_eq!(Time::MAX.to_string(), "T#24D_20H_31M_23S_647MS");
}

/// Magnitudes far past TIME's range stay range errors, with either sign: past 2^40 ms (where
/// the parser caps the magnitude before the sign is applied), at 2^63 ms and at 2^64 - 1 ms,
/// the largest the digits' 64-bit accumulator holds (a cap that let such a value through as a
/// signed number would turn it into a small negative time).
#[test]
fn time_huge_magnitudes_are_range_errors() {
    for text in [
        "T#1099511627777MS",        // 2^40 + 1
        "T#9223372036854775808MS",  // 2^63
        "T#18446744073709551615MS", // 2^64 - 1
        "T#-18446744073709551615MS",
        "T#99999999999D",
        "18446744073709551615",
        "-9223372036854775809",
    ] {
        assert_eq!(time_err(text), LiteralErrorKind::OutOfRange, "{text}");
    }
}

/// An unexpected character is named whole, whatever its UTF-8 length (1 to 4 bytes), in both
/// parsers' paths (after a component, in place of a value, in plain milliseconds).
#[test]
fn unexpected_characters_are_named_whole() {
    use LiteralErrorKind::UnexpectedChar;
    for (text, c) in [
        ("T#5S?", '?'),
        ("T#5Sé", 'é'),
        ("T#é", 'é'),
        ("5é", 'é'),
        ("T#5S€", '€'),
        ("T#5S😀", '😀'),
        ("12😀", '😀'),
    ] {
        assert_eq!(time_err(text), UnexpectedChar(c), "{text}");
    }
    assert_eq!(s5_err("S5T#5S€"), UnexpectedChar('€'));
}

/// S7-1200 manual: "T#200ms or 200" and "T#2s_200ms".
#[test]
fn time_s7_1200_literal_forms() {
    assert_eq!(time("T#200ms"), 200);
    assert_eq!(time("200"), 200);
    assert_eq!(time("T#2s_200ms"), 2_200);
    assert_eq!(time("TIME#2S200MS"), 2_200);
    assert_eq!(time("T#-5s"), -5_000);
    assert_eq!(time("T#90m"), 5_400_000);
    assert_eq!(Time::from_millis(2_200).to_string(), "T#2S_200MS");
    assert_eq!(Time::ZERO.to_string(), "T#0MS");
}

#[test]
fn time_malformed() {
    use LiteralErrorKind::*;
    let cases: &[(&str, LiteralErrorKind)] = &[
        ("", Empty),
        ("T#", NoComponents),
        ("T#-", NoComponents),
        ("X#5S", Prefix),
        ("5S", UnexpectedChar('S')),
        ("-", MissingDigits),
        ("T#5", MissingUnit),
        ("T#5Y", UnknownUnit),
        (
            "T#1H_75M",
            ComponentRange(plc_timers::time::Unit::Minute, 75),
        ),
        ("T#1S_1H", UnitOrder(plc_timers::time::Unit::Hour)),
        ("T#1.5S", Fraction),
        ("T#--5S", UnexpectedChar('-')),
        ("12a", UnexpectedChar('a')),
    ];
    for (text, kind) in cases {
        assert_eq!(time_err(text), *kind, "{text}");
    }
}

/// More malformed S5TIME shapes: every way a literal can be wrong names the right error kind.
#[test]
fn s5t_malformed_shapes() {
    use plc_timers::time::Unit::*;
    use LiteralErrorKind::*;
    let cases: &[(&str, LiteralErrorKind)] = &[
        (" S5T#1S", Prefix),                        // leading space
        ("S5T #1S", Prefix),                        // space in the prefix
        ("S5#1S", Prefix),                          // truncated prefix
        ("S5TIME#", NoComponents),                  // long prefix, nothing after
        ("s5t#", NoComponents),                     // lower case, nothing after
        ("S5T#2_", MissingUnit),                    // separator where the unit goes
        ("S5T#2 S", UnexpectedChar(' ')),           // space between number and unit
        ("S5T#2µs", UnknownUnit),                   // non-ASCII unit
        ("S5T#1US", UnknownUnit),                   // microseconds are not an S5TIME unit
        ("S5T#1D", UnknownUnit),                    // days neither
        ("S5T#2M7Sx", UnknownUnit),                 // trailing letters glue to the unit
        ("S5T#2M7S#", UnexpectedChar('#')),         // trailing garbage
        ("S5T#2H2H", UnitOrder(Hour)),              // unit twice
        ("S5T#2MS7S", UnitOrder(Second)),           // units out of order
        ("S5T#5S_1M", UnitOrder(Minute)),           // units out of order with separator
        ("S5T#1H_60M", ComponentRange(Minute, 60)), // later component at its limit
        ("S5T#1S_1000MS", ComponentRange(Milli, 1_000)),
        ("S5T#1,5S", Fraction),                     // decimal comma
        ("S5T#1S_-5MS", UnexpectedChar('-')),       // sign inside
        ("S5T#3H", OutOfRange),                     // above 9 990 s
        ("S5T#9991S", OutOfRange),                  // one second above
        ("S5T#9990S_1MS", OutOfRange),              // exact value checked before rounding
        ("S5TIME#-0MS", Negative),                  // negative S5TIME
        ("S5T#18446744073709551615MS", OutOfRange), // u64::MAX fits the lexer, not S5TIME
        ("S5T#18446744073709551616MS", Overflow),   // u64::MAX + 1 overflows while parsing
        ("S5T#18446744073709551615S", Overflow),    // the product overflows u64
        ("W#16#-123", HexDigits),                   // sign in a word
        ("W#16#0x12", HexDigits),                   // C-style hex
        ("W#16#2127 ", HexDigits),                  // trailing space
        ("W#16#21_27", HexDigits),                  // underscore in a word
        ("W#16#00A0", BcdDigit(0xA)),               // tens digit
        ("W#16#000B", BcdDigit(0xB)),               // ones digit
        ("w#16#3f99", BcdDigit(0xF)),               // hundreds digit, lower case
        ("W#10#2127", Prefix),                      // wrong radix
    ];
    for (text, kind) in cases {
        assert_eq!(s5_err(text), *kind, "{text}");
    }
}

/// More malformed TIME shapes, and the accepted spellings next to them.
#[test]
fn time_malformed_shapes() {
    use plc_timers::time::Unit::*;
    use LiteralErrorKind::*;
    let cases: &[(&str, LiteralErrorKind)] = &[
        ("TIME#", NoComponents),
        ("t#", NoComponents),
        ("T#1D_24H", ComponentRange(Hour, 24)),
        ("T#1D1D", UnitOrder(Day)),
        ("T#5MS_3S", UnitOrder(Second)),
        ("T#25D", OutOfRange),
        ("T#-25D", OutOfRange),
        ("T#1H-5M", UnexpectedChar('-')),
        ("T#+5S", UnexpectedChar('+')),
        ("T#99999999999999999999MS", Overflow),
        ("99999999999999999999", Overflow),
        ("- 5", UnexpectedChar(' ')),
        ("1e3", UnexpectedChar('e')),
        ("0x10", UnexpectedChar('x')),
        ("T#5MS_", UnexpectedChar('_')),
        ("T#5 S", UnexpectedChar(' ')),
        ("T#5µs", UnknownUnit),
        ("T#5US", UnknownUnit),
        ("LT#5S", Prefix),
        ("-2147483649", OutOfRange),
    ];
    for (text, kind) in cases {
        assert_eq!(time_err(text), *kind, "{text}");
    }
    assert_eq!(time("T#-0MS"), 0);
    assert_eq!(time("+5"), 5);
    assert_eq!(time("time#1d"), 86_400_000);
    assert_eq!(time("T#24D"), 2_073_600_000);
}

/// TIME-ARITH-01 at the S7-1200 manual range ends: one past either end is `None` (checked) or the
/// end itself (saturating).
#[test]
fn time_s7_1200_arithmetic_at_range_ends() {
    let one = Time::from_millis(1);
    assert_eq!(Time::MAX.checked_add(one), None);
    assert_eq!(Time::MIN.checked_sub(one), None);
    assert_eq!(Time::MAX.saturating_add(one), Time::MAX);
    assert_eq!(Time::MIN.saturating_sub(one), Time::MIN);
    assert_eq!(Time::MIN.checked_neg(), None);
    assert_eq!(Time::MAX.checked_neg(), Time::MIN.checked_add(one));
    assert_eq!(
        Time::from_millis(2_000).checked_add(Time::from_millis(200)),
        Some(Time::from_millis(2_200))
    );
}

/// S7-1200 manual Table 8-21 note 1: a negative PT is taken as 0; a non-negative one as it is, up to
/// the largest TIME.
#[test]
fn time_s7_1200_table_8_21_negative_preset_taken_as_zero() {
    assert_eq!(Time::MIN.clamp_negative(), 0);
    assert_eq!(Time::from_millis(-1).clamp_negative(), 0);
    assert_eq!(Time::ZERO.clamp_negative(), 0);
    assert_eq!(Time::from_millis(500).clamp_negative(), 500);
    assert_eq!(Time::MAX.clamp_negative(), 2_147_483_647);
}

/// Every error kind says where: the byte offset of the token that is wrong (the first byte of a
/// number for its range or overflow, the unit letter for a unit out of order, the character
/// itself for a stray one, the start of the value after the prefix for a total out of range).
/// Offsets counted by hand from the literal.
#[test]
fn error_positions_point_at_the_fault() {
    use plc_timers::time::Unit;
    use LiteralErrorKind as K;
    let s5 = [
        ("", K::Empty, 0),
        ("X#5S", K::Prefix, 0),
        ("S5T#", K::NoComponents, 4),
        ("S5T#5", K::MissingUnit, 5),
        ("S5T#5Q", K::UnknownUnit, 5),
        ("S5T#S", K::MissingDigits, 4),
        ("S5T#1M_S", K::MissingDigits, 7),
        ("S5T#1.5S", K::Fraction, 5),
        ("S5T#5 S", K::UnexpectedChar(' '), 5),
        ("S5T#1S__5MS", K::UnexpectedChar('_'), 7),
        ("S5T#1S1M", K::UnitOrder(Unit::Minute), 7),
        ("S5T#1M75S", K::ComponentRange(Unit::Second, 75), 6),
        ("S5T#1M_75S", K::ComponentRange(Unit::Second, 75), 7),
        ("S5T#99999999999999999999S", K::Overflow, 4),
        ("S5T#1S_99999999999999999999MS", K::Overflow, 7),
        // The number fits 64 bits, its product with the unit does not.
        ("S5T#99999999999999H", K::Overflow, 4),
        ("W#16#20A1", K::BcdDigit(10), 7),
        // One to four hex digits, nothing else (not five with a leading zero, not a sign).
        ("W#16#", K::HexDigits, 5),
        ("W#16#00001", K::HexDigits, 5),
        ("W#16#+123", K::HexDigits, 5),
        ("S5T#-5S", K::Negative, 4),
        ("S5T#3H", K::OutOfRange, 4),
    ];
    for (text, kind, position) in s5 {
        let e = text.parse::<S5Time>().expect_err(text);
        assert_eq!((e.kind, e.position), (kind, position), "{text:?}");
    }
    let time = [
        ("T#5X", K::UnknownUnit, 3),
        ("T#-", K::NoComponents, 3),
        ("12a", K::UnexpectedChar('a'), 2),
        ("T#99999999999999999999999MS", K::Overflow, 2),
        ("T#1S_99999999999999999999MS", K::Overflow, 5),
        ("T#999999999999999D", K::Overflow, 2),
        ("T#1H_30S_2M", K::UnitOrder(Unit::Minute), 10),
        ("T#1H70M", K::ComponentRange(Unit::Minute, 70), 4),
        ("TIME#-5.5S", K::Fraction, 7),
        ("T#25D", K::OutOfRange, 2),
        ("TIME#-25D", K::OutOfRange, 5),
        ("99999999999", K::OutOfRange, 0),
    ];
    for (text, kind, position) in time {
        let e = text.parse::<Time>().expect_err(text);
        assert_eq!((e.kind, e.position), (kind, position), "{text:?}");
    }
}

/// The message names the literal type and offers the forms of that type.
#[test]
fn error_messages_name_the_type_and_its_forms() {
    let s5 = "X#5S"
        .parse::<S5Time>()
        .expect_err("bad prefix")
        .to_string();
    let time = "X#5S".parse::<Time>().expect_err("bad prefix").to_string();
    assert_eq!(
        s5,
        "invalid S5TIME literal at byte 0: unknown prefix; write S5T#aH_bbM_ccS_dddMS, S5TIME#… or W#16#wxyz"
    );
    assert_eq!(
        time,
        "invalid TIME literal at byte 0: unknown prefix; write T#…, TIME#… (e.g. T#2S_200MS, T#-5S) or whole milliseconds"
    );
    let s5 = "S5T#5Q".parse::<S5Time>().expect_err("unit").to_string();
    let time = "T#5Q".parse::<Time>().expect_err("unit").to_string();
    assert!(s5.ends_with("units are H, M, S, MS"), "{s5}");
    assert!(time.ends_with("units are D, H, M, S, MS"), "{time}");
}

/// A negative S5TIME has its own message, which names the range, instead of "above the
/// maximum" (S5T-LIT-01); the error points at the sign.
#[test]
fn s5t_negative_has_its_own_message() {
    let e = S5Time::parse("S5T#-1S").expect_err("an S5TIME is never negative");
    assert_eq!((e.kind, e.position), (LiteralErrorKind::Negative, 4));
    let message = e.to_string();
    assert!(message.contains("cannot be negative"), "{message}");
    assert!(!message.contains("above"), "{message}");
}

/// The literal parsers are `const fn`: a constant written as a literal is checked at compile
/// time (the doc tests of `s5time!` and `time!` show that a bad literal does not compile).
#[test]
fn literals_as_constants() {
    const TV: S5Time = plc_timers::s5time!("S5T#2M7S");
    const PT: Time = plc_timers::time!("T#-5S");
    assert_eq!((TV.to_word(), PT.as_millis()), (0x2127, -5_000));
    assert_eq!(Ok(TV), S5Time::parse("W#16#2127"));
}

fn ltime(text: &str) -> i64 {
    match text.parse::<LTime>() {
        Ok(t) => t.as_nanos(),
        Err(e) => panic!("{text}: {e}"),
    }
}

/// LTIME-LIT-01, LTIME-RANGE-01: the forms and the range ends of the PLCopen description of
/// LTIME (OPC UA for IEC 61131-3, DataType LTIME), written as this crate writes them (no `+`).
#[test]
fn ltime_literal_forms() {
    assert_eq!(ltime("LT#-106751d23h47m16s854ms775us808ns"), i64::MIN);
    assert_eq!(ltime("LT#106751d23h47m16s854ms775us807ns"), i64::MAX);
    assert_eq!(ltime("LT#1ms500us"), 1_500_000);
    assert_eq!(ltime("LTIME#1MS_500US"), 1_500_000);
    assert_eq!(ltime("lt#2s_200ms"), 2_200_000_000);
    assert_eq!(ltime("LT#-5NS"), -5);
    assert_eq!(ltime("LT#90M"), 5_400_000_000_000);
    assert_eq!(ltime("LT#30D"), 30 * 86_400 * 1_000_000_000);
    assert_eq!(ltime("1500"), 1_500);
    assert_eq!(ltime("-9223372036854775808"), i64::MIN);
    assert_eq!(LTime::from_nanos(1_500_000).to_string(), "LT#1MS_500US");
    assert_eq!(LTime::ZERO.to_string(), "LT#0NS");
    assert_eq!(
        LTime::MIN.to_string(),
        "LT#-106751D_23H_47M_16S_854MS_775US_808NS"
    );
    // A TIME converts exactly: T#2S_200MS is 2.2e9 ns.
    assert_eq!(
        LTime::from(Time::from_millis(2_200)).as_nanos(),
        2_200_000_000
    );
    assert_eq!(LTime::from(Time::MIN).as_nanos(), -2_147_483_648_000_000);
    const PT: LTime = plc_timers::ltime!("LT#1MS500US");
    assert_eq!(PT.as_nanos(), 1_500_000);
}

/// Every LTIME literal error is a typed error at the faulty token, with a message that says
/// what is allowed.
#[test]
fn ltime_malformed() {
    use LiteralErrorKind::*;
    let cases: &[(&str, LiteralErrorKind, usize)] = &[
        ("", Empty, 0),
        ("LT#", NoComponents, 3),
        ("LT#5Y", UnknownUnit, 4),
        ("LT#5US_1MS", UnitOrder(Unit::Milli), 8),
        ("LT#1MS_1000US", ComponentRange(Unit::Micro, 1_000), 7),
        ("LT#1US_1000NS", ComponentRange(Unit::Nano, 1_000), 7),
        ("LT#1.5US", Fraction, 4),
        ("LT#5", MissingUnit, 4),
        ("LT#+5S", UnexpectedChar('+'), 3),
        ("T#5S", Prefix, 0),
        ("LT#106752D", OutOfRange, 3),
        ("LT#-106751D_23H_47M_16S_854MS_775US_809NS", OutOfRange, 3),
        ("9223372036854775808", OutOfRange, 0),
        ("LT#99999999999999999999NS", Overflow, 3),
    ];
    for &(text, kind, position) in cases {
        let e = text.parse::<LTime>().expect_err(text);
        assert_eq!((e.kind, e.position), (kind, position), "{text}");
    }
    // US and NS are units of LTIME, not of TIME.
    assert_eq!(time_err("T#5US"), UnknownUnit);
    assert_eq!(time_err("T#5NS"), UnknownUnit);
    let message = "LT#5Q".parse::<LTime>().expect_err("unit").to_string();
    assert_eq!(
        message,
        "invalid LTIME literal at byte 4: unknown unit; units are D, H, M, S, MS, US, NS"
    );
    let message = "LT#106752D"
        .parse::<LTime>()
        .expect_err("range")
        .to_string();
    assert!(
        message.contains("LT#-106751D_23H_47M_16S_854MS_775US_808NS ..= LT#106751D_23H_47M_16S_854MS_775US_807NS"),
        "{message}"
    );
}
