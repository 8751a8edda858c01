//! Share → Download as a SCORM package (docs/lms.md): the exercise or the
//! view on screen as a package an LMS imports, built in the browser from
//! the app's own files, so a lecturer needs no command line.

use edgewise_model::package::{Item, Package, PackageError, Scorm, file_stem};

use super::EdgewiseApp;

/// The pass mark of a package made here, as `edgewise package` defaults
/// it; a set or another mark is the command's.
const PASS_MARK: &str = "80";

impl EdgewiseApp {
    /// The package of what is on screen (the exercise, or else the view),
    /// and the name to save it under.
    pub fn scorm_package(&self, scorm: Scorm) -> Result<(String, Package), String> {
        let (stem, title, item) = match &self.tab().practice {
            Some(session) => (
                session.exercise.name.clone(),
                session.exercise.title.clone(),
                Item::Exercise(Box::new(session.exercise.clone())),
            ),
            None => {
                self.tab()
                    .document
                    .as_ref()
                    .ok_or("open a mesh or an exercise first")?;
                let url = self.share_url(&crate::platform::page_base())?;
                let item = Item::view(1, &url).map_err(|err| match err {
                    PackageError::Link { reason, .. } => {
                        format!("this view cannot be packaged: {reason}")
                    }
                    other => other.to_string(),
                })?;
                ("edgewise-view".to_owned(), self.embed_title(), item)
            }
        };
        let package =
            Package::new(scorm, &title, PASS_MARK, vec![item]).map_err(|err| err.to_string())?;
        let stem = file_stem(&stem);
        Ok((format!("{stem}-scorm-{}.zip", scorm.name()), package))
    }

    /// The Share window's row: a button per SCORM version.
    pub(super) fn scorm_download_ui(&mut self, ui: &mut egui::Ui) {
        ui.horizontal_wrapped(|ui| {
            ui.label("Download as a SCORM package, for an LMS's gradebook:");
            for scorm in [Scorm::V1_2, Scorm::V2004] {
                let button = ui.button(format!("SCORM {}", scorm.name())).on_hover_text(format!(
                    "A zip to upload to Moodle, Canvas, Blackboard or Brightspace; it passes at \
                     {PASS_MARK}%. For a set of exercises or another mark, use `edgewise package`."
                ));
                if !button.clicked() {
                    continue;
                }
                match self.scorm_package(scorm) {
                    Ok((name, package)) => {
                        self.share_status = Some(format!("Making {name}…"));
                        crate::platform::download_package(
                            package,
                            name,
                            self.package_status.clone(),
                            ui.ctx().clone(),
                        );
                    }
                    Err(message) => self.share_status = Some(message),
                }
            }
        });
        if let Some(said) = self.package_status.borrow_mut().take() {
            self.share_status = Some(said);
        }
    }
}
