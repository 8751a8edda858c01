//! What one step of a trace shows, following the journal's conventions
//! (section 6 and Table 3):
//! - a lookup colours its base and its result green, and tints the column
//!   it read in the base's table row;
//! - an assignment adds the variable's name to the element's label; every
//!   element a variable refers to is purple;
//! - a comparison colours both sides light blue and points an arrow at each
//!   (two arrows when both sides are the same element);
//! - marks are blue, persistent, and lowest in priority;
//! - `highlight` is yellow;
//! - everything else fades.
//!
//! Steps are numbered as the step slider shows them: step 0 is the moment the
//! inputs are picked, step k the moment after the k-th operation.

use crate::trace_role::TraceRole;
use edgewise_core::schema::ElementRef;
use std::collections::HashMap;

use edgewise_core::lang::{Algorithm, Routine, StepKind, Trace, Type, Value};
use serde::Serialize;

use crate::{
    paint::{Paint, Painted},
    selection::Role,
    theme::Theme,
};

/// A variable and its value at one step, as the algorithm view lists them.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct VariableView {
    pub name: String,
    pub ty: &'static str,
    /// "Edge 13", "Integer 4", "Boolean true" or "null".
    pub value: String,
}

/// The `message` lines a step shows: the latest ones. A runaway loop can
/// print a hundred thousand, and each shown line is laid out every frame.
pub const MOST_OUTPUT_LINES: usize = 200;

/// Everything the views show for one step.
#[derive(Clone, Debug, PartialEq)]
pub struct TraceFrame {
    /// 0..=steps.
    pub step: usize,
    pub steps: usize,
    /// The 1-based source line of the operation shown (the header at step 0).
    pub line: u32,
    /// Byte offsets of the expression executed, in the algorithm's source.
    pub span: Option<(u32, u32)>,
    pub variables: Vec<VariableView>,
    /// The call stack, the started algorithm first: `cutCorner (called on
    /// line 140)`. One entry outside calls.
    pub calls: Vec<String>,
    /// A short name of the operation: "start" at step 0, then "lookup",
    /// "assign", "compare", "compute", "mark", "highlight", "message",
    /// "write", "new", "delete", "call", "return", "index", "store",
    /// "append" or "done".
    pub operation: &'static str,
    /// The message line: this step in one sentence.
    pub message: String,
    pub marked: Vec<ElementRef>,
    /// The run finished and this is its last step.
    pub done: bool,
    /// The run stopped on an error and this is the last step before it.
    pub error: Option<String>,
    /// The algorithm's latest `message` output so far (at most
    /// [`MOST_OUTPUT_LINES`]), oldest first.
    pub output: Vec<String>,
    /// How many `message`s the run printed so far.
    pub output_count: usize,
    pub paint: Paint,
}

/// "Edge 13", "Integer 4", "Boolean true", "null".
pub fn value_text(value: Value) -> String {
    match value {
        Value::Null => "null".to_owned(),
        Value::Vertex(i) => format!("Vertex {i}"),
        Value::Edge(i) => format!("Edge {i}"),
        Value::Face(i) => format!("Face {i}"),
        Value::Integer(n) => format!("Integer {n}"),
        Value::Boolean(b) => format!("Boolean {b}"),
        Value::Float(_) => format!("Float {value}"),
        Value::Vector(_) => format!("Vector {value}"),
        Value::Array(n) => format!("Array {n}"),
    }
}

/// A value as a table cell shows it: an id, `∅` for none, or coordinates.
fn cell_text(value: Value) -> String {
    match value {
        Value::Null => "∅".to_owned(),
        Value::Vertex(i) | Value::Edge(i) | Value::Face(i) => i.to_string(),
        other => other.to_string(),
    }
}

