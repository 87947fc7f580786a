//! Impls of other crates' traits, asked for with `derive: [serde, bytemuck, approx, mint]`.
//!
//! The orphan rule leaves these to the crate that defines the types, so they are emitted
//! here rather than written by users. Each crate's impls sit in one anonymous
//! `const _: () = { use <path> as __ga_<crate>; ... };` block carrying the entry's
//! `#[cfg(..)]` attributes: the `use` is the only place the crate is named, so a missing
//! dependency is one "unresolved import" error, pointing at the user's `serde` in the
//! `derive` list (the default path `::serde` carries that token's span). Batch modules get
//! none of them: `wide`'s vectors are not plain floats.

use proc_macro2::TokenStream;
use quote::{format_ident, quote};

use super::expr::{field_ident, float, scalar_type, type_tokens};
use crate::algebra::blade_name;
use crate::plan::{Plan, TypeId};
use crate::spec::{Integration, IntegrationKind, Spec};

/// Every requested integration of one (non-batch) module.
pub fn emit_integrations(spec: &Spec, plan: &Plan) -> TokenStream {
    if plan.lanes.is_some() {
        return TokenStream::new();
    }
    spec.integrations
        .iter()
        .map(|integration| emit_integration(plan, integration))
        .collect()
}

fn emit_integration(plan: &Plan, integration: &Integration) -> TokenStream {
    let path = &integration.path;
    let cfgs = &integration.cfgs;
    let (alias, body, allow) = match integration.kind {
        IntegrationKind::Serde => (format_ident!("__ga_serde"), serde(plan), quote!()),
        IntegrationKind::Bytemuck => (
            format_ident!("__ga_bytemuck"),
            bytemuck(plan),
            quote!(#[allow(unsafe_code)]),
        ),
        IntegrationKind::Approx => (format_ident!("__ga_approx"), approx(plan), quote!()),
        IntegrationKind::Mint => (format_ident!("__ga_mint"), mint(plan), quote!()),
    };
    // The whole `use` carries the span of the user's entry: rustc reports an unresolved
    // import at the use tree, and a tree mixing spans falls back to the macro call.
    let span = integration.span;
    let alias = proc_macro2::Ident::new(&alias.to_string(), span);
    let import = quote::quote_spanned!(span=> use #path as #alias;);
    quote! {
        #(#cfgs)*
        #allow
        const _: () = {
            #import
            #body
        };
    }
}

/// The field names of a type as strings, in canonical order.
fn field_names(plan: &Plan, t: TypeId) -> Vec<String> {
    plan.types
        .get(t)
        .blades
        .iter()
        .map(|&b| blade_name(b))
        .collect()
}

/// Each type as a struct of named blades (`{"s": 1.0, "e12": 0.0, ...}`); reading also
/// accepts a sequence in canonical order, and rejects unknown, repeated or missing blades.
fn serde(plan: &Plan) -> TokenStream {
    let s = scalar_type(plan);
    let zero = float(0.0);
    let impls = plan.emitted.iter().map(|&t| {
        let name = type_tokens(plan, t);
        let name_str = plan.types.get(t).name.clone();
        let names = field_names(plan, t);
        let fields: Vec<_> = plan
            .types
            .get(t)
            .blades
            .iter()
            .map(|&b| field_ident(b))
            .collect();
        let len = fields.len();
        quote! {
            impl __ga_serde::Serialize for #name {
                fn serialize<Ser: __ga_serde::Serializer>(
                    &self,
                    serializer: Ser,
                ) -> ::core::result::Result<Ser::Ok, Ser::Error> {
                    use __ga_serde::ser::SerializeStruct;
                    let mut state = serializer.serialize_struct(#name_str, #len)?;
                    #(state.serialize_field(#names, &self.#fields)?;)*
                    state.end()
                }
            }

            impl<'de> __ga_serde::Deserialize<'de> for #name {
                fn deserialize<De: __ga_serde::Deserializer<'de>>(
                    deserializer: De,
                ) -> ::core::result::Result<Self, De::Error> {
                    const FIELDS: &[&str] = &[#(#names),*];
                    deserializer
                        .deserialize_struct(
                            #name_str,
                            FIELDS,
                            __GaBlades::<#len> { name: #name_str, fields: FIELDS },
                        )
                        .map(Self::from_array)
                }
            }
        }
    });
    let impls: TokenStream = impls.collect();
    super::template::fill(
        SERDE_VISITOR,
        &[("s", &s), ("zero", &zero), ("impls", &impls)],
    )
}

/// The visitor that reads a type by blade names or in canonical order, and each type's
/// impls (`#impls`).
const SERDE_VISITOR: &str = r#"
/// Reads the components of one type, by blade name or in canonical order.
struct __GaBlades<const N: usize> {
    name: &'static str,
    fields: &'static [&'static str],
}

