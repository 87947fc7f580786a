//! Reads criterion's results and writes a markdown table of per-item medians.
//!
//! Criterion keeps, for every benchmark, `<criterion>/<group>/<function>/new/` with
//! `benchmark.json` (ids and throughput) and `estimates.json` (statistics of the time
//! per iteration, in ns). One iteration of these benches is a whole batch or chain, so the
//! time per item is the median divided by the throughput's element count.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::io;
use std::path::{Path, PathBuf};

/// Column order of the implementations; others follow in alphabetical order.
pub const IMPLEMENTATIONS: &[&str] = &[
    "ga-core",
    "glam",
    "glam mat3",
    "nalgebra",
    "nalgebra matrix",
    "ultraviolet",
    "ultraviolet rotate_vecs",
    "ultraviolet x2",
    "ultraviolet x4",
    "ultraviolet x8",
    "table",
];

/// One benchmark's result.
#[derive(Clone, Debug, PartialEq)]
pub struct Record {
    /// The criterion group, e.g. `g3/rotor_mul/f32/batch`.
    pub group: String,
    /// The implementation, e.g. `glam`.
    pub function: String,
    /// The median time per item in nanoseconds.
    pub median_ns: f64,
}

/// The string value of `"key": "..."` in a JSON text (no escapes inside the value).
#[must_use]
pub fn json_string(json: &str, key: &str) -> Option<String> {
    let rest = after_key(json, key)?;
    let rest = rest.strip_prefix('"')?;
    Some(rest[..rest.find('"')?].to_string())
}

/// The number value of `"key": 1.5` in a JSON text (the first occurrence of the key).
#[must_use]
pub fn json_number(json: &str, key: &str) -> Option<f64> {
    let rest = after_key(json, key)?;
    let end = rest
        .find(|c: char| !(c.is_ascii_digit() || "+-.eE".contains(c)))
        .unwrap_or(rest.len());
    rest[..end].parse().ok()
}

fn after_key<'a>(json: &'a str, key: &str) -> Option<&'a str> {
    let quoted = format!("\"{key}\"");
    let rest = &json[json.find(&quoted)? + quoted.len()..];
    Some(rest.trim_start().strip_prefix(':')?.trim_start())
}

/// The record of one `new/` directory, or `None` when a file is missing or malformed.
#[must_use]
pub fn read_record(new_dir: &Path) -> Option<Record> {
    let benchmark = std::fs::read_to_string(new_dir.join("benchmark.json")).ok()?;
    let estimates = std::fs::read_to_string(new_dir.join("estimates.json")).ok()?;
    let median = &estimates[estimates.find("\"median\"")?..];
    let median_ns = json_number(median, "point_estimate")?;
    let elements = json_number(&benchmark, "Elements").unwrap_or(1.0);
    Some(Record {
        group: json_string(&benchmark, "group_id")?,
        function: json_string(&benchmark, "function_id")?,
        median_ns: median_ns / elements,
    })
}

/// Every record under `criterion_dir`, found by walking the tree for `new/` directories.
pub fn read_records(criterion_dir: &Path) -> io::Result<Vec<Record>> {
    let mut records = Vec::new();
    let mut stack: Vec<PathBuf> = vec![criterion_dir.to_path_buf()];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir)? {
            let path = entry?.path();
            if !path.is_dir() {
                continue;
            }
            if path.file_name().is_some_and(|name| name == "new") {
                records.extend(read_record(&path));
            } else {
                stack.push(path);
            }
        }
    }
    records.sort_by(|a, b| (&a.group, &a.function).cmp(&(&b.group, &b.function)));
    Ok(records)
}

