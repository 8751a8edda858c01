//! The built `edgewise` binary: output, stderr messages and exit codes
//! (0 fine, 1 bad input, 2 usage) of every command.

use std::path::Path;
use std::process::Output;

use crate::common::{code, root, run, run_in, scratch, stderr, stdout};

#[test]
fn info_prints_counts_topology_and_warnings() {
    let output = run(&["info", "meshes/torus.obj"]);
    assert_eq!(code(&output), 0, "{}", stderr(&output));
    assert_eq!(
        stdout(&output),
        "file:                 meshes/torus.obj\n\
         format:               OBJ (.obj)\n\
         structure:            winged-edge\n\
         vertices:             288\n\
         edges:                576\n\
         faces:                288\n\
         half-edges:           1152\n\
         boundary loops:       0\n\
         components:           1\n\
         Euler characteristic: 0\n\
         genus:                1\n\
         warnings:             none\n"
    );
}

#[test]
fn info_names_a_converted_table_file_and_boundaries() {
    let output = run(&["info", "meshes/annulus.htb", "--structure", "winged"]);
    assert_eq!(code(&output), 0);
    let text = stdout(&output);
    assert!(
        text.contains(
            "structure:            winged-edge (converted from the file's half-edge tables)\n"
        ),
        "{text}"
    );
    assert!(text.contains("boundary loops:       2\n"), "{text}");
    assert!(
        text.contains("genus:                - (the surface has a boundary)\n"),
        "{text}"
    );
}

#[test]
fn info_lists_warnings_with_their_lines() {
    let obj = b"v 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 5 5\nf 1 2 3\n";
    let output = run_in(&root(), &["info", "-"], Some(obj));
    assert_eq!(code(&output), 0, "{}", stderr(&output));
    let text = stdout(&output);
    assert!(
        text.contains("format:               OBJ (.obj)\n"),
        "{text}"
    );
    assert!(
        text.contains("warnings:             1\n  <stdin>:4: vertex 3 is not used by any face; it is kept as an isolated vertex\n"),
        "{text}"
    );
    assert!(text.contains("components:           2\n"), "{text}");
}

/// Two holes touching at vertex 139: the vertex is split, with a warning,
/// and the mesh loads.
const TOUCHING_HOLES: &str = "tests/external/trimesh-icosphere-touching-holes.ply";

#[test]
fn info_reports_a_split_vertex() {
    let output = run(&["info", TOUCHING_HOLES]);
    assert_eq!(code(&output), 0, "{}", stderr(&output));
    let text = stdout(&output);
    assert!(text.contains("vertices:             163\n"), "{text}");
    assert!(text.contains("boundary loops:       1\n"), "{text}");
    assert!(
        text.contains(&format!(
            "warnings:             1\n  {TOUCHING_HOLES}: vertex 139 joined 2 fans of faces; \
             split into 139 and 162\n"
        )),
        "{text}"
    );
}

#[test]
fn check_accepts_a_split_vertex_with_a_warning() {
    for structure in ["winged", "half"] {
        let output = run(&["check", TOUCHING_HOLES, "--structure", structure]);
        assert_eq!(code(&output), 0, "{}", stderr(&output));
        assert_eq!(
            stderr(&output),
            format!(
                "{TOUCHING_HOLES}: warning: vertex 139 joined 2 fans of faces; split into 139 and 162\n"
            )
        );
        assert!(
            stdout(&output).starts_with(&format!(
                "{TOUCHING_HOLES}: ok (163 vertices, 478 edges, 316 faces; "
            )),
            "{}",
            stdout(&output)
        );
    }
}

#[test]
fn standard_input_is_recognised_by_content() {
    let wtb = std::fs::read(root().join("meshes/open-square.wtb")).expect("sample");
    let output = run_in(&root(), &["check", "-"], Some(&wtb));
    assert_eq!(code(&output), 0, "{}", stderr(&output));
    assert_eq!(
        stdout(&output),
        "<stdin>: ok (4 vertices, 5 edges, 2 faces; winged-edge)\n"
    );
}

