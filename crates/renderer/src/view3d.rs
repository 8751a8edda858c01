//! The 3D view: the mesh drawn with wgpu inside egui, with camera and picking.
//!
//! - Vertices are spheres, edges arrows pointing at their end vertex (a
//!   half-edge mesh shows each edge as two arrows, each inset into its own
//!   face), faces are filled and mostly see-through.
//! - Drawing goes through an egui paint callback (`renderer::ViewCallback`):
//!   instanced, one draw per element kind; geometry buffers are rebuilt only
//!   when the mesh changes and style buffers only when the styles'
//!   generation changes. Each drawable file (spheres, arrows, faces,
//!   orientation) owns its instance type, pipeline, buffers and draw call;
//!   `gpu` is the plumbing they share.
//! - Labels, pointers and the hover preview are egui shapes painted over it.
//! - Camera, picking and labels work without a GPU (headless UI tests).
//!
//! The app must run eframe with `depth_buffer: 24` ([`gpu::DEPTH_BITS`]).

mod arrows;
mod axes;
mod base_image;
mod bvh;
mod coarse;
mod faces;
mod gpu;
mod labels;
mod motion_proxy;
mod orientation;
mod picking;
mod renderer;
mod spheres;
mod style;

use edgewise_core::schema::{ElementKind, ElementRef};
use std::collections::BTreeMap;
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};

use egui::{PointerButton, Rect, Sense};
use glam::Vec3;

pub use gpu::{DEPTH_BITS, depth_format};

use edgewise_pictures::camera::{Camera, ViewTransforms};
use edgewise_pictures::geometry::MeshGeometry;
use edgewise_pictures::options::{PickFilter, ViewOptions};
use edgewise_pictures::palette::Palette;
use edgewise_pictures::scene::Scene;
use edgewise_pictures::styles::{ElementStyle, SceneStyles};
use edgewise_pictures::vector;
use gpu::FrameUniform;
use picking::{PickAccel, PickQuery};
use renderer::{DrawFlags, GeometryUpload, Renderers, StyleUpload, UploadState, ViewCallback};

/// Edges shorter than this many points on screen (the mean edge, at the
/// mesh's centre) are drawn as lines, without vertex spheres: arrows that
/// small show no direction, and cost a software renderer 36 triangles each.
pub const COARSE_BELOW_POINTS: f32 = 6.0;

/// Meshes of at most this many edges (or half-edges) always draw in full:
/// they are cheap at any size.
pub const COARSE_ABOVE_EDGES: usize = 3_000;

/// What the view's styles were built for: the styles' generation, the
/// palette's base colours (line, boundary, face) and the geometry.
type StylesKey = (u64, (egui::Color32, egui::Color32, egui::Color32), u64);

/// How long, in seconds, the camera must rest before a mesh drawn from its
/// motion proxy is drawn whole again: longer than the gap between two
/// frames of a drag on a slow machine, so that a drag does not redraw the
/// whole mesh between two moves.
const MOTION_SETTLE: f64 = 0.3;

/// How far, in points, the base image's copy reaches past the projection
/// of the mesh's bounding box: its lines are a pixel wide, and rounding to
/// pixels moves an edge by less than one.
const MESH_EXTENT_MARGIN: f32 = 2.0;

/// What happened in the view this frame.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ViewResponse {
    /// An element was clicked.
    pub clicked: Option<ElementRef>,
    /// The element under the pointer (the preview).
    pub hovered: Option<ElementRef>,
    /// The background was clicked (the selection should clear).
    pub background_clicked: bool,
    /// An element was right-clicked, at this point: the edit menu.
    pub context: Option<(ElementRef, egui::Pos2)>,
}

/// Ids for views and uploads, unique in the process.
fn next_id() -> u64 {
    static NEXT: AtomicU64 = AtomicU64::new(1);
    NEXT.fetch_add(1, Ordering::Relaxed)
}

/// The link to the GPU side, when there is one.
struct GpuLink {
    renderer: Arc<egui::mutex::RwLock<egui_wgpu::Renderer>>,
    uploaded: Arc<UploadState>,
    /// CPU copies waiting for the next `prepare`.
    geometry: Option<Arc<GeometryUpload>>,
    styles: Option<Arc<StyleUpload>>,
}

impl GpuLink {
    /// Drops the CPU copies the GPU side has taken.
    fn drop_taken(&mut self) {
        if self
            .geometry
            .as_ref()
            .is_some_and(|g| self.uploaded.geometry.load(Ordering::Acquire) == g.id)
        {
            self.geometry = None;
        }
        if self
            .styles
            .as_ref()
            .is_some_and(|s| self.uploaded.styles.load(Ordering::Acquire) == s.id)
        {
            self.styles = None;
        }
    }
}

