//! One walker for every ordered walk around an element (a circulator, as in
//! tri-mesh or `baby_shark`): a [`Ring`] says where the walk starts and how it
//! steps, and [`Circulator`] does the stepping, so the stop rules live in one
//! place instead of one hand-written loop per structure and element.

/// One ring of steps around an element: the half-edges ending at a vertex,
/// the edges of a face, and so on.
///
/// The tables may be broken (from `from_raw_parts`), so a ring must not
/// assume that a step leads back to the start; [`Circulator`] stops it.
pub trait Ring {
    /// One position on the ring (an id, or an id with a side).
    type Step: Copy + PartialEq;

    /// Where the walk starts (the element's incident edge), or `None` when
    /// there is none or it is not on the ring.
    fn first(&self) -> Option<Self::Step>;

    /// The step following `step`, or `None` when the tables lead off the
    /// ring (a missing row, or a row that no longer touches the element).
    fn after(&self, step: Self::Step) -> Option<Self::Step>;

    /// The most steps a walk may take: at least one lap of a valid ring, so a
    /// broken ring that never comes back to its start still ends.
    fn budget(&self) -> usize;
}

/// Walks a [`Ring`] from its first step until it comes back to that step,
/// leaves the ring, or has spent the ring's budget: it always ends and never
/// panics, even on broken tables.
#[derive(Clone, Debug)]
pub struct Circulator<R: Ring> {
    ring: R,
    start: Option<R::Step>,
    next: Option<R::Step>,
    budget: usize,
}

impl<R: Ring> Circulator<R> {
    /// Walks `ring` from its [`first`](Ring::first) step.
    pub fn new(ring: R) -> Self {
        let start = ring.first();
        Self::starting_at(ring, start)
    }

    /// Walks `ring` from `start` instead, for callers that pick the start
    /// (the polygon export). `start` must be on the ring: it is yielded
    /// unchecked.
    pub(crate) fn starting_at(ring: R, start: Option<R::Step>) -> Self {
        let budget = ring.budget();
        Self {
            ring,
            start,
            next: start,
            budget,
        }
    }
}

impl<R: Ring> Iterator for Circulator<R> {
    type Item = R::Step;

    fn next(&mut self) -> Option<R::Step> {
        let current = self.next?;
        self.budget = self.budget.checked_sub(1)?;
        self.next = self
            .ring
            .after(current)
            .filter(|&following| Some(following) != self.start);
        Some(current)
    }
}
