//! The macro's error messages: each case under `tests/ui/` makes one mistake and its
//! `.stderr` shows the single error it gets; the cases under `tests/ui-pass/` use the
//! derive form and a restricted module end to end. Regenerate the `.stderr` files with
//! `TRYBUILD=overwrite cargo test -p ga-ui-tests --test ui` and read the diff.

#[test]
fn each_mistake_gets_one_error_at_its_token_and_valid_inputs_compile() {
    // The `.stderr` files are rustc's own messages. A compiler wrapper for the workspace in
    // the environment is inherited by trybuild's cargo and changes them: clippy's driver, as
    // CI runs it for the workspace's test build, prints `std::vec::Vec<f64>` where rustc
    // prints `Vec<f64>`. (This test is the process's only one: nothing reads the
    // environment beside it.)
    for wrapper in ["RUSTC_WORKSPACE_WRAPPER", "CLIPPY_ARGS"] {
        std::env::remove_var(wrapper);
    }
    let cases = trybuild::TestCases::new();
    cases.compile_fail("tests/ui/**/*.rs");
    cases.pass("tests/ui-pass/*.rs");
}
