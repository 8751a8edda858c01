//! `edgewise package`: the zip read back by an independent reader (the
//! `zip` crate), its manifest parsed as XML and held to what an LMS needs,
//! and bad input refused with exit 2 and nothing written.

use std::collections::BTreeSet;
use std::io::Read as _;
use std::path::Path;

use quick_xml::Reader;
use quick_xml::events::Event;

use crate::common::{code, run_in, scratch, stderr};

/// A stand-in for `dist/`: the names and the stamped build of a release.
fn release(dir: &Path) -> std::path::PathBuf {
    let app = dir.join("dist");
    std::fs::create_dir_all(&app).expect("dist");
    let files = [
        ("index.html", "<script>const BUILD = 'c0ffee12';</script>"),
        ("edgewise_app.c0ffee12.js", "export default function () {}"),
        ("edgewise_app_bg.c0ffee12.wasm", "\0asm"),
        ("favicon.svg", "<svg/>"),
    ];
    for (name, text) in files {
        std::fs::write(app.join(name), text).expect("write");
    }
    app
}

fn entries(zip: &Path) -> Vec<(String, Vec<u8>)> {
    let file = std::fs::File::open(zip).expect("the zip");
    let mut archive = zip::ZipArchive::new(file).expect("a zip archive");
    (0..archive.len())
        .map(|i| {
            let mut entry = archive.by_index(i).expect("an entry");
            let mut bytes = Vec::new();
            entry
                .read_to_end(&mut bytes)
                .expect("inflates, CRC checked");
            (entry.name().expect("a UTF-8 name").into_owned(), bytes)
        })
        .collect()
}

/// One element of the manifest: its path from the root
/// (`manifest/metadata/schema`), attributes and text.
struct Element {
    path: String,
    attributes: Vec<(String, String)>,
    text: String,
}

impl Element {
    fn attribute(&self, name: &str) -> Option<&str> {
        self.attributes
            .iter()
            .find(|(key, _)| key == name)
            .map(|(_, value)| value.as_str())
    }
}

/// The manifest's elements in document order, as an LMS's importer walks
/// them; malformed XML fails the test.
fn parse_manifest(xml: &str) -> Vec<Element> {
    let mut reader = Reader::from_str(xml);
    let mut path: Vec<String> = Vec::new();
    let mut open: Vec<usize> = Vec::new();
    let mut elements: Vec<Element> = Vec::new();
    loop {
        let event = reader.read_event().expect("well-formed XML");
        match &event {
            Event::Start(tag) | Event::Empty(tag) => {
                let name = String::from_utf8_lossy(tag.name().as_ref()).into_owned();
                let attributes = tag
                    .attributes()
                    .map(|a| {
                        let a = a.expect("an attribute");
                        (
                            String::from_utf8_lossy(a.key.as_ref()).into_owned(),
                            a.normalized_value(quick_xml::XmlVersion::Explicit1_0)
                                .expect("a value")
                                .into_owned(),
                        )
                    })
                    .collect();
                let full = path
                    .iter()
                    .chain([&name])
                    .cloned()
                    .collect::<Vec<_>>()
                    .join("/");
                elements.push(Element {
                    path: full,
                    attributes,
                    text: String::new(),
                });
                if matches!(event, Event::Start(_)) {
                    path.push(name);
                    open.push(elements.len() - 1);
                }
            }
            Event::Text(text) => {
                if let Some(&at) = open.last() {
                    elements[at].text.push_str(&text.decode().expect("text"));
                }
            }
            // quick-xml gives `&amp;` and its kin as their own events.
            Event::GeneralRef(reference) => {
                let text = match &**reference {
                    b"amp" => "&",
                    b"lt" => "<",
                    b"gt" => ">",
                    b"quot" => "\"",
                    b"apos" => "'",
                    other => panic!("an unknown entity {:?}", String::from_utf8_lossy(other)),
                };
                if let Some(&at) = open.last() {
                    elements[at].text.push_str(text);
                }
            }
            Event::End(_) => {
                path.pop();
                open.pop();
            }
            Event::Eof => break,
            _ => {}
        }
    }
    assert!(path.is_empty(), "every element is closed");
    elements
}

