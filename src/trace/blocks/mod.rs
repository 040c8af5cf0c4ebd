//! One adapter per block family: how a trace row becomes a call of the block.

pub(crate) mod counter;
pub(crate) mod iec;
pub(crate) mod s5;
