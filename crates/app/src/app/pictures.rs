//! Pictures of the active tab for slides and handouts: the SVG of the view
//! and its tables ([`crate::export`]), and screenshots of the whole window,
//! which the browser encodes as PNG.

use std::collections::BTreeMap;
use std::sync::{Arc, Mutex};

use super::EdgewiseApp;
use crate::{
    accessible,
    command::CommandError,
    export::{self, Picture, RowLook},
};

/// Where a requested screenshot arrives from the renderer.
pub(super) type ScreenshotSlot = Arc<Mutex<Option<Arc<egui::ColorImage>>>>;

impl EdgewiseApp {
    /// The view as vector shapes with the tables beside it, highlighted
    /// rows in their colours and roles in words, and the message line as
    /// the caption.
    pub fn export_svg(&self) -> Result<String, CommandError> {
        let tab = self.tab();
        let document = tab
            .document
            .as_ref()
            .ok_or("open a mesh before exporting a picture of it")?;
        let view = tab
            .view
            .vector_view(&self.view_options)
            .ok_or("the view has not been drawn yet; export it after the next frame")?;
        let tables = accessible::text_tables(document.mesh(), export::TABLE_ROWS);
        let mut rows: BTreeMap<_, RowLook> = BTreeMap::new();
        for painted in &self.current_paint().painted {
            let look = rows.entry(painted.element).or_insert_with(|| RowLook {
                colour: painted.colour,
                roles: Vec::new(),
            });
            if !look.roles.contains(&painted.role) {
                look.roles.push(painted.role.clone());
            }
        }
        let title = match tab.run.algorithm() {
            Some(algorithm) => format!("Edgewise: {} on {}", algorithm.name, document.name),
            None => format!("Edgewise: {}", document.name),
        };
        Ok(export::svg(&Picture {
            title,
            caption: self.message_text(None),
            view: &view,
            tables: &tables,
            rows: &rows,
        }))
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
        let image = self.screenshot.as_ref()?.lock().ok()?.take()?;
        self.screenshot = None;
        Some(image)
    }
}
