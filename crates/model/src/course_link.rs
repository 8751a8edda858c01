//! Course links: a whole view of Edgewise in a URL, so lecture notes can link
//! to, or embed, exactly the mesh, algorithm step, selection and camera they
//! discuss.
//!
//! Short settings go in the query (`?sample=cube&structure=half&step=12`).
//! Mesh and algorithm text go in the fragment (`#mesh=…&format=obj`), raw
//! DEFLATE then base64url: the fragment never reaches the server, so a link
//! carries a mesh without anyone hosting it.
//!
//! Parsing never fails. Each unknown parameter, malformed value or corrupt
//! payload gives one message naming the parameter and what was expected, and
//! that field keeps its default, so a link with one typo still opens the
//! rest of its view. See docs/embedding.md for the parameters.

use edgewise_core::schema::{ElementKind, ElementRef};
use std::collections::BTreeMap;

use base64::Engine as _;
use edgewise_core::formats::compact;
use edgewise_core::mesh::{Polygons, Structure};

use crate::algorithm::session::Argument;
use edgewise_pictures::camera::Camera;
use edgewise_pictures::options::{DrawIds, ViewOptions};

/// The most base64 text a fragment payload may hold; longer ones are refused
/// before decoding, so a huge link cannot stall the page.
pub const MAX_PAYLOAD_CHARS: usize = 1 << 20;
/// The most bytes a payload may inflate to (a zip bomb stops here).
pub const MAX_INFLATED_BYTES: usize = 8 << 20;
/// The colour keys `colors=` accepts: the trace roles as `state()` names
/// them, then the selection roles in camelCase.
pub fn color_keys() -> Vec<String> {
    use crate::trace_role::TraceRole;
    let trace = [
        TraceRole::Lookup,
        TraceRole::Compared,
        TraceRole::Variable,
        TraceRole::Highlighted,
        TraceRole::Output,
    ];
    trace
        .into_iter()
        .map(|role| role.key().to_owned())
        .chain(crate::selection::Role::all().map(crate::selection::Role::setting_key))
        .chain([crate::settings::BOUNDARY.to_owned()])
        .collect()
}
/// The mesh formats an inline mesh may be written in (all have a text form).
pub const INLINE_FORMATS: &[&str] = &["obj", "ply", "wtb", "htb"];
/// The range `meshScale=` accepts, as the View menu's slider.
pub const MESH_SCALE_RANGE: (f32, f32) = (0.25, 4.0);
/// The range `labelScale=` accepts, as the View menu's slider.
pub const LABEL_SCALE_RANGE: (f32, f32) = (0.5, 3.0);
/// The nearest `camera=` may be: the smallest distance four decimals show.
pub const MIN_CAMERA_DISTANCE: f32 = 1e-4;
/// The range `codeSize=` accepts, in points.
pub const CODE_SIZE_RANGE: (f32, f32) = (8.0, 40.0);

/// Base64url; padding is accepted when decoding because hand-made links
/// (JavaScript's `btoa`) often keep it.
const BASE64URL: base64::engine::GeneralPurpose = base64::engine::GeneralPurpose::new(
    &base64::alphabet::URL_SAFE,
    base64::engine::GeneralPurposeConfig::new()
        .with_encode_padding(false)
        .with_decode_padding_mode(base64::engine::DecodePaddingMode::Indifferent),
);
/// Values are quoted in messages up to this many characters.
const QUOTE_CHARS: usize = 40;
/// The query parameters, in the order `to_url` writes them.
const QUERY_KEYS: &[&str] = &[
    "sample",
    "mesh",
    "structure",
    "algorithm",
    "args",
    "step",
    "select",
    "camera",
    "ids",
    "axes",
    "orientation",
    "solid",
    "meshScale",
    "labelScale",
    "theme",
    "embed",
    "origins",
    "tables",
    "panels",
    "present",
    "colors",
    "codeSize",
    "exercise",
    "seed",
];
/// The fragment parameters, in the order `to_url` writes them.
const FRAGMENT_KEYS: &[&str] = &["mesh", "poly", "format", "alg", "ask", "exercise"];

/// Where the link's mesh comes from.
#[derive(Clone, Debug, PartialEq)]
pub enum MeshSource {
    /// A built-in sample by name (`?sample=cube`).
    Sample(String),
    /// A file on the same site, relative to the app's page
    /// (`?mesh=meshes/torus.obj`).
    Path(String),
    /// Mesh text carried in the fragment (`#mesh=<payload>&format=obj`);
    /// `format` is one of [`INLINE_FORMATS`].
    Inline { text: String, format: String },
    /// Polygons in their compact binary form (`#poly=<payload>`,
    /// [`edgewise_core::formats::compact`]): what Share writes when building
    /// from them gives back the mesh's tables exactly, a fraction of the
    /// tables' size.
    Polygons(Polygons),
}

/// The colour theme a link asks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ThemeChoice {
    Light,
    Dark,
}

/// Which panels presentation mode shows (`?panels=algorithm,tables,menu`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Panels {
    pub algorithm: bool,
    pub tables: bool,
    pub menu: bool,
}

