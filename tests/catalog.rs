//! The block catalog against the boxes as the manuals draw them: box names, the international
//! STL mnemonics, inputs, outputs, the preset and whether a trace needs the CPU time. The
//! command-line tool, the vectors, the diagrams and the bindings all take these from the
//! catalog, so a wrong entry would be wrong everywhere at once and no comparison of two
//! implementations would see it.
//!
//! Sources (`spec/sources.md`): LAD manual §9.3-§9.7 (the S5 timer boxes S_PULSE, S_PEXT,
//! S_ODT, S_ODTS, S_OFFDT: S, TV, R in; Q, BI, BCD out) and its counter boxes (S_CU, S_CD,
//! S_CUD: CU and/or CD, S, PV, R in; Q, CV, CV_BCD out); the STL manual (`SP SE SD SS SF`, and
//! `FR` on timers and counters); S7-1200 manual, Tables 8-18/8-19 (TP, TON, TOF: IN, PT in; Q,
//! ET out; TONR adds R) and §8.3 (CTU: CU, R, PV; CTD: CD, LD, PV; CTUD: CU, CD, R, LD, PV; Q,
//! CV out, CTUD QU, QD, CV); RT and PT coils (the `-(RT)-` coil on the IEC timers' data).

use plc_timers::catalog::{Block, Port, PresetKind};

/// One box: name, STL mnemonics, inputs (with FR where STL has it), outputs, preset port and
/// kind, whether it is a timer (needs the CPU time), its coils.
struct Box {
    name: &'static str,
    aliases: &'static [&'static str],
    inputs: &'static [&'static str],
    outputs: &'static [&'static str],
    preset: (&'static str, PresetKind),
    timer: bool,
    coils: &'static [&'static str],
}

const S5_TIMER_IN: &[&str] = &["S", "R", "FR", "TV"];
const S5_TIMER_OUT: &[&str] = &["Q", "BI", "BCD"];
const TV: (&str, PresetKind) = ("TV", PresetKind::S5Time);
const PT: (&str, PresetKind) = ("PT", PresetKind::Time);
const PV_INT: (&str, PresetKind) = ("PV", PresetKind::Integer);
const PV_S5: (&str, PresetKind) = ("PV", PresetKind::S5Count);

const fn s5_timer(name: &'static str, aliases: &'static [&'static str]) -> Box {
    Box {
        name,
        aliases,
        inputs: S5_TIMER_IN,
        outputs: S5_TIMER_OUT,
        preset: TV,
        timer: true,
        coils: &[],
    }
}

const fn iec_timer(name: &'static str, inputs: &'static [&'static str]) -> Box {
    Box {
        name,
        aliases: &[],
        inputs,
        outputs: &["Q", "ET"],
        preset: PT,
        timer: true,
        coils: &["RT"],
    }
}

const fn counter(
    name: &'static str,
    inputs: &'static [&'static str],
    outputs: &'static [&'static str],
    preset: (&'static str, PresetKind),
) -> Box {
    Box {
        name,
        aliases: &[],
        inputs,
        outputs,
        preset,
        timer: false,
        coils: &[],
    }
}

const BOXES: [Box; 15] = [
    s5_timer("S_PULSE", &["SP"]),
    s5_timer("S_PEXT", &["SE"]),
    s5_timer("S_ODT", &["SD"]),
    s5_timer("S_ODTS", &["SS"]),
    s5_timer("S_OFFDT", &["SF"]),
    iec_timer("TP", &["IN", "PT"]),
    iec_timer("TON", &["IN", "PT"]),
    iec_timer("TOF", &["IN", "PT"]),
    iec_timer("TONR", &["IN", "R", "PT"]),
    counter("CTU", &["CU", "R", "PV"], &["Q", "CV"], PV_INT),
    counter("CTD", &["CD", "LD", "PV"], &["Q", "CV"], PV_INT),
    counter(
        "CTUD",
        &["CU", "CD", "R", "LD", "PV"],
        &["QU", "QD", "CV"],
        PV_INT,
    ),
    counter(
        "S_CU",
        &["CU", "S", "R", "FR", "PV"],
        &["Q", "CV", "CV_BCD"],
        PV_S5,
    ),
    counter(
        "S_CD",
        &["CD", "S", "R", "FR", "PV"],
        &["Q", "CV", "CV_BCD"],
        PV_S5,
    ),
    counter(
        "S_CUD",
        &["CU", "CD", "S", "R", "FR", "PV"],
        &["Q", "CV", "CV_BCD"],
        PV_S5,
    ),
];

fn names(ports: &[Port]) -> Vec<&'static str> {
    ports.iter().map(|p| p.name()).collect()
}

