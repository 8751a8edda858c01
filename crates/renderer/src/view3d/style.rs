//! Colours: the base palette for light and dark themes (the journal's
//! scheme: gray base, highlights in the app's colours) and the per-element
//! GPU styles built from [`SceneStyles`], in full or as patches.

use std::collections::BTreeMap;

use edgewise_core::schema::{ElementKind, ElementRef};
use egui::Color32;

use super::arrows::ArrowInstance;
use super::faces;
use super::gpu::StyleVertex;
use super::renderer::{StyleUpload, StyleWrites};
use super::spheres::SphereInstance;
use edgewise_pictures::palette::{
    FADE_FACE_ALPHA, FADE_FACE_MIX, FADE_LINE, Palette, face_colour, line_colour, rgb,
};
use edgewise_pictures::scene::Scene;
use edgewise_pictures::styles::{ElementStyle, SceneStyles, is_highlighted};

/// The frame uniform's `fade`: whether elements without a style of their
/// own fade, and how, as [`Palette::faded`] and [`face_colour`] do.
pub fn uniform_fade(fade_others: bool) -> [f32; 4] {
    [
        if fade_others { 1.0 } else { 0.0 },
        FADE_LINE,
        FADE_FACE_ALPHA,
        FADE_FACE_MIX,
    ]
}

/// The GPU style of a vertex or edge.
pub fn line_style(style: &ElementStyle, palette: &Palette) -> StyleVertex {
    line_style_on(style, palette, palette.line)
}

/// [`line_style`] for an element whose own base colour is `base`.
fn line_style_on(style: &ElementStyle, palette: &Palette, base: Color32) -> StyleVertex {
    let [r, g, b] = rgb(line_colour(style, palette, base));
    StyleVertex {
        colour: [r, g, b, 255],
        extra: [if style.colour.is_some() { 255 } else { 0 }, 0, 0, 0],
    }
}

/// The GPU style of a face (alpha for see-through drawing).
pub fn face_style(style: &ElementStyle, palette: &Palette) -> StyleVertex {
    let (colour, alpha) = face_colour(style, palette);
    let [r, g, b] = rgb(colour);
    StyleVertex {
        colour: [r, g, b, (alpha * 255.0).round() as u8],
        extra: [if style.colour.is_some() { 255 } else { 0 }, 0, 0, 0],
    }
}

/// A GPU style as the frame uniform's gamma-space colour.
pub fn uniform_colour(style: StyleVertex) -> [f32; 4] {
    style.colour.map(|c| f32::from(c) / 255.0)
}

/// What a style upload is made against: the view's scene and palette.
pub struct StyleContext<'a> {
    pub scene: &'a Scene,
    pub palette: &'a Palette,
}

