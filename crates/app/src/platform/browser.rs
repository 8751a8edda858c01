//! The browser: files through a picker, drops and downloads, settings in
//! local storage, the Fullscreen API.
//!
//! Browsers read files asynchronously, so what is read goes into an inbox
//! that [`FileIo::receive`] empties on the app's next frame.

use std::{cell::RefCell, rc::Rc};

use eframe::wasm_bindgen::{JsCast as _, JsValue, closure::Closure};
use wasm_bindgen_futures::JsFuture;

use edgewise_core::formats::MAX_FILE_BYTES;

use super::{PendingFile, RunText};

/// The id of the canvas the app draws in (index.html).
pub const CANVAS_ID: &str = "edgewise_canvas";

/// The files the picker offers for meshes.
const MESH_FILES: &str = ".wtb,.htb,.ply,.obj";

/// Files read (or failed reads, as messages) waiting for the next frame.
type Inbox = Rc<RefCell<Vec<Result<PendingFile, String>>>>;

/// Opening and saving files in the browser.
#[derive(Default)]
pub struct FileIo {
    inbox: Inbox,
}

impl FileIo {
    /// Offers `bytes` as a download called `name`; returns what to tell the
    /// user.
    pub fn write(&mut self, name: &str, bytes: &[u8]) -> Result<String, String> {
        download(name, bytes).map(|()| format!("Downloaded {name}"))
    }

    /// Starts reading the file dropped this frame, if any, and returns the
    /// files that finished reading since the last frame.
    pub fn receive(&mut self, ctx: &egui::Context) -> Vec<Result<PendingFile, String>> {
        if let Some(file) = ctx.input(|i| i.raw.dropped_files.first().cloned()) {
            read_dropped(&self.inbox, ctx, file);
        }
        self.inbox.borrow_mut().drain(..).collect()
    }

    /// The Open mesh… button: the browser's file picker.
    pub fn open_ui(
        &mut self,
        ui: &mut egui::Ui,
        extensions: &str,
    ) -> Option<Result<PendingFile, String>> {
        let clicked = ui
            .button("Open mesh…")
            .on_hover_text(format!("Open a {extensions} file, or drop one on the page"))
            .clicked();
        match clicked.then(|| self.pick(ui.ctx(), MESH_FILES)) {
            Some(Err(message)) => Some(Err(message)),
            _ => None,
        }
    }

    /// Nothing to add under Save as…: downloads go where the browser puts them.
    pub fn save_note_ui(&self, _ui: &mut egui::Ui) {}

    /// Opens the browser's file picker offering `accept`; the chosen file
    /// arrives through [`Self::receive`], so there is nothing to tell the
    /// user (`Ok(None)`). Must run soon after a click: browsers only open
    /// pickers for a user's action.
    pub fn pick(&self, ctx: &egui::Context, accept: &str) -> Result<Option<&'static str>, String> {
        let document = web_sys::window()
            .and_then(|w| w.document())
            .ok_or("no document to open a file picker in")?;
        let input = document
            .create_element("input")
            .map_err(|err| js_error_text(&err))?
            .dyn_into::<web_sys::HtmlInputElement>()
            .map_err(|_| "the browser did not create a file input")?;
        input.set_type("file");
        input.set_accept(accept);
        let (inbox, ctx, target) = (self.inbox.clone(), ctx.clone(), input.clone());
        // Called once when a file is chosen; a cancelled picker leaves it unused.
        let on_change = Closure::once_into_js(move || {
            if let Some(file) = target.files().and_then(|files| files.get(0)) {
                read_file(inbox, ctx, file);
            }
        });
        input
            .add_event_listener_with_callback("change", on_change.unchecked_ref())
            .map_err(|err| js_error_text(&err))?;
        input.click();
        Ok(None)
    }
}

/// Reads a file from the picker into `inbox`, refusing huge files before
/// reading them into memory.
fn read_file(inbox: Inbox, ctx: egui::Context, file: web_sys::File) {
    wasm_bindgen_futures::spawn_local(async move {
        let name = file.name();
        let result = if file.size() > MAX_FILE_BYTES as f64 {
            Err(too_large(&name, file.size()))
        } else {
            JsFuture::from(file.array_buffer())
                .await
                .map(|buffer| PendingFile {
                    name: name.clone(),
                    bytes: js_sys::Uint8Array::new(&buffer).to_vec(),
                })
                .map_err(|err| format!("{name}: cannot read the file: {}", js_error_text(&err)))
        };
        inbox.borrow_mut().push(result);
        ctx.request_repaint();
    });
}

