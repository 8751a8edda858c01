//! Keeps the page's copy for screen readers ([`crate::accessible`]) in step
//! with the app: rebuilt when the mesh changes, and only the role cells
//! that change when the selection or the step does.

use std::collections::BTreeMap;

use edgewise_core::schema::ElementRef;

use super::EdgewiseApp;
use crate::{accessible, platform};

/// What the page's copy was last built for.
#[derive(Default)]
pub(crate) struct ReaderCopy {
    /// Mesh id, selection and trace step.
    key: Option<(u64, Option<ElementRef>, Option<usize>)>,
    /// The role cells' words.
    roles: BTreeMap<ElementRef, String>,
}

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
        if key == self.reader_copy.key {
            return;
        }
        let same_mesh =
            matches!((key, self.reader_copy.key), (Some(now), Some(before)) if now.0 == before.0);
        self.reader_copy.key = key;
        let message = self.message_text(None);
        let roles = accessible::role_words(&self.state().highlights);
        if same_mesh {
            let changes = accessible::role_changes(&self.reader_copy.roles, &roles);
            platform::change_for_readers(&changes, message.as_deref());
        } else {
            let tables = self
                .tab()
                .document
                .as_ref()
                .map(|document| accessible::tables_html(document.mesh(), &roles));
            platform::show_to_readers(tables.as_deref(), message.as_deref());
        }
        self.reader_copy.roles = roles;
    }
}