fn one<'a>(elements: &'a [Element], path: &str) -> &'a Element {
    let found: Vec<&Element> = elements.iter().filter(|e| e.path == path).collect();
    assert_eq!(found.len(), 1, "exactly one {path}");
    found[0]
}

#[test]
fn a_package_is_a_zip_whose_manifest_lists_exactly_its_files() {
    let dir = scratch("package");
    let app = release(&dir);
    let app = app.to_str().expect("UTF-8");
    for (version, schema_version, scorm_type, namespace) in [
        (
            "1.2",
            "1.2",
            "adlcp:scormtype",
            "http://www.imsproject.org/xsd/imscp_rootv1p1p2",
        ),
        (
            "2004",
            "2004 4th Edition",
            "adlcp:scormType",
            "http://www.imsglobal.org/xsd/imscp_v1p1",
        ),
    ] {
        let zip = dir.join(format!("week3-{version}.zip"));
        let output = run_in(
            &dir,
            &[
                "package",
                zip.to_str().expect("UTF-8"),
                "--scorm",
                version,
                "--exercise",
                "split-edge-half-edge",
                "--exercise",
                "walk-face-loop-half-edge",
                "--exercise",
                "predict-vertex-edges-half-edge",
                "--link",
                "https://edgewise.example/?sample=cube",
                "--title",
                "Week 3 & half-edges",
                "--pass-mark",
                "70",
                "--app",
                app,
            ],
            None,
        );
        assert_eq!(code(&output), 0, "{}", stderr(&output));
        assert!(
            stderr(&output).contains("3 exercises and 1 view"),
            "{}",
            stderr(&output)
        );

        let files = entries(&zip);
        let names: BTreeSet<&str> = files.iter().map(|(name, _)| name.as_str()).collect();
        assert_eq!(names.len(), files.len(), "no name twice");
        let text = |name: &str| {
            let bytes = &files.iter().find(|(n, _)| n == name).expect(name).1;
            String::from_utf8(bytes.clone()).expect("UTF-8")
        };
        let elements = parse_manifest(&text("imsmanifest.xml"));
        let manifest = one(&elements, "manifest");
        assert_eq!(manifest.attribute("xmlns"), Some(namespace));
        assert!(
            manifest
                .attribute("identifier")
                .is_some_and(|id| id.starts_with("edgewise-"))
        );
        assert_eq!(one(&elements, "manifest/metadata/schema").text, "ADL SCORM");
        assert_eq!(
            one(&elements, "manifest/metadata/schemaversion").text,
            schema_version
        );
        let organizations = one(&elements, "manifest/organizations");
        let organization = one(&elements, "manifest/organizations/organization");
        assert_eq!(
            organizations.attribute("default"),
            organization.attribute("identifier")
        );
        assert_eq!(
            one(&elements, "manifest/organizations/organization/title").text,
            "Week 3 & half-edges"
        );
        let item = one(&elements, "manifest/organizations/organization/item");
        let resource = one(&elements, "manifest/resources/resource");
        assert_eq!(
            item.attribute("identifierref"),
            resource.attribute("identifier")
        );
        assert_eq!(resource.attribute(scorm_type), Some("sco"));
        assert_eq!(resource.attribute("type"), Some("webcontent"));
        assert_eq!(resource.attribute("href"), Some("launch.html"));
        if version == "1.2" {
            assert_eq!(
                one(
                    &elements,
                    "manifest/organizations/organization/item/adlcp:masteryscore"
                )
                .text,
                "70"
            );
        } else {
            let measure = "manifest/organizations/organization/item/imsss:sequencing/imsss:objectives/imsss:primaryObjective/imsss:minNormalizedMeasure";
            assert_eq!(one(&elements, measure).text, "0.7");
        }
        let listed: BTreeSet<&str> = elements
            .iter()
            .filter(|e| e.path == "manifest/resources/resource/file")
            .map(|e| e.attribute("href").expect("href"))
            .collect();
        let zipped: BTreeSet<&str> = names
            .iter()
            .copied()
            .filter(|&n| n != "imsmanifest.xml")
            .collect();
        assert_eq!(
            listed, zipped,
            "every file listed is zipped, and every file zipped listed"
        );
        for needed in [
            "launch.html",
            "edgewise-scorm.js",
            "index.html",
            "edgewise_app.c0ffee12.js",
            "edgewise_app_bg.c0ffee12.wasm",
            "exercises/split-edge-half-edge.toml",
            "exercises/walk-face-loop-half-edge.toml",
            "exercises/predict-vertex-edges-half-edge.toml",
        ] {
            assert!(names.contains(needed), "{needed}");
        }
        let launch = text("launch.html");
        assert!(
            launch.contains(&format!("\"scorm\":\"{version}\"")),
            "{launch}"
        );
        assert!(launch.contains("\"passMark\":70"));
        assert!(
            !launch.contains("http://") && !launch.contains("https://"),
            "nothing fetched from elsewhere"
        );
        assert_eq!(
            text("exercises/split-edge-half-edge.toml"),
            include_str!("../../../../algorithms/exercises/split-edge-half-edge.toml")
        );
    }
}

