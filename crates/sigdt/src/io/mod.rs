//! Reading point files and writing results (placeholder, being written).
