//! Reads criterion's results and writes a markdown table of per-item medians.