/// The message for a file refused by its size, before any of it is read.
fn too_large(name: &str, size: f64) -> String {
    format!(
        "{name}: the file is {size} bytes; Edgewise reads files of at most {MAX_FILE_BYTES} bytes"
    )
}

/// Reads a file dropped on the page (eframe hands it over unread) into
/// `inbox`, refusing huge files by their size before reading them.
fn read_dropped(inbox: &Inbox, ctx: &egui::Context, file: egui::DroppedFileHandle) {
    let (inbox, ctx) = (inbox.clone(), ctx.clone());
    wasm_bindgen_futures::spawn_local(async move {
        let name = file
            .path()
            .file_name()
            .map_or_else(String::new, |n| n.to_string_lossy().into_owned());
        let size = file.web_file().map_or(0.0, |file| file.size());
        let result = if size > MAX_FILE_BYTES as f64 {
            Err(too_large(&name, size))
        } else {
            file.bytes_async()
                .await
                .map(|bytes| PendingFile {
                    name: name.clone(),
                    bytes,
                })
                .map_err(|err| format!("{name}: cannot read the file: {err}"))
        };
        inbox.borrow_mut().push(result);
        ctx.request_repaint();
    });
}

/// Offers `bytes` as a download called `name`: a Blob behind a temporary
/// link that is clicked and removed, its URL revoked once the download began.
fn download(name: &str, bytes: &[u8]) -> Result<(), String> {
    let window = web_sys::window().ok_or("no window to download from")?;
    let document = window.document().ok_or("no document to download from")?;
    let body = document.body().ok_or("the page has no body")?;
    let parts = js_sys::Array::of1(&js_sys::Uint8Array::from(bytes));
    let options = web_sys::BlobPropertyBag::new();
    options.set_type("application/octet-stream");
    let blob = web_sys::Blob::new_with_u8_array_sequence_and_options(&parts, &options)
        .map_err(|err| js_error_text(&err))?;
    let url =
        web_sys::Url::create_object_url_with_blob(&blob).map_err(|err| js_error_text(&err))?;
    let anchor = document
        .create_element("a")
        .map_err(|err| js_error_text(&err))?
        .dyn_into::<web_sys::HtmlAnchorElement>()
        .map_err(|_| "the browser did not create a link")?;
    anchor.set_href(&url);
    anchor.set_download(name);
    anchor.set_hidden(true);
    body.append_child(&anchor)
        .map_err(|err| js_error_text(&err))?;
    anchor.click();
    anchor.remove();
    let revoke = Closure::once_into_js(move || {
        web_sys::Url::revoke_object_url(&url).ok();
    });
    window
        .set_timeout_with_callback_and_timeout_and_arguments_0(revoke.unchecked_ref(), 1000)
        .map_err(|err| js_error_text(&err))?;
    Ok(())
}

/// A JavaScript exception or value as text, for messages.
pub fn js_error_text(value: &JsValue) -> String {
    value
        .as_string()
        .or_else(|| {
            value
                .dyn_ref::<js_sys::Error>()
                .map(|err| String::from(err.message()))
        })
        .unwrap_or_else(|| format!("{value:?}"))
}

fn local_storage() -> Option<web_sys::Storage> {
    web_sys::window().and_then(|w| w.local_storage().ok().flatten())
}

/// The settings saved in this browser under `key`, if any.
pub fn load_settings(key: &str) -> Option<String> {
    local_storage().and_then(|storage| storage.get_item(key).ok().flatten())
}

/// Saves the settings in this browser; a full or disabled storage is
/// logged, not fatal.
pub fn store_settings(key: &str, json: &str) {
    match local_storage() {
        Some(storage) => {
            if storage.set_item(key, json).is_err() {
                log::warn!("the settings could not be saved in local storage");
            }
        }
        None => log::warn!("this browser offers no local storage; settings last this visit"),
    }
}

/// Enters or leaves fullscreen for a presentation.
pub fn set_fullscreen(_ctx: &egui::Context, on: bool) {
    let Some(document) = web_sys::window().and_then(|w| w.document()) else {
        return;
    };
    if on {
        if let Some(element) = document.document_element()
            && element.request_fullscreen().is_err()
        {
            log::warn!("the browser refused fullscreen; presenting in the window");
        }
    } else if document.fullscreen_element().is_some() {
        document.exit_fullscreen();
    }
}

