use std::path::PathBuf;

use base64::Engine as _;
use proptest::prelude::*;

use super::*;

#[path = "../../../core/tests/it/golden/mod.rs"]
mod golden;

const BASE: &str = "https://example.org/edgewise/index.html";

fn parse_url(url: &str) -> (CourseLink, Vec<String>) {
    CourseLink::parse_url(url)
}

fn full_link() -> CourseLink {
    CourseLink {
        mesh: Some(MeshSource::Sample("tetrahedron".into())),
        structure: Some(Structure::WingedEdge),
        algorithm: Some("vertexAdjacentEdge".into()),
        algorithm_source: None,
        questions: None,
        args: vec![
            ("v".into(), Argument::Number(1.0)),
            ("closed".into(), Argument::Boolean(true)),
        ],
        step: Some(3),
        selection: Some(ElementRef {
            kind: ElementKind::Edge,
            id: 3,
        }),
        camera: Some(Camera {
            target: [0.0, -0.25, 1.5],
            yaw: 0.55,
            pitch: 0.4,
            distance: 5.0,
        }),
        ids: Some(DrawIds::Always),
        axes: Some(true),
        orientation: Some(false),
        solid: Some(true),
        mesh_scale: Some(1.5),
        label_scale: Some(2.0),
        theme: Some(ThemeChoice::Dark),
        embed: true,
        tables: Some(false),
        panels: Some(Panels {
            algorithm: true,
            tables: true,
            menu: false,
        }),
        present: true,
        colors: BTreeMap::from([
            ("lookup".to_owned(), [0x22, 0xaa, 0x44]),
            ("marked".to_owned(), [0x1d, 0x5b, 0xd8]),
        ]),
        code_size: Some(18.0),
        exercise: Some(ExerciseLink::Name("flip-edge-half-edge".into())),
        seed: Some(9),
    }
}

#[test]
fn a_full_link_is_written_in_a_stable_readable_order() {
    assert_eq!(
        full_link().to_url(BASE),
        "https://example.org/edgewise/index.html?sample=tetrahedron&structure=winged\
         &algorithm=vertexAdjacentEdge&args=v:1,closed:true&step=3&select=edge:3\
         &camera=0.55,0.4,5,0,-0.25,1.5&ids=always&axes=1&orientation=0&solid=1\
         &meshScale=1.5&labelScale=2&theme=dark&embed=1&tables=0&panels=algorithm,tables\
         &present=1&colors=lookup:22aa44,marked:1d5bd8&codeSize=18&exercise=flip-edge-half-edge&seed=9"
    );
    let (link, messages) = parse_url(&full_link().to_url(BASE));
    assert_eq!(messages, Vec::<String>::new());
    assert_eq!(link, full_link());
}

#[test]
fn an_empty_link_is_the_bare_page() {
    assert_eq!(CourseLink::default().to_url(BASE), BASE);
    assert_eq!(
        CourseLink::default().to_url("https://a.org/?embed=1#mesh=x"),
        "https://a.org/"
    );
    assert_eq!(CourseLink::parse("", ""), (CourseLink::default(), vec![]));
    assert_eq!(CourseLink::parse("?", "#"), (CourseLink::default(), vec![]));
}

#[test]
fn inline_mesh_and_algorithm_travel_in_the_fragment() {
    let link = CourseLink {
        mesh: Some(MeshSource::Inline {
            text: "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n".into(),
            format: "obj".into(),
        }),
        algorithm: Some("mine".into()),
        algorithm_source: Some("// my algorithm\n".into()),
        ..CourseLink::default()
    };
    let url = link.to_url(BASE);
    let (search, fragment) = split_url(&url);
    assert_eq!(search, "algorithm=mine");
    assert!(fragment.starts_with("mesh="), "{fragment}");
    assert!(fragment.contains("&format=obj&alg="), "{fragment}");
    assert!(
        fragment
            .bytes()
            .all(|b| b.is_ascii_alphanumeric() || b"-_=&".contains(&b)),
        "{fragment}"
    );
    assert_eq!(parse_url(&url), (link, vec![]));
}

#[test]
fn a_payload_made_in_a_page_with_padding_is_read() {
    // btoa() pads; CompressionStream('deflate-raw') makes what compress_to_vec makes.
    let compressed = miniz_oxide::deflate::compress_to_vec(b"v 0 0 0\n", 6);
    let padded = base64::engine::general_purpose::URL_SAFE.encode(&compressed);
    assert!(padded.ends_with('='));
    let (link, messages) = CourseLink::parse("", &format!("#mesh={padded}"));
    assert_eq!(messages, Vec::<String>::new());
    assert_eq!(
        link.mesh,
        Some(MeshSource::Inline {
            text: "v 0 0 0\n".into(),
            format: "obj".into()
        })
    );
}