/// The markdown table: one row per group, ns per item for each implementation, with the
/// ratio to glam in parentheses when glam is in the group, and ga-core over the table.
#[must_use]
pub fn markdown(records: &[Record]) -> String {
    let mut rows: BTreeMap<&str, BTreeMap<&str, f64>> = BTreeMap::new();
    for r in records {
        rows.entry(&r.group)
            .or_default()
            .insert(&r.function, r.median_ns);
    }
    let mut columns: Vec<&str> = IMPLEMENTATIONS
        .iter()
        .copied()
        .filter(|name| records.iter().any(|r| r.function == *name))
        .collect();
    let mut others: Vec<&str> = records
        .iter()
        .map(|r| r.function.as_str())
        .filter(|name| !IMPLEMENTATIONS.contains(name))
        .collect();
    others.sort_unstable();
    others.dedup();
    columns.extend(others);

    let mut out = String::new();
    let _ = writeln!(
        out,
        "| operation | scalar | mode | {} | ga-core / table |",
        columns.join(" | ")
    );
    let _ = writeln!(out, "|---|---|---|{}---|", "---:|".repeat(columns.len()));
    for (group, times) in &rows {
        let mut parts: Vec<&str> = group.rsplitn(3, '/').collect();
        parts.reverse();
        let (operation, scalar, mode) = match parts.as_slice() {
            [operation, scalar, mode] => (*operation, *scalar, *mode),
            _ => (*group, "", ""),
        };
        let glam = times.get("glam").copied();
        let cells: Vec<String> = columns
            .iter()
            .map(|name| match (times.get(name), glam) {
                (Some(t), Some(g)) => format!("{} ({:.2})", format_ns(*t), t / g),
                (Some(t), None) => format_ns(*t),
                (None, _) => "-".to_string(),
            })
            .collect();
        let versus_table = match (times.get("ga-core"), times.get("table")) {
            (Some(ga), Some(table)) => format!("{:.3}", ga / table),
            _ => "-".to_string(),
        };
        let _ = writeln!(
            out,
            "| {operation} | {scalar} | {mode} | {} | {versus_table} |",
            cells.join(" | ")
        );
    }
    out
}

/// Nanoseconds with three significant digits.
fn format_ns(ns: f64) -> String {
    if ns >= 100.0 {
        format!("{ns:.0}")
    } else if ns >= 10.0 {
        format!("{ns:.1}")
    } else {
        format!("{ns:.2}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const BENCHMARK: &str = r#"{"group_id":"g3/rotor_mul/f32/batch","function_id":"glam","value_str":null,"throughput":{"Elements":4096},"full_id":"g3/rotor_mul/f32/batch/glam"}"#;
    const ESTIMATES: &str = r#"{"mean":{"confidence_interval":{"confidence_level":0.95,"lower_bound":1.0,"upper_bound":3.0},"point_estimate":2.0,"standard_error":0.1},"median":{"confidence_interval":{"confidence_level":0.95,"lower_bound":8000.0,"upper_bound":8400.0},"point_estimate":8192.0,"standard_error":10.0}}"#;

    #[test]
    fn json_fields_are_read_by_key() {
        assert_eq!(
            json_string(BENCHMARK, "function_id").as_deref(),
            Some("glam")
        );
        assert_eq!(json_number(BENCHMARK, "Elements"), Some(4096.0));
        assert_eq!(json_number(ESTIMATES, "point_estimate"), Some(2.0));
        assert_eq!(json_string(BENCHMARK, "missing"), None);
    }

    #[test]
    fn records_report_the_median_per_element() {
        let dir = std::env::temp_dir().join(format!("ga-benches-summary-{}", std::process::id()));
        let new_dir = dir.join("g3_rotor_mul_f32_batch").join("glam").join("new");
        std::fs::create_dir_all(&new_dir).unwrap();
        std::fs::write(new_dir.join("benchmark.json"), BENCHMARK).unwrap();
        std::fs::write(new_dir.join("estimates.json"), ESTIMATES).unwrap();
        let records = read_records(&dir).unwrap();
        std::fs::remove_dir_all(&dir).unwrap();
        assert_eq!(
            records,
            vec![Record {
                group: "g3/rotor_mul/f32/batch".into(),
                function: "glam".into(),
                median_ns: 2.0,
            }]
        );
    }

    #[test]
    fn table_gives_ratios_to_glam_and_ga_core_over_table() {
        let record = |function: &str, median_ns| Record {
            group: "g3/rotor_mul/f32/batch".into(),
            function: function.into(),
            median_ns,
        };
        let table = markdown(&[
            record("ga-core", 1.0),
            record("glam", 2.0),
            record("table", 40.0),
        ]);
        let row = table.lines().nth(2).unwrap();
        assert_eq!(
            row,
            "| g3/rotor_mul | f32 | batch | 1.00 (0.50) | 2.00 (1.00) | 40.0 (20.00) | 0.025 |"
        );
    }
}
