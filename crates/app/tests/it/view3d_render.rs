//! Renders the 3D view offscreen, through egui and `egui_wgpu` exactly as the
//! app does (paint callback, `Depth24Plus` attachment), and writes PNGs to
//! `target/view3d-renders/` (under `CARGO_TARGET_DIR` when set) to be looked
//! at. Checks a few pixels against CPU projections so the GPU and the picking
//! agree on where things are.
//!
//! Needs a wgpu adapter; on a machine without one (no GPU and no lavapipe)
//! the tests report that and pass.

#![allow(clippy::unwrap_used)]

use crate::support;

use crate::support::worst_channel_difference;

use edgewise_core::schema::{ElementKind, ElementRef};
use std::path::PathBuf;

use edgewise_core::mesh::{Mesh, Polygons, Structure, generate};
use edgewise_pictures::camera::Camera;
use edgewise_pictures::geometry::MeshGeometry;
use edgewise_pictures::options::{DrawIds, ViewOptions};
use edgewise_pictures::styles::{ElementStyle, Pointer, SceneStyles};
use edgewise_renderer::view3d::{View3d, ViewResponse};
use eframe::egui_wgpu::RenderState;
use egui::{Color32, Pos2, Rect, Vec2};

fn out_dir() -> PathBuf {
    let target = std::env::var_os("CARGO_TARGET_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../target"));
    let dir = target.join("view3d-renders");
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// An RGBA image.
struct Image {
    width: u32,
    height: u32,
    pixels: Vec<u8>,
}

impl Image {
    fn pixel(&self, x: u32, y: u32) -> [u8; 4] {
        let i = ((y * self.width + x) * 4) as usize;
        [
            self.pixels[i],
            self.pixels[i + 1],
            self.pixels[i + 2],
            self.pixels[i + 3],
        ]
    }

    /// Whether any pixel within `radius` of (x, y) satisfies `test`.
    fn any_near(&self, at: Pos2, radius: i32, test: impl Fn([u8; 4]) -> bool) -> bool {
        (-radius..=radius).any(|dy| {
            (-radius..=radius).any(|dx| {
                let (x, y) = (at.x as i32 + dx, at.y as i32 + dy);
                x >= 0
                    && y >= 0
                    && (x as u32) < self.width
                    && (y as u32) < self.height
                    && test(self.pixel(x as u32, y as u32))
            })
        })
    }

    /// A `size`-pixel square around `center`, magnified `zoom` times, to look
    /// at details.
    fn zoomed(&self, center: Pos2, size: u32, zoom: u32) -> Self {
        let (x0, y0) = (
            center.x as i64 - i64::from(size / 2),
            center.y as i64 - i64::from(size / 2),
        );
        let mut pixels = Vec::with_capacity((size * size * zoom * zoom * 4) as usize);
        for y in 0..size * zoom {
            for x in 0..size * zoom {
                let (sx, sy) = (x0 + i64::from(x / zoom), y0 + i64::from(y / zoom));
                let inside =
                    sx >= 0 && sy >= 0 && sx < i64::from(self.width) && sy < i64::from(self.height);
                pixels.extend(if inside {
                    self.pixel(sx as u32, sy as u32)
                } else {
                    [0, 0, 0, 255]
                });
            }
        }
        Self {
            width: size * zoom,
            height: size * zoom,
            pixels,
        }
    }

    fn save(&self, name: &str) -> PathBuf {
        let path = out_dir().join(name);
        let file = std::fs::File::create(&path).unwrap();
        let mut encoder = png::Encoder::new(std::io::BufWriter::new(file), self.width, self.height);
        encoder.set_color(png::ColorType::Rgba);
        encoder.set_depth(png::BitDepth::Eight);
        encoder
            .write_header()
            .unwrap()
            .write_image_data(&self.pixels)
            .unwrap();
        eprintln!("wrote {}", path.display());
        path
    }
}

/// Renders a frame of `ui` at `size` pixels and returns the picture.
struct Harness {
    render_state: RenderState,
    ctx: egui::Context,
    size: [u32; 2],
    pixels_per_point: f32,
}

impl Harness {
    fn new(render_state: RenderState, size: [u32; 2]) -> Self {
        Self {
            render_state,
            ctx: egui::Context::default(),
            size,
            pixels_per_point: 1.0,
        }
    }

    fn screen(&self) -> Rect {
        Rect::from_min_size(
            Pos2::ZERO,
            Vec2::new(self.size[0] as f32, self.size[1] as f32) / self.pixels_per_point,
        )
    }