#[test]
fn check_accepts_every_sample() {
    for entry in std::fs::read_dir(root().join("meshes")).expect("meshes/") {
        let name = entry
            .expect("entry")
            .file_name()
            .to_string_lossy()
            .into_owned();
        if name.ends_with(".md") {
            continue;
        }
        let output = run_in(&root().join("meshes"), &["check", &name], None);
        assert_eq!(code(&output), 0, "{name}: {}", stderr(&output));
        assert!(
            stdout(&output).starts_with(&format!("{name}: ok (")),
            "{}",
            stdout(&output)
        );
        assert_eq!(stderr(&output), "", "{name}");
    }
}

/// `edgewise check` prints exactly what the corpus expects, and exits 1.
#[test]
fn check_refuses_every_bad_input_with_its_expected_messages() {
    let dir = root().join("tests/bad-inputs");
    let mut checked = 0;
    for entry in std::fs::read_dir(&dir).expect("corpus") {
        let name = entry
            .expect("entry")
            .file_name()
            .to_string_lossy()
            .into_owned();
        if name.ends_with(".expected") || name == "README.md" {
            continue;
        }
        let stem = name.rsplit_once('.').map_or(name.as_str(), |(s, _)| s);
        let expected =
            std::fs::read_to_string(dir.join(format!("{stem}.expected"))).expect("expected");
        let output = run_in(&dir, &["check", &name], None);
        assert_eq!(code(&output), 1, "{name}");
        assert_eq!(stderr(&output), expected, "{name}");
        assert_eq!(stdout(&output), "", "{name}");
        checked += 1;
    }
    assert!(checked >= 40);
}

#[test]
fn a_missing_file_is_bad_input() {
    let output = run(&["check", "meshes/no-such-mesh.obj"]);
    assert_eq!(code(&output), 1);
    assert!(stderr(&output).starts_with("meshes/no-such-mesh.obj: cannot read the file: "));
}

#[test]
fn convert_goes_through_every_format_and_back() {
    let dir = scratch("convert");
    let source = root().join("meshes/dodecahedron.obj");
    let steps = [
        (source.clone(), dir.join("a.ply"), "binary"),
        (dir.join("a.ply"), dir.join("b.wtb"), "ascii"),
        (dir.join("b.wtb"), dir.join("c.htb"), "ascii"),
        (dir.join("c.htb"), dir.join("d.ply"), "binary-big-endian"),
        (dir.join("d.ply"), dir.join("e.obj"), "ascii"),
    ];
    for (input, output, ply) in &steps {
        let input = input.to_string_lossy();
        let out = output.to_string_lossy();
        let result = run(&["convert", &input, &out, "--ply", ply]);
        assert_eq!(code(&result), 0, "{input} -> {out}: {}", stderr(&result));
        assert!(
            stdout(&result).contains("20 vertices, 12 faces"),
            "{}",
            stdout(&result)
        );
    }
    let info = |path: &Path| {
        let text = stdout(&run(&["info", &path.to_string_lossy()]));
        text.lines().skip(3).collect::<Vec<_>>().join("\n")
    };
    assert_eq!(info(&dir.join("e.obj")), info(&source));
    assert_eq!(info(&dir.join("b.wtb")), info(&source));
}

#[test]
fn convert_to_an_unknown_format_is_a_usage_error() {
    let out = std::env::temp_dir().join("edgewise-cli-out.stl");
    let output = run(&["convert", "meshes/cube.htb", &out.to_string_lossy()]);
    assert_eq!(code(&output), 2);
    assert!(stderr(&output).contains("give it a .obj, .ply, .wtb or .htb extension"));
}

