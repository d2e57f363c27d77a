//! Scene files (issue 5; being built).