    fn frame(&self, events: Vec<egui::Event>, ui: impl FnMut(&mut egui::Ui)) -> Image {
        let pixels = support::gpu::draw_frame(
            &self.render_state,
            &self.ctx,
            self.screen(),
            self.size,
            events,
            ui,
        )
        .expect("the frame renders");
        Image {
            width: self.size[0],
            height: self.size[1],
            pixels,
        }
    }

    /// Runs the view for a couple of frames (the first uploads and frames)
    /// and returns the last picture and response.
    fn show(
        &self,
        view: &mut View3d,
        styles: &SceneStyles,
        options: &ViewOptions,
        events: Vec<egui::Event>,
    ) -> (Image, ViewResponse) {
        let mut response = ViewResponse::default();
        let _ = self.frame(Vec::new(), |ui| {
            response = view.ui(ui, styles, options);
        });
        let image = self.frame(events, |ui| {
            response = view.ui(ui, styles, options);
        });
        (image, response)
    }
}

fn geometry(polygons: &Polygons, structure: Structure) -> MeshGeometry {
    let (mesh, _) = Mesh::build(polygons, structure).unwrap();
    MeshGeometry::from_mesh(&mesh)
}

fn styles_for(_geometry: &MeshGeometry) -> SceneStyles {
    SceneStyles {
        generation: 1,
        ..SceneStyles::default()
    }
}

/// The entry of one element, made if missing.
fn entry(styles: &mut SceneStyles, kind: ElementKind, id: u32) -> &mut ElementStyle {
    styles
        .elements
        .entry(ElementRef::new(kind, id))
        .or_default()
}

const YELLOW: Color32 = Color32::from_rgb(232, 196, 40);
const GREEN: Color32 = Color32::from_rgb(56, 168, 72);
const PURPLE: Color32 = Color32::from_rgb(150, 70, 190);
const LIGHT_BLUE: Color32 = Color32::from_rgb(80, 180, 230);

fn is_near_colour(pixel: [u8; 4], colour: Color32, tolerance: i32) -> bool {
    let [r, g, b, _] = colour.to_array();
    (i32::from(pixel[0]) - i32::from(r)).abs() <= tolerance
        && (i32::from(pixel[1]) - i32::from(g)).abs() <= tolerance
        && (i32::from(pixel[2]) - i32::from(b)).abs() <= tolerance
}

#[test]
fn winged_edge_cube_with_highlights_labels_and_pointers() {
    let Some(rs) = support::gpu::render_state() else {
        eprintln!("no wgpu adapter: skipped");
        return;
    };
    let harness = Harness::new(rs.clone(), [900, 640]);
    let geometry = geometry(&generate::cube(), Structure::WingedEdge);
    let mut view = View3d::new(Some(&rs));
    view.set_geometry(geometry.clone(), true);
    let mut styles = styles_for(&geometry);
    styles.fade_others = true;
    entry(&mut styles, ElementKind::Face, 1).colour = Some(YELLOW);
    *entry(&mut styles, ElementKind::Edge, 3) = ElementStyle {
        colour: Some(GREEN),
        faded: false,
        label: Some("3: Left Predecessor".to_owned()),
    };
    *entry(&mut styles, ElementKind::Vertex, 6) = ElementStyle {
        colour: Some(PURPLE),
        faded: false,
        label: Some("6: v".to_owned()),
    };
    styles.pointers = vec![
        Pointer {
            target: ElementRef::new(ElementKind::Edge, 3),
            colour: LIGHT_BLUE,
        },
        Pointer {
            target: ElementRef::new(ElementKind::Edge, 3),
            colour: LIGHT_BLUE,
        },
    ];
    let options = ViewOptions {
        show_axes: true,
        ..ViewOptions::default()
    };
    let (image, _) = harness.show(&mut view, &styles, &options, Vec::new());
    image.save("winged_cube.png");

    // The purple vertex is drawn where the CPU projects it.
    let transforms = view.transforms(harness.screen());
    let (at, _) = transforms.project(geometry.positions[6]).unwrap();
    assert!(
        image.any_near(at, 3, |p| is_near_colour(p, PURPLE, 70)),
        "no purple near {at:?}: {:?}",
        image.pixel(at.x as u32, at.y as u32)
    );
    image.zoomed(at, 160, 3).save("winged_cube_zoom.png");
    // Clicking there picks that vertex.
    assert_eq!(
        view.pick_at(harness.screen(), at, &options),
        Some(ElementRef::new(ElementKind::Vertex, 6))
    );
}

