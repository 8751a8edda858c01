//! Parts of the UI drawn once into a texture and copied while they stay the
//! same: the tables, the menus, the algorithm panel, the OBJ editor and the
//! welcome card, which repaint unchanged on every frame of an orbit.
//!
//! Under a software renderer (`SwiftShader`) a pixel that egui's shader
//! covers costs several times what a texture copy does, since that shader
//! runs both sides of a branch on a uniform. A part whose shapes are the
//! same as the frame before is drawn, by `egui_wgpu`'s own renderer, into a
//! texture of its size, and while they stay the same each frame copies that
//! texture instead. A part that changed is drawn directly, as before, so a
//! selection or a step costs no more; the texture is drawn again at the
//! first frame after which nothing changed.
//!
//! The layout and the interaction are egui's as ever: only the shapes a
//! part painted are swapped for one paint callback, at the end of the frame.

use std::{collections::HashMap, sync::Arc};

use egui::{
    Rect, Shape,
    epaint::{ClippedPrimitive, ClippedShape, Primitive, TextureId, ViewportInPixels},
};
use egui_wgpu::{self, CallbackResources, CallbackTrait, RenderState, ScreenDescriptor};

use crate::{
    texture_copy::{self, CopySource},
    view3d::depth_format,
};

/// Where a part's shapes begin in its layer, from [`UiCache::begin`].
#[derive(Clone, Copy, Debug)]
pub struct Mark {
    layer: egui::LayerId,
    start: usize,
}

/// A part's shapes this frame: a range of a layer.
struct Range {
    name: &'static str,
    layer: egui::LayerId,
    start: usize,
    /// `None`: to the layer's end.
    end: Option<usize>,
}

/// What is known of a part from the frames before.
#[derive(Default)]
struct Part {
    /// Its shapes last frame, in screen points.
    shapes: Vec<ClippedShape>,
    /// The texture's contents: its version and what it was drawn from.
    drawn: Option<Arc<Drawing>>,
}

/// A part's shapes, tessellated for a texture whose corner is at `rect.min`.
struct Drawing {
    version: u64,
    /// On screen, in points, on whole pixels.
    rect: Rect,
    size_px: [u32; 2],
    pixels_per_point: f32,
    primitives: Vec<ClippedPrimitive>,
}

/// How many frames drew parts and copied them, for `state().uiCache`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct UiCacheCounts {
    /// Parts drawn into their textures.
    pub drawn: u64,
    /// Parts copied from their textures (drawn ones included).
    pub copied: u64,
}

/// The app's cached parts; see the module docs.
#[derive(Default)]
pub struct UiCache {
    parts: HashMap<&'static str, Part>,
    ranges: Vec<Range>,
    /// `drawn` also numbers the drawings: a texture holds one version.
    counts: UiCacheCounts,
}

impl UiCache {
    /// Marks where the part that `ui` paints next begins.
    pub fn begin(ui: &egui::Ui) -> Mark {
        let layer = ui.layer_id();
        let start = ui
            .ctx()
            .graphics(|graphics| graphics.get(layer).map_or(0, |list| list.next_idx().0));
        Mark { layer, start }
    }

    /// Ends the part begun at `mark`.
    pub fn end(&mut self, ui: &egui::Ui, name: &'static str, mark: Mark) {
        let end = ui
            .ctx()
            .graphics(|graphics| graphics.get(mark.layer).map_or(0, |list| list.next_idx().0));
        self.ranges.push(Range {
            name,
            layer: mark.layer,
            start: mark.start,
            end: Some(end),
        });
    }

    /// Makes all of `layer` (a window's, say) a part.
    pub fn whole_layer(&mut self, name: &'static str, layer: egui::LayerId) {
        self.ranges.push(Range {
            name,
            layer,
            start: 0,
            end: None,
        });
    }

    pub fn counts(&self) -> UiCacheCounts {
        self.counts
    }

