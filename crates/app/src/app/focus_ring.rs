//! A ring around the widget with keyboard focus, shown once the keyboard
//! moves focus (Tab) and hidden at the next pointer press, like the web's
//! `:focus-visible`. egui marks focus only with its hover look, which a
//! projector washes out. Text fields keep their caret as their cue.

use egui::{Color32, Id, LayerId, Order, Rect, Stroke, StrokeKind};

/// How far the ring stands off the widget, in points.
const GAP: f32 = 2.0;
const WIDTH: f32 = 2.5;

/// Whether focus came from the keyboard, and where the ring was drawn.
#[derive(Default)]
pub(crate) struct FocusRing {
    from_keyboard: bool,
    drawn: Option<Rect>,
}

impl FocusRing {
    /// Where the ring was drawn in the last frame, if anywhere.
    pub fn drawn(&self) -> Option<Rect> {
        self.drawn
    }

    /// Draws the ring above every panel and window; call after the widgets
    /// of the frame are laid out.
    pub fn ui(&mut self, ctx: &egui::Context, colour: Color32) {
        let (tabbed, pressed) =
            ctx.input(|i| (i.key_pressed(egui::Key::Tab), i.pointer.any_pressed()));
        if tabbed {
            self.from_keyboard = true;
        }
        if pressed {
            self.from_keyboard = false;
        }
        self.drawn = None;
        if !self.from_keyboard || ctx.text_edit_focused() {
            return;
        }
        let Some(response) = ctx
            .memory(egui::Memory::focused)
            .and_then(|id| ctx.read_response(id))
        else {
            return;
        };
        // The part of the widget its scroll area shows.
        let rect = response.interact_rect.expand(GAP);
        if !rect.is_positive() {
            return;
        }
        ctx.layer_painter(LayerId::new(Order::Tooltip, Id::unique("focus_ring")))
            .rect_stroke(rect, 3.0, Stroke::new(WIDTH, colour), StrokeKind::Outside);
        self.drawn = Some(rect);
    }
}