#[test]
fn half_edge_grid_with_all_ids_dark() {
    let Some(rs) = support::gpu::render_state() else {
        eprintln!("no wgpu adapter: skipped");
        return;
    };
    let harness = Harness::new(rs.clone(), [900, 640]);
    let geometry = geometry(&generate::grid(3, 2), Structure::HalfEdge);
    let mut view = View3d::new(Some(&rs));
    view.set_geometry(geometry.clone(), true);
    view.set_camera(Camera {
        yaw: 0.25,
        pitch: 0.35,
        ..view.camera()
    });
    let mut styles = styles_for(&geometry);
    entry(&mut styles, ElementKind::Edge, 0).colour = Some(GREEN);
    entry(&mut styles, ElementKind::Face, 4).colour = Some(YELLOW);
    let options = ViewOptions {
        draw_ids: DrawIds::Always,
        show_orientation: true,
        dark: true,
        ..ViewOptions::default()
    };
    let (image, _) = harness.show(&mut view, &styles, &options, Vec::new());
    image.save("half_edge_grid_dark.png");

    // The green half-edge is drawn off its edge, inside its face.
    let transforms = view.transforms(harness.screen());
    let anchor = view.anchor(ElementRef::new(ElementKind::Edge, 0)).unwrap();
    let (at, _) = transforms.project(anchor).unwrap();
    assert!(image.any_near(at, 12, |p| is_near_colour(p, GREEN, 80)));
}

#[test]
fn solid_tetrahedron_with_hover() {
    let Some(rs) = support::gpu::render_state() else {
        eprintln!("no wgpu adapter: skipped");
        return;
    };
    let harness = Harness::new(rs.clone(), [640, 480]);
    let geometry = geometry(&generate::regular_tetrahedron(), Structure::HalfEdge);
    let mut view = View3d::new(Some(&rs));
    view.set_geometry(geometry.clone(), true);
    let styles = styles_for(&geometry);
    let options = ViewOptions {
        solid_faces: true,
        show_orientation: true,
        mesh_scale: 1.5,
        ..ViewOptions::default()
    };
    // Hover the middle of the view: a face (or an edge in front of it).
    let _ = harness.show(&mut view, &styles, &options, Vec::new());
    let center = harness.screen().center() + Vec2::new(0.0, 40.0);
    let (image, response) = harness.show(
        &mut view,
        &styles,
        &options,
        vec![egui::Event::PointerMoved(center)],
    );
    image.save("solid_tetrahedron_hover.png");
    assert!(response.hovered.is_some(), "{response:?}");
}

/// On an sRGB target the view's pipelines convert colours to linear (their
/// `srgb_target` constant), so what is read back matches a plain target's
/// picture; without the conversion every lit pixel would come out lighter.
#[test]
fn an_srgb_target_shows_what_a_plain_target_does() {
    let (Some(plain), Some(srgb)) = (
        support::gpu::render_state(),
        support::gpu::render_state_for(wgpu::TextureFormat::Rgba8UnormSrgb),
    ) else {
        eprintln!("no wgpu adapter: skipped");
        return;
    };
    let geometry = geometry(&generate::cube(), Structure::HalfEdge);
    let styles = styles_for(&geometry);
    // Solid faces: every pixel of the mesh opaque, so no blending (done in
    // linear light on an sRGB target) moves it.
    let options = ViewOptions {
        solid_faces: true,
        draw_ids: DrawIds::Never,
        ..ViewOptions::default()
    };
    let [plain_image, srgb_image] = [plain, srgb].map(|rs| {
        let harness = Harness::new(rs.clone(), [320, 240]);
        let mut view = View3d::new(Some(&rs));
        view.set_geometry(geometry.clone(), true);
        harness.show(&mut view, &styles, &options, Vec::new()).0
    });
    srgb_image.save("srgb_target_cube.png");
    let pixels = plain_image.pixels.chunks_exact(4);
    let drawn = pixels.clone().filter(|p| p[..3] != [0, 0, 0]).count();
    let differing = pixels
        .zip(srgb_image.pixels.chunks_exact(4))
        .filter(|(a, b)| a.iter().zip(*b).any(|(a, b)| a.abs_diff(*b) > 3))
        .count();
    assert!(drawn > 320 * 240 / 10, "the cube covers {drawn} pixels");
    assert!(
        differing * 100 < drawn,
        "{differing} of the {drawn} pixels drawn differ between the targets"
    );
}

