//! `recordRun(options)`: the running algorithm's run as a WebM video,
//! recorded by the browser's `MediaRecorder` from the app's canvas while the
//! trace steps from the start to the end, for a lecturer's slides or a
//! course page. The trace is left at the step it was on.

use eframe::wasm_bindgen::{JsCast as _, JsValue, closure::Closure};
use std::cell::RefCell;
use std::rc::Rc;

use super::arguments::{check_options, expected};
use super::{after_ms, with_app};
use crate::command::Command;
use crate::platform::CANVAS_ID;

const CALL: &str = "recordRun(options)";
/// Milliseconds each step is shown, unless `options.delay` says otherwise.
const DEFAULT_DELAY_MS: f64 = 600.0;
/// The range `options.delay` accepts.
const DELAY_RANGE_MS: (f64, f64) = (50.0, 5_000.0);
/// The most steps a recording shows (at the shortest delay, about 25 s).
pub const MAX_RECORDED_STEPS: usize = 500;

/// Reads the options, then records; the Promise resolves to
/// `{name, base64, type}`.
pub fn record_run(runner: &eframe::WebRunner, options: &JsValue) -> js_sys::Promise {
    let delay = match read_delay(options) {
        Ok(delay) => delay,
        Err(message) => return js_sys::Promise::reject(&js_sys::Error::new(&message)),
    };
    let runner = runner.clone();
    wasm_bindgen_futures::future_to_promise(async move {
        record(&runner, delay)
            .await
            .map_err(|message| js_sys::Error::new(&message).into())
    })
}

fn read_delay(options: &JsValue) -> Result<f64, String> {
    if options.is_undefined() || options.is_null() {
        return Ok(DEFAULT_DELAY_MS);
    }
    check_options(CALL, options, &["delay"])?;
    let value = js_sys::Reflect::get(options, &"delay".into()).unwrap_or(JsValue::UNDEFINED);
    if value.is_undefined() {
        return Ok(DEFAULT_DELAY_MS);
    }
    value
        .as_f64()
        .filter(|ms| (DELAY_RANGE_MS.0..=DELAY_RANGE_MS.1).contains(ms))
        .ok_or_else(|| {
            expected(
                CALL,
                "options.delay",
                "milliseconds from 50 to 5000",
                &value,
            )
        })
}

async fn record(runner: &eframe::WebRunner, delay: f64) -> Result<JsValue, String> {
    let error_text = |err: JsValue| crate::platform::js_error_text(&err);
    let (name, start_step, steps) = with_app(runner, |app| {
        let tab = app.tab();
        let session = tab.run.session()?;
        let mesh = tab.document.as_ref().map_or("mesh", |d| d.name.as_str());
        let name = format!(
            "{}-{}.webm",
            edgewise_model::document::mesh_stem(mesh),
            session.trace.algorithm().name
        );
        Some((name, session.step(), session.steps()))
    })
    .map_err(error_text)?
    .ok_or("run an algorithm first: a recording shows each step of its run")?;
    if steps + 1 > MAX_RECORDED_STEPS {
        return Err(format!(
            "the run has {steps} steps; a recording shows at most {MAX_RECORDED_STEPS}"
        ));
    }
    let canvas: web_sys::HtmlCanvasElement = web_sys::window()
        .and_then(|window| window.document())
        .and_then(|document| document.get_element_by_id(CANVAS_ID))
        .and_then(|element| element.dyn_into().ok())
        .ok_or("the app's canvas is missing")?;
    let stream = canvas.capture_stream().map_err(error_text)?;
    let options = web_sys::MediaRecorderOptions::new();
    options.set_mime_type("video/webm");
    let recorder =
        web_sys::MediaRecorder::new_with_media_stream_and_media_recorder_options(&stream, &options)
            .map_err(|err| format!("this browser cannot record WebM video: {}", error_text(err)))?;
    let chunks = Rc::new(RefCell::new(Vec::<JsValue>::new()));
    let on_data = {
        let chunks = Rc::clone(&chunks);
        Closure::<dyn FnMut(web_sys::BlobEvent)>::new(move |event: web_sys::BlobEvent| {
            if let Some(data) = event.data() {
                chunks.borrow_mut().push(data.into());
            }
        })
    };
    recorder.set_ondataavailable(Some(on_data.as_ref().unchecked_ref()));
    let stopped = js_sys::Promise::new(&mut |resolve, _reject| {
        recorder.set_onstop(Some(&resolve));
    });

    let step = |command: Command| {
        with_app(runner, |app| app.execute(command).map(drop))
            .map_err(error_text)?
            .map_err(String::from)
    };
    step(Command::Goto(0))?;
    after_ms(100).await;
    recorder.start().map_err(error_text)?;
    let ms = delay.round() as i32;
    after_ms(ms).await;
    for _ in 0..steps {
        step(Command::Step(1))?;
        after_ms(ms).await;
    }
    recorder.stop().map_err(error_text)?;
    wasm_bindgen_futures::JsFuture::from(stopped)
        .await
        .map_err(error_text)?;
    drop(on_data);
    step(Command::Goto(start_step))?;

    let parts = js_sys::Array::new();
    for chunk in chunks.borrow().iter() {
        parts.push(chunk);
    }
    let bag = web_sys::BlobPropertyBag::new();
    bag.set_type("video/webm");
    let blob =
        web_sys::Blob::new_with_blob_sequence_and_options(&parts, &bag).map_err(error_text)?;
    let buffer = wasm_bindgen_futures::JsFuture::from(blob.array_buffer())
        .await
        .map_err(error_text)?;
    let bytes = js_sys::Uint8Array::new(&buffer).to_vec();
    if bytes.is_empty() {
        return Err("the browser recorded no video; is the page hidden?".to_owned());
    }
    let object = super::exported_object(&crate::files::SavedFile { name, bytes }, true)
        .map_err(error_text)?;
    js_sys::Reflect::set(&object, &"type".into(), &"video/webm".into()).map_err(error_text)?;
    Ok(object)
}
