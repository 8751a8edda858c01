//! The 3D view: the mesh drawn with wgpu inside egui, with camera and picking.
