//! Three-digit BCD, the form of the S5TIME value field, the DEZ/BCD timer output and the S5
//! counter's CV_BCD (LAD manual §9.1: "each group of four bits holds the binary code of one
//! decimal digit").

/// Encodes 0..=999 as three BCD digits (bits 11-0). Values above 999 give digits above 9 in
/// the hundreds; callers keep `v <= 999`.
///
/// ```
/// use plc_timers::time::bcd3_encode;
/// assert_eq!(bcd3_encode(127), 0x0127);
/// ```
pub const fn bcd3_encode(v: u16) -> u16 {
    (v / 100) << 8 | (v / 10 % 10) << 4 | (v % 10)
}

/// Decodes the three BCD digits in bits 11-0 of `field` (bits 15-12 ignored) to 0..=999, or
/// gives the first digit above 9, from the hundreds down, as `(position, digit)` with position
/// 0 = ones, 1 = tens, 2 = hundreds (S5T-BCD-01).
///
/// ```
/// use plc_timers::time::{bcd3_decode, bcd3_encode};
/// assert_eq!(bcd3_decode(0x2127), Ok(127));
/// assert_eq!(bcd3_decode(0x00A1), Err((1, 0xA)));
/// assert_eq!(bcd3_decode(bcd3_encode(999)), Ok(999));
/// ```
pub const fn bcd3_decode(field: u16) -> Result<u16, (u8, u8)> {
    let mut value = 0u16;
    let mut position = 3u8;
    while position > 0 {
        position -= 1;
        let digit = ((field >> (4 * position)) & 0xF) as u8;
        if digit > 9 {
            return Err((position, digit));
        }
        value = value * 10 + digit as u16;
    }
    Ok(value)
}

/// The BCD form of every value a 10-bit binary field can hold (0..=1023; entries above 999 are
/// 0 and never read, since every such field holds at most 999): the optimized timer and
/// counter words read their DEZ/BCD output here instead of dividing twice.
pub(crate) const BCD3_TABLE: [u16; 1024] = {
    let mut t = [0u16; 1024];
    let mut v = 0;
    while v < 1000 {
        t[v] = bcd3_encode(v as u16);
        v += 1;
    }
    t
};
