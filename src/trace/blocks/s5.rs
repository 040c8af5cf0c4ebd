//! Trace adapter of this family (filled in by the family's issue).

use std::boxed::Box;
use std::string::String;

use crate::trace::block::TraceBlock;
use crate::trace::registry::BlockOptions;

/// The block called `name` (upper case, aliases included) if this family has it; `Err` carries a
/// message about a bad `--type`.
pub(crate) fn lookup(
    _name: &str,
    _options: &BlockOptions,
) -> Option<Result<Box<dyn TraceBlock>, String>> {
    None
}
