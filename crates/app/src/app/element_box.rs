//! The keyboard's way to the elements: a box on the message line where
//! typing `e 3`, `vertex 1` or `f2` and Enter does what a click on that
//! element does (select it, give it to an algorithm waiting for an input,
//! answer a question, end a finished run). `/` puts the cursor in it.

use edgewise_core::schema::Records as _;

use super::EdgewiseApp;

/// The box's id, for giving it focus.
const ID: &str = "element_box";
/// Below this many points of message line, the box shrinks.
const NARROW: f32 = 520.0;

impl EdgewiseApp {
    /// The box, at the right of the message line.
    pub(super) fn element_box_ui(&mut self, ui: &mut egui::Ui) {
        let id = egui::Id::unique(ID);
        let slash = !ui.ctx().egui_wants_keyboard_input()
            && ui.input_mut(|i| {
                let pressed = i.consume_key(egui::Modifiers::NONE, egui::Key::Slash);
                if pressed {
                    // The key's text must not reach the box it focuses.
                    i.events
                        .retain(|event| !matches!(event, egui::Event::Text(text) if text == "/"));
                }
                pressed
            });
        if slash {
            ui.memory_mut(|memory| memory.request_focus(id));
        }
        // A narrow view keeps most of its line for the message.
        let (width, hint) = if ui.available_width() < NARROW {
            (56.0, "/ go to")
        } else {
            (120.0, "go to: e 3   ( / )")
        };
        let response = ui.add(
            egui::TextEdit::singleline(&mut self.element_box)
                .id(id)
                .desired_width(width)
                .hint_text(hint),
        );
        let response = response.on_hover_text(
            "Type an element (vertex 1, e 3, f2) and Enter: the same as clicking it",
        );
        // The browser may deliver the `/` that focused the box a frame
        // later; no element starts with one.
        if let Some(rest) = self.element_box.strip_prefix('/') {
            self.element_box = rest.to_owned();
        }
        if response.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter)) {
            let typed = std::mem::take(&mut self.element_box);
            if !typed.trim().is_empty() {
                self.element_typed(&typed);
            }
        }
    }

    /// Does what a click on the typed element does, or says why not.
    fn element_typed(&mut self, typed: &str) {
        let element = match edgewise_model::selection::parse_element(typed) {
            Ok(element) => element,
            Err(message) => return self.report(message),
        };
        let Some(document) = &self.tab().document else {
            return self.report("no mesh is open".to_owned());
        };
        if !document.mesh().contains(element) {
            let count = document.mesh().count(element.kind);
            return self.report(format!(
                "there is no {} {} (the table has {count} rows)",
                element.kind.prose(),
                element.id
            ));
        }
        self.element_clicked(Some(element));
    }
}
