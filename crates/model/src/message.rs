//! The message line: the one sentence under the view that says what it
//! shows. The app writes it there and the pictures use it as their caption.

use edgewise_core::mesh::Mesh;
use edgewise_core::schema::ElementRef;
use edgewise_pictures::text_table::row_name;

use crate::algorithm::frame::TraceFrame;
use crate::algorithm::session::Run;
use crate::document::Document;

/// "Half-edge 3", "Edge 3", "Vertex 1": a row's name to start a sentence.
pub fn titled(mesh: &Mesh, element: ElementRef) -> String {
    let name = row_name(mesh, element);
    let mut chars = name.chars();
    chars
        .next()
        .map(|first| first.to_uppercase().chain(chars).collect())
        .unwrap_or_default()
}

/// The message line while an algorithm runs: the input it waits for, or
/// the step shown (`frame`) and the question asked there.
pub fn run_message(run: &Run, frame: Option<&TraceFrame>) -> Option<String> {
    match run {
        Run::Idle => None,
        Run::Picking(pending) => Some(pending.prompt().unwrap_or_else(|| {
            format!(
                "{}: set its inputs, then press Start",
                pending.algorithm.name
            )
        })),
        Run::Tracing(session) => {
            let frame = frame?;
            let step = format!("Step {} of {}: {}", frame.step, frame.steps, frame.message);
            let question = session
                .quiz
                .as_ref()
                .and_then(|quiz| quiz.waiting(session.step()));
            Some(match question {
                Some(asked) => format!("{step} Question: {}", asked.posed.question.prompt),
                None => step,
            })
        }
    }
}

/// The message line: the run's message, else what a click on the
/// `hovered` element would do, else the selection and what it references,
/// else the file's first note, else what to do first.
pub fn message_line(
    document: &Document,
    run_message: Option<String>,
    hovered: Option<ElementRef>,
) -> String {
    if let Some(text) = run_message {
        text
    } else if let Some(pick) = hovered.filter(|&h| document.selection() != Some(h)) {
        format!("{}: click to select", titled(document.mesh(), pick))
    } else if let Some(first) = document.highlights().first() {
        let refs: Vec<String> = document.highlights()[1..]
            .iter()
            .map(|h| format!("{} {}", h.role.key(), h.element.id))
            .collect();
        format!(
            "{} selected: {}",
            titled(document.mesh(), first.element),
            refs.join(", ")
        )
    } else if let Some(warning) = document.warnings.first() {
        format!("Note: {warning}")
    } else {
        "Click a vertex, edge or face, here or in the tables.".to_owned()
    }
}