impl<'de, const N: usize> __ga_serde::de::Visitor<'de> for __GaBlades<N> {
    type Value = [#s; N];

    fn expecting(&self, f: &mut ::core::fmt::Formatter) -> ::core::fmt::Result {
        ::core::write!(f, "struct {} with blades {:?}", self.name, self.fields)
    }

    fn visit_seq<A: __ga_serde::de::SeqAccess<'de>>(
        self,
        mut seq: A,
    ) -> ::core::result::Result<[#s; N], A::Error> {
        let mut out = [#zero; N];
        for (i, slot) in out.iter_mut().enumerate() {
            *slot = match seq.next_element()? {
                ::core::option::Option::Some(value) => value,
                ::core::option::Option::None => {
                    return ::core::result::Result::Err(
                        <A::Error as __ga_serde::de::Error>::invalid_length(i, &self),
                    )
                }
            };
        }
        ::core::result::Result::Ok(out)
    }

    fn visit_map<A: __ga_serde::de::MapAccess<'de>>(
        self,
        mut map: A,
    ) -> ::core::result::Result<[#s; N], A::Error> {
        let mut found: [::core::option::Option<#s>; N] = [::core::option::Option::None; N];
        while let ::core::option::Option::Some(i) =
            map.next_key_seed(__GaBladeName { fields: self.fields })?
        {
            if found[i].is_some() {
                return ::core::result::Result::Err(
                    <A::Error as __ga_serde::de::Error>::duplicate_field(self.fields[i]),
                );
            }
            found[i] = ::core::option::Option::Some(map.next_value()?);
        }
        let mut out = [#zero; N];
        for (i, slot) in out.iter_mut().enumerate() {
            *slot = match found[i] {
                ::core::option::Option::Some(value) => value,
                ::core::option::Option::None => {
                    return ::core::result::Result::Err(
                        <A::Error as __ga_serde::de::Error>::missing_field(self.fields[i]),
                    )
                }
            };
        }
        ::core::result::Result::Ok(out)
    }
}

/// A blade name read as the index of its field.
struct __GaBladeName {
    fields: &'static [&'static str],
}

impl<'de> __ga_serde::de::DeserializeSeed<'de> for __GaBladeName {
    type Value = usize;

    fn deserialize<De: __ga_serde::Deserializer<'de>>(
        self,
        deserializer: De,
    ) -> ::core::result::Result<usize, De::Error> {
        deserializer.deserialize_identifier(self)
    }
}

impl<'de> __ga_serde::de::Visitor<'de> for __GaBladeName {
    type Value = usize;

    fn expecting(&self, f: &mut ::core::fmt::Formatter) -> ::core::fmt::Result {
        ::core::write!(f, "one of the blades {:?}", self.fields)
    }

    fn visit_str<E: __ga_serde::de::Error>(
        self,
        value: &str,
    ) -> ::core::result::Result<usize, E> {
        self.fields
            .iter()
            .position(|f| *f == value)
            .ok_or_else(|| E::unknown_field(value, self.fields))
    }
}

#impls
"#;

