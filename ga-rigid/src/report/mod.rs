//! The main job: every method on the reference scenes, error against run time, and the
//! stiff and extreme cases. Scenes are the test models of `REFERENCES.md`; a scene runs only
//! the methods that apply to it (no closed form for an asymmetric body, no exact flow
//! under a torque), and the report says what it left out.

mod measure;
mod scenes;
mod stability;
mod work_precision;

pub use measure::{attitude_error, Outcome};
pub use scenes::{reference_scenes, stability_scenes, TestScene};

use std::fmt::Write as _;

use crate::error::Error;

/// How much to run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Size {
    /// Three step sizes or tolerances per method, one timing run: seconds (what CI runs).
    Quick,
    /// Nine step sizes or tolerances per method, best of three timings: about a minute.
    Full,
}

/// The whole report as text.
pub fn report(size: Size) -> Result<String, Error> {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "# ga-rigid report ({})\n\nAttitude error: the angle of ~R_ref R (rad) at the end \
         time. m error: the body angular momentum's error relative to its size. Energy \
         drift: relative, kinetic plus the torque's potential. Time: wall clock for the \
         whole run, {}. Reference: the exact flow (Jacobi elliptic functions) for free \
         bodies, Dormand-Prince at 1e-13 under a torque.\n",
        match size {
            Size::Quick => "quick",
            Size::Full => "full",
        },
        match size {
            Size::Quick => "one run",
            Size::Full => "best of three runs",
        }
    );
    for scene in reference_scenes()? {
        work_precision::section(&mut out, &scene, size)?;
    }
    stability::section(&mut out, &stability_scenes()?)?;
    Ok(out)
}
