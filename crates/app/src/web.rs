//! Browser start-up and the `window.edgewise` JavaScript API.
//!
//! The page (index.html) shows a loading message and an error box. This module
//! starts eframe in the page's canvas, reports panics and start-up failures in
//! that box, and defines `window.edgewise` once the app is running, so page
//! authors and browser tests can tell when it is ready.

mod api;
mod arguments;
mod recording;

use eframe::wasm_bindgen::{JsCast as _, JsValue};

use crate::{
    EdgewiseApp,
    files::{ANNOUNCE_BYTES, opening_label},
    platform::{CANVAS_ID, js_error_text},
};
use edgewise_model::course_link::{CourseLink, FetchedMesh, MeshSource};

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

    let web_options = web_options(&canvas).await;
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
    api::install(&runner).map_err(|err| {
        format!(
            "Edgewise could not define window.edgewise: {}",
            js_error_text(&err)
        )
    })?;
    follow_page_link(&runner).await;
    let backend = with_app(&runner, |app| app.state().backend).unwrap_or("webgl2");
    crate::platform::deliver_events(&mut vec![crate::EmbedEvent::Ready {
        version: edgewise_core::VERSION,
        backend,
    }]);
    Ok(())
}

/// eframe's options: WebGPU where the browser offers an adapter, and
/// otherwise WebGL2 in an opaque canvas.
async fn web_options(canvas: &web_sys::HtmlCanvasElement) -> eframe::WebOptions {
    let mut options = eframe::WebOptions {
        depth_buffer: 24,
        ..Default::default()
    };
    if !wgpu::util::is_browser_webgpu_supported().await {
        opaque_webgl2_context(canvas);
        // No second request for a WebGPU adapter the browser lacks.
        if let eframe::egui_wgpu::WgpuSetup::CreateNew(create_new) =
            &mut options.wgpu_options.wgpu_setup
        {
            create_new.instance_descriptor.backends = wgpu::Backends::GL;
        }
    }
    options
}

/// Makes the canvas's WebGL2 context without an alpha channel (or a depth
/// buffer: wgpu draws into textures of its own). A canvas keeps the first
/// context made for it, so this is the one wgpu then gets; wgpu's own
/// request has an alpha channel, and a browser compositing in software then
/// blends the whole canvas over the page each frame, about 2 ms of a frame
/// at 1280×800 under `SwiftShader`. Where this fails, wgpu's request reports
/// why.
fn opaque_webgl2_context(canvas: &web_sys::HtmlCanvasElement) {
    let attributes = js_sys::Object::new();
    for (name, value) in [("alpha", false), ("antialias", false), ("depth", false)] {
        let _set = js_sys::Reflect::set(&attributes, &name.into(), &value.into());
    }
    let _context = canvas.get_context_with_context_options("webgl2", &attributes);
}

/// Applies the course link in the page's address (`?sample=…#mesh=…`),
/// fetching a `?mesh=` file first. A broken link is reported in the app's
/// error panel; the app still starts.
async fn follow_page_link(runner: &eframe::WebRunner) {
    let Some(location) = web_sys::window().map(|w| w.location()) else {
        return;
    };
    let search = location.search().unwrap_or_default();
    let hash = location.hash().unwrap_or_default();
    if search.is_empty() && hash.is_empty() {
        if let Err(err) = with_app(runner, EdgewiseApp::first_visit) {
            log::error!("the first view could not open: {}", js_error_text(&err));
        }
        return;
    }
    let (link, messages) = CourseLink::parse(&search, &hash);
    let fetched = match &link.mesh {
        Some(MeshSource::Path(path)) => Some(FetchedMesh {
            name: path.rsplit('/').next().unwrap_or(path).to_owned(),
            bytes: crate::platform::fetch_bytes(path).await,
        }),
        _ => None,
    };
    // A large fetched file: say so, and let that paint before reading it.
    if let Some(FetchedMesh {
        name,
        bytes: Ok(bytes),
    }) = &fetched
        && bytes.len() > ANNOUNCE_BYTES
    {
        let label = opening_label(name, bytes.len());
        if with_app(runner, |app| set_busy(app, Some(label))).is_ok() {
            after_a_paint().await;
        }
    }
    let applied = with_app(runner, |app| {
        set_busy(app, None);
        app.apply_course_link(&link, messages, fetched)
    });
    if let Err(err) = applied {
        log::error!("the link could not be applied: {}", js_error_text(&err));
    }
}

/// Resolves after the browser has had time to paint a frame (eframe paints
/// on the next animation frame after a repaint request).
async fn after_a_paint() {
    after_ms(100).await;
}

/// Resolves after `ms` milliseconds (at once where there is no timer).
async fn after_ms(ms: i32) {
    let promise = js_sys::Promise::new(&mut |resolve, _reject| {
        let timer = web_sys::window().map(|window| {
            window.set_timeout_with_callback_and_timeout_and_arguments_0(&resolve, ms)
        });
        // Without a timer the promise would never settle: go on at once.
        if !matches!(timer, Some(Ok(_))) {
            let _resolved = resolve.call0(&JsValue::NULL);
        }
    });
    let _painted = wasm_bindgen_futures::JsFuture::from(promise).await;
}

/// Shows (or, with `None`, hides) what is being opened outside the file
/// inbox: a large text given to `loadMesh`, a large linked file.
fn set_busy(app: &mut EdgewiseApp, label: Option<String>) {
    app.files.busy = label;
    app.request_repaint();
}

/// An exported file as the API answers it (`exportMesh`, `exportHandout`,
/// `recordRun`): `{name, text}`, or `{name, base64}` for binary output.
fn exported_object(saved: &crate::files::SavedFile, binary: bool) -> Result<JsValue, JsValue> {
    use base64::Engine as _;
    let object = js_sys::Object::new();
    js_sys::Reflect::set(&object, &"name".into(), &saved.name.as_str().into())?;
    let (key, value) = if binary {
        // Standard base64 with padding, so binary files cross the JSON
        // boundary.
        (
            "base64",
            base64::engine::general_purpose::STANDARD.encode(&saved.bytes),
        )
    } else {
        ("text", String::from_utf8_lossy(&saved.bytes).into_owned())
    };
    js_sys::Reflect::set(&object, &key.into(), &value.into())?;
    Ok(object.into())
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
