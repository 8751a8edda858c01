//! The `edgewise` command.

use clap::Parser;

/// Inspect, check, convert and trace winged-edge and half-edge meshes.
#[derive(Parser, Debug)]
#[command(name = "edgewise", version = edgewise_core::VERSION, about)]
struct Cli {}

fn main() {
    let _cli = Cli::parse();
}
