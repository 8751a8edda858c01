//! The bodies of the fuzz targets in `fuzz/`, one function per target.
//!
//! The fuzz targets (nightly, libFuzzer) and the replay tests
//! (`crates/core/tests/it/fuzz_regressions.rs`, stable, run by `cargo xtask
//! test`) both call these, so a crash found by the fuzzer is replayed by
//! exactly the code that found it. Each function panics only on a bug: a
//! reader that panics, or a mesh that loads but does not validate.
//!
//! Not part of the library's interface.

use std::sync::OnceLock;

use crate::formats::{self, Format, Loaded};
use crate::lang::{self, RunOptions, Type, Value};
use crate::mesh::operations::{self, Operation};
use crate::mesh::{ConvertError, Edit as _, Mesh, Structure};
use crate::schema::ElementRef;

/// Lines of a fuzzed run's trace that are rendered: enough to reach arrays
/// and messages, few enough that a million-step run stays fast.
const VM_RENDERED_LINES: usize = 5_000;

/// File names for [`detect`], picked by the input's first byte: bare
/// extensions, names with and without extensions, and an unknown one.
pub const DETECT_NAMES: [&str; 8] = [
    "",
    "mesh",
    "mesh.obj",
    "MESH.PLY",
    "dir/mesh.wtb",
    "htb",
    "mesh.txt",
    "dir.d\\pasted",
];

/// `.obj` bytes, read into both structures.
pub fn obj(data: &[u8]) {
    load_both(data, Format::Obj);
}

/// `.ply` bytes (ASCII or either binary byte order), read into both
/// structures.
pub fn ply(data: &[u8]) {
    load_both(data, Format::Ply);
}

/// `.wtb` bytes, read and converted to half-edge, and read for diagnosis.
pub fn wtb(data: &[u8]) {
    load_both(data, Format::Wtb);
    diagnose(data, "fuzz.wtb");
}

/// `.htb` bytes, read and converted to winged-edge, and read for diagnosis.
pub fn htb(data: &[u8]) {
    load_both(data, Format::Htb);
    diagnose(data, "fuzz.htb");
}

/// What the app does with tables opened for diagnosis, however broken:
/// check every rule, draw the faces it can walk, count, and read every
/// reference; none of it may panic or run without end.
fn diagnose(data: &[u8], name: &str) {
    use crate::schema::{Column, ElementKind, Records};
    let Ok(loaded) = formats::load_for_diagnosis(data, name, Structure::HalfEdge) else {
        return;
    };
    let mesh = &loaded.mesh;
    drop(mesh.validate());
    drop(mesh.to_polygons());
    drop(mesh.live_stats());
    for kind in ElementKind::ALL {
        for id in 0..Records::count(mesh, kind) as u32 {
            for entry in Column::table(mesh.structure(), kind) {
                drop(mesh.reference(ElementRef::new(kind, id), entry.column));
            }
        }
    }
    for warning in &loaded.warnings {
        drop(warning.to_string());
    }
}

/// Format detection then loading: the first byte picks a file name from
/// [`DETECT_NAMES`] and the structure, the rest is the file.
pub fn detect(data: &[u8]) {
    let Some((&selector, bytes)) = data.split_first() else {
        return;
    };
    let name = DETECT_NAMES[usize::from(selector) % DETECT_NAMES.len()];
    let structure = if selector & 0x80 == 0 {
        Structure::HalfEdge
    } else {
        Structure::WingedEdge
    };
    let sniffed = Format::sniff(bytes);
    match formats::load(bytes, name, structure) {
        Ok(loaded) => {
            if !name.contains('.') && Format::from_name(name).is_none() {
                assert_eq!(loaded.format, sniffed, "a name with no extension sniffs");
            }
            check_loaded(&loaded, structure);
        }
        Err(error) => drop(error.to_string()),
    }
}

/// Algorithm text through the whole pipeline: lexer, parser, checker,
/// compiler, then the disassembler (or the rendered diagnostics).
pub fn compile(data: &[u8]) {
    // The compiler takes `&str`: text that is not UTF-8 never reaches it.
    let Ok(source) = std::str::from_utf8(data) else {
        return;
    };
    match lang::compile(source) {
        Ok(program) => {
            let listing = lang::disassemble_all(program.algorithms.iter().map(AsRef::as_ref));
            assert!(program.algorithms.is_empty() || !listing.is_empty());
        }
        Err(diagnostics) => {
            assert!(!diagnostics.is_empty(), "a failed compile says why");
            drop(lang::render_all(&diagnostics, source, Some("fuzz.alg")));
        }
    }
}

