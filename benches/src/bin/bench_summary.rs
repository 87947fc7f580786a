//! Prints a markdown table of the per-item medians criterion recorded.
//!
//! Usage: `bench_summary [CRITERION_DIR]`; the default is `$CARGO_TARGET_DIR/criterion`,
//! else `target/criterion`.

use std::path::PathBuf;
use std::process::ExitCode;

use ga_benches::summary::{markdown, read_records};

fn main() -> ExitCode {
    let dir = std::env::args_os()
        .nth(1)
        .map(PathBuf::from)
        .unwrap_or_else(|| {
            let target = std::env::var_os("CARGO_TARGET_DIR").unwrap_or_else(|| "target".into());
            PathBuf::from(target).join("criterion")
        });
    match read_records(&dir) {
        Ok(records) if records.is_empty() => {
            eprintln!("no criterion results under {}", dir.display());
            ExitCode::FAILURE
        }
        Ok(records) => {
            print!("{}", markdown(&records));
            ExitCode::SUCCESS
        }
        Err(error) => {
            eprintln!("cannot read {}: {error}", dir.display());
            ExitCode::FAILURE
        }
    }
}
