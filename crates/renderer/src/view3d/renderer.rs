//! The paint callback: each view's buffers, and the order drawables upload
//! and draw in. Apart from gpu.rs so that drawables depend on the plumbing
//! and only this file depends on the drawables.

use std::collections::HashMap;
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};

use egui_wgpu::{CallbackResources, CallbackTrait, RenderState, ScreenDescriptor};

use super::arrows::{ArrowBuffers, ArrowInstance, ArrowRenderer};
use super::base_image::{self, BaseImage, BaseImageRenderer, BaseKey};
use super::coarse::{CoarseBuffers, CoarseGeometry, CoarseRenderer};
use super::faces::{FaceBuffers, FaceRenderer};
use super::gpu::{
    FrameBindGroup, FrameUniform, PipelineFactory, StyleVertex, frame_bind_group_layout,
};
use super::orientation::{MarkInstance, OrientationBuffers, OrientationRenderer};
use super::spheres::{SphereBuffers, SphereInstance, SphereRenderer};

/// Geometry buffers' contents, built on the CPU when the mesh changes and
/// uploaded once.
#[derive(Default)]
pub struct GeometryUpload {
    pub id: u64,
    pub spheres: Vec<SphereInstance>,
    pub arrows: Vec<ArrowInstance>,
    /// Three corners per triangle.
    pub faces: Vec<[f32; 3]>,
    pub marks: Vec<MarkInstance>,
    pub coarse: CoarseGeometry,
    /// The coarse geometry simplified, drawn while the camera moves
    /// (`motion_proxy.rs`); none for a mesh small enough to draw itself.
    pub proxy: Option<CoarseGeometry>,
}

/// New styles for some or all elements of one drawable.
#[derive(Debug)]
pub enum StyleWrites {
    /// Every element's style.
    All(Vec<StyleVertex>),
    /// Runs of styles, each from its first element; the rest stay.
    Runs(Vec<(u32, Vec<StyleVertex>)>),
}

impl Default for StyleWrites {
    fn default() -> Self {
        Self::All(Vec::new())
    }
}

impl StyleWrites {
    fn write<T: bytemuck::Pod + Default>(
        &self,
        buffers: &mut super::gpu::StyledBuffers<T>,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
    ) {
        match self {
            Self::All(styles) => buffers.write_styles(device, queue, styles),
            Self::Runs(runs) => buffers.patch_styles(queue, runs),
        }
    }
}

/// Style buffers' contents when the styles' generation changes: all of
/// them after a new mesh or theme, else patches of the elements whose look
/// changed, so that a selection or a trace step costs what it changes.
#[derive(Default)]
pub struct StyleUpload {
    pub id: u64,
    /// The upload these patches apply over; None when everything is
    /// written.
    pub patches: Option<u64>,
    pub vertices: StyleWrites,
    pub edges: StyleWrites,
    /// Three per triangle, like [`GeometryUpload::faces`].
    pub faces: StyleWrites,
    /// The highlighted vertices, edges and faces again, drawn in full over
    /// the coarse level of detail: instances (or corners), then styles.
    pub full_spheres: (Vec<SphereInstance>, Vec<StyleVertex>),
    pub full_arrows: (Vec<ArrowInstance>, Vec<StyleVertex>),
    pub full_faces: (Vec<[f32; 3]>, Vec<StyleVertex>),
}

impl StyleUpload {
    /// Writes the styles of the arrows, spheres and faces drawn in full
    /// detail.
    fn write_detail(&self, view: &mut ViewBuffers, device: &wgpu::Device, queue: &wgpu::Queue) {
        self.vertices.write(&mut view.spheres, device, queue);
        self.edges.write(&mut view.arrows, device, queue);
        self.faces.write(&mut view.faces, device, queue);
    }
}

/// Tells the view which uploads the GPU side has taken, so it can drop its
/// CPU copies.
#[derive(Default)]
pub struct UploadState {
    pub geometry: AtomicU64,
    pub styles: AtomicU64,
    /// How many times the coarse base image was drawn, and copied to the
    /// screen in place of drawing the mesh.
    pub base_image_drawn: AtomicU64,
    pub base_image_copied: AtomicU64,
    /// How many frames drew the motion proxy in place of the coarse lines
    /// and faces.
    pub proxy_drawn: AtomicU64,
}

