//! Inertia: the bivector map against the classic matrix formula, textbook solids, exact
//! polyhedral mass properties, OBJ reading, and the eigen-solver.

// Index loops over 3x3 matrices read like the formulas they check (J_ab, V^T V = 1).
#![allow(clippy::needless_range_loop)]

use std::path::Path;

use ga_core::f64::g3::*;
use ga_rigid::error::Error;
use ga_rigid::glam::{DMat3, DQuat, DVec3};
use ga_rigid::inertia::{matrix_from_rotor, rotor_from_matrix, symmetric_eigen, Inertia, Mesh};

/// A row-major 3x3 matrix, the form the formulas below are written in; the library takes
/// and returns glam's column-major `DMat3`, and the products go through glam, a matrix
/// library that shares no code with ga-rigid.
type Matrix3 = [[f64; 3]; 3];

fn to_glam(a: &Matrix3) -> DMat3 {
    // glam is column-major: the rows of `a` are the columns of the transpose.
    DMat3::from_cols_array_2d(a).transpose()
}

fn from_glam(m: DMat3) -> Matrix3 {
    m.transpose().to_cols_array_2d()
}

fn multiply(a: &Matrix3, b: &Matrix3) -> Matrix3 {
    from_glam(to_glam(a) * to_glam(b))
}

fn transpose(a: &Matrix3) -> Matrix3 {
    from_glam(to_glam(a).transpose())
}

fn mul_vec(a: &Matrix3, x: [f64; 3]) -> [f64; 3] {
    (to_glam(a) * DVec3::from_array(x)).to_array()
}

fn determinant(a: &Matrix3) -> f64 {
    to_glam(a).determinant()
}

use ga_test_rng::Rng;

/// The generator for these tests' seeds 1, 2, 3...: each multiplied by the golden-ratio
/// constant (and made odd), the start these tests' tolerances were set on.
fn seeded(seed: u64) -> Rng {
    Rng::new(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1)
}

/// Three components uniform in [-r, r).
fn vec3(rng: &mut Rng, r: f64) -> [f64; 3] {
    rng.uniform_array(-r, r)
}

/// A uniformly distributed unit rotor: a point of [-1, 1)^4 with norm in (0.1, 1),
/// normalised.
fn rotor(rng: &mut Rng) -> Rotor {
    loop {
        let c: [f64; 4] = rng.uniform_array(-1.0, 1.0);
        let n = c.iter().map(|x| x * x).sum::<f64>().sqrt();
        if n > 0.1 && n < 1.0 {
            return Rotor::new(c[0] / n, c[1] / n, c[2] / n, c[3] / n);
        }
    }
}

/// Bivector B = b12 e12 + b13 e13 + b23 e23 is I b with axial vector b = (b23, -b13, b12).
fn axial(b: Bivector) -> [f64; 3] {
    [b.e23, -b.e13, b.e12]
}

fn from_axial(a: [f64; 3]) -> Bivector {
    Bivector::new(a[2], -a[1], a[0])
}

fn max_abs(m: &Matrix3) -> f64 {
    m.iter().flatten().fold(0.0_f64, |a, x| a.max(x.abs()))
}

fn assert_close(a: f64, b: f64, tol: f64, what: &str) {
    assert!(
        (a - b).abs() <= tol,
        "{what}: {a} vs {b} differ by {} > {tol}",
        (a - b).abs()
    );
}

fn assert_rel(a: f64, b: f64, rel: f64, what: &str) {
    assert_close(a, b, rel * a.abs().max(b.abs()), what);
}

/// The classic formula: com, then sum m (|d|^2 1 - d d^T).
fn classic_inertia(points: &[(f64, [f64; 3])]) -> (f64, [f64; 3], Matrix3) {
    let mass: f64 = points.iter().map(|p| p.0).sum();
    let mut com = [0.0; 3];
    for (m, x) in points {
        for i in 0..3 {
            com[i] += m * x[i] / mass;
        }
    }
    let mut j = [[0.0; 3]; 3];
    for (m, x) in points {
        let d = [x[0] - com[0], x[1] - com[1], x[2] - com[2]];
        let d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        for a in 0..3 {
            for b in 0..3 {
                j[a][b] += m * (if a == b { d2 } else { 0.0 } - d[a] * d[b]);
            }
        }
    }
    (mass, com, j)
}

fn random_cloud(rng: &mut Rng) -> Vec<(f64, [f64; 3])> {
    let n = 4 + (rng.next_u64() % 40) as usize;
    let offset = vec3(rng, 10.0);
    let stretch = [
        rng.uniform(0.2, 3.0),
        rng.uniform(0.2, 3.0),
        rng.uniform(0.2, 3.0),
    ];
    (0..n)
        .map(|_| {
            let x = vec3(rng, 1.0);
            (
                rng.uniform(0.1, 2.0),
                [
                    offset[0] + stretch[0] * x[0],
                    offset[1] + stretch[1] * x[1],
                    offset[2] + stretch[2] * x[2],
                ],
            )
        })
        .collect()
}