#[test]
fn an_oversized_payload_is_refused_before_decoding() {
    let payload = "A".repeat(MAX_PAYLOAD_CHARS + 1);
    let (link, messages) = CourseLink::parse("sample=cube", &format!("mesh={payload}"));
    assert_eq!(
        messages,
        [
            "#mesh: the payload is 1.0 MiB, more than the 1 MiB a link may carry; put the \
             file beside the page and link it with mesh=path instead"
        ]
    );
    assert_eq!(link.mesh, Some(MeshSource::Sample("cube".into())));
}

#[test]
fn decompression_stops_at_the_limit() {
    // 9 MiB of one letter compresses to a few kilobytes: a small zip bomb.
    let bomb = encode_payload(&"v".repeat(9 << 20));
    assert!(bomb.len() < 100_000, "{}", bomb.len());
    let (link, messages) = CourseLink::parse("", &format!("alg={bomb}"));
    assert_eq!(
        messages,
        [
            "#alg: the text is more than 8 MiB once uncompressed, the most a link may carry; \
             put the algorithms in a smaller file"
        ]
    );
    assert_eq!(link.algorithm_source, None);
}

#[test]
fn to_url_checked_refuses_what_parse_would() {
    let link = CourseLink {
        mesh: Some(MeshSource::Inline {
            text: "#".repeat(MAX_INFLATED_BYTES + 1),
            format: "obj".into(),
        }),
        ..CourseLink::default()
    };
    assert_eq!(
        link.to_url_checked(BASE),
        Err(
            "#mesh: the text is 8.0 MiB, more than the 8 MiB a link may carry; put the file \
             beside the page and link it with mesh=path instead"
                .into()
        )
    );
    assert!(full_link().to_url_checked(BASE).is_ok());
}

#[test]
fn text_that_is_not_utf8_is_refused() {
    let payload = BASE64URL.encode(miniz_oxide::deflate::compress_to_vec(&[0xff, 0xfe], 6));
    let (_, messages) = CourseLink::parse("", &format!("mesh={payload}"));
    assert_eq!(messages, ["#mesh: the uncompressed text is not UTF-8"]);
}

#[test]
fn values_are_percent_encoded_and_decoded() {
    let link = CourseLink {
        mesh: Some(MeshSource::Path("my meshes/a&b+c=d%.obj".into())),
        ..CourseLink::default()
    };
    let url = link.to_url(BASE);
    assert!(
        url.ends_with("?mesh=my%20meshes/a%26b%2Bc%3Dd%25.obj"),
        "{url}"
    );
    assert_eq!(parse_url(&url), (link, vec![]));
    // Browsers and forms write spaces as +.
    let (link, _) = CourseLink::parse("mesh=my+meshes/a.obj", "");
    assert_eq!(link.mesh, Some(MeshSource::Path("my meshes/a.obj".into())));
    // A broken escape is kept as written, as URLSearchParams does.
    assert_eq!(decode("a%2"), "a%2");
    assert_eq!(decode("%zz%41"), "%zzA");
}

#[test]
fn bare_switches_are_on() {
    let (link, messages) = CourseLink::parse("embed&present&axes", "");
    assert!(messages.is_empty(), "{messages:?}");
    assert!(link.embed && link.present);
    assert_eq!(link.axes, Some(true));
}

#[test]
fn the_inline_mesh_beats_a_path_which_beats_a_sample() {
    let payload = encode_payload("v 0 0 0\n");
    let (link, messages) = CourseLink::parse(
        "sample=cube&mesh=meshes/torus.obj",
        &format!("mesh={payload}&format=ply"),
    );
    assert_eq!(
        link.mesh,
        Some(MeshSource::Inline {
            text: "v 0 0 0\n".into(),
            format: "ply".into()
        })
    );
    assert_eq!(
        messages,
        [
            "sample= and mesh= both give a mesh; mesh= is used",
            "mesh= and #mesh= both give a mesh; #mesh= is used"
        ]
    );
}

