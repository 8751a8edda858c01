//! A bounding volume hierarchy over boxes, built once per mesh, so picking a
//! 200k-face mesh visits a few dozen primitives instead of all of them.

use glam::Vec3;

const LEAF_SIZE: usize = 4;

#[derive(Clone, Copy, Debug)]
struct Node {
    min: Vec3,
    max: Vec3,
    /// Leaf: first item. Interior: index of the right child (the left child
    /// follows the node).
    start: u32,
    /// Number of items in a leaf; 0 for an interior node.
    count: u32,
}

/// A BVH over item boxes; items are `u32` indices into the caller's list.
#[derive(Clone, Debug, Default)]
pub struct Bvh {
    nodes: Vec<Node>,
    items: Vec<u32>,
}

impl Bvh {
    /// Builds the hierarchy over `boxes` (min, max), splitting at the median
    /// along the longest axis of the box centers.
    pub fn build(boxes: &[(Vec3, Vec3)]) -> Self {
        let mut items: Vec<u32> = (0..boxes.len())
            .filter_map(|i| u32::try_from(i).ok())
            .collect();
        let mut nodes = Vec::with_capacity(2 * boxes.len() / LEAF_SIZE + 1);
        if !items.is_empty() {
            build_node(boxes, &mut items, 0, &mut nodes);
        }
        Self { nodes, items }
    }

    /// Visits the hierarchy: `enter(min, max)` says whether to descend into
    /// a node; `leaf(item)` is called for every item of an entered leaf.
    pub fn visit(&self, mut enter: impl FnMut(Vec3, Vec3) -> bool, mut leaf: impl FnMut(u32)) {
        if self.nodes.is_empty() {
            return;
        }
        let mut stack = vec![0_usize];
        while let Some(index) = stack.pop() {
            let Some(node) = self.nodes.get(index) else {
                continue;
            };
            if !enter(node.min, node.max) {
                continue;
            }
            if node.count > 0 {
                let start = node.start as usize;
                let end = start + node.count as usize;
                for &item in self.items.get(start..end).unwrap_or_default() {
                    leaf(item);
                }
            } else {
                stack.push(node.start as usize);
                stack.push(index + 1);
            }
        }
    }

    #[cfg(test)]
    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }
}

fn build_node(boxes: &[(Vec3, Vec3)], items: &mut [u32], offset: usize, nodes: &mut Vec<Node>) {
    let (mut min, mut max) = (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY));
    let (mut cmin, mut cmax) = (min, max);
    for &item in items.iter() {
        let (lo, hi) = boxes[item as usize];
        min = min.min(lo);
        max = max.max(hi);
        let c = (lo + hi) * 0.5;
        cmin = cmin.min(c);
        cmax = cmax.max(c);
    }
    let index = nodes.len();
    nodes.push(Node {
        min,
        max,
        start: u32::try_from(offset).unwrap_or(u32::MAX),
        count: u32::try_from(items.len()).unwrap_or(u32::MAX),
    });
    if items.len() <= LEAF_SIZE {
        return;
    }
    let extent = cmax - cmin;
    let axis = if extent.x >= extent.y && extent.x >= extent.z {
        0
    } else if extent.y >= extent.z {
        1
    } else {
        2
    };
    let mid = items.len() / 2;
    items.select_nth_unstable_by(mid, |&a, &b| {
        let ca = boxes[a as usize].0[axis] + boxes[a as usize].1[axis];
        let cb = boxes[b as usize].0[axis] + boxes[b as usize].1[axis];
        ca.total_cmp(&cb)
    });
    let (left, right) = items.split_at_mut(mid);
    build_node(boxes, left, offset, nodes);
    let right_index = nodes.len();
    build_node(boxes, right, offset + mid, nodes);
    if let Some(node) = nodes.get_mut(index) {
        node.start = u32::try_from(right_index).unwrap_or(u32::MAX);
        node.count = 0;
    }
}

/// The parameter range where a ray (origin, inverse direction) crosses a
/// box, if it does in front of the origin.
pub fn ray_box(origin: Vec3, inv_dir: Vec3, min: Vec3, max: Vec3) -> Option<(f32, f32)> {
    let t0 = (min - origin) * inv_dir;
    let t1 = (max - origin) * inv_dir;
    // f32::min/max ignore NaN (0 * inf), which keeps axis-parallel rays right.
    let near = t0.min(t1);
    let far = t0.max(t1);
    let enter = near.x.max(near.y).max(near.z).max(0.0);
    let exit = far.x.min(far.y).min(far.z);
    (enter <= exit).then_some((enter, exit))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn visits_exactly_the_boxes_the_ray_crosses() {
        let boxes: Vec<(Vec3, Vec3)> = (0..100)
            .map(|i| {
                let p = Vec3::new(i as f32, (i % 7) as f32, 0.0);
                (p - 0.25, p + 0.25)
            })
            .collect();
        let bvh = Bvh::build(&boxes);
        let origin = Vec3::new(42.0, 0.0, -10.0);
        let dir = Vec3::Z;
        let inv = dir.recip();
        let mut hits = Vec::new();
        bvh.visit(
            |min, max| ray_box(origin, inv, min, max).is_some(),
            |item| {
                let (min, max) = boxes[item as usize];
                if ray_box(origin, inv, min, max).is_some() {
                    hits.push(item);
                }
            },
        );
        assert_eq!(hits, vec![42]);
    }

    #[test]
    fn empty_and_identical_boxes_are_fine() {
        let bvh = Bvh::build(&[]);
        assert!(bvh.is_empty());
        bvh.visit(|_, _| true, |_| panic!("no items"));
        let same = vec![(Vec3::ONE, Vec3::ONE); 50];
        let bvh = Bvh::build(&same);
        let mut count = 0;
        bvh.visit(|_, _| true, |_| count += 1);
        assert_eq!(count, 50);
    }
}
