//! `simulate`'s record of a run: the JSON sidecar of `--out FILE` and the note on the step
//! control. The run itself, in the body's principal frame and back, is [`ga_rigid::run`].

use ga_rigid::limits::StepSource;
use ga_rigid::registry::{Method, Step};

/// The sidecar record of a CSV written with `--out FILE`: `FILE.json`.
#[must_use]
pub fn sidecar_path(out: &std::path::Path) -> std::path::PathBuf {
    let mut name = out.as_os_str().to_os_string();
    name.push(".json");
    std::path::PathBuf::from(name)
}

/// What produced a CSV: the scene file, the method, the step control and where it came
/// from, the run.
#[derive(Clone, Copy, Debug)]
pub struct Record<'a> {
    /// The scene file as given on the command line.
    pub scene: &'a std::path::Path,
    /// The method.
    pub method: Method,
    /// The step control used.
    pub step: Step,
    /// Where the step control came from.
    pub source: StepSource,
    /// The run length and sampling.
    pub run: ga_rigid::scene::Run,
}

impl Record<'_> {
    /// One sentence on the step control, for the note on standard error.
    #[must_use]
    pub fn describe_step(&self) -> String {
        let reason = match self.source {
            StepSource::Given => "as given",
            StepSource::Default(reason) => reason,
        };
        match self.step {
            Step::Fixed(h) => format!("--dt {} ({reason})", ga_rigid::error::num(h)),
            Step::Tolerance(tol) => format!("--tol {} ({reason})", ga_rigid::error::num(tol)),
            Step::AtSamples => "no step: the solution is evaluated at the samples".to_string(),
        }
    }

    /// The record as a JSON object, `csv` naming the file it describes.
    #[must_use]
    pub fn to_json(self, csv: &std::path::Path) -> String {
        let (dt, tol) = match self.step {
            Step::Fixed(h) => (format!("{h:?}"), "null".to_string()),
            Step::Tolerance(tol) => ("null".to_string(), format!("{tol:?}")),
            Step::AtSamples => ("null".to_string(), "null".to_string()),
        };
        let source = match self.source {
            StepSource::Given => "given",
            StepSource::Default(reason) => reason,
        };
        format!(
            "{{\n  \"csv\": {},\n  \"scene\": {},\n  \"method\": {},\n  \"dt\": {dt},\n  \
             \"tol\": {tol},\n  \"step_source\": {},\n  \"t_end\": {:?},\n  \"samples\": {},\n  \
             \"ga_rigid_version\": {}\n}}\n",
            json_string(&csv.display().to_string()),
            json_string(&self.scene.display().to_string()),
            json_string(self.method.name()),
            json_string(source),
            self.run.t_end,
            self.run.samples,
            json_string(env!("CARGO_PKG_VERSION")),
        )
    }
}

/// A JSON string literal (RFC 8259, section 7).
fn json_string(text: &str) -> String {
    let mut out = String::with_capacity(text.len() + 2);
    out.push('"');
    for c in text.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            c if (c as u32) < 0x20 => out.push_str(&format!("\\u{:04x}", c as u32)),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}