/// A mesh's view geometry made a slice at a time: the scene, each picking
/// hierarchy, the GPU arrays, then the motion proxy. Run one slice per
/// frame, a large mesh never freezes the page; [`View3d::show_prepared`]
/// then shows it.
pub struct Preparation {
    geometry: Option<MeshGeometry>,
    scene: Option<Scene>,
    accel: PickAccel,
    upload: Option<GeometryUpload>,
    with_gpu: bool,
    done: usize,
}

impl Preparation {
    /// How many slices there are.
    pub const SLICES: usize = 6;

    /// Geometry to prepare; `with_gpu` says whether GPU arrays are wanted
    /// ([`View3d::has_gpu`]).
    pub fn new(geometry: MeshGeometry, with_gpu: bool) -> Self {
        Self {
            geometry: Some(geometry),
            scene: None,
            accel: PickAccel::default(),
            upload: None,
            with_gpu,
            done: 0,
        }
    }

    /// Makes the next slice; true once every slice is made.
    pub fn step(&mut self) -> bool {
        match (self.done, &self.scene) {
            (0, _) => {
                let geometry = self.geometry.take().unwrap_or_default();
                self.scene = Some(Scene::new(geometry));
            }
            (1, Some(scene)) => self.accel.build(scene, ElementKind::Vertex),
            (2, Some(scene)) => self.accel.build(scene, ElementKind::Edge),
            (3, Some(scene)) => self.accel.build(scene, ElementKind::Face),
            (4, Some(scene)) if self.with_gpu => self.upload = Some(Self::upload(scene)),
            (5, Some(scene)) => {
                if let Some(upload) = &mut self.upload {
                    upload.proxy = motion_proxy::proxy(&upload.coarse, scene.bounds);
                }
            }
            _ => {}
        }
        self.done = (self.done + 1).min(Self::SLICES);
        self.is_done()
    }

    /// Whether every slice is made.
    pub fn is_done(&self) -> bool {
        self.done == Self::SLICES
    }

    /// The share of the slices made, from 0 to 1.
    pub fn progress(&self) -> f32 {
        self.done as f32 / Self::SLICES as f32
    }

    /// The GPU arrays of a scene (their id is set when shown), but for
    /// the motion proxy, a slice of its own.
    fn upload(scene: &Scene) -> GeometryUpload {
        GeometryUpload {
            id: 0,
            spheres: spheres::instances(scene),
            arrows: arrows::instances(scene),
            faces: faces::corners(scene),
            marks: orientation::instances(scene),
            coarse: coarse::geometry(scene),
            proxy: None,
        }
    }
}

/// Inputs that decide the hovered element; picking reruns only when they
/// change.
#[derive(Clone, Copy, Debug, PartialEq)]
struct HoverKey {
    pointer: egui::Pos2,
    camera: Camera,
    viewport: Rect,
    geometry_id: u64,
    sizes_key: u32,
    filter: PickFilter,
    solid: bool,
}

/// The 3D view.
pub struct View3d {
    id: u64,
    camera: Camera,
    scene: Scene,
    accel: PickAccel,
    geometry_id: u64,
    styles_id: u64,
    /// (styles generation, dark, geometry id) the current styles were built for.
    styles_key: Option<StylesKey>,
    /// Elements with a colour or label, for the labels pass.
    highlighted: Vec<ElementRef>,
    /// The entries and fading the current GPU styles were built from, for
    /// patching only what the next styles change.
    shown: BTreeMap<ElementRef, ElementStyle>,
    fade_others: bool,
    /// Whether the last styles went to the GPU as patches.
    patched: bool,
    last_aspect: f32,
    /// Whether the last frame drew the coarse level of detail.
    coarse: bool,
    /// When the pointer or keys last moved the camera (egui's clock).
    camera_moved_at: Option<f64>,
    /// Where the view was drawn last, for [`Self::screen_position`].
    last_viewport: Option<Rect>,
    frame_pending: bool,
    hover: Option<(HoverKey, Option<ElementRef>)>,
    /// An element hovered elsewhere (a table row), outlined as if the
    /// pointer were on it.
    preview: Option<ElementRef>,
    gpu: Option<GpuLink>,
}

impl View3d {
    /// Creates the renderers if a wgpu render state exists (None in
    /// headless UI tests).
    pub fn new(render_state: Option<&egui_wgpu::RenderState>) -> Self {
        let gpu = render_state.map(|render_state| {
            Renderers::install(render_state);
            GpuLink {
                renderer: render_state.renderer.clone(),
                uploaded: Arc::new(UploadState::default()),
                geometry: None,
                styles: None,
            }
        });
        let mut view = Self {
            id: next_id(),
            camera: Camera::default(),
            scene: Scene::new(MeshGeometry::default()),
            accel: PickAccel::default(),
            geometry_id: 0,
            styles_id: 0,
            styles_key: None,
            highlighted: Vec::new(),
            shown: BTreeMap::new(),
            fade_others: false,
            patched: false,
            last_aspect: 1.5,
            coarse: false,
            camera_moved_at: None,
            last_viewport: None,
            frame_pending: false,
            hover: None,
            preview: None,
            gpu,
        };
        view.set_geometry(MeshGeometry::default(), false);
        view
    }

