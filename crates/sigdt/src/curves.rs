//! Curve samplers (placeholder, being written).
