//! LTIMER-STRUCT-01: the S7-1500 `IEC_LTIMER` (`IecLTimer`) is 32 bytes; its bytes
//! (`to_bytes`, the layout the C ABI's `plc_timers_iec_ltimer` mirrors) hold START, PT and ET
//! at offsets 0, 8 and 16, the flag byte at 24 and zeros after it, and `from_bytes` restores
//! exactly the structures the operations can reach.

use plc_timers::iec::{IecKind, IecLTimer, IecState, IecTimerOps};
use proptest::prelude::*;

/// Any IEC state on the 64-bit clock, valid or not (ET above PT, START kept while stopped).
fn any_state() -> impl Strategy<Value = IecState<u64>> {
    let kind = prop_oneof![
        Just(None),
        Just(Some(IecKind::Tp)),
        Just(Some(IecKind::Ton)),
        Just(Some(IecKind::Tof)),
        Just(Some(IecKind::Tonr)),
    ];
    // Small values as often as wide ones, so that ET = PT and START = 0 occur.
    let word = prop_oneof![0u64..4, any::<u64>()];
    (
        kind,
        any::<bool>(),
        any::<bool>(),
        word.clone(),
        word.clone(),
        word,
        any::<bool>(),
    )
        .prop_map(|(kind, input, running, start, pt, et, q)| IecState {
            kind,
            input,
            running,
            start,
            pt,
            et,
            q,
        })
}

proptest! {
    #[test]
    fn ltimer_bytes_hold_the_members_and_restore_the_structure(
        state in any_state(),
        byte in 25usize..32,
        value in 1u8..=255,
    ) {
        prop_assert_eq!(core::mem::size_of::<IecLTimer>(), 32, "LTIMER-STRUCT-01: 32 bytes");
        let Some(t) = IecLTimer::from_state(state) else {
            prop_assert!(!state.is_valid(), "LTIMER-STRUCT-01: every valid state has a structure");
            return Ok(());
        };
        let bytes = t.to_bytes();
        prop_assert_eq!(&bytes[0..8], &state.start.to_ne_bytes(), "LTIMER-STRUCT-01: START at 0");
        prop_assert_eq!(&bytes[8..16], &state.pt.to_ne_bytes(), "LTIMER-STRUCT-01: PT at 8");
        prop_assert_eq!(&bytes[16..24], &state.et.to_ne_bytes(), "LTIMER-STRUCT-01: ET at 16");
        prop_assert_eq!(&bytes[25..], &[0u8; 7], "LTIMER-STRUCT-01: zero after the flag byte");
        prop_assert_eq!(IecLTimer::from_bytes(bytes), Some(t), "LTIMER-STRUCT-01: round trip");
        prop_assert_eq!(t.state(), state, "LTIMER-STRUCT-01: the state kept");
        let mut padded = bytes;
        padded[byte] = value;
        prop_assert!(IecLTimer::from_bytes(padded).is_none(), "LTIMER-STRUCT-01: non-zero padding refused");
    }

    /// Bytes of a state no operation reaches are refused: ET above PT, or a START kept by a
    /// stopped timer, written at their offsets over a valid structure's bytes.
    #[test]
    fn ltimer_bytes_of_an_invalid_state_are_refused(pt in 0u64..u64::MAX, start in 1u64..) {
        let mut bytes = IecLTimer::new().to_bytes();
        bytes[8..16].copy_from_slice(&pt.to_ne_bytes());
        bytes[16..24].copy_from_slice(&(pt + 1).to_ne_bytes());
        prop_assert!(IecLTimer::from_bytes(bytes).is_none(), "LTIMER-STRUCT-01: ET above PT refused");
        let mut stopped = IecLTimer::new().to_bytes();
        stopped[0..8].copy_from_slice(&start.to_ne_bytes());
        prop_assert!(IecLTimer::from_bytes(stopped).is_none(), "LTIMER-STRUCT-01: START of a stopped timer refused");
        // The flag byte: bit 7 is no flag.
        let mut flags = IecLTimer::new().to_bytes();
        flags[24] = 0x80;
        prop_assert!(IecLTimer::from_bytes(flags).is_none(), "LTIMER-STRUCT-01: an unknown flag bit refused");
    }
}
