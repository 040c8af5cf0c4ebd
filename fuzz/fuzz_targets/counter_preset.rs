//! The S5 counter preset parser (`C#…`, `W#16#…`, plain numbers) on arbitrary text: no panic;
//! what parses is 0..=999 and its BCD word decodes back to it.
#![no_main]

use libfuzzer_sys::fuzz_target;
use plc_timers::counter::s5::CounterPreset;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    if let Ok(p) = text.parse::<CounterPreset>() {
        assert!(p.value() <= 999);
        assert_eq!(CounterPreset::from_bcd(p.to_bcd()), Ok(p));
    }
});
