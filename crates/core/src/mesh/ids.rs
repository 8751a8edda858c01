//! Typed element ids, so a vertex number can never be used where an edge
//! number is expected.
//!
//! Every id is a `u32`: it halves the memory of the link tables compared with
//! `usize` on 64-bit targets, and no mesh the app can hold in memory gets near
//! four billion elements.

use std::fmt;

macro_rules! element_id {
    ($(#[$doc:meta])* $name:ident, $label:literal) => {
        $(#[$doc])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Default)]
        pub struct $name(u32);

        impl $name {
            /// The id of the element with this number.
            #[inline]
            pub const fn new(index: u32) -> Self {
                Self(index)
            }

            /// The number of the element, for indexing its table.
            #[inline]
            pub const fn index(self) -> usize {
                self.0 as usize
            }

            /// The number of the element as stored.
            #[inline]
            pub const fn raw(self) -> u32 {
                self.0
            }

            /// The id for a table index, or `None` if it does not fit in a `u32`.
            #[inline]
            pub fn from_index(index: usize) -> Option<Self> {
                u32::try_from(index).ok().map(Self)
            }
        }

        impl fmt::Display for $name {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                write!(f, concat!($label, " {}"), self.0)
            }
        }

        impl From<$name> for usize {
            #[inline]
            fn from(id: $name) -> usize {
                id.index()
            }
        }
    };
}

element_id!(
    /// A vertex, numbered from 0 in creation order.
    VertexId,
    "vertex"
);
element_id!(
    /// A winged edge, numbered from 0 in order of first appearance.
    EdgeId,
    "edge"
);
element_id!(
    /// A face, numbered from 0 in creation order.
    FaceId,
    "face"
);
element_id!(
    /// A half-edge: interior half-edges first (face by face), then boundary ones.
    HalfEdgeId,
    "half-edge"
);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ids_display_their_kind() {
        assert_eq!(VertexId::new(3).to_string(), "vertex 3");
        assert_eq!(EdgeId::new(7).to_string(), "edge 7");
        assert_eq!(FaceId::new(2).to_string(), "face 2");
        assert_eq!(HalfEdgeId::new(5).to_string(), "half-edge 5");
        assert_eq!(HalfEdgeId::new(5).index(), 5);
        assert_eq!(VertexId::from_index(4), Some(VertexId::new(4)));
    }
}