#[test]
fn tables_prints_the_three_tables() {
    let output = run_in(&root().join("meshes"), &["tables", "open-square.wtb"], None);
    assert_eq!(code(&output), 0);
    let expected =
        std::fs::read_to_string(root().join("tests/golden/formats/open-square.winged.tables.txt"))
            .expect("golden");
    assert_eq!(stdout(&output), expected);
    let output = run_in(
        &root().join("meshes"),
        &["tables", "open-square.wtb", "--structure", "half"],
        None,
    );
    let expected =
        std::fs::read_to_string(root().join("tests/golden/formats/open-square.half.tables.txt"))
            .expect("golden");
    assert_eq!(stdout(&output), expected);
}

/// `edgewise trace` of vertexAdjacentEdge on Table 2 from `v`, with `more`.
fn trace_table_2(v: &str, more: &[&str]) -> Output {
    let arg = format!("v={v}");
    let mut args = vec![
        "trace",
        "algorithms/winged-edge.alg",
        "vertexAdjacentEdge",
        "meshes/tetrahedron.wtb",
        "--arg",
        &arg,
    ];
    args.extend_from_slice(more);
    run(&args)
}

#[test]
fn trace_prints_each_step_and_the_marked_elements() {
    let output = trace_table_2("3", &[]);
    assert_eq!(code(&output), 0, "{}", stderr(&output));
    let text = stdout(&output);
    let lines: Vec<&str> = text.lines().collect();
    assert!(lines[0].starts_with("step 1  line "), "{text}");
    assert!(
        lines
            .iter()
            .any(|l| l.contains("  lookup e.startVertex -> vertex ")),
        "{text}"
    );
    // Vertex D of the paper's Table 2: its incident edge is e (4); the loop
    // visits e, a and c.
    assert_eq!(lines.last(), Some(&"marked: edge 4, edge 0, edge 2"));
}

#[test]
fn trace_prints_a_question_set_with_its_answers() {
    let output = trace_table_2(
        "1",
        &[
            "--questions",
            "algorithms/questions/vertex-adjacent-edge.txt",
        ],
    );
    assert_eq!(code(&output), 0, "{}", stderr(&output));
    let text = stdout(&output);
    let questions = text.split_once("questions:\n").map(|(_, q)| q);
    assert_eq!(
        questions.map(|q| q.lines().take(2).collect::<Vec<_>>()),
        Some(vec![
            "  at step 0 (before line 13): Which edge will e be after the lookup v.incidentEdge?",
            "    answer: edge 1. Step 1: lookup v.incidentEdge -> edge 1. Step 2: assign e := edge 1.",
        ]),
        "{text}"
    );
    assert_eq!(text.matches("    answer: ").count(), 6, "{text}");

    let dir = scratch("questions");
    let set = dir.join("set.txt");
    std::fs::write(&set, "line 13: fine\nstep twelve: oops\n").expect("written");
    let output = trace_table_2("1", &["--questions", set.to_str().expect("UTF-8 path")]);
    assert_eq!(code(&output), 1);
    assert!(
        stderr(&output)
            .ends_with("set.txt:2:6: `twelve` is not a line or step number (1 or more)\n"),
        "{}",
        stderr(&output)
    );
}

#[test]
fn trace_builds_the_structure_the_algorithm_declares() {
    let output = run(&[
        "trace",
        "algorithms/half-edge.alg",
        "vertexAdjacentEdge",
        "meshes/tetrahedron.wtb",
        "--arg",
        "v=0",
    ]);
    assert_eq!(code(&output), 0, "{}", stderr(&output));
    assert!(
        stdout(&output)
            .lines()
            .last()
            .is_some_and(|l| l.starts_with("marked: edge "))
    );
}