#[test]
fn view_options_round_trip_through_a_link() {
    let mut link = CourseLink::default();
    link.set_view_options(&ViewOptions::default());
    assert_eq!(link, CourseLink::default(), "defaults stay out of the link");

    let options = ViewOptions {
        draw_ids: DrawIds::Never,
        label_scale: 2.5,
        show_orientation: true,
        ..ViewOptions::default()
    };
    link.set_view_options(&options);
    assert_eq!(
        link.to_url(BASE),
        format!("{BASE}?ids=never&orientation=1&labelScale=2.5")
    );
    let mut applied = ViewOptions::default();
    parse_url(&link.to_url(BASE))
        .0
        .apply_view_options(&mut applied);
    assert_eq!(applied, options);
}

#[test]
fn the_embed_snippet_is_a_lazy_titled_iframe() {
    assert_eq!(
        embed_snippet(
            "https://example.org/?embed=1&sample=cube\"",
            (640, 420),
            "Edgewise: \"cube\""
        ),
        "<iframe src=\"https://example.org/?embed=1&amp;sample=cube&quot;\" width=\"640\" \
         height=\"420\" title=\"Edgewise: &quot;cube&quot;\" allow=\"fullscreen\" \
         allowfullscreen loading=\"lazy\" style=\"border: 1px solid #c8c6bf; border-radius: \
         6px; max-width: 100%;\"></iframe>"
    );
}

fn golden_path() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../tests/golden/course-link-messages.txt")
}

/// Every message, for the links in tests/golden/course-link-messages.txt.
/// `EDGEWISE_BLESS=1` rewrites the messages after the links.
#[test]
fn messages_match_the_golden_file() {
    let path = golden_path();
    let expected = std::fs::read_to_string(&path).expect("the golden file");
    let mut actual = String::new();
    for line in expected.lines() {
        if line.starts_with("    ") {
            continue;
        }
        actual.push_str(line);
        actual.push('\n');
        if line.is_empty() || line.starts_with("//") {
            continue;
        }
        let (search, fragment) = match line.find('#') {
            Some(at) => line.split_at(at),
            None => (line, ""),
        };
        let (_, messages) = CourseLink::parse(search, fragment);
        if messages.is_empty() {
            actual.push_str("    (no messages)\n");
        }
        for message in messages {
            actual.push_str(&format!("    {message}\n"));
        }
    }
    golden::assert_matches(&path, actual);
}

/// A float that survives printing with four decimals exactly.
fn short_float(range: std::ops::Range<i32>) -> impl Strategy<Value = f32> {
    range.prop_map(|k| k as f32 / 1000.0)
}

fn name() -> impl Strategy<Value = String> {
    "[a-zA-Z_][a-zA-Z0-9_]{0,12}"
}

fn arb_mesh() -> impl Strategy<Value = Option<MeshSource>> {
    let samples: Vec<String> = crate::samples::SAMPLES
        .iter()
        .map(|s| s.name.to_owned())
        .collect();
    prop_oneof![
        Just(None),
        proptest::sample::select(samples).prop_map(|s| Some(MeshSource::Sample(s))),
        (
            "[a-zA-Z0-9 _&=+%-]{1,8}(/[a-zA-Z0-9 _&=+%-]{1,8}){0,2}",
            0..4usize
        )
            .prop_map(|(stem, ext)| format!("{stem}.{}", INLINE_FORMATS[ext]))
            .prop_filter("a path links may use", |path| check_mesh_path(path).is_ok())
            .prop_map(|path| Some(MeshSource::Path(path))),
        (any::<String>(), 0..4usize).prop_map(|(text, f)| Some(MeshSource::Inline {
            text,
            format: INLINE_FORMATS[f].to_owned()
        })),
        arb_polygons().prop_map(|polygons| Some(MeshSource::Polygons(polygons))),
    ]
}

/// Polygons of any (non-NaN) positions and faces of 3 to 6 corners.
fn arb_polygons() -> impl Strategy<Value = Polygons> {
    let position = proptest::array::uniform3(any::<f32>().prop_filter("not NaN", |x| !x.is_nan()));
    (
        proptest::collection::vec(position, 3..12),
        proptest::collection::vec(proptest::collection::vec(any::<u32>(), 3..7), 0..6),
    )
        .prop_map(|(positions, faces)| {
            let count = positions.len() as u32;
            let mut polygons = Polygons::new();
            for p in positions {
                polygons.push_vertex(glam::Vec3::from_array(p));
            }
            for face in faces {
                let face: Vec<u32> = face.iter().map(|v| v % count).collect();
                polygons.push_face(&face);
            }
            polygons
        })
}

