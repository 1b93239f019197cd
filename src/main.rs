//! The `rolling-disk` binary: the command line of [`rolling_disk`].

fn main() -> std::process::ExitCode {
    rolling_disk::main()
}