    /// Whether the view draws with a GPU (not in headless UI tests).
    pub fn has_gpu(&self) -> bool {
        self.gpu.is_some()
    }

    /// Replaces the geometry (a new mesh or a structure switch) and frames it
    /// if `frame` is true.
    pub fn set_geometry(&mut self, geometry: MeshGeometry, frame: bool) {
        let prepared = Preparation::new(geometry, self.has_gpu());
        self.show_prepared(prepared, frame);
    }

    /// Shows geometry prepared by [`Preparation`] (doing whatever slices it
    /// has left), framing it if `frame` is true.
    pub fn show_prepared(&mut self, mut prepared: Preparation, frame: bool) {
        while !prepared.step() {}
        self.scene = prepared
            .scene
            .take()
            .unwrap_or_else(|| Scene::new(MeshGeometry::default()));
        self.accel = std::mem::take(&mut prepared.accel);
        self.geometry_id = next_id();
        self.styles_key = None;
        self.highlighted.clear();
        self.hover = None;
        if let Some(gpu) = &mut self.gpu {
            let mut upload = prepared.upload.take().unwrap_or_else(|| {
                let mut upload = Preparation::upload(&self.scene);
                upload.proxy = motion_proxy::proxy(&upload.coarse, self.scene.bounds);
                upload
            });
            upload.id = self.geometry_id;
            gpu.geometry = Some(Arc::new(upload));
            gpu.styles = None;
        }
        if frame {
            self.frame_all();
            // The viewport's shape is known at the next `ui`.
            self.frame_pending = true;
        }
    }

    /// Frames the whole mesh.
    /// Outlines `element` this frame as if the pointer were on it: the
    /// preview of a table row under the pointer.
    pub fn set_preview(&mut self, element: Option<ElementRef>) {
        self.preview = element;
    }

    pub fn frame_all(&mut self) {
        self.scene.frame(&mut self.camera, self.last_aspect);
    }

    /// The camera, as plain data.
    pub fn camera(&self) -> Camera {
        self.camera
    }

    pub fn set_camera(&mut self, camera: Camera) {
        self.camera = camera.sanitized();
        self.frame_pending = false;
    }

    /// The transforms of the last known viewport (for tests and the app's
    /// own projections).
    pub fn transforms(&self, viewport: Rect) -> ViewTransforms {
        ViewTransforms::new(self.camera, viewport, self.scene.center, self.scene.radius)
    }

    /// The element under a point of `viewport`, as a click there would pick.
    pub fn pick_at(
        &self,
        viewport: Rect,
        pointer: egui::Pos2,
        options: &ViewOptions,
    ) -> Option<ElementRef> {
        let transforms = self.transforms(viewport);
        PickQuery {
            scene: &self.scene,
            accel: &self.accel,
            transforms: &transforms,
            sizes: self.scene.sizes(options.mesh_scale),
            filter: options.pickable,
            solid_faces: options.solid_faces,
        }
        .pick(pointer)
    }

    /// Where an element's label attaches, in world space (None for an id out
    /// of range).
    pub fn anchor(&self, pick: ElementRef) -> Option<Vec3> {
        self.scene.anchor(pick)
    }

    /// Whether the last frame drew the coarse level of detail: edges as
    /// lines, no vertex spheres, highlighted elements in full.
    pub fn coarse(&self) -> bool {
        self.coarse
    }

    /// How many times the coarse level of detail's base image was drawn,
    /// and copied to the screen instead of drawing the mesh; `None`
    /// without a GPU.
    pub fn base_image_counts(&self) -> Option<[u64; 2]> {
        let uploaded = &self.gpu.as_ref()?.uploaded;
        Some([
            uploaded.base_image_drawn.load(Ordering::Relaxed),
            uploaded.base_image_copied.load(Ordering::Relaxed),
        ])
    }

    /// How many frames drew the motion proxy in place of the mesh's coarse
    /// lines and faces; `None` without a GPU.
    pub fn motion_proxy_frames(&self) -> Option<u64> {
        let uploaded = &self.gpu.as_ref()?.uploaded;
        Some(uploaded.proxy_drawn.load(Ordering::Relaxed))
    }

