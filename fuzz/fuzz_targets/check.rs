//! `plc-timers check`'s input path on arbitrary bytes (a trace that may carry outputs): the
//! first byte picks the block; the checker returns a report or a located error, never panics.
#![no_main]

use libfuzzer_sys::fuzz_target;
use plc_timers::trace::{check, lookup, BlockOptions, BLOCK_NAMES};

fuzz_target!(|data: &[u8]| {
    let Some((&selector, csv)) = data.split_first() else { return };
    let name = BLOCK_NAMES[usize::from(selector) % BLOCK_NAMES.len()];
    if let Ok(mut block) = lookup(name, &BlockOptions::default()) {
        if let Ok(report) = check(block.as_mut(), csv, &[]) {
            assert!(!report.compared.is_empty());
        }
    }
});
