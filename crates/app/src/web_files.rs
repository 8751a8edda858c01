//! Files in the browser: a file picker, reading dropped files, and downloads.
//!
//! Browsers read files asynchronously, so what is read goes into an
//! [`Inbox`] that the app empties on its next frame.

use std::{cell::RefCell, rc::Rc};

use eframe::wasm_bindgen::{JsCast as _, closure::Closure};
use wasm_bindgen_futures::JsFuture;

use edgewise_core::formats::MAX_FILE_BYTES;

use crate::{files::PendingFile, web::js_error_text as js_text};

/// Files read (or failed reads, as messages) waiting for the next frame.
pub type Inbox = Rc<RefCell<Vec<Result<PendingFile, String>>>>;

/// What the picker offers for meshes.
pub const MESHES: &str = ".wtb,.htb,.ply,.obj";
/// What the picker offers for algorithms.
pub const ALGORITHMS: &str = ".alg,.txt";

/// Opens the browser's file picker offering `accept`; the chosen file
/// arrives in `inbox`. Must run soon after a click: browsers only open
/// pickers for a user's action.
pub fn pick_file(inbox: &Inbox, ctx: &egui::Context, accept: &str) -> Result<(), String> {
    let document = web_sys::window()
        .and_then(|w| w.document())
        .ok_or("no document to open a file picker in")?;
    let input = document
        .create_element("input")
        .map_err(|err| js_text(&err))?
        .dyn_into::<web_sys::HtmlInputElement>()
        .map_err(|_| "the browser did not create a file input")?;
    input.set_type("file");
    input.set_accept(accept);
    let (inbox, ctx, target) = (inbox.clone(), ctx.clone(), input.clone());
    // Called once when a file is chosen; a cancelled picker leaves it unused.
    let on_change = Closure::once_into_js(move || {
        if let Some(file) = target.files().and_then(|files| files.get(0)) {
            read_file(inbox, ctx, file);
        }
    });
    input
        .add_event_listener_with_callback("change", on_change.unchecked_ref())
        .map_err(|err| js_text(&err))?;
    input.click();
    Ok(())
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
                .map_err(|err| format!("{name}: cannot read the file: {}", js_text(&err)))
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
pub fn read_dropped(inbox: &Inbox, ctx: &egui::Context, file: egui::DroppedFileHandle) {
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
pub fn download(name: &str, bytes: &[u8]) -> Result<(), String> {
    let window = web_sys::window().ok_or("no window to download from")?;
    let document = window.document().ok_or("no document to download from")?;
    let body = document.body().ok_or("the page has no body")?;
    let parts = js_sys::Array::of1(&js_sys::Uint8Array::from(bytes));
    let options = web_sys::BlobPropertyBag::new();
    options.set_type("application/octet-stream");
    let blob = web_sys::Blob::new_with_u8_array_sequence_and_options(&parts, &options)
        .map_err(|err| js_text(&err))?;
    let url = web_sys::Url::create_object_url_with_blob(&blob).map_err(|err| js_text(&err))?;
    let anchor = document
        .create_element("a")
        .map_err(|err| js_text(&err))?
        .dyn_into::<web_sys::HtmlAnchorElement>()
        .map_err(|_| "the browser did not create a link")?;
    anchor.set_href(&url);
    anchor.set_download(name);
    anchor.set_hidden(true);
    body.append_child(&anchor).map_err(|err| js_text(&err))?;
    anchor.click();
    anchor.remove();
    let revoke = Closure::once_into_js(move || {
        web_sys::Url::revoke_object_url(&url).ok();
    });
    window
        .set_timeout_with_callback_and_timeout_and_arguments_0(revoke.unchecked_ref(), 1000)
        .map_err(|err| js_text(&err))?;
    Ok(())
}
