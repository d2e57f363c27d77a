//! Nothing to build: this package exists for `tests/replay.rs`.