/// Everything a course link can say. `None`, `false` and empty mean "not in
/// the link": the app keeps its own default or the user's setting.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CourseLink {
    pub mesh: Option<MeshSource>,
    pub structure: Option<Structure>,
    /// The algorithm to run: a library name, or one in `algorithm_source`.
    pub algorithm: Option<String>,
    /// Algorithm source carried in the fragment (`#alg=<payload>`), loaded
    /// into the menu before `algorithm` is run.
    pub algorithm_source: Option<String>,
    /// A question set for the algorithm (`#ask=<payload>`), already read
    /// once without error (see [`edgewise_core::lang::question`]).
    pub questions: Option<String>,
    /// The algorithm's inputs, in link order (`?args=v:0,n:3`).
    pub args: Vec<(String, Argument)>,
    /// The trace step to show (`?step=12`).
    pub step: Option<usize>,
    pub selection: Option<ElementRef>,
    /// Not sanitised here: apply it with [`Camera::sanitized`].
    pub camera: Option<Camera>,
    pub ids: Option<DrawIds>,
    pub axes: Option<bool>,
    pub orientation: Option<bool>,
    pub solid: Option<bool>,
    pub mesh_scale: Option<f32>,
    pub label_scale: Option<f32>,
    pub theme: Option<ThemeChoice>,
    /// `?embed=1`: the app is inside someone else's page.
    pub embed: bool,
    /// `?tables=0|1`: whether an embedded view shows the tables.
    pub tables: Option<bool>,
    pub panels: Option<Panels>,
    /// `?present=1`: presentation mode.
    pub present: bool,
    /// Role colours changed from the defaults: a key of [`color_keys`] to RGB.
    pub colors: BTreeMap<String, [u8; 3]>,
    /// The algorithm view's font size, in points.
    pub code_size: Option<f32>,
    /// An exercise to start (`?exercise=flip-edge-half-edge`, or any
    /// exercise's text as `#exercise=<payload>`).
    pub exercise: Option<ExerciseLink>,
    /// The seed of the exercise's instance (`?seed=12`).
    pub seed: Option<u64>,
}

/// The exercise a link opens.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ExerciseLink {
    /// A shipped exercise by name.
    Name(String),
    /// An exercise file's text.
    Text(String),
}

impl ExerciseLink {
    /// What `startExercise` takes: the name, or the text.
    pub fn as_str(&self) -> &str {
        match self {
            Self::Name(text) | Self::Text(text) => text,
        }
    }
}

/// Splits a URL, or just its `?…#…` part, into what `location.search`
/// and `location.hash` give (without the `?` and `#`).
pub fn split_url(url: &str) -> (&str, &str) {
    let (rest, fragment) = url.split_once('#').unwrap_or((url, ""));
    let search = rest.split_once('?').map_or("", |(_, query)| query);
    (search, fragment)
}

impl CourseLink {
    /// [`Self::parse`] of a whole URL, or of its `?…#…` part.
    pub fn parse_url(url: &str) -> (Self, Vec<String>) {
        let (search, fragment) = split_url(url);
        Self::parse(search, fragment)
    }

    /// Reads a link from `location.search` and `location.hash` (the leading
    /// `?` and `#` are optional). Returns the link and one message for each
    /// part that was ignored.
    pub fn parse(search: &str, fragment: &str) -> (Self, Vec<String>) {
        let mut parser = Parser::default();
        let search = search.strip_prefix('?').unwrap_or(search);
        let fragment = fragment.strip_prefix('#').unwrap_or(fragment);
        for (key, value) in pairs(search, &mut parser.messages) {
            parser.query(&key, &value);
        }
        for (key, value) in pairs(fragment, &mut parser.messages) {
            parser.fragment(&key, &value);
        }
        parser.finish()
    }

    /// The link as `base?query#fragment`, with only the fields that are set,
    /// always in the same order. Anything after `?` or `#` in `base` is
    /// replaced.
    pub fn to_url(&self, base: &str) -> String {
        self.build(base).url
    }

    /// Like [`Self::to_url`], but refuses a link whose mesh or algorithm
    /// text is too large for [`Self::parse`] to accept.
    pub fn to_url_checked(&self, base: &str) -> Result<String, String> {
        let built = self.build(base);
        match &self.mesh {
            Some(MeshSource::Inline { text, .. }) => {
                check_payload_size("mesh", text.len(), built.mesh_payload_chars)?;
            }
            Some(MeshSource::Polygons(polygons)) => {
                let bytes = compact::encode(polygons).len();
                check_payload_size("poly", bytes, built.mesh_payload_chars)?;
            }
            _ => {}
        }
        if let Some(source) = &self.algorithm_source {
            check_payload_size("alg", source.len(), built.alg_payload_chars)?;
        }
        if let Some(questions) = &self.questions {
            check_payload_size("ask", questions.len(), built.ask_payload_chars)?;
        }
        if let Some(ExerciseLink::Text(text)) = &self.exercise {
            check_payload_size("exercise", text.len(), built.exercise_payload_chars)?;
        }
        Ok(built.url)
    }

    /// Sets the view fields to the options that differ from the defaults.
    pub fn set_view_options(&mut self, options: &ViewOptions) {
        let default = ViewOptions::default();
        let changed = |a: bool, b: bool| (a != b).then_some(a);
        self.ids = (options.draw_ids != default.draw_ids).then_some(options.draw_ids);
        self.axes = changed(options.show_axes, default.show_axes);
        self.orientation = changed(options.show_orientation, default.show_orientation);
        self.solid = changed(options.solid_faces, default.solid_faces);
        self.mesh_scale = (options.mesh_scale != default.mesh_scale).then_some(options.mesh_scale);
        self.label_scale =
            (options.label_scale != default.label_scale).then_some(options.label_scale);
    }

    /// Applies the view fields that are set to `options`.
    pub fn apply_view_options(&self, options: &mut ViewOptions) {
        if let Some(ids) = self.ids {
            options.draw_ids = ids;
        }
        if let Some(axes) = self.axes {
            options.show_axes = axes;
        }
        if let Some(orientation) = self.orientation {
            options.show_orientation = orientation;
        }
        if let Some(solid) = self.solid {
            options.solid_faces = solid;
        }
        if let Some(scale) = self.mesh_scale {
            options.mesh_scale = scale;
        }
        if let Some(scale) = self.label_scale {
            options.label_scale = scale;
        }
    }