/// `Pod` and `Zeroable`: every type is `#[repr(C)]` with fields of one float type only,
/// so it has no padding, and every bit pattern (zero included) is a valid value.
fn bytemuck(plan: &Plan) -> TokenStream {
    let impls = plan.emitted.iter().map(|&t| {
        let name = type_tokens(plan, t);
        quote! {
            // SAFETY: `#[repr(C)]`, fields all of one float type: no padding, no invalid
            // bit patterns, and all zeros is `ZERO`.
            unsafe impl __ga_bytemuck::Zeroable for #name {}
            // SAFETY: as above; the type is `Copy` and owns no references.
            unsafe impl __ga_bytemuck::Pod for #name {}
        }
    });
    quote!(#(#impls)*)
}

/// `AbsDiffEq`, `RelativeEq`, `UlpsEq`: component by component, with the scalar type's
/// own defaults (what approx does for arrays and glam for its vectors).
fn approx(plan: &Plan) -> TokenStream {
    let s = scalar_type(plan);
    let impls = plan.emitted.iter().map(|&t| {
        let name = type_tokens(plan, t);
        let fields: Vec<_> = plan
            .types
            .get(t)
            .blades
            .iter()
            .map(|&b| field_ident(b))
            .collect();
        quote! {
            impl __ga_approx::AbsDiffEq for #name {
                type Epsilon = #s;

                #[inline]
                fn default_epsilon() -> #s {
                    <#s as __ga_approx::AbsDiffEq>::default_epsilon()
                }

                #[inline]
                fn abs_diff_eq(&self, other: &Self, epsilon: #s) -> bool {
                    true #(&& <#s as __ga_approx::AbsDiffEq>::abs_diff_eq(
                        &self.#fields, &other.#fields, epsilon))*
                }
            }

            impl __ga_approx::RelativeEq for #name {
                #[inline]
                fn default_max_relative() -> #s {
                    <#s as __ga_approx::RelativeEq>::default_max_relative()
                }

                #[inline]
                fn relative_eq(&self, other: &Self, epsilon: #s, max_relative: #s) -> bool {
                    true #(&& <#s as __ga_approx::RelativeEq>::relative_eq(
                        &self.#fields, &other.#fields, epsilon, max_relative))*
                }
            }

            impl __ga_approx::UlpsEq for #name {
                #[inline]
                fn default_max_ulps() -> u32 {
                    <#s as __ga_approx::UlpsEq>::default_max_ulps()
                }

                #[inline]
                fn ulps_eq(&self, other: &Self, epsilon: #s, max_ulps: u32) -> bool {
                    true #(&& <#s as __ga_approx::UlpsEq>::ulps_eq(
                        &self.#fields, &other.#fields, epsilon, max_ulps))*
                }
            }
        }
    });
    quote!(#(#impls)*)
}

/// G3 only (checked in spec): `Vector` <-> `Vector3`, `Rotor` <-> `Quaternion` with
/// `w = s, x = -e23, y = e13, z = -e12` (docs/derivations/rotor-quaternion.md), and the
/// rotor's rotation matrix as a `ColumnMatrix3`.
fn mint(plan: &Plan) -> TokenStream {
    let s = scalar_type(plan);
    let mut out = TokenStream::new();
    let vector = TypeId::grade(1);
    if plan.emitted.contains(&vector) {
        let name = type_tokens(plan, vector);
        out.extend(quote! {
            impl ::core::convert::From<__ga_mint::Vector3<#s>> for #name {
                #[inline]
                fn from(v: __ga_mint::Vector3<#s>) -> Self {
                    Self::new(v.x, v.y, v.z)
                }
            }

            impl ::core::convert::From<#name> for __ga_mint::Vector3<#s> {
                #[inline]
                fn from(v: #name) -> Self {
                    __ga_mint::Vector3 { x: v.e1, y: v.e2, z: v.e3 }
                }
            }
        });
    }
    let even = TypeId::even(3);
    if plan.emitted.contains(&even) {
        let name = type_tokens(plan, even);
        let (one, two) = (float(1.0), float(2.0));
        out.extend(super::template::fill(
            MINT_EVEN,
            &[("s", &s), ("name", &name), ("one", &one), ("two", &two)],
        ));
    }
    out
}

/// `From` between `Even` and mint's quaternion and matrix (`#name` the type).
const MINT_EVEN: &str = r#"
impl ::core::convert::From<__ga_mint::Quaternion<#s>> for #name {
    #[inline]
    fn from(q: __ga_mint::Quaternion<#s>) -> Self {
        Self::new(q.s, -q.v.z, q.v.y, -q.v.x)
    }
}

impl ::core::convert::From<#name> for __ga_mint::Quaternion<#s> {
    #[inline]
    fn from(r: #name) -> Self {
        __ga_mint::Quaternion {
            v: __ga_mint::Vector3 { x: -r.e23, y: r.e13, z: -r.e12 },
            s: r.s,
        }
    }
}

impl ::core::convert::From<#name> for __ga_mint::ColumnMatrix3<#s> {
    /// The matrix of `x -> R x ~R` for a unit rotor: columns the images of
    /// e1, e2, e3 (the unit quaternion's matrix under the mapping above).
    #[inline]
    fn from(r: #name) -> Self {
        let (w, x, y, z) = (r.s, -r.e23, r.e13, -r.e12);
        let column = |x, y, z| __ga_mint::Vector3 { x, y, z };
        __ga_mint::ColumnMatrix3 {
            x: column(
                #one - #two * (y * y + z * z),
                #two * (x * y + w * z),
                #two * (x * z - w * y),
            ),
            y: column(
                #two * (x * y - w * z),
                #one - #two * (x * x + z * z),
                #two * (y * z + w * x),
            ),
            z: column(
                #two * (x * z + w * y),
                #two * (y * z - w * x),
                #one - #two * (x * x + y * y),
            ),
        }
    }
}
"#;
