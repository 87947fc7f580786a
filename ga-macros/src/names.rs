//! Names derived from the user's names, shared by the front end (the derive form's module)
//! and the back ends (WGSL function names), so that neither reaches into the other.

/// `SpaceTime` -> `space_time`.
pub fn snake_case(name: &str) -> String {
    let mut out = String::new();
    for (i, c) in name.chars().enumerate() {
        if c.is_uppercase() {
            if i > 0 {
                out.push('_');
            }
            out.extend(c.to_lowercase());
        } else {
            out.push(c);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn snake_case_splits_words() {
        assert_eq!(snake_case("SpaceTime"), "space_time");
        assert_eq!(snake_case("G3"), "g3");
    }
}
