//! The S5TIME literal parser on arbitrary text: no panic; what parses is at most 9 990 s and
//! formats back to the same duration.
#![no_main]

use libfuzzer_sys::fuzz_target;
use plc_timers::time::S5Time;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    if let Ok(t) = text.parse::<S5Time>() {
        assert!(t.as_millis() <= S5Time::MAX_MILLIS);
        let back: S5Time = t.to_string().parse().expect("Display output parses");
        assert_eq!(back.as_millis(), t.as_millis());
    }
});
