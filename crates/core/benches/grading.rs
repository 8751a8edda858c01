//! What grading a do-it answer costs on a 20k-face mesh (the 100×100
//! torus, 20,000 triangles), in both structures: the answer is the
//! library's own result, so every check runs to the end (a pass is the
//! slowest grade; a fail stops at its first difference). Live feedback
//! grades at every write, so this must stay well under a frame's worth of
//! a student's patience: the target is 50 ms.
//!
//! Run: `cargo bench -p edgewise-core --bench grading`.

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use edgewise_core::mesh::grade::grade_edit;
use edgewise_core::mesh::operations::{self, Operation};
use edgewise_core::mesh::{Edit, Mesh, Structure, generate};

fn grading(c: &mut Criterion) {
    let mut group = c.benchmark_group("grading/torus-20k");
    group.sample_size(20);
    for structure in Structure::ALL {
        let (before, _) =
            Mesh::build(&generate::torus(100, 100), structure).expect("the torus builds");
        for operation in [
            Operation::FlipEdge,
            Operation::SplitEdge,
            Operation::CollapseEdge,
        ] {
            let ids = [1000];
            let mut answer = before.clone();
            operations::apply(&mut answer, operation, &ids).expect("it applies");
            let label = format!("{} {operation}, a pass", structure.prose());
            group.bench_function(label, |b| {
                b.iter(|| {
                    let grade = grade_edit(&before, operation, &ids, &answer).expect("applies");
                    black_box(grade.passed())
                });
            });
            if operation == Operation::CollapseEdge {
                // As `edgewise practice check` reads it: from a saved file,
                // its rows compacted.
                answer.compact();
                let label = format!("{} {operation}, a pass, compacted", structure.prose());
                group.bench_function(label, |b| {
                    b.iter(|| {
                        let grade = grade_edit(&before, operation, &ids, &answer).expect("applies");
                        black_box(grade.passed())
                    });
                });
            }
        }
    }
    group.finish();
}

criterion_group!(benches, grading);
criterion_main!(benches);