/// What to draw this frame besides the mesh.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct DrawFlags {
    pub axes: bool,
    pub orientation: bool,
    pub solid_faces: bool,
    /// The coarse level of detail: edges as lines and no vertex spheres,
    /// but highlighted elements in full.
    pub coarse: bool,
    /// The coarse level of detail may be copied from its base image.
    pub base_image: bool,
    /// How many lines and triangles a frame draws of a new mesh's base
    /// image.
    pub base_image_part: u32,
    /// A large mesh's motion proxy stands in for its coarse lines and
    /// faces while the camera moves and while the base image is drawn.
    pub motion_proxy: bool,
    /// The camera is moving.
    pub moving: bool,
}

/// Every drawable's renderer, shared by all views, and each view's buffers;
/// kept in `egui_wgpu`'s callback resources.
pub struct Renderers {
    frame_layout: wgpu::BindGroupLayout,
    spheres: SphereRenderer,
    arrows: ArrowRenderer,
    coarse: CoarseRenderer,
    faces: FaceRenderer,
    orientation: OrientationRenderer,
    base_image: BaseImageRenderer,
    views: HashMap<u64, ViewBuffers>,
}

impl Renderers {
    /// Creates the renderers for a render target format.
    pub fn new(device: &wgpu::Device, target_format: wgpu::TextureFormat) -> Self {
        let frame_layout = frame_bind_group_layout(device);
        let factory = PipelineFactory::new(device, &frame_layout, target_format);
        Self {
            spheres: SphereRenderer::new(&factory),
            arrows: ArrowRenderer::new(&factory),
            coarse: CoarseRenderer::new(&factory),
            faces: FaceRenderer::new(&factory),
            orientation: OrientationRenderer::new(&factory),
            base_image: BaseImageRenderer::new(device, &frame_layout, target_format),
            frame_layout,
            views: HashMap::new(),
        }
    }

    /// Registers the renderers with an eframe render state (once).
    pub fn install(render_state: &RenderState) {
        let mut renderer = render_state.renderer.write();
        if renderer.callback_resources.get::<Self>().is_none() {
            let renderers = Self::new(&render_state.device, render_state.target_format);
            renderer.callback_resources.insert(renderers);
        }
    }

    /// Forgets a view's buffers.
    pub fn remove_view(resources: &mut CallbackResources, view_id: u64) {
        if let Some(renderers) = resources.get_mut::<Self>() {
            renderers.views.remove(&view_id);
        }
    }
}

/// One view's buffers: its frame uniform and what each drawable uploaded.
struct ViewBuffers {
    frame: FrameBindGroup,
    geometry_id: u64,
    styles_id: u64,
    spheres: SphereBuffers,
    arrows: ArrowBuffers,
    faces: FaceBuffers,
    mark_buffers: OrientationBuffers,
    axes: ArrowBuffers,
    full_spheres: SphereBuffers,
    full_arrows: ArrowBuffers,
    full_faces: FaceBuffers,
    coarse: CoarseBuffers,
    /// The motion proxy's lines and faces; empty for a small mesh.
    proxy: CoarseBuffers,
    /// The geometry was uploaded this frame: a large mesh's first frame
    /// takes its buffers and draws no lines or faces, not even its proxy,
    /// so that showing it costs no more than it must.
    uploading: bool,
    /// Arrows, spheres and faces of the current geometry not yet uploaded:
    /// only full detail draws them, so a dense mesh seen from afar uploads
    /// them when first drawn so (most of torus-200k's 39 MB).
    detail: Option<Arc<GeometryUpload>>,
    /// The style uploads for those arrows, spheres and faces since they
    /// were last written whole, kept with them and written after them (a
    /// trace stepped while coarse adds a small patch a step).
    detail_styles: Vec<Arc<StyleUpload>>,
    /// The orientation marks not yet uploaded, likewise until first shown.
    marks: Option<Arc<GeometryUpload>>,
    base_image: BaseImage,
    /// The frame uniform the base image is drawn with: unfaded.
    base_image_frame: FrameBindGroup,
}

