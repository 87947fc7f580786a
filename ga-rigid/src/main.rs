//! The `ga-rigid` command line; see [`ga_rigid::cli`].

fn main() -> std::process::ExitCode {
    ga_rigid::cli::main()
}