#[test]
fn point_cloud_inertia_matches_the_classic_matrix_formula() {
    let mut rng = seeded(1);
    for _ in 0..200 {
        let points = random_cloud(&mut rng);
        let (mass, com, j) = classic_inertia(&points);
        let inertia = Inertia::from_point_masses(&points).unwrap();
        assert_rel(inertia.mass().unwrap(), mass, 1e-14, "mass");
        let c = inertia.centre_of_mass();
        for (a, b) in [c.e1, c.e2, c.e3].iter().zip(com) {
            assert_close(*a, b, 1e-12 * (1.0 + b.abs()), "centre of mass");
        }
        let scale = max_abs(&j);
        let stored = from_glam(inertia.matrix());
        for a in 0..3 {
            for b in 0..3 {
                assert_close(stored[a][b], j[a][b], 1e-12 * scale, "matrix entry");
            }
        }
        for _ in 0..5 {
            let b = from_axial(vec3(&mut rng, 1.0));
            let expected = mul_vec(&j, axial(b));
            let got = axial(inertia.apply(b));
            for k in 0..3 {
                assert_close(got[k], expected[k], 1e-12 * scale, "I(B) against J b");
            }
        }
    }
}

#[test]
fn apply_inverse_undoes_apply() {
    let mut rng = seeded(2);
    for _ in 0..100 {
        let inertia = Inertia::from_point_masses(&random_cloud(&mut rng)).unwrap();
        let b = from_axial(vec3(&mut rng, 1.0));
        let back = inertia.apply_inverse(inertia.apply(b));
        let (x, y) = (axial(back), axial(b));
        let cond = inertia.moments()[2] / inertia.moments()[0];
        for k in 0..3 {
            assert_close(x[k], y[k], 1e-13 * cond, "I^-1(I(B))");
        }
        let inv = inertia.inverse_moments();
        for k in 0..3 {
            assert_rel(inv[k] * inertia.moments()[k], 1.0, 1e-15, "inverse moments");
        }
    }
}

#[test]
fn principal_axes_are_eigenbivectors_with_ascending_moments() {
    let mut rng = seeded(3);
    for _ in 0..100 {
        let inertia = Inertia::from_point_masses(&random_cloud(&mut rng)).unwrap();
        let [i1, i2, i3] = inertia.moments();
        assert!(i1 <= i2 && i2 <= i3, "moments ascending");
        let r = inertia.rotor();
        assert!(r.s >= 0.0, "canonical sign");
        // I(R (I e_k) ~R) = i_k R (I e_k) ~R, with I e1 = e23, I e2 = -e13, I e3 = e12.
        let basis = [
            Bivector::new(0.0, 0.0, 1.0),
            Bivector::new(0.0, -1.0, 0.0),
            Bivector::new(1.0, 0.0, 0.0),
        ];
        for (k, b) in basis.iter().enumerate() {
            let axis = r.sandwich(*b);
            let image = inertia.apply(axis);
            let (x, y) = (axial(image), axial(axis));
            for c in 0..3 {
                assert_close(
                    x[c],
                    inertia.moments()[k] * y[c],
                    1e-12 * i3,
                    "eigenbivector",
                );
            }
        }
    }
}

#[test]
fn from_principal_keeps_order_and_is_exact() {
    let inertia = Inertia::from_principal([2.0, 1.5, 2.0 / 3.0]).unwrap();
    assert_eq!(inertia.moments(), [2.0, 1.5, 2.0 / 3.0]);
    assert_eq!(inertia.mass(), None);
    // I(w1 e23 - w2 e13 + w3 e12) = i1 w1 e23 - i2 w2 e13 + i3 w3 e12.
    let omega = Bivector::new(3.0, -2.0, 1.0);
    assert_eq!(inertia.apply(omega), Bivector::new(2.0, -3.0, 2.0));
}

#[test]
fn literature_test_bodies_need_the_unphysical_constructor() {
    // Hairer-Lubich-Wanner, EULR and Principia's Dzhanibekov body break the triangle
    // inequality: no mass distribution has them, but Euler's equations do not care.
    for moments in [[2.0, 1.0, 2.0 / 3.0], [0.5, 2.0, 3.0], [3.0, 5.0, 9.0]] {
        let e = Inertia::from_principal(moments).unwrap_err();
        assert!(matches!(e, Error::TriangleInequality { .. }), "{e}");
        let inertia = Inertia::from_principal_unphysical(moments).unwrap();
        assert_eq!(inertia.moments(), moments);
    }
    let e = Inertia::from_principal_unphysical([1.0, 0.0, 1.0]).unwrap_err();
    assert!(matches!(e, Error::NotPositive { .. }), "{e}");
}

#[test]
fn from_principal_frame_rotates_the_axes() {
    let mut rng = seeded(4);
    let r = rotor(&mut rng);
    let inertia = Inertia::from_principal_frame([1.0, 2.0, 2.5], r).unwrap();
    let v = from_glam(matrix_from_rotor(r));
    let d = [[1.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 2.5]];
    let j = multiply(&multiply(&v, &d), &transpose(&v));
    let b = from_axial([0.3, -0.7, 1.1]);
    let got = axial(inertia.apply(b));
    let expected = mul_vec(&j, axial(b));
    for k in 0..3 {
        assert_close(got[k], expected[k], 1e-14, "rotated principal frame");
    }
}

#[test]
fn bad_principal_moments_are_typed_errors() {
    let e = Inertia::from_principal([1.0, -1.0, 1.0]).unwrap_err();
    assert!(matches!(e, Error::NotPositive { .. }), "{e}");
    assert_eq!(e.to_string(), "moments: moments must be positive, got -1");
    let e = Inertia::from_principal([1.0, 0.0, 1.0]).unwrap_err();
    assert!(matches!(e, Error::NotPositive { .. }), "{e}");
    let e = Inertia::from_principal([1.0, f64::NAN, 1.0]).unwrap_err();
    assert!(matches!(e, Error::NotFinite { .. }), "{e}");
    let e = Inertia::from_principal([1.0, f64::INFINITY, 1.0]).unwrap_err();
    assert!(matches!(e, Error::NotFinite { .. }), "{e}");
    let e = Inertia::from_principal([1.0, 2.0, 3.5]).unwrap_err();
    assert!(matches!(e, Error::TriangleInequality { .. }), "{e}");
    // A flat body sits exactly on the boundary: allowed.
    Inertia::from_principal([1.0, 2.0, 3.0]).unwrap();
    let e =
        Inertia::from_principal_frame([1.0, 1.0, 1.0], Rotor::new(0.0, 0.0, 0.0, 0.0)).unwrap_err();
    assert!(matches!(e, Error::ZeroRotor { .. }), "{e}");
}

