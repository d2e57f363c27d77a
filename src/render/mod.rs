//! Rendering scenes (issue 5; being built).
