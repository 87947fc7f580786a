//! The inertia map on bivectors, stored in its principal frame.
//!
//! The inertia of a body about its centre of mass is the linear map
//! `I(B) = integral of rho x ^ (x . B)` from bivectors to bivectors. With `B = I b`
//! (`I = e1e2e3`, `b` the axial vector) it is `I(I b) = I (J b)` where
//! `J = integral of rho (|x|^2 1 - x x^T)` is the classic inertia matrix, because
//! `x ^ (x . (I b)) = I (x x (b x x)) = I (|x|^2 b - x (x . b))`. So everything is computed
//! on matrices and stored as principal moments plus the rotor that turns the principal
//! axes into the reference frame.

// The glob also brings the generated operation traits (`sandwich`, ...) into scope.
use ga_core::f64::g3::*;

use ga_core::glam::DMat3;

use super::eigen::{
    eigen_rows, from_rows, multiply, rotor_from_rows, rows_from_rotor, to_rows, transpose, Matrix3,
};
use crate::error::{finite, finite3, num, positive, Error};

/// Relative slack in the triangle inequality: moments computed from a flat body satisfy
/// i3 = i1 + i2 exactly in real arithmetic, which rounding may break by a few ulps.
const TRIANGLE_SLACK: f64 = 1e-12;

/// A computed principal moment at most this fraction of the largest counts as zero: the
/// mass lies on a line (collinear points, a needle mesh) and the inertia is singular.
const DEGENERATE_RATIO: f64 = 1e-12;

/// The inertia of a rigid body: principal moments, principal frame, and (when known)
/// the mass and centre of mass it was computed from.
///
/// The principal rotor R turns principal axes into the reference frame: the k-th
/// principal axis is `R e_k ~R`, the k-th column of the eigenvector matrix. In the
/// principal frame `I(I e_k) = i_k I e_k`, i.e. `I(e23) = i1 e23`, `I(e13) = i2 e13`,
/// `I(e12) = i3 e12`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Inertia {
    moments: [f64; 3],
    inverse_moments: [f64; 3],
    rotor: Rotor,
    mass: Option<f64>,
    centre_of_mass: Vector,
}

impl Inertia {
    /// A body whose reference frame is its principal frame, with principal moments
    /// `[i1, i2, i3]` about e1, e2, e3 in that order (they are not sorted).
    ///
    /// Errors name the parameter `moments`: non-finite, zero or negative moments, and
    /// moments that break the triangle inequality `i_a + i_b >= i_c`.
    pub fn from_principal(moments: [f64; 3]) -> Result<Self, Error> {
        check_moments("moments", moments)?;
        Ok(Self::new_unchecked(moments, Rotor::ONE, None, Vector::ZERO))
    }

    /// Like [`Inertia::from_principal`] but without the triangle inequality: for the test
    /// bodies of the literature that no mass distribution has, such as Hairer, Lubich and
    /// Wanner's (2, 1, 2/3), the EULR problem's (0.5, 2, 3) or Principia's (3, 5, 9).
    /// Euler's equations are well posed for any positive moments.
    ///
    /// Errors name the parameter `moments`: non-finite, zero or negative moments.
    pub fn from_principal_unphysical(moments: [f64; 3]) -> Result<Self, Error> {
        for i in moments {
            positive("moments", "moments", i)?;
        }
        Ok(Self::new_unchecked(moments, Rotor::ONE, None, Vector::ZERO))
    }

    /// Like [`Inertia::from_principal`], with principal axes `R e_k ~R` in the reference
    /// frame; `rotor` is normalised (a zero rotor is an error naming `rotor`).
    pub fn from_principal_frame(moments: [f64; 3], rotor: Rotor) -> Result<Self, Error> {
        check_moments("moments", moments)?;
        let rotor = normalize_rotor("rotor", rotor.to_array())?;
        Ok(Self::new_unchecked(moments, rotor, None, Vector::ZERO))
    }

    /// The inertia with matrix `j` (about the centre of mass, in the reference frame),
    /// found by the eigen-solver: moments ascending, rotor from the eigenvectors.
    ///
    /// `mass` and `centre_of_mass` are recorded as given (the mass is checked positive).
    /// Errors name the parameter `matrix`: non-finite or asymmetric entries, a singular
    /// matrix (the mass lies on a line or a point), moments that are not positive or
    /// break the triangle inequality (a matrix that is no body's inertia).
    pub fn from_matrix(
        j: &DMat3,
        mass: Option<f64>,
        centre_of_mass: Vector,
    ) -> Result<Self, Error> {
        Self::from_rows(&to_rows(j), mass, centre_of_mass)
    }