#[test]
fn bad_point_masses_are_typed_errors() {
    let e = Inertia::from_point_masses(&[]).unwrap_err();
    assert!(matches!(e, Error::Degenerate { .. }), "{e}");
    let e = Inertia::from_point_masses(&[(1.0, [0.0; 3]), (-1.0, [1.0, 0.0, 0.0])]).unwrap_err();
    assert_eq!(e.to_string(), "points[1]: mass must be positive, got -1");
    let e = Inertia::from_point_masses(&[(1.0, [0.0, f64::NAN, 0.0])]).unwrap_err();
    assert!(matches!(e, Error::NotFinite { .. }), "{e}");
    // One point, or points on a line: a principal moment is zero.
    let e = Inertia::from_point_masses(&[(1.0, [1.0, 2.0, 3.0])]).unwrap_err();
    assert!(matches!(e, Error::Degenerate { .. }), "{e}");
    let line: Vec<_> = (0..5)
        .map(|k| (1.0, [0.1 * k as f64, 0.3 * k as f64 + 7.0, -0.2 * k as f64]))
        .collect();
    let e = Inertia::from_point_masses(&line).unwrap_err();
    assert!(matches!(e, Error::Degenerate { .. }), "{e}");
    assert!(e.to_string().starts_with("points: "), "{e}");
}

#[test]
fn planar_point_masses_satisfy_the_perpendicular_axis_theorem() {
    // A flat body: i3 = i1 + i2 exactly in real arithmetic, the edge of the triangle
    // inequality; rounding must not turn it into an error.
    let points = [
        (1.0, [1.0, 0.0, 0.0]),
        (2.0, [0.0, 1.5, 0.0]),
        (1.5, [-0.7, -0.4, 0.0]),
        (0.5, [0.3, -1.1, 0.0]),
    ];
    let inertia = Inertia::from_point_masses(&points).unwrap();
    let [i1, i2, i3] = inertia.moments();
    assert_rel(i1 + i2, i3, 1e-14, "i1 + i2 = i3");
}

#[test]
fn solids_have_textbook_moments() {
    let (m, a, b, c) = (2.5, 1.2, 0.7, 3.1);
    let checks: Vec<(&str, Inertia, [f64; 3])> = vec![
        (
            "box",
            Inertia::solid_box(m, [a, b, c]).unwrap(),
            [
                m * (b * b + c * c) / 12.0,
                m * (a * a + c * c) / 12.0,
                m * (a * a + b * b) / 12.0,
            ],
        ),
        (
            "sphere",
            Inertia::solid_sphere(m, a).unwrap(),
            [2.0 / 5.0 * m * a * a; 3],
        ),
        (
            "hollow sphere",
            Inertia::hollow_sphere(m, a).unwrap(),
            [2.0 / 3.0 * m * a * a; 3],
        ),
        (
            "cylinder",
            Inertia::solid_cylinder(m, a, c).unwrap(),
            [
                m * (3.0 * a * a + c * c) / 12.0,
                m * (3.0 * a * a + c * c) / 12.0,
                m * a * a / 2.0,
            ],
        ),
        (
            "cone",
            Inertia::solid_cone(m, a, c).unwrap(),
            [
                3.0 / 80.0 * m * (4.0 * a * a + c * c),
                3.0 / 80.0 * m * (4.0 * a * a + c * c),
                3.0 / 10.0 * m * a * a,
            ],
        ),
        (
            "ellipsoid",
            Inertia::solid_ellipsoid(m, [a, b, c]).unwrap(),
            [
                m * (b * b + c * c) / 5.0,
                m * (a * a + c * c) / 5.0,
                m * (a * a + b * b) / 5.0,
            ],
        ),
    ];
    for (name, inertia, expected) in checks {
        for k in 0..3 {
            assert_rel(inertia.moments()[k], expected[k], 1e-15, name);
        }
        assert_eq!(inertia.mass(), Some(m), "{name}");
        assert_eq!(inertia.rotor(), Rotor::ONE, "{name}");
        assert_eq!(
            inertia.centre_of_mass(),
            Vector::new(0.0, 0.0, 0.0),
            "{name}"
        );
    }
}

#[test]
fn bad_solid_dimensions_name_the_parameter() {
    let e = Inertia::solid_box(1.0, [1.0, 0.0, 1.0]).unwrap_err();
    assert_eq!(e.to_string(), "size: edge lengths must be positive, got 0");
    let e = Inertia::solid_sphere(-2.0, 1.0).unwrap_err();
    assert_eq!(e.to_string(), "mass: mass must be positive, got -2");
    let e = Inertia::solid_cone(1.0, 1.0, f64::NAN).unwrap_err();
    assert_eq!(e.to_string(), "height: height must be finite, got NaN");
    let e = Inertia::solid_sphere(1.0, 1e200).unwrap_err();
    assert!(e.to_string().starts_with("radius: "), "{e}");
}

