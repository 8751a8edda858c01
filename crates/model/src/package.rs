//! SCORM packages (docs/lms.md): a zip an LMS imports, holding the release
//! app, the exercises and a launch page whose runtime reports the set's
//! score, each graded action and the saved attempts to the LMS.
//!
//! The CLI (`edgewise package`) and the app's Share window both build them
//! here, from the same release files, so a package made in the browser is
//! the one the command makes.

mod manifest;
pub mod zip;

use std::fmt;

use serde_json::json;

use crate::course_link::{CourseLink, MeshSource};
use crate::practice::Exercise;

/// The launch page the LMS opens, with the package's title and items
/// stamped in.
const LAUNCH_PAGE: &str = include_str!("../../../web/scorm/launch.html");
/// The runtime the launch page runs: it finds the LMS's API, reports scores
/// and interactions, and saves attempts.
const RUNTIME: &str = include_str!("../../../web/scorm/edgewise-scorm.js");

/// The longest package title: LMS lists show about this much.
pub const MAX_TITLE_CHARS: usize = 200;
/// The most items a package holds: a week's practice, not a course.
pub const MAX_ITEMS: usize = 50;

/// The version of SCORM a package speaks.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scorm {
    V1_2,
    /// SCORM 2004, 4th edition.
    V2004,
}

impl Scorm {
    /// `1.2` or `2004`.
    pub fn parse(text: &str) -> Option<Self> {
        match text {
            "1.2" => Some(Self::V1_2),
            "2004" => Some(Self::V2004),
            _ => None,
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Self::V1_2 => "1.2",
            Self::V2004 => "2004",
        }
    }

    /// The manifest's `schemaversion`.
    pub fn schema_version(self) -> &'static str {
        match self {
            Self::V1_2 => "1.2",
            Self::V2004 => "2004 4th Edition",
        }
    }
}

/// One thing a package shows.
#[derive(Clone, Debug)]
pub enum Item {
    /// An exercise, scored.
    Exercise(Box<Exercise>),
    /// A course link's view, with no score: its title and the page it
    /// opens inside the package (`index.html?…#…`).
    View { title: String, href: String },
}

impl Item {
    /// The view a course link (`https://…/?sample=cube#…` or just its
    /// `?…#…`) opens, as the package's own copy of the app shows it; `n` is
    /// its place among the links, for messages.
    pub fn view(n: usize, url: &str) -> Result<Self, PackageError> {
        let refuse = |reason: String| Err(PackageError::Link { n, reason });
        let (mut link, ignored) = CourseLink::parse_url(url);
        if let Some(message) = ignored.first() {
            return refuse(message.clone());
        }
        if let Some(MeshSource::Path(path)) = &link.mesh {
            return refuse(format!(
                "its mesh `{path}` is a file on its site, which the package does not hold; \
                 share the view with the mesh in the link"
            ));
        }
        if link.exercise.is_some() {
            return refuse("it opens an exercise: give the exercise with --exercise".to_owned());
        }
        let title = match (&link.algorithm, &link.mesh) {
            (Some(algorithm), Some(MeshSource::Sample(sample))) => {
                format!("{algorithm} on the {sample}")
            }
            (Some(algorithm), _) => algorithm.clone(),
            (None, Some(MeshSource::Sample(sample))) => format!("The {sample}"),
            (None, _) => format!("View {n}"),
        };
        link.embed = true;
        let href = link
            .to_url_checked("index.html")
            .map_err(|reason| PackageError::Link { n, reason })?;
        Ok(Self::View { title, href })
    }
}

/// The release app's files, as `cargo xtask build-web` leaves them in
/// `dist/`.
pub struct AppFiles {
    build: String,
    files: Vec<(String, Vec<u8>)>,
}

impl AppFiles {
    /// The build a release's `index.html` loads (its JS and wasm carry it
    /// in their names), or `None` for a page that is not a release's.
    pub fn build_of(index_html: &str) -> Option<&str> {
        let start = index_html.find("const BUILD = '")? + "const BUILD = '".len();
        let length = index_html[start..].find('\'')?;
        let build = &index_html[start..start + length];
        (!build.is_empty() && build.bytes().all(|b| b.is_ascii_hexdigit())).then_some(build)
    }

