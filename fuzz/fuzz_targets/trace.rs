//! The CLI's input paths on arbitrary bytes: the first byte picks the block of the catalog, the
//! rest is the CSV trace (bit 0x40 of the first byte: an IEC timer on LTIME). `run` must return outputs or a located error, never panic; reference
//! and optimized must give the same result on every trace.
#![no_main]

use libfuzzer_sys::fuzz_target;
use plc_timers::catalog::{Block, DataType, PresetKind};
use plc_timers_trace::{check, run, BlockSpec, Error, Implementation};

fuzz_target!(|data: &[u8]| {
    let Some((&selector, csv)) = data.split_first() else {
        return;
    };
    let block = Block::ALL[usize::from(selector) % Block::ALL.len()];
    let ltime = selector & 0x40 != 0 && block.data_types().contains(&DataType::LTime);
    let spec = match ltime {
        true => BlockSpec::typed(block, Some(DataType::LTime)).expect("an IEC timer takes LTIME"),
        false => BlockSpec::new(block),
    };
    let text = match block.preset().kind {
        PresetKind::S5Time => Some("S5T#30MS"),
        PresetKind::Time if ltime => Some("LT#20ms"),
        PresetKind::Time => Some("T#20ms"),
        _ if selector & 0x80 != 0 => Some("3"),
        _ => None,
    };
    let preset = text.inspect(|t| {
        spec.preset_literal(t).expect("a valid preset");
    });
    let mut results = Vec::new();
    for implementation in [Implementation::Reference, Implementation::Optimized] {
        let mut out = Vec::new();
        let r = run(spec.with(implementation), preset, csv, &mut out);
        results.push(r.map(|_| out).map_err(|e| match e {
            Error::Input(e) => e.to_string(),
            Error::Output(e) => panic!("writing to a Vec failed: {e}"),
        }));
    }
    assert_eq!(
        results[0], results[1],
        "reference and optimized differ on {block}"
    );
    let _ = check(spec, preset, None, csv);
});
