// The bare pages' frame loop, as `cargo xtask bench-web` reads it:
// `window.baseline` counts the frames drawn and times the last one.
"use strict";
window.baseline = { ready: false, frames: 0, lastFrameMs: 0 };

/** Calls `draw` every animation frame and waits for `gl` to finish it, as
 *  the app's frame does before it ends. */
function runFrames(gl, draw) {
  const frame = () => {
    const start = performance.now();
    draw();
    gl.finish();
    window.baseline.lastFrameMs = performance.now() - start;
    window.baseline.frames += 1;
    requestAnimationFrame(frame);
  };
  window.baseline.ready = true;
  requestAnimationFrame(frame);
}
