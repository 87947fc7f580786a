/// A basis blade: bit `i` set means the generator `e{i+1}` is a factor, in ascending order.
pub type Blade = u32;

/// The grade of a blade: how many generators it has.
pub fn grade(blade: Blade) -> u32 {
    blade.count_ones()
}

/// The indices of a blade's generators, ascending and 1-based.
fn indices(blade: Blade) -> Vec<u32> {
    (0..32)
        .filter(|i| blade & (1 << i) != 0)
        .map(|i| i + 1)
        .collect()
}

/// The field name of a blade: `s` for the scalar, otherwise `e` and the ascending indices.
pub fn blade_name(blade: Blade) -> String {
    if blade == 0 {
        return "s".to_owned();
    }
    let digits: String = indices(blade).iter().map(|i| i.to_string()).collect();
    format!("e{digits}")
}

/// Every blade of an n-dimensional algebra in canonical order: grade first, then
/// lexicographic on the ascending index list (G3: 1, e1, e2, e3, e12, e13, e23, e123).
pub fn canonical_blades(dimension: usize) -> Vec<Blade> {
    let mut blades: Vec<Blade> = (0..(1u32 << dimension)).collect();
    blades.sort_by_key(|&b| (grade(b), indices(b)));
    blades
}

/// Reads a blade name (`e13`, or `s` for the scalar); `None` unless the indices are
/// single digits from 1 to `dimension`, strictly ascending.
pub fn parse_blade(name: &str, dimension: usize) -> Option<Blade> {
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
        let index = c.to_digit(10)?;
        if index <= previous || index as usize > dimension {
            return None;
        }
        blade |= 1 << (index - 1);
        previous = index;
    }
    Some(blade)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn g3_canonical_order_is_grade_then_lexicographic() {
        let names: Vec<String> = canonical_blades(3).into_iter().map(blade_name).collect();
        assert_eq!(names, ["s", "e1", "e2", "e3", "e12", "e13", "e23", "e123"]);
    }

    #[test]
    fn g4_bivectors_are_lexicographic() {
        let names: Vec<String> = canonical_blades(4)
            .into_iter()
            .filter(|&b| grade(b) == 2)
            .map(blade_name)
            .collect();
        assert_eq!(names, ["e12", "e13", "e14", "e23", "e24", "e34"]);
    }

    #[test]
    fn blade_names_round_trip_and_reject_bad_spellings() {
        for n in 1..=6 {
            for blade in canonical_blades(n) {
                assert_eq!(parse_blade(&blade_name(blade), n), Some(blade));
            }
        }
        for bad in ["e21", "e4", "e", "x", "e11", "e0", "E1"] {
            assert_eq!(parse_blade(bad, 3), None, "{bad}");
        }
    }
}