    /// Whether the mesh's edges are so small on screen, and so many, that
    /// arrows and spheres would cost far more than they show: the mean edge
    /// at the mesh's centre under [`COARSE_BELOW_POINTS`] long, and more
    /// than [`COARSE_ABOVE_EDGES`] edges.
    fn is_small_on_screen(&self, transforms: &ViewTransforms) -> bool {
        if self.scene.edge_count() <= COARSE_ABOVE_EDGES {
            return false;
        }
        let distance = (self.scene.center - transforms.eye).length();
        self.scene.unit < COARSE_BELOW_POINTS * transforms.world_per_point(distance)
    }

    /// Whether the last change of styles went to the GPU as patches of the
    /// elements it changed, rather than as every element's style.
    pub fn styles_patched(&self) -> bool {
        self.patched
    }

    /// The view as vector shapes, from the camera and in the colours of
    /// the last frame drawn; `None` before the first.
    pub fn vector_view(&self, options: &ViewOptions) -> Option<vector::VectorView> {
        let looks = vector::Looks {
            styles: &self.shown,
            fade_others: self.fade_others,
        };
        self.vector_view_with(&self.scene, &looks, options)
    }

    /// [`Self::vector_view`] of another moment from the same camera: the
    /// mesh as `geometry` (the view's own when `None`) in `styles`, for a
    /// handout's pages.
    pub fn vector_view_of(
        &self,
        geometry: Option<MeshGeometry>,
        styles: &SceneStyles,
        options: &ViewOptions,
    ) -> Option<vector::VectorView> {
        let looks = vector::Looks {
            styles: &styles.elements,
            fade_others: styles.fade_others,
        };
        match geometry {
            Some(geometry) => self.vector_view_with(&Scene::new(geometry), &looks, options),
            None => self.vector_view_with(&self.scene, &looks, options),
        }
    }

    fn vector_view_with(
        &self,
        scene: &Scene,
        looks: &vector::Looks<'_>,
        options: &ViewOptions,
    ) -> Option<vector::VectorView> {
        let viewport = self.last_viewport?;
        Some(vector::vector_view(
            scene,
            looks,
            &self.transforms(viewport),
            options,
        ))
    }

    /// Takes `rect` as the view's place, framing the mesh if a new one
    /// waits for it, and `styles` as its colours: what every frame does
    /// before drawing.
    fn place(&mut self, rect: Rect, styles: &SceneStyles, options: &ViewOptions) -> Palette {
        self.last_aspect = rect.aspect_ratio();
        self.last_viewport = Some(rect);
        if self.frame_pending {
            self.frame_all();
            self.frame_pending = false;
        }
        let palette = Palette::of(options);
        self.update_styles(styles, &palette);
        palette
    }

    /// Lays the view out `size` points big as its first frame in a window
    /// would, with no window and no GPU, so that [`Self::vector_view`]
    /// has a camera to draw from: `edgewise render`.
    pub fn lay_out_offscreen(
        &mut self,
        size: egui::Vec2,
        styles: &SceneStyles,
        options: &ViewOptions,
    ) {
        self.place(Rect::from_min_size(egui::Pos2::ZERO, size), styles, options);
    }

    /// Where an element's anchor (a vertex, an edge's middle, a face's
    /// centre) was on screen in the last frame drawn, in points; `None` if
    /// it is behind the eye, off the view, or not drawn yet.
    pub fn screen_position(&self, element: ElementRef) -> Option<egui::Pos2> {
        let viewport = self.last_viewport?;
        let (at, _) = self.transforms(viewport).project(self.anchor(element)?)?;
        viewport.contains(at).then_some(at)
    }

