//! Operands of the S7-300/400 memory areas (`T n`, `C n`), and the error for one that an area
//! does not have.

use core::fmt;

/// Which memory area an operand addresses.
///
/// ```
/// use plc_timers::counter::s5::CounterMemory;
/// use plc_timers::Operand;
/// let e = CounterMemory::<2>::new().load(2).unwrap_err();
/// assert_eq!((e.operand, e.operand.letter()), (Operand::Counter, "C"));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Operand {
    /// A timer, `T n`.
    Timer,
    /// A counter, `C n` (German `Z n`).
    Counter,
}

impl Operand {
    /// The operand's letter in the international mnemonics (`T`, `C`).
    pub const fn letter(self) -> &'static str {
        match self {
            Operand::Timer => "T",
            Operand::Counter => "C",
        }
    }

    const fn noun(self) -> &'static str {
        match self {
            Operand::Timer => "timer",
            Operand::Counter => "counter",
        }
    }
}

/// An operation named a timer or counter that the area does not have.
///
/// ```
/// use plc_timers::s5::TimerMemory;
/// let area = TimerMemory::<4>::new();
/// let e = area.status(7).unwrap_err();
/// assert_eq!(e.to_string(), "no timer T 7: this area has T 0 to T 3");
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NoSuchOperand {
    /// The area.
    pub operand: Operand,
    /// The number given.
    pub index: usize,
    /// How many operands the area has (numbers 0 .. count-1).
    pub count: usize,
}

impl NoSuchOperand {
    pub(crate) const fn new(operand: Operand, index: usize, count: usize) -> NoSuchOperand {
        NoSuchOperand {
            operand,
            index,
            count,
        }
    }
}

impl fmt::Display for NoSuchOperand {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (noun, letter) = (self.operand.noun(), self.operand.letter());
        if self.count == 0 {
            return write!(f, "no {noun} {letter} {}: this area is empty", self.index);
        }
        write!(
            f,
            "no {noun} {letter} {}: this area has {letter} 0 to {letter} {}",
            self.index,
            self.count - 1
        )
    }
}

#[cfg(feature = "std")]
impl std::error::Error for NoSuchOperand {}

/// The word of `operand` number `index` in an area, or the error naming the area's range.
pub(crate) fn word<W: Copy>(
    words: &[W],
    operand: Operand,
    index: usize,
) -> Result<W, NoSuchOperand> {
    words
        .get(index)
        .copied()
        .ok_or(NoSuchOperand::new(operand, index, words.len()))
}

/// [`word`], for writing.
pub(crate) fn word_mut<W>(
    words: &mut [W],
    operand: Operand,
    index: usize,
) -> Result<&mut W, NoSuchOperand> {
    let count = words.len();
    words
        .get_mut(index)
        .ok_or(NoSuchOperand::new(operand, index, count))
}
