//! `window.edgewise`, generated from two tables.
//!
//! - [`COMMANDS`]: each entry reads its JavaScript arguments into a
//!   [`Command`]; every command returns a Promise that resolves to `null`
//!   when done and rejects with an `Error` whose message says what went
//!   wrong (a bad argument names the call, the argument and what was
//!   expected, before anything is read or changed).
//! - [`QUERIES`]: each entry returns a value (`state`, `algorithms`,
//!   `shareUrl`) or, for `settled`, `exportMesh` and `exportImage`, a
//!   Promise of one.

use eframe::wasm_bindgen::{JsCast as _, JsValue, closure::Closure};

use edgewise_core::{
    formats::{Format, MAX_FILE_BYTES},
    lang::{MAX_SOURCE_BYTES, Value, question},
    mesh::{Structure, operations::Operation},
    schema::{ElementKind, ElementRef},
};

use super::arguments::{
    MAX_NAME_CHARS, arguments, check_options, expected, is_array, items, option_bool,
    option_string, option_text, option_whole_number, shown, structure_option, text_argument,
    whole_number,
};
use super::{after_a_paint, after_ms, exported_object, with_app};
use crate::{
    EdgewiseApp,
    command::Command,
    files::{ANNOUNCE_BYTES, SavedFile, opening_label},
    platform::js_error_text,
    save_format::SaveFormat,
};