    /// At the end of a frame: swaps the shapes of each part unchanged since
    /// the frame before for a copy of its texture. Without a render state
    /// (UI tests) every part is drawn directly.
    pub fn finish(&mut self, ctx: &egui::Context, render_state: Option<&RenderState>) {
        let ranges = std::mem::take(&mut self.ranges);
        let Some(render_state) = render_state else {
            return;
        };
        // `None` when the font atlas grew this frame: draw directly, and
        // into the textures again once the new atlas is on the GPU.
        let font = current_font_texture(ctx, render_state);
        let max_side = render_state.device.limits().max_texture_dimension_2d;
        let pixels_per_point = ctx.pixels_per_point();
        let screen = ctx.content_rect();
        let mut names = Vec::new();
        for range in ranges {
            let shapes = ctx.graphics(|graphics| {
                graphics.get(range.layer).map_or_else(Vec::new, |list| {
                    let end = range.end.unwrap_or(list.next_idx().0);
                    list.all_entries()
                        .skip(range.start)
                        .take(end.saturating_sub(range.start))
                        .cloned()
                        .collect()
                })
            });
            names.push(range.name);
            let part = self.parts.entry(range.name).or_default();
            let Some(font) = font
                .as_ref()
                .filter(|_| shapes == part.shapes && cacheable(&shapes))
            else {
                part.shapes = shapes;
                part.drawn = None;
                continue;
            };
            let drawn = match &part.drawn {
                Some(drawn) if drawn.pixels_per_point == pixels_per_point => Arc::clone(drawn),
                _ => {
                    let version = self.counts.drawn + 1;
                    let Some(drawing) =
                        tessellate(ctx, &shapes, screen, pixels_per_point, max_side, version)
                    else {
                        continue;
                    };
                    self.counts.drawn = version;
                    let drawn = Arc::new(drawing);
                    part.drawn = Some(Arc::clone(&drawn));
                    drawn
                }
            };
            let count = shapes.len();
            let rect = drawn.rect;
            let callback = egui_wgpu::Callback::new_paint_callback(
                rect,
                PartCallback {
                    name: range.name,
                    drawing: drawn,
                    font: font.clone(),
                },
            );
            ctx.graphics_mut(|graphics| {
                let list = graphics.entry(range.layer);
                list.set(egui::layers::ShapeIdx(range.start), rect, callback.into());
                for index in range.start + 1..range.start + count {
                    list.reset_shape(egui::layers::ShapeIdx(index));
                }
            });
            self.counts.copied += 1;
        }
        // A part not shown this frame starts afresh when shown again.
        self.parts.retain(|name, _| names.contains(name));
    }
}

/// eframe's font texture, if it matches the atlas this frame's shapes use.
fn current_font_texture(ctx: &egui::Context, render_state: &RenderState) -> Option<wgpu::Texture> {
    let texture = render_state
        .renderer
        .read()
        .texture(&TextureId::default())?
        .texture
        .clone()?;
    #[expect(
        clippy::redundant_closure_for_method_calls,
        reason = "the method path is not general over FontsView's lifetime"
    )]
    let [width, height] = ctx.fonts(|fonts| fonts.font_image_size());
    (texture.width() as usize == width && texture.height() as usize == height).then_some(texture)
}

/// Whether a part can be drawn into a texture: only shapes drawn with the
/// font texture (no images, no paint callbacks of their own).
fn cacheable(shapes: &[ClippedShape]) -> bool {
    !shapes.is_empty()
        && shapes
            .iter()
            .all(|clipped| drawn_with_fonts(&clipped.shape))
}

fn drawn_with_fonts(shape: &Shape) -> bool {
    match shape {
        Shape::Vec(shapes) => shapes.iter().all(drawn_with_fonts),
        Shape::Callback(_) => false,
        Shape::Mesh(mesh) => mesh.texture_id == TextureId::default(),
        Shape::Rect(rect) => rect.brush.is_none(),
        _ => true,
    }
}