impl ViewBuffers {
    fn new(device: &wgpu::Device, frame_layout: &wgpu::BindGroupLayout) -> Self {
        Self {
            frame: FrameBindGroup::new(device, frame_layout),
            geometry_id: 0,
            styles_id: 0,
            spheres: SphereBuffers::new("view3d spheres", "view3d vertex styles"),
            arrows: ArrowBuffers::new("view3d arrows", "view3d edge styles"),
            faces: FaceBuffers::new("view3d faces", "view3d face styles"),
            mark_buffers: OrientationBuffers::default(),
            axes: ArrowBuffers::new("view3d axes", "view3d axes styles"),
            full_spheres: SphereBuffers::new("view3d full spheres", "view3d full sphere styles"),
            full_arrows: ArrowBuffers::new("view3d full arrows", "view3d full arrow styles"),
            full_faces: FaceBuffers::new("view3d full faces", "view3d full face styles"),
            coarse: CoarseBuffers::default(),
            proxy: CoarseBuffers::default(),
            uploading: false,
            detail: None,
            detail_styles: Vec::new(),
            marks: None,
            base_image: BaseImage::default(),
            base_image_frame: FrameBindGroup::new(device, frame_layout),
        }
    }
}

/// The paint callback of one view for one frame.
pub struct ViewCallback {
    pub view_id: u64,
    pub frame: FrameUniform,
    pub geometry_id: u64,
    pub styles_id: u64,
    /// Present until the GPU side has taken it.
    pub geometry: Option<Arc<GeometryUpload>>,
    pub styles: Option<Arc<StyleUpload>>,
    pub axes: [ArrowInstance; 3],
    pub axes_styles: [StyleVertex; 3],
    pub flags: DrawFlags,
    pub uploaded: Arc<UploadState>,
    /// The view's size in pixels, as `egui_wgpu` sets the viewport.
    pub viewport_px: [u32; 2],
    /// Where on screen (points) the mesh can be, or `None` for anywhere in
    /// the view: the base image is copied there only, as a software
    /// renderer pays for every pixel the copy covers (about 9 ms a frame
    /// for the whole view in `cargo xtask bench-web`'s window, under
    /// `SwiftShader`).
    pub mesh_extent: Option<egui::Rect>,
    /// Asked for another frame while the base image is drawn in parts.
    pub repaint: egui::Context,
}

impl ViewCallback {
    /// Whether `view`'s coarse level of detail has a motion proxy to use.
    fn has_proxy(&self, view: &ViewBuffers) -> bool {
        self.flags.coarse && self.flags.motion_proxy && view.proxy.primitive_count() > 0
    }

    /// Whether this frame draws `view`'s motion proxy in place of its
    /// coarse lines and faces: while the camera moves, and while the base
    /// image is drawn a part a frame behind it (after the camera moved, the
    /// view's size changed, or a new mesh).
    fn draws_proxy(&self, view: &ViewBuffers) -> bool {
        self.has_proxy(view)
            && (self.flags.moving
                || self.base_key().is_some_and(|key| {
                    view.base_image
                        .is_partial(&key, view.coarse.primitive_count())
                }))
    }

    /// Copies the base image over the part of the view the mesh can cover,
    /// then gives the pass back the callback's clip rectangle, which
    /// `egui_wgpu` does not set again for shapes that share it.
    fn copy_base_image_to(
        &self,
        pass: &mut wgpu::RenderPass<'static>,
        info: &egui::PaintCallbackInfo,
        renderers: &Renderers,
        view: &ViewBuffers,
    ) {
        let scissor = match self.mesh_extent {
            Some(extent) => egui::epaint::ViewportInPixels::from_points(
                &extent.intersect(info.clip_rect),
                info.pixels_per_point,
                info.screen_size_px,
            ),
            None => info.clip_rect_in_pixels(),
        };
        if scissor.width_px <= 0 || scissor.height_px <= 0 {
            return;
        }
        let set_scissor = |pass: &mut wgpu::RenderPass<'static>,
                           area: &egui::epaint::ViewportInPixels| {
            // From `ViewportInPixels::from_points`: clamped to the screen, so
            // never negative.
            let [x, y, width, height] =
                [area.left_px, area.top_px, area.width_px, area.height_px].map(|v| v.max(0) as u32);
            pass.set_scissor_rect(x, y, width, height);
        };
        set_scissor(pass, &scissor);
        renderers.base_image.draw(pass, &view.base_image);
        set_scissor(pass, &info.clip_rect_in_pixels());
        self.uploaded
            .base_image_copied
            .fetch_add(1, Ordering::Relaxed);
    }

    /// What the coarse base image must show this frame, if one is used:
    /// only behind see-through faces, which hide nothing.
    fn base_key(&self) -> Option<BaseKey> {
        (self.flags.coarse && self.flags.base_image && !self.flags.solid_faces).then(|| {
            let mut frame = self.frame;
            // Drawn unfaded; the copy fades it.
            frame.fade[0] = 0.0;
            BaseKey {
                geometry_id: self.geometry_id,
                frame,
                size: self.viewport_px,
            }
        })
    }
}

