// What the bare pages share: a canvas filling the window, and the frame
// loop as `cargo xtask bench-web` reads it (`window.baseline` counts the
// frames drawn and times the last one).
"use strict";
window.baseline = { ready: false, frames: 0, lastFrameMs: 0 };

/** A canvas filling the window, in device pixels, and its WebGL2 context
 *  made with `options`. */
function windowCanvas(options) {
  document.documentElement.style.cssText = "height: 100%; overflow: hidden";
  document.body.style.cssText = "margin: 0; height: 100%; overflow: hidden";
  const canvas = document.createElement("canvas");
  canvas.style.cssText = "width: 100%; height: 100%; display: block";
  document.body.append(canvas);
  canvas.width = canvas.clientWidth * devicePixelRatio;
  canvas.height = canvas.clientHeight * devicePixelRatio;
  return { canvas, gl: canvas.getContext("webgl2", options) };
}

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