fn arb_argument() -> impl Strategy<Value = Argument> {
    prop_oneof![
        any::<bool>().prop_map(Argument::Boolean),
        any::<f64>()
            .prop_filter("finite", |x| x.is_finite())
            .prop_map(Argument::Number),
        (0..1000u32).prop_map(|n| Argument::Number(f64::from(n))),
    ]
}

fn arb_link() -> impl Strategy<Value = CourseLink> {
    let camera = (
        short_float(-7000..7000),
        short_float(-1500..1500),
        short_float(1..1_000_000),
        [
            short_float(-100_000..100_000),
            short_float(-100_000..100_000),
            short_float(-100_000..100_000),
        ],
    )
        .prop_map(|(yaw, pitch, distance, target)| Camera {
            target,
            yaw,
            pitch,
            distance,
        });
    let kind = proptest::sample::select(vec![
        ElementKind::Vertex,
        ElementKind::Edge,
        ElementKind::Face,
    ]);
    // A question set that reads: `line N: prompt` or `step N: prompt`.
    let questions = proptest::collection::vec(
        (any::<bool>(), 1..100_000u32, "[A-Za-z?][A-Za-z ?]{0,40}"),
        1..4,
    )
    .prop_map(|lines| {
        lines
            .into_iter()
            .map(|(step, n, prompt)| {
                format!("{} {n}: {prompt}\n", if step { "step" } else { "line" })
            })
            .collect::<String>()
    });
    let algorithm = proptest::option::of((
        name(),
        proptest::option::of(any::<String>()),
        proptest::collection::btree_map(name(), arb_argument(), 0..4),
        proptest::option::of(any::<usize>()),
        proptest::option::of(questions),
    ));
    let colors = proptest::collection::btree_map(
        proptest::sample::select(color_keys()),
        any::<[u8; 3]>(),
        0..4,
    );
    let view = (
        proptest::option::of(proptest::sample::select(vec![
            DrawIds::Always,
            DrawIds::Highlighted,
            DrawIds::Never,
        ])),
        proptest::option::of(any::<bool>()),
        proptest::option::of(any::<bool>()),
        proptest::option::of(any::<bool>()),
        proptest::option::of(25..=400u32).prop_map(|x| x.map(|x| x as f32 / 100.0)),
        proptest::option::of(50..=300u32).prop_map(|x| x.map(|x| x as f32 / 100.0)),
    );
    let page = (
        proptest::option::of(any::<bool>()),
        any::<bool>(),
        proptest::option::of(any::<bool>()),
        proptest::option::of(any::<[bool; 3]>()),
        any::<bool>(),
        colors,
        proptest::option::of(8..=40u32).prop_map(|x| x.map(|x| x as f32)),
    );
    (
        arb_mesh(),
        proptest::option::of(any::<bool>()),
        algorithm,
        proptest::option::of((kind, any::<u32>())),
        proptest::option::of(camera),
        view,
        page,
    )
        .prop_map(|(mesh, half, algorithm, selection, camera, view, page)| {
            let (ids, axes, orientation, solid, mesh_scale, label_scale) = view;
            let (dark, embed, tables, panels, present, colors, code_size) = page;
            let (algorithm, algorithm_source, args, step, questions) = match algorithm {
                Some((name, source, args, step, questions)) => (
                    Some(name),
                    source,
                    args.into_iter().collect(),
                    step,
                    questions,
                ),
                None => (None, None, Vec::new(), None, None),
            };
            CourseLink {
                mesh,
                structure: half.map(|half| {
                    if half {
                        Structure::HalfEdge
                    } else {
                        Structure::WingedEdge
                    }
                }),
                algorithm,
                algorithm_source,
                questions,
                args,
                step,
                selection: selection.map(|(kind, id)| ElementRef { kind, id }),
                camera,
                ids,
                axes,
                orientation,
                solid,
                mesh_scale,
                label_scale,
                theme: dark.map(|dark| {
                    if dark {
                        ThemeChoice::Dark
                    } else {
                        ThemeChoice::Light
                    }
                }),
                embed,
                tables,
                panels: panels.map(|[algorithm, tables, menu]| Panels {
                    algorithm,
                    tables,
                    menu,
                }),
                present,
                colors,
                code_size,
                exercise: None,
                seed: None,
            }
        })
}

