//! The TIME literal parser on arbitrary text: no panic; what parses formats back to itself.
#![no_main]

use libfuzzer_sys::fuzz_target;
use plc_timers::time::Time;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    if let Ok(t) = text.parse::<Time>() {
        assert_eq!(t.to_string().parse::<Time>(), Ok(t));
    }
});
