//! What a package holds and what it refuses. The zip itself is read back by
//! an independent reader in the CLI's tests (crates/cli/tests/it/package.rs).

use super::{AppFiles, Item, Package, PackageError, Scorm};
use crate::practice::catalog;

fn app() -> AppFiles {
    AppFiles::read(|name| match name {
        "index.html" => Ok(b"<script>const BUILD = '0123abcd';</script>".to_vec()),
        "favicon.svg" | "edgewise_app.0123abcd.js" | "edgewise_app_bg.0123abcd.wasm" => {
            Ok(name.as_bytes().to_vec())
        }
        _ => Err("not found".to_owned()),
    })
    .expect("a release")
}

fn exercise(name: &str) -> Item {
    Item::Exercise(Box::new(
        catalog::find(name).expect("shipped").expect("reads"),
    ))
}

fn package(scorm: Scorm) -> Package {
    Package::new(
        scorm,
        "Week 3: <half-edges> & \"walks\"",
        "70",
        vec![
            exercise("split-edge-half-edge"),
            exercise("walk-face-loop-half-edge"),
            Item::view(
                1,
                "https://edgewise.example/?sample=cube&algorithm=vertexValence",
            )
            .expect("a view"),
        ],
    )
    .expect("a package")
}

#[test]
fn a_package_holds_the_app_the_exercises_and_a_stamped_launch_page() {
    for scorm in [Scorm::V1_2, Scorm::V2004] {
        let files = package(scorm).files(&app());
        let names: Vec<&str> = files.iter().map(|(name, _)| name.as_str()).collect();
        assert_eq!(
            names,
            [
                "imsmanifest.xml",
                "launch.html",
                "edgewise-scorm.js",
                "index.html",
                "edgewise_app.0123abcd.js",
                "edgewise_app_bg.0123abcd.wasm",
                "favicon.svg",
                "exercises/split-edge-half-edge.toml",
                "exercises/walk-face-loop-half-edge.toml",
            ]
        );
        let manifest = String::from_utf8(files[0].1.clone()).expect("UTF-8");
        for name in &names[1..] {
            assert!(
                manifest.contains(&format!("<file href=\"{name}\"/>")),
                "{name}"
            );
        }
        assert!(manifest.contains(&format!(
            "<schemaversion>{}</schemaversion>",
            scorm.schema_version()
        )));
        assert!(manifest.contains("Week 3: &lt;half-edges&gt; &amp; &quot;walks&quot;"));
        let launch = String::from_utf8(files[1].1.clone()).expect("UTF-8");
        assert!(!launch.contains("__EDGEWISE_"), "every marker is stamped");
        assert!(launch.contains("<title>Week 3: &lt;half-edges&gt;"));
        assert!(!launch.contains("<half-edges>"), "no markup from the title");
        let config = package(scorm).config();
        assert_eq!(config["scorm"], scorm.name());
        assert_eq!(config["passMark"], 70);
        assert_eq!(config["items"][0]["doIt"], true);
        assert_eq!(config["items"][1]["doIt"], false);
        assert_eq!(config["items"][2]["kind"], "view");
        assert_eq!(config["items"][2]["title"], "vertexValence on the cube");
        let href = config["items"][2]["href"].as_str().expect("href");
        assert!(
            href.starts_with("index.html?") && href.contains("embed=1"),
            "{href}"
        );
    }
}

#[test]
fn the_same_package_has_the_same_identifier_and_bytes() {
    let zip = |scorm| package(scorm).zip(&app()).expect("zips");
    assert_eq!(zip(Scorm::V1_2), zip(Scorm::V1_2));
    let manifest = |scorm| String::from_utf8(package(scorm).files(&app())[0].1.clone());
    let identifier = |text: String| {
        let start = text.find("identifier=\"edgewise-").expect("identifier");
        text[start..start + 37].to_owned()
    };
    assert_eq!(
        identifier(manifest(Scorm::V1_2).expect("UTF-8")),
        identifier(manifest(Scorm::V2004).expect("UTF-8"))
    );
}

#[test]
fn bad_input_is_refused_with_what_to_change() {
    let new = |title: &str, mark: &str, items: Vec<Item>| {
        Package::new(Scorm::V1_2, title, mark, items)
            .expect_err("refused")
            .to_string()
    };
    let one = || vec![exercise("split-edge-half-edge")];
    for mark in ["101", "-1", "12.5", "", "eighty"] {
        assert!(new("T", mark, one()).contains("from 0 to 100"), "{mark}");
    }
    assert!(new("", "80", one()).contains("empty"));
    assert!(new(&"x".repeat(201), "80", one()).contains("200"));
    assert!(new("a\u{7}b", "80", one()).contains("control"));
    assert!(new("T", "80", Vec::new()).contains("at least one --exercise or --link"));
    let twice = vec![
        exercise("split-edge-half-edge"),
        exercise("split-edge-half-edge"),
    ];
    assert!(new("T", "80", twice).contains("`split-edge-half-edge` is given twice"));

    let link = |url: &str| Item::view(2, url).expect_err(url).to_string();
    assert!(link("https://e.example/?mesh=meshes/torus.obj").contains("--link 2: its mesh"));
    assert!(link("https://e.example/?exercise=kev-half-edge").contains("--exercise"));
    assert!(link("https://e.example/?nonsense=1").starts_with("--link 2: "));

    let missing = AppFiles::read(|name| match name {
        "index.html" => Ok(b"const BUILD = '__EDGEWISE_BUILD__';".to_vec()),
        _ => Err("not found".to_owned()),
    });
    assert!(matches!(missing, Err(PackageError::App { .. })));
    let missing = AppFiles::read(|name| match name {
        "index.html" => Ok(b"const BUILD = 'ab12';".to_vec()),
        _ => Err("not found".to_owned()),
    })
    .err()
    .map(|err| err.to_string())
    .expect("refused");
    assert!(
        missing.contains("edgewise_app.ab12.js: not found"),
        "{missing}"
    );
    assert!(missing.contains("cargo xtask build-web"), "{missing}");
}
