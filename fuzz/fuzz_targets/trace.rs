//! The CLI's input paths on arbitrary bytes: the first byte picks the block of the catalog, the
//! rest is the CSV trace. `run` must return outputs or a located error, never panic; reference
//! and optimized must give the same result on every trace.
#![no_main]

use libfuzzer_sys::fuzz_target;
use plc_timers::catalog::{Block, PresetKind};
use plc_timers_trace::{check, run, BlockSpec, Error, Implementation, PresetValue};

fuzz_target!(|data: &[u8]| {
    let Some((&selector, csv)) = data.split_first() else {
        return;
    };
    let block = Block::ALL[usize::from(selector) % Block::ALL.len()];
    let spec = BlockSpec::new(block);
    let text = match block.preset().kind {
        PresetKind::S5Time => Some("S5T#30MS"),
        PresetKind::Time => Some("T#20ms"),
        _ if selector & 0x80 != 0 => Some("3"),
        _ => None,
    };
    let preset = text.map(|t| PresetValue::parse(spec, t).expect("a valid preset"));
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