#[test]
fn torus_20k_faces() {
    let Some(rs) = support::gpu::render_state() else {
        eprintln!("no wgpu adapter: skipped");
        return;
    };
    let harness = Harness::new(rs.clone(), [900, 640]);
    let geometry = geometry(&generate::torus(100, 100), Structure::HalfEdge);
    let mut view = View3d::new(Some(&rs));
    view.set_geometry(geometry.clone(), true);
    // A selection on a dense mesh: the three labels would overlap.
    let mut styles = styles_for(&geometry);
    *entry(&mut styles, ElementKind::Face, 0) = ElementStyle {
        colour: Some(YELLOW),
        faded: false,
        label: Some("0: Left Face".to_owned()),
    };
    *entry(&mut styles, ElementKind::Edge, 0) = ElementStyle {
        colour: Some(GREEN),
        faded: false,
        label: Some("0: Incident Edge".to_owned()),
    };
    *entry(&mut styles, ElementKind::Vertex, 0) = ElementStyle {
        colour: Some(PURPLE),
        faded: false,
        label: Some("0: Selected Vertex".to_owned()),
    };
    let options = ViewOptions::default();
    let (image, _) = harness.show(&mut view, &styles, &options, Vec::new());
    image.save("torus_20k.png");
    // Among 20k faces, the styled vertex is drawn where the CPU projects it,
    // and clicking there picks it.
    let transforms = view.transforms(harness.screen());
    let (at, _) = transforms
        .project(geometry.positions[0])
        .expect("vertex 0 is in view");
    image.zoomed(at, 200, 2).save("torus_20k_labels_zoom.png");
    assert!(
        image.any_near(at, 3, |p| is_near_colour(p, PURPLE, 70)),
        "no purple near {at:?}: {:?}",
        image.pixel(at.x as u32, at.y as u32)
    );
    assert_eq!(
        view.pick_at(harness.screen(), at, &options),
        Some(ElementRef::new(ElementKind::Vertex, 0))
    );
    // Close up on the outer equator: the coarse arrow and sphere templates.
    view.set_camera(Camera {
        target: [2.6, 0.0, 0.0],
        yaw: 1.2,
        pitch: 0.3,
        distance: 0.9,
    });
    let (close, _) = harness.show(&mut view, &styles, &options, Vec::new());
    close.save("torus_20k_close.png");
    // Close up, the mesh fills the view: its middle is not the background.
    let middle = close.pixel(450, 320);
    assert_ne!(middle, image.pixel(0, 0), "nothing drawn in the close-up");
}

/// A mesh whose edges are a few pixels long is drawn coarse: edges as lines,
/// no vertex spheres, but the highlighted vertex and edge in full. Closer
/// up, the full arrows and spheres return.
#[test]
fn a_dense_mesh_far_away_is_drawn_coarse_with_its_highlights_in_full() {
    let Some(rs) = support::gpu::render_state() else {
        eprintln!("no wgpu adapter: skipped");
        return;
    };
    let harness = Harness::new(rs.clone(), [640, 480]);
    let geometry = geometry(&generate::torus(200, 200), Structure::HalfEdge);
    let mut view = View3d::new(Some(&rs));
    view.set_geometry(geometry.clone(), true);
    let mut styles = styles_for(&geometry);
    *entry(&mut styles, ElementKind::Vertex, 0) = ElementStyle {
        colour: Some(PURPLE),
        faded: false,
        label: Some("0: Selected Vertex".to_owned()),
    };
    *entry(&mut styles, ElementKind::Edge, 0) = ElementStyle {
        colour: Some(GREEN),
        faded: false,
        label: None,
    };
    let options = ViewOptions::default();
    let (far, _) = harness.show(&mut view, &styles, &options, Vec::new());
    far.save("torus_80k_coarse.png");
    assert!(view.coarse(), "80k faces seen whole are drawn coarse");
    let transforms = view.transforms(harness.screen());
    let (at, _) = transforms
        .project(geometry.positions[0])
        .expect("vertex 0 is in view");
    far.zoomed(at, 120, 3).save("torus_80k_coarse_zoom.png");
    assert!(
        far.any_near(at, 4, |p| is_near_colour(p, PURPLE, 70)),
        "the highlighted vertex keeps its sphere: {:?}",
        far.pixel(at.x as u32, at.y as u32)
    );
    // The wireframe is drawn: many pixels are neither background nor face.
    let background = far.pixel(0, 0);
    let drawn = (0..far.height)
        .step_by(4)
        .flat_map(|y| (0..far.width).step_by(4).map(move |x| (x, y)))
        .filter(|&(x, y)| far.pixel(x, y) != background)
        .count();
    assert!(drawn > 2000, "only {drawn} sampled pixels drawn");

    // A selection moving while coarse patches styles that full detail has
    // not drawn yet; they are written with the arrows when it first does.
    // The new highlights lie in the close-up below.
    let close_camera = Camera {
        target: [1.35, 0.0, 0.0],
        yaw: 1.2,
        pitch: 0.3,
        distance: 0.4,
    };
    let mut direct_view = View3d::new(Some(&rs));
    direct_view.set_geometry(geometry.clone(), false);
    direct_view.set_camera(close_camera);
    harness.show(&mut direct_view, &styles, &options, Vec::new());
    let middle = Rect::from_center_size(harness.screen().center(), Vec2::splat(200.0));
    let in_close_up = |kind, count: usize| {
        (0..u32::try_from(count).unwrap_or(u32::MAX))
            .find(|&id| {
                direct_view
                    .screen_position(ElementRef::new(kind, id))
                    .is_some_and(|at| middle.contains(at))
            })
            .expect("an element in the close-up")
    };
    let edge = in_close_up(ElementKind::Edge, geometry.edges.len());
    let face = in_close_up(ElementKind::Face, geometry.faces.len());
    styles.generation += 1;
    styles
        .elements
        .remove(&ElementRef::new(ElementKind::Edge, 0));
    entry(&mut styles, ElementKind::Edge, edge).colour = Some(YELLOW);
    entry(&mut styles, ElementKind::Face, face).colour = Some(LIGHT_BLUE);
    harness.show(&mut view, &styles, &options, Vec::new());
    assert!(view.styles_patched() && view.coarse());

    view.set_camera(close_camera);
    let (close, _) = harness.show(&mut view, &styles, &options, Vec::new());
    close.save("torus_80k_close.png");
    assert!(!view.coarse(), "close up, arrows and spheres return");

    // The arrows, spheres and faces, uploaded only now with their styles,
    // draw what a view that was never coarse draws.
    let (direct, _) = harness.show(&mut direct_view, &styles, &options, Vec::new());
    assert!(!direct_view.coarse());
    assert!(
        close.pixels == direct.pixels,
        "detail uploaded on the way in draws differently"
    );
}

