//! The UI cache draws a part unchanged since the frame before into a
//! texture and copies it: the picture must be the one drawing the part
//! directly gives. Needs a wgpu adapter (lavapipe on CI), as the 3D view's
//! render tests do.

#![allow(clippy::unwrap_used)]

use crate::support;

use crate::support::worst_channel_difference;

use edgewise_renderer::ui_cache::{PartTextures, UiCache, UiCacheCounts};
use eframe::egui_wgpu::RenderState;
use egui::{Color32, Pos2, Rect, Vec2};

const SIZE: [u32; 2] = [420, 260];

/// A part like a table: text, a coloured row, hairlines and a button.
fn part_ui(ui: &mut egui::Ui, words: &str) {
    ui.heading("Half-edges");
    for row in 0..6 {
        let (rect, _) = ui.allocate_exact_size(Vec2::new(360.0, 20.0), egui::Sense::hover());
        if row == 2 {
            ui.painter()
                .rect_filled(rect, 0.0, Color32::from_rgb(0xff, 0xd0, 0x80));
        }
        ui.painter().text(
            rect.left_center(),
            egui::Align2::LEFT_CENTER,
            format!("{row}   {words} {}", row * 7),
            egui::FontId::monospace(13.0),
            ui.visuals().text_color(),
        );
        ui.painter()
            .hline(rect.x_range(), rect.bottom(), (1.0, Color32::GRAY));
    }
    let _ = ui.button("Dismiss");
}

/// Draws one frame of a panel whose contents are the cached part.
fn frame(rs: &RenderState, ctx: &egui::Context, cache: &mut UiCache, words: &str) -> Vec<u8> {
    let screen = Rect::from_min_size(
        Pos2::ZERO,
        Vec2::new(SIZE[0] as f32, SIZE[1] as f32) / ctx.pixels_per_point(),
    );
    support::gpu::draw_frame(rs, ctx, screen, SIZE, Vec::new(), |ui| {
        egui::CentralPanel::default().show(ui, |ui| {
            let mark = UiCache::begin(ui);
            part_ui(ui, words);
            cache.end(ui, "part", mark);
        });
        cache.finish(ui.ctx(), Some(rs));
    })
    .expect("the frame renders")
}

#[test]
fn a_part_unchanged_since_the_frame_before_is_copied_as_drawn() {
    let Some(rs) = support::gpu::render_state() else {
        eprintln!("no wgpu adapter: skipped");
        return;
    };
    PartTextures::install(&rs);
    // A texture's corner on a whole pixel that is no whole point as well.
    for pixels_per_point in [1.0, 1.5] {
        copied_as_drawn(&rs, pixels_per_point);
    }
}

fn copied_as_drawn(rs: &RenderState, pixels_per_point: f32) {
    let rs = rs.clone();
    let ctx = egui::Context::default();
    ctx.set_pixels_per_point(pixels_per_point);
    let mut cache = UiCache::default();

    // egui settles its fonts and layout over the first frames.
    for words in ["warm", "warmer"] {
        frame(&rs, &ctx, &mut cache, words);
    }
    // New shapes are drawn directly; the next frame draws them into the
    // texture and copies it, and the one after only copies.
    let direct = frame(&rs, &ctx, &mut cache, "pair");
    assert_eq!(cache.counts(), UiCacheCounts::default());
    let drawn = frame(&rs, &ctx, &mut cache, "pair");
    assert_eq!(
        cache.counts(),
        UiCacheCounts {
            drawn: 1,
            copied: 1
        }
    );
    let copied = frame(&rs, &ctx, &mut cache, "pair");
    assert_eq!(
        cache.counts(),
        UiCacheCounts {
            drawn: 1,
            copied: 2
        }
    );
    for (name, pixels) in [("drawn", &drawn), ("copied", &copied)] {
        let worst = worst_channel_difference(&direct, pixels);
        assert!(
            worst <= 2,
            "{name} at {pixels_per_point}: up to {worst} levels from drawing directly"
        );
    }

    // A change is drawn directly again, and shows.
    let changed = frame(&rs, &ctx, &mut cache, "next");
    assert_eq!(
        cache.counts(),
        UiCacheCounts {
            drawn: 1,
            copied: 2
        }
    );
    assert!(worst_channel_difference(&direct, &changed) > 100);
    let redrawn = frame(&rs, &ctx, &mut cache, "next");
    assert_eq!(
        cache.counts(),
        UiCacheCounts {
            drawn: 2,
            copied: 3
        }
    );
    assert!(worst_channel_difference(&changed, &redrawn) <= 2);
}
