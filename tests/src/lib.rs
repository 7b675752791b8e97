//! Validation helpers.
