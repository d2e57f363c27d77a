//! The integration tests, as one test binary: each file of `tests/` is a
//! module here (its path and name unchanged), so `cargo test` links one
//! binary instead of twenty. That is most of an incremental test build,
//! and what made each `cargo mutants` mutant slow. Each module keeps its
//! own `#![cfg(feature = ...)]`.

mod bounds;
mod bounds_search;
mod careful_f32;
mod determinism;
mod far_quadric;
mod fixtures;
mod judge_edges;
mod known_wrong;
mod known_wrong_camera;
mod known_wrong_lanes;
mod known_wrong_plane;
mod known_wrong_quadric;
mod known_wrong_sphere;
mod non_finite;
mod one_judge;
mod props_camera;
mod props_plane;
mod props_quadric;
mod props_sphere;
mod props_sphere_quadric;
mod render_snapshots;
mod scene_errors;
mod semantics;
mod stage_bounds;
mod stiff_catalogue;
mod stiff_report;
mod support;
mod variants;
mod x4_identity;