    /// [`Inertia::from_matrix`] on a row-major array `j[row][column]`, the form the
    /// constructors from masses and meshes compute in.
    pub(crate) fn from_rows(
        j: &Matrix3,
        mass: Option<f64>,
        centre_of_mass: Vector,
    ) -> Result<Self, Error> {
        let field = "matrix";
        let mut scale: f64 = 0.0;
        for row in j {
            finite3(field, "entries", *row)?;
            for x in row {
                scale = scale.max(x.abs());
            }
        }
        for (a, b) in [(0, 1), (0, 2), (1, 2)] {
            let (x, y) = (j[a][b], j[b][a]);
            if (x - y).abs() > 1e-12 * scale {
                return Err(Error::invalid(
                    field,
                    format!(
                        "the matrix must be symmetric, but entry ({a},{b}) is {} and ({b},{a}) is {}",
                        num(x),
                        num(y)
                    ),
                ));
            }
        }
        if let Some(m) = mass {
            positive("mass", "mass", m)?;
        }
        finite3(
            "centre_of_mass",
            "coordinates",
            [centre_of_mass.e1, centre_of_mass.e2, centre_of_mass.e3],
        )?;
        let (values, vectors) = eigen_rows(j);
        let [i1, i2, i3] = values;
        if i3 <= 0.0 || i1.abs() <= DEGENERATE_RATIO * i3 {
            return Err(Error::degenerate(
                field,
                format!(
                    "the principal moments {}, {}, {} include a zero one: \
                     the mass lies on a line or at a point",
                    short(i1),
                    short(i2),
                    short(i3)
                ),
            ));
        }
        check_moments(field, values)?;
        let rotor = rotor_from_rows(&vectors);
        Ok(Self::new_unchecked(values, rotor, mass, centre_of_mass))
    }

    /// Assemble from checked parts; `rotor` must be a unit rotor.
    pub(crate) fn new_unchecked(
        moments: [f64; 3],
        rotor: Rotor,
        mass: Option<f64>,
        centre_of_mass: Vector,
    ) -> Self {
        Self {
            moments,
            inverse_moments: moments.map(|i| 1.0 / i),
            rotor,
            mass,
            centre_of_mass,
        }
    }

    /// The principal moments `[i1, i2, i3]` about the principal axes `R e_k ~R`.
    #[must_use]
    pub fn moments(&self) -> [f64; 3] {
        self.moments
    }

    /// The reciprocals `[1/i1, 1/i2, 1/i3]` of the principal moments.
    #[must_use]
    pub fn inverse_moments(&self) -> [f64; 3] {
        self.inverse_moments
    }

    /// The unit rotor that turns principal axes into the reference frame
    /// (`R e_k ~R` is the k-th principal axis), with a non-negative scalar part.
    #[must_use]
    pub fn rotor(&self) -> Rotor {
        self.rotor
    }

    /// The total mass, when the inertia was computed from a mass distribution (`None`
    /// for [`Inertia::from_principal`]).
    #[must_use]
    pub fn mass(&self) -> Option<f64> {
        self.mass
    }

    /// The centre of mass in the reference frame (the origin for principal moments and
    /// standard solids, which are centred on it).
    #[must_use]
    pub fn centre_of_mass(&self) -> Vector {
        self.centre_of_mass
    }

    /// The inertia matrix J in the reference frame, acting on axial vectors:
    /// `I(I b) = I (J b)`.
    #[must_use]
    pub fn matrix(&self) -> DMat3 {
        from_rows(&self.matrix_rows())
    }

    /// [`Inertia::matrix`] as a row-major array `j[row][column]`.
    fn matrix_rows(&self) -> Matrix3 {
        let v = rows_from_rotor(self.rotor);
        let mut vd = v;
        for row in &mut vd {
            for (k, x) in row.iter_mut().enumerate() {
                *x *= self.moments[k];
            }
        }
        multiply(&vd, &transpose(&v))
    }