    fn build(&self, base: &str) -> Built {
        let mut query = Vec::new();
        let mut fragment = Vec::new();
        let mut built = Built::default();
        let mut push = |key: &str, value: String| query.push(format!("{key}={}", encode(&value)));

        match &self.mesh {
            Some(MeshSource::Sample(name)) => push("sample", name.clone()),
            Some(MeshSource::Path(path)) => push("mesh", path.clone()),
            Some(MeshSource::Inline { text, format }) => {
                let payload = encode_payload(text);
                built.mesh_payload_chars = payload.len();
                fragment.push(format!("mesh={payload}"));
                fragment.push(format!("format={}", encode(format)));
            }
            Some(MeshSource::Polygons(polygons)) => {
                let payload = encode_bytes(&compact::encode(polygons));
                built.mesh_payload_chars = payload.len();
                fragment.push(format!("poly={payload}"));
            }
            None => {}
        }
        if let Some(structure) = self.structure {
            push("structure", structure.link_name().to_owned());
        }
        if let Some(name) = &self.algorithm {
            push("algorithm", name.clone());
        }
        if !self.args.is_empty() {
            let args: Vec<String> = self
                .args
                .iter()
                .map(|(name, value)| match value {
                    Argument::Number(n) => format!("{name}:{n}"),
                    Argument::Boolean(b) => format!("{name}:{b}"),
                })
                .collect();
            push("args", args.join(","));
        }
        if let Some(step) = self.step {
            push("step", step.to_string());
        }
        if let Some(element) = self.selection {
            push(
                "select",
                format!("{}:{}", kind_name(element.kind), element.id),
            );
        }
        if let Some(camera) = self.camera {
            let numbers = [
                camera.yaw,
                camera.pitch,
                camera.distance,
                camera.target[0],
                camera.target[1],
                camera.target[2],
            ];
            let numbers: Vec<String> = numbers.iter().map(|&x| decimals4(x)).collect();
            push("camera", numbers.join(","));
        }
        if let Some(ids) = self.ids {
            push("ids", draw_ids_name(ids).to_owned());
        }
        for (key, value) in [
            ("axes", self.axes),
            ("orientation", self.orientation),
            ("solid", self.solid),
        ] {
            if let Some(value) = value {
                push(key, flag(value));
            }
        }
        if let Some(scale) = self.mesh_scale {
            push("meshScale", scale.to_string());
        }
        if let Some(scale) = self.label_scale {
            push("labelScale", scale.to_string());
        }
        if let Some(theme) = self.theme {
            push("theme", theme_name(theme).to_owned());
        }
        if self.embed {
            push("embed", flag(true));
        }
        if let Some(tables) = self.tables {
            push("tables", flag(tables));
        }
        if let Some(panels) = self.panels {
            let names: Vec<&str> = [
                (panels.algorithm, "algorithm"),
                (panels.tables, "tables"),
                (panels.menu, "menu"),
            ]
            .into_iter()
            .filter_map(|(on, name)| on.then_some(name))
            .collect();
            let value = if names.is_empty() {
                "none".to_owned()
            } else {
                names.join(",")
            };
            push("panels", value);
        }
        if self.present {
            push("present", flag(true));
        }
        if !self.colors.is_empty() {
            let colors: Vec<String> = self
                .colors
                .iter()
                .map(|(key, [r, g, b])| format!("{key}:{r:02x}{g:02x}{b:02x}"))
                .collect();
            push("colors", colors.join(","));
        }
        if let Some(size) = self.code_size {
            push("codeSize", size.to_string());
        }
        match &self.exercise {
            Some(ExerciseLink::Name(name)) => push("exercise", name.clone()),
            Some(ExerciseLink::Text(_)) | None => {}
        }
        if let Some(seed) = self.seed {
            push("seed", seed.to_string());
        }
        if let Some(source) = &self.algorithm_source {
            let payload = encode_payload(source);
            built.alg_payload_chars = payload.len();
            fragment.push(format!("alg={payload}"));
        }
        if let Some(questions) = &self.questions {
            let payload = encode_payload(questions);
            built.ask_payload_chars = payload.len();
            fragment.push(format!("ask={payload}"));
        }

        if let Some(ExerciseLink::Text(text)) = &self.exercise {
            let payload = encode_payload(text);
            built.exercise_payload_chars = payload.len();
            fragment.push(format!("exercise={payload}"));
        }

        let base = base.split(['?', '#']).next().unwrap_or_default();
        let mut url = base.to_owned();
        if !query.is_empty() {
            url.push('?');
            url.push_str(&query.join("&"));
        }
        if !fragment.is_empty() {
            url.push('#');
            url.push_str(&fragment.join("&"));
        }
        built.url = url;
        built
    }
}

/// An `<iframe>` for a page author to paste: lazy, titled with what it
/// shows (a screen reader's name for the frame), allowed to go full screen,
/// and never wider than the page.
pub fn embed_snippet(url: &str, (width, height): (u32, u32), title: &str) -> String {
    format!(
        "<iframe src=\"{}\" width=\"{width}\" height=\"{height}\" \
         title=\"{}\" allow=\"fullscreen\" allowfullscreen \
         loading=\"lazy\" style=\"border: 1px solid #c8c6bf; border-radius: 6px; \
         max-width: 100%;\"></iframe>",
        escape_attribute(url),
        escape_attribute(title)
    )
}

/// DEFLATE then base64url: the form of `#mesh=` and `#alg=` payloads, and
/// what `CompressionStream('deflate-raw')` plus base64url makes in a page.
pub fn encode_payload(text: &str) -> String {
    encode_bytes(text.as_bytes())
}