/// Builds the frame of step `step` (clamped to the trace's length).
pub fn frame_at(trace: &Trace, step: usize, theme: &Theme) -> TraceFrame {
    let algorithm = trace.algorithm();
    let steps = trace.len();
    let step = step.min(steps);
    let view = step.checked_sub(1).and_then(|index| trace.step(index));
    let variables = match step {
        0 => trace.initial_variables().to_vec(),
        k => trace.variables_at(k - 1),
    };
    // Inside a call, the variables shown are the running algorithm's.
    let frames = step
        .checked_sub(1)
        .map(|index| trace.frames_at(index))
        .unwrap_or_default();
    let calls: Vec<String> = frames
        .iter()
        .map(|frame| match frame.call_line {
            Some(line) => format!("{} (called on line {line})", frame.name),
            None => frame.name.to_owned(),
        })
        .collect();
    let shown: Vec<(String, Type, Value)> = match frames.last() {
        Some(frame) if frames.len() > 1 => frame
            .variables
            .iter()
            .map(|(info, value)| (info.name.clone(), info.ty, *value))
            .collect(),
        _ => algorithm
            .variables
            .iter()
            .zip(&variables)
            .map(|(info, value)| (info.name.clone(), info.ty, *value))
            .collect(),
    };
    let (marked, highlighted): (Vec<ElementRef>, Vec<ElementRef>) = match step {
        0 => (Vec::new(), Vec::new()),
        k => (
            trace.marked_at(k - 1).collect(),
            trace.highlighted_at(k - 1).collect(),
        ),
    };
    let at_end = step == steps;
    let error = trace
        .outcome()
        .error()
        .filter(|_| at_end)
        .map(ToString::to_string);
    let done = at_end && error.is_none() && matches!(view.map(|v| v.kind), Some(StepKind::Done));
    let (output_count, latest) = trace.messages_before(step, MOST_OUTPUT_LINES);
    let output = latest.to_vec();

    let mut paint = Paint {
        fade_others: true,
        ..Paint::default()
    };
    // The current operation first: it outranks everything else.
    if let Some(view) = view.filter(|_| !done) {
        paint_operation(&mut paint, view.kind, theme);
    }
    paint.focus = paint.painted.first().map(|p| p.element);
    // At the end only the marks stay (Neperud, section 5.4).
    if !done {
        for &element in &highlighted {
            push_role(&mut paint, theme, element, TraceRole::Highlighted);
        }
    }
    let mut names: HashMap<ElementRef, Vec<&str>> = HashMap::new();
    if !done {
        for (name, _, value) in &shown {
            if let Some(element) = value.element() {
                names.entry(element).or_default().push(name);
            }
        }
        let mut referred: Vec<ElementRef> = names.keys().copied().collect();
        referred.sort_by_key(|e| (e.kind as u8, e.id));
        for element in referred {
            push_role(&mut paint, theme, element, TraceRole::Variable);
        }
    }
    for &element in &marked {
        push_role(&mut paint, theme, element, TraceRole::Output);
    }
    label(&mut paint, &names);

    let (line, span) = match view {
        Some(view) => (view.line, Some((view.span.start, view.span.end))),
        None => (algorithm.first_line, None),
    };
    let message = match (&error, view) {
        (Some(error), _) => format!("Stopped at {error}"),
        (None, None) => format!(
            "{} is ready: step forward to run it{}",
            algorithm.name,
            inputs_text(algorithm, &variables)
        ),
        // Inside a call, the step names the called algorithm's variables.
        (None, Some(view)) => {
            let running = frames.last().map_or(&***algorithm, |frame| frame.routine);
            describe(running, view.kind, view.span, &marked)
        }
    };
    TraceFrame {
        step,
        steps,
        line,
        span,
        variables: shown
            .iter()
            .map(|(name, ty, value)| VariableView {
                name: name.clone(),
                ty: type_name(*ty),
                value: match value {
                    Value::Array(_) => {
                        format!("Array {}", trace.show(*value, step.saturating_sub(1)))
                    }
                    other => value_text(*other),
                },
            })
            .collect(),
        calls,
        operation: view.map_or("start", |v| operation_name(v.kind)),
        message,
        marked,
        done,
        error,
        output,
        output_count,
        paint,
    }
}

/// Adds `element` to what the views colour, in `role`'s colour.
fn push_role(paint: &mut Paint, theme: &Theme, element: ElementRef, role: TraceRole) {
    paint.painted.push(Painted {
        element,
        colour: theme.trace_colour(role),
        role: role.key().to_owned(),
    });
}

/// Colours what the current operation reads, writes, creates, marks,
/// deletes or compares, and the table cells it reads or writes.
fn paint_operation(paint: &mut Paint, kind: StepKind<'_>, theme: &Theme) {
    match kind {
        StepKind::Lookup {
            base,
            field,
            result,
        } => {
            if let Some(base) = base.element() {
                push_role(paint, theme, base, TraceRole::Lookup);
                paint.cells.insert(
                    (base, Role::Column(field)),
                    theme.trace_colour(TraceRole::Lookup),
                );
            }
            if let Some(result) = result.element() {
                push_role(paint, theme, result, TraceRole::Lookup);
            }
        }
        StepKind::Write {
            element,
            field,
            old,
            new,
        } => {
            if let Some(element) = element.element() {
                push_role(paint, theme, element, TraceRole::Written);
                let cell = (element, Role::Column(field));
                paint
                    .cells
                    .insert(cell, theme.trace_colour(TraceRole::Written));
                paint.struck.insert(cell, cell_text(old));
            }
            if let Some(target) = new.element() {
                push_role(paint, theme, target, TraceRole::Written);
            }
        }
        StepKind::New { element } => {
            if let Some(element) = element.element() {
                push_role(paint, theme, element, TraceRole::Created);
            }
        }
        // Blue at the step that marks it, though a variable still refers
        // to it (the journal's Fig. 9e).
        StepKind::Mark { element } => {
            if let Some(element) = element.element() {
                push_role(paint, theme, element, TraceRole::Output);
            }
        }
        StepKind::Delete { element } => {
            if let Some(element) = element.element() {
                push_role(paint, theme, element, TraceRole::Deleted);
            }
        }
        StepKind::Compare { left, right, .. } => {
            for side in [left, right] {
                if let Some(element) = side.element() {
                    push_role(paint, theme, element, TraceRole::Compared);
                    paint
                        .pointers
                        .push((element, theme.trace_colour(TraceRole::Compared)));
                }
            }
        }
        _ => {}
    }
}