    /// Draws the view filling `ui`'s available rect and handles camera input
    /// and picking.
    pub fn ui(
        &mut self,
        ui: &mut egui::Ui,
        styles: &SceneStyles,
        options: &ViewOptions,
    ) -> ViewResponse {
        let (rect, response) = ui.allocate_exact_size(ui.available_size(), Sense::click_and_drag());
        if rect.width() < 1.0 || rect.height() < 1.0 {
            return ViewResponse::default();
        }
        let palette = self.place(rect, styles, options);
        let camera = self.camera;
        self.handle_camera_input(ui, &response, rect);
        let now = ui.input(|i| i.time);
        if self.camera != camera {
            self.camera_moved_at = Some(now);
        }

        let transforms = self.transforms(rect);
        self.coarse = self.is_small_on_screen(&transforms);
        let sizes = self.scene.sizes(options.mesh_scale);
        let query = PickQuery {
            scene: &self.scene,
            accel: &self.accel,
            transforms: &transforms,
            sizes,
            filter: options.pickable,
            solid_faces: options.solid_faces,
        };

        let dragging = response.dragged() || ui.input(|i| i.pointer.any_down());
        let hovered = match response.hover_pos() {
            Some(pointer) if !dragging => {
                let key = HoverKey {
                    pointer,
                    camera: self.camera,
                    viewport: rect,
                    geometry_id: self.geometry_id,
                    sizes_key: options.mesh_scale.to_bits(),
                    filter: options.pickable,
                    solid: options.solid_faces,
                };
                match self.hover {
                    Some((cached, pick)) if cached == key => pick,
                    _ => {
                        let pick = query.pick(pointer);
                        self.hover = Some((key, pick));
                        pick
                    }
                }
            }
            _ => None,
        };

        let mut view_response = ViewResponse {
            hovered,
            ..ViewResponse::default()
        };
        if response.clicked()
            && let Some(pointer) = response.interact_pointer_pos()
        {
            match query.pick(pointer) {
                Some(pick) => view_response.clicked = Some(pick),
                None => view_response.background_clicked = true,
            }
        }
        if response.secondary_clicked()
            && let Some(pointer) = response.interact_pointer_pos()
        {
            view_response.context = query.pick(pointer).map(|pick| (pick, pointer));
        }
        if hovered.is_some() && !dragging {
            ui.ctx().set_cursor_icon(egui::CursorIcon::PointingHand);
        } else if response.dragged() {
            ui.ctx().set_cursor_icon(egui::CursorIcon::Grabbing);
        }

        // Paint: background, the 3D callback, then overlays.
        let painter = ui.painter_at(rect);
        if !options.backdrop_cleared {
            painter.rect_filled(rect, 0.0, palette.background);
        }
        let moving = self.is_moving(ui.ctx(), now);
        self.add_callback(&painter, rect, &transforms, options, &palette, moving);
        let overlay = labels::Overlay {
            painter: &painter,
            transforms: &transforms,
            scene: &self.scene,
            accel: &self.accel,
            styles,
            options,
            sizes,
            palette,
        };
        let outlined = hovered.or(self.preview);
        if let Some(pick) = outlined {
            overlay.paint_hover(pick);
        }
        overlay.paint_labels(&self.highlighted, outlined);
        overlay.paint_pointers();
        if options.show_axes {
            overlay.paint_axis_letters();
        }
        view_response
    }

    /// Whether the camera moved within the last [`MOTION_SETTLE`] seconds;
    /// if so, asks for a frame when that time is up, to draw the mesh whole.
    fn is_moving(&self, ctx: &egui::Context, now: f64) -> bool {
        let Some(moved_at) = self.camera_moved_at else {
            return false;
        };
        let left = moved_at + MOTION_SETTLE - now;
        if left > 0.0 {
            ctx.request_repaint_after(std::time::Duration::from_secs_f64(left));
        }
        left > 0.0
    }

    fn handle_camera_input(&mut self, ui: &egui::Ui, response: &egui::Response, rect: Rect) {
        let (shift, scroll, zoom, touch) = ui.input(|i| {
            (
                i.modifiers.shift,
                i.smooth_scroll_delta,
                i.zoom_delta(),
                i.multi_touch(),
            )
        });
        let delta = response.drag_delta();
        // Two fingers pan (and pinch, through `zoom`); one finger orbits.
        let touch_pan = touch.filter(|t| t.num_touches >= 2 && response.contains_pointer());
        if let Some(touch) = touch_pan {
            self.camera.pan(touch.translation_delta, rect.height());
        } else if response.dragged_by(PointerButton::Primary) {
            if shift {
                self.camera.pan(delta, rect.height());
            } else {
                self.camera.orbit(delta);
            }
        }
        if response.dragged_by(PointerButton::Middle) {
            self.camera.pan(delta, rect.height());
        }
        if response.dragged_by(PointerButton::Secondary) {
            self.camera.zoom((-delta.y * 0.01).exp());
        }
        if response.contains_pointer() {
            if scroll.y != 0.0 {
                self.camera.zoom((scroll.y * 0.0025).exp());
                ui.ctx()
                    .input_mut(|i| i.smooth_scroll_delta = egui::Vec2::ZERO);
            }
            if zoom != 1.0 {
                self.camera.zoom(zoom);
            }
        }
        if response.double_clicked() {
            self.frame_all();
        }
        self.camera_keys(ui);
    }

