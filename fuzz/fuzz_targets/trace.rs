//! The CLI's input paths on arbitrary bytes: the first byte picks the block and the
//! implementation, the rest is the CSV trace (and, for a few blocks, a preset option). `run` and
//! `check` must return a result or a located error, never panic; reference and optimized must
//! agree on every trace both accept.
#![no_main]

use libfuzzer_sys::fuzz_target;
use plc_timers::trace::{check, lookup, run, BlockOptions, Implementation, BLOCK_NAMES};

fuzz_target!(|data: &[u8]| {
    let Some((&selector, csv)) = data.split_first() else { return };
    let name = BLOCK_NAMES[usize::from(selector) % BLOCK_NAMES.len()];
    let preset: &[(&'static str, &str)] = match selector >> 5 {
        0 => &[("tv", "S5T#30MS")],
        1 => &[("pt", "T#20ms")],
        2 => &[("pv", "3")],
        _ => &[],
    };
    let options = |implementation| BlockOptions { int_type: None, implementation };
    let mut outputs = Vec::new();
    for implementation in [Implementation::Reference, Implementation::Optimized] {
        let Ok(mut block) = lookup(name, &options(implementation)) else { return };
        let mut out = Vec::new();
        outputs.push(run(block.as_mut(), csv, preset, &mut out).map(|()| out).map_err(|e| e.to_string()));
    }
    assert_eq!(outputs[0], outputs[1], "reference and optimized differ on {name}");
    if let Ok(mut block) = lookup(name, &options(Implementation::Reference)) {
        let _ = check(block.as_mut(), csv, preset);
    }
});
