//! The coarse level of detail's base image: the mesh's lines and flat
//! faces drawn once into a texture the size of the view, then copied to the
//! screen each frame until the camera, the mesh, the colours or the view's
//! size change (only within the projection of the mesh's bounding box, as
//! a software renderer pays for each pixel copied). A selection, a trace
//! step or a panel repainting over an unchanged view then costs one copy
//! and the highlighted elements, however large the mesh; a software
//! renderer otherwise redraws every line and face of it.
//!
//! The image is premultiplied: cleared to transparent, with faces blended
//! over the lines as on screen, so copying it over the backdrop gives what
//! drawing there would. It is drawn unfaded, from a frame uniform of its
//! own, and the copy fades it while others are highlighted, so the first
//! selection keeps it too. Highlighted elements are drawn after the copy,
//! over the faces rather than under them; solid faces, which hide what is
//! behind them, are always drawn directly.
//!
//! A large new mesh's first image is drawn over several frames, a part of
//! its lines and faces in each after a first frame that only uploads, so
//! that showing a large mesh does not freeze the page for the whole drawing
//! (about 220 ms for torus-200k under `SwiftShader`); until done, the part
//! drawn so far is copied. Later images (a turn of the camera, a resize)
//! are drawn whole, as the user is watching them follow the pointer.
//! A mesh with a motion proxy (`motion_proxy.rs`) draws every image in
//! parts behind the proxy, which shows until the image is done: a new
//! mesh's, a resized view's, and, once the camera rests, a turned one's
//! (while the camera moves, the proxy is drawn and the image waits).

use super::gpu::{FrameUniform, TargetConstants, depth_format};
use crate::texture_copy::{self, CopySource};

const SHADER: &str = concat!(
    include_str!("shaders/common.wgsl"),
    include_str!("../texture_copy.wgsl"),
    include_str!("shaders/base_image.wgsl")
);

/// What an image was drawn for; any change draws it again.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BaseKey {
    pub geometry_id: u64,
    pub frame: FrameUniform,
    /// The view's size in pixels.
    pub size: [u32; 2],
}

/// The copy pipeline, shared by every view.
pub struct BaseImageRenderer {
    layout: wgpu::BindGroupLayout,
    pipeline: wgpu::RenderPipeline,
    target_format: wgpu::TextureFormat,
    /// The largest texture side the device allows.
    max_side: u32,
}

impl BaseImageRenderer {
    pub fn new(
        device: &wgpu::Device,
        frame_layout: &wgpu::BindGroupLayout,
        target_format: wgpu::TextureFormat,
    ) -> Self {
        let layout = texture_copy::image_layout(device, "view3d base image");
        let constants = TargetConstants::new(target_format);
        let pipeline = texture_copy::pipeline(
            device,
            target_format,
            depth_format(),
            &texture_copy::CopySpec {
                label: "view3d base image",
                source: SHADER,
                fragment_entry: "fs_base_image",
                // The frame uniform stays bound at 0 for the drawables after.
                bind_group_layouts: &[Some(frame_layout), Some(&layout)],
                options: constants.options(),
            },
        );
        Self {
            layout,
            pipeline,
            target_format,
            max_side: device.limits().max_texture_dimension_2d,
        }
    }

    /// Copies `image` over the viewport.
    pub fn draw(&self, pass: &mut wgpu::RenderPass<'static>, image: &BaseImage) {
        let Some(target) = &image.target else {
            return;
        };
        pass.set_pipeline(&self.pipeline);
        pass.set_bind_group(1, &target.colour.bind_group, &[]);
        pass.draw(0..3, 0..1);
    }
}

/// What [`BaseImage::update`] did this frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Update {
    /// Nothing: the image is current, or the view has no image.
    Kept,
    /// Drew a part; another frame must draw the rest.
    Part,
    /// Drew the last part, or the whole image.
    Finished,
}

/// One view's image and the textures it is drawn into.
#[derive(Default)]
pub struct BaseImage {
    drawn_for: Option<BaseKey>,
    /// How many of the image's primitives are drawn.
    drawn: u32,
    /// The mesh of the last image begun: another draws part by part.
    geometry_id: Option<u64>,
    target: Option<Target>,
}