/// The part's shapes tessellated into a texture covering what they draw,
/// on whole pixels; `None` if that is empty or larger than a texture can be.
fn tessellate(
    ctx: &egui::Context,
    shapes: &[ClippedShape],
    screen: Rect,
    pixels_per_point: f32,
    max_side: u32,
    version: u64,
) -> Option<Drawing> {
    let drawn = shapes
        .iter()
        .map(|clipped| {
            clipped
                .shape
                .visual_bounding_rect()
                .intersect(clipped.clip_rect)
        })
        .filter(Rect::is_positive)
        .fold(Rect::NOTHING, Rect::union)
        .expand(1.0 / pixels_per_point)
        .intersect(screen);
    if !drawn.is_positive() {
        return None;
    }
    let rect = Rect::from_min_max(
        ((drawn.min.to_vec2() * pixels_per_point).floor() / pixels_per_point).to_pos2(),
        ((drawn.max.to_vec2() * pixels_per_point).ceil() / pixels_per_point).to_pos2(),
    );
    // The pixels `egui_wgpu` gives the paint callback: the texture covers
    // exactly those.
    let screen_px = (screen.size() * pixels_per_point).round();
    let viewport = ViewportInPixels::from_points(
        &rect,
        pixels_per_point,
        [screen_px.x as u32, screen_px.y as u32],
    );
    let size_px = [viewport.width_px, viewport.height_px].map(|side| side.max(0) as u32);
    if size_px.iter().any(|&side| side == 0 || side > max_side) {
        return None;
    }
    // Tessellated where the shapes are, then moved: egui rounds text and
    // lines to pixels, which moving the shapes first could round otherwise.
    let offset = egui::vec2(viewport.left_px as f32, viewport.top_px as f32) / pixels_per_point;
    let mut primitives = ctx.tessellate(shapes.to_vec(), pixels_per_point);
    for clipped in &mut primitives {
        clipped.clip_rect = clipped.clip_rect.translate(-offset);
        if let Primitive::Mesh(mesh) = &mut clipped.primitive {
            mesh.translate(-offset);
        }
    }
    Some(Drawing {
        version,
        rect,
        size_px,
        pixels_per_point,
        primitives,
    })
}

/// Copies a part's texture, drawing it first when its version is new.
struct PartCallback {
    name: &'static str,
    drawing: Arc<Drawing>,
    font: wgpu::Texture,
}

impl CallbackTrait for PartCallback {
    fn prepare(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        _screen_descriptor: &ScreenDescriptor,
        encoder: &mut wgpu::CommandEncoder,
        resources: &mut CallbackResources,
    ) -> Vec<wgpu::CommandBuffer> {
        let Some(textures) = resources.get_mut::<PartTextures>() else {
            return Vec::new();
        };
        let copy_layout = &textures.copy.layout;
        let target = textures.target_format;
        let part = textures
            .parts
            .entry(self.name)
            .or_insert_with(|| GpuPart::new(device, target));
        part.draw(
            device,
            queue,
            encoder,
            &self.drawing,
            &self.font,
            copy_layout,
        )
    }

    fn paint(
        &self,
        _info: egui::PaintCallbackInfo,
        pass: &mut wgpu::RenderPass<'static>,
        resources: &CallbackResources,
    ) {
        let Some(textures) = resources.get::<PartTextures>() else {
            return;
        };
        let Some(copied) = textures
            .parts
            .get(self.name)
            .and_then(|part| part.target.as_ref())
        else {
            return;
        };
        pass.set_pipeline(&textures.copy.pipeline);
        pass.set_bind_group(0, &copied.bind_group, &[]);
        pass.draw(0..3, 0..1);
    }
}

/// The GPU side: every part's texture and the pipeline that copies them.
pub struct PartTextures {
    target_format: wgpu::TextureFormat,
    copy: CopyPipeline,
    parts: HashMap<&'static str, GpuPart>,
}

impl PartTextures {
    /// Registers the textures with an eframe render state (once).
    pub fn install(render_state: &RenderState) {
        let mut renderer = render_state.renderer.write();
        if renderer.callback_resources.get::<Self>().is_none() {
            let textures = Self {
                target_format: render_state.target_format,
                copy: CopyPipeline::new(&render_state.device, render_state.target_format),
                parts: HashMap::new(),
            };
            renderer.callback_resources.insert(textures);
        }
    }
}