proptest! {
    #[test]
    fn every_link_survives_a_round_trip(link in arb_link()) {
        let url = link.to_url(BASE);
        let (parsed, messages) = parse_url(&url);
        prop_assert_eq!(messages, Vec::<String>::new(), "{}", url);
        prop_assert_eq!(parsed, link);
    }

    #[test]
    fn any_text_parses_to_a_link_that_writes_back_stably(
        search in "([a-zA-Z]{1,10}(=[-a-z0-9:,.%+/&=]{0,12})?&){0,4}",
        fragment in any::<String>(),
    ) {
        let (link, _) = CourseLink::parse(&search, &fragment);
        let url = link.to_url(BASE);
        let (again, messages) = parse_url(&url);
        prop_assert_eq!(messages, Vec::<String>::new(), "{}", url);
        prop_assert_eq!(again.to_url(BASE), url);
    }

    #[test]
    fn query_parameters_with_any_value_give_a_link_or_a_message(
        key in proptest::sample::select(QUERY_KEYS),
        value in any::<String>(),
    ) {
        let query = format!("algorithm=a&{key}={}", encode(&value));
        let (link, _) = CourseLink::parse(&query, "");
        let url = link.to_url(BASE);
        let (again, messages) = parse_url(&url);
        prop_assert_eq!(messages, Vec::<String>::new(), "{}", url);
        prop_assert_eq!(again.to_url(BASE), url);
    }
}

/// Every way a `mesh=` value could reach another site once a browser's URL
/// parser has read it: each is refused with a message, and only plain
/// relative paths open.
#[test]
fn mesh_paths_never_reach_another_site() {
    let refused = [
        " //evil.example/x.obj",
        "  //evil.example/x.obj",
        "//evil.example/x.obj ",
        "\t//evil.example/x.obj",
        "/\t/evil.example/x.obj",
        "\n//evil.example/x.obj",
        "\\\\evil.example/x.obj",
        "/\\evil.example/x.obj",
        "\\/evil.example/x.obj",
        "https://evil.example/x.obj",
        "HtTpS://evil.example/x.obj",
        " https://evil.example/x.obj",
        "javascript:alert(1)//x.obj",
        "data:text/plain,v.obj",
        "https://user:pass@evil.example/x.obj",
        "//user@evil.example/x.obj",
        "/meshes/x.obj",
        "meshes/../../x.obj",
        "meshes/%2e%2e/x.obj",
        "meshes/x.obj\u{0}",
    ];
    for path in refused {
        assert!(check_mesh_path(path).is_err(), "{path:?} was accepted");
        // As a link: decoded once, then checked.
        let encoded: String = path.bytes().map(|b| format!("%{b:02X}")).collect();
        let (link, messages) = CourseLink::parse(&format!("mesh={encoded}"), "");
        assert_eq!(link.mesh, None, "{path:?}");
        assert!(
            messages.iter().any(|m| m.starts_with("mesh=")),
            "{path:?}: {messages:?}"
        );
    }
    // Escapes decode once: what is left is a file name on this site.
    for (query, path) in [
        ("mesh=%2F%2Fevil.example%2Fx.obj", None),
        ("mesh=%5C%5Cevil.example%2Fx.obj", None),
        ("mesh=meshes%2Ftorus.obj", Some("meshes/torus.obj")),
        ("mesh=a%252F%252Fb.obj", Some("a%2F%2Fb.obj")),
        ("mesh=user%40host.obj", Some("user@host.obj")),
        ("mesh=my+meshes/a.obj", Some("my meshes/a.obj")),
    ] {
        let (link, _) = CourseLink::parse(query, "");
        assert_eq!(
            link.mesh,
            path.map(|p| MeshSource::Path(p.to_owned())),
            "{query}"
        );
    }
}

/// `origins=` is the embed bridge's: the link only names a malformed one.
#[test]
fn origins_are_checked_and_left_to_the_embed_bridge() {
    for good in [
        "https://notes.example.edu",
        "https://notes.example.edu,http://127.0.0.1:8080",
        "http://[::1]:9000",
    ] {
        let (link, messages) = CourseLink::parse(&format!("embed&origins={good}"), "");
        assert!(messages.is_empty(), "{good}: {messages:?}");
        assert!(link.embed);
    }
    for bad in [
        "",
        "notes.example.edu",
        "https://a.edu/path",
        "javascript:x",
        "https://",
        "*",
    ] {
        let (_, messages) = CourseLink::parse(&format!("embed&origins={bad}"), "");
        assert_eq!(messages.len(), 1, "{bad}: {messages:?}");
        assert!(
            messages[0].contains("expected a comma-separated list of origins"),
            "{messages:?}"
        );
    }
}
