//! Browser start-up and the `window.edgewise` JavaScript API.
//!
//! The page (index.html) shows a loading message and an error box. This module
//! starts eframe in the page's canvas, reports panics and start-up failures in
//! that box, and defines `window.edgewise` once the app is running, so page
//! authors and browser tests can tell when it is ready.

use eframe::wasm_bindgen::{JsCast as _, JsValue, closure::Closure};

use edgewise_core::mesh::Structure;

use crate::{
    Argument, EdgewiseApp, FetchedMesh,
    course_link::{CourseLink, MeshSource},
    files::{SaveFormat, SavedFile},
    selection::{ElementKind, ElementRef},
};

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
    })?;
    follow_page_link(&runner).await;
    Ok(())
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
        return;
    }
    let (link, messages) = CourseLink::parse(&search, &hash);
    let fetched = match &link.mesh {
        Some(MeshSource::Path(path)) => Some(FetchedMesh {
            name: path.rsplit('/').next().unwrap_or(path).to_owned(),
            bytes: fetch_bytes(path).await,
        }),
        _ => None,
    };
    let applied = with_app(runner, |app| {
        app.apply_course_link(&link, messages, fetched)
    });
    if let Err(err) = applied {
        log::error!("the link could not be applied: {}", js_error_text(&err));
    }
}

/// Reads a same-site file, within the size the loaders accept.
async fn fetch_bytes(path: &str) -> Result<Vec<u8>, String> {
    let window = web_sys::window().ok_or("no window")?;
    let response = wasm_bindgen_futures::JsFuture::from(window.fetch_with_str(path))
        .await
        .map_err(|err| format!("cannot fetch it: {}", js_error_text(&err)))?
        .dyn_into::<web_sys::Response>()
        .map_err(|_| "the fetch gave no response".to_owned())?;
    if !response.ok() {
        return Err(format!(
            "the server answered {} {}",
            response.status(),
            response.status_text()
        ));
    }
    let buffer = wasm_bindgen_futures::JsFuture::from(
        response.array_buffer().map_err(|err| js_error_text(&err))?,
    )
    .await
    .map_err(|err| js_error_text(&err))?;
    let bytes = js_sys::Uint8Array::new(&buffer).to_vec();
    if bytes.len() > edgewise_core::formats::MAX_FILE_BYTES {
        return Err(format!(
            "the file is {} bytes; Edgewise reads files of at most {} bytes",
            bytes.len(),
            edgewise_core::formats::MAX_FILE_BYTES
        ));
    }
    Ok(bytes)
}