#[test]
fn trace_stops_at_the_step_limit_with_exit_1() {
    let output = run(&[
        "trace",
        "algorithms/winged-edge.alg",
        "vertexAdjacentEdge",
        "meshes/cube.htb",
        "--arg",
        "v=1",
        "--step-limit",
        "5",
    ]);
    assert_eq!(code(&output), 1);
    assert_eq!(
        stdout(&output).lines().count(),
        6,
        "five steps and the marked line"
    );
    assert!(
        stdout(&output).ends_with("marked: edge 2\n"),
        "{}",
        stdout(&output)
    );
    let err = stderr(&output);
    assert!(err.starts_with("algorithms/winged-edge.alg:"), "{err}");
    assert!(err.contains("step limit"), "{err}");
}

#[test]
fn trace_command_line_mistakes_are_usage_errors() {
    let base = ["trace", "algorithms/winged-edge.alg"];
    for (extra, message) in [
        (
            vec!["noSuchAlgorithm", "meshes/cube.htb"],
            "no algorithm is named `noSuchAlgorithm`",
        ),
        (
            vec!["vertexAdjacentEdge", "meshes/cube.htb", "--arg", "v=99"],
            "vertex 99 does not exist",
        ),
        (
            vec!["vertexAdjacentEdge", "meshes/cube.htb", "--arg", "w=1"],
            "has no parameter `w`",
        ),
        (
            vec!["vertexAdjacentEdge", "meshes/cube.htb"],
            "no value given for parameter `v`",
        ),
    ] {
        let args: Vec<&str> = base.iter().copied().chain(extra).collect();
        let output = run(&args);
        assert_eq!(code(&output), 2, "{args:?}");
        assert!(
            stderr(&output).contains(message),
            "{args:?}: {}",
            stderr(&output)
        );
    }
}

#[test]
fn trace_on_a_bad_mesh_or_algorithm_is_bad_input() {
    let output = run(&[
        "trace",
        "tests/algorithms/errors/03-misspelled-lookup.alg",
        "x",
        "meshes/cube.htb",
    ]);
    assert_eq!(code(&output), 1);
    assert!(
        stderr(&output).contains("error: unknown lookup"),
        "{}",
        stderr(&output)
    );
    let output = run(&[
        "trace",
        "algorithms/winged-edge.alg",
        "vertexAdjacentEdge",
        "tests/bad-inputs/wtb-bad-wing.wtb",
        "--arg",
        "v=0",
    ]);
    assert_eq!(code(&output), 1);
    assert!(stderr(&output).contains("wtb-bad-wing.wtb:24:71: edge 2 left_predecessor"));
}

#[test]
fn check_alg_reports_errors_with_exit_1() {
    let errors = root().join("tests/algorithms/errors");
    let output = run_in(&errors, &["check-alg", "03-misspelled-lookup.alg"], None);
    assert_eq!(code(&output), 1);
    let expected =
        std::fs::read_to_string(root().join("tests/algorithms/errors/03-misspelled-lookup.txt"))
            .expect("the language's golden message");
    assert_eq!(stderr(&output).trim_end(), expected.trim_end());
    let output = run(&["check-alg", "algorithms/half-edge.alg"]);
    assert_eq!(code(&output), 0, "{}", stderr(&output));
    assert!(stdout(&output).starts_with("algorithms/half-edge.alg: ok, "));
    assert!(stdout(&output).contains("  vertexAdjacentEdge(v : Vertex) : HalfEdge\n"));
}

#[test]
fn disasm_lists_one_or_every_algorithm() {
    let one = run(&["disasm", "algorithms/half-edge.alg", "vertexAdjacentEdge"]);
    assert_eq!(code(&one), 0);
    assert!(stdout(&one).starts_with("algorithm vertexAdjacentEdge(v : Vertex) : HalfEdge\n"));
    let all = run(&["disasm", "algorithms/half-edge.alg"]);
    assert_eq!(code(&all), 0);
    assert!(stdout(&all).len() > stdout(&one).len());
    assert_eq!(
        code(&run(&["disasm", "algorithms/half-edge.alg", "nope"])),
        2
    );
}

