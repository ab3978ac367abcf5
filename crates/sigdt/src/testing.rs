//! Test checkers (placeholder).
