//! Parse, validate, plan, emit: the pipeline behind both entry points.

use proc_macro2::TokenStream;

use crate::emit;
use crate::names::snake_case;
use crate::plan::{Plan, TypeId};
use crate::spec::{check_emitted, validate, RawAlgebra, RawDerive, Spec};

/// The plan of a validated spec, refused when an operation the user listed would be
/// missing from it.
fn plan(spec: &Spec) -> syn::Result<Plan> {
    let plan = Plan::new(spec);
    let n = spec.metric.dimension();
    let emits = |id| plan.emitted.contains(&id);
    check_emitted(
        spec,
        n >= 2 && emits(TypeId::grade(2)),
        emits(TypeId::even(n)),
    )?;
    #[cfg(feature = "wgsl")]
    if spec.wgsl.is_some() {
        crate::spec::check_wgsl_names(spec, &emit::colliding_functions(&plan))?;
    }
    Ok(plan)
}

/// `algebra! { ... }`.
pub fn algebra(input: RawAlgebra) -> syn::Result<TokenStream> {
    let spec = validate(input.attrs, input.vis, input.name, input.entries)?;
    let plan = plan(&spec)?;
    Ok(emit::module(&spec, &plan))
}

/// The validated spec of an `algebra!` input (for the WGSL snapshot test).
#[cfg(all(test, feature = "wgsl"))]
pub fn spec_of(input: RawAlgebra) -> syn::Result<Spec> {
    validate(input.attrs, input.vis, input.name, input.entries)
}

/// `#[derive(Algebra)]`: the same items, in a sibling module named after the marker type
/// in snake case (`struct SpaceTime;` gives `mod space_time`).
pub fn derive(input: syn::DeriveInput) -> syn::Result<TokenStream> {
    let raw = RawDerive::from_derive(input)?;
    let module_name = syn::Ident::new(&snake_case(&raw.name.to_string()), raw.name.span());
    let spec = validate(raw.attrs, raw.vis, module_name, raw.entries)?;
    let plan = plan(&spec)?;
    Ok(emit::module(&spec, &plan))
}