/// A selection changing on a big mesh patches the styles of the elements it
/// touches; the picture must be exactly what styles sent whole draw, in full
/// and at the coarse level of detail, faces included.
#[test]
fn patched_styles_draw_what_whole_styles_draw() {
    let Some(rs) = support::gpu::render_state() else {
        eprintln!("no wgpu adapter: skipped");
        return;
    };
    let harness = Harness::new(rs.clone(), [480, 360]);
    for (polygons, coarse) in [
        (generate::grid(4, 3), false),
        (generate::torus(120, 120), true),
    ] {
        let geometry = geometry(&polygons, Structure::HalfEdge);
        let mut first = styles_for(&geometry);
        first.fade_others = true;
        entry(&mut first, ElementKind::Face, 1).colour = Some(YELLOW);
        entry(&mut first, ElementKind::Edge, 2).colour = Some(GREEN);
        entry(&mut first, ElementKind::Vertex, 3).colour = Some(PURPLE);
        let mut second = first.clone();
        second.generation += 1;
        second
            .elements
            .remove(&ElementRef::new(ElementKind::Face, 1));
        second
            .elements
            .remove(&ElementRef::new(ElementKind::Edge, 2));
        entry(&mut second, ElementKind::Face, 5).colour = Some(GREEN);
        entry(&mut second, ElementKind::Edge, 7).colour = Some(YELLOW);
        entry(&mut second, ElementKind::Vertex, 3).colour = Some(YELLOW);
        let options = ViewOptions::default();

        let mut patched = View3d::new(Some(&rs));
        patched.set_geometry(geometry.clone(), true);
        harness.show(&mut patched, &first, &options, Vec::new());
        assert!(!patched.styles_patched(), "a new mesh's styles go whole");
        let (after_patch, _) = harness.show(&mut patched, &second, &options, Vec::new());
        assert!(patched.styles_patched());
        assert_eq!(patched.coarse(), coarse);

        let mut whole = View3d::new(Some(&rs));
        whole.set_geometry(geometry.clone(), true);
        let (drawn_whole, _) = harness.show(&mut whole, &second, &options, Vec::new());
        let differing = after_patch
            .pixels
            .chunks(4)
            .zip(drawn_whole.pixels.chunks(4))
            .filter(|(a, b)| a != b)
            .count();
        if differing > 0 {
            after_patch.save(&format!("patched_{coarse}.png"));
            drawn_whole.save(&format!("whole_{coarse}.png"));
        }
        assert_eq!(differing, 0, "coarse: {coarse}");

        // Clearing the highlights stops the others fading: the frame
        // uniform's, so still patches.
        let mut cleared = second.clone();
        cleared.generation += 1;
        cleared.fade_others = false;
        cleared.elements.clear();
        let (after_clear, _) = harness.show(&mut patched, &cleared, &options, Vec::new());
        assert!(patched.styles_patched(), "unfading patches");
        let mut fresh = View3d::new(Some(&rs));
        fresh.set_geometry(geometry.clone(), true);
        let (cleared_whole, _) = harness.show(&mut fresh, &cleared, &options, Vec::new());
        assert_eq!(
            after_clear.pixels, cleared_whole.pixels,
            "coarse: {coarse}, cleared"
        );
        harness.show(&mut patched, &second, &options, Vec::new());
        assert!(patched.styles_patched(), "fading again patches");

        // The first styles' highlights are gone: no yellow face 1 left.
        assert_ne!(
            after_patch.pixels,
            harness
                .show(&mut whole, &first, &options, Vec::new())
                .0
                .pixels
        );
    }
}

