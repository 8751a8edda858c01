//! A large mesh opens or converts in slices across frames, with the old mesh shown
//! until the new one is ready, and Cancel keeps the old one.

use crate::support;

use edgewise_app::command::Command;
use edgewise_core::mesh::Structure;

fn job_progress(harness: &support::AppHarness) -> Option<f32> {
    harness.state().state().job.map(|job| job.progress)
}

#[test]
fn a_large_mesh_opens_a_slice_per_frame_and_the_old_one_stays_meanwhile() {
    let mut harness = support::harness_with("cube", Some(Structure::HalfEdge));
    harness
        .state_mut()
        .load_sample("torus-200k", Some(Structure::HalfEdge))
        .expect("the load starts");
    let state = harness.state().state();
    let job = state.job.expect("a job is under way");
    assert_eq!(job.label, "Opening torus-200k");
    assert_eq!(
        state.mesh.as_deref(),
        Some("cube.htb"),
        "the old mesh stays"
    );

    let mut seen = vec![job.progress];
    while let Some(progress) = job_progress(&harness) {
        harness.step();
        seen.push(progress);
        assert!(seen.len() < 20, "the job ends: {seen:?}");
    }
    assert!(
        seen.windows(2).all(|w| w[0] <= w[1]) && seen.len() >= 2,
        "progress grows over frames: {seen:?}"
    );
    let state = harness.state().state();
    assert_eq!(state.mesh.as_deref(), Some("torus-200k"));
    assert_eq!(state.counts.faces, 316 * 316 * 2);
    assert_eq!(
        state.history.undo.last().map(String::as_str),
        Some("open torus-200k"),
        "{:?}",
        state.history
    );
    let job = harness.state().pending_job();
    assert!(job.is_none());
    // The statistics and the rule check are worked out in a frame before
    // the mesh shows, and are the new mesh's.
    let stats = state.stats.expect("statistics");
    assert_eq!((stats.vertices, stats.faces), (316 * 316, 316 * 316 * 2));
    assert_eq!((stats.euler, stats.genus), (0, vec![Some(1)]));
    assert!(!state.diagnosis, "a sound mesh is not diagnosed");

    // Converting is sliced the same way, and undo gives the half-edge back.
    harness
        .state_mut()
        .execute(Command::SetStructure(Structure::WingedEdge))
        .expect("the conversion starts");
    assert_eq!(harness.state().state().structure, Some("half"));
    let id = harness.state().pending_job().expect("a conversion job");
    harness.run();
    assert_eq!(harness.state().job_outcome(id), Some(Ok(())));
    let state = harness.state().state();
    assert_eq!(state.structure, Some("winged"));
    let stats = state.stats.expect("statistics");
    assert_eq!(stats.edges, 316 * 316 * 3, "the winged-edge mesh's edges");
    harness.state_mut().execute(Command::Undo).expect("undoes");
    assert_eq!(harness.state().state().structure, Some("half"));
}

#[test]
fn cancel_keeps_the_old_mesh() {
    let mut harness = support::harness_with("cube", Some(Structure::HalfEdge));
    harness
        .state_mut()
        .load_sample("torus-200k", None)
        .expect("the load starts");
    let id = harness.state().pending_job().expect("a job");
    harness.step();
    harness
        .state_mut()
        .execute(Command::Cancel)
        .expect("cancels");
    harness.run();
    let state = harness.state().state();
    assert_eq!(state.mesh.as_deref(), Some("cube.htb"));
    assert!(state.job.is_none());
    assert_eq!(
        harness.state().job_outcome(id),
        Some(Err("Opening torus-200k was cancelled".to_owned()))
    );
    let refused = harness.state_mut().execute(Command::Cancel).unwrap_err();
    assert_eq!(refused.to_string(), "nothing is being opened or converted");
}

#[test]
fn a_small_mesh_opens_at_once() {
    let mut harness = support::harness_with("cube", None);
    harness
        .state_mut()
        .load_sample("icosphere-20k", None)
        .expect("opens");
    let state = harness.state().state();
    assert!(state.job.is_none());
    assert_eq!(state.mesh.as_deref(), Some("icosphere-20k.ply"));
}

#[test]
fn a_course_link_runs_its_algorithm_on_its_large_mesh() {
    let (harness, messages) = support::open_link(
        "?sample=torus-200k&structure=winged&algorithm=vertexStar&args=v:7&step=2",
        "",
    );
    assert!(messages.is_empty(), "{messages:?}");
    let state = harness.state().state();
    assert_eq!(state.mesh.as_deref(), Some("torus-200k"));
    assert_eq!(state.structure, Some("winged"));
    let trace = state.trace.expect("the algorithm runs on the torus");
    assert_eq!(trace.step, 2);
    assert_eq!(trace.variables["v"], "Vertex 7");
}
