//! Typed element ids, so a vertex number can never be used where an edge
//! number is expected.
//!
//! Every id is a `u32` (half the memory of `usize` on 64-bit targets; no mesh
//! the app can hold gets near four billion elements), stored bit-inverted in a
//! `NonZeroU32` so that `Option<Id>` is still four bytes: a half-edge row is 16
//! bytes instead of 20 and a winged-edge row 32 instead of 40. The price is
//! one reserved number, `u32::MAX`, which no element can have anyway (counts
//! stay below it); `new(u32::MAX)` gives `u32::MAX - 1`, just as nonexistent.

use std::cmp::Ordering;
use std::fmt;
use std::num::NonZeroU32;

macro_rules! element_id {
    ($(#[$doc:meta])* $name:ident, $label:literal) => {
        $(#[$doc])*
        #[derive(Clone, Copy, PartialEq, Eq, Hash)]
        pub struct $name(NonZeroU32);

        impl $name {
            /// The id of the element with this number. `u32::MAX` is reserved
            /// (see the module notes) and becomes `u32::MAX - 1`.
            #[inline]
            pub const fn new(index: u32) -> Self {
                match NonZeroU32::new(!index) {
                    Some(inverted) => Self(inverted),
                    None => Self(NonZeroU32::MIN),
                }
            }

            /// The number of the element, for indexing its table.
            #[inline]
            pub const fn index(self) -> usize {
                self.raw() as usize
            }

            /// The number of the element.
            #[inline]
            pub const fn raw(self) -> u32 {
                !self.0.get()
            }

            /// The id for a table index, or `None` if it does not fit.
            /// What a new record's required references hold until an edit
            /// sets them: the reserved number, which no row has.
            pub const UNSET: Self = Self::new(u32::MAX);

            /// Whether this is [`Self::UNSET`].
            #[inline]
            pub const fn is_unset(self) -> bool {
                self.0.get() == 1
            }

            #[inline]
            pub fn from_index(index: usize) -> Option<Self> {
                u32::try_from(index).ok().filter(|&i| i != u32::MAX).map(Self::new)
            }
        }

        impl Default for $name {
            fn default() -> Self {
                Self::new(0)
            }
        }

        impl PartialOrd for $name {
            fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
                Some(self.cmp(other))
            }
        }

        impl Ord for $name {
            fn cmp(&self, other: &Self) -> Ordering {
                self.raw().cmp(&other.raw())
            }
        }

        impl fmt::Debug for $name {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                write!(f, concat!(stringify!($name), "({})"), self.raw())
            }
        }

        impl fmt::Display for $name {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                if self.is_unset() {
                    return f.write_str(concat!("no ", $label, " (not set yet)"));
                }
                write!(f, concat!($label, " {}"), self.raw())
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
        assert_eq!(VertexId::from_index(u32::MAX as usize), None);
        assert_eq!(format!("{:?}", EdgeId::new(9)), "EdgeId(9)");
    }

    #[test]
    fn optional_ids_cost_nothing() {
        assert_eq!(size_of::<Option<FaceId>>(), 4);
        assert!(FaceId::new(2) < FaceId::new(10));
        assert_eq!(FaceId::new(u32::MAX).raw(), u32::MAX - 1);
        assert_eq!(HalfEdgeId::default().raw(), 0);
        assert!(EdgeId::UNSET.is_unset() && !EdgeId::new(3).is_unset());
        assert_eq!(EdgeId::UNSET.to_string(), "no edge (not set yet)");
    }
}