/// An exercise file is packed under its stem.
#[test]
fn an_exercise_file_is_packed_under_its_stem() {
    let dir = scratch("package-file");
    let app = release(&dir);
    std::fs::write(
        dir.join("my kev.toml"),
        include_str!("../../../../algorithms/exercises/kev-half-edge.toml"),
    )
    .expect("write");
    let output = run_in(
        &dir,
        &[
            "package",
            "mine.zip",
            "--scorm",
            "2004",
            "--exercise",
            "my kev.toml",
            "--app",
            app.to_str().expect("UTF-8"),
        ],
        None,
    );
    assert_eq!(code(&output), 0, "{}", stderr(&output));
    let files = entries(&dir.join("mine.zip"));
    assert!(
        files
            .iter()
            .any(|(name, _)| name == "exercises/my-kev.toml")
    );
}

#[test]
fn bad_input_exits_2_with_a_message_and_writes_nothing() {
    let dir = scratch("package-bad");
    let app = release(&dir);
    let app = app.to_str().expect("UTF-8");
    let cases: &[(&[&str], &str)] = &[
        (
            &["--exercise", "no-such-exercise"],
            "no exercise is named `no-such-exercise`",
        ),
        (
            &["--exercise", "kev-half-edge", "--exercise", "kev-half-edge"],
            "`kev-half-edge` is given twice",
        ),
        (
            &["--exercise", "kev-half-edge", "--pass-mark", "101"],
            "--pass-mark 101",
        ),
        (
            &["--exercise", "kev-half-edge", "--pass-mark", "-5"],
            "from 0 to 100",
        ),
        (&[], "at least one --exercise or --link"),
        (
            &["--link", "https://e.example/?mesh=meshes/torus.obj"],
            "--link 1: its mesh",
        ),
        (
            &["--exercise", "kev-half-edge", "--scorm", "2005"],
            "--scorm 2005",
        ),
        (
            &["--exercise", "kev-half-edge", "--app", "nowhere"],
            "index.html",
        ),
    ];
    for (args, says) in cases {
        let mut line = vec!["package", "out.zip"];
        for (option, default) in [("--scorm", "1.2"), ("--app", app)] {
            if !args.contains(&option) {
                line.extend([option, default]);
            }
        }
        line.extend_from_slice(args);
        let output = run_in(&dir, &line, None);
        assert_eq!(code(&output), 2, "{args:?}: {}", stderr(&output));
        assert!(
            stderr(&output).contains(says),
            "{args:?}: {}",
            stderr(&output)
        );
        assert!(!dir.join("out.zip").exists(), "{args:?}: nothing written");
    }
}
