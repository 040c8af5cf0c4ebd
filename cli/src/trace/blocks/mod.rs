//! One adapter per block family: how a trace row becomes a call of the block.

use std::string::String;

use super::block::CellError;

pub(crate) mod counter;
pub(crate) mod iec;
pub(crate) mod s5;

/// The last preset text and its parsed value: most traces repeat one preset on every row, so
/// each adapter parses it once.
pub(crate) struct PresetCache<T> {
    last: Option<(String, T)>,
}

impl<T: Copy> PresetCache<T> {
    pub(crate) const fn new() -> PresetCache<T> {
        PresetCache { last: None }
    }

    /// The value of `text`, parsed by `parse` unless it is the text of the previous row.
    pub(crate) fn get(
        &mut self,
        text: &str,
        parse: impl FnOnce(&str) -> Result<T, CellError>,
    ) -> Result<T, CellError> {
        match &self.last {
            Some((cached, value)) if cached == text => Ok(*value),
            _ => {
                let value = parse(text)?;
                self.last = Some((String::from(text), value));
                Ok(value)
            }
        }
    }
}