/// Labels each coloured element with its roles' glyphs, then the names of
/// the variables that refer to it.
fn label(paint: &mut Paint, names: &HashMap<ElementRef, Vec<&str>>) {
    let mut glyphs: HashMap<ElementRef, Vec<&str>> = HashMap::new();
    for painted in &paint.painted {
        if let Some(glyph) = TraceRole::parse(&painted.role).and_then(TraceRole::glyph) {
            let entry = glyphs.entry(painted.element).or_default();
            if !entry.contains(&glyph) {
                entry.push(glyph);
            }
        }
    }
    paint.variable_names = names
        .iter()
        .map(|(element, names)| (*element, names.join(", ")))
        .collect();
    let labelled: std::collections::BTreeSet<ElementRef> =
        glyphs.keys().chain(names.keys()).copied().collect();
    paint.labels = labelled
        .into_iter()
        .map(|element| {
            let marks = glyphs.get(&element).map(|g| g.concat());
            let names = names.get(&element).map(|n| n.join(", "));
            let label = [marks, names].into_iter().flatten().collect::<Vec<_>>();
            (element, label.join(" "))
        })
        .collect();
}

fn type_name(ty: Type) -> &'static str {
    ty.name()
}

fn operation_name(kind: StepKind<'_>) -> &'static str {
    match kind {
        StepKind::Lookup { .. } => "lookup",
        StepKind::Assign { .. } => "assign",
        StepKind::Compare { .. } => "compare",
        StepKind::Compute { .. } => "compute",
        StepKind::Mark { .. } => "mark",
        StepKind::Highlight { .. } => "highlight",
        StepKind::Message { .. } => "message",
        StepKind::Write { .. } => "write",
        StepKind::New { .. } => "new",
        StepKind::Delete { .. } => "delete",
        StepKind::Call { .. } | StepKind::Invoke { .. } => "call",
        StepKind::Return { .. } => "return",
        StepKind::Index { .. } => "index",
        StepKind::Store { .. } => "store",
        StepKind::Append { .. } => "append",
        StepKind::Done => "done",
    }
}

/// " with v = vertex 1", or "" without parameters.
fn inputs_text(algorithm: &Algorithm, variables: &[Value]) -> String {
    let inputs: Vec<String> = algorithm
        .params()
        .zip(variables)
        .map(|(p, v)| format!("{} = {v}", p.name))
        .collect();
    if inputs.is_empty() {
        String::new()
    } else {
        format!(" with {}", inputs.join(", "))
    }
}

/// One sentence for the message line.
fn describe(
    algorithm: &Routine,
    kind: StepKind<'_>,
    span: edgewise_core::lang::Span,
    marked: &[ElementRef],
) -> String {
    let code = algorithm.snippet(span);
    match kind {
        StepKind::Lookup { base, result, .. } => {
            format!("Lookup {code}: the table row of {base} gives {result}")
        }
        StepKind::Assign { variable, value } => {
            let name = algorithm
                .variables
                .get(variable)
                .map_or("?", |v| v.name.as_str());
            format!("Assignment: {name} := {value}")
        }
        StepKind::Compare {
            op,
            left,
            right,
            result,
        } => format!(
            "Comparison {code}: {left} {} {right} is {result}",
            op.symbol()
        ),
        StepKind::Compute {
            op,
            left,
            right,
            result,
        } => match right {
            Some(right) => format!("Compute {code}: {left} {} {right} = {result}", op.symbol()),
            None => format!("Compute {code}: {} {left} = {result}", op.symbol()),
        },
        StepKind::Mark { element } => format!("Mark {element}: it joins the output"),
        StepKind::Highlight { element } => format!("Highlight {element}"),
        StepKind::Message { text } => format!("Message: {text}"),
        StepKind::Write {
            element,
            field,
            old,
            new,
        } => format!(
            "Write {code}: the {} of {element} was {old}, now {new}",
            field.key()
        ),
        StepKind::New { element } => format!("New: {element} is added with the next free id"),
        StepKind::Delete { element } => {
            format!("Delete {element}: its row stays as a gap until the ids are compacted")
        }
        StepKind::Call { result, .. } => format!("Call {code} = {result}"),
        StepKind::Invoke { algorithm, .. } => {
            format!("Call {algorithm}: its steps follow, one level deeper")
        }
        StepKind::Return { value: Some(value) } => format!("Return {value} to the caller"),
        StepKind::Return { value: None } => "Return to the caller".to_owned(),
        StepKind::Index { index, result, .. } => format!("Index {code}: item {index} is {result}"),
        StepKind::Store {
            index, old, new, ..
        } => format!("Store {code}: item {index} was {old}, now {new}"),
        StepKind::Append { value, length, .. } => {
            format!("Append {value}: the array now has {length} items")
        }
        StepKind::Done => {
            let output: Vec<String> = marked.iter().map(ToString::to_string).collect();
            if output.is_empty() {
                format!("{} is done; it marked nothing", algorithm.name)
            } else {
                format!(
                    "{} is done. Output: {}. Pick an element to end the run",
                    algorithm.name,
                    output.join(", ")
                )
            }
        }
    }
}