    /// The files of the release `build`, in package order.
    pub fn names(build: &str) -> [String; 4] {
        [
            "index.html".to_owned(),
            format!("edgewise_app.{build}.js"),
            format!("edgewise_app_bg.{build}.wasm"),
            "favicon.svg".to_owned(),
        ]
    }

    /// The release's files, read by `read` (from a folder, or fetched by
    /// the page); `read` gives the bytes of a name or why not.
    pub fn read(
        mut read: impl FnMut(&str) -> Result<Vec<u8>, String>,
    ) -> Result<Self, PackageError> {
        let missing = |file: &str, reason: String| PackageError::App {
            file: file.to_owned(),
            reason,
        };
        let index = read("index.html").map_err(|reason| missing("index.html", reason))?;
        let text = String::from_utf8_lossy(&index);
        let build = Self::build_of(&text)
            .ok_or_else(|| {
                missing(
                    "index.html",
                    "it is not a release's page (no build is stamped in it)".to_owned(),
                )
            })?
            .to_owned();
        let mut files = vec![("index.html".to_owned(), index)];
        for name in Self::names(&build).into_iter().skip(1) {
            let bytes = read(&name).map_err(|reason| missing(&name, reason))?;
            files.push((name, bytes));
        }
        Ok(Self { build, files })
    }

    pub fn build(&self) -> &str {
        &self.build
    }
}

/// A package to build: checked when made.
#[derive(Clone, Debug)]
pub struct Package {
    pub scorm: Scorm,
    pub title: String,
    /// The share of the total that passes, in percent.
    pub pass_mark: u8,
    pub items: Vec<Item>,
}

/// Why a package cannot be built; each names what to change.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum PackageError {
    NoItems,
    TooManyItems(usize),
    Duplicate(String),
    PassMark(String),
    Title(String),
    Link { n: usize, reason: String },
    App { file: String, reason: String },
    Zip(String),
}

impl fmt::Display for PackageError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::NoItems => f.write_str("a package needs at least one --exercise or --link"),
            Self::TooManyItems(n) => {
                write!(f, "{n} items; a package holds at most {MAX_ITEMS}")
            }
            Self::Duplicate(name) => write!(
                f,
                "the exercise `{name}` is given twice; each counts once in the total"
            ),
            Self::PassMark(given) => write!(
                f,
                "--pass-mark {given}: the pass mark is a whole percentage from 0 to 100"
            ),
            Self::Title(reason) => write!(f, "--title: {reason}"),
            Self::Link { n, reason } => write!(f, "--link {n}: {reason}"),
            Self::App { file, reason } => write!(
                f,
                "the release app's {file}: {reason} (run `cargo xtask build-web`, or give --app DIR)"
            ),
            Self::Zip(reason) => f.write_str(reason),
        }
    }
}

impl std::error::Error for PackageError {}

impl Package {
    /// Checks what a package is made of; `pass_mark` is as given.
    pub fn new(
        scorm: Scorm,
        title: &str,
        pass_mark: &str,
        items: Vec<Item>,
    ) -> Result<Self, PackageError> {
        let pass_mark = pass_mark
            .trim()
            .parse::<u8>()
            .ok()
            .filter(|&mark| mark <= 100)
            .ok_or_else(|| PackageError::PassMark(pass_mark.chars().take(24).collect()))?;
        let title = title.trim();
        if title.is_empty() {
            return Err(PackageError::Title("the title is empty".to_owned()));
        }
        if title.chars().count() > MAX_TITLE_CHARS {
            return Err(PackageError::Title(format!(
                "the title is longer than {MAX_TITLE_CHARS} characters"
            )));
        }
        if title.chars().any(char::is_control) {
            return Err(PackageError::Title(
                "the title holds a control character".to_owned(),
            ));
        }
        if items.is_empty() {
            return Err(PackageError::NoItems);
        }
        if items.len() > MAX_ITEMS {
            return Err(PackageError::TooManyItems(items.len()));
        }
        let mut seen = std::collections::HashSet::new();
        for item in &items {
            if let Item::Exercise(exercise) = item
                && !seen.insert(file_stem(&exercise.name))
            {
                return Err(PackageError::Duplicate(exercise.name.clone()));
            }
        }
        Ok(Self {
            scorm,
            title: title.to_owned(),
            pass_mark,
            items,
        })
    }

