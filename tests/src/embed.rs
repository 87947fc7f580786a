//! Conversion of the generated types to and from the reference's dense layout.
//!
//! A type's blades are read from its field names (through its derived `Debug`),
//! not assumed: a value whose `k`-th array component is `k + 1` prints as
//! `Vector { e1: 1.0, e2: 2.0, e3: 3.0 }`, which names the blade of every
//! `to_array` index. The test `layout` checks that this is the canonical order.

use crate::blade::blade_from_name;

/// A generated type of the algebra whose multivector type is `M`, seen as a dense
/// reference multivector.
pub trait Embed<M>: Copy {
    /// The type's name in `TERM_COUNTS` (`Scalar` for the scalar).
    const NAME: &'static str;

    /// The blade of each `to_array` component, in array order.
    fn blades() -> &'static [usize];

    /// The dense reference multivector with this value's components.
    fn to_reference(self) -> Vec<f64>;

    /// The value holding `dense`'s components on this type's blades (the others
    /// are dropped).
    fn from_reference(dense: &[f64]) -> Self;
}

/// The blade of each array index, from the `Debug` text of a value whose `k`-th
/// component is `k + 1`.
///
/// # Panics
/// If the text is not `Name { field: value, ... }` with `len` fields named by
/// blades, holding the values `1..=len`.
#[must_use]
pub fn blades_from_debug(text: &str, len: usize) -> Vec<usize> {
    let open = text
        .find('{')
        .unwrap_or_else(|| panic!("no fields in {text}"));
    let close = text
        .rfind('}')
        .unwrap_or_else(|| panic!("no fields in {text}"));
    let mut blades = vec![None; len];
    for field in text[open + 1..close]
        .split(',')
        .map(str::trim)
        .filter(|f| !f.is_empty())
    {
        let (name, value) = field
            .split_once(':')
            .unwrap_or_else(|| panic!("not a field: {field} in {text}"));
        let blade = blade_from_name(name.trim())
            .unwrap_or_else(|| panic!("field {name} is not a blade name in {text}"));
        let value: f64 = value
            .trim()
            .parse()
            .unwrap_or_else(|_| panic!("field {name} has no number in {text}"));
        let index = (value as usize)
            .checked_sub(1)
            .filter(|&k| k < len && value.fract() == 0.0)
            .unwrap_or_else(|| panic!("field {name} holds {value}, not an index in {text}"));
        assert!(blades[index].is_none(), "two fields hold {value} in {text}");
        blades[index] = Some(blade);
    }
    blades
        .into_iter()
        .enumerate()
        .map(|(k, blade)| blade.unwrap_or_else(|| panic!("no field holds {} in {text}", k + 1)))
        .collect()
}

/// Implements [`Embed`] for the listed types of the algebra in scope (its
/// `Multivector` must be in scope) and for its scalar type (`f64` or `f32`),
/// named `Scalar`. The reference is `f64`: an `f32` algebra's values widen
/// exactly on the way out and round on the way in.
#[macro_export]
macro_rules! embed_types {
    ($scalar:ident; $($ty:ident),* $(,)?) => {
        $(
            impl $crate::embed::Embed<Multivector> for $ty {
                const NAME: &'static str = stringify!($ty);

                fn blades() -> &'static [usize] {
                    static BLADES: ::std::sync::OnceLock<::std::vec::Vec<usize>> =
                        ::std::sync::OnceLock::new();
                    BLADES.get_or_init(|| {
                        let mut values = <$ty>::ZERO.to_array();
                        for (k, value) in values.iter_mut().enumerate() {
                            *value = (k + 1) as $scalar;
                        }
                        let text = format!("{:?}", <$ty>::from_array(values));
                        $crate::embed::blades_from_debug(&text, values.len())
                    })
                }

                fn to_reference(self) -> ::std::vec::Vec<f64> {
                    let mut dense = vec![0.0; Multivector::ZERO.to_array().len()];
                    let blades = <Self as $crate::embed::Embed<Multivector>>::blades();
                    for (&blade, value) in blades.iter().zip(self.to_array()) {
                        dense[blade] = f64::from(value);
                    }
                    dense
                }

                fn from_reference(dense: &[f64]) -> Self {
                    let mut values = <$ty>::ZERO.to_array();
                    let blades = <Self as $crate::embed::Embed<Multivector>>::blades();
                    for (value, &blade) in values.iter_mut().zip(blades) {
                        *value = dense[blade] as $scalar;
                    }
                    <$ty>::from_array(values)
                }
            }
        )*

        impl $crate::embed::Embed<Multivector> for $scalar {
            const NAME: &'static str = "Scalar";

            fn blades() -> &'static [usize] {
                &[0]
            }

            fn to_reference(self) -> ::std::vec::Vec<f64> {
                let mut dense = vec![0.0; Multivector::ZERO.to_array().len()];
                dense[0] = f64::from(self);
                dense
            }

            fn from_reference(dense: &[f64]) -> Self {
                dense[0] as $scalar
            }
        }
    };
}

/// The dense reference multivector of any generated value (including `Zero` and
/// the scalar), through `Multivector::from`.
#[macro_export]
macro_rules! dense {
    ($value:expr) => {
        <Multivector as $crate::embed::Embed<Multivector>>::to_reference(Multivector::from($value))
    };
}