/// A box mesh with corners at +-size/2, outward-wound.
fn box_mesh(size: [f64; 3]) -> Mesh {
    let h = size.map(|s| s / 2.0);
    let mut vertices = Vec::new();
    for k in 0..8 {
        vertices.push([
            if k & 1 == 0 { -h[0] } else { h[0] },
            if k & 2 == 0 { -h[1] } else { h[1] },
            if k & 4 == 0 { -h[2] } else { h[2] },
        ]);
    }
    // Each face as a quad counter-clockwise seen from outside, split into two triangles.
    let quads = [
        [0, 2, 3, 1], // z = -h
        [4, 5, 7, 6], // z = +h
        [0, 1, 5, 4], // y = -h
        [2, 6, 7, 3], // y = +h
        [0, 4, 6, 2], // x = -h
        [1, 3, 7, 5], // x = +h
    ];
    let mut triangles = Vec::new();
    for q in quads {
        triangles.push([q[0], q[1], q[2]]);
        triangles.push([q[0], q[2], q[3]]);
    }
    Mesh {
        vertices,
        triangles,
    }
}

fn transformed(mesh: &Mesh, r: Rotor, t: [f64; 3]) -> Mesh {
    let m = from_glam(matrix_from_rotor(r));
    Mesh {
        vertices: mesh
            .vertices
            .iter()
            .map(|v| {
                let x = mul_vec(&m, *v);
                [x[0] + t[0], x[1] + t[1], x[2] + t[2]]
            })
            .collect(),
        triangles: mesh.triangles.clone(),
    }
}

#[test]
fn box_mesh_has_exact_box_mass_properties_in_any_pose() {
    let size = [1.0, 2.0, 3.0];
    let density = 1.5;
    let mass = density * 6.0;
    let solid = Inertia::solid_box(mass, size).unwrap();
    let mut rng = seeded(5);
    for _ in 0..20 {
        let r = rotor(&mut rng);
        let t = vec3(&mut rng, 50.0);
        let inertia = Inertia::from_mesh(&transformed(&box_mesh(size), r, t), density).unwrap();
        assert_rel(inertia.mass().unwrap(), mass, 1e-13, "mass");
        let c = inertia.centre_of_mass();
        for (a, b) in [c.e1, c.e2, c.e3].iter().zip(t) {
            assert_close(*a, b, 1e-12 * (1.0 + b.abs()), "centre of mass");
        }
        // The box's moments are distinct and ascending along e3, e2, e1.
        let [s1, s2, s3] = solid.moments();
        let expected = [s3, s2, s1];
        for k in 0..3 {
            assert_rel(inertia.moments()[k], expected[k], 1e-11, "moment");
        }
        // The principal axes are the box's axes turned by r, up to sign.
        let axes = from_glam(matrix_from_rotor(inertia.rotor()));
        let turned = from_glam(matrix_from_rotor(r));
        for (k, box_axis) in [2, 1, 0].into_iter().enumerate() {
            let dot: f64 = (0..3).map(|i| axes[i][k] * turned[i][box_axis]).sum();
            assert_close(dot.abs(), 1.0, 1e-10, "principal axis");
        }
    }
}