/// Whether the page was fullscreen for a presentation and no longer is (the
/// browser handles Escape itself in fullscreen).
pub fn left_fullscreen() -> bool {
    use std::sync::atomic::{AtomicBool, Ordering};
    static WAS_FULLSCREEN: AtomicBool = AtomicBool::new(false);
    let now = web_sys::window()
        .and_then(|w| w.document())
        .is_some_and(|d| d.fullscreen_element().is_some());
    let was = WAS_FULLSCREEN.swap(now, Ordering::Relaxed);
    was && !now
}

/// Keeps the canvas's backing store at its CSS size times
/// `devicePixelRatio`, and says whether it had to be resized. eframe sizes
/// it from the resize observer's device-pixel box, which under Chromium's
/// device emulation (`DevTools`' device mode) is the real screen's and not
/// the emulated ratio's: the UI, laid out at the emulated ratio, would fill
/// a corner of the canvas. A difference of a pixel or two is rounding, and
/// the observer's size, exact on a real screen, is kept.
pub fn fit_canvas() -> bool {
    use wasm_bindgen::JsCast as _;
    let Some(window) = web_sys::window() else {
        return false;
    };
    let Some(canvas) = window
        .document()
        .and_then(|d| d.get_element_by_id(CANVAS_ID))
        .and_then(|e| e.dyn_into::<web_sys::HtmlCanvasElement>().ok())
    else {
        return false;
    };
    let ratio = window.device_pixel_ratio();
    let wanted = |css: i32| (f64::from(css) * ratio).round() as u32;
    let (width, height) = (
        wanted(canvas.client_width()),
        wanted(canvas.client_height()),
    );
    let off = |have: u32, want: u32| f64::from(have.abs_diff(want)) > ratio + 1.0;
    if width == 0 || height == 0 || !(off(canvas.width(), width) || off(canvas.height(), height)) {
        return false;
    }
    canvas.set_width(width);
    canvas.set_height(height);
    true
}

/// Whether the browser's main pointer is a finger (a phone, a tablet).
pub fn coarse_pointer() -> bool {
    web_sys::window()
        .and_then(|w| w.match_media("(pointer: coarse)").ok().flatten())
        .is_some_and(|query| query.matches())
}

/// The page's address without query or fragment.
pub fn page_base() -> String {
    web_sys::window()
        .and_then(|w| {
            let location = w.location();
            Some(format!(
                "{}{}",
                location.origin().ok()?,
                location.pathname().ok()?
            ))
        })
        .unwrap_or_default()
}

/// Dispatches each queued event on `window` as an `edgewise:<name>`
/// `CustomEvent` whose `detail` is the event's JSON; index.html forwards them
/// to an embedding page.
pub fn deliver_events(events: &mut Vec<crate::EmbedEvent>) {
    let Some(window) = web_sys::window() else {
        return;
    };
    for event in events.drain(..) {
        let Ok(json) = serde_json::to_string(&event) else {
            continue;
        };
        let Ok(detail) = js_sys::JSON::parse(&json) else {
            continue;
        };
        let init = web_sys::CustomEventInit::new();
        init.set_detail(&detail);
        let name = format!("edgewise:{}", event.name());
        match web_sys::CustomEvent::new_with_event_init_dict(&name, &init) {
            Ok(dom_event) => {
                if let Err(err) = window.dispatch_event(&dom_event) {
                    log::warn!("{name} was not delivered: {}", js_error_text(&err));
                }
            }
            Err(err) => log::warn!("{name} could not be made: {}", js_error_text(&err)),
        }
    }
}

/// The page has a copy of the app for screen readers (index.html).
pub const READER_COPY: bool = true;

/// Fills the page's copy for screen readers: the tables' HTML (built from
/// numbers and fixed names only) and the message, which an `aria-live`
/// region announces.
pub fn show_to_readers(tables: Option<&str>, message: Option<&str>) {
    let Some(document) = web_sys::window().and_then(|w| w.document()) else {
        return;
    };
    if let Some(element) = document.get_element_by_id("edgewise_a11y_tables") {
        element.set_inner_html(tables.unwrap_or("<p>No mesh is open.</p>"));
    }
    set_text_of(&document, "edgewise_a11y_live", message);
}

/// Changes the words of some role cells of the page's copy for screen
/// readers (by HTML id) and its
/// message.
pub fn change_for_readers(cells: &[(String, String)], message: Option<&str>) {
    let Some(document) = web_sys::window().and_then(|w| w.document()) else {
        return;
    };
    for (id, words) in cells {
        set_text_of(&document, id, Some(words));
    }
    set_text_of(&document, "edgewise_a11y_live", message);
}