/// Defines `window.edgewise`. Commands return a Promise that resolves to
/// null on success or to the error message, as the API documents.
fn install_js_api(runner: &eframe::WebRunner) -> Result<(), JsValue> {
    let window = web_sys::window().ok_or("no window")?;
    let api = js_sys::Object::new();

    let backend = with_app(runner, |app| app.backend().as_str())?;
    js_sys::Reflect::set(&api, &"version".into(), &edgewise_core::VERSION.into())?;
    js_sys::Reflect::set(&api, &"backend".into(), &backend.into())?;

    let r = runner.clone();
    let state = Closure::<dyn Fn() -> Result<JsValue, JsValue>>::new(move || {
        let json = with_app(&r, |app| serde_json::to_string(&app.state()))?
            .map_err(|err| JsValue::from_str(&err.to_string()))?;
        js_sys::JSON::parse(&json)
    });
    set_fn(&api, "state", &state.into_js_value())?;

    let r = runner.clone();
    let load_mesh = Closure::<dyn Fn(JsValue, JsValue) -> js_sys::Promise>::new(
        move |text: JsValue, options: JsValue| {
            let result = (|| {
                let text = text
                    .as_string()
                    .ok_or("loadMesh(text, options): text must be a string")?;
                let format = option_string(&options, "format")?;
                let structure = structure_option(&options)?;
                // Without a format the content decides (a pasted file has no name).
                let name = format.map_or_else(|| "pasted".to_owned(), |f| format!("pasted.{f}"));
                with_app(&r, |app| {
                    let result = app.load_mesh(text.as_bytes(), &name, structure);
                    app.request_repaint();
                    result
                })
                .map_err(|err| js_error_text(&err))?
            })();
            settle(result)
        },
    );
    set_fn(&api, "loadMesh", &load_mesh.into_js_value())?;

    let r = runner.clone();
    let load_sample = Closure::<dyn Fn(JsValue, JsValue) -> js_sys::Promise>::new(
        move |name: JsValue, options: JsValue| {
            let result = (|| {
                let name = name
                    .as_string()
                    .ok_or("loadSample(name, options): name must be a string")?;
                let structure = structure_option(&options)?;
                with_app(&r, |app| {
                    let result = app.load_sample(&name, structure);
                    app.request_repaint();
                    result
                })
                .map_err(|err| js_error_text(&err))?
            })();
            settle(result)
        },
    );
    set_fn(&api, "loadSample", &load_sample.into_js_value())?;

    let r = runner.clone();
    let select = Closure::<dyn Fn(JsValue, JsValue) -> js_sys::Promise>::new(
        move |kind: JsValue, id: JsValue| {
            let result = (|| {
                let kind = kind
                    .as_string()
                    .and_then(|k| ElementKind::parse(&k))
                    .ok_or("select(kind, id): kind must be 'vertex', 'edge' or 'face'")?;
                let id = id
                    .as_f64()
                    .filter(|id| id.fract() == 0.0 && *id >= 0.0 && *id <= f64::from(u32::MAX))
                    .ok_or("select(kind, id): id must be a whole number from 0")?
                    as u32;
                with_app(&r, |app| {
                    let result = app.select(Some(ElementRef { kind, id }));
                    app.request_repaint();
                    result
                })
                .map_err(|err| js_error_text(&err))?
            })();
            settle(result)
        },
    );
    set_fn(&api, "select", &select.into_js_value())?;

    let r = runner.clone();
    let clear = Closure::<dyn Fn() -> js_sys::Promise>::new(move || {
        let result = with_app(&r, |app| {
            let result = app.select(None);
            app.request_repaint();
            result
        })
        .map_err(|err| js_error_text(&err))
        .and_then(|r| r);
        settle(result)
    });
    set_fn(&api, "clearSelection", &clear.into_js_value())?;

    let r = runner.clone();
    let set_structure = Closure::<dyn Fn(JsValue) -> js_sys::Promise>::new(move |name: JsValue| {
        let result = (|| {
            let structure = name
                .as_string()
                .and_then(|n| crate::parse_structure(&n))
                .ok_or("setStructure(name): name must be 'winged' or 'half'")?;
            with_app(&r, |app| {
                let result = app.switch_structure(structure);
                app.request_repaint();
                result
            })
            .map_err(|err| js_error_text(&err))?
        })();
        settle(result)
    });
    set_fn(&api, "setStructure", &set_structure.into_js_value())?;

    let r = runner.clone();
    let export_mesh = Closure::<dyn Fn(JsValue) -> js_sys::Promise>::new(move |format: JsValue| {
        let result = (|| {
            let format = format
                .as_string()
                .and_then(|f| SaveFormat::parse(&f))
                .ok_or(
                    "exportMesh(format): format must be 'wtb', 'htb', 'ply', 'ply-binary' or 'obj'",
                )?;
            let saved =
                with_app(&r, |app| app.export(format)).map_err(|err| js_error_text(&err))??;
            exported_object(&saved, format.is_binary()).map_err(|err| js_error_text(&err))
        })();
        match result {
            Ok(object) => js_sys::Promise::resolve(&object),
            Err(message) => js_sys::Promise::reject(&js_sys::Error::new(&message)),
        }
    });
    set_fn(&api, "exportMesh", &export_mesh.into_js_value())?;

    let r = runner.clone();
    let choose = Closure::<dyn Fn(JsValue) -> js_sys::Promise>::new(move |name: JsValue| {
        let result = (|| {
            let structure = if name.is_null() || name.is_undefined() {
                None
            } else {
                Some(
                    name.as_string()
                        .and_then(|n| crate::parse_structure(&n))
                        .ok_or("chooseStructure(name): name must be 'winged', 'half' or null")?,
                )
            };
            with_app(&r, |app| {
                let result = app.answer_structure_dialog(structure);
                app.request_repaint();
                result
            })
            .map_err(|err| js_error_text(&err))?
        })();
        settle(result)
    });
    set_fn(&api, "chooseStructure", &choose.into_js_value())?;

    install_algorithm_api(runner, &api)?;
    install_view_api(runner, &api)?;

    js_sys::Reflect::set(&window, &"edgewise".into(), &api)?;
    Ok(())
}