/// An icosphere of radius 1: the icosahedron, each triangle split in four `levels`
/// times, vertices pushed onto the sphere.
fn icosphere(levels: usize) -> Mesh {
    let p = (1.0 + 5f64.sqrt()) / 2.0;
    let mut vertices: Vec<[f64; 3]> = vec![
        [-1.0, p, 0.0],
        [1.0, p, 0.0],
        [-1.0, -p, 0.0],
        [1.0, -p, 0.0],
        [0.0, -1.0, p],
        [0.0, 1.0, p],
        [0.0, -1.0, -p],
        [0.0, 1.0, -p],
        [p, 0.0, -1.0],
        [p, 0.0, 1.0],
        [-p, 0.0, -1.0],
        [-p, 0.0, 1.0],
    ];
    let norm = |v: [f64; 3]| {
        let n = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        v.map(|x| x / n)
    };
    vertices = vertices.into_iter().map(norm).collect();
    let mut triangles: Vec<[usize; 3]> = vec![
        [0, 11, 5],
        [0, 5, 1],
        [0, 1, 7],
        [0, 7, 10],
        [0, 10, 11],
        [1, 5, 9],
        [5, 11, 4],
        [11, 10, 2],
        [10, 7, 6],
        [7, 1, 8],
        [3, 9, 4],
        [3, 4, 2],
        [3, 2, 6],
        [3, 6, 8],
        [3, 8, 9],
        [4, 9, 5],
        [2, 4, 11],
        [6, 2, 10],
        [8, 6, 7],
        [9, 8, 1],
    ];
    for _ in 0..levels {
        let mut midpoints = std::collections::HashMap::new();
        let mut mid = |a: usize, b: usize, vertices: &mut Vec<[f64; 3]>| {
            *midpoints.entry((a.min(b), a.max(b))).or_insert_with(|| {
                let (u, v) = (vertices[a], vertices[b]);
                vertices.push(norm([u[0] + v[0], u[1] + v[1], u[2] + v[2]]));
                vertices.len() - 1
            })
        };
        let mut next = Vec::new();
        for [a, b, c] in triangles {
            let ab = mid(a, b, &mut vertices);
            let bc = mid(b, c, &mut vertices);
            let ca = mid(c, a, &mut vertices);
            next.extend([[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]);
        }
        triangles = next;
    }
    Mesh {
        vertices,
        triangles,
    }
}

#[test]
fn fine_icosphere_mesh_approaches_the_solid_sphere() {
    let mesh = icosphere(4);
    let density = 2.0;
    let inertia = Inertia::from_mesh(&mesh, density).unwrap();
    let mass = inertia.mass().unwrap();
    // 5120 faces: the inscribed polyhedron misses about 0.3 % of the ball's volume.
    assert_rel(
        mass,
        density * 4.0 / 3.0 * std::f64::consts::PI,
        5e-3,
        "mass",
    );
    for k in 0..3 {
        assert_rel(inertia.moments()[k], 0.4 * mass, 5e-3, "moment per mass");
    }
    let c = inertia.centre_of_mass();
    for x in [c.e1, c.e2, c.e3] {
        assert_close(x, 0.0, 1e-14, "centre of mass");
    }
    // Closer to the sphere as the mesh is refined.
    let coarse = Inertia::from_mesh(&icosphere(2), density).unwrap();
    let err = |i: &Inertia| (i.moments()[0] / i.mass().unwrap() - 0.4).abs();
    assert!(err(&inertia) < err(&coarse) / 4.0);
}

/// A closed cone (or cylinder with `apex = false`) of `n` segments around e3, from
/// z = `z0` to z = `z0 + h`, outward-wound.
fn revolved(n: usize, r: f64, h: f64, z0: f64, apex: bool) -> Mesh {
    let mut vertices = vec![[0.0, 0.0, z0], [0.0, 0.0, z0 + h]];
    for k in 0..n {
        let a = 2.0 * std::f64::consts::PI * k as f64 / n as f64;
        vertices.push([r * a.cos(), r * a.sin(), z0]);
    }
    if !apex {
        for k in 0..n {
            let a = 2.0 * std::f64::consts::PI * k as f64 / n as f64;
            vertices.push([r * a.cos(), r * a.sin(), z0 + h]);
        }
    }
    let bottom = |k: usize| 2 + k % n;
    let top = |k: usize| 2 + n + k % n;
    let mut triangles = Vec::new();
    for k in 0..n {
        triangles.push([0, bottom(k + 1), bottom(k)]);
        if apex {
            triangles.push([1, bottom(k), bottom(k + 1)]);
        } else {
            triangles.push([1, top(k), top(k + 1)]);
            triangles.push([bottom(k), bottom(k + 1), top(k + 1)]);
            triangles.push([bottom(k), top(k + 1), top(k)]);
        }
    }
    Mesh {
        vertices,
        triangles,
    }
}

#[test]
fn cone_moments_are_about_its_centre_of_mass_a_quarter_up() {
    let (r, h, density) = (0.8, 2.0, 1.0);
    let mesh = revolved(720, r, h, -h / 4.0, true);
    let inertia = Inertia::from_mesh(&mesh, density).unwrap();
    let c = inertia.centre_of_mass();
    assert_close(c.e3, 0.0, 1e-12, "centre of mass at the origin");
    let mass = inertia.mass().unwrap();
    let solid = Inertia::solid_cone(mass, r, h).unwrap();
    // The polygon is a slightly smaller disc; 720 segments leave ~1e-5 of difference.
    let [s1, s2, s3] = solid.moments();
    let mut expected = [s1, s2, s3];
    expected.sort_by(f64::total_cmp);
    for k in 0..3 {
        assert_rel(inertia.moments()[k], expected[k], 1e-4, "cone moment");
    }
}

#[test]
fn cylinder_mesh_approaches_the_solid_cylinder() {
    let (r, h) = (0.5, 3.0);
    let inertia = Inertia::from_mesh(&revolved(720, r, h, 10.0, false), 3.0).unwrap();
    let solid = Inertia::solid_cylinder(inertia.mass().unwrap(), r, h).unwrap();
    let mut expected = solid.moments();
    expected.sort_by(f64::total_cmp);
    for k in 0..3 {
        assert_rel(inertia.moments()[k], expected[k], 1e-4, "cylinder moment");
    }
    assert_close(inertia.centre_of_mass().e3, 11.5, 1e-12, "centre of mass");
}

const CUBE_OBJ: &str = "\
# a unit cube with quads
o cube
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 1 1 1
v 0 1 1
vn 0 0 1
f 1 4 3 2
f 5 6 7 8
f 1/1 2/2 6/3 5/4
f 2//1 3//1 7//1 6//1
f -5 -1 -2 -6
f 4 1 5 8
";

fn cube_obj(text: &str) -> Result<Inertia, Error> {
    let mesh = Mesh::parse_obj(text, Path::new("cube.obj"))?;
    Inertia::from_mesh(&mesh, 1.0)
}

#[test]
fn obj_quads_negative_indices_and_slashes_parse_to_a_closed_cube() {
    let inertia = cube_obj(CUBE_OBJ).unwrap();
    assert_rel(inertia.mass().unwrap(), 1.0, 1e-14, "volume");
    for k in 0..3 {
        assert_rel(inertia.moments()[k], 1.0 / 6.0, 1e-13, "cube moment");
    }
    let c = inertia.centre_of_mass();
    for x in [c.e1, c.e2, c.e3] {
        assert_close(x, 0.5, 1e-15, "centre");
    }
}

#[test]
fn obj_with_a_missing_face_is_open() {
    let text = CUBE_OBJ.replace("f 4 1 5 8\n", "");
    let e = cube_obj(&text).unwrap_err();
    assert!(matches!(e, Error::OpenMesh { .. }), "{e}");
}

#[test]
fn obj_with_a_flipped_face_is_inconsistently_oriented() {
    let text = CUBE_OBJ.replace("f 4 1 5 8", "f 8 5 1 4");
    let e = cube_obj(&text).unwrap_err();
    assert!(matches!(e, Error::OpenMesh { .. }), "{e}");
}

#[test]
fn obj_wound_inside_out_has_negative_volume() {
    let mut text = String::new();
    for line in CUBE_OBJ.lines() {
        if let Some(rest) = line.strip_prefix("f ") {
            let mut refs: Vec<&str> = rest.split_whitespace().collect();
            refs.reverse();
            text.push_str(&format!("f {}\n", refs.join(" ")));
        } else {
            text.push_str(line);
            text.push('\n');
        }
    }
    let e = cube_obj(&text).unwrap_err();
    assert!(e.to_string().contains("volume must be positive"), "{e}");
}

#[test]
fn obj_bad_lines_report_their_line_number() {
    let e = cube_obj(&CUBE_OBJ.replace("f 4 1 5 8", "f 4 1 5 0")).unwrap_err();
    assert!(matches!(e, Error::Obj { line: 17, .. }), "{e}");
    let e = cube_obj(&CUBE_OBJ.replace("f 4 1 5 8", "f 4 1 5 9")).unwrap_err();
    assert!(matches!(e, Error::Obj { line: 17, .. }), "{e}");
    assert!(e.to_string().contains("out of range"), "{e}");
    let e = cube_obj(&CUBE_OBJ.replace("f 4 1 5 8", "f 4 1 5 -9")).unwrap_err();
    assert!(matches!(e, Error::Obj { line: 17, .. }), "{e}");
    let e = cube_obj(&CUBE_OBJ.replace("v 0 1 1", "v 0 1 nan")).unwrap_err();
    assert!(matches!(e, Error::Obj { line: 10, .. }), "{e}");
    let e = cube_obj(&CUBE_OBJ.replace("v 0 1 1", "v 0 1")).unwrap_err();
    assert!(matches!(e, Error::Obj { line: 10, .. }), "{e}");
    let e = cube_obj(&CUBE_OBJ.replace("f 4 1 5 8", "f 4 1")).unwrap_err();
    assert!(matches!(e, Error::Obj { line: 17, .. }), "{e}");
    assert!(e.to_string().starts_with("mesh: cube.obj:17: "), "{e}");
}

#[test]
fn mesh_density_must_be_positive() {
    let mesh = box_mesh([1.0, 1.0, 1.0]);
    let e = Inertia::from_mesh(&mesh, 0.0).unwrap_err();
    assert_eq!(e.to_string(), "density: density must be positive, got 0");
}

fn reconstruct(values: [f64; 3], v: &Matrix3) -> Matrix3 {
    let d = [
        [values[0], 0.0, 0.0],
        [0.0, values[1], 0.0],
        [0.0, 0.0, values[2]],
    ];
    multiply(&multiply(v, &d), &transpose(v))
}

fn assert_orthonormal_proper(v: &Matrix3) {
    let vtv = multiply(&transpose(v), v);
    for a in 0..3 {
        for b in 0..3 {
            let id = if a == b { 1.0 } else { 0.0 };
            assert_close(vtv[a][b], id, 1e-14, "V^T V = 1");
        }
    }
    assert_close(determinant(v), 1.0, 1e-14, "det V = +1");
}

#[test]
fn eigen_reconstructs_random_symmetric_matrices() {
    let mut rng = seeded(6);
    for _ in 0..1000 {
        let mut a = [[0.0; 3]; 3];
        for i in 0..3 {
            for j in i..3 {
                let x = rng.uniform(-10.0, 10.0);
                a[i][j] = x;
                a[j][i] = x;
            }
        }
        let e = symmetric_eigen(&to_glam(&a));
        assert!(e.values[0] <= e.values[1] && e.values[1] <= e.values[2]);
        let vectors = from_glam(e.vectors);
        assert_orthonormal_proper(&vectors);
        let back = reconstruct(e.values, &vectors);
        let scale = max_abs(&a);
        for i in 0..3 {
            for j in 0..3 {
                assert_close(back[i][j], a[i][j], 1e-13 * scale, "V D V^T = A");
            }
        }
        // Trace and determinant are preserved.
        assert_close(
            e.values.iter().sum::<f64>(),
            a[0][0] + a[1][1] + a[2][2],
            1e-13 * scale,
            "trace",
        );
    }
}

#[test]
fn eigen_handles_repeated_eigenvalues() {
    let mut rng = seeded(7);
    for values in [[1.0, 1.0, 3.0], [1.0, 3.0, 3.0], [2.0, 2.0, 2.0 + 1e-12]] {
        for _ in 0..100 {
            let q = from_glam(matrix_from_rotor(rotor(&mut rng)));
            let a = reconstruct(values, &q);
            let e = symmetric_eigen(&to_glam(&a));
            let vectors = from_glam(e.vectors);
            assert_orthonormal_proper(&vectors);
            for k in 0..3 {
                assert_close(e.values[k], values[k], 1e-14 * 3.0, "repeated eigenvalue");
            }
            let back = reconstruct(e.values, &vectors);
            for i in 0..3 {
                for j in 0..3 {
                    assert_close(back[i][j], a[i][j], 1e-14 * 3.0, "reconstruction");
                }
            }
        }
    }
}

#[test]
fn eigen_of_a_sphere_is_the_identity_frame() {
    let e = symmetric_eigen(&DMat3::from_diagonal(DVec3::splat(2.0)));
    assert_eq!(e.values, [2.0, 2.0, 2.0]);
    assert_eq!(rotor_from_matrix(&e.vectors), Rotor::ONE);
    let sphere = Inertia::from_point_masses(&[
        (1.0, [1.0, 0.0, 0.0]),
        (1.0, [-1.0, 0.0, 0.0]),
        (1.0, [0.0, 1.0, 0.0]),
        (1.0, [0.0, -1.0, 0.0]),
        (1.0, [0.0, 0.0, 1.0]),
        (1.0, [0.0, 0.0, -1.0]),
    ])
    .unwrap();
    assert_eq!(sphere.moments(), [4.0, 4.0, 4.0]);
}

#[test]
fn rotor_minus_e12_turns_e1_toward_e2_in_sandwich_and_matrix() {
    for t in [0.3_f64, 1.0, 2.5, -1.2, 3.1] {
        let r = Rotor::new((t / 2.0).cos(), -(t / 2.0).sin(), 0.0, 0.0);
        let y = r.sandwich(Vector::new(1.0, 0.0, 0.0));
        assert_close(y.e1, t.cos(), 1e-15, "sandwich e1");
        assert_close(y.e2, t.sin(), 1e-15, "sandwich e2");
        assert_close(y.e3, 0.0, 1e-15, "sandwich e3");
        let m = matrix_from_rotor(r);
        assert_close(m.x_axis.x, t.cos(), 1e-15, "matrix e1");
        assert_close(m.x_axis.y, t.sin(), 1e-15, "matrix e2");
    }
}

#[test]
fn matrix_columns_are_the_sandwiched_basis_and_shepperd_inverts_them() {
    let mut rng = seeded(8);
    for _ in 0..1000 {
        let r = rotor(&mut rng);
        let m = from_glam(matrix_from_rotor(r));
        let basis = [
            Vector::new(1.0, 0.0, 0.0),
            Vector::new(0.0, 1.0, 0.0),
            Vector::new(0.0, 0.0, 1.0),
        ];
        for (k, e) in basis.iter().enumerate() {
            let y = r.sandwich(*e);
            for (i, yi) in [y.e1, y.e2, y.e3].iter().enumerate() {
                assert_close(m[i][k], *yi, 1e-15, "column k = R e_k ~R");
            }
        }
        let back = rotor_from_matrix(&to_glam(&m));
        let sign = if r.s < 0.0 { -1.0 } else { 1.0 };
        for (a, b) in [back.s, back.e12, back.e13, back.e23]
            .iter()
            .zip([r.s, r.e12, r.e13, r.e23])
        {
            assert_close(*a, sign * b, 1e-15, "Shepperd round trip");
        }
    }
}

// The public API on glam's `DMat3` (issue 23): each function against glam's own formulas
// or a matrix written by hand.

/// glam's quaternion of a rotor, written out here (`w = s, x = -e23, y = e13, z = -e12`),
/// so that glam's `DMat3::from_quat` is a reference that shares no code with ga-rigid or
/// with ga-core's conversions.
fn glam_quat(r: Rotor) -> DQuat {
    DQuat::from_xyzw(-r.e23, r.e13, -r.e12, r.s)
}

fn assert_mat_close(a: DMat3, b: DMat3, tol: f64, what: &str) {
    let d = (a - b)
        .to_cols_array()
        .iter()
        .fold(0.0_f64, |m, x| m.max(x.abs()));
    assert!(d <= tol, "{what}: {a} vs {b} differ by {d} > {tol}");
}

fn assert_rotor_close_up_to_sign(a: Rotor, b: Rotor, tol: f64, what: &str) {
    let d = (a - b).norm().min((a + b).norm());
    assert!(d <= tol, "{what}: {a:?} vs {b:?} differ by {d} > {tol}");
}

#[test]
fn matrix_from_rotor_is_glams_from_quat() {
    // By hand: a quarter turn in the e12 plane (R = cos(pi/4) - e12 sin(pi/4)) sends e1
    // to e2 and e2 to -e1; the columns of glam's matrix are the images.
    let h = std::f64::consts::FRAC_1_SQRT_2;
    let by_hand = DMat3::from_cols(DVec3::Y, DVec3::NEG_X, DVec3::Z);
    assert_mat_close(
        matrix_from_rotor(Rotor::new(h, -h, 0.0, 0.0)),
        by_hand,
        1e-15,
        "quarter turn",
    );
    let mut rng = seeded(20);
    for _ in 0..1000 {
        let r = rotor(&mut rng);
        let m = matrix_from_rotor(r);
        assert_mat_close(m, DMat3::from_quat(glam_quat(r)), 1e-15, "glam's from_quat");
        // And ga-core's conversion, which the docs say it agrees with to rounding.
        assert_mat_close(m, DMat3::from(r), 1e-15, "ga-core's DMat3::from");
    }
}

#[test]
fn rotor_from_matrix_inverts_glams_from_quat() {
    let mut rng = seeded(21);
    for _ in 0..1000 {
        let r = rotor(&mut rng);
        let m = DMat3::from_quat(glam_quat(r));
        let back = rotor_from_matrix(&m);
        assert!(back.s >= 0.0, "canonical sign: {back:?}");
        assert_rotor_close_up_to_sign(back, r, 1e-15, "glam's from_quat inverted");
        assert_rotor_close_up_to_sign(back, Rotor::from_mat3(m), 1e-15, "ga-core's from_mat3");
    }
    // Half turns by hand, where a trace-only formula divides by zero: diag(1, -1, -1) is a
    // half turn about e1, the rotor -e23 (= cos(pi/2) - sin(pi/2) I e1), and likewise.
    let half_turns = [
        (DVec3::new(1.0, -1.0, -1.0), Rotor::new(0.0, 0.0, 0.0, 1.0)),
        (DVec3::new(-1.0, 1.0, -1.0), Rotor::new(0.0, 0.0, 1.0, 0.0)),
        (DVec3::new(-1.0, -1.0, 1.0), Rotor::new(0.0, 1.0, 0.0, 0.0)),
    ];
    for (diagonal, expected) in half_turns {
        let back = rotor_from_matrix(&DMat3::from_diagonal(diagonal));
        assert_rotor_close_up_to_sign(back, expected, 0.0, "half turn");
    }
}

#[test]
fn symmetric_eigen_of_a_glam_matrix_returns_eigenvectors_as_columns() {
    let mut rng = seeded(22);
    for _ in 0..200 {
        let q = DMat3::from_quat(glam_quat(rotor(&mut rng)));
        let d = [
            rng.uniform(0.5, 1.0),
            rng.uniform(1.5, 2.0),
            rng.uniform(2.5, 3.0),
        ];
        let a = q * DMat3::from_diagonal(DVec3::from_array(d)) * q.transpose();
        let e = symmetric_eigen(&a);
        assert_close(e.vectors.determinant(), 1.0, 1e-14, "proper rotation");
        for k in 0..3 {
            assert_close(e.values[k], d[k], 1e-14, "eigenvalue");
            // Column k belongs to values[k]: A v = lambda v, v = +-q's column k.
            let v = e.vectors.col(k);
            let residual = (a * v - v * e.values[k]).abs().max_element();
            assert!(residual <= 1e-14, "A v - lambda v = {residual}");
            assert_close(v.dot(q.col(k)).abs(), 1.0, 1e-13, "glam's column k");
        }
    }
}

#[test]
fn inertia_matrix_is_glams_r_d_r_transpose() {
    let moments = [1.0, 2.0, 2.5];
    let d = DMat3::from_diagonal(DVec3::from_array(moments));
    let mut rng = seeded(23);
    for _ in 0..200 {
        let r = rotor(&mut rng);
        let inertia = Inertia::from_principal_frame(moments, r).unwrap();
        let q = DMat3::from_quat(glam_quat(r));
        let j = inertia.matrix();
        assert_mat_close(j, q * d * q.transpose(), 1e-14, "J = Q D Q^T");
        // It acts on axial vectors as the bivector map does: I(I b) = I (J b).
        let b = vec3(&mut rng, 1.0);
        let expected = (j * DVec3::from_array(b)).to_array();
        let got = axial(inertia.apply(from_axial(b)));
        for k in 0..3 {
            assert_close(got[k], expected[k], 1e-14, "J b against I(I b)");
        }
    }
    // Principal moments alone: the diagonal matrix, exactly.
    let inertia = Inertia::from_principal(moments).unwrap();
    assert_eq!(inertia.matrix(), d);
}

#[test]
fn from_matrix_takes_a_glam_matrix_and_names_rows_and_columns() {
    let mut rng = seeded(24);
    for _ in 0..100 {
        let r = rotor(&mut rng);
        let q = DMat3::from_quat(glam_quat(r));
        let j = q * DMat3::from_diagonal(DVec3::new(1.0, 1.5, 2.0)) * q.transpose();
        let inertia = Inertia::from_matrix(&j, Some(3.0), Vector::ZERO).unwrap();
        assert_eq!(inertia.mass(), Some(3.0));
        for (got, expected) in inertia.moments().iter().zip([1.0, 1.5, 2.0]) {
            assert_close(*got, expected, 1e-14, "moment");
        }
        // The principal axes are q's columns up to sign: the rotor's matrix, by glam.
        let axes = DMat3::from_quat(glam_quat(inertia.rotor()));
        for k in 0..3 {
            assert_close(axes.col(k).dot(q.col(k)).abs(), 1.0, 1e-13, "axis");
        }
    }
    // glam is column-major: `col(1).x` is row 0, column 1. The message counts (row, column).
    let asymmetric = DMat3::from_cols(
        DVec3::new(2.0, 0.5, 0.0),
        DVec3::new(0.25, 2.0, 0.0),
        DVec3::new(0.0, 0.0, 2.0),
    );
    let e = Inertia::from_matrix(&asymmetric, None, Vector::ZERO).unwrap_err();
    assert!(matches!(e, Error::Invalid { .. }), "{e}");
    assert!(
        e.to_string()
            .ends_with("entry (0,1) is 0.25 and (1,0) is 0.5"),
        "{e}"
    );
}

#[test]
fn mesh_covariance_is_glams_rotated_box_second_moment() {
    // A box of sides a, b, c has `integral of d d^T dV = V diag(a^2, b^2, c^2) / 12` in its
    // own axes; turned by Q it is `Q (that) Q^T`.
    let size = [1.0, 2.0, 3.0];
    let volume = 6.0;
    let own = DMat3::from_diagonal(DVec3::from_array(size.map(|s| volume * s * s / 12.0)));
    let mut rng = seeded(25);
    for _ in 0..20 {
        let r = rotor(&mut rng);
        let moments = transformed(&box_mesh(size), r, [0.5, -0.3, 0.2]).moments();
        let q = DMat3::from_quat(glam_quat(r));
        assert_close(moments.volume, volume, 1e-13, "volume");
        assert_mat_close(
            moments.covariance,
            q * own * q.transpose(),
            1e-13,
            "covariance",
        );
    }
}
