//! Basis blades as bitmasks: bit `i` set means the blade contains `e_{i+1}`.
//!
//! Everything here is metric-free: grades, the sign of reordering a product of
//! two blades into ascending order, the canonical order of blades and their
//! field names.

/// The grade of a blade: how many generators it holds.
#[must_use]
pub fn grade(blade: usize) -> usize {
    blade.count_ones() as usize
}

/// The sign of sorting `e_A e_B` into ascending order, ignoring the squares of
/// shared generators: `(-1)^swaps`, where each generator of `a` must swap past
/// every generator of `b` with a lower index.
#[must_use]
pub fn reorder_sign(a: usize, b: usize) -> f64 {
    let mut swaps = 0;
    let mut rest = a;
    while rest != 0 {
        let bit = rest.trailing_zeros();
        swaps += grade(b & ((1 << bit) - 1));
        rest &= rest - 1;
    }
    if swaps % 2 == 0 {
        1.0
    } else {
        -1.0
    }
}

/// The one-based indices of the generators in a blade, ascending: `0b101` is `[1, 3]`.
#[must_use]
pub fn indices(blade: usize) -> Vec<usize> {
    (0..usize::BITS as usize)
        .filter(|bit| blade & (1 << bit) != 0)
        .map(|bit| bit + 1)
        .collect()
}

/// Every blade of the `n`-dimensional algebra in canonical order: grade first,
/// then lexicographic on the ascending index list (G3: 1, e1, e2, e3, e12, e13,
/// e23, e123).
#[must_use]
pub fn canonical_blades(n: usize) -> Vec<usize> {
    let mut blades: Vec<usize> = (0..1 << n).collect();
    blades.sort_by_key(|&blade| (grade(blade), indices(blade)));
    blades
}

/// The blades of the given grades in canonical order: the field order of a type
/// holding exactly those grades.
#[must_use]
pub fn blades_of_grades(n: usize, grades: &[usize]) -> Vec<usize> {
    canonical_blades(n)
        .into_iter()
        .filter(|&blade| grades.contains(&grade(blade)))
        .collect()
}

/// The grades `0..=n` that a type named `name` holds in the `n`-dimensional
/// algebra (`Scalar` is the plain scalar), or `None` for an unknown name.
#[must_use]
pub fn grades_of_type(name: &str, n: usize) -> Option<Vec<usize>> {
    const GRADE_TYPES: [&str; 6] = [
        "Vector",
        "Bivector",
        "Trivector",
        "Quadvector",
        "Pentavector",
        "Hexavector",
    ];
    let all = 0..=n;
    match name {
        "Scalar" => Some(vec![0]),
        "Pseudoscalar" => Some(vec![n]),
        "Even" | "Rotor" => Some(all.filter(|r| r % 2 == 0).collect()),
        "Odd" => Some(all.filter(|r| r % 2 == 1).collect()),
        "Multivector" => Some(all.collect()),
        _ => {
            let r = GRADE_TYPES.iter().position(|&t| t == name)? + 1;
            (r <= n).then(|| vec![r])
        }
    }
}

/// The field name of a blade: `s` for the scalar, else `e` and the ascending
/// indices (`0b101` is `e13`).
#[must_use]
pub fn blade_name(blade: usize) -> String {
    if blade == 0 {
        return "s".to_owned();
    }
    let digits: String = indices(blade).iter().map(ToString::to_string).collect();
    format!("e{digits}")
}

/// The blade named by a field: `s` is the scalar, `e13` is `0b101`. The indices are
/// single digits from 1 to 9 in strictly ascending order; anything else is `None`.
#[must_use]
pub fn blade_from_name(name: &str) -> Option<usize> {
    if name == "s" {
        return Some(0);
    }
    let digits = name.strip_prefix('e')?;
    if digits.is_empty() {
        return None;
    }
    let mut blade = 0;
    let mut previous = 0;
    for c in digits.chars() {
        let index = c.to_digit(10)? as usize;
        if index <= previous {
            return None;
        }
        blade |= 1 << (index - 1);
        previous = index;
    }
    Some(blade)
}

/// The blades of a canonical component list given by field names.
///
/// # Panics
/// If a name is not a blade name.
#[must_use]
pub fn blades_from_names(names: &[&str]) -> Vec<usize> {
    names
        .iter()
        .map(|name| blade_from_name(name).unwrap_or_else(|| panic!("not a blade name: {name}")))
        .collect()
}

/// `n` choose `r`.
#[must_use]
pub fn binomial(n: usize, r: usize) -> usize {
    if r > n {
        return 0;
    }
    (0..r).fold(1, |acc, k| acc * (n - k) / (k + 1))
}
