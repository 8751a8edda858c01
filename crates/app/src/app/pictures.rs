//! Pictures of the active tab for slides and handouts: the SVG of the view
//! and its tables, and a PDF handout of a run with a page per step (both
//! made by [`edgewise_model::moment`] from the view's camera), and
//! screenshots of the whole window, which the browser encodes as PNG.

use std::sync::{Arc, Mutex};

use super::EdgewiseApp;
use crate::command::CommandError;
use edgewise_model::moment;
use edgewise_pictures::geometry::MeshGeometry;
use edgewise_pictures::styles::SceneStyles;

/// Where a requested screenshot arrives from the renderer.
pub(super) type ScreenshotSlot = Arc<Mutex<Option<Arc<egui::ColorImage>>>>;

impl EdgewiseApp {
    /// Lays the active tab out as its first frame in a window `width` by
    /// `height` points would, with no window: a mesh being opened is made now,
    /// the camera frames it, and the colours are the current moment's.
    /// [`Self::export_svg`] and [`Self::export_handout`] then work from
    /// the command line (`edgewise render`).
    pub fn lay_out_offscreen(&mut self, width: f32, height: f32) {
        self.finish_pending();
        self.refresh_styles();
        self.sync_view_options();
        let tab = &mut self.tabs[self.active_tab];
        tab.pane
            .lay_out_offscreen(egui::vec2(width, height), &self.view_options);
    }

    /// The view as vector shapes with the tables beside it, highlighted
    /// rows in their colours and roles in words, and the message line as
    /// the caption.
    pub fn export_svg(&self) -> Result<String, CommandError> {
        let tab = self.tab();
        let document = tab
            .document
            .as_ref()
            .ok_or("open a mesh before exporting a picture of it")?;
        moment::check_picture_size(document)?;
        let view = tab
            .pane
            .view
            .vector_view(&self.view_options)
            .ok_or("the view has not been drawn yet; export it after the next frame")?;
        Ok(moment::svg_picture(
            document,
            tab.run.algorithm().map(|algorithm| algorithm.name.as_str()),
            self.message_text(None),
            &self.current_paint(),
            &view,
        ))
    }

    /// A PDF handout of the run: one page per step (see
    /// [`moment::handout`]). Returns the file's name and bytes.
    pub fn export_handout(&self) -> Result<(String, Vec<u8>), CommandError> {
        let tab = self.tab();
        let (Some(document), Some(session)) = (tab.document.as_ref(), tab.run.session()) else {
            return Err("run an algorithm first: a handout has a page per step of its run".into());
        };
        let view_of = |geometry: Option<MeshGeometry>, styles: &SceneStyles| {
            tab.pane
                .view
                .vector_view_of(geometry, styles, &self.view_options)
        };
        Ok(moment::handout(
            document,
            session,
            tab.edit_applied,
            &self.theme,
            view_of,
        )?)
    }

    /// Asks for a screenshot of the next frame; [`Self::take_screenshot`]
    /// gives it once drawn.
    pub fn request_screenshot(&mut self) {
        let slot = Arc::new(Mutex::new(None));
        self.screenshot = Some(Arc::clone(&slot));
        if let Some(ctx) = &self.ctx {
            ctx.request_screenshot(move |image| {
                if let Ok(mut slot) = slot.lock() {
                    *slot = Some(image);
                }
            });
            ctx.request_repaint();
        }
    }

    /// The screenshot asked for, once the frame is drawn.
    pub fn take_screenshot(&mut self) -> Option<Arc<egui::ColorImage>> {
        let image = self.screenshot.as_ref()?.lock().ok()?.take();
        if image.is_some() {
            self.screenshot = None;
        } else if let Some(ctx) = &self.ctx {
            // The pixels are read back a frame or more after the one drawn,
            // and egui draws no frame for their arrival: on an idle page the
            // wait would last until the next pointer move.
            ctx.request_repaint();
        }
        image
    }
}