struct Target {
    colour: CopySource,
    depth: wgpu::TextureView,
}

impl BaseImage {
    /// Whether the image, whole or in part, is drawn for `key`.
    pub fn is_current(&self, key: &BaseKey) -> bool {
        self.drawn_for.as_ref() == Some(key)
    }

    /// Whether the image for `key` is begun but not all of its `total`
    /// primitives are drawn yet.
    pub fn is_partial(&self, key: &BaseKey, total: u32) -> bool {
        self.is_current(key) && self.drawn < total
    }

    /// Draws the image for `key`, or its next part, with `draw`, which
    /// draws the given range of the image's `total` primitives (in an
    /// order where parts drawn one after the other give the whole). A new
    /// mesh of more than `part` primitives is drawn `part` a frame, from
    /// the frame after the first, and so is an image drawn `behind` what
    /// shows meanwhile (the motion proxy), from the first; any other image
    /// whole.
    /// The image is current afterwards unless the view is too large for a
    /// texture (the mesh is then drawn directly).
    #[expect(clippy::too_many_arguments, reason = "one call site, each distinct")]
    pub fn update(
        &mut self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        renderer: &BaseImageRenderer,
        key: BaseKey,
        total: u32,
        part: u32,
        behind: bool,
        draw: impl FnOnce(&mut wgpu::RenderPass<'static>, std::ops::Range<u32>),
    ) -> Update {
        let continuing = self.is_current(&key);
        if continuing && self.drawn >= total {
            return Update::Kept;
        }
        let [width, height] = key.size;
        if width == 0 || height == 0 || width.max(height) > renderer.max_side {
            self.drawn_for = None;
            return Update::Kept;
        }
        if self
            .target
            .as_ref()
            .is_none_or(|t| t.colour.size != key.size)
        {
            self.target = Some(Target::new(device, renderer, key.size));
        }
        let Some(target) = &self.target else {
            return Update::Kept;
        };
        let start = if continuing { self.drawn } else { 0 };
        let part = part.max(1);
        let end = if continuing {
            start.saturating_add(part).min(total)
        } else if self.geometry_id != Some(key.geometry_id) && total > part {
            // A new large mesh's first frame uploads its buffers; the
            // parts begin in the next.
            0
        } else if behind {
            part.min(total)
        } else {
            total
        };
        let finished = end >= total;
        // A later part draws over the earlier ones, against their depth.
        let (colour_load, depth_load) = if start == 0 {
            (
                wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT),
                wgpu::LoadOp::Clear(1.0),
            )
        } else {
            (wgpu::LoadOp::Load, wgpu::LoadOp::Load)
        };
        let mut pass = encoder
            .begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("view3d base image"),
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view: &target.colour.view,
                    depth_slice: None,
                    resolve_target: None,
                    ops: wgpu::Operations {
                        load: colour_load,
                        store: wgpu::StoreOp::Store,
                    },
                })],
                depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                    view: &target.depth,
                    depth_ops: Some(wgpu::Operations {
                        load: depth_load,
                        store: if finished {
                            wgpu::StoreOp::Discard
                        } else {
                            wgpu::StoreOp::Store
                        },
                    }),
                    stencil_ops: None,
                }),
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            })
            .forget_lifetime();
        draw(&mut pass, start..end);
        drop(pass);
        self.drawn_for = Some(key);
        self.drawn = end;
        self.geometry_id = Some(key.geometry_id);
        if finished {
            Update::Finished
        } else {
            Update::Part
        }
    }
}

impl Target {
    fn new(device: &wgpu::Device, renderer: &BaseImageRenderer, size: [u32; 2]) -> Self {
        let colour = CopySource::new(
            device,
            &renderer.layout,
            "view3d base image",
            renderer.target_format,
            size,
        );
        let depth = texture_copy::render_target(
            device,
            "view3d base image depth",
            depth_format(),
            wgpu::TextureUsages::RENDER_ATTACHMENT,
            size,
        );
        Self { colour, depth }
    }
}
