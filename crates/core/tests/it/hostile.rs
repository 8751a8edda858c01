//! The hostile-input corpus in tests/hostile/: files made to hurt a reader
//! (NUL bytes, bytes that are not UTF-8, counts in the billions, indices past
//! the end) and, made here because they are large, one-megabyte lines and
//! algorithms of 100,000 terms. Each case's outcome, as `edgewise check` and
//! `edgewise check-alg` report it, is in `NAME.expected`; `EDGEWISE_BLESS=1`
//! rewrites those files, to be reviewed like code.

use crate::golden;

use std::path::{Path, PathBuf};

use edgewise_core::formats::{self, Format};
use edgewise_core::lang;
use edgewise_core::mesh::Structure;

fn corpus_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../tests/hostile")
}

/// The tetrahedron every generated mesh case starts from.
const TETRAHEDRON_OBJ: &str =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n";

const MEGABYTE: usize = 1 << 20;

fn sample(name: &str) -> String {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../meshes")
        .join(name);
    std::fs::read_to_string(path).expect("the sample exists")
}

fn algorithm(params: &str, body: &str) -> String {
    format!("algorithm a({params}) : HalfEdge;\nbegin\n{body}\nend\n")
}

/// The cases too large to keep as files, made the same way every run.
fn generated() -> Vec<(&'static str, Vec<u8>)> {
    let long_word = "x".repeat(MEGABYTE);
    let comment_line = format!("# {long_word}\n");
    let wtb = sample("tetrahedron.wtb");
    let htb = sample("cube.htb");
    let ply = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n\
               property float z\nelement face 4\nproperty list uchar int vertex_indices\n\
               end_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 2 0 3\n";
    let cases: Vec<(&'static str, String)> = vec![
        (
            "obj-1mb-comment-line.obj",
            format!("{comment_line}{TETRAHEDRON_OBJ}"),
        ),
        (
            "obj-1mb-number.obj",
            TETRAHEDRON_OBJ.replacen("v 1 0 0", &format!("v 1 0 {long_word}"), 1),
        ),
        (
            "obj-1mb-line-of-indices.obj",
            format!("{TETRAHEDRON_OBJ}f{}\n", " 1".repeat(MEGABYTE / 2)),
        ),
        (
            "ply-1mb-comment-line.ply",
            ply.replacen(
                "format ascii 1.0\n",
                &format!("format ascii 1.0\ncomment {long_word}\n"),
                1,
            ),
        ),
        (
            "ply-1mb-property-line.ply",
            ply.replacen(
                "property float z",
                &format!("property float z {long_word}"),
                1,
            ),
        ),
        ("wtb-1mb-comment-line.wtb", format!("{comment_line}{wtb}")),
        (
            "wtb-1mb-field.wtb",
            wtb.replacen("vertices 4", &format!("vertices {long_word}"), 1),
        ),
        ("htb-1mb-comment-line.htb", format!("{comment_line}{htb}")),
        (
            "htb-1mb-row.htb",
            htb.replacen(
                "faces 6",
                &format!("faces 6{}", " 0".repeat(MEGABYTE / 2)),
                1,
            ),
        ),
        (
            "alg-1mb-comment-line.alg",
            format!(
                "// {}\n{}",
                "x".repeat(MEGABYTE - 100),
                algorithm("v : Vertex", "mark v;")
            ),
        ),
        (
            "alg-100000-additions.alg",
            algorithm("n : Integer", &format!("n := n{};", " + 1".repeat(100_000))),
        ),
        (
            "alg-100000-ands.alg",
            algorithm(
                "b : Boolean",
                &format!("b := b{};", " and b".repeat(100_000)),
            ),
        ),
        (
            "alg-100000-ors.alg",
            algorithm(
                "b : Boolean",
                &format!("b := b{};", " or b".repeat(100_000)),
            ),
        ),
        (
            "alg-40000-lookups.alg",
            algorithm(
                "v : Vertex",
                &format!("v := v{};", ".incidentEdge.endVertex".repeat(20_000)),
            ),
        ),
        (
            "alg-100000-parentheses.alg",
            algorithm(
                "n : Integer",
                &format!("n := {}1{};", "(".repeat(100_000), ")".repeat(100_000)),
            ),
        ),
        (
            "alg-100000-nots.alg",
            algorithm("b : Boolean", &format!("b := {}b;", "not ".repeat(100_000))),
        ),
        (
            "alg-50000-nested-ifs.alg",
            algorithm(
                "b : Boolean",
                &format!(
                    "{}b := true;{}",
                    "if b then ".repeat(50_000),
                    " end".repeat(50_000)
                ),
            ),
        ),
        (
            "alg-50000-errors.alg",
            algorithm("n : Integer", &"n := 1 # 2;\n".repeat(50_000)),
        ),
        (
            "run-60000-variables.alg",
            format!(
                "// run: wide cube.htb v=0\nalgorithm wide(v : Vertex) : HalfEdge;\nvar {} : \
                 Integer;\nbegin\n  while true do\n    a0 := a0 + 1;\n  end;\nend;\n",
                variables(60_000)
            ),
        ),
        (
            "run-calls-20000-variables.alg",
            format!(
                "// run: spin cube.htb v=0\nalgorithm fat(v : Vertex) : HalfEdge returns Integer;\n\
                 var {} : Integer;\nbegin\n  return 1;\nend;\nalgorithm spin(v : Vertex) : \
                 HalfEdge;\nvar i : Integer;\nbegin\n  while true do\n    i := fat(v);\n  \
                 end;\nend;\n",
                variables(20_000)
            ),
        ),
        (
            "alg-too-large.alg",
            format!("// {}\n", "x".repeat(lang::MAX_SOURCE_BYTES)),
        ),
    ];
    cases
        .into_iter()
        .map(|(name, text)| (name, text.into_bytes()))
        .collect()
}

