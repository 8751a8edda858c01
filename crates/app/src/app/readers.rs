//! Keeps the page's copy for screen readers ([`crate::accessible`]) in step
//! with the app: the tables rebuilt when the mesh changes, and only the
//! role cells that change when the selection or the step does; the run's
//! place, line and variables at each step; the algorithm list when the
//! library or the structure changes.

use std::collections::BTreeMap;
use std::hash::{Hash as _, Hasher as _};

use edgewise_core::schema::ElementRef;

use super::EdgewiseApp;
use crate::{accessible, platform};

/// What the page's copy shows: mesh id, selection, and the trace's step
/// and whether it plays.
type CopyKey = (u64, Option<ElementRef>, Option<(usize, bool)>);

/// What the page's copy was last built for.
#[derive(Default)]
pub(crate) struct ReaderCopy {
    key: Option<CopyKey>,
    /// The role cells' words.
    roles: BTreeMap<ElementRef, String>,
    /// A hash of the algorithms' names and the mesh's structure.
    algorithms: Option<u64>,
}

impl EdgewiseApp {
    pub(super) fn mirror_for_readers(&mut self) {
        if !platform::READER_COPY {
            return;
        }
        self.mirror_algorithms();
        let tab = self.tab();
        let key = tab.document.as_ref().map(|d| {
            (
                d.mesh_id(),
                d.selection(),
                tab.run.session().map(|s| (s.step(), s.playing)),
            )
        });
        if key == self.reader_copy.key {
            return;
        }
        let same_mesh =
            matches!((key, self.reader_copy.key), (Some(now), Some(before)) if now.0 == before.0);
        self.reader_copy.key = key;
        let message = self.message_text(None);
        let paint = self.current_paint();
        let roles = accessible::role_words(&self.state().highlights, &paint.variable_names);
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
        let run = &self.tab().run;
        let copy = run
            .session()
            .zip(run.current_frame(&self.theme))
            .map(|(session, frame)| {
                accessible::RunCopy::new(&frame, session.trace.algorithm(), session.playing)
            });
        let variables = copy
            .as_ref()
            .map(accessible::RunCopy::variables_html)
            .unwrap_or_default();
        let text = copy.as_ref().map(|copy| platform::RunText {
            status: &copy.status,
            line: &copy.line,
            variables_html: &variables,
        });
        platform::show_run_to_readers(text.as_ref());
    }

    /// The algorithm list, rebuilt only when it or the structure changes:
    /// rebuilding it would move a reader's focus out of its form.
    fn mirror_algorithms(&mut self) {
        let structure = self.tab().document.as_ref().map(|d| d.mesh().structure());
        let entries = self.algorithms.library.entries();
        let mut hasher = std::collections::hash_map::DefaultHasher::new();
        structure.hash(&mut hasher);
        for entry in entries {
            entry.algorithm.name.hash(&mut hasher);
            entry.algorithm.first_line.hash(&mut hasher);
        }
        let key = hasher.finish();
        if self.reader_copy.algorithms == Some(key) {
            return;
        }
        self.reader_copy.algorithms = Some(key);
        let html = match structure {
            Some(structure) => accessible::algorithms_html(
                entries.iter().map(|entry| &**entry.algorithm),
                structure,
            ),
            None => "<p>Open a mesh to run an algorithm on it.</p>".to_owned(),
        };
        platform::show_algorithms_to_readers(&html);
    }
}