/// A torus of 14,400 vertices in a 480×360 view, which sees it whole and
/// coarse, and its plain styles; None without a wgpu adapter.
fn coarse_torus() -> Option<(RenderState, Harness, MeshGeometry, SceneStyles)> {
    let Some(rs) = support::gpu::render_state() else {
        eprintln!("no wgpu adapter: skipped");
        return None;
    };
    let harness = Harness::new(rs.clone(), [480, 360]);
    let geometry = geometry(&generate::torus(120, 120), Structure::HalfEdge);
    let styles = styles_for(&geometry);
    Some((rs, harness, geometry, styles))
}

/// The coarse level of detail copied from its base image looks as drawing
/// it directly does; a step or selection then keeps the image, and a turn
/// of the camera draws it again.
#[test]
fn the_coarse_base_image_draws_what_drawing_directly_does() {
    let Some((rs, harness, geometry, styles)) = coarse_torus() else {
        return;
    };
    let from_image = ViewOptions::default();
    let direct = ViewOptions {
        base_image: false,
        ..ViewOptions::default()
    };
    let mut view = View3d::new(Some(&rs));
    view.set_geometry(geometry.clone(), true);
    let (copied, _) = harness.show(&mut view, &styles, &from_image, Vec::new());
    assert!(view.coarse());
    // Two frames: the image drawn once and copied twice.
    assert_eq!(view.base_image_counts(), Some([1, 2]));
    let (drawn, _) = harness.show(&mut view, &styles, &direct, Vec::new());
    assert_eq!(
        view.base_image_counts(),
        Some([1, 2]),
        "off: drawn directly"
    );
    // Blending into the image and then over the backdrop rounds to 8 bits
    // twice; no channel may move further than that.
    let worst = worst_channel_difference(&copied.pixels, &drawn.pixels);
    if worst > 2 {
        copied.save("base_image_copied.png");
        drawn.save("base_image_drawn.png");
    }
    assert!(worst <= 2, "a channel differs by {worst}");

    // A new highlight over the kept image, the others faded by the copy.
    let mut stepped = styles.clone();
    stepped.generation += 1;
    stepped.fade_others = true;
    entry(&mut stepped, ElementKind::Vertex, 3).colour = Some(PURPLE);
    entry(&mut stepped, ElementKind::Edge, 7).colour = Some(GREEN);
    let (after_step, _) = harness.show(&mut view, &stepped, &from_image, Vec::new());
    assert_eq!(
        view.base_image_counts(),
        Some([1, 4]),
        "a step keeps the image"
    );
    let (direct_step, _) = harness.show(&mut view, &stepped, &direct, Vec::new());
    // Fading the picture as a whole fades each line and face as drawing
    // them faded does, to a few levels where faces overlap.
    let differing = after_step
        .pixels
        .chunks(4)
        .zip(direct_step.pixels.chunks(4))
        .filter(|(a, b)| a.iter().zip(b.iter()).any(|(x, y)| x.abs_diff(*y) > 4))
        .count();
    // Only where a highlight lies under a see-through face may they differ:
    // copied, the highlight is drawn over the faces.
    after_step.save("base_image_step.png");
    direct_step.save("base_image_step_drawn.png");
    assert!(differing < 400, "{differing} pixels differ after a step");
    assert_ne!(after_step.pixels, copied.pixels, "the new highlight shows");

    // A turn of the camera, or solid faces, draws the mesh again.
    let mut camera = view.camera();
    camera.yaw += 0.3;
    view.set_camera(camera);
    harness.show(&mut view, &stepped, &from_image, Vec::new());
    assert_eq!(view.base_image_counts(), Some([2, 6]));
    let solid = ViewOptions {
        solid_faces: true,
        ..ViewOptions::default()
    };
    harness.show(&mut view, &stepped, &solid, Vec::new());
    assert_eq!(view.base_image_counts(), Some([2, 6]), "solid faces hide");

    // Off the view's centre, the copy, which covers only the part of the
    // view the mesh can reach, still misses none of it.
    camera.target = [0.9, 0.6, 0.0];
    view.set_camera(camera);
    let (copied_aside, _) = harness.show(&mut view, &styles, &from_image, Vec::new());
    assert_eq!(view.base_image_counts(), Some([3, 8]));
    let (drawn_aside, _) = harness.show(&mut view, &styles, &direct, Vec::new());
    assert_ne!(drawn_aside.pixels, drawn.pixels, "the mesh moved");
    let worst = worst_channel_difference(&copied_aside.pixels, &drawn_aside.pixels);
    if worst > 2 {
        copied_aside.save("base_image_aside_copied.png");
        drawn_aside.save("base_image_aside_drawn.png");
    }
    assert!(worst <= 2, "aside, a channel differs by {worst}");
}

