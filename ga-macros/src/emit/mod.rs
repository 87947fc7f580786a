//! The back end: writes the module from a [`Plan`]. Nothing here can fail: every choice
//! was made and checked before.

mod batch;
mod conveniences;
mod exp_log;
mod expr;
#[cfg(feature = "generic")]
mod generic;
mod integrations;
mod math;
mod motors;
mod operators;
mod products;
mod projective;
mod simd;
mod sin_cos;
mod template;
mod types;
mod unary;
mod versor;
#[cfg(feature = "wgsl")]
mod wgsl;

#[cfg(feature = "wgsl")]
pub use wgsl::colliding_functions;
#[cfg(all(test, feature = "wgsl"))]
pub use wgsl::wgsl_source;

use proc_macro2::TokenStream;
use quote::quote;

use crate::plan::{Plan, TypeId, TypeKind};
use crate::spec::{Op, Spec};

/// The items of the algebra module, without the `mod` wrapper.
pub fn module_items(spec: &Spec, plan: &Plan) -> TokenStream {
    let n = plan.metric.dimension();
    let mut items = types::emit_support_items(plan);
    if spec.generic_scalar.is_some() {
        // Without the `generic` feature validation refuses a generic scalar.
        #[cfg(feature = "generic")]
        {
            items.extend(generic::emit_math());
            items.extend(generic::emit_defaults(plan));
        }
    } else if plan.lanes.is_none() {
        items.extend(math::emit_math(plan, &spec.math));
    }
    for &t in &plan.emitted {
        items.extend(types::emit_struct(plan, t));
        items.extend(unary::emit_unary(plan, t));
        if plan.has(Op::Reflect)
            && plan.emitted.contains(&TypeId::grade(1))
            && plan.has(Op::Sandwich)
        {
            items.extend(versor::emit_reflect(plan, t));
        }
        let mv_available = plan.emitted.contains(&TypeId::multivector(n));
        if plan.has(Op::Factor)
            && mv_available
            && matches!(plan.types.get(t).kind, TypeKind::Grade(_))
        {
            items.extend(versor::emit_blades(plan, t));
        }
    }
    if simd::module_uses_lanes(plan) {
        items.extend(simd::emit_lane_helpers());
    }
    items.extend(products::emit_product_traits(plan));
    items.extend(products::emit_products(plan));
    if plan.has(Op::Add) {
        items.extend(operators::emit_operators(plan));
    } else {
        items.extend(operators::emit_scaling(plan));
    }
    if plan.has(Op::Sandwich) {
        items.extend(versor::emit_sandwiches(plan));
    }
    items.extend(conveniences::emit_conveniences(plan));
    items.extend(projective::emit_projective_constructors(plan));
    items.extend(motors::emit_motor_toolkit(plan));
    if plan.lanes.is_none() && plan.emitted.contains(&TypeId::multivector(n)) {
        items.extend(unary::emit_multivector_inverse(plan));
        items.extend(versor::emit_multivector_helpers(plan));
    }
    let (exp, log) = (plan.exp_form(), plan.log_form());
    if let Some(form) = exp {
        items.extend(exp_log::emit_exp(plan, form));
    }
    if let Some(form) = log {
        items.extend(exp_log::emit_log(plan, form));
    }
    if exp.is_some() || log.is_some() {
        items.extend(exp_log::emit_scalar_functions(plan));
    }
    items.extend(integrations::emit_integrations(spec, plan));
    #[cfg(feature = "wgsl")]
    items.extend(wgsl::emit_wgsl(spec, plan));
    if plan.lanes.is_none() {
        // The batch modules are this emitter run again on a batch plan.
        for &lanes in &spec.lanes {
            let batch = plan.batch(lanes);
            let batch_items = module_items(spec, &batch);
            items.extend(batch::emit_batch_module(&batch, lanes, batch_items));
        }
    }
    items
}

/// The whole module: the user's attributes and visibility around the items.
pub fn module(spec: &Spec, plan: &Plan) -> TokenStream {
    let items = module_items(spec, plan);
    #[cfg(feature = "generic")]
    let items = match &spec.generic_scalar {
        Some(path) => generic::rewrite(items, path),
        None => items,
    };
    let (attrs, vis, name) = (&spec.attrs, &spec.vis, &spec.name);
    // Generated code follows the sign table term by term (`a.s * b.s - a.e12 * b.e12`,
    // constructors with one argument per component), which clippy's style lints would
    // rewrite; the user's own lints should not fire on code they did not write.
    quote! {
        #(#attrs)*
        #[allow(clippy::all, clippy::pedantic, clippy::nursery)]
        #vis mod #name {
            #items
        }
    }
}
