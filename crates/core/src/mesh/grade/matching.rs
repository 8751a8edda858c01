//! Matching the answer's darts onto the result's: one anchor per component
//! (where the operation did nothing, if it can), then successors and pairs
//! followed outwards, each step checked for place and boundary. The first
//! link that cannot match is the difference reported.

use super::darts::NONE;
use super::{Checked, Comparison, Difference, coordinates, differ};
use crate::mesh::ids::{FaceId, VertexId};
use crate::mesh::validate::Element;
use crate::schema::{Column, ElementKind, ElementRef};

/// Which link of a dart a step of the matching follows.
#[derive(Clone, Copy)]
enum Link {
    Next,
    Twin,
}

impl Comparison<'_> {
    /// Matches every component of the result, from one anchor dart, then
    /// checks that nothing of the answer is left over.
    pub(super) fn match_darts(&mut self) -> Checked {
        let mut outgoing: Vec<Vec<u32>> = vec![Vec::new(); self.given.positions.len()];
        for a in 0..self.given.len() as u32 {
            if self.given.is_live(a) {
                outgoing[self.given.origin[a as usize] as usize].push(a);
            }
        }
        // Anchored where the operation did nothing first, so that a wrong
        // cell is met from the side that is right.
        let (untouched, touched): (Vec<u32>, Vec<u32>) = (0..self.expected.len() as u32)
            .filter(|&d| self.expected.is_live(d))
            .partition(|&d| !self.touched.contains(&self.expected.element(d)));
        for anchor in untouched.into_iter().chain(touched) {
            if self.forward[anchor as usize] == NONE {
                self.match_component(anchor, &outgoing)?;
            }
        }
        if let Some(a) = (0..self.given.len() as u32)
            .find(|&a| self.given.is_live(a) && self.backward[a as usize] == NONE)
        {
            return differ(
                Some(self.given.element(a)),
                format!(
                    "{} is not in the result of {}",
                    self.given.describe(a),
                    self.task
                ),
            );
        }
        self.check_isolated_vertices()
    }

    fn match_component(&mut self, anchor: u32, outgoing: &[Vec<u32>]) -> Checked {
        let origin = self.expected.origin[anchor as usize];
        let candidates: Vec<u32> = self
            .near(self.expected.position(origin))
            .into_iter()
            .flat_map(|v| outgoing[v as usize].iter().copied())
            .filter(|&a| self.backward[a as usize] == NONE && self.fits(anchor, a))
            .collect();
        let mut best: Option<(usize, Difference)> = None;
        for a in candidates {
            match self.grow(anchor, a) {
                Ok(()) => return Ok(()),
                Err((reached, difference)) => {
                    if best.as_ref().is_none_or(|(most, _)| reached > *most) {
                        best = Some((reached, difference));
                    }
                }
            }
        }
        if let Some((_, difference)) = best {
            return Err(difference);
        }
        let end = self.expected.end(anchor);
        differ(
            None,
            format!(
                "after {} an edge runs from {} to {}{}; the answer has no such edge",
                self.task,
                self.name_at(self.expected.position(origin)),
                self.name_at(self.expected.position(end)),
                if self.expected.face[anchor as usize] == NONE {
                    " along the boundary"
                } else {
                    ""
                }
            ),
        )
    }

    /// Maps the component from `e0` ↦ `a0`, following successors and pairs;
    /// on a difference, undoes its mapping and says how far it got.
    fn grow(&mut self, e0: u32, a0: u32) -> Result<(), (usize, Difference)> {
        let mut assigned = vec![e0];
        self.assign(e0, a0);
        let mut stack = vec![(e0, a0)];
        while let Some((e, a)) = stack.pop() {
            for link in [Link::Next, Link::Twin] {
                let (en, an) = match link {
                    Link::Next => (self.expected.next[e as usize], self.given.next[a as usize]),
                    Link::Twin => (self.expected.twin[e as usize], self.given.twin[a as usize]),
                };
                if self.forward.get(en as usize) == Some(&an) {
                    continue;
                }
                let free = self.forward.get(en as usize) == Some(&NONE)
                    && self.backward.get(an as usize) == Some(&NONE);
                if !free || !self.fits(en, an) {
                    let difference = self.link_difference(link, a, en, an);
                    let reached = assigned.len();
                    for d in assigned {
                        self.backward[self.forward[d as usize] as usize] = NONE;
                        self.forward[d as usize] = NONE;
                    }
                    return Err((reached, difference));
                }
                self.assign(en, an);
                assigned.push(en);
                stack.push((en, an));
            }
        }
        Ok(())
    }

    fn assign(&mut self, e: u32, a: u32) {
        self.forward[e as usize] = a;
        self.backward[a as usize] = e;
    }

    /// Whether answer dart `a` can stand for result dart `e`: both live,
    /// from and to the same places, on a face or both on the boundary.
    pub(super) fn fits(&self, e: u32, a: u32) -> bool {
        self.expected.is_live(e)
            && self.given.is_live(a)
            && (self.expected.face[e as usize] == NONE) == (self.given.face[a as usize] == NONE)
            && self.same_place(
                self.expected.origin[e as usize],
                self.given.origin[a as usize],
            )
            && self.same_place(self.expected.end(e), self.given.end(a))
    }

    fn same_place(&self, expected_vertex: u32, given_vertex: u32) -> bool {
        match (
            self.expected.position(expected_vertex),
            self.given.position(given_vertex),
        ) {
            (Some(p), Some(q)) => p.distance(q) <= self.tolerance,
            _ => false,
        }
    }

    /// Says why answer dart `an`, reached from `a` by `link`, is not the
    /// result's `en`.
    fn link_difference(&self, link: Link, a: u32, en: u32, an: u32) -> Difference {
        let given = &self.given;
        if self.given.is_live(an)
            && self.expected.is_live(en)
            && self.same_place(self.expected.origin[en as usize], given.origin[an as usize])
            && self.same_place(self.expected.end(en), given.end(an))
            && (self.expected.face[en as usize] == NONE) != (given.face[an as usize] == NONE)
        {
            let column = given.face_column(an);
            let message = match given.face[an as usize] {
                NONE => format!(
                    "{} has no {}: it is on the boundary, but after {} a face lies on that side",
                    given.describe(an),
                    column.key(),
                    self.task
                ),
                f => format!(
                    "{} has {} {}, but after {} that side of the edge is on the boundary",
                    given.describe(an),
                    column.key(),
                    FaceId::new(f),
                    self.task
                ),
            };
            return Difference {
                element: Some(given.element(an)),
                message,
            };
        }
        let from_to = format!(
            "from {} to {}",
            self.name_at(self.expected.position(self.expected.origin[en as usize])),
            self.name_at(self.expected.position(self.expected.end(en)))
        );
        let wanted = match self.forward.get(en as usize) {
            Some(&mapped) if mapped != NONE => format!("{from_to} ({})", given.describe(mapped)),
            _ => from_to,
        };
        let got = if given.is_live(an) {
            given.describe(an)
        } else {
            Element::of(given.structure, given.element(an)).to_string()
        };
        let (column, should) = match link {
            Link::Next => (
                given.next_column(a),
                format!(
                    "the next side around {} runs {wanted}",
                    match given.face[a as usize] {
                        NONE => "the boundary".to_owned(),
                        f => FaceId::new(f).to_string(),
                    }
                ),
            ),
            Link::Twin => (Column::PairEdge, format!("its pair runs {wanted}")),
        };
        Difference {
            element: Some(given.element(a)),
            message: format!(
                "{}'s {} is {got}; after {} {should}",
                given.describe(a),
                column.key(),
                self.task
            ),
        }
    }

    /// Matches the vertices no edge reaches, by position.
    fn check_isolated_vertices(&self) -> Checked {
        let mut used = vec![false; self.given.positions.len()];
        for a in 0..self.given.len() {
            if self.given.is_live(a as u32) {
                used[self.given.origin[a] as usize] = true;
            }
        }
        let mut reached = vec![false; self.expected.positions.len()];
        for e in 0..self.expected.len() {
            if self.expected.is_live(e as u32) {
                reached[self.expected.origin[e] as usize] = true;
            }
        }
        for (v, position) in self.expected.positions.iter().enumerate() {
            if position.is_none() || reached[v] {
                continue;
            }
            match self
                .near(*position)
                .into_iter()
                .find(|&w| !used[w as usize])
            {
                Some(w) => used[w as usize] = true,
                None => {
                    return differ(
                        None,
                        format!(
                            "after {} a vertex with no edges is at {}; the answer has none there",
                            self.task,
                            coordinates(position.unwrap_or_default())
                        ),
                    );
                }
            }
        }
        match (0..used.len()).find(|&w| !used[w] && self.given.positions[w].is_some()) {
            Some(w) => differ(
                Some(ElementRef::new(ElementKind::Vertex, w as u32)),
                format!(
                    "{} at {} is not in the result of {}",
                    VertexId::new(w as u32),
                    coordinates(self.given.positions[w].unwrap_or_default()),
                    self.task
                ),
            ),
            None => Ok(()),
        }
    }
}
