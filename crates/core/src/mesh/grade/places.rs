//! Finding the vertices at a position, within the grader's tolerance: the
//! vertices sorted by x, so a lookup is a binary search and a short scan.

use glam::Vec3;

pub(super) struct Places {
    by_x: Vec<(f32, u32)>,
    tolerance: f32,
}

impl Places {
    pub fn new(positions: &[Option<Vec3>], tolerance: f32) -> Self {
        let mut by_x: Vec<(f32, u32)> = positions
            .iter()
            .enumerate()
            .filter_map(|(v, p)| p.map(|p| (p.x, v as u32)))
            .collect();
        by_x.sort_by(|a, b| a.0.total_cmp(&b.0));
        Self { by_x, tolerance }
    }

    /// The vertices of `positions` (the table this was made from) within
    /// the tolerance of `p`.
    pub fn near(&self, positions: &[Option<Vec3>], p: Vec3) -> Vec<u32> {
        let start = self
            .by_x
            .partition_point(|&(x, _)| x < p.x - self.tolerance);
        self.by_x[start..]
            .iter()
            .take_while(|&&(x, _)| x <= p.x + self.tolerance)
            .filter(|&&(_, v)| {
                positions
                    .get(v as usize)
                    .copied()
                    .flatten()
                    .is_some_and(|q| q.distance(p) <= self.tolerance)
            })
            .map(|&(_, v)| v)
            .collect()
    }
}