/// DEFLATE then base64url, for any bytes (`#poly=`).
fn encode_bytes(bytes: &[u8]) -> String {
    BASE64URL.encode(miniz_oxide::deflate::compress_to_vec(bytes, 9))
}

/// Reverses [`encode_payload`] within the size limits; `name` is the
/// fragment parameter, for the message.
pub fn decode_payload(name: &str, payload: &str) -> Result<String, String> {
    let bytes = decode_bytes(name, "text", payload)?;
    String::from_utf8(bytes).map_err(|_| format!("#{name}: the uncompressed text is not UTF-8"))
}

/// `#poly=`'s polygons, refused with the place where they go wrong.
fn decode_polygons(payload: &str) -> Result<Polygons, String> {
    let bytes = decode_bytes("poly", "polygons", payload)?;
    compact::decode(&bytes).map_err(|err| {
        format!(
            "#poly: the polygons are damaged ({err}); the link may have been changed or cut \
             short when it was copied"
        )
    })
}

/// Reverses [`encode_bytes`] within the size limits; `what` the payload
/// holds ("text", "polygons"), for the message.
fn decode_bytes(name: &str, what: &str, payload: &str) -> Result<Vec<u8>, String> {
    if payload.is_empty() {
        return Err(format!(
            "#{name}= is empty; expected compressed {what}, as the Share dialog writes it"
        ));
    }
    if payload.len() > MAX_PAYLOAD_CHARS {
        return Err(format!(
            "#{name}: the payload is {}, more than the {} a link may carry; {}",
            mebibytes(payload.len()),
            mebibytes(MAX_PAYLOAD_CHARS),
            too_large_hint(name)
        ));
    }
    let compressed = BASE64URL.decode(payload).map_err(|_| {
        format!(
            "#{name}: the payload is not base64url text (letters, digits, - and _); \
             the link may have been changed or cut short when it was copied"
        )
    })?;
    let bytes = miniz_oxide::inflate::decompress_to_vec_with_limit(&compressed, MAX_INFLATED_BYTES)
        .map_err(|err| match err.status {
            miniz_oxide::inflate::TINFLStatus::HasMoreOutput => format!(
                "#{name}: the text is more than {} once uncompressed, the most a link may \
                 carry; {}",
                mebibytes(MAX_INFLATED_BYTES),
                too_large_hint(name)
            ),
            _ => format!(
                "#{name}: the payload is not raw DEFLATE data; the link may have been cut \
                 short when it was copied"
            ),
        })?;
    Ok(bytes)
}

#[derive(Default)]
struct Built {
    url: String,
    mesh_payload_chars: usize,
    alg_payload_chars: usize,
    ask_payload_chars: usize,
    exercise_payload_chars: usize,
}

fn check_payload_size(name: &str, text_bytes: usize, payload_chars: usize) -> Result<(), String> {
    if text_bytes > MAX_INFLATED_BYTES {
        return Err(format!(
            "#{name}: the text is {}, more than the {} a link may carry; {}",
            mebibytes(text_bytes),
            mebibytes(MAX_INFLATED_BYTES),
            too_large_hint(name)
        ));
    }
    if payload_chars > MAX_PAYLOAD_CHARS {
        return Err(format!(
            "#{name}: the compressed text is {}, more than the {} a link may carry; {}",
            mebibytes(payload_chars),
            mebibytes(MAX_PAYLOAD_CHARS),
            too_large_hint(name)
        ));
    }
    Ok(())
}

fn too_large_hint(name: &str) -> &'static str {
    if name == "mesh" || name == "poly" {
        "put the file beside the page and link it with mesh=path instead"
    } else {
        "put the algorithms in a smaller file"
    }
}

fn mebibytes(bytes: usize) -> String {
    let mib = bytes as f64 / f64::from(1u32 << 20);
    if mib.fract() == 0.0 {
        format!("{mib} MiB")
    } else {
        format!("{mib:.1} MiB")
    }
}

/// Collects the fields and messages while reading a link.
#[derive(Default)]
struct Parser {
    link: CourseLink,
    messages: Vec<String>,
    /// Which mesh parameter set `link.mesh`: inline beats path beats sample.
    mesh_from: Option<&'static str>,
    format: Option<String>,
    /// `args=` as written, for the message when there is no algorithm.
    args_written: Option<String>,
    seen: Vec<String>,
}

