//! Every literal parser on arbitrary text: no panic; whatever parses formats back to the same
//! value (S5TIME: the same duration).
#![no_main]

use libfuzzer_sys::fuzz_target;
use plc_timers::counter::s5::CounterPreset;
use plc_timers::time::{S5Time, Time};

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else { return };
    if let Ok(t) = text.parse::<S5Time>() {
        let back: S5Time = t.to_string().parse().expect("Display output parses");
        assert_eq!(back.as_millis(), t.as_millis());
        assert!(t.as_millis() <= S5Time::MAX_MILLIS);
    }
    if let Ok(t) = text.parse::<Time>() {
        assert_eq!(t.to_string().parse::<Time>(), Ok(t));
    }
    if let Ok(p) = text.parse::<CounterPreset>() {
        assert!(p.value() <= 999);
        assert_eq!(CounterPreset::from_bcd(p.to_bcd()), Ok(p));
    }
});
