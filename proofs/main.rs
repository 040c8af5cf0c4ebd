//! Properties of every block, each written once as a plain function and driven two ways:
//!
//! - by a concrete driver that `cargo test --test proofs` runs: exhaustive enumeration where the
//!   domain is finite and small enough, proptest otherwise;
//! - by a `#[kani::proof]` harness, compiled only under `cfg(kani)`, for `cargo kani --tests`.
//!
//! One module per family. See the README's "Verification" section for what each harness proves
//! and what has been run where.

mod counter;
mod iec;
mod s5;
mod time;