#[test]
fn every_block_is_its_box() {
    assert_eq!(Block::ALL.len(), BOXES.len(), "one block per box");
    for (block, b) in Block::ALL.iter().zip(&BOXES) {
        assert_eq!(block.name(), b.name, "{block:?}: the box name");
        assert_eq!(
            block.to_string(),
            b.name,
            "{block:?}: displayed as its box name"
        );
        assert_eq!(block.aliases(), b.aliases, "{}: the STL mnemonics", b.name);
        assert_eq!(names(block.inputs()), b.inputs, "{}: inputs", b.name);
        assert_eq!(names(block.outputs()), b.outputs, "{}: outputs", b.name);
        assert_eq!(names(block.coils()), b.coils, "{}: coils", b.name);
        let preset = block.preset();
        assert_eq!(
            (preset.port.name(), preset.kind),
            b.preset,
            "{}: preset",
            b.name
        );
        assert_eq!(block.requires_time(), b.timer, "{}: needs t_ms", b.name);
        assert_eq!(block.family().is_timer(), b.timer, "{}: family", b.name);
        for port in Port::ALL {
            assert_eq!(
                block.has_input(port),
                b.inputs.contains(&port.name()),
                "{}: has_input({})",
                b.name,
                port.name()
            );
        }
    }
}

/// A block is found by its name or a mnemonic, ASCII case ignored; German mnemonics are not
/// accepted (German `SE` is the international `SD`, `SV` the international `SE`).
#[test]
fn lookup_by_name_and_mnemonic() {
    for (block, b) in Block::ALL.iter().zip(&BOXES) {
        for name in core::iter::once(b.name).chain(b.aliases.iter().copied()) {
            assert_eq!(Block::lookup(name), Some(*block), "{name}");
            assert_eq!(
                Block::lookup(&name.to_ascii_lowercase()),
                Some(*block),
                "{name}"
            );
        }
    }
    assert_eq!(
        Block::lookup("SE"),
        Some(Block::SPext),
        "international SE is S_PEXT"
    );
    for german in ["SI", "SV", "SA", "Z_VORW", "ZAEHLER", ""] {
        assert_eq!(Block::lookup(german), None, "{german:?}");
    }
}

/// What each pin carries: the signals are BOOL, BI, ET and CV integers, BCD and CV_BCD words
/// (LAD manual §9.1: DEZ/BCD is the time value with its base in BCD), TV, PT and PV presets.
#[test]
fn every_pin_carries_its_kind() {
    use plc_timers::catalog::ValueKind;
    for port in Port::ALL {
        let expected = match port.name() {
            "BI" | "ET" | "CV" => ValueKind::Int,
            "BCD" | "CV_BCD" => ValueKind::Word,
            "TV" | "PT" | "PV" => ValueKind::Preset,
            _ => ValueKind::Bool,
        };
        assert_eq!(port.kind(), expected, "{}", port.name());
    }
    let mut all: Vec<&str> = Port::ALL.iter().map(|p| p.name()).collect();
    all.sort_unstable();
    all.dedup();
    assert_eq!(all.len(), Port::ALL.len(), "pin names are distinct");
}

/// An operand the area lacks is named as STL writes it (`T n`, `C n`, the international
/// mnemonics) with the area's range.
#[test]
fn missing_operands_are_named_as_stl_writes_them() {
    use plc_timers::counter::s5::CounterMemory;
    use plc_timers::s5::TimerMemory;
    use plc_timers::Operand;
    assert_eq!(
        (Operand::Timer.letter(), Operand::Counter.letter()),
        ("T", "C")
    );
    let t = TimerMemory::<4>::new().status(7).expect_err("T 7 of 4");
    assert_eq!(t.to_string(), "no timer T 7: this area has T 0 to T 3");
    let c = CounterMemory::<2>::new().load(2).expect_err("C 2 of 2");
    assert_eq!((c.operand, c.index, c.count), (Operand::Counter, 2, 2));
    assert!(
        c.to_string().contains("C 2") && c.to_string().contains("C 0 to C 1"),
        "{c}"
    );
}