    /// The camera from the keyboard, when no text field has it:
    /// Shift+arrows orbit by 15°, `+` and `-` zoom, Shift+Home frames the
    /// mesh. (Plain arrows and Home walk a trace.)
    fn camera_keys(&mut self, ui: &egui::Ui) {
        use egui::{Key, Modifiers};
        if ui.ctx().egui_wants_keyboard_input() {
            return;
        }
        // 32 points of drag turn the camera about 15 degrees.
        const TURN: f32 = 32.0;
        let (orbit, zoom, frame) = ui.input(|i| {
            let shifted = |key| i.modifiers.matches_exact(Modifiers::SHIFT) && i.key_pressed(key);
            let orbit = [
                (Key::ArrowLeft, egui::vec2(-TURN, 0.0)),
                (Key::ArrowRight, egui::vec2(TURN, 0.0)),
                (Key::ArrowUp, egui::vec2(0.0, -TURN)),
                (Key::ArrowDown, egui::vec2(0.0, TURN)),
            ]
            .into_iter()
            .filter(|(key, _)| shifted(*key))
            .fold(egui::Vec2::ZERO, |sum, (_, delta)| sum + delta);
            // Ctrl or Cmd with + and - zoom the page instead.
            let bare = !i.modifiers.command && !i.modifiers.alt;
            let zoom = if bare && (i.key_pressed(Key::Plus) || i.key_pressed(Key::Equals)) {
                1.25
            } else if bare && i.key_pressed(Key::Minus) {
                0.8
            } else {
                1.0
            };
            (orbit, zoom, shifted(Key::Home))
        });
        if orbit != egui::Vec2::ZERO {
            self.camera.orbit(orbit);
        }
        if zoom != 1.0 {
            self.camera.zoom(zoom);
        }
        if frame {
            self.frame_all();
        }
    }

    /// Brings the per-element GPU styles and the highlighted list up to
    /// date when the styles' generation, the theme or the mesh changed:
    /// patches for the elements whose look changed, or everything after a
    /// new mesh, theme or fading (or while the last upload is still on its
    /// way to the GPU).
    fn update_styles(&mut self, styles: &SceneStyles, palette: &Palette) {
        // The palette's base colours decide every plain element's style.
        let look = (palette.line, palette.boundary, palette.face);
        let key = (styles.generation, look, self.geometry_id);
        if self.styles_key == Some(key) {
            return;
        }
        // Fading the others is the frame uniform's, so it patches too.
        let same_base = self
            .styles_key
            .is_some_and(|(_, was, geometry)| was == look && geometry == self.geometry_id);
        self.styles_key = Some(key);
        let base_id = self.styles_id;
        self.styles_id = next_id();
        self.highlighted = styles
            .elements
            .iter()
            .filter(|(element, style)| {
                edgewise_pictures::styles::is_highlighted(style)
                    && self.scene.anchor(**element).is_some()
            })
            .map(|(element, _)| *element)
            .collect();
        if let Some(gpu) = &mut self.gpu {
            let context = style::StyleContext {
                scene: &self.scene,
                palette,
            };
            gpu.drop_taken();
            self.patched = same_base && gpu.styles.is_none();
            let upload = if self.patched {
                context.build_patches(&self.shown, styles, base_id, self.styles_id)
            } else {
                context.build_all(styles, self.styles_id)
            };
            gpu.styles = Some(Arc::new(upload));
        }
        self.shown.clone_from(&styles.elements);
        self.fade_others = styles.fade_others;
    }

    fn add_callback(
        &mut self,
        painter: &egui::Painter,
        rect: Rect,
        transforms: &ViewTransforms,
        options: &ViewOptions,
        palette: &Palette,
        moving: bool,
    ) {
        let Some(gpu) = &mut self.gpu else {
            return;
        };
        let pixels_per_point = painter.pixels_per_point();
        gpu.drop_taken();
        let sizes = self.scene.sizes(options.mesh_scale);
        // Unfaded: the shaders fade the coarse view with the plain elements
        // (`FrameUniform::fade`).
        let base = ElementStyle::default();
        // Coarse lines fade as the arrows they stand for would, by the mean
        // edge's length in pixels.
        let edge_pixels = self.scene.unit * pixels_per_point
            / transforms
                .world_per_point((self.scene.center - transforms.eye).length())
                .max(1e-30);
        let [r, g, b, _] = style::line_style(&base, palette).colour;
        let coarse_line = edgewise_pictures::palette::fade_small(
            egui::Color32::from_rgb(r, g, b),
            edge_pixels,
            24.0,
            palette,
        );
        let (right, up) = transforms.screen_axes();
        let light = (self.camera.backward() + up * 0.7 - right * 0.45).normalize_or_zero();
        let [r, g, b, _] = palette.orientation.to_normalized_gamma_f32();
        let frame = FrameUniform {
            clip_from_world: transforms.clip_from_world.to_cols_array_2d(),
            eye: transforms.eye.extend(1.0).to_array(),
            light: light.extend(0.0).to_array(),
            sizes: [
                sizes.vertex_radius,
                sizes.shaft_radius,
                sizes.head_radius,
                sizes.head_length,
            ],
            params: [
                0.0,
                self.scene.arrow_gap(),
                self.scene.unit * 0.004,
                2.0 / (rect.height() * pixels_per_point * transforms.clip_from_view.y_axis.y)
                    .max(1e-6),
            ],
            orientation_colour: [r, g, b, 1.0],
            background: palette.background.to_normalized_gamma_f32(),
            coarse_line: coarse_line.to_normalized_gamma_f32(),
            coarse_face: style::uniform_colour(style::face_style(&base, palette)),
            fade: style::uniform_fade(self.fade_others),
        };
        let (axes, axes_styles) = axes::instances(&self.scene, &sizes, palette);
        let callback = ViewCallback {
            view_id: self.id,
            frame,
            geometry_id: self.geometry_id,
            styles_id: self.styles_id,
            geometry: gpu.geometry.clone(),
            styles: gpu.styles.clone(),
            axes,
            axes_styles,
            flags: DrawFlags {
                axes: options.show_axes,
                orientation: options.show_orientation,
                solid_faces: options.solid_faces,
                coarse: self.coarse,
                base_image: options.base_image,
                base_image_part: options.base_image_part,
                motion_proxy: options.motion_proxy,
                moving,
            },
            uploaded: gpu.uploaded.clone(),
            // As `egui_wgpu` rounds the callback's rect to pixels.
            viewport_px: [
                pixel_span(rect.min.x, rect.max.x, pixels_per_point),
                pixel_span(rect.min.y, rect.max.y, pixels_per_point),
            ],
            mesh_extent: transforms
                .screen_rect_of_box(self.scene.bounds)
                .map(|extent| extent.expand(MESH_EXTENT_MARGIN)),
            repaint: painter.ctx().clone(),
        };
        painter.add(egui_wgpu::Callback::new_paint_callback(rect, callback));
    }
}

