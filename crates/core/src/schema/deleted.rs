//! The rows an edit deleted. A deleted row keeps its number, so the ids of
//! every other element stay put while an algorithm runs and the tables can
//! show it as a gap; [`crate::mesh::edit::Edit::compact`] renumbers.

use std::collections::BTreeSet;

use crate::schema::{ElementKind, ElementRef};

/// Deleted rows of the three tables. Almost always empty, so the check in
/// every row accessor costs one branch.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Deleted(BTreeSet<ElementRef>);

impl Deleted {
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }

    #[inline]
    pub fn contains(&self, element: ElementRef) -> bool {
        !self.0.is_empty() && self.0.contains(&element)
    }

    /// Whether row `index` of `kind`'s table is deleted.
    #[inline]
    pub fn row(&self, kind: ElementKind, index: usize) -> bool {
        !self.0.is_empty()
            && u32::try_from(index).is_ok_and(|id| self.0.contains(&ElementRef::new(kind, id)))
    }

    pub(crate) fn insert(&mut self, element: ElementRef) -> bool {
        self.0.insert(element)
    }

    pub(crate) fn remove(&mut self, element: ElementRef) -> bool {
        self.0.remove(&element)
    }

    /// Every deleted row, vertices first, each kind in id order.
    pub fn iter(&self) -> impl Iterator<Item = ElementRef> + '_ {
        self.0.iter().copied()
    }

    /// The number of deleted rows of one kind.
    pub fn count(&self, kind: ElementKind) -> usize {
        self.0.iter().filter(|e| e.kind == kind).count()
    }

    pub(crate) fn clear(&mut self) {
        self.0.clear();
    }
}