/// The algorithm half of the API: loadAlgorithms, algorithms, run, step,
/// back, goto and abort.
fn install_algorithm_api(runner: &eframe::WebRunner, api: &js_sys::Object) -> Result<(), JsValue> {
    let r = runner.clone();
    let load = Closure::<dyn Fn(JsValue, JsValue) -> js_sys::Promise>::new(
        move |source: JsValue, file: JsValue| {
            let result = (|| {
                let source = source
                    .as_string()
                    .ok_or("loadAlgorithms(source): source must be a string")?;
                let file = file.as_string().unwrap_or_else(|| "page.alg".to_owned());
                command(&r, |app| app.load_algorithms(&source, &file).map(|_| ()))
            })();
            settle(result)
        },
    );
    set_fn(api, "loadAlgorithms", &load.into_js_value())?;

    let r = runner.clone();
    let list = Closure::<dyn Fn() -> Result<JsValue, JsValue>>::new(move || {
        let json = with_app(&r, |app| serde_json::to_string(&app.algorithm_list()))?
            .map_err(|err| JsValue::from_str(&err.to_string()))?;
        js_sys::JSON::parse(&json)
    });
    set_fn(api, "algorithms", &list.into_js_value())?;

    let r = runner.clone();
    let run = Closure::<dyn Fn(JsValue, JsValue) -> js_sys::Promise>::new(
        move |name: JsValue, args: JsValue| {
            let result = (|| {
                let name = name
                    .as_string()
                    .ok_or("run(name, args): name must be a string")?;
                let args = arguments(&args)?;
                command(&r, |app| app.run_algorithm(&name, &args))
            })();
            settle(result)
        },
    );
    set_fn(api, "run", &run.into_js_value())?;

    type StepFn = fn(&mut EdgewiseApp, usize) -> Result<(), String>;
    let steppers: [(&str, StepFn, f64); 3] = [
        ("step", EdgewiseApp::trace_step, 1.0),
        ("back", EdgewiseApp::trace_back, 1.0),
        ("goto", EdgewiseApp::trace_goto, f64::NAN),
    ];
    for (name, f, default) in steppers {
        let r = runner.clone();
        let stepper = Closure::<dyn Fn(JsValue) -> js_sys::Promise>::new(move |n: JsValue| {
            let result = (|| {
                let n = if n.is_undefined() || n.is_null() {
                    default
                } else {
                    n.as_f64().unwrap_or(f64::NAN)
                };
                if !(n.is_finite() && n.fract() == 0.0 && n >= 0.0) {
                    return Err(format!("{name}(n): n must be a whole number from 0"));
                }
                command(&r, |app| f(app, n as usize))
            })();
            settle(result)
        });
        set_fn(api, name, &stepper.into_js_value())?;
    }

    let r = runner.clone();
    let abort = Closure::<dyn Fn() -> js_sys::Promise>::new(move || {
        settle(command(&r, EdgewiseApp::abort_algorithm))
    });
    set_fn(api, "abort", &abort.into_js_value())
}

/// Tabs and the side-by-side view: newTab, switchTab, closeTab, setSideBySide.
fn install_view_api(runner: &eframe::WebRunner, api: &js_sys::Object) -> Result<(), JsValue> {
    let r = runner.clone();
    let new_tab = Closure::<dyn Fn() -> js_sys::Promise>::new(move || {
        settle(command(&r, |app| {
            app.new_tab();
            Ok(())
        }))
    });
    set_fn(api, "newTab", &new_tab.into_js_value())?;

    type TabFn = fn(&mut EdgewiseApp, usize) -> Result<(), String>;
    let tab_commands: [(&str, TabFn); 2] = [
        ("switchTab", EdgewiseApp::switch_tab),
        ("closeTab", EdgewiseApp::close_tab),
    ];
    for (name, f) in tab_commands {
        let r = runner.clone();
        let tab = Closure::<dyn Fn(JsValue) -> js_sys::Promise>::new(move |index: JsValue| {
            let result = match index.as_f64() {
                Some(i) if i.fract() == 0.0 && i >= 0.0 => command(&r, |app| f(app, i as usize)),
                _ => Err(format!(
                    "{name}(index): index must be a whole number from 0"
                )),
            };
            settle(result)
        });
        set_fn(api, name, &tab.into_js_value())?;
    }

    let r = runner.clone();
    let share_url = Closure::<dyn Fn() -> Result<JsValue, JsValue>>::new(move || {
        let base = crate::app::course::page_base();
        with_app(&r, |app| app.share_url(&base))?
            .map(|url| JsValue::from_str(&url))
            .map_err(|message| JsValue::from(js_sys::Error::new(&message)))
    });
    set_fn(api, "shareUrl", &share_url.into_js_value())?;

    let r = runner.clone();
    let side_by_side = Closure::<dyn Fn(JsValue) -> js_sys::Promise>::new(move |on: JsValue| {
        let on = on.as_bool().unwrap_or(true);
        settle(command(&r, |app| app.set_side_by_side(on)))
    });
    set_fn(api, "setSideBySide", &side_by_side.into_js_value())
}

