//! `TERM_COUNTS` states how many multiplications each unrolled product performs.
//! Every entry is recounted by brute force with the reference: the number of
//! component pairs of the two types whose blade product is non-zero and passes
//! the product's grade filter (for the commutator: whose blades anticommute).

use ga_tests::blade::{blades_of_grades, grades_of_type};
use ga_tests::{Algebra, Product};
use std::collections::HashMap;

/// The blades of the type named `name`, in canonical order.
fn blades_of_type(name: &str, n: usize) -> Vec<usize> {
    let grades = grades_of_type(name, n).unwrap_or_else(|| panic!("unknown type {name}"));
    blades_of_grades(n, &grades)
}

fn check_term_counts(metric: &[i8], term_counts: &[(&str, &str, &str, usize)]) {
    let algebra = Algebra::new(metric);
    let n = algebra.dim();
    assert!(!term_counts.is_empty(), "TERM_COUNTS is empty");
    let mut wrong = Vec::new();
    for &(product, lhs, rhs, count) in term_counts {
        let kind =
            Product::from_name(product).unwrap_or_else(|| panic!("unknown product {product}"));
        let recount = algebra.term_count(kind, &blades_of_type(lhs, n), &blades_of_type(rhs, n));
        if recount != count {
            wrong.push(format!(
                "  {lhs} {product} {rhs}: TERM_COUNTS says {count}, recount {recount}"
            ));
        }
    }
    assert!(
        wrong.is_empty(),
        "{} of {} term counts disagree with the recount for metric {metric:?}:\n{}",
        wrong.len(),
        term_counts.len(),
        wrong.join("\n")
    );
}

fn check_coverage(metric: &[i8], types: &[&str], term_counts: &[(&str, &str, &str, usize)]) {
    let algebra = Algebra::new(metric);
    let n = algebra.dim();
    let mut entries: HashMap<(&str, &str, &str), usize> = HashMap::new();
    for &(product, lhs, rhs, _) in term_counts {
        *entries.entry((product, lhs, rhs)).or_default() += 1;
    }
    let duplicated: Vec<_> = entries
        .iter()
        .filter(|(_, &k)| k > 1)
        .map(|(key, _)| key)
        .collect();
    assert!(
        duplicated.is_empty(),
        "listed more than once: {duplicated:?}"
    );
    let mut missing = Vec::new();
    for product in Product::ALL {
        for &lhs in types {
            for &rhs in types {
                let scalars = lhs == "Scalar" && rhs == "Scalar";
                let terms =
                    algebra.term_count(product, &blades_of_type(lhs, n), &blades_of_type(rhs, n));
                if !scalars && terms > 0 && !entries.contains_key(&(product.name(), lhs, rhs)) {
                    missing.push(format!("  {lhs} {} {rhs} ({terms} terms)", product.name()));
                }
            }
        }
    }
    assert!(
        missing.is_empty(),
        "{} non-vanishing products have no TERM_COUNTS entry for metric {metric:?}:\n{}",
        missing.len(),
        missing.join("\n")
    );
}

macro_rules! term_count_tests {
    (
        $alg:ident, $($path:ident)::+,
        dim = $dim:tt,
        metric = $metric:tt,
        types = [$($ty:ident),* $(,)?],
        $($rest:tt)*
    ) => {
        mod $alg {
            #[test]
            fn every_term_count_matches_a_brute_force_recount() {
                super::check_term_counts(&$metric, $($path)::+::TERM_COUNTS);
            }

            #[test]
            fn term_counts_list_every_non_vanishing_product_of_every_type_pair() {
                super::check_coverage(&$metric, &[$(stringify!($ty)),*], $($path)::+::TERM_COUNTS);
            }
        }
    };
}

ga_tests::for_each_algebra!(term_count_tests);