#[test]
fn usage_errors_exit_2() {
    assert_eq!(code(&run(&["no-such-command"])), 2);
    assert_eq!(code(&run(&["info"])), 2);
    assert_eq!(
        code(&run(&["info", "meshes/cube.htb", "--structure", "quad"])),
        2
    );
    let help = run(&["--help"]);
    assert_eq!(code(&help), 0);
    for command in [
        "info",
        "check",
        "convert",
        "edit",
        "tables",
        "trace",
        "render",
        "check-alg",
        "disasm",
    ] {
        assert!(stdout(&help).contains(command), "--help lists {command}");
    }
}

#[test]
fn edit_flips_an_octahedron_edge_and_writes_the_result() {
    let dir = scratch("edit-flip");
    let out = dir.join("flipped.obj");
    let output = run(&[
        "edit",
        "meshes/octahedron.obj",
        &out.to_string_lossy(),
        "flip-edge",
        "0",
    ]);
    assert_eq!(code(&output), 0, "{}", stderr(&output));
    assert_eq!(
        stdout(&output),
        format!(
            "meshes/octahedron.obj: flip-edge 0 (winged-edge)\n\
             before: V 6, E 12, F 8, V − E + F = 2\n\
             after:  V 6, E 12, F 8, V − E + F = 2\n\
             wrote {} (200 bytes)\n",
            out.display()
        )
    );
    let check = run(&["check", &out.to_string_lossy()]);
    assert_eq!(code(&check), 0, "{}", stderr(&check));
    // A flip keeps the counts but changes the faces.
    let original = std::fs::read_to_string(root().join("meshes/octahedron.obj")).expect("sample");
    let flipped = std::fs::read_to_string(&out).expect("written");
    let faces = |text: &str| text.lines().filter(|l| l.starts_with("f ")).count();
    assert_eq!(faces(&flipped), faces(&original));
}

#[test]
fn edit_compacts_the_ids_and_converts_when_asked() {
    let dir = scratch("edit-collapse");
    let out = dir.join("collapsed.htb");
    let output = run(&[
        "edit",
        "meshes/quad-grid.obj",
        &out.to_string_lossy(),
        "collapse-edge",
        "13",
        "--structure",
        "half-edge",
    ]);
    assert_eq!(code(&output), 0, "{}", stderr(&output));
    let text = stdout(&output);
    assert!(
        text.starts_with(
            "meshes/quad-grid.obj: collapse-edge 13 (half-edge)\n\
             before: V 25, E 40, F 16, V − E + F = 1\n\
             after:  V 24, E 39, F 16, V − E + F = 1\n"
        ),
        "{text}"
    );
    let check = run(&["check", &out.to_string_lossy()]);
    assert_eq!(
        stdout(&check),
        format!(
            "{}: ok (24 vertices, 39 edges, 16 faces; half-edge)\n",
            out.display()
        )
    );
}

#[test]
fn edit_refuses_a_flip_on_the_tetrahedron_with_exit_1() {
    let dir = scratch("edit-refused");
    let out = dir.join("never.wtb");
    let output = run(&[
        "edit",
        "meshes/tetrahedron.wtb",
        &out.to_string_lossy(),
        "flip-edge",
        "0",
    ]);
    assert_eq!(code(&output), 1);
    assert_eq!(
        stderr(&output),
        "meshes/tetrahedron.wtb: flip-edge 0: flipping edge 0 would join vertices 1 and 2 \
         a second time (edge 3 already joins them)\n"
    );
    assert_eq!(stdout(&output), "");
    assert!(!out.exists(), "a refused edit writes nothing");
    let output = run(&[
        "edit",
        "meshes/open-square.wtb",
        &out.to_string_lossy(),
        "remove-vertex",
        "9",
    ]);
    assert_eq!(code(&output), 1);
    assert_eq!(
        stderr(&output),
        "meshes/open-square.wtb: remove-vertex 9: vertex 9 does not exist\n"
    );
}

