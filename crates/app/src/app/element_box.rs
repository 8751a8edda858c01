//! The keyboard's way to the elements: a box on the message line where
//! typing `e 3`, `vertex 1` or `f2` and Enter does what a click on that
//! element does (select it, give it to an algorithm waiting for an input,
//! answer a question, end a finished run). `/` puts the cursor in it.

use edgewise_core::schema::{ElementKind, ElementRef, Records as _};

use super::EdgewiseApp;

/// The box's id, for giving it focus.
const ID: &str = "element_box";
/// Below this many points of message line, the box shrinks.
const NARROW: f32 = 520.0;

/// Reads `vertex 3`, `v3`, `edge 5`, `e 5`, `half-edge 5`, `h5`, `face 1`
/// or `f1` (any case).
pub fn parse_element(text: &str) -> Result<ElementRef, String> {
    let text = text.trim().to_ascii_lowercase();
    let split = text
        .find(|c: char| c.is_ascii_digit())
        .unwrap_or(text.len());
    let (word, number) = text.split_at(split);
    let kind = match word.trim() {
        "v" | "vertex" => Some(ElementKind::Vertex),
        "e" | "h" | "edge" | "half-edge" | "halfedge" => Some(ElementKind::Edge),
        "f" | "face" => Some(ElementKind::Face),
        _ => None,
    };
    let id = number.trim().parse::<u32>().ok();
    match (kind, id) {
        (Some(kind), Some(id)) => Ok(ElementRef::new(kind, id)),
        _ => Err(format!(
            "`{}`: type an element as vertex, edge or face and its id, such as e 3 or vertex 1",
            text.chars().take(40).collect::<String>()
        )),
    }
}

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
        let element = match parse_element(typed) {
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn elements_are_read_in_long_and_short_forms() {
        let cases = [
            ("vertex 3", ElementRef::new(ElementKind::Vertex, 3)),
            ("v3", ElementRef::new(ElementKind::Vertex, 3)),
            (" E 12 ", ElementRef::new(ElementKind::Edge, 12)),
            ("half-edge 5", ElementRef::new(ElementKind::Edge, 5)),
            ("h5", ElementRef::new(ElementKind::Edge, 5)),
            ("face1", ElementRef::new(ElementKind::Face, 1)),
        ];
        for (text, element) in cases {
            assert_eq!(parse_element(text), Ok(element), "{text}");
        }
        for text in ["3", "edge", "x 3", "edge -1", "edge 99999999999"] {
            assert!(parse_element(text).is_err(), "{text}");
        }
        assert_eq!(
            parse_element("q 1"),
            Err("`q 1`: type an element as vertex, edge or face and its id, such as e 3 or vertex 1".to_owned())
        );
    }
}