impl Parser {
    fn query(&mut self, key: &str, value: &str) {
        if QUERY_KEYS.contains(&key) {
            self.note_repeat(key.to_owned());
        }
        let result = match key {
            "sample" => self.sample(value),
            "mesh" => self.mesh_path(value),
            "structure" => Structure::parse_link_name(value)
                .map(|s| self.link.structure = Some(s))
                .ok_or("expected winged or half, such as structure=half"),
            "algorithm" => parse_name(value)
                .map(|n| self.link.algorithm = Some(n))
                .ok_or("expected an algorithm's name, such as algorithm=vertexAdjacentEdge"),
            "args" => {
                self.args_written = Some(value.to_owned());
                parse_args(value).map(|a| self.link.args = a)
            }
            "step" => value
                .parse()
                .map(|n| self.link.step = Some(n))
                .map_err(|_| "expected a whole number of steps, such as step=12"),
            "exercise" => {
                self.exercise(value);
                Ok(())
            }
            "seed" => value
                .parse()
                .map(|n| self.link.seed = Some(n))
                .map_err(|_| "expected a whole number, such as seed=12"),
            "select" => parse_selection(value)
                .map(|e| self.link.selection = Some(e))
                .ok_or("expected vertex, edge or face and an id, such as select=edge:3"),
            "camera" => parse_camera(value)
                .map(|c| self.link.camera = Some(c))
                .ok_or(
                    "expected six numbers yaw,pitch,distance,x,y,z with a distance of at least \
                     0.0001, such as camera=0.55,0.4,5,0,0,0",
                ),
            "ids" => parse_draw_ids(value)
                .map(|ids| self.link.ids = Some(ids))
                .ok_or("expected always, highlighted or never, such as ids=always"),
            "axes" => parse_flag(value).map(|b| self.link.axes = Some(b)),
            "orientation" => parse_flag(value).map(|b| self.link.orientation = Some(b)),
            "solid" => parse_flag(value).map(|b| self.link.solid = Some(b)),
            "meshScale" => parse_in_range(value, MESH_SCALE_RANGE)
                .map(|x| self.link.mesh_scale = Some(x))
                .ok_or("expected a number from 0.25 to 4, such as meshScale=1.5"),
            "labelScale" => parse_in_range(value, LABEL_SCALE_RANGE)
                .map(|x| self.link.label_scale = Some(x))
                .ok_or("expected a number from 0.5 to 3, such as labelScale=2"),
            "theme" => match value {
                "light" => Some(ThemeChoice::Light),
                "dark" => Some(ThemeChoice::Dark),
                _ => None,
            }
            .map(|t| self.link.theme = Some(t))
            .ok_or("expected light or dark, such as theme=dark"),
            "embed" => parse_flag(value).map(|b| self.link.embed = b),
            // The page's embed bridge reads it (docs/embedding.md); the
            // link only checks it, so a mistake is named.
            "origins" => check_origins(value),
            "tables" => parse_flag(value).map(|b| self.link.tables = Some(b)),
            "panels" => parse_panels(value)
                .map(|p| self.link.panels = Some(p))
                .ok_or(
                    "expected none or a list of algorithm, tables and menu, \
                     such as panels=algorithm,tables",
                ),
            "present" => parse_flag(value).map(|b| self.link.present = b),
            "colors" => {
                self.colors(value);
                Ok(())
            }
            "codeSize" => parse_in_range(value, CODE_SIZE_RANGE)
                .map(|x| self.link.code_size = Some(x))
                .ok_or("expected a font size from 8 to 40 points, such as codeSize=18"),
            _ => {
                self.messages.push(unknown(key, value, QUERY_KEYS, ""));
                Ok(())
            }
        };
        if let Err(expected) = result {
            self.messages
                .push(format!("{key}={}: {expected}", quote(value)));
        }
    }

    fn fragment(&mut self, key: &str, value: &str) {
        if FRAGMENT_KEYS.contains(&key) {
            self.note_repeat(format!("#{key}"));
        }
        match key {
            "mesh" => match decode_payload("mesh", value) {
                Ok(text) => self.set_mesh(
                    "#mesh",
                    MeshSource::Inline {
                        text,
                        format: String::new(),
                    },
                ),
                Err(message) => self.messages.push(message),
            },
            "poly" => match decode_polygons(value) {
                Ok(polygons) => self.set_mesh("#poly", MeshSource::Polygons(polygons)),
                Err(message) => self.messages.push(message),
            },
            "format" => {
                if INLINE_FORMATS.contains(&value) {
                    self.format = Some(value.to_owned());
                } else {
                    self.messages.push(format!(
                        "#format={}: expected obj, ply, wtb or htb, such as format=obj",
                        quote(value)
                    ));
                }
            }
            "alg" => match decode_payload("alg", value) {
                Ok(source) => self.link.algorithm_source = Some(source),
                Err(message) => self.messages.push(message),
            },
            "exercise" => match decode_payload("exercise", value) {
                Ok(text) => self.link.exercise = Some(ExerciseLink::Text(text)),
                Err(message) => self.messages.push(message),
            },
            "ask" => match decode_payload("ask", value) {
                Ok(text) => match edgewise_core::lang::question::parse_set(&text) {
                    Ok(_) => self.link.questions = Some(text),
                    Err(error) => self
                        .messages
                        .push(format!("#ask= question set, line {error}")),
                },
                Err(message) => self.messages.push(message),
            },
            _ => self.messages.push(unknown(key, value, FRAGMENT_KEYS, "#")),
        }
    }

    /// Says so when a parameter comes twice (`shown` is `step` or `#mesh`).
    fn note_repeat(&mut self, shown: String) {
        if self.seen.contains(&shown) {
            self.messages.push(format!(
                "{shown}= is given more than once; the last one is used"
            ));
        } else {
            self.seen.push(shown);
        }
    }

    fn exercise(&mut self, name: &str) {
        if crate::practice::catalog::SHIPPED
            .iter()
            .any(|e| e.name == name)
        {
            self.link.exercise = Some(ExerciseLink::Name(name.to_owned()));
        } else {
            self.messages.push(format!(
                "exercise={}: no exercise has that name; the exercises are {}",
                quote(name),
                crate::practice::catalog::names().join(", ")
            ));
        }
    }