#[test]
fn edit_command_line_mistakes_are_usage_errors() {
    let out = std::env::temp_dir().join("edgewise-cli-edit-usage.obj");
    let out = out.to_string_lossy();
    for (args, message) in [
        (
            vec!["flop", "0"],
            "no operation is named `flop`; the operations are flip-edge,",
        ),
        (
            vec!["flip-edge", "0", "1"],
            "flip-edge takes 1 id (edge), not 2",
        ),
        (vec!["flip-edge"], "required"),
    ] {
        let mut all = vec!["edit", "meshes/cube.htb", &out];
        all.extend(&args);
        let output = run(&all);
        assert_eq!(code(&output), 2, "{args:?}");
        assert!(
            stderr(&output).contains(message),
            "{args:?}: {}",
            stderr(&output)
        );
    }
    let help = run(&["edit", "--help"]);
    assert!(
        stdout(&help).contains("  mekr <face> <vertex on the face> <vertex on a boundary loop>\n")
    );
}

#[test]
fn trace_runs_an_editing_algorithm_and_saves_what_it_leaves() {
    let dir = scratch("trace-save");
    let out = dir.join("flipped.obj");
    let output = run(&[
        "trace",
        "algorithms/half-edge-edits.alg",
        "flipEdge",
        "meshes/hexagon.obj",
        "--arg",
        "h=2",
        "--save",
        &out.to_string_lossy(),
    ]);
    assert_eq!(code(&output), 0, "{}", stderr(&output));
    let text = stdout(&output);
    assert!(
        text.contains("write edge 2.endVertex := vertex 2 (was vertex 0)"),
        "{text}"
    );
    assert!(
        text.contains(
            "changes: 12\nbefore: V 7, E 12, F 6, V − E + F = 1\nafter:  V 7, E 12, F 6, V − E + F = 1\n"
        ),
        "{text}"
    );
    assert!(
        text.ends_with(&format!("wrote {} (189 bytes)\n", out.display())),
        "{text}"
    );
    let check = run(&["check", &out.to_string_lossy()]);
    assert_eq!(code(&check), 0, "{}", stderr(&check));
    let flipped = std::fs::read_to_string(&out).expect("written");
    assert!(flipped.contains("f 2 3 4\nf 3 2 1\n"), "{flipped}");

    // A refusal is an error at its line, and nothing is written.
    let refused = dir.join("refused.obj");
    let output = run(&[
        "trace",
        "algorithms/half-edge-edits.alg",
        "flipEdge",
        "meshes/hexagon.obj",
        "--arg",
        "h=0",
        "--save",
        &refused.to_string_lossy(),
    ]);
    assert_eq!(code(&output), 1);
    assert_eq!(
        stderr(&output),
        "algorithms/half-edge-edits.alg:41: error: edge 0 is on the boundary; a flip needs two faces\n"
    );
    assert!(!refused.exists());
}

#[test]
fn trace_refuses_to_save_what_an_algorithm_left_broken() {
    let dir = scratch("trace-broken");
    let alg = dir.join("broken.alg");
    std::fs::write(
        &alg,
        "algorithm unpair(h : Edge) : HalfEdge;\nbegin\n  h.pair := h.next;\nend;\n",
    )
    .expect("scratch file");
    let out = dir.join("out.obj");
    let output = run(&[
        "trace",
        &alg.to_string_lossy(),
        "unpair",
        "meshes/hexagon.obj",
        "--arg",
        "h=2",
        "--save",
        &out.to_string_lossy(),
    ]);
    assert_eq!(code(&output), 1);
    let message = stderr(&output);
    assert!(message.contains("unpair left"), "{message}");
    assert!(message.contains("broken record"), "{message}");
    assert!(message.contains("edge 2 pair_edge"), "{message}");
    assert!(!out.exists());
}
