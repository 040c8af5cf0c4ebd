//! `plc-timers check`'s input path on arbitrary bytes (a trace that may carry outputs): the
//! first byte picks the block; the checker returns a report or a located error, never panics,
//! and a difference it reports names requirements of the catalog.
#![no_main]

use libfuzzer_sys::fuzz_target;
use plc_timers::catalog::Block;
use plc_timers::rule::Rule;
use plc_timers_trace::{check, BlockSpec};

fuzz_target!(|data: &[u8]| {
    let Some((&selector, csv)) = data.split_first() else {
        return;
    };
    let block = Block::ALL[usize::from(selector) % Block::ALL.len()];
    let outputs: Option<&[&str]> = if selector & 0x80 != 0 {
        Some(&["Q"])
    } else {
        None
    };
    if let Ok(report) = check(BlockSpec::new(block), None, outputs, csv) {
        assert!(!report.compared.is_empty());
        if let Some(d) = report.difference {
            // The rules are the catalog's (`Rule`), and the report quotes each with its text.
            let text = d.to_string();
            for rule in d.why.rules {
                assert_eq!(Rule::from_id(rule.id()), Some(rule));
                assert!(text.contains(rule.text()));
            }
        }
    }
});