/// Algorithm text, compiled; every algorithm that compiles is run on a small
/// sample mesh of its structure with arguments that fit its parameters.
///
/// The input is the source text, optionally followed by a NUL byte and the
/// argument bytes: the first picks the mesh, then one byte (two for an
/// Integer) per parameter; missing bytes count as zero.
pub fn vm(data: &[u8]) {
    let (text, argument_bytes) = match data.iter().position(|&b| b == 0) {
        Some(nul) => (&data[..nul], &data[nul + 1..]),
        None => (data, &[][..]),
    };
    // The compiler takes `&str`: text that is not UTF-8 never reaches it.
    let Ok(source) = std::str::from_utf8(text) else {
        return;
    };
    let Ok(program) = lang::compile(source) else {
        return;
    };
    let mut bytes = argument_bytes.iter().copied();
    let mesh_choice = bytes.next().unwrap_or(0);
    for algorithm in &program.algorithms {
        let mesh = sample_mesh(algorithm.structure, mesh_choice);
        let mut inputs: Vec<(&str, Value)> = Vec::new();
        for param in algorithm.params() {
            let byte = bytes.next().unwrap_or(0);
            let value = match param.ty {
                Type::Integer => {
                    let low = bytes.next().unwrap_or(0);
                    Value::Integer(i32::from(i16::from_le_bytes([low, byte])))
                }
                Type::Boolean => Value::Boolean(byte & 1 == 1),
                ty => {
                    let Some(kind) = ty.element_kind() else {
                        return;
                    };
                    let count = lang::Topology::count(mesh, kind).max(1);
                    let index = usize::from(byte) % count;
                    Value::from(ElementRef::new(kind, u32::try_from(index).unwrap_or(0)))
                }
            };
            inputs.push((param.name.as_str(), value));
        }
        check_run(algorithm, mesh, &inputs);
    }
}

/// Runs `algorithm` with the real limits, recording and not, and checks
/// that both agree; an editing algorithm runs on copies of `mesh`. The trace
/// is checked and dropped before the other run starts, so one run's budget
/// at a time is alive, as in the app.
fn check_run(algorithm: &std::sync::Arc<lang::Algorithm>, mesh: &Mesh, inputs: &[(&str, Value)]) {
    let options = RunOptions::default();
    let refused = |error: lang::InputError| -> ! { panic!("fitting arguments refused: {error}") };
    let mut traced = mesh.clone();
    let trace = if algorithm.edits() {
        lang::run_editing(algorithm, &mut traced, inputs, options)
    } else {
        lang::run(algorithm, mesh, inputs, options)
    }
    .unwrap_or_else(|e| refused(e));
    check_trace(&trace, options);
    // Only the trace keeps its steps, so only it may stop for memory.
    let expected = (!hit_memory_limit(trace.outcome())).then(|| {
        (
            trace.outcome().clone(),
            trace.final_variables().to_vec(),
            traced.stats(),
        )
    });
    drop(trace);
    drop(traced);

    let mut executed = mesh.clone();
    let execution = if algorithm.edits() {
        lang::execute_editing(algorithm, &mut executed, inputs, options)
    } else {
        lang::execute(algorithm, mesh, inputs, options)
    }
    .unwrap_or_else(|e| refused(e));
    if let Some((outcome, variables, stats)) = expected {
        assert_eq!(
            execution.outcome, outcome,
            "execute and run agree on the outcome"
        );
        assert_eq!(
            execution.variables, variables,
            "execute and run agree on the final variables"
        );
        assert_eq!(executed.stats(), stats, "both runs edit alike");
    }
}

/// The trace stays within its budget, and its first, middle and last steps
/// decode and its first lines render.
fn check_trace(trace: &lang::Trace, options: RunOptions) {
    assert!(
        trace.memory_bytes() <= options.memory_limit,
        "the trace keeps {} bytes, over its budget",
        trace.memory_bytes()
    );
    let last = trace.len().saturating_sub(1);
    for index in [0, last / 2, last] {
        assert!(
            trace.step(index).is_some() || trace.is_empty(),
            "step {index} exists"
        );
    }
    for line in trace.lines().take(VM_RENDERED_LINES) {
        drop(line);
    }
}

fn hit_memory_limit(outcome: &lang::Outcome) -> bool {
    outcome
        .error()
        .is_some_and(|error| error.kind == lang::RuntimeErrorKind::MemoryLimit)
}

/// A chain of local operations on a sample mesh (or on an OBJ after a NUL
/// byte), never compacted; after each accepted one the mesh must convert
/// and save faithfully ([`check_saved_faithfully`]).
///
/// The first byte picks the sample and the structure; then every four
/// bytes are an operation and up to three ids.
pub fn convert(data: &[u8]) {
    let (edits, obj) = match data.iter().position(|&b| b == 0) {
        Some(nul) => (&data[..nul], Some(&data[nul + 1..])),
        None => (data, None),
    };
    let choice = edits.first().copied().unwrap_or(0);
    let structure = if choice & 2 == 0 {
        Structure::WingedEdge
    } else {
        Structure::HalfEdge
    };
    let mut mesh = match obj.map(|bytes| formats::load_as(bytes, Format::Obj, structure)) {
        Some(Ok(loaded)) if loaded.mesh.validate().is_empty() => loaded.mesh,
        Some(_) => return,
        None => sample_mesh(structure, choice).clone(),
    };
    for chunk in edits.get(1..).unwrap_or(&[]).chunks(4).take(32) {
        let operation = Operation::ALL[usize::from(chunk[0]) % Operation::ALL.len()];
        let ids: Vec<u32> = operation
            .arguments()
            .iter()
            .zip(chunk.iter().skip(1))
            .map(|(argument, &byte)| {
                let rows = lang::Topology::count(&mesh, argument.kind).max(1);
                u32::from(byte) % u32::try_from(rows).unwrap_or(u32::MAX)
            })
            .collect();
        if operations::apply(&mut mesh, operation, &ids).is_ok()
            && let Err(problem) = check_saved_faithfully(&mesh)
        {
            panic!("after {operation} {ids:?}: {problem}");
        }
    }
}

