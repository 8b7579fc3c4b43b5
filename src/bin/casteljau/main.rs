//! The `casteljau` binary: parses the command line and exits with its code.

mod answers;
mod cli;
mod commands;

fn main() {
    std::process::exit(cli::main());
}
