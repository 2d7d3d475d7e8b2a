//! Canal-surface blends (placeholder, filled below).