impl StyleContext<'_> {
    fn count(&self, kind: ElementKind) -> usize {
        match kind {
            ElementKind::Vertex => self.scene.vertex_count(),
            ElementKind::Edge => self.scene.edge_count(),
            ElementKind::Face => self.scene.face_count(),
        }
    }

    /// The style of an element without one of its own: unfaded, marked
    /// for the shaders to fade while others are highlighted (the frame
    /// uniform's `fade`), so fading never rewrites every element's style.
    fn plain_style(&self, element: ElementRef) -> StyleVertex {
        let mut style = self.gpu_style(element, &ElementStyle::default());
        style.extra[3] = 255;
        style
    }

    /// An element's style: its own, or [`Self::plain_style`].
    fn style_of(&self, element: ElementRef, styles: &SceneStyles) -> StyleVertex {
        match styles.elements.get(&element) {
            Some(style) => self.gpu_style(element, style),
            None => self.plain_style(element),
        }
    }

    fn gpu_style(&self, element: ElementRef, style: &ElementStyle) -> StyleVertex {
        match element.kind {
            ElementKind::Face => face_style(style, self.palette),
            ElementKind::Vertex => line_style(style, self.palette),
            ElementKind::Edge => {
                let base = if self.scene.is_boundary_half_edge(element.id as usize) {
                    self.palette.boundary
                } else {
                    self.palette.line
                };
                line_style_on(style, self.palette, base)
            }
        }
    }

    /// The corners of face `f`'s triangles in the face buffers.
    fn corner_range(&self, f: usize) -> Option<(u32, u32)> {
        let start = *self.scene.face_triangle_start.get(f)?;
        let end = *self.scene.face_triangle_start.get(f + 1)?;
        Some((start * 3, end.saturating_sub(start) * 3))
    }

    /// Every element's GPU style.
    pub fn build_all(&self, styles: &SceneStyles, id: u64) -> StyleUpload {
        let all = |kind: ElementKind| {
            let mut out: Vec<StyleVertex> = (0..self.count(kind) as u32)
                .map(|id| self.plain_style(ElementRef::new(kind, id)))
                .collect();
            let first = ElementRef::new(kind, 0);
            let last = ElementRef::new(kind, u32::MAX);
            for (element, style) in styles.elements.range(first..=last) {
                if let Some(slot) = out.get_mut(element.id as usize) {
                    *slot = self.gpu_style(*element, style);
                }
            }
            out
        };
        let faces = all(ElementKind::Face);
        StyleUpload {
            id,
            patches: None,
            vertices: StyleWrites::All(all(ElementKind::Vertex)),
            edges: StyleWrites::All(all(ElementKind::Edge)),
            faces: StyleWrites::All(faces::corner_styles(self.scene, |f| {
                faces.get(f).copied().unwrap_or_default()
            })),
            ..self.full(styles)
        }
    }

    /// Patches for the elements whose own style differs between `before`
    /// and `styles`; fading the others is the frame uniform's.
    pub fn build_patches(
        &self,
        before: &BTreeMap<ElementRef, ElementStyle>,
        styles: &SceneStyles,
        base: u64,
        id: u64,
    ) -> StyleUpload {
        let mut runs: [Vec<(u32, Vec<StyleVertex>)>; 3] = Default::default();
        let changed = before
            .keys()
            .chain(styles.elements.keys())
            .filter(|element| before.get(element) != styles.elements.get(element));
        for &element in changed {
            let (index, kind) = (element.id as usize, element.kind);
            if index >= self.count(kind) {
                continue;
            }
            let style = self.style_of(element, styles);
            match kind {
                ElementKind::Vertex => runs[0].push((element.id, vec![style])),
                ElementKind::Edge => runs[1].push((element.id, vec![style])),
                ElementKind::Face => {
                    if let Some((first, corners)) = self.corner_range(index) {
                        runs[2].push((first, vec![style; corners as usize]));
                    }
                }
            }
        }
        let [vertices, edges, faces] = runs.map(StyleWrites::Runs);
        StyleUpload {
            id,
            patches: Some(base),
            vertices,
            edges,
            faces,
            ..self.full(styles)
        }
    }

    /// The highlighted elements' instances and styles for drawing in full
    /// over the coarse level of detail.
    fn full(&self, styles: &SceneStyles) -> StyleUpload {
        let mut upload = StyleUpload::default();
        for (&element, style) in &styles.elements {
            let index = element.id as usize;
            if !is_highlighted(style) || index >= self.count(element.kind) {
                continue;
            }
            let gpu = self.gpu_style(element, style);
            match element.kind {
                ElementKind::Vertex => {
                    upload.full_spheres.0.push(SphereInstance {
                        center: self.scene.position(element.id).to_array(),
                    });
                    upload.full_spheres.1.push(gpu);
                }
                ElementKind::Edge => {
                    upload.full_arrows.0.push(ArrowInstance {
                        start: self.scene.arrow_starts[index].to_array(),
                        end: self.scene.arrow_ends[index].to_array(),
                    });
                    upload.full_arrows.1.push(gpu);
                }
                ElementKind::Face => {
                    if let Some((first, corners)) = self.corner_range(index) {
                        let triangles = (first / 3) as usize..((first + corners) / 3) as usize;
                        for t in self.scene.triangles.get(triangles).unwrap_or_default() {
                            upload
                                .full_faces
                                .0
                                .extend(t.map(|v| self.scene.position(v).to_array()));
                        }
                        upload
                            .full_faces
                            .1
                            .extend(std::iter::repeat_n(gpu, corners as usize));
                    }
                }
            }
        }
        upload
    }
}

#[cfg(test)]
mod tests {
    use edgewise_core::mesh::{Mesh, Structure, generate};

    use super::*;
    use edgewise_pictures::geometry::MeshGeometry;

    #[test]
    fn boundary_half_edges_have_their_own_base_colour() {
        for (structure, boundary_count) in [(Structure::HalfEdge, 4), (Structure::WingedEdge, 0)] {
            let (mesh, _) = Mesh::build(&generate::open_square(), structure).expect("builds");
            let scene = Scene::new(MeshGeometry::from_mesh(&mesh));
            let palette = Palette::new(false);
            let context = StyleContext {
                scene: &scene,
                palette: &palette,
            };
            let upload = context.build_all(&SceneStyles::default(), 1);
            let StyleWrites::All(edges) = &upload.edges else {
                panic!("a whole upload");
            };
            let mut boundary = 0;
            for (e, style) in edges.iter().enumerate() {
                let expected = if scene.is_boundary_half_edge(e) {
                    boundary += 1;
                    palette.boundary
                } else {
                    palette.line
                };
                assert_eq!(style.colour[..3], rgb(expected), "{structure:?} edge {e}");
            }
            assert_eq!(boundary, boundary_count, "{structure:?}");
        }
    }
}