/// A new mesh's base image is drawn a part a frame, each frame asking for
/// the next, and the parts make the picture drawing it whole does; a turn
/// of the camera then draws it whole at once.
#[test]
fn a_new_mesh_s_base_image_is_drawn_in_parts_that_make_the_whole() {
    // 43,200 lines and 28,800 triangles: eight parts of 10,000.
    let Some((rs, harness, geometry, styles)) = coarse_torus() else {
        return;
    };
    let by_parts = ViewOptions {
        base_image_part: 10_000,
        ..ViewOptions::default()
    };
    let whole = ViewOptions {
        base_image_part: u32::MAX,
        ..ViewOptions::default()
    };
    let mut reference = View3d::new(Some(&rs));
    reference.set_geometry(geometry.clone(), true);
    let first = harness.frame(Vec::new(), |ui| {
        reference.ui(ui, &styles, &whole);
    });
    assert!(reference.coarse());
    assert_eq!(reference.base_image_counts(), Some([1, 1]), "drawn at once");

    let mut view = View3d::new(Some(&rs));
    view.set_geometry(geometry, true);
    let mut pictures = Vec::new();
    let mut asked_again = Vec::new();
    while view
        .base_image_counts()
        .is_some_and(|[drawn, _]| drawn == 0)
        && pictures.len() < 20
    {
        pictures.push(harness.frame(Vec::new(), |ui| {
            view.ui(ui, &styles, &by_parts);
        }));
        asked_again.push(harness.ctx.has_requested_repaint());
    }
    // The first frame uploads the mesh and draws none of it.
    assert_eq!(pictures.len(), 9, "a frame, then eight draw the image");
    assert_eq!(view.base_image_counts(), Some([1, 9]), "each copies it");
    assert!(
        asked_again[..8].iter().all(|asked| *asked),
        "each part asks for the next frame: {asked_again:?}"
    );
    let [empty, partial, .., last] = pictures.as_slice() else {
        unreachable!("nine pictures");
    };
    assert_ne!(
        empty.pixels, partial.pixels,
        "the second frame draws a part"
    );
    assert_ne!(partial.pixels, last.pixels, "and only a part");
    if last.pixels != first.pixels {
        last.save("base_image_parts.png");
        first.save("base_image_whole.png");
    }
    assert!(
        last.pixels == first.pixels,
        "the parts make the whole, pixel for pixel"
    );

    // The same mesh seen from elsewhere is drawn whole, in one frame.
    let mut camera = view.camera();
    camera.yaw += 0.3;
    view.set_camera(camera);
    harness.frame(Vec::new(), |ui| {
        view.ui(ui, &styles, &by_parts);
    });
    assert_eq!(view.base_image_counts(), Some([2, 10]));
}

/// `-` pressed: the keyboard's step of the camera away from the mesh.
fn minus_key() -> egui::Event {
    egui::Event::Key {
        key: egui::Key::Minus,
        physical_key: None,
        pressed: true,
        repeat: false,
        modifiers: egui::Modifiers::NONE,
    }
}

/// The pixels of `image` that are not its top-left pixel's colour (the
/// background).
fn drawn_mask(image: &Image) -> Vec<bool> {
    let background = image.pixel(0, 0);
    image.pixels.chunks(4).map(|p| p != background).collect()
}

/// Frames of `view` until its base image has been drawn whole `count`
/// times in all, each frame's picture; at most 60.
fn frames_until_drawn(
    harness: &Harness,
    view: &mut View3d,
    styles: &SceneStyles,
    options: &ViewOptions,
    count: u64,
) -> Vec<Image> {
    let mut pictures = Vec::new();
    while view
        .base_image_counts()
        .is_some_and(|[drawn, _]| drawn < count)
        && pictures.len() < 60
    {
        pictures.push(harness.frame(Vec::new(), |ui| {
            view.ui(ui, styles, options);
        }));
    }
    pictures
}

