//! Reads criterion's results and writes markdown tables of per-item medians.
//!
//! Criterion keeps, for every benchmark, `<criterion>/<group>/<function>/new/` with
//! `benchmark.json` (ids and throughput) and `estimates.json` (statistics of the time
//! per iteration, in ns). One iteration of these benches is a whole batch or chain, so the
//! time per item is the median divided by the throughput's element count.
//!
//! The algebra groups make one wide table, a column per library. The rigid-body groups
//! (`rigid/...`, from `benches/rigid.rs`) compare methods rather than libraries, so they
//! make a second table, a row per method, followed by issue 4's two ratios.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::io;
use std::path::{Path, PathBuf};

use crate::rigid;

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

/// The markdown summary: the algebra table ([`library_table`]) and then, when there are
/// rigid-body results, their table and ratios ([`rigid_table`]).
#[must_use]
pub fn markdown(records: &[Record]) -> String {
    let (rigid, libraries): (Vec<Record>, Vec<Record>) = records
        .iter()
        .cloned()
        .partition(|r| r.group.starts_with("rigid/"));
    let mut out = String::new();
    if !libraries.is_empty() {
        out += &library_table(&libraries);
    }
    if !rigid.is_empty() {
        if !out.is_empty() {
            out.push('\n');
        }
        out += &rigid_table(&rigid);
    }
    out
}

/// `group` split into operation, scalar and mode (`g3/rotor_mul/f32/batch`).
fn split_group(group: &str) -> (&str, &str, &str) {
    let mut parts: Vec<&str> = group.rsplitn(3, '/').collect();
    parts.reverse();
    match parts.as_slice() {
        [operation, scalar, mode] => (*operation, *scalar, *mode),
        _ => (group, "", ""),
    }
}

/// The algebra table: one row per group, ns per item for each implementation, with the
/// ratio to glam in parentheses when glam is in the group, and ga-core over the table.
#[must_use]
pub fn library_table(records: &[Record]) -> String {
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
        let (operation, scalar, mode) = split_group(group);
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

/// The rigid-body table: one row per method, the median per item with its unit and the
/// items per second; then closed-form evaluation over one RK4 step (issue 4's target: at
/// most 3) and the fastest geometric-algebra method of the race over ode_solvers' Dop853.
#[must_use]
pub fn rigid_table(records: &[Record]) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "| rigid-body operation | scalar | mode | method | median per item | items per second |"
    );
    let _ = writeln!(out, "|---|---|---|---|---:|---:|");
    for r in records {
        let (operation, scalar, mode) = split_group(&r.group);
        let _ = writeln!(
            out,
            "| {operation} | {scalar} | {mode} | {} | {} | {:.3e} |",
            r.function,
            format_time(r.median_ns),
            1e9 / r.median_ns
        );
    }
    let time = |group: &str, function: &str| {
        records
            .iter()
            .find(|r| r.group == group && r.function == function)
            .map(|r| r.median_ns)
    };
    let _ = writeln!(out);
    match (
        time(rigid::TOP_GROUP, rigid::CLOSED_FORM),
        time(rigid::TOP_GROUP, rigid::RK4_STEP),
    ) {
        (Some(closed), Some(step)) => {
            let _ = writeln!(
                out,
                "Closed-form evaluation / RK4 step ({}): {} / {} = {:.2} (target: at most 3).",
                rigid::TOP_GROUP,
                format_time(closed),
                format_time(step),
                closed / step
            );
        }
        _ => {
            let _ = writeln!(out, "Closed-form evaluation / RK4 step: not measured.");
        }
    }
    let best = rigid::RACE_GA_METHODS
        .iter()
        .filter_map(|&name| Some((name, time(rigid::RACE_GROUP, name)?)))
        .min_by(|a, b| a.1.total_cmp(&b.1));
    match (best, time(rigid::RACE_GROUP, rigid::RACE_PEER)) {
        (Some((name, ga)), Some(peer)) => {
            let _ = writeln!(
                out,
                "Best GA method / {} to an attitude error of {:e} at t = {} ({}): {name} {} / {} \
                 = {:.2}.",
                rigid::RACE_PEER,
                rigid::RACE_TARGET,
                rigid::RACE_T_END,
                rigid::RACE_GROUP,
                format_time(ga),
                format_time(peer),
                ga / peer
            );
        }
        _ => {
            let _ = writeln!(out, "Best GA method / {}: not measured.", rigid::RACE_PEER);
        }
    }
    out
}

/// A time with three significant digits in ns, us or ms.
fn format_time(ns: f64) -> String {
    if ns >= 1e6 {
        format!("{} ms", format_ns(ns * 1e-6))
    } else if ns >= 1e3 {
        format!("{} us", format_ns(ns * 1e-3))
    } else {
        format!("{} ns", format_ns(ns))
    }
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

    #[test]
    fn rigid_rows_get_their_own_table_and_the_two_ratios() {
        let record = |group: &str, function: &str, median_ns| Record {
            group: group.into(),
            function: function.into(),
            median_ns,
        };
        let summary = markdown(&[
            record("g3/rotor_mul/f32/batch", "glam", 2.0),
            record(rigid::TOP_GROUP, rigid::CLOSED_FORM, 60.0),
            record(rigid::TOP_GROUP, rigid::RK4_STEP, 40.0),
            record(rigid::RACE_GROUP, "rk4", 50_000.0),
            record(rigid::RACE_GROUP, "dopri5", 30_000.0),
            record(rigid::RACE_GROUP, "exact", 1_000.0),
            record(rigid::RACE_GROUP, rigid::RACE_PEER, 20_000.0),
        ]);
        let lines: Vec<&str> = summary.lines().collect();
        assert_eq!(lines[2], "| g3/rotor_mul | f32 | batch | 2.00 (1.00) | - |");
        assert!(
            lines.contains(&"| rigid/reach_1e-10 | f64 | hlw_t10 | dopri5 | 30.0 us | 3.333e4 |")
        );
        assert!(lines
            .iter()
            .any(|l| l.starts_with("Closed-form evaluation / RK4 step") && l.contains("= 1.50")));
        // The exact flow is not a time-stepping method: dopri5 is the best of the race.
        assert!(lines
            .iter()
            .any(|l| l.starts_with("Best GA method")
                && l.contains("dopri5 30.0 us / 20.0 us = 1.50")));
    }

    #[test]
    fn missing_ratios_say_so() {
        let table = rigid_table(&[Record {
            group: rigid::STEP_GROUP.into(),
            function: "rk4".into(),
            median_ns: 1_500_000.0,
        }]);
        assert!(table.contains("| rk4 | 1.50 ms | 6.667e2 |"));
        assert!(table.contains("Closed-form evaluation / RK4 step: not measured."));
        assert!(table.contains("Best GA method / ode_solvers dop853: not measured."));
    }
}