/// How many whole pixels lie between two edges in points, each rounded.
fn pixel_span(from: f32, to: f32, pixels_per_point: f32) -> u32 {
    let span = (to * pixels_per_point).round() - (from * pixels_per_point).round();
    // A float-to-int cast saturates: negative and NaN spans give 0.
    span as u32
}

impl Drop for View3d {
    fn drop(&mut self) {
        if let Some(gpu) = &self.gpu {
            let mut renderer = gpu.renderer.write();
            Renderers::remove_view(&mut renderer.callback_resources, self.id);
        }
    }
}

#[cfg(test)]
mod tests {
    use egui::{Event, Modifiers, Pos2, Rect, Vec2};

    use super::*;
    use edgewise_pictures::geometry::EdgeGeometry;
    use edgewise_pictures::options::DrawIds;
    use edgewise_pictures::styles::Pointer;

    fn screen() -> Rect {
        Rect::from_min_size(Pos2::ZERO, Vec2::new(800.0, 600.0))
    }

    fn square() -> MeshGeometry {
        MeshGeometry {
            positions: vec![
                Vec3::new(0.0, 0.0, 0.0),
                Vec3::new(1.0, 0.0, 0.0),
                Vec3::new(1.0, 1.0, 0.0),
                Vec3::new(0.0, 1.0, 0.0),
            ],
            edges: [(0, 1), (1, 2), (2, 3), (3, 0)]
                .into_iter()
                .map(|(start, end)| EdgeGeometry {
                    start,
                    end,
                    face: None,
                    pair: None,
                })
                .collect(),
            faces: vec![vec![0, 1, 2, 3]],
            half_edges: false,
        }
    }

    fn frame(ctx: &egui::Context, view: &mut View3d, events: Vec<Event>) -> ViewResponse {
        let mut response = ViewResponse::default();
        let raw = egui::RawInput {
            screen_rect: Some(screen()),
            events,
            ..Default::default()
        };
        ctx.run_ui(raw, |ui| {
            response = view.ui(ui, &SceneStyles::default(), &ViewOptions::default());
        })
        .drop_without_applying_deltas();
        response
    }

    fn button(pos: Pos2, pressed: bool) -> Event {
        Event::PointerButton {
            pos,
            button: PointerButton::Primary,
            pressed,
            modifiers: Modifiers::NONE,
        }
    }

    fn click(ctx: &egui::Context, view: &mut View3d, pos: Pos2) -> ViewResponse {
        frame(ctx, view, vec![Event::PointerMoved(pos), button(pos, true)]);
        frame(ctx, view, vec![button(pos, false)])
    }

    #[test]
    fn headless_view_hovers_clicks_and_clears() {
        let ctx = egui::Context::default();
        let mut view = View3d::new(None);
        view.set_geometry(square(), true);
        frame(&ctx, &mut view, Vec::new());
        let transforms = view.transforms(screen());
        let (corner, _) = transforms.project(Vec3::new(1.0, 1.0, 0.0)).unwrap();
        let hover = frame(&ctx, &mut view, vec![Event::PointerMoved(corner)]);
        assert_eq!(hover.hovered, Some(ElementRef::new(ElementKind::Vertex, 2)));

        let response = click(&ctx, &mut view, corner);
        assert_eq!(
            response.clicked,
            Some(ElementRef::new(ElementKind::Vertex, 2))
        );
        assert!(!response.background_clicked);

        let center = transforms.project(Vec3::new(0.5, 0.45, 0.0)).unwrap().0;
        assert_eq!(
            click(&ctx, &mut view, center).clicked,
            Some(ElementRef::new(ElementKind::Face, 0))
        );

        let response = click(&ctx, &mut view, Pos2::new(5.0, 5.0));
        assert_eq!(response.clicked, None);
        assert!(response.background_clicked);
    }