/// A large mesh is drawn from its motion proxy, the same shape from far
/// fewer lines and faces, while its new base image is drawn a part a frame,
/// and while the camera moves (the image waits); once the camera has
/// rested for a while, the image is drawn again behind the proxy, and then
/// shows exactly what a view that never drew the proxy shows. A resize
/// draws the image behind the proxy too.
#[test]
fn a_large_mesh_is_drawn_from_its_motion_proxy_while_the_camera_moves() {
    let Some(rs) = support::gpu::render_state() else {
        eprintln!("no wgpu adapter: skipped");
        return;
    };
    let harness = Harness::new(rs.clone(), [480, 360]);
    // 120k lines and 80k triangles: more than a proxy is made for, and
    // four parts of 50k.
    let geometry = geometry(&generate::torus(200, 200), Structure::HalfEdge);
    let styles = styles_for(&geometry);
    let options = ViewOptions {
        base_image_part: 50_000,
        ..ViewOptions::default()
    };
    let mut view = View3d::new(Some(&rs));
    view.set_geometry(geometry.clone(), true);
    let loading = frames_until_drawn(&harness, &mut view, &styles, &options, 1);
    assert!(view.coarse());
    assert_eq!(loading.len(), 5, "a frame uploads, four draw the image");
    assert_eq!(
        view.motion_proxy_frames(),
        Some(3),
        "the upload's frame draws nothing, the proxy shows until the last part"
    );
    assert_eq!(view.base_image_counts(), Some([1, 1]), "then the image");

    let moving = harness.frame(vec![minus_key()], |ui| {
        view.ui(ui, &styles, &options);
    });
    assert_eq!(
        view.motion_proxy_frames(),
        Some(4),
        "the step draws the proxy"
    );
    assert_eq!(
        view.base_image_counts(),
        Some([1, 1]),
        "and the image waits"
    );

    // The same camera, never moved: the mesh itself.
    let itself = ViewOptions {
        motion_proxy: false,
        base_image_part: u32::MAX,
        ..options.clone()
    };
    let mut reference = View3d::new(Some(&rs));
    reference.set_geometry(geometry, true);
    reference.set_camera(view.camera());
    let (whole, _) = harness.show(&mut reference, &styles, &itself, Vec::new());
    assert_eq!(reference.motion_proxy_frames(), Some(0));
    assert_eq!(reference.base_image_counts(), Some([1, 2]));
    assert_ne!(moving.pixels, whole.pixels, "the proxy is not the mesh");
    // But it covers what the mesh covers, to a pixel or two at the edges.
    let (a, b) = (drawn_mask(&moving), drawn_mask(&whole));
    let both = a.iter().zip(&b).filter(|(x, y)| **x && **y).count();
    let either = a.iter().zip(&b).filter(|(x, y)| **x || **y).count();
    moving.save("motion_proxy.png");
    whole.save("motion_proxy_rested.png");
    assert!(
        both as f64 > 0.9 * either as f64,
        "the proxy covers {both} of the {either} pixels either covers"
    );

    // egui's clock runs 1/60 s a frame here: the camera rests after 0.3 s,
    // about 18 frames, and the image is then drawn in four.
    let pictures = frames_until_drawn(&harness, &mut view, &styles, &options, 2);
    let proxy_frames = view.motion_proxy_frames().unwrap_or(0) - 3;
    assert!(
        (18..=24).contains(&proxy_frames),
        "{proxy_frames} frames drew the proxy since the step"
    );
    let [.., behind, last] = pictures.as_slice() else {
        panic!("{} frames", pictures.len());
    };
    assert!(
        behind.pixels == moving.pixels,
        "the proxy shows until the image is done"
    );
    assert!(
        last.pixels == whole.pixels,
        "then the mesh, as if never moved"
    );
    assert_eq!(
        view.base_image_counts().map(|[drawn, _]| drawn),
        Some(2),
        "drawn once more"
    );

    // A smaller view, as when a panel opens beside it, draws its image
    // behind the proxy too, from its first frame.
    let before = view.motion_proxy_frames().unwrap_or(0);
    let mut resized = Vec::new();
    while view.base_image_counts().is_some_and(|[drawn, _]| drawn < 3) && resized.len() < 10 {
        resized.push(harness.frame(Vec::new(), |ui| {
            ui.allocate_ui(Vec2::new(400.0, 300.0), |ui| {
                view.ui(ui, &styles, &options);
            });
        }));
    }
    assert_eq!(resized.len(), 4, "four parts");
    assert_eq!(
        view.motion_proxy_frames(),
        Some(before + 3),
        "the proxy shows until the last"
    );
}
