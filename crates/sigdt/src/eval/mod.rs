//! Evaluation against ground truth (in progress).
