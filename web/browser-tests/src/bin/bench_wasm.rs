//! `cargo xtask bench-wasm`, in Chromium: opens the page the xtask serves
//! beside the wasm32 benchmark module, runs the module there and prints its
//! table, as node prints it.
//!
//! Environment (set by the xtask): `EDGEWISE_URL` (the page),
//! `EDGEWISE_CHROMIUM` and `EDGEWISE_CHROMEDRIVER`.

use std::time::Duration;

use anyhow::Context as _;
use edgewise_browser_tests::{Browser, LaunchOptions, Renderer};

/// Instantiates the module with the clock and the output it imports, runs
/// it, and returns what it printed.
const RUN: &str = "(async () => {
  const bytes = await (await fetch('edgewise_bench_wasm.wasm')).arrayBuffer();
  let memory;
  let text = '';
  const { instance } = await WebAssembly.instantiate(bytes, {
    bench: {
      now: () => performance.now(),
      print: (ptr, len) => {
        text += new TextDecoder().decode(new Uint8Array(memory.buffer, ptr, len));
      },
    },
  });
  memory = instance.exports.memory;
  instance.exports.run();
  return text;
})()";

#[tokio::main]
async fn main() -> anyhow::Result<()> {
    let browser = Browser::launch_with(LaunchOptions {
        renderer: Renderer::None,
        ..LaunchOptions::default()
    })
    .await?;
    // The 1M-triangle rounds take about a minute on these machines.
    browser.set_script_timeout(Duration::from_secs(600)).await?;
    browser.goto("").await?;
    let table = browser.eval_async(RUN).await?;
    let table = table
        .as_str()
        .context("the benchmark module printed no table")?;
    print!("{table}");
    browser.close().await
}
