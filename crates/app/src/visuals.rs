//! How the theme looks in egui: its visuals, the bold code face, and the
//! colour the frame is cleared to.

use edgewise_model::theme::Theme;
use edgewise_pictures::palette::Palette;
use egui::Color32;

/// The bold code face for keywords (egui ships only a regular monospace).
const CODE_BOLD: &[u8] = include_bytes!("../assets/fonts/DejaVuSansMono-Bold.ttf");

/// What the frame is cleared to: the 3D view's background, which is also
/// the panels' colour. Panels draw no fill of their own and the app's views
/// none over the clear ([`edgewise_pictures::options::ViewOptions::backdrop_cleared`]):
/// a software renderer pays tens of milliseconds for each full-window fill,
/// and each pixel is now filled once.
pub fn backdrop(dark: bool) -> [f32; 4] {
    Palette::new(dark).background.to_normalized_gamma_f32()
}

/// Applies `theme` to egui's visuals.
pub fn apply_theme(theme: &Theme, ctx: &egui::Context) {
    let mut visuals = if theme.dark {
        egui::Visuals::dark()
    } else {
        egui::Visuals::light()
    };
    // Panels show the cleared frame ([`backdrop`]).
    visuals.panel_fill = Color32::TRANSPARENT;
    visuals.window_shadow = egui::epaint::Shadow::NONE;
    visuals.popup_shadow = egui::epaint::Shadow::NONE;
    if !theme.dark {
        visuals.window_fill = Color32::from_rgb(0xfa, 0xf9, 0xf6);
        visuals.extreme_bg_color = Color32::from_rgb(0xfd, 0xfd, 0xfb);
    }
    ctx.set_visuals(visuals);
}

/// The font family name of the bold code face, registered by
/// [`install_fonts`]; the algorithm view sets keywords in it.
pub const CODE_BOLD_FAMILY: &str = "code-bold";

/// Registers the bold code face as the font family [`CODE_BOLD_FAMILY`],
/// and as the last fallback of the
/// other families for the control symbols (▶ ◀ ❚ ✖) the default fonts lack.
/// Call before any text is laid out in the first frame, so it applies at once.
pub fn install_fonts(ctx: &egui::Context) {
    use egui::epaint::text::{FontData, FontInsert, FontPriority, InsertFontFamily};
    let family = |family, priority| InsertFontFamily { family, priority };
    ctx.add_font(FontInsert::new(
        "DejaVuSansMono-Bold",
        FontData::from_static(CODE_BOLD),
        vec![
            family(
                egui::FontFamily::Name(CODE_BOLD_FAMILY.into()),
                FontPriority::Highest,
            ),
            family(egui::FontFamily::Proportional, FontPriority::Lowest),
            family(egui::FontFamily::Monospace, FontPriority::Lowest),
        ],
    ));
}