/// How the mesh itself is drawn this frame, decided once before drawing.
#[derive(Clone, Copy)]
enum MeshDraw<'a> {
    /// Every vertex a sphere, every edge an arrow, every face filled.
    Detail,
    /// The coarse level of detail: lines and flat faces from `source`, and
    /// the highlighted elements in full over them.
    Coarse(CoarseSource<'a>),
}

/// Where the coarse level of detail's lines and faces come from.
#[derive(Clone, Copy)]
enum CoarseSource<'a> {
    /// A copy of the base image, which holds both.
    BaseImage,
    /// These buffers: the mesh's own, or its motion proxy.
    Buffers(&'a CoarseBuffers),
    /// None yet: the proxy drawn in place of the mesh is being uploaded.
    Uploading,
}

impl ViewCallback {
    /// How this frame draws `view`'s mesh: in detail; or coarse, from the
    /// base image when it is current for this size, else from the motion
    /// proxy while the camera moves or the image is drawn, else from the
    /// coarse buffers.
    fn mesh_draw<'a>(&self, view: &'a ViewBuffers, info: &egui::PaintCallbackInfo) -> MeshDraw<'a> {
        if !self.flags.coarse {
            return MeshDraw::Detail;
        }
        let viewport = info.viewport_in_pixels();
        let draws_proxy = self.draws_proxy(view);
        let from_image = !draws_proxy
            && self
                .base_key()
                .filter(|key| {
                    [i64::from(key.size[0]), i64::from(key.size[1])]
                        == [i64::from(viewport.width_px), i64::from(viewport.height_px)]
                })
                .is_some_and(|key| view.base_image.is_current(&key));
        MeshDraw::Coarse(if from_image {
            CoarseSource::BaseImage
        } else if view.uploading && draws_proxy {
            CoarseSource::Uploading
        } else if draws_proxy {
            self.uploaded.proxy_drawn.fetch_add(1, Ordering::Relaxed);
            CoarseSource::Buffers(&view.proxy)
        } else {
            CoarseSource::Buffers(&view.coarse)
        })
    }

    /// The mesh's vertices and edges.
    fn draw_opaque(
        &self,
        pass: &mut wgpu::RenderPass<'static>,
        info: &egui::PaintCallbackInfo,
        renderers: &Renderers,
        view: &ViewBuffers,
        mesh: MeshDraw<'_>,
    ) {
        match mesh {
            MeshDraw::Detail => {
                renderers.spheres.draw(pass, &view.spheres);
                renderers.arrows.draw(pass, &view.arrows);
            }
            MeshDraw::Coarse(source) => {
                match source {
                    CoarseSource::BaseImage => self.copy_base_image_to(pass, info, renderers, view),
                    CoarseSource::Buffers(buffers) => renderers.coarse.draw_lines(pass, buffers),
                    CoarseSource::Uploading => {}
                }
                renderers.spheres.draw(pass, &view.full_spheres);
                renderers.arrows.draw(pass, &view.full_arrows);
            }
        }
    }

    /// The mesh's faces, solid or see-through.
    fn draw_faces(
        &self,
        pass: &mut wgpu::RenderPass<'static>,
        renderers: &Renderers,
        view: &ViewBuffers,
        mesh: MeshDraw<'_>,
    ) {
        let solid = self.flags.solid_faces;
        match mesh {
            MeshDraw::Detail => renderers.faces.draw(pass, &view.faces, solid),
            MeshDraw::Coarse(source) => {
                if let CoarseSource::Buffers(buffers) = source {
                    renderers.coarse.draw_faces(pass, buffers, solid);
                }
                renderers.faces.draw(pass, &view.full_faces, solid);
            }
        }
    }
}