/// Runs a command on the app and asks for a frame to show its effect.
fn command(
    runner: &eframe::WebRunner,
    f: impl FnOnce(&mut EdgewiseApp) -> Result<(), String>,
) -> Result<(), String> {
    with_app(runner, |app| {
        let result = f(app);
        app.request_repaint();
        result
    })
    .map_err(|err| js_error_text(&err))?
}

/// `run`'s arguments object: parameter names to ids, integers or booleans.
fn arguments(args: &JsValue) -> Result<Vec<(String, Argument)>, String> {
    if args.is_undefined() || args.is_null() {
        return Ok(Vec::new());
    }
    // Not `dyn_ref`: an object made by the page around an iframe belongs to
    // another realm, and fails an `instanceof Object` check.
    if !args.is_object() {
        return Err("run(name, args): args must be an object such as {v: 0}".to_owned());
    }
    let object: &js_sys::Object = args.unchecked_ref();
    let mut out = Vec::new();
    for entry in js_sys::Object::entries(object).iter() {
        let pair = js_sys::Array::from(&entry);
        let key = pair.get(0).as_string().unwrap_or_default();
        let value = pair.get(1);
        let argument = if let Some(b) = value.as_bool() {
            Argument::Boolean(b)
        } else if let Some(n) = value.as_f64() {
            Argument::Number(n)
        } else {
            return Err(format!(
                "run(name, args): args.{key} must be a number (an id) or a boolean"
            ));
        };
        out.push((key, argument));
    }
    Ok(out)
}

/// Puts a function on the API object. The API lives as long as the page, so
/// closures are handed to JavaScript for good.
fn set_fn(api: &js_sys::Object, name: &str, function: &JsValue) -> Result<(), JsValue> {
    js_sys::Reflect::set(api, &name.into(), function).map(|_| ())
}

/// A Promise that resolves to null on success or to the error message.
fn settle(result: Result<(), String>) -> js_sys::Promise {
    js_sys::Promise::resolve(&match result {
        Ok(()) => JsValue::NULL,
        Err(message) => JsValue::from_str(&message),
    })
}

/// `exportMesh`'s answer: `{name, text}`, or `{name, base64}` for binary output.
fn exported_object(saved: &SavedFile, binary: bool) -> Result<JsValue, JsValue> {
    let object = js_sys::Object::new();
    js_sys::Reflect::set(&object, &"name".into(), &saved.name.as_str().into())?;
    let (key, value) = if binary {
        ("base64", base64(&saved.bytes))
    } else {
        ("text", String::from_utf8_lossy(&saved.bytes).into_owned())
    };
    js_sys::Reflect::set(&object, &key.into(), &value.into())?;
    Ok(object.into())
}

/// Standard base64 with padding, so binary files cross the JSON boundary.
fn base64(bytes: &[u8]) -> String {
    const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let b = [
            chunk[0],
            chunk.get(1).copied().unwrap_or(0),
            chunk.get(2).copied().unwrap_or(0),
        ];
        let n = u32::from(b[0]) << 16 | u32::from(b[1]) << 8 | u32::from(b[2]);
        for i in 0..4 {
            if i <= chunk.len() {
                out.push(char::from(ALPHABET[(n >> (18 - 6 * i)) as usize & 63]));
            } else {
                out.push('=');
            }
        }
    }
    out
}

/// `options[key]` as a string, if present.
fn option_string(options: &JsValue, key: &str) -> Result<Option<String>, String> {
    if options.is_undefined() || options.is_null() {
        return Ok(None);
    }
    let value = js_sys::Reflect::get(options, &key.into()).unwrap_or(JsValue::UNDEFINED);
    if value.is_undefined() || value.is_null() {
        return Ok(None);
    }
    value
        .as_string()
        .map(Some)
        .ok_or_else(|| format!("option '{key}' must be a string"))
}

fn structure_option(options: &JsValue) -> Result<Option<Structure>, String> {
    option_string(options, "structure")?
        .map(|name| {
            crate::parse_structure(&name)
                .ok_or_else(|| format!("structure must be 'winged' or 'half', not '{name}'"))
        })
        .transpose()
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

pub(crate) fn js_error_text(value: &JsValue) -> String {
    value
        .as_string()
        .or_else(|| {
            value
                .dyn_ref::<js_sys::Error>()
                .map(|err| String::from(err.message()))
        })
        .unwrap_or_else(|| format!("{value:?}"))
}
