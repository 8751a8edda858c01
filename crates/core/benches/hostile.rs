//! The worst work one input can ask for within the limits (docs/limits.md):
//! compiling the costliest algorithm texts of at most 1 MiB, and reading
//! mesh texts per megabyte, so the time one load takes at the 256 MiB limit
//! can be read off. Each figure is the whole call, refusal included.
//!
//! Run: `cargo bench -p edgewise-core --bench hostile`.

use std::hint::black_box;
use std::time::Duration;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use edgewise_core::formats;
use edgewise_core::lang;
use edgewise_core::mesh::{Mesh, Structure, generate};

fn algorithm(params: &str, vars: &str, body: &str) -> String {
    format!("algorithm a({params}) : HalfEdge;\n{vars}begin\n{body}\nend\n")
}

/// Algorithm texts near 1 MiB that each stress one pass.
fn sources() -> Vec<(&'static str, String)> {
    let names: Vec<String> = (0..20_000).map(|i| format!("x{i}")).collect();
    let many_variables = algorithm(
        "",
        &format!("var {} : Integer;\n", names.join(", ")),
        &names
            .iter()
            .map(|n| format!("{n} := {n} + 1;\n"))
            .collect::<String>(),
    );
    let misspelled = many_variables.replace(":= x", ":= y");
    let mut statements = String::new();
    while statements.len() < 1_000_000 {
        statements.push_str("if n > 1 then n := n div 2 + n mod 3; else n := n * 3 + 1; end\n");
    }
    let algorithms: String = (0..25_000)
        .map(|i| format!("algorithm a{i}() : HalfEdge; begin end\n"))
        .collect();
    vec![
        (
            "100000-additions",
            algorithm(
                "n : Integer",
                "",
                &format!("n := n{};", " + 1".repeat(100_000)),
            ),
        ),
        (
            "100000-parentheses",
            algorithm(
                "n : Integer",
                "",
                &format!("n := {}1{};", "(".repeat(100_000), ")".repeat(100_000)),
            ),
        ),
        ("20000-variables", many_variables),
        ("20000-misspelled-variables", misspelled),
        (
            "1mib-of-statements",
            algorithm("n : Integer", "", &statements),
        ),
        ("25000-algorithms", algorithms),
        (
            "50000-errors",
            algorithm("n : Integer", "", &"n := 1 # 2;\n".repeat(50_000)),
        ),
    ]
}

fn compile(c: &mut Criterion) {
    let mut group = c.benchmark_group("hostile/compile");
    group.sample_size(10);
    group.measurement_time(Duration::from_secs(3));
    for (name, source) in sources() {
        assert!(
            source.len() <= lang::MAX_SOURCE_BYTES,
            "{name} is too large"
        );
        group.throughput(Throughput::Bytes(source.len() as u64));
        group.bench_function(name, |b| {
            b.iter(|| black_box(lang::compile(black_box(&source)).is_ok()));
        });
    }
    group.finish();
}

/// Mesh texts of about 8 MB: the time per byte scales to the 256 MiB limit.
fn load(c: &mut Criterion) {
    let mut group = c.benchmark_group("hostile/load");
    group.sample_size(10);
    group.measurement_time(Duration::from_secs(5));
    let torus = generate::torus(200, 200);
    let (half, _) = Mesh::build(&torus, Structure::HalfEdge).expect("the torus builds");
    for (name, format) in [
        ("obj", formats::Format::Obj),
        ("ply", formats::Format::Ply),
        ("htb", formats::Format::Htb),
        ("wtb", formats::Format::Wtb),
    ] {
        let bytes = formats::save(&half, format, &formats::SaveOptions::default()).expect("saves");
        let file = format!("torus.{name}");
        group.throughput(Throughput::Bytes(bytes.len() as u64));
        group.bench_function(format!("{name}-{:.1}MB", bytes.len() as f64 / 1e6), |b| {
            b.iter(|| {
                black_box(formats::load(black_box(&bytes), &file, Structure::HalfEdge).is_ok())
            });
        });
    }
    group.finish();
}

criterion_group!(benches, compile, load);
criterion_main!(benches);
