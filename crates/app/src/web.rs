//! Browser start-up and the `window.edgewise` JavaScript API.
//!
//! The page (index.html) shows a loading message and an error box. This module
//! starts eframe in the page's canvas, reports panics and start-up failures in
//! that box, and defines `window.edgewise` once the app is running, so page
//! authors and browser tests can tell when it is ready.

use edgewise_core::schema::{ElementKind, ElementRef};
use eframe::wasm_bindgen::{JsCast as _, JsValue, closure::Closure};

use edgewise_core::{formats::MAX_FILE_BYTES, lang::MAX_SOURCE_BYTES, mesh::Structure};

/// The longest name, file name or option value the API takes.
const MAX_NAME_CHARS: usize = 256;

use crate::{
    Argument, EdgewiseApp, FetchedMesh,
    course_link::{CourseLink, MeshSource},
    files::{ANNOUNCE_BYTES, SaveFormat, SavedFile, opening_label},
    platform::js_error_text,
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
    // A large fetched file: say so, and let that paint before reading it.
    if let Some(FetchedMesh {
        name,
        bytes: Ok(bytes),
    }) = &fetched
        && bytes.len() > ANNOUNCE_BYTES
    {
        let label = opening_label(name, bytes.len());
        if with_app(runner, |app| app.set_busy(Some(label))).is_ok() {
            after_a_paint().await;
        }
    }
    let applied = with_app(runner, |app| {
        app.set_busy(None);
        app.apply_course_link(&link, messages, fetched)
    });
    if let Err(err) = applied {
        log::error!("the link could not be applied: {}", js_error_text(&err));
    }
}

/// Reads a same-site file, refusing one larger than the loaders accept
/// before its body is read: by its `Content-Length`, or, when the server
/// sends none, as soon as the bytes read pass the limit.
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
    let too_large = |size: String| {
        format!("the file is {size} bytes; Edgewise reads files of at most {MAX_FILE_BYTES} bytes")
    };
    let announced = response
        .headers()
        .get("content-length")
        .ok()
        .flatten()
        .and_then(|length| length.trim().parse::<u64>().ok());
    if let Some(length) = announced
        && length > MAX_FILE_BYTES as u64
    {
        return Err(too_large(length.to_string()));
    }
    let Some(body) = response.body() else {
        return Ok(Vec::new());
    };
    let reader = body
        .get_reader()
        .dyn_into::<web_sys::ReadableStreamDefaultReader>()
        .map_err(|_| "the response cannot be read".to_owned())?;
    let mut bytes = Vec::new();
    loop {
        let chunk = wasm_bindgen_futures::JsFuture::from(reader.read())
            .await
            .map_err(|err| format!("cannot read it: {}", js_error_text(&err)))?;
        let done = js_sys::Reflect::get(&chunk, &"done".into()).map_or(true, |d| d.is_truthy());
        if done {
            return Ok(bytes);
        }
        let value = js_sys::Reflect::get(&chunk, &"value".into()).unwrap_or(JsValue::UNDEFINED);
        let part = js_sys::Uint8Array::new(&value);
        if bytes.len() + part.length() as usize > MAX_FILE_BYTES {
            // Stops the download; its outcome no longer matters.
            let _cancelled = reader.cancel();
            return Err(too_large(format!("more than {MAX_FILE_BYTES}")));
        }
        bytes.extend(part.to_vec());
    }
}

