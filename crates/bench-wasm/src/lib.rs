//! The builders against the floor as wasm32, the table `cargo bench -p
//! edgewise-core --bench mesh_build` prints natively, from the same code
//! (core's `benches/support/`). `cargo xtask bench-wasm` builds this with the
//! browser build's profile and runs it under node, which supplies the clock
//! and the output. Memory freed by one build is reused by the next, as in
//! the page, so the figures measure the work rather than page faults.
//!
//! Empty on other targets.
#![cfg(target_arch = "wasm32")]
#![allow(
    unsafe_code,
    reason = "the clock and the output are node's functions, imported raw \
              so that the module needs no bindings"
)]

#[path = "../../core/benches/support/floor.rs"]
mod floor;
#[path = "../../core/benches/support/ratios.rs"]
mod ratios;

#[link(wasm_import_module = "bench")]
unsafe extern "C" {
    /// Milliseconds, from `performance.now()`.
    fn now() -> f64;
    /// Writes `len` bytes of UTF-8 at `text` to standard output.
    fn print(text: *const u8, len: usize);
}

/// Measures and prints the table.
#[unsafe(no_mangle)]
pub extern "C" fn run() {
    // SAFETY: node's `now` takes nothing and returns a number.
    let rows = ratios::measure(&|| unsafe { now() });
    let table = ratios::table(&rows, "≤ 1.3×");
    // SAFETY: the bytes are valid for the call; node copies them out.
    unsafe { print(table.as_ptr(), table.len()) };
}
