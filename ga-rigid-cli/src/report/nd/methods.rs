//! The methods of the n-dimensional body that the four-dimensional scenes run, each with
//! its one name: the 3D registry's where the registry has the method, the integrator's
//! own otherwise (`lie-dopri5`, which has no 3D twin); a test checks that every
//! integrator built here calls itself by that name.

use ga_rigid::error::Error;
use ga_rigid::nd::{
    ImplicitMidpoint, Integrator, LieDop853, LieDopri5, LieRk4, PlaneSplitting, Rk4, G4,
};
use ga_rigid::registry::{Method, StepKind, DOPRI_ABSOLUTE_TOLERANCE_RATIO};

/// A method of `ga_rigid::nd` in the four-dimensional part of the report.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum NdMethod {
    /// Classical RK4, the rotor scaled back to unit norm ([`Rk4`]).
    Rk4,
    /// Runge-Kutta-Munthe-Kaas of order four ([`LieRk4`]).
    LieRk4,
    /// The implicit midpoint rule ([`ImplicitMidpoint`]).
    Midpoint,
    /// The plane-by-plane splitting ([`PlaneSplitting`]).
    Splitting,
    /// Adaptive RKMK with the Dormand-Prince 8(5,3) pair ([`LieDop853`]).
    LieDop853,
    /// Adaptive RKMK with the Dormand-Prince 5(4) pair ([`LieDopri5`]).
    LieDopri5,
    /// The symmetric body's closed form (`ga_rigid::nd::SymmetricBody4`).
    ClosedForm,
}

/// How a method is drawn: its family's marker, as in the 3D panels.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Family {
    /// Fixed step, order two.
    SecondOrder,
    /// Fixed step, order four.
    FourthOrder,
    /// Adaptive, or no steps at all.
    AdaptiveOrExact,
}

impl NdMethod {
    /// Every method, in the order of the plots' legends and the tables.
    pub const ALL: [NdMethod; 7] = [
        NdMethod::Rk4,
        NdMethod::LieRk4,
        NdMethod::Midpoint,
        NdMethod::Splitting,
        NdMethod::LieDop853,
        NdMethod::LieDopri5,
        NdMethod::ClosedForm,
    ];

    /// The 3D registry's method of the same name, where it has one.
    #[must_use]
    pub fn registry(self) -> Option<Method> {
        match self {
            NdMethod::Rk4 => Some(Method::Rk4),
            NdMethod::LieRk4 => Some(Method::LieRk4),
            NdMethod::Midpoint => Some(Method::Midpoint),
            NdMethod::Splitting => Some(Method::Splitting),
            NdMethod::LieDop853 => Some(Method::LieDop853),
            NdMethod::ClosedForm => Some(Method::ClosedForm),
            NdMethod::LieDopri5 => None,
        }
    }

    /// The method's name in the CSV, the plots and the page.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self.registry() {
            Some(method) => method.name(),
            None => "lie-dopri5",
        }
    }

    /// Whether the method takes a fixed step, a tolerance, or no steps.
    #[must_use]
    pub fn step_kind(self) -> StepKind {
        match self {
            NdMethod::Rk4 | NdMethod::LieRk4 | NdMethod::Midpoint | NdMethod::Splitting => {
                StepKind::Fixed
            }
            NdMethod::LieDop853 | NdMethod::LieDopri5 => StepKind::Adaptive,
            NdMethod::ClosedForm => StepKind::AtSamples,
        }
    }

    /// The method's family, for its marker.
    #[must_use]
    pub fn family(self) -> Family {
        match self {
            NdMethod::Midpoint | NdMethod::Splitting => Family::SecondOrder,
            NdMethod::Rk4 | NdMethod::LieRk4 => Family::FourthOrder,
            _ => Family::AdaptiveOrExact,
        }
    }
}

/// The name of a setting's kind in the CSV: `dt`, `tol` or `samples`.
#[must_use]
pub fn param_kind(kind: StepKind) -> &'static str {
    match kind {
        StepKind::Fixed => "dt",
        StepKind::Adaptive => "tol",
        StepKind::AtSamples => "samples",
    }
}

/// The fixed-step integrator of `method` with steps of `h` (an error for the adaptive
/// methods and the closed form, which [`super::measure`] runs itself to count their steps).
pub fn fixed_step(method: NdMethod, h: f64) -> Result<Box<dyn Integrator<G4>>, Error> {
    Ok(match method {
        NdMethod::Rk4 => Box::new(Rk4::new(h)?),
        NdMethod::LieRk4 => Box::new(LieRk4::new(h)?),
        NdMethod::Midpoint => Box::new(ImplicitMidpoint::new(h)?),
        NdMethod::Splitting => Box::new(PlaneSplitting::new(h)?),
        _ => {
            return Err(Error::invalid(
                method.name(),
                "not a fixed-step method of the n-dimensional body",
            ))
        }
    })
}

/// [`LieDop853`] at relative tolerance `tol`, the absolute tolerance in the registry's
/// ratio to it (as `nd::run` and the 3D methods build it).
pub fn lie_dop853(tol: f64) -> Result<LieDop853, Error> {
    LieDop853::new(tol, tol * DOPRI_ABSOLUTE_TOLERANCE_RATIO)
}

/// [`LieDopri5`] at relative tolerance `tol`, the absolute tolerance as [`lie_dop853`]'s.
pub fn lie_dopri5(tol: f64) -> Result<LieDopri5, Error> {
    LieDopri5::new(tol, tol * DOPRI_ABSOLUTE_TOLERANCE_RATIO)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One name per method: the integrator built for a method calls itself by the
    /// method's name, and the names are distinct.
    #[test]
    fn every_integrator_is_called_by_its_methods_name() {
        for method in NdMethod::ALL {
            let name = match method.step_kind() {
                StepKind::Fixed => fixed_step(method, 0.1).unwrap().name(),
                StepKind::Adaptive if method == NdMethod::LieDop853 => {
                    Integrator::<G4>::name(&lie_dop853(1e-6).unwrap())
                }
                StepKind::Adaptive => Integrator::<G4>::name(&lie_dopri5(1e-6).unwrap()),
                StepKind::AtSamples => Method::ClosedForm.name(),
            };
            assert_eq!(name, method.name(), "{method:?}");
        }
        let mut names: Vec<&str> = NdMethod::ALL.iter().map(|m| m.name()).collect();
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), NdMethod::ALL.len());
    }
}