/// Defines `window.edgewise`. Queries (`state`, `algorithms`, `shareUrl`)
/// return their value. Commands return a Promise that resolves when done
/// (to `null`, or to what the command gives) and rejects with an `Error`
/// whose message says what went wrong: a bad argument names the command, the
/// argument and what was expected, before anything is read or changed.
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
            let call = "loadMesh(text, options)";
            let checked = (|| {
                let text = text_argument(call, "text", &text, MAX_FILE_BYTES)?;
                check_options(call, &options, &["format", "structure"])?;
                let format = option_string(call, &options, "format")?;
                if let Some(format) = &format
                    && edgewise_core::formats::Format::from_name(&format!("x.{format}")).is_none()
                {
                    return Err(format!(
                        "{call}: options.format must be 'obj', 'ply', 'wtb' or 'htb', not '{}'",
                        shown(format)
                    ));
                }
                let structure = structure_option(call, &options)?;
                // Without a format the content decides (a pasted file has no name).
                let name = format.map_or_else(|| "pasted".to_owned(), |f| format!("pasted.{f}"));
                Ok((text, name, structure))
            })();
            let (text, name, structure) = match checked {
                Ok(checked) => checked,
                Err(message) => return settle(Err(message)),
            };
            if text.len() <= ANNOUNCE_BYTES {
                return settle(command(&r, |app| {
                    app.load_mesh(text.as_bytes(), &name, structure)
                }));
            }
            // A large text: show that it is being opened, and open it once
            // that has been painted, since reading it blocks the page.
            let label = opening_label("the text", text.len());
            if let Err(message) = command(&r, |app| {
                app.set_busy(Some(label));
                Ok(())
            }) {
                return settle(Err(message));
            }
            let r = r.clone();
            wasm_bindgen_futures::future_to_promise(async move {
                after_a_paint().await;
                command(&r, |app| {
                    app.set_busy(None);
                    app.load_mesh(text.as_bytes(), &name, structure)
                })
                .map(|()| JsValue::NULL)
                .map_err(|message| js_sys::Error::new(&message).into())
            })
        },
    );
    set_fn(&api, "loadMesh", &load_mesh.into_js_value())?;

    let r = runner.clone();
    let load_sample = Closure::<dyn Fn(JsValue, JsValue) -> js_sys::Promise>::new(
        move |name: JsValue, options: JsValue| {
            let call = "loadSample(name, options)";
            settle((|| {
                let name = text_argument(call, "name", &name, MAX_NAME_CHARS)?;
                check_options(call, &options, &["structure"])?;
                let structure = structure_option(call, &options)?;
                command(&r, |app| app.load_sample(&name, structure))
            })())
        },
    );
    set_fn(&api, "loadSample", &load_sample.into_js_value())?;

    let r = runner.clone();
    let select = Closure::<dyn Fn(JsValue, JsValue) -> js_sys::Promise>::new(
        move |kind: JsValue, id: JsValue| {
            let call = "select(kind, id)";
            settle((|| {
                let kind = kind
                    .as_string()
                    .and_then(|k| ElementKind::parse(&k))
                    .ok_or_else(|| expected(call, "kind", "'vertex', 'edge' or 'face'", &kind))?;
                let id = whole_number(call, "id", &id)?;
                let id = u32::try_from(id)
                    .map_err(|_| format!("{call}: id {id} is larger than any element id"))?;
                command(&r, |app| app.select(Some(ElementRef { kind, id })))
            })())
        },
    );
    set_fn(&api, "select", &select.into_js_value())?;

    let r = runner.clone();
    let clear = Closure::<dyn Fn() -> js_sys::Promise>::new(move || {
        settle(command(&r, |app| app.select(None)))
    });
    set_fn(&api, "clearSelection", &clear.into_js_value())?;

    let r = runner.clone();
    let set_structure = Closure::<dyn Fn(JsValue) -> js_sys::Promise>::new(move |name: JsValue| {
        settle((|| {
            let structure = name
                .as_string()
                .and_then(|n| Structure::parse_link_name(&n))
                .ok_or_else(|| {
                    expected("setStructure(name)", "name", "'winged' or 'half'", &name)
                })?;
            command(&r, |app| app.switch_structure(structure))
        })())
    });
    set_fn(&api, "setStructure", &set_structure.into_js_value())?;

    let r = runner.clone();
    let export_mesh = Closure::<dyn Fn(JsValue) -> js_sys::Promise>::new(move |format: JsValue| {
        let result = (|| {
            let format = format
                .as_string()
                .and_then(|f| SaveFormat::parse(&f))
                .ok_or_else(|| {
                    expected(
                        "exportMesh(format)",
                        "format",
                        "'wtb', 'htb', 'ply', 'ply-binary' or 'obj'",
                        &format,
                    )
                })?;
            let saved =
                with_app(&r, |app| app.export(format)).map_err(|err| js_error_text(&err))??;
            exported_object(&saved, format.is_binary()).map_err(|err| js_error_text(&err))
        })();
        settle_with(result)
    });
    set_fn(&api, "exportMesh", &export_mesh.into_js_value())?;

    let r = runner.clone();
    let choose = Closure::<dyn Fn(JsValue) -> js_sys::Promise>::new(move |name: JsValue| {
        settle((|| {
            let structure = if name.is_null() {
                None
            } else {
                Some(
                    name.as_string()
                        .and_then(|n| Structure::parse_link_name(&n))
                        .ok_or_else(|| {
                            expected(
                                "chooseStructure(name)",
                                "name",
                                "'winged', 'half' or null",
                                &name,
                            )
                        })?,
                )
            };
            command(&r, |app| app.answer_structure_dialog(structure))
        })())
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
            let call = "loadAlgorithms(source, file)";
            settle((|| {
                let source = text_argument(call, "source", &source, MAX_SOURCE_BYTES)?;
                let file = if file.is_undefined() {
                    "page.alg".to_owned()
                } else {
                    text_argument(call, "file", &file, MAX_NAME_CHARS)?
                };
                command(&r, |app| app.load_algorithms(&source, &file).map(|_| ()))
            })())
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
            let call = "run(name, args)";
            settle((|| {
                let name = text_argument(call, "name", &name, MAX_NAME_CHARS)?;
                let args = arguments(call, &args)?;
                command(&r, |app| app.run_algorithm(&name, &args))
            })())
        },
    );
    set_fn(api, "run", &run.into_js_value())?;

    type StepFn = fn(&mut EdgewiseApp, usize) -> Result<(), String>;
    // Name, call as messages show it, argument, function, default.
    let steppers: [(&str, &str, &str, StepFn, Option<u64>); 3] = [
        ("step", "step(n)", "n", EdgewiseApp::trace_step, Some(1)),
        ("back", "back(n)", "n", EdgewiseApp::trace_back, Some(1)),
        ("goto", "goto(k)", "k", EdgewiseApp::trace_goto, None),
    ];
    for (name, call, argument, f, default) in steppers {
        let r = runner.clone();
        let stepper = Closure::<dyn Fn(JsValue) -> js_sys::Promise>::new(move |n: JsValue| {
            settle((|| {
                let n = match default {
                    Some(default) if n.is_undefined() => default,
                    _ => whole_number(call, argument, &n)?,
                };
                let n = usize::try_from(n).unwrap_or(usize::MAX);
                command(&r, |app| f(app, n))
            })())
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
    let tab_commands: [(&str, &str, TabFn); 2] = [
        ("switchTab", "switchTab(index)", EdgewiseApp::switch_tab),
        ("closeTab", "closeTab(index)", EdgewiseApp::close_tab),
    ];
    for (name, call, f) in tab_commands {
        let r = runner.clone();
        let tab = Closure::<dyn Fn(JsValue) -> js_sys::Promise>::new(move |index: JsValue| {
            settle((|| {
                let index = whole_number(call, "index", &index)?;
                let index = usize::try_from(index).unwrap_or(usize::MAX);
                command(&r, |app| f(app, index))
            })())
        });
        set_fn(api, name, &tab.into_js_value())?;
    }

    let r = runner.clone();
    let share_url = Closure::<dyn Fn() -> Result<JsValue, JsValue>>::new(move || {
        let base = crate::platform::page_base();
        with_app(&r, |app| app.share_url(&base))?
            .map(|url| JsValue::from_str(&url))
            .map_err(|message| JsValue::from(js_sys::Error::new(&message)))
    });
    set_fn(api, "shareUrl", &share_url.into_js_value())?;

    let r = runner.clone();
    let side_by_side = Closure::<dyn Fn(JsValue) -> js_sys::Promise>::new(move |on: JsValue| {
        settle((|| {
            let on = on
                .as_bool()
                .ok_or_else(|| expected("setSideBySide(on)", "on", "true or false", &on))?;
            command(&r, |app| app.set_side_by_side(on))
        })())
    });
    set_fn(api, "setSideBySide", &side_by_side.into_js_value())
}

/// Resolves after the browser has had time to paint a frame (eframe paints
/// on the next animation frame after a repaint request).
async fn after_a_paint() {
    let promise = js_sys::Promise::new(&mut |resolve, _reject| {
        let timer = web_sys::window().map(|window| {
            window.set_timeout_with_callback_and_timeout_and_arguments_0(&resolve, 100)
        });
        // Without a timer the promise would never settle: go on at once.
        if !matches!(timer, Some(Ok(_))) {
            let _resolved = resolve.call0(&JsValue::NULL);
        }
    });
    let _painted = wasm_bindgen_futures::JsFuture::from(promise).await;
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
fn arguments(call: &str, args: &JsValue) -> Result<Vec<(String, Argument)>, String> {
    if args.is_undefined() || args.is_null() {
        return Ok(Vec::new());
    }
    // Not `dyn_ref`: an object made by the page around an iframe belongs to
    // another realm, and fails an `instanceof Object` check.
    if !args.is_object() || js_sys::Array::is_array(args) {
        return Err(expected(call, "args", "an object such as {v: 0}", args));
    }
    let object: &js_sys::Object = args.unchecked_ref();
    let mut out = Vec::new();
    for entry in js_sys::Object::entries(object).iter() {
        let pair = js_sys::Array::from(&entry);
        let key = pair.get(0).as_string().unwrap_or_default();
        let value = pair.get(1);
        let what = format!("args.{}", shown(&key));
        let argument = if let Some(b) = value.as_bool() {
            Argument::Boolean(b)
        } else if value.as_f64().is_some() {
            Argument::Number(whole_number(call, &what, &value)? as f64)
        } else {
            return Err(expected(
                call,
                &what,
                "a whole number (an id) or a boolean",
                &value,
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

/// A command's Promise: resolves to null on success, rejects with an Error.
fn settle(result: Result<(), String>) -> js_sys::Promise {
    settle_with(result.map(|()| JsValue::NULL))
}

/// A command's Promise: resolves to the value, or rejects with an Error.
fn settle_with(result: Result<JsValue, String>) -> js_sys::Promise {
    match result {
        Ok(value) => js_sys::Promise::resolve(&value),
        Err(message) => js_sys::Promise::reject(&js_sys::Error::new(&message)),
    }
}

/// "select(kind, id): id must be a whole number from 0, not 'abc'".
fn expected(call: &str, argument: &str, what: &str, value: &JsValue) -> String {
    format!(
        "{call}: {argument} must be {what}, not {}",
        described(value)
    )
}

/// A JavaScript value as a message shows it: short, and typed.
fn described(value: &JsValue) -> String {
    if value.is_undefined() {
        "undefined (it is missing)".to_owned()
    } else if value.is_null() {
        "null".to_owned()
    } else if let Some(text) = value.as_string() {
        format!("the string '{}'", shown(&text))
    } else if let Some(n) = value.as_f64() {
        format!("{n}")
    } else if let Some(b) = value.as_bool() {
        format!("{b}")
    } else if js_sys::Array::is_array(value) {
        "an array".to_owned()
    } else if value.is_function() {
        "a function".to_owned()
    } else {
        "an object".to_owned()
    }
}

/// User text quoted in a message: at most 40 characters, escaped.
fn shown(text: &str) -> String {
    edgewise_core::lang::diagnostic::shorten(text, 40)
        .chars()
        .flat_map(char::escape_debug)
        .collect()
}

/// A whole number from 0 that a JavaScript number holds exactly.
fn whole_number(call: &str, argument: &str, value: &JsValue) -> Result<u64, String> {
    const MAX_EXACT: f64 = 9_007_199_254_740_991.0; // Number.MAX_SAFE_INTEGER
    value
        .as_f64()
        .filter(|n| n.fract() == 0.0 && (0.0..=MAX_EXACT).contains(n))
        .map(|n| n as u64)
        .ok_or_else(|| expected(call, argument, "a whole number from 0", value))
}

/// A string argument, refused before it is copied out of JavaScript when it
/// holds more than `limit` UTF-16 units (a lower bound on its UTF-8 bytes).
fn text_argument(
    call: &str,
    argument: &str,
    value: &JsValue,
    limit: usize,
) -> Result<String, String> {
    let Some(text) = value.dyn_ref::<js_sys::JsString>() else {
        return Err(expected(call, argument, "a string", value));
    };
    let units = text.length() as usize;
    if units > limit {
        return Err(format!(
            "{call}: {argument} is {units} characters long; it may hold at most {limit}"
        ));
    }
    Ok(String::from(text))
}

/// Refuses an options object that is not an object or has unknown keys, so a
/// misspelled option is named instead of silently ignored.
fn check_options(call: &str, options: &JsValue, known: &[&str]) -> Result<(), String> {
    if options.is_undefined() || options.is_null() {
        return Ok(());
    }
    if !options.is_object() || js_sys::Array::is_array(options) {
        return Err(expected(call, "options", "an object", options));
    }
    let keys = js_sys::Object::keys(options.unchecked_ref::<js_sys::Object>());
    for key in keys.iter() {
        let key = key.as_string().unwrap_or_default();
        if !known.contains(&key.as_str()) {
            return Err(format!(
                "{call}: there is no option '{}'; the options are {}",
                shown(&key),
                known.join(" and ")
            ));
        }
    }
    Ok(())
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
fn option_string(call: &str, options: &JsValue, key: &str) -> Result<Option<String>, String> {
    if options.is_undefined() || options.is_null() {
        return Ok(None);
    }
    let value = js_sys::Reflect::get(options, &key.into()).unwrap_or(JsValue::UNDEFINED);
    if value.is_undefined() {
        return Ok(None);
    }
    text_argument(call, &format!("options.{key}"), &value, MAX_NAME_CHARS).map(Some)
}

fn structure_option(call: &str, options: &JsValue) -> Result<Option<Structure>, String> {
    option_string(call, options, "structure")?
        .map(|name| {
            Structure::parse_link_name(&name).ok_or_else(|| {
                format!(
                    "{call}: options.structure must be 'winged' or 'half', not '{}'",
                    shown(&name)
                )
            })
        })
        .transpose()
}

impl EdgewiseApp {
    /// Shows (or, with `None`, hides) what is being opened outside the
    /// file inbox: a large text given to `loadMesh`, a large linked file.
    fn set_busy(&mut self, label: Option<String>) {
        self.files.busy = label;
        self.request_repaint();
    }
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
