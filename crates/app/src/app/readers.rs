//! Keeps the page's copy for screen readers ([`crate::accessible`]) in step
//! with the app: rebuilt when the mesh, the selection or the step changes.

use super::EdgewiseApp;
use crate::{accessible, platform};

/// What the copy was last built for: mesh id, selection and trace step.
pub(crate) type ReaderKey = Option<(
    u64,
    Option<edgewise_core::schema::ElementRef>,
    Option<usize>,
)>;

impl EdgewiseApp {
    pub(super) fn mirror_for_readers(&mut self) {
        if !platform::READER_COPY {
            return;
        }
        let tab = self.tab();
        let key = tab.document.as_ref().map(|d| {
            (
                d.mesh_id(),
                d.selection(),
                tab.run.session().map(crate::algorithm::TraceSession::step),
            )
        });
        if key == self.reader_key {
            return;
        }
        self.reader_key = key;
        let tables = self
            .tab()
            .document
            .as_ref()
            .map(|document| accessible::tables_html(document.mesh(), &self.state().highlights));
        let message = self.message_text(None);
        platform::show_to_readers(tables.as_deref(), message.as_deref());
    }
}