/// What every command that converts or writes a mesh promises: `mesh`
/// (deleted rows and all) converts to the other structure and writes in
/// every format to files that validate and read back to the counts of the
/// compacted mesh. Only a polygon format may refuse (a face passing a
/// vertex twice), or .htb for a winged-edge mesh with a dangling edge, and
/// the refusal names the format that keeps the mesh.
pub fn check_saved_faithfully(mesh: &Mesh) -> Result<(), String> {
    let mut compacted = mesh.clone();
    compacted.compact();
    let expected = shape_counts(&compacted);
    match mesh.convert_to(mesh.structure().other()) {
        Ok(converted) => {
            let issues = converted.validate();
            if !issues.is_empty() {
                return Err(format!("the converted mesh is broken: {issues:?}"));
            }
            if shape_counts(&converted) != expected {
                return Err(format!(
                    "converted to {:?} counts, expected {expected:?}",
                    shape_counts(&converted)
                ));
            }
        }
        Err(ConvertError::PassesTwice { .. }) => {}
        Err(error) => return Err(format!("the conversion was refused: {error}")),
    }
    for format in Format::ALL {
        match formats::save(mesh, format, &formats::SaveOptions::default()) {
            Ok(bytes) => {
                let structure = format.native_structure().unwrap_or(mesh.structure());
                let loaded = formats::load_as(&bytes, format, structure).map_err(|error| {
                    format!("the {format:?} written does not read back: {error}")
                })?;
                let issues = loaded.mesh.validate();
                if !issues.is_empty() {
                    return Err(format!("the {format:?} read back is broken: {issues:?}"));
                }
                if shape_counts(&loaded.mesh) != expected {
                    return Err(format!(
                        "the {format:?} read back has {:?} counts, expected {expected:?}",
                        shape_counts(&loaded.mesh)
                    ));
                }
            }
            Err(error) => {
                let message = error.to_string();
                let polygon_format = format.native_structure().is_none();
                let winged_to_htb =
                    format == Format::Htb && mesh.structure() == Structure::WingedEdge;
                if !(polygon_format && message.contains(".wtb or .htb")
                    || winged_to_htb && message.contains("keep this mesh in winged-edge (.wtb)"))
                {
                    return Err(format!("{format:?} refused: {message}"));
                }
            }
        }
    }
    Ok(())
}

/// V, E, F, boundary loops and V − E + F: what a file must give back.
fn shape_counts(mesh: &Mesh) -> (usize, usize, usize, usize, i64) {
    let stats = mesh.stats();
    (
        stats.vertices,
        stats.edges,
        stats.faces,
        stats.boundary_loops,
        stats.euler_characteristic,
    )
}

/// The sample meshes [`vm`] runs algorithms on: the tetrahedron and the cube
/// from meshes/, each in both structures.
fn sample_mesh(structure: Structure, choice: u8) -> &'static Mesh {
    static MESHES: OnceLock<[Mesh; 4]> = OnceLock::new();
    let meshes = MESHES.get_or_init(|| {
        let load =
            |bytes: &[u8], format, structure| match formats::load_as(bytes, format, structure) {
                Ok(loaded) => loaded.mesh,
                Err(error) => panic!("a sample mesh does not load: {error}"),
            };
        let tetrahedron = include_bytes!("../../../meshes/tetrahedron.wtb");
        let cube = include_bytes!("../../../meshes/cube.htb");
        [
            load(tetrahedron, Format::Wtb, Structure::WingedEdge),
            load(tetrahedron, Format::Wtb, Structure::HalfEdge),
            load(cube, Format::Htb, Structure::WingedEdge),
            load(cube, Format::Htb, Structure::HalfEdge),
        ]
    });
    let offset = match structure {
        Structure::WingedEdge => 0,
        Structure::HalfEdge => 1,
    };
    &meshes[usize::from(choice & 1) * 2 + offset]
}

fn load_both(data: &[u8], format: Format) {
    for structure in [Structure::WingedEdge, Structure::HalfEdge] {
        match formats::load_as(data, format, structure) {
            Ok(loaded) => check_loaded(&loaded, structure),
            // Rendering the message exercises its location and text too.
            Err(error) => drop(error.to_string()),
        }
    }
}

/// What every successful load promises: the structure asked for, and a mesh
/// with no violated rule.
fn check_loaded(loaded: &Loaded, structure: Structure) {
    assert_eq!(loaded.mesh.structure(), structure);
    let issues = loaded.mesh.validate();
    assert!(
        issues.is_empty(),
        "a loaded {} mesh does not validate: {issues:?}",
        loaded.format
    );
    drop(loaded.mesh.stats());
}