    #[test]
    fn drag_orbits_and_scroll_zooms() {
        let ctx = egui::Context::default();
        let mut view = View3d::new(None);
        view.set_geometry(square(), true);
        frame(&ctx, &mut view, Vec::new());
        let before = view.camera();
        let start = Pos2::new(400.0, 300.0);
        frame(
            &ctx,
            &mut view,
            vec![Event::PointerMoved(start), button(start, true)],
        );
        for i in 1..=5 {
            frame(
                &ctx,
                &mut view,
                vec![Event::PointerMoved(start + Vec2::new(20.0 * i as f32, 0.0))],
            );
        }
        let end = start + Vec2::new(100.0, 0.0);
        let released = frame(&ctx, &mut view, vec![button(end, false)]);
        assert_eq!(released.clicked, None, "a drag is not a click");
        let after = view.camera();
        assert!(
            (after.yaw - before.yaw).abs() > 0.1,
            "{before:?} → {after:?}"
        );
        assert_eq!(after.distance, before.distance);

        frame(
            &ctx,
            &mut view,
            vec![Event::MouseWheel {
                unit: egui::MouseWheelUnit::Point,
                delta: Vec2::new(0.0, 120.0),
                phase: egui::TouchPhase::Move,
                modifiers: Modifiers::NONE,
                source: egui::MouseWheelSource::Wheel,
            }],
        );
        for _ in 0..30 {
            frame(&ctx, &mut view, Vec::new());
        }
        assert!(
            view.camera().distance < after.distance,
            "scrolling up zooms in"
        );
    }

    #[test]
    fn new_geometry_is_framed_and_cameras_round_trip() {
        let mut view = View3d::new(None);
        let mut far = square();
        for p in &mut far.positions {
            *p += Vec3::new(100.0, 0.0, 0.0);
        }
        view.set_geometry(far, true);
        assert!((view.camera().target()[0] - 100.5).abs() < 1e-3);
        let camera = Camera {
            target: [1.0, 2.0, 3.0],
            yaw: 1.0,
            pitch: 0.5,
            distance: 7.0,
        };
        view.set_camera(camera);
        assert_eq!(view.camera(), camera);
        let json = serde_json::to_string(&camera).unwrap();
        assert_eq!(serde_json::from_str::<Camera>(&json).unwrap(), camera);
        // Replacing the mesh without framing keeps the camera.
        view.set_geometry(square(), false);
        assert_eq!(view.camera(), camera);
    }

    #[test]
    fn odd_meshes_do_not_panic() {
        let ctx = egui::Context::default();
        let odd = [
            MeshGeometry::default(),
            MeshGeometry {
                positions: vec![Vec3::ONE; 3],
                edges: vec![EdgeGeometry {
                    start: 0,
                    end: 9,
                    face: Some(4),
                    pair: Some(7),
                }],
                faces: vec![vec![0, 1, 2], vec![], vec![5, 6, 7, 8]],
                half_edges: true,
            },
        ];
        for geometry in odd {
            let mut view = View3d::new(None);
            view.set_geometry(geometry, true);
            let styles = SceneStyles {
                generation: 3,
                fade_others: false,
                elements: [
                    (ElementKind::Vertex, 0),
                    (ElementKind::Edge, 7),
                    (ElementKind::Face, 2),
                ]
                .into_iter()
                .map(|(kind, id)| {
                    let style = ElementStyle {
                        colour: Some(egui::Color32::RED),
                        faded: false,
                        label: Some("x".to_owned()),
                    };
                    (ElementRef::new(kind, id), style)
                })
                .collect(),
                pointers: vec![Pointer {
                    target: ElementRef::new(ElementKind::Face, 99),
                    colour: egui::Color32::RED,
                }],
            };
            let options = ViewOptions {
                draw_ids: DrawIds::Always,
                show_axes: true,
                show_orientation: true,
                ..ViewOptions::default()
            };
            for pos in [Pos2::new(400.0, 300.0), Pos2::new(1.0, 1.0)] {
                let raw = egui::RawInput {
                    screen_rect: Some(screen()),
                    events: vec![Event::PointerMoved(pos)],
                    ..Default::default()
                };
                ctx.run_ui(raw, |ui| {
                    view.ui(ui, &styles, &options);
                })
                .drop_without_applying_deltas();
            }
        }
    }
}