    fn sample(&mut self, name: &str) -> Result<(), &'static str> {
        if crate::samples::find(name).is_some() {
            self.set_mesh("sample", MeshSource::Sample(name.to_owned()));
            Ok(())
        } else {
            let names: Vec<&str> = crate::samples::SAMPLES.iter().map(|s| s.name).collect();
            self.messages.push(format!(
                "sample={}: no sample has that name; the samples are {}",
                quote(name),
                names.join(", ")
            ));
            Ok(())
        }
    }

    fn mesh_path(&mut self, path: &str) -> Result<(), &'static str> {
        check_mesh_path(path).map(|()| self.set_mesh("mesh", MeshSource::Path(path.to_owned())))
    }

    /// Keeps the strongest mesh source and says which one was dropped.
    fn set_mesh(&mut self, from: &'static str, source: MeshSource) {
        let rank = |from: &str| match from {
            "#mesh" | "#poly" => 2,
            "mesh" => 1,
            _ => 0,
        };
        match self.mesh_from {
            Some(previous) if previous != from => {
                let (kept, dropped) = if rank(from) > rank(previous) {
                    (from, previous)
                } else {
                    (previous, from)
                };
                self.messages.push(format!(
                    "{dropped}= and {kept}= both give a mesh; {kept}= is used"
                ));
                if kept == previous {
                    return;
                }
            }
            _ => {}
        }
        self.mesh_from = Some(from);
        self.link.mesh = Some(source);
    }

    fn colors(&mut self, value: &str) {
        for entry in value.split(',') {
            let Some((key, hex)) = entry.split_once(':') else {
                self.messages.push(format!(
                    "colors={}: expected role:rrggbb pairs, such as colors=lookup:22aa44,marked:1d5bd8",
                    quote(entry)
                ));
                continue;
            };
            let keys = color_keys();
            if !keys.iter().any(|known| known == key) {
                self.messages.push(format!(
                    "colors={}: {} is not a role; the roles are {}",
                    quote(entry),
                    quote(key),
                    keys.join(", ")
                ));
                continue;
            }
            match parse_hex_colour(hex) {
                Some(rgb) => {
                    self.link.colors.insert(key.to_owned(), rgb);
                }
                None => self.messages.push(format!(
                    "colors={}: expected a colour as six hex digits, such as {key}:22aa44",
                    quote(entry)
                )),
            }
        }
    }

    fn finish(mut self) -> (CourseLink, Vec<String>) {
        match (&mut self.link.mesh, self.format.take()) {
            (Some(MeshSource::Inline { format, .. }), chosen) => {
                // The Share dialog always writes format=; OBJ is the common hand-made case.
                *format = chosen.unwrap_or_else(|| "obj".to_owned());
            }
            (_, Some(format)) => self.messages.push(format!(
                "#format={format}: only used with #mesh=, which this link does not have"
            )),
            (_, None) => {}
        }
        if self.link.algorithm.is_none() {
            if let (Some(written), false) = (&self.args_written, self.link.args.is_empty()) {
                self.messages.push(format!(
                    "args={}: only used with algorithm=, which this link does not have",
                    quote(written)
                ));
                self.link.args.clear();
            }
            if let Some(step) = self.link.step.take() {
                self.messages.push(format!(
                    "step={step}: only used with algorithm=, which this link does not have"
                ));
            }
            if self.link.questions.take().is_some() {
                self.messages.push(
                    "#ask=: only used with algorithm=, which this link does not have".to_owned(),
                );
            }
        }
        (self.link, self.messages)
    }
}

/// Splits `a=1&b=2` into decoded pairs. A bare key (`embed`) has an empty
/// value, which the switches read as on.
fn pairs(text: &str, messages: &mut Vec<String>) -> Vec<(String, String)> {
    let mut out = Vec::new();
    for piece in text.split('&').filter(|p| !p.is_empty()) {
        let (key, value) = piece.split_once('=').unwrap_or((piece, ""));
        let key = decode(key);
        if key.is_empty() {
            messages.push(format!(
                "{}: a parameter has no name before its =",
                quote(&decode(piece))
            ));
            continue;
        }
        out.push((key, decode(value)));
    }
    out
}

fn unknown(key: &str, value: &str, known: &[&str], part: &str) -> String {
    let shown = if value.is_empty() {
        format!("{part}{}", quote(key))
    } else {
        format!("{part}{}={}", quote(key), quote(value))
    };
    let near = known.iter().find(|k| k.eq_ignore_ascii_case(key));
    let mut message = match near {
        Some(k) => format!("{shown}: unknown parameter; did you mean {k}?"),
        None => format!("{shown}: unknown parameter"),
    };
    if part == "#" && QUERY_KEYS.contains(&key) {
        message.push_str(&format!("; {key}= belongs before the #"));
    } else if part.is_empty() && near.is_none() {
        message.push_str("; see docs/embedding.md for the parameters Edgewise reads");
    }
    message
}

/// `origins=`: the embedding pages allowed to command the view and hear
/// its events, as a comma-separated list of `https://host[:port]` origins.
fn check_origins(value: &str) -> Result<(), &'static str> {
    let is_origin = |item: &str| {
        let Some((scheme, rest)) = item.split_once("://") else {
            return false;
        };
        let (host, port) = match rest.rsplit_once(':') {
            Some((host, port)) if !host.ends_with(']') || rest.starts_with('[') => {
                (host, Some(port))
            }
            _ => (rest, None),
        };
        matches!(scheme, "http" | "https")
            && !host.is_empty()
            && host
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || matches!(c, '.' | '-' | '[' | ']' | ':'))
            && port.is_none_or(|p| {
                !p.is_empty() && p.len() <= 5 && p.bytes().all(|b| b.is_ascii_digit())
            })
    };
    if !value.is_empty() && value.split(',').all(is_origin) {
        Ok(())
    } else {
        Err("expected a comma-separated list of origins, such as \
             origins=https://notes.example.edu,https://slides.example.edu")
    }
}