/// One part's texture, and the egui renderer that draws into it (one each,
/// as a renderer's buffers hold one drawing at a time).
struct GpuPart {
    renderer: egui_wgpu::Renderer,
    format: wgpu::TextureFormat,
    target: Option<CopySource>,
    version: u64,
    font: Option<(wgpu::Texture, TextureId)>,
}

impl GpuPart {
    fn new(device: &wgpu::Device, target_format: wgpu::TextureFormat) -> Self {
        Self {
            renderer: egui_wgpu::Renderer::new(
                device,
                target_format,
                egui_wgpu::RendererOptions::default(),
            ),
            format: target_format,
            target: None,
            version: 0,
            font: None,
        }
    }

    /// Draws `drawing` into the texture unless it holds it already.
    fn draw(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        drawing: &Drawing,
        font: &wgpu::Texture,
        copy_layout: &wgpu::BindGroupLayout,
    ) -> Vec<wgpu::CommandBuffer> {
        if self.version == drawing.version {
            return Vec::new();
        }
        self.version = drawing.version;
        let font_id = self.font_id(device, font);
        let target = match self.target.take() {
            Some(target) if target.size == drawing.size_px => target,
            _ => CopySource::new(
                device,
                copy_layout,
                "ui cache part",
                self.format,
                drawing.size_px,
            ),
        };
        let target = self.target.insert(target);
        let primitives: Vec<ClippedPrimitive> = drawing
            .primitives
            .iter()
            .cloned()
            .map(|mut clipped| {
                if let Primitive::Mesh(mesh) = &mut clipped.primitive {
                    mesh.texture_id = font_id;
                }
                clipped
            })
            .collect();
        let screen = ScreenDescriptor {
            size_in_pixels: drawing.size_px,
            pixels_per_point: drawing.pixels_per_point,
        };
        let commands = self
            .renderer
            .update_buffers(device, queue, encoder, &primitives, &screen);
        let mut pass = encoder
            .begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("ui cache part"),
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view: &target.view,
                    resolve_target: None,
                    depth_slice: None,
                    ops: wgpu::Operations {
                        load: wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT),
                        store: wgpu::StoreOp::Store,
                    },
                })],
                depth_stencil_attachment: None,
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            })
            .forget_lifetime();
        self.renderer.render(&mut pass, &primitives, &screen);
        commands
    }

    /// The id this part's renderer knows eframe's font texture by,
    /// registered again when eframe makes a new one.
    fn font_id(&mut self, device: &wgpu::Device, font: &wgpu::Texture) -> TextureId {
        if let Some((known, id)) = &self.font
            && known == font
        {
            return *id;
        }
        if let Some((_, id)) = self.font.take() {
            self.renderer.free_texture(&id);
        }
        let view = font.create_view(&wgpu::TextureViewDescriptor::default());
        let id = self
            .renderer
            .register_native_texture(device, &view, wgpu::FilterMode::Linear);
        self.font = Some((font.clone(), id));
        id
    }
}

/// Copies a part's texture over the callback's viewport.
struct CopyPipeline {
    layout: wgpu::BindGroupLayout,
    pipeline: wgpu::RenderPipeline,
}

impl CopyPipeline {
    fn new(device: &wgpu::Device, target_format: wgpu::TextureFormat) -> Self {
        let layout = texture_copy::image_layout(device, "ui cache copy");
        let pipeline = texture_copy::pipeline(
            device,
            target_format,
            depth_format(),
            &texture_copy::CopySpec {
                label: "ui cache copy",
                source: &[texture_copy::SHADER, include_str!("ui_cache/copy.wgsl")].concat(),
                fragment_entry: "fs_part",
                bind_group_layouts: &[Some(&layout)],
                options: wgpu::PipelineCompilationOptions::default(),
            },
        );
        Self { layout, pipeline }
    }
}