/// Shows the run's place, current line and variables in the page's copy,
/// or hides its step controls when no run is open.
pub fn show_run_to_readers(run: Option<&RunText<'_>>) {
    let Some(document) = web_sys::window().and_then(|w| w.document()) else {
        return;
    };
    if let Some(controls) = document.get_element_by_id("edgewise_a11y_controls") {
        let result = match run {
            Some(_) => controls.remove_attribute("hidden"),
            None => controls.set_attribute("hidden", ""),
        };
        if let Err(err) = result {
            log::warn!("the readers' step controls: {}", js_error_text(&err));
        }
    }
    set_text_of(&document, "edgewise_a11y_status", run.map(|r| r.status));
    set_text_of(&document, "edgewise_a11y_line", run.map(|r| r.line));
    if let Some(element) = document.get_element_by_id("edgewise_a11y_variables") {
        element.set_inner_html(run.map_or("", |r| r.variables_html));
    }
}

/// Fills the page's algorithm list (forms whose every text is escaped).
pub fn show_algorithms_to_readers(html: &str) {
    if let Some(element) = web_sys::window()
        .and_then(|w| w.document())
        .and_then(|d| d.get_element_by_id("edgewise_a11y_algorithms"))
    {
        element.set_inner_html(html);
    }
}

/// Sets the text of the page's element `id`, where the page has one.
fn set_text_of(document: &web_sys::Document, id: &str, text: Option<&str>) {
    if let Some(element) = document.get_element_by_id(id) {
        element.set_text_content(text);
    }
}

/// The SCORM package's zip, built from the release files this page was
/// loaded from (its `index.html`, JS, wasm and icon), so a lecturer needs
/// nothing but the browser.
pub async fn package_zip(package: &edgewise_model::package::Package) -> Result<Vec<u8>, String> {
    use edgewise_model::package::AppFiles;
    let index = fetch_bytes("index.html")
        .await
        .map_err(|err| format!("index.html: {err}"))?;
    let build = AppFiles::build_of(&String::from_utf8_lossy(&index))
        .ok_or("this page is not a release build (`cargo xtask build-web` makes one)")?
        .to_owned();
    let mut fetched = vec![("index.html".to_owned(), index)];
    for name in AppFiles::names(&build).into_iter().skip(1) {
        let bytes = fetch_bytes(&name)
            .await
            .map_err(|err| format!("{name}: {err}"))?;
        fetched.push((name, bytes));
    }
    let app = AppFiles::read(|name| {
        fetched
            .iter()
            .position(|(n, _)| n == name)
            .map(|at| fetched.swap_remove(at).1)
            .ok_or_else(|| "not fetched".to_owned())
    })
    .map_err(|err| err.to_string())?;
    package.zip(&app).map_err(|err| err.to_string())
}

/// Builds `package` (see [`package_zip`]) and downloads it as `name`;
/// `status` then holds what to tell the user.
pub fn download_package(
    package: edgewise_model::package::Package,
    name: String,
    status: Rc<RefCell<Option<String>>>,
    ctx: egui::Context,
) {
    wasm_bindgen_futures::spawn_local(async move {
        let said = match package_zip(&package).await {
            Ok(bytes) => download(&name, &bytes).map(|()| {
                format!(
                    "Downloaded {name} ({:.1} MB): upload it to your LMS as a SCORM package.",
                    bytes.len() as f64 / 1e6
                )
            }),
            Err(err) => Err(err),
        };
        *status.borrow_mut() =
            Some(said.unwrap_or_else(|err| format!("The package could not be made: {err}")));
        ctx.request_repaint();
    });
}

/// Reads a same-site file, refusing one larger than the loaders accept
/// before its body is read: by its `Content-Length`, or, when the server
/// sends none, as soon as the bytes read pass the limit.
pub async fn fetch_bytes(path: &str) -> Result<Vec<u8>, String> {
    let window = web_sys::window().ok_or("no window")?;
    // The link checked the path; the browser's own URL parser has the last
    // word on where it leads.
    let page = window
        .location()
        .href()
        .map_err(|err| js_error_text(&err))?;
    let resolved = web_sys::Url::new_with_base(path, &page)
        .map_err(|_| "it is not a path this page can open".to_owned())?;
    let origin = window
        .location()
        .origin()
        .map_err(|err| js_error_text(&err))?;
    if resolved.origin() != origin {
        return Err(format!(
            "it leads to {}, another site; links open only this site's files",
            resolved.origin()
        ));
    }
    let response = JsFuture::from(window.fetch_with_str(path))
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
        let chunk = JsFuture::from(reader.read())
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
