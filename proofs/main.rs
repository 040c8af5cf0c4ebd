//! Properties of every block, each written once as a plain function and driven three ways:
//!
//! - by a concrete driver that `cargo test --test proofs` runs: exhaustive enumeration where the
//!   domain is finite and small enough (the small-scope argument is in each driver's doc);
//! - by a `bolero` harness, `#[test]` and, under `cfg(kani)`, also `#[kani::proof]`: one body
//!   that `cargo test` runs on random values, `cargo kani --tests` proves over symbolic ones,
//!   and `cargo bolero` can fuzz;
//! - proptest, where a generator weighted to the edge cases serves better.
//!
//! Every behavioural requirement has a property of its own whose assertion messages start with
//! its ID (`tests/spec_catalog.rs` checks this), with an oracle written from the rule's text.
//! `cover!` marks premises that must be reachable ([`cover`]). One module per family. See the
//! README's "Verification" section for what runs where.

// Under `cfg(kani)` the concrete drivers (and the generators and constants only they use) are
// compiled out; what is left is the harnesses and the properties they call.
#![cfg_attr(kani, allow(dead_code, unused_imports))]

mod cover;

mod counter;
mod decisions;
mod domain;
mod explain;
mod iec;
mod s5;
mod time;