    /// Every file of the package, the manifest first.
    pub fn files(&self, app: &AppFiles) -> Vec<(String, Vec<u8>)> {
        let mut files = vec![
            ("launch.html".to_owned(), self.launch_page(app).into_bytes()),
            ("edgewise-scorm.js".to_owned(), RUNTIME.as_bytes().to_vec()),
        ];
        files.extend(app.files.iter().cloned());
        for item in &self.items {
            if let Item::Exercise(exercise) = item {
                files.push((exercise_file(exercise), exercise.text.clone().into_bytes()));
            }
        }
        let names: Vec<String> = files.iter().map(|(name, _)| name.clone()).collect();
        let manifest = manifest::manifest(self, &self.identifier(), &names);
        files.insert(0, ("imsmanifest.xml".to_owned(), manifest.into_bytes()));
        files
    }

    /// The package as a zip.
    pub fn zip(&self, app: &AppFiles) -> Result<Vec<u8>, PackageError> {
        let mut zip = zip::ZipWriter::default();
        for (name, bytes) in self.files(app) {
            zip.add(&name, &bytes).map_err(PackageError::Zip)?;
        }
        Ok(zip.finish())
    }

    /// What the runtime reads: the version, the pass mark and the items.
    pub fn config(&self) -> serde_json::Value {
        let items: Vec<serde_json::Value> = self
            .items
            .iter()
            .map(|item| match item {
                Item::Exercise(exercise) => json!({
                    "kind": "exercise",
                    "name": file_stem(&exercise.name),
                    "title": exercise.title,
                    "file": exercise_file(exercise),
                    "doIt": matches!(exercise.task, crate::practice::TaskSpec::DoIt(_)),
                }),
                Item::View { title, href } => json!({
                    "kind": "view",
                    "title": title,
                    "href": href,
                }),
            })
            .collect();
        json!({
            "scorm": self.scorm.name(),
            "title": self.title,
            "passMark": self.pass_mark,
            "items": items,
        })
    }

    fn launch_page(&self, app: &AppFiles) -> String {
        // `<` escaped keeps `</script>` in a title from closing the script.
        let config = self.config().to_string().replace('<', "\\u003c");
        LAUNCH_PAGE
            .replace(
                "__EDGEWISE_TITLE__",
                &crate::course_link::escape_attribute(&self.title),
            )
            .replace("__EDGEWISE_BUILD__", app.build())
            .replace("__EDGEWISE_PACKAGE__", &config)
    }

    /// The manifest's identifier: the same for the same package, so an LMS
    /// sees an updated upload as the same course.
    fn identifier(&self) -> String {
        let mut hash: u64 = 0xcbf2_9ce4_8422_2325;
        let mut mix = |text: &str| {
            for byte in text.bytes().chain([0]) {
                hash = (hash ^ u64::from(byte)).wrapping_mul(0x0100_0000_01b3);
            }
        };
        mix(&self.title);
        for item in &self.items {
            match item {
                Item::Exercise(exercise) => mix(&exercise.name),
                Item::View { href, .. } => mix(href),
            }
        }
        format!("edgewise-{hash:016x}")
    }
}

/// A file name made of what every LMS and zip tool takes.
pub fn file_stem(name: &str) -> String {
    name.chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '-' || c == '_' {
                c
            } else {
                '-'
            }
        })
        .collect()
}

fn exercise_file(exercise: &Exercise) -> String {
    format!("exercises/{}.toml", file_stem(&exercise.name))
}

#[cfg(test)]
mod tests;