/// A same-site path relative to the app's page. Absolute URLs, `//hosts`,
/// schemes, `..`, and whatever the URL parser would strip into one of them
/// are refused, so a link can only open the site's own files; the page also
/// resolves the path and compares origins before it fetches.
fn check_mesh_path(path: &str) -> Result<(), &'static str> {
    if path.is_empty() {
        return Err("expected a path to a mesh file on this site, such as mesh=meshes/torus.obj");
    }
    // The URL parser strips spaces and control characters from both ends
    // (and tabs and newlines from anywhere): " //host/x.obj" is another
    // site's file.
    if path.starts_with(|c: char| c <= ' ') || path.ends_with(|c: char| c <= ' ') {
        return Err(
            "expected a path that starts and ends with a visible character, such as \
             mesh=meshes/torus.obj; spaces and control characters at either end are not allowed",
        );
    }
    if path.starts_with("//") {
        return Err(
            "expected a path on this site, such as mesh=meshes/torus.obj; links cannot load \
             meshes from other sites",
        );
    }
    if path.starts_with('/') || path.contains('\\') {
        return Err(
            "expected a path relative to the app's page, such as mesh=meshes/torus.obj; \
             it may not start with / or contain \\",
        );
    }
    let first_segment = path.split('/').next().unwrap_or_default();
    if first_segment.contains(':') {
        return Err(
            "expected a path on this site, such as mesh=meshes/torus.obj; links cannot load \
             meshes from other sites",
        );
    }
    if path.chars().any(|c| c.is_control() || c == '?' || c == '#') {
        return Err("expected a plain file path, without ?, # or control characters");
    }
    let dot_segment = path.split('/').any(|segment| {
        let s = segment.to_ascii_lowercase().replace("%2e", ".");
        s == "." || s == ".."
    });
    if dot_segment {
        return Err(
            "expected a path inside the app's folder, such as mesh=meshes/torus.obj; \
             . and .. segments are not allowed",
        );
    }
    let extension = path.rsplit_once('.').map(|(_, e)| e.to_ascii_lowercase());
    if !extension.is_some_and(|e| INLINE_FORMATS.contains(&e.as_str())) {
        return Err("expected a .obj, .ply, .wtb or .htb file, such as mesh=meshes/torus.obj");
    }
    Ok(())
}

/// An algorithm or parameter name: letters, digits and `_`, not starting
/// with a digit.
fn parse_name(text: &str) -> Option<String> {
    let mut chars = text.chars();
    let first = chars.next()?;
    let ok = (first.is_ascii_alphabetic() || first == '_')
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_');
    ok.then(|| text.to_owned())
}

fn parse_args(value: &str) -> Result<Vec<(String, Argument)>, &'static str> {
    const EXPECTED: &str =
        "expected name:value pairs separated by commas, such as args=v:0,n:3 or args=closed:true";
    let mut args: Vec<(String, Argument)> = Vec::new();
    for entry in value.split(',') {
        let (name, value) = entry.split_once(':').ok_or(EXPECTED)?;
        let name = parse_name(name).ok_or(EXPECTED)?;
        let argument = Argument::parse(value).ok_or(EXPECTED)?;
        if args.iter().any(|(n, _)| *n == name) {
            return Err("expected each input once, such as args=v:0,n:3");
        }
        args.push((name, argument));
    }
    Ok(args)
}

fn parse_selection(value: &str) -> Option<ElementRef> {
    let (kind, id) = value.split_once(':')?;
    let kind = match kind {
        "vertex" => ElementKind::Vertex,
        "edge" => ElementKind::Edge,
        "face" => ElementKind::Face,
        _ => return None,
    };
    Some(ElementRef {
        kind,
        id: id.parse().ok()?,
    })
}

fn parse_camera(value: &str) -> Option<Camera> {
    let numbers: Vec<f32> = value
        .split(',')
        .map(|x| parse_finite(x).map(|x| x as f32).filter(|x| x.is_finite()))
        .collect::<Option<_>>()?;
    let [yaw, pitch, distance, x, y, z] = numbers[..] else {
        return None;
    };
    (distance >= MIN_CAMERA_DISTANCE).then_some(Camera {
        target: [x, y, z],
        yaw,
        pitch,
        distance,
    })
}

fn parse_draw_ids(value: &str) -> Option<DrawIds> {
    match value {
        "always" => Some(DrawIds::Always),
        "highlighted" => Some(DrawIds::Highlighted),
        "never" => Some(DrawIds::Never),
        _ => None,
    }
}

fn parse_panels(value: &str) -> Option<Panels> {
    let mut panels = Panels::default();
    if value == "none" || value.is_empty() {
        return Some(panels);
    }
    for name in value.split(',') {
        match name {
            "algorithm" => panels.algorithm = true,
            "tables" => panels.tables = true,
            "menu" => panels.menu = true,
            _ => return None,
        }
    }
    Some(panels)
}

/// A switch: `1`/`true`/bare name for on, `0`/`false` for off.
fn parse_flag(value: &str) -> Result<bool, &'static str> {
    match value {
        "" | "1" | "true" => Ok(true),
        "0" | "false" => Ok(false),
        _ => Err("expected 1 or 0 (on or off)"),
    }
}

fn parse_finite(text: &str) -> Option<f64> {
    // Rust also reads "inf" and "NaN"; a link has no use for them.
    text.parse::<f64>().ok().filter(|x| x.is_finite())
}

fn parse_in_range(value: &str, (low, high): (f32, f32)) -> Option<f32> {
    let x = parse_finite(value)? as f32;
    (low..=high).contains(&x).then_some(x)
}

fn parse_hex_colour(hex: &str) -> Option<[u8; 3]> {
    let hex = hex.strip_prefix('#').unwrap_or(hex);
    if hex.len() != 6 || !hex.bytes().all(|b| b.is_ascii_hexdigit()) {
        return None;
    }
    let byte = |i: usize| u8::from_str_radix(&hex[i..i + 2], 16).ok();
    Some([byte(0)?, byte(2)?, byte(4)?])
}

fn kind_name(kind: ElementKind) -> &'static str {
    match kind {
        ElementKind::Vertex => "vertex",
        ElementKind::Edge => "edge",
        ElementKind::Face => "face",
    }
}

fn draw_ids_name(ids: DrawIds) -> &'static str {
    match ids {
        DrawIds::Always => "always",
        DrawIds::Highlighted => "highlighted",
        DrawIds::Never => "never",
    }
}