/// A command of the API: its name, the call as messages show it, and how
/// its (at most two) arguments become a [`Command`].
struct CommandEntry {
    name: &'static str,
    call: &'static str,
    read: fn(&'static str, &JsValue, &JsValue) -> Result<Command, String>,
}

/// Every command, in the order docs/embedding.md lists them.
const COMMANDS: &[CommandEntry] = &[
    CommandEntry {
        name: "loadMesh",
        call: "loadMesh(text, options)",
        read: read_load_mesh,
    },
    CommandEntry {
        name: "loadSample",
        call: "loadSample(name, options)",
        read: |call, name, options| {
            let name = text_argument(call, "name", name, MAX_NAME_CHARS)?;
            check_options(call, options, &["structure"])?;
            let structure = structure_option(call, options)?;
            Ok(Command::LoadSample { name, structure })
        },
    },
    CommandEntry {
        name: "select",
        call: "select(kind, id)",
        read: |call, kind, id| Ok(Command::Select(Some(read_element(call, kind, id)?))),
    },
    CommandEntry {
        name: "clearSelection",
        call: "clearSelection()",
        read: |_, _, _| Ok(Command::Select(None)),
    },
    CommandEntry {
        name: "setStructure",
        call: "setStructure(name)",
        read: |call, name, _| {
            let structure = structure_name(name)
                .ok_or_else(|| expected(call, "name", "'winged' or 'half'", name))?;
            Ok(Command::SetStructure(structure))
        },
    },
    CommandEntry {
        name: "chooseStructure",
        call: "chooseStructure(name)",
        read: |call, name, _| {
            if name.is_null() {
                return Ok(Command::ChooseStructure(None));
            }
            let structure = structure_name(name)
                .ok_or_else(|| expected(call, "name", "'winged', 'half' or null", name))?;
            Ok(Command::ChooseStructure(Some(structure)))
        },
    },
    CommandEntry {
        name: "loadAlgorithms",
        call: "loadAlgorithms(source, file)",
        read: |call, source, file| {
            let source = text_argument(call, "source", source, MAX_SOURCE_BYTES)?;
            let file = if file.is_undefined() {
                "page.alg".to_owned()
            } else {
                text_argument(call, "file", file, MAX_NAME_CHARS)?
            };
            Ok(Command::LoadAlgorithms { source, file })
        },
    },
    CommandEntry {
        name: "run",
        call: "run(name, args)",
        read: |call, name, args| {
            let name = text_argument(call, "name", name, MAX_NAME_CHARS)?;
            let args = arguments(call, args)?;
            Ok(Command::RunAlgorithm { name, args })
        },
    },
    CommandEntry {
        name: "step",
        call: "step(n)",
        read: |call, n, _| Ok(Command::Step(count(call, "n", n, Some(1))?)),
    },
    CommandEntry {
        name: "answer",
        call: "answer(value, id)",
        read: read_answer,
    },
    CommandEntry {
        name: "ask",
        call: "ask(questions)",
        read: |call, text, _| {
            let text = text_argument(call, "questions", text, question::MAX_SET_BYTES)?;
            Ok(Command::SetQuestions(text))
        },
    },
    CommandEntry {
        name: "back",
        call: "back(n)",
        read: |call, n, _| Ok(Command::Back(count(call, "n", n, Some(1))?)),
    },
    CommandEntry {
        name: "play",
        call: "play()",
        read: |_, _, _| Ok(Command::SetPlaying(true)),
    },
    CommandEntry {
        name: "pause",
        call: "pause()",
        read: |_, _, _| Ok(Command::SetPlaying(false)),
    },
    CommandEntry {
        name: "stepOver",
        call: "stepOver()",
        read: |_, _, _| Ok(Command::StepOver),
    },
    CommandEntry {
        name: "stepOut",
        call: "stepOut()",
        read: |_, _, _| Ok(Command::StepOut),
    },
    CommandEntry {
        name: "goto",
        call: "goto(k)",
        read: |call, k, _| Ok(Command::Goto(count(call, "k", k, None)?)),
    },
    CommandEntry {
        name: "abort",
        call: "abort()",
        read: |_, _, _| Ok(Command::Abort),
    },
    CommandEntry {
        name: "closeAlgorithm",
        call: "closeAlgorithm()",
        read: |_, _, _| Ok(Command::CloseAlgorithm),
    },
    CommandEntry {
        name: "cancel",
        call: "cancel()",
        read: |_, _, _| Ok(Command::Cancel),
    },
    CommandEntry {
        name: "edit",
        call: "edit(op, ids)",
        read: read_edit,
    },
    CommandEntry {
        name: "restoreBeforeEdit",
        call: "restoreBeforeEdit()",
        read: |_, _, _| Ok(Command::RestoreBeforeEdit),
    },
    CommandEntry {
        name: "undo",
        call: "undo()",
        read: |_, _, _| Ok(Command::Undo),
    },
    CommandEntry {
        name: "redo",
        call: "redo()",
        read: |_, _, _| Ok(Command::Redo),
    },
    CommandEntry {
        name: "compactIds",
        call: "compactIds()",
        read: |_, _, _| Ok(Command::CompactIds),
    },
    CommandEntry {
        name: "addRow",
        call: "addRow(kind)",
        read: |call, kind, _| Ok(Command::AddRow(read_kind(call, kind)?)),
    },
    CommandEntry {
        name: "deleteRow",
        call: "deleteRow(kind, id)",
        read: |call, kind, id| Ok(Command::DeleteRow(read_element(call, kind, id)?)),
    },
    CommandEntry {
        name: "setPosition",
        call: "setPosition(id, position)",
        read: read_set_position,
    },
    CommandEntry {
        name: "startExercise",
        call: "startExercise(exercise, options)",
        read: |call, exercise, options| {
            let exercise = text_argument(
                call,
                "exercise",
                exercise,
                crate::app::practice::MAX_EXERCISE_BYTES,
            )?;
            check_options(call, options, &["seed", "progress", "name"])?;
            let seed = option_whole_number(call, options, "seed")?;
            let progress = option_text(call, options, "progress", MAX_PROGRESS_CHARS)?;
            if seed.is_some() && progress.is_some() {
                return Err(format!(
                    "{call}: give options.seed or options.progress, not both (a saved attempt has its seed)"
                ));
            }
            let name = option_string(call, options, "name")?;
            if let Some(name) = &name
                && !name
                    .chars()
                    .all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_')
            {
                return Err(format!(
                    "{call}: options.name {name:?} may hold only letters, digits, '-' and '_'"
                ));
            }
            Ok(Command::StartExercise {
                exercise,
                seed,
                progress,
                name,
            })
        },
    },
    CommandEntry {
        name: "answerExercise",
        call: "answerExercise(kind, id)",
        read: |call, kind, id| {
            if kind.is_null() {
                return Ok(Command::AnswerExercise(None));
            }
            Ok(Command::AnswerExercise(Some(read_element(call, kind, id)?)))
        },
    },
    CommandEntry {
        name: "submitExercise",
        call: "submitExercise()",
        read: |_, _, _| Ok(Command::SubmitExercise),
    },
    CommandEntry {
        name: "showModelAnswer",
        call: "showModelAnswer()",
        read: |_, _, _| Ok(Command::ShowModelAnswer),
    },
    CommandEntry {
        name: "newInstance",
        call: "newInstance()",
        read: |_, _, _| Ok(Command::NewInstance),
    },
    CommandEntry {
        name: "endExercise",
        call: "endExercise()",
        read: |_, _, _| Ok(Command::EndExercise),
    },
    CommandEntry {
        name: "newTab",
        call: "newTab()",
        read: |_, _, _| Ok(Command::NewTab),
    },
    CommandEntry {
        name: "switchTab",
        call: "switchTab(index)",
        read: |call, index, _| Ok(Command::SwitchTab(count(call, "index", index, None)?)),
    },
    CommandEntry {
        name: "closeTab",
        call: "closeTab(index)",
        read: |call, index, _| Ok(Command::CloseTab(count(call, "index", index, None)?)),
    },
    CommandEntry {
        name: "setSideBySide",
        call: "setSideBySide(on)",
        read: |call, on, _| {
            let on = on
                .as_bool()
                .ok_or_else(|| expected(call, "on", "true or false", on))?;
            Ok(Command::SetSideBySide(on))
        },
    },
];

/// A query of the API: its name and how it answers.
struct QueryEntry {
    name: &'static str,
    answer: fn(&eframe::WebRunner, &JsValue, &JsValue) -> Result<JsValue, JsValue>,
}

/// Every query.
const QUERIES: &[QueryEntry] = &[
    QueryEntry {
        name: "state",
        answer: |runner, _, _| json(runner, |app| serde_json::to_string(&app.state())),
    },
    QueryEntry {
        name: "exerciseProgress",
        answer: |runner, _, _| {
            with_app(runner, |app| app.exercise_progress())
                .map(|progress| progress.map_or(JsValue::NULL, |p| JsValue::from_str(&p)))
        },
    },
    QueryEntry {
        name: "algorithms",
        answer: |runner, _, _| json(runner, |app| serde_json::to_string(&app.algorithm_list())),
    },
    QueryEntry {
        name: "shareUrl",
        answer: |runner, _, _| {
            let base = crate::platform::page_base();
            with_app(runner, |app| app.share_url(&base))?
                .map(|url| JsValue::from_str(&url))
                .map_err(|message| JsValue::from(js_sys::Error::new(&message)))
        },
    },
    QueryEntry {
        name: "settled",
        answer: |runner, timeout, _| {
            let call = "settled(timeoutMs)";
            Ok(
                match count(call, "timeoutMs", timeout, Some(SETTLE_TIMEOUT_MS)) {
                    Ok(timeout) => until_settled(runner.clone(), timeout),
                    Err(message) => settle(Err(message)),
                }
                .into(),
            )
        },
    },
    QueryEntry {
        name: "exportMesh",
        answer: |runner, format, _| Ok(export(runner, format).into()),
    },
    QueryEntry {
        name: "exportPackage",
        answer: |runner, version, _| Ok(export_package(runner, version).into()),
    },
    QueryEntry {
        name: "exportHandout",
        answer: |runner, _, _| {
            let result = with_app(runner, |app| app.export_handout())
                .map_err(|err| js_error_text(&err))
                .and_then(|handout| handout.map_err(String::from))
                .and_then(|(name, bytes)| {
                    exported_object(&SavedFile { name, bytes }, true)
                        .map_err(|err| js_error_text(&err))
                });
            Ok(settle_with(result).into())
        },
    },
    QueryEntry {
        name: "recordRun",
        answer: |runner, options, _| Ok(super::recording::record_run(runner, options).into()),
    },
    QueryEntry {
        name: "exportImage",
        answer: |runner, format, _| Ok(export_image(runner, format).into()),
    },
    QueryEntry {
        name: "screenPosition",
        answer: |runner, kind, id| {
            let element = read_element("screenPosition(kind, id)", kind, id)
                .map_err(|message| JsValue::from(js_sys::Error::new(&message)))?;
            let position = with_app(runner, |app| app.screen_position(element))?;
            json(runner, |_| serde_json::to_string(&position))
        },
    },
];

/// `edit(op, ids)`: an operation by its command-line name and its ids, an
/// array (or one id on its own).
fn read_edit(call: &'static str, op: &JsValue, ids: &JsValue) -> Result<Command, String> {
    let names: Vec<&str> = Operation::ALL.iter().map(|op| op.name()).collect();
    let wanted = format!("one of '{}'", names.join("', '"));
    let name = op
        .as_string()
        .filter(|name| name.len() <= MAX_NAME_CHARS)
        .ok_or_else(|| expected(call, "op", &wanted, op))?;
    // Exact, as every other name the API takes ('FLIP-EDGE' is refused).
    let operation = Operation::ALL
        .into_iter()
        .find(|operation| operation.name() == name)
        .ok_or_else(|| expected(call, "op", &wanted, op))?;
    let (values, count) = if is_array(ids) {
        items(call, "ids", ids, MAX_EDIT_IDS)?
    } else {
        (vec![ids.clone()], 1)
    };
    if count > MAX_EDIT_IDS {
        return Err(expected(call, "ids", "at most three ids", ids));
    }
    let ids = values
        .iter()
        .enumerate()
        .map(|(i, value)| {
            let id = whole_number(call, &format!("ids[{i}]"), value)?;
            u32::try_from(id).map_err(|_| format!("{call}: id {id} is larger than any element id"))
        })
        .collect::<Result<Vec<u32>, String>>()?;
    Ok(Command::Edit { operation, ids })
}

/// `setCell(kind, id, column, value)`: a record's reference set by hand;
/// `column` as the language names it, `value` an id or `null`.
fn read_set_cell(
    kind: &JsValue,
    id: &JsValue,
    column: &JsValue,
    value: &JsValue,
) -> Result<Command, String> {
    const CALL: &str = "setCell(kind, id, column, value)";
    let element = read_element(CALL, kind, id)?;
    let column = text_argument(CALL, "column", column, MAX_NAME_CHARS)?;
    let target = if value.is_null() {
        None
    } else {
        let target = whole_number(CALL, "value", value)
            .map_err(|_| expected(CALL, "value", "an id or null", value))?;
        Some(
            u32::try_from(target)
                .map_err(|_| format!("{CALL}: value {target} is larger than any element id"))?,
        )
    };
    Ok(Command::SetCell {
        element,
        column,
        target,
    })
}

/// `setPosition(id, [x, y, z])`: a vertex moved by hand.
fn read_set_position(
    call: &'static str,
    id: &JsValue,
    position: &JsValue,
) -> Result<Command, String> {
    let vertex = read_element(call, &"vertex".into(), id)?.id;
    if !is_array(position) {
        return Err(expected(call, "position", "an array [x, y, z]", position));
    }
    let (values, length) = items(call, "position", position, 3)?;
    let numbers: Vec<f32> = values
        .iter()
        .filter_map(JsValue::as_f64)
        .filter(|n| n.is_finite() && n.abs() <= f64::from(f32::MAX))
        .map(|n| n as f32)
        .collect();
    match numbers.as_slice() {
        [x, y, z] if length == 3 => Ok(Command::SetPosition {
            vertex,
            position: [*x, *y, *z],
        }),
        _ => Err(expected(
            call,
            "position",
            "three finite numbers [x, y, z]",
            position,
        )),
    }
}

/// An element named by its kind (`'vertex'`, `'edge'`, `'face'`) and id.
fn read_element(call: &str, kind: &JsValue, id: &JsValue) -> Result<ElementRef, String> {
    let kind = read_kind(call, kind)?;
    let id = whole_number(call, "id", id)?;
    let id =
        u32::try_from(id).map_err(|_| format!("{call}: id {id} is larger than any element id"))?;
    Ok(ElementRef::new(kind, id))
}

/// An element kind: `'vertex'`, `'edge'` or `'face'`.
fn read_kind(call: &str, kind: &JsValue) -> Result<ElementKind, String> {
    kind.as_string()
        .and_then(|k| ElementKind::parse(&k))
        .ok_or_else(|| expected(call, "kind", "'vertex', 'edge' or 'face'", kind))
}

/// `answer(kind, id)` for an element, `answer(null)`, `answer(true)` or
/// `answer(4)`.
fn read_answer(call: &'static str, value: &JsValue, id: &JsValue) -> Result<Command, String> {
    let given = if value.is_null() {
        Value::Null
    } else if let Some(b) = value.as_bool() {
        Value::Boolean(b)
    } else if let Some(n) = value.as_f64() {
        if !n.is_finite() || n.abs() > f64::from(f32::MAX) {
            return Err(expected(call, "value", "a finite number", value));
        }
        edgewise_model::algorithm::quiz::number_value(n as f32)
    } else if value.is_string() {
        read_element(call, value, id)?.into()
    } else {
        return Err(expected(
            call,
            "value",
            "'vertex', 'edge' or 'face' with an id, null, true, false or a number",
            value,
        ));
    };
    Ok(Command::Answer(given))
}

/// The longest saved attempt `startExercise` takes: SCORM 2004's
/// `suspend_data` holds 64,000 characters.
const MAX_PROGRESS_CHARS: usize = 64_000;

/// The most ids an operation takes (MEKR: a face and two vertices).
const MAX_EDIT_IDS: usize = 3;

/// `loadMesh(text, options)`: the text and how to read it.
fn read_load_mesh(
    call: &'static str,
    text: &JsValue,
    options: &JsValue,
) -> Result<Command, String> {
    let text = text_argument(call, "text", text, MAX_FILE_BYTES)?;
    check_options(call, options, &["format", "structure", "diagnose"])?;
    let format = option_string(call, options, "format")?;
    if let Some(format) = &format
        && Format::from_name(&format!("x.{format}")).is_none()
    {
        return Err(format!(
            "{call}: options.format must be 'obj', 'ply', 'wtb' or 'htb', not '{}'",
            shown(format)
        ));
    }
    let structure = structure_option(call, options)?;
    // Without a format the content decides (a pasted file has no name).
    let name = format.map_or_else(|| "pasted".to_owned(), |f| format!("pasted.{f}"));
    let diagnose = option_bool(call, options, "diagnose")?.unwrap_or(false);
    Ok(Command::LoadMesh {
        bytes: text.into_bytes(),
        name,
        structure,
        diagnose,
    })
}

/// A structure's link name (`'winged'`, `'half'`, …), if `value` is one.
fn structure_name(value: &JsValue) -> Option<Structure> {
    value
        .as_string()
        .and_then(|name| Structure::parse_link_name(&name))
}

/// A count or index argument; `default` when it is left out, if it may be.
fn count(
    call: &str,
    argument: &str,
    value: &JsValue,
    default: Option<u64>,
) -> Result<usize, String> {
    let n = match default {
        Some(default) if value.is_undefined() => default,
        _ => whole_number(call, argument, value)?,
    };
    Ok(usize::try_from(n).unwrap_or(usize::MAX))
}

/// Defines `window.edgewise` from [`COMMANDS`] and [`QUERIES`].
pub(super) fn install(runner: &eframe::WebRunner) -> Result<(), JsValue> {
    let window = web_sys::window().ok_or("no window")?;
    let api = js_sys::Object::new();
    let backend = with_app(runner, |app| app.backend().as_str())?;
    js_sys::Reflect::set(&api, &"version".into(), &edgewise_core::VERSION.into())?;
    js_sys::Reflect::set(&api, &"backend".into(), &backend.into())?;
    for entry in COMMANDS {
        let runner = runner.clone();
        let function = Closure::<dyn Fn(JsValue, JsValue) -> js_sys::Promise>::new(
            move |first: JsValue, second: JsValue| match (entry.read)(entry.call, &first, &second) {
                Ok(command) => perform(&runner, command),
                Err(message) => settle(Err(message)),
            },
        );
        set_fn(&api, entry.name, &function.into_js_value())?;
    }
    // setCell takes four arguments; every other command two at most.
    let set_cell = {
        let runner = runner.clone();
        Closure::<dyn Fn(JsValue, JsValue, JsValue, JsValue) -> js_sys::Promise>::new(
            move |kind: JsValue, id: JsValue, column: JsValue, value: JsValue| match read_set_cell(
                &kind, &id, &column, &value,
            ) {
                Ok(command) => perform(&runner, command),
                Err(message) => settle(Err(message)),
            },
        )
    };
    set_fn(&api, "setCell", &set_cell.into_js_value())?;
    for entry in QUERIES {
        let runner = runner.clone();
        let function = Closure::<dyn Fn(JsValue, JsValue) -> Result<JsValue, JsValue>>::new(
            move |first: JsValue, second: JsValue| (entry.answer)(&runner, &first, &second),
        );
        set_fn(&api, entry.name, &function.into_js_value())?;
    }
    js_sys::Reflect::set(&window, &"edgewise".into(), &api)?;
    Ok(())
}

/// Carries out a command and settles its Promise. A large `loadMesh` text
/// first shows that it is being opened, and is read once that has been
/// painted, since reading it blocks the page.
fn perform(runner: &eframe::WebRunner, command: Command) -> js_sys::Promise {
    let large = matches!(&command, Command::LoadMesh { bytes, .. } if bytes.len() > ANNOUNCE_BYTES);
    if !large {
        let before = with_app(runner, |app| app.pending_job()).ok().flatten();
        let result = execute(runner, command);
        let started = with_app(runner, |app| app.pending_job()).ok().flatten();
        return match (result, started) {
            (Ok(()), Some(job)) if started != before => until_shown(runner.clone(), job),
            (result, _) => settle(result),
        };
    }
    let label = match &command {
        Command::LoadMesh { bytes, .. } => opening_label("the text", bytes.len()),
        _ => String::new(),
    };
    if let Err(message) = with_app(runner, |app| super::set_busy(app, Some(label))) {
        return settle(Err(js_error_text(&message)));
    }
    let runner = runner.clone();
    wasm_bindgen_futures::future_to_promise(async move {
        after_a_paint().await;
        let _shown = with_app(&runner, |app| super::set_busy(app, None));
        execute(&runner, command)
            .map(|()| JsValue::NULL)
            .map_err(|message| js_sys::Error::new(&message).into())
    })
}

/// Settles once the large mesh of job `job` is shown (a slice per frame),
/// or fails if it was cancelled or replaced.
fn until_shown(runner: eframe::WebRunner, job: u64) -> js_sys::Promise {
    wasm_bindgen_futures::future_to_promise(async move {
        loop {
            after_ms(16).await;
            match with_app(&runner, |app| app.job_outcome(job))? {
                None => {}
                Some(Ok(())) => return Ok(JsValue::NULL),
                Some(Err(why)) => return Err(js_sys::Error::new(&why).into()),
            }
        }
    })
}

/// How long `settled()` waits by default: a slow software-rendered frame
/// takes under a second, so a view still asking for frames after this is
/// animating without end.
const SETTLE_TIMEOUT_MS: u64 = 10_000;

/// Resolves to the number of frames drawn once the view has settled
/// ([`EdgewiseApp::settled`]) and the next animation frame drew nothing:
/// eframe paints for input (a key, a click) in its own animation-frame
/// callback, which runs before this one, so input already delivered has
/// been drawn. Rejects, naming what keeps asking for frames, after
/// `timeout_ms`; a hidden page, which runs no animation frames, settles
/// only once shown.
fn until_settled(runner: eframe::WebRunner, timeout_ms: usize) -> js_sys::Promise {
    wasm_bindgen_futures::future_to_promise(async move {
        let start = js_sys::Date::now();
        let mut last = None;
        loop {
            let (settled, frames) = with_app(&runner, |app| (app.settled(), app.frame_count()))?;
            if settled && last == Some(frames) {
                return Ok(JsValue::from_f64(frames as f64));
            }
            let waited = js_sys::Date::now() - start;
            if waited > timeout_ms as f64 {
                let causes = with_app(&runner, |app| app.repaint_causes())?;
                return Err(js_sys::Error::new(&format!(
                    "the view did not settle within {timeout_ms} ms: it kept asking for frames ({causes})"
                ))
                .into());
            }
            let in_a_frame =
                next_frame_within((timeout_ms as f64 - waited).max(0.0) as i32 + 1).await;
            // Only a look from inside an animation frame counts as the second.
            last = (settled && in_a_frame).then_some(frames);
        }
    })
}

/// Resolves `true` in the next animation frame, or `false` after `ms` if
/// none came first (a hidden page runs none). The frame clears the timer,
/// so a long wait, a look a frame, leaves no timers behind.
async fn next_frame_within(ms: i32) -> bool {
    let promise = js_sys::Promise::new(&mut |resolve, _reject| {
        let Some(window) = web_sys::window() else {
            let _resolved = resolve.call1(&JsValue::NULL, &JsValue::FALSE);
            return;
        };
        let timer = window.set_timeout_with_callback_and_timeout_and_arguments_1(
            &resolve,
            ms,
            &JsValue::FALSE,
        );
        let in_frame = {
            let (resolve, window, timer) = (resolve.clone(), window.clone(), timer.clone());
            Closure::once_into_js(move || {
                if let Ok(timer) = timer {
                    window.clear_timeout_with_handle(timer);
                }
                let _resolved = resolve.call1(&JsValue::NULL, &JsValue::TRUE);
            })
        };
        let frame = window.request_animation_frame(in_frame.unchecked_ref());
        if frame.is_err() && timer.is_err() {
            let _resolved = resolve.call1(&JsValue::NULL, &JsValue::FALSE);
        }
    });
    wasm_bindgen_futures::JsFuture::from(promise)
        .await
        .ok()
        .and_then(|value| value.as_bool())
        .unwrap_or(false)
}

/// Runs a command on the app; the app records a refusal and asks for a frame.
fn execute(runner: &eframe::WebRunner, command: Command) -> Result<(), String> {
    with_app(runner, |app| app.execute(command))
        .map_err(|err| js_error_text(&err))?
        .map(drop)
        .map_err(String::from)
}

/// A query's answer serialized by the app, as a JavaScript value.
fn json(
    runner: &eframe::WebRunner,
    serialize: impl FnOnce(&EdgewiseApp) -> serde_json::Result<String>,
) -> Result<JsValue, JsValue> {
    let text = with_app(runner, |app| serialize(app))?
        .map_err(|err| JsValue::from_str(&err.to_string()))?;
    js_sys::JSON::parse(&text)
}

/// `exportMesh(format)`: the open mesh written as `format`.
fn export(runner: &eframe::WebRunner, format: &JsValue) -> js_sys::Promise {
    let result = (|| {
        let format = format
            .as_string()
            .and_then(|f| SaveFormat::parse(&f))
            .ok_or_else(|| {
                expected(
                    "exportMesh(format)",
                    "format",
                    "'wtb', 'htb', 'ply', 'ply-binary' or 'obj'",
                    format,
                )
            })?;
        let saved =
            with_app(runner, |app| app.export(format)).map_err(|err| js_error_text(&err))??;
        exported_object(&saved, format.is_binary()).map_err(|err| js_error_text(&err))
    })();
    settle_with(result)
}

/// `exportPackage(version)`: the SCORM package (`'1.2'` or `'2004'`) of
/// the exercise or the view on screen, as the Share window downloads it:
/// a Promise of `{name, base64}`.
fn export_package(runner: &eframe::WebRunner, version: &JsValue) -> js_sys::Promise {
    const CALL: &str = "exportPackage(version)";
    let prepared = version
        .as_string()
        .and_then(|v| edgewise_model::package::Scorm::parse(&v))
        .ok_or_else(|| expected(CALL, "version", "'1.2' or '2004'", version))
        .and_then(|scorm| {
            with_app(runner, |app| app.scorm_package(scorm)).map_err(|err| js_error_text(&err))?
        });
    match prepared {
        Err(message) => settle_with(Err(message)),
        Ok((name, package)) => wasm_bindgen_futures::future_to_promise(async move {
            let bytes = crate::platform::package_zip(&package)
                .await
                .map_err(|message| JsValue::from(js_sys::Error::new(&message)))?;
            exported_object(&SavedFile { name, bytes }, true)
        }),
    }
}

/// `exportImage(format)`: `'svg'` resolves to the SVG text of the view
/// and its tables; `'png'` to a `data:image/png` URL of the next frame.
fn export_image(runner: &eframe::WebRunner, format: &JsValue) -> js_sys::Promise {
    const CALL: &str = "exportImage(format)";
    match format.as_string().as_deref() {
        Some("svg") => settle_with(
            with_app(runner, |app| app.export_svg())
                .map_err(|err| js_error_text(&err))
                .and_then(|svg| svg.map(JsValue::from).map_err(String::from)),
        ),
        Some("png") => {
            if let Err(err) = with_app(runner, EdgewiseApp::request_screenshot) {
                return settle(Err(js_error_text(&err)));
            }
            let runner = runner.clone();
            wasm_bindgen_futures::future_to_promise(async move {
                // The screenshot comes with the next frame drawn.
                for _ in 0..300 {
                    after_ms(16).await;
                    if let Some(image) = with_app(&runner, EdgewiseApp::take_screenshot)? {
                        return png_data_url(&image);
                    }
                }
                Err(js_sys::Error::new(&format!(
                    "{CALL}: no frame was drawn within 5 seconds; is the page hidden?"
                ))
                .into())
            })
        }
        _ => settle(Err(expected(CALL, "format", "'png' or 'svg'", format))),
    }
}

/// The image as a PNG data URL, encoded by the browser through a canvas.
fn png_data_url(image: &egui::ColorImage) -> Result<JsValue, JsValue> {
    let [width, height] = image.size.map(|n| n as u32);
    let document = web_sys::window()
        .and_then(|window| window.document())
        .ok_or("exportImage: no document")?;
    let canvas: web_sys::HtmlCanvasElement = document
        .create_element("canvas")?
        .dyn_into()
        .map_err(|_| JsValue::from("exportImage: no canvas"))?;
    canvas.set_width(width);
    canvas.set_height(height);
    let context: web_sys::CanvasRenderingContext2d = canvas
        .get_context("2d")?
        .ok_or("exportImage: no 2D context")?
        .dyn_into()
        .map_err(|_| JsValue::from("exportImage: no 2D context"))?;
    let rgba: Vec<u8> = image
        .pixels
        .iter()
        .flat_map(egui::Color32::to_srgba_unmultiplied)
        .collect();
    let data = web_sys::ImageData::new_with_u8_clamped_array_and_sh(
        wasm_bindgen::Clamped(&rgba),
        width,
        height,
    )?;
    context.put_image_data(&data, 0.0, 0.0)?;
    Ok(canvas.to_data_url_with_type("image/png")?.into())
}

/// Puts a function on the API object. The API lives as long as the page, so
/// closures are handed to JavaScript for good.
fn set_fn(api: &js_sys::Object, name: &str, function: &JsValue) -> Result<(), JsValue> {
    js_sys::Reflect::set(api, &name.into(), function).map(|_| ())
}

/// A command's Promise: resolves to null on success, rejects with an Error.
fn settle(result: Result<(), String>) -> js_sys::Promise {
    settle_with(result.map(|()| JsValue::NULL))
}

/// A command's Promise: resolves to the value, or rejects with an Error.
fn settle_with(result: Result<JsValue, String>) -> js_sys::Promise {
    match result {
        Ok(value) => js_sys::Promise::resolve(&value),
        Err(message) => js_sys::Promise::reject(&js_sys::Error::new(&message)),
    }
}
