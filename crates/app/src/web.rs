//! Browser start-up and the `window.edgewise` JavaScript API.
//!
//! The page (index.html) shows a loading message and an error box. This module
//! starts eframe in the page's canvas, reports panics and start-up failures in
//! that box, and defines `window.edgewise` once the app is running, so page
//! authors and browser tests can tell when it is ready.

use eframe::wasm_bindgen::{JsCast as _, JsValue, closure::Closure};

use crate::EdgewiseApp;

/// The id of the canvas in index.html.
const CANVAS_ID: &str = "edgewise_canvas";
/// The loading message shown by index.html until the app runs.
const LOADING_ID: &str = "edgewise_loading";
/// The box that shows start-up failures and panics.
const ERROR_ID: &str = "edgewise_error";

/// Starts the app in the page's canvas. Called from `main` on wasm32.
pub fn start() {
    install_panic_report();
    eframe::WebLogger::init(log::LevelFilter::Info).ok();

    wasm_bindgen_futures::spawn_local(async {
        if let Err(message) = start_app().await {
            log::error!("{message}");
            show_error(&message);
        }
    });
}

async fn start_app() -> Result<(), String> {
    let document = web_sys::window()
        .and_then(|w| w.document())
        .ok_or("Edgewise needs a browser window with a document.")?;
    let canvas = document
        .get_element_by_id(CANVAS_ID)
        .ok_or_else(|| format!("The page has no element with id '{CANVAS_ID}'."))?
        .dyn_into::<web_sys::HtmlCanvasElement>()
        .map_err(|_| format!("The element '{CANVAS_ID}' is not a canvas."))?;

    let web_options = eframe::WebOptions {
        depth_buffer: 24,
        ..Default::default()
    };
    let runner = eframe::WebRunner::new();
    runner
        .start(
            canvas,
            web_options,
            Box::new(|cc| Ok(Box::new(EdgewiseApp::new(cc)))),
        )
        .await
        .map_err(|err| {
            format!(
                "Edgewise needs WebGPU or WebGL2 for its 3D view, and this browser offers neither. \
                 Try a recent Chrome, Edge, Firefox or Safari, and check that hardware \
                 acceleration is turned on.\n\nDetails: {}",
                js_error_text(&err)
            )
        })?;

    if let Some(loading) = document.get_element_by_id(LOADING_ID) {
        loading.remove();
    }
    install_js_api(&runner).map_err(|err| {
        format!(
            "Edgewise could not define window.edgewise: {}",
            js_error_text(&err)
        )
    })
}

/// Defines `window.edgewise`: `version`, `backend` and `state()`.
fn install_js_api(runner: &eframe::WebRunner) -> Result<(), JsValue> {
    let window = web_sys::window().ok_or("no window")?;
    let api = js_sys::Object::new();

    let backend = with_app(runner, |app| app.backend().as_str())?;
    js_sys::Reflect::set(&api, &"version".into(), &edgewise_core::VERSION.into())?;
    js_sys::Reflect::set(&api, &"backend".into(), &backend.into())?;

    let state_runner = runner.clone();
    let state = Closure::<dyn Fn() -> Result<JsValue, JsValue>>::new(move || {
        let json = with_app(&state_runner, |app| serde_json::to_string(&app.state()))?
            .map_err(|err| JsValue::from_str(&err.to_string()))?;
        js_sys::JSON::parse(&json)
    });
    // The API lives as long as the page, so the closure is handed to JS for good.
    js_sys::Reflect::set(&api, &"state".into(), &state.into_js_value())?;

    js_sys::Reflect::set(&window, &"edgewise".into(), &api)?;
    Ok(())
}

/// Runs `f` on the app, or fails if the app has panicked or is busy drawing.
fn with_app<R>(
    runner: &eframe::WebRunner,
    f: impl FnOnce(&mut EdgewiseApp) -> R,
) -> Result<R, JsValue> {
    let mut app = runner.app_mut::<EdgewiseApp>().ok_or_else(|| {
        JsValue::from_str("Edgewise is not running (it has stopped after an internal error).")
    })?;
    Ok(f(&mut app))
}

/// Shows panics in the page's error box as well as in the console (eframe
/// logs them there), so a user never faces a frozen canvas without a reason.
fn install_panic_report() {
    let previous = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        show_error(&format!(
            "Edgewise stopped after an internal error. Please reload the page.\n\n{info}"
        ));
        previous(info);
    }));
}

/// Puts `message` in the page's error box and makes it visible.
fn show_error(message: &str) {
    let Some(document) = web_sys::window().and_then(|w| w.document()) else {
        return;
    };
    if let Some(loading) = document.get_element_by_id(LOADING_ID) {
        loading.remove();
    }
    if let Some(error) = document.get_element_by_id(ERROR_ID) {
        error.set_text_content(Some(message));
        error.set_attribute("data-visible", "true").ok();
    }
}

fn js_error_text(value: &JsValue) -> String {
    value
        .as_string()
        .or_else(|| {
            value
                .dyn_ref::<js_sys::Error>()
                .map(|err| String::from(err.message()))
        })
        .unwrap_or_else(|| format!("{value:?}"))
}
