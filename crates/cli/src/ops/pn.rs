//! Ops of the `pn` topic (being written; see docs/ARCHITECTURE.md).

use super::OpSpec;

/// The ops of this topic.
pub const OPS: &[OpSpec] = &[];
