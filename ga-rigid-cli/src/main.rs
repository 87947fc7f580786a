//! The `ga-rigid` command line; see [`ga_rigid_cli`].

fn main() -> std::process::ExitCode {
    ga_rigid_cli::main()
}