fn theme_name(theme: ThemeChoice) -> &'static str {
    match theme {
        ThemeChoice::Light => "light",
        ThemeChoice::Dark => "dark",
    }
}

fn flag(on: bool) -> String {
    if on { "1" } else { "0" }.to_owned()
}

/// At most four decimals, without trailing zeros: short links, and camera
/// positions no one can tell apart.
fn decimals4(x: f32) -> String {
    let text = format!("{x:.4}");
    let text = text.trim_end_matches('0').trim_end_matches('.');
    if text == "-0" { "0" } else { text }.to_owned()
}

/// A value as quoted in a message: shortened, so a pasted payload in the
/// wrong place does not flood the message line, and with control, invisible
/// and direction-changing characters escaped (`\u{202e}`), so a crafted link
/// cannot hide or reorder what the message says.
fn quote(value: &str) -> String {
    let mut quoted = String::new();
    for (count, ch) in value.chars().enumerate() {
        if count == QUOTE_CHARS {
            quoted.push('…');
            break;
        }
        let hidden = ch.is_control()
            || matches!(ch, '\u{200b}'..='\u{200f}' | '\u{202a}'..='\u{202e}' | '\u{2066}'..='\u{2069}' | '\u{feff}');
        if hidden {
            quoted.extend(ch.escape_unicode());
        } else {
            quoted.push(ch);
        }
    }
    quoted
}

/// Percent-encodes a query value. Commas, colons and slashes stay readable
/// (`args=v:0,n:3`, `mesh=meshes/cube.htb`); everything that could end the
/// value or the URL is escaped.
fn encode(value: &str) -> String {
    let mut out = String::with_capacity(value.len());
    for byte in value.bytes() {
        if byte.is_ascii_alphanumeric() || b"-._~,:/!*'()".contains(&byte) {
            out.push(char::from(byte));
        } else {
            out.push_str(&format!("%{byte:02X}"));
        }
    }
    out
}

/// Decodes `%XX` and `+` as `URLSearchParams` does: a malformed escape is
/// kept as it is, and bytes that are not UTF-8 become U+FFFD.
fn decode(text: &str) -> String {
    let bytes = text.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        let hex = |b: u8| char::from(b).to_digit(16);
        match bytes[i] {
            b'%' if i + 2 < bytes.len() => match (hex(bytes[i + 1]), hex(bytes[i + 2])) {
                (Some(high), Some(low)) => {
                    out.push((high * 16 + low) as u8);
                    i += 3;
                    continue;
                }
                _ => out.push(b'%'),
            },
            b'+' => out.push(b' '),
            b => out.push(b),
        }
        i += 1;
    }
    String::from_utf8_lossy(&out).into_owned()
}

/// A mesh file a link's `mesh=` path names, read by the caller (the
/// browser fetches it; the command line reads it from disk).
pub struct FetchedMesh {
    pub name: String,
    pub bytes: Result<Vec<u8>, String>,
}

/// What a link sets up once its mesh is open, in the order a lecturer
/// would: the app and a [`crate::still::Still`] each follow a link through
/// this, so both refuse the same parts with the same words.
pub trait Follow {
    fn load_algorithms(&mut self, source: &str, file: &str) -> Result<(), String>;
    fn run_algorithm(&mut self, name: &str, args: &[(String, Argument)]) -> Result<(), String>;
    fn set_questions(&mut self, text: &str) -> Result<(), String>;
    fn goto(&mut self, step: usize) -> Result<(), String>;
    /// Whether an algorithm waits for inputs or is traced.
    fn is_running(&self) -> bool;
    fn select(&mut self, element: ElementRef) -> Result<(), String>;
}

impl CourseLink {
    /// `settings` with the link's theme, colours and code size: a link's
    /// look applies to one visit, over the user's own settings.
    pub fn look(&self, settings: &crate::settings::Settings) -> crate::settings::Settings {
        let mut settings = settings.clone();
        if let Some(theme) = self.theme {
            settings.dark = theme == ThemeChoice::Dark;
        }
        for (key, [r, g, b]) in &self.colors {
            settings.colours.insert(
                key.clone(),
                edgewise_pictures::palette::to_hex(ecolor::Color32::from_rgb(*r, *g, *b)),
            );
        }
        if let Some(size) = self.code_size {
            settings.code_size = size;
        }
        settings
    }
}

impl CourseLink {
    /// Loads the link's algorithms, runs its algorithm with its inputs and
    /// questions to its step, or selects its element; each part that cannot
    /// be followed adds a message naming its parameter.
    pub fn follow(&self, target: &mut impl Follow, messages: &mut Vec<String>) {
        if let Some(source) = &self.algorithm_source
            && let Err(message) = target.load_algorithms(source, "link.alg")
        {
            messages.push(message);
        }
        if let Some(name) = &self.algorithm {
            match target.run_algorithm(name, &self.args) {
                Ok(()) => {
                    if let Some(questions) = &self.questions
                        && let Err(message) = target.set_questions(questions)
                    {
                        messages.push(format!("#ask=: {message}"));
                    }
                    if let Some(step) = self.step
                        && let Err(message) = target.goto(step)
                    {
                        messages.push(format!("step={step}: {message}"));
                    }
                }
                Err(message) => messages.push(format!("algorithm={name}: {message}")),
            }
        } else if self.step.is_some() {
            messages.push("step= needs an algorithm= to step through".to_owned());
        }
        if let Some(selection) = self.selection {
            if target.is_running() {
                messages.push("select= is ignored while an algorithm runs".to_owned());
            } else if let Err(message) = target.select(selection) {
                messages.push(format!("select=: {message}"));
            }
        }
    }
}

/// Text made safe inside an HTML attribute or element.
pub fn escape_attribute(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('"', "&quot;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

#[cfg(test)]
mod tests;