/// `a0, a1, …` up to `count` names, for algorithms with many variables.
fn variables(count: usize) -> String {
    (0..count)
        .map(|i| format!("a{i}"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// What `edgewise check` or `edgewise check-alg` reports for a file; for an
/// algorithm file with a `// run: NAME MESH ARG…` line, what `edgewise
/// trace` reports after running it on that sample.
fn outcome(name: &str, bytes: &[u8]) -> String {
    if name.ends_with(".alg") {
        let source = match lang::source_text(bytes, Some(name)) {
            Ok(source) => source,
            Err(rendered) => return rendered,
        };
        return match lang::compile_rendered(source, Some(name)) {
            Ok(program) => match source
                .lines()
                .next()
                .and_then(|l| l.strip_prefix("// run: "))
            {
                Some(run) => run_outcome(name, &program, run),
                None => format!("{name}: ok, {} algorithms\n", program.algorithms.len()),
            },
            Err(rendered) => rendered,
        };
    }
    let structure = Format::from_name(name)
        .and_then(Format::native_structure)
        .unwrap_or(Structure::WingedEdge);
    match formats::load(bytes, name, structure) {
        Ok(loaded) => {
            let stats = loaded.mesh.stats();
            let mut out = format!(
                "{name}: ok ({} vertices, {} edges, {} faces)\n",
                stats.vertices, stats.edges, stats.faces
            );
            for warning in &loaded.warnings {
                out.push_str(&format!("{name}: warning: {warning}\n"));
            }
            out
        }
        Err(error) => error.render(name),
    }
}

/// Runs `NAME MESH ARG…` of `program` as `edgewise trace` does, with the
/// default limits, and gives the error line it prints; the run must keep
/// no more memory than its budget.
fn run_outcome(file: &str, program: &lang::Program, run: &str) -> String {
    let mut words = run.split_whitespace();
    let (Some(name), Some(mesh)) = (words.next(), words.next()) else {
        return format!("{file}: the run line needs a name and a mesh\n");
    };
    let Some(algorithm) = program.algorithm(name) else {
        return format!("{file}: no algorithm `{name}`\n");
    };
    let arguments: Vec<(String, lang::Value)> = words
        .map(|word| algorithm.parse_argument(word).expect("a valid argument"))
        .collect();
    let inputs: Vec<(&str, lang::Value)> =
        arguments.iter().map(|(n, v)| (n.as_str(), *v)).collect();
    let mut mesh = formats::load(sample(mesh).as_bytes(), mesh, algorithm.structure)
        .expect("the sample loads")
        .mesh;
    let options = lang::RunOptions::default();
    let trace = if algorithm.edits() {
        lang::run_editing(algorithm, &mut mesh, &inputs, options)
    } else {
        lang::run(algorithm, &mesh, &inputs, options)
    }
    .expect("the inputs fit");
    assert!(
        trace.memory_bytes() <= lang::DEFAULT_MEMORY_LIMIT,
        "{file}: the trace keeps {} bytes",
        trace.memory_bytes()
    );
    match trace.outcome().error() {
        Some(error) => format!("{file}:{}: error: {}\n", error.line, error.message),
        None => format!("{file}: ran {} steps\n", trace.len()),
    }
}

/// The cases kept as files, by name, with their bytes.
fn committed(dir: &Path) -> Vec<(String, Vec<u8>)> {
    golden::corpus_inputs(dir)
        .into_iter()
        .map(|name| {
            let bytes = std::fs::read(dir.join(&name)).expect("readable");
            (name, bytes)
        })
        .collect()
}

#[test]
fn every_hostile_input_gets_its_expected_message() {
    let dir = corpus_dir();
    let files = committed(&dir);
    assert!(
        files.len() >= 20,
        "the corpus has only {} files",
        files.len()
    );
    let cases = files.into_iter().chain(
        generated()
            .into_iter()
            .map(|(name, bytes)| (name.to_owned(), bytes)),
    );
    let mut failures = Vec::new();
    let mut count = 0;
    for (name, bytes) in cases {
        count += 1;
        // Every case runs on a wasm-sized stack: a reader that recursed on
        // its input would overflow here, not only in the browser.
        let (file, input) = (name.clone(), bytes);
        let actual = std::thread::Builder::new()
            .stack_size(MEGABYTE)
            .spawn(move || outcome(&file, &input))
            .expect("thread starts")
            .join()
            .unwrap_or_else(|_| format!("{name}: PANICKED\n"));
        failures.extend(golden::compare(
            &golden::expected_path(&dir, &name),
            &actual,
        ));
    }
    assert!(count >= 40, "only {count} cases ran");
    golden::assert_none(&failures);
}

#[test]
fn no_hostile_message_grows_with_its_input() {
    for (name, bytes) in generated() {
        let message = outcome(name, &bytes);
        assert!(
            message.len() < 32_000,
            "{name}: {} bytes of message",
            message.len()
        );
    }
}