impl CallbackTrait for ViewCallback {
    fn prepare(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        _screen_descriptor: &ScreenDescriptor,
        egui_encoder: &mut wgpu::CommandEncoder,
        resources: &mut CallbackResources,
    ) -> Vec<wgpu::CommandBuffer> {
        let Some(renderers) = resources.get_mut::<Renderers>() else {
            return Vec::new();
        };
        let frame_layout = &renderers.frame_layout;
        let view = renderers
            .views
            .entry(self.view_id)
            .or_insert_with(|| ViewBuffers::new(device, frame_layout));

        // Uploads are skipped by id: each is taken once, then only drawn.
        view.uploading = false;
        if let Some(geometry) = &self.geometry
            && geometry.id != view.geometry_id
        {
            view.uploading = true;
            view.coarse.replace(device, &geometry.coarse);
            view.proxy = CoarseBuffers::default();
            if let Some(proxy) = &geometry.proxy {
                view.proxy.replace(device, proxy);
            }
            // Styles kept for the last mesh's arrows would not fit these.
            view.detail_styles.clear();
            view.detail = Some(Arc::clone(geometry));
            view.marks = Some(Arc::clone(geometry));
            view.geometry_id = geometry.id;
            self.uploaded.geometry.store(geometry.id, Ordering::Release);
        }
        if self.flags.orientation
            && let Some(geometry) = view.marks.take()
        {
            view.mark_buffers.replace_marks(device, &geometry.marks);
        }
        if !self.flags.coarse
            && let Some(geometry) = view.detail.take()
        {
            view.spheres.replace_elements(device, &geometry.spheres);
            view.arrows.replace_elements(device, &geometry.arrows);
            view.faces.replace_elements(device, &geometry.faces);
            for styles in std::mem::take(&mut view.detail_styles) {
                styles.write_detail(view, device, queue);
            }
        }
        // Patches apply only over the styles they were made against (the
        // view sends everything when it cannot know which those are).
        if let Some(styles) = &self.styles
            && styles.id != view.styles_id
            && styles.patches.is_none_or(|base| base == view.styles_id)
        {
            if view.detail.is_some() {
                if styles.patches.is_none() {
                    view.detail_styles.clear();
                }
                view.detail_styles.push(Arc::clone(styles));
            } else {
                styles.write_detail(view, device, queue);
            }
            view.full_spheres
                .replace(device, queue, &styles.full_spheres);
            view.full_arrows.replace(device, queue, &styles.full_arrows);
            view.full_faces.replace(device, queue, &styles.full_faces);
            view.styles_id = styles.id;
            self.uploaded.styles.store(styles.id, Ordering::Release);
        }
        if self.flags.axes {
            view.axes.write_elements(device, queue, &self.axes);
            view.axes.write_styles(device, queue, &self.axes_styles);
        }

        view.frame.write(queue, &self.frame);

        // The base image, drawn in this encoder before egui's pass (and
        // after the uniform write above, which the queue applies first).
        // A mesh with a proxy draws any new image behind it, a part a
        // frame; while the camera moves, the image waits.
        if self.has_proxy(view) && self.flags.moving {
            // The image waits.
        } else if let Some(key) = self.base_key()
            && view.geometry_id == self.geometry_id
        {
            let behind = self.has_proxy(view);
            let coarse = &renderers.coarse;
            let (frame_group, buffers) = (&view.base_image_frame, &view.coarse);
            let update = view.base_image.update(
                device,
                egui_encoder,
                &renderers.base_image,
                key,
                buffers.primitive_count(),
                self.flags.base_image_part,
                behind,
                |pass, part| {
                    frame_group.write(queue, &key.frame);
                    frame_group.bind(pass);
                    coarse.draw_part(pass, buffers, part);
                },
            );
            match update {
                base_image::Update::Kept => {}
                base_image::Update::Part => self.repaint.request_repaint(),
                base_image::Update::Finished => {
                    self.uploaded
                        .base_image_drawn
                        .fetch_add(1, Ordering::Relaxed);
                }
            }
        }
        Vec::new()
    }

    fn paint(
        &self,
        info: egui::PaintCallbackInfo,
        pass: &mut wgpu::RenderPass<'static>,
        resources: &CallbackResources,
    ) {
        let Some(renderers) = resources.get::<Renderers>() else {
            return;
        };
        let Some(view) = renderers.views.get(&self.view_id) else {
            return;
        };
        // Buffers of another mesh or styles generation would not match each
        // other; draw nothing until both are current.
        if view.geometry_id != self.geometry_id || view.styles_id != self.styles_id {
            return;
        }
        view.frame.bind(pass);
        let mesh = self.mesh_draw(view, &info);
        // Opaque first: the mesh's vertices and edges, then the extras.
        self.draw_opaque(pass, &info, renderers, view, mesh);
        if self.flags.axes {
            renderers.arrows.draw(pass, &view.axes);
        }
        if self.flags.orientation {
            renderers.orientation.draw(pass, &view.mark_buffers);
        }
        // Faces last: see-through ones test depth against everything opaque
        // without hiding what is behind them.
        self.draw_faces(pass, renderers, view, mesh);
    }
}