    /// The inertia map `I(B)` of a bivector given in the reference frame.
    #[must_use]
    pub fn apply(&self, b: Bivector) -> Bivector {
        self.scaled(b, self.moments)
    }

    /// The inertia about another point, by the parallel-axis theorem:
    /// `J_p = J_c + m (|c|^2 1 - c c^T)`, where `c` (`offset`, in the reference frame) runs
    /// from that point to the centre of mass, then diagonalised afresh (the principal frame
    /// turns when `c` is off a principal axis). Needs the mass: an error naming `mass` for
    /// an inertia given by its moments alone, which are taken to be about the point already.
    pub fn about_point(&self, offset: Vector) -> Result<Self, Error> {
        let Some(mass) = self.mass else {
            return Err(Error::invalid(
                "mass",
                "moments alone have no mass to shift them to another point; \
                 give them about that point",
            ));
        };
        let c = finite3("offset", "offset", offset.to_array())?;
        let squared = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
        let mut j = self.matrix_rows();
        for (a, row) in j.iter_mut().enumerate() {
            for (b, x) in row.iter_mut().enumerate() {
                let diagonal = if a == b { squared } else { 0.0 };
                *x += mass * (diagonal - c[a] * c[b]);
            }
        }
        // Symmetric up to the rounding of `matrix()`'s products: make it exactly so.
        for (a, b) in [(0, 1), (0, 2), (1, 2)] {
            let mean = 0.5 * (j[a][b] + j[b][a]);
            j[a][b] = mean;
            j[b][a] = mean;
        }
        Inertia::from_rows(&j, Some(mass), self.centre_of_mass)
    }

    /// The inverse map `I^-1(B)`: the angular velocity bivector of angular momentum `B`.
    #[must_use]
    pub fn apply_inverse(&self, b: Bivector) -> Bivector {
        self.scaled(b, self.inverse_moments)
    }

    /// Rotate `b` into the principal frame (`~R b R`), scale `I e_k` by `k[k]`, and
    /// rotate back (`R b' ~R`).
    fn scaled(&self, b: Bivector, k: [f64; 3]) -> Bivector {
        // The identity rotor is the common case (principal moments, solids): skip the
        // two sandwiches so those stay exact.
        if self.rotor == Rotor::ONE {
            return scale_principal(b, k);
        }
        let principal = self.rotor.reverse().sandwich(b);
        self.rotor.sandwich(scale_principal(principal, k))
    }
}

/// Scale a principal-frame bivector: `I e1 = e23`, `I e2 = -e13`, `I e3 = e12`.
fn scale_principal(b: Bivector, k: [f64; 3]) -> Bivector {
    Bivector::new(b.e12 * k[2], b.e13 * k[1], b.e23 * k[0])
}

/// Check principal moments: finite, positive, and the triangle inequality.
fn check_moments(field: &str, moments: [f64; 3]) -> Result<(), Error> {
    for i in moments {
        positive(field, "moments", i)?;
    }
    let mut sorted = moments;
    sorted.sort_by(f64::total_cmp);
    let [a, b, c] = sorted;
    if a + b < c - TRIANGLE_SLACK * (a + b + c) {
        return Err(Error::TriangleInequality {
            field: field.to_string(),
            a,
            b,
            c,
        });
    }
    Ok(())
}

/// Normalise a rotor given as `[s, e12, e13, e23]`, rejecting non-finite and zero ones.
pub(crate) fn normalize_rotor(field: &str, r: [f64; 4]) -> Result<Rotor, Error> {
    for x in r {
        finite(field, "rotor components", x)?;
    }
    let largest = r.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    if largest == 0.0 {
        return Err(Error::ZeroRotor {
            field: field.to_string(),
        });
    }
    // Divide by the largest component first so that neither tiny nor huge components
    // underflow or overflow when squared.
    let scaled = r.map(|x| x / largest);
    let n = scaled.iter().map(|x| x * x).sum::<f64>().sqrt();
    let [s, e12, e13, e23] = scaled.map(|x| x / n);
    Ok(Rotor::new(s, e12, e13, e23))
}

/// A moment for a message: four significant digits (`1.235e-17`), enough to see which
/// one is zero, short enough that three fit in one line.
fn short(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        format!("{x}")
    } else {
        format!("{x:.3e}")
    }
}
