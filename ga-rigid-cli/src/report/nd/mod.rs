//! The report's four-dimensional part: the methods of `ga_rigid::nd` on three G4 scenes,
//! error against run time as in 3D; `nd_results.csv`, one diagram per scene and the
//! page's "Four dimensions".

mod measure;
mod methods;
mod page;
mod plot;
mod results;
mod run;
mod scenes;

pub use measure::{attitude_error, errors, references, run_once, NdErrors, NdReference, NdRun};
pub use methods::{param_kind, Family, NdMethod};
pub use page::nd_section;
pub use plot::{nd_colour, nd_marker, nd_svg, nd_svg_name};
pub use results::{nd_csv, ND_CSV_HEADER};
pub use run::{
    nd_error_floor, nd_job_count, nd_order, run_nd, NdCheck, NdMeasurement, NdSceneResult,
};
pub use scenes::{nd_scenes, NdTestScene, Published, PERTURBATION, REFERENCE_BODY_AT_10};
