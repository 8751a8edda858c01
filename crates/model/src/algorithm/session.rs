//! A run of one algorithm: first its inputs are picked, then its recorded
//! trace is walked step by step, forwards and back, with breakpoints and
//! auto-play. The whole trace is recorded when the inputs are complete, so
//! stepping back costs no more than stepping forward.

use edgewise_core::schema::{ElementKind, ElementRef};
use std::collections::BTreeSet;
use std::sync::Arc;

use edgewise_core::{
    lang::{self, Algorithm, RunOptions, Trace, Type, Value, compiler::VariableInfo},
    mesh::Mesh,
};

/// An algorithm waiting for its inputs.
#[derive(Clone, Debug)]
pub struct PendingRun {
    pub algorithm: Arc<Algorithm>,
    /// Values given so far, by parameter name. Integer and Boolean
    /// parameters start with their default so the panel can edit them.
    pub inputs: Vec<(String, Value)>,
}

impl PendingRun {
    pub fn new(algorithm: Arc<Algorithm>) -> Self {
        let inputs = algorithm
            .params()
            .filter(|p| p.ty.element_kind().is_none())
            .map(|p| (p.name.clone(), p.ty.default_value()))
            .collect();
        Self { algorithm, inputs }
    }

    /// The first element parameter still without a value.
    pub fn missing(&self) -> Option<&VariableInfo> {
        self.algorithm
            .params()
            .find(|p| !self.inputs.iter().any(|(name, _)| *name == p.name))
    }

    /// The kind of element the next pick gives, if one is needed.
    pub fn wanted_kind(&self) -> Option<ElementKind> {
        self.missing().and_then(|p| p.ty.element_kind())
    }

    /// "Pick a Vertex for v", or None when every input is given.
    pub fn prompt(&self) -> Option<String> {
        self.missing()
            .map(|p| format!("{}: pick a {} for {}", self.algorithm.name, p.ty, p.name))
    }

    /// Gives the next missing element parameter the picked element; a pick of
    /// another kind is refused with a reason.
    pub fn pick(&mut self, element: ElementRef) -> Result<(), String> {
        let Some(param) = self.missing() else {
            return Err("every input is already given".to_owned());
        };
        let wanted = param.ty.element_kind();
        if wanted != Some(element.kind) {
            return Err(format!(
                "{} needs a {} for {}, not a {}",
                self.algorithm.name,
                param.ty,
                param.name,
                element.kind.prose()
            ));
        }
        let name = param.name.clone();
        self.inputs.push((name, Value::from(element)));
        Ok(())
    }

    /// Sets a parameter by name (the JavaScript API's `run(name, args)` and
    /// the panel's Integer and Boolean fields).
    pub fn set(&mut self, name: &str, value: Value) {
        match self.inputs.iter_mut().find(|(n, _)| n == name) {
            Some(slot) => slot.1 = value,
            None => self.inputs.push((name.to_owned(), value)),
        }
    }

    /// Whether any parameter is an Integer or a Boolean, which the panel
    /// shows as fields with a Start button rather than starting at once.
    pub fn has_scalar_inputs(&self) -> bool {
        self.algorithm
            .params()
            .any(|p| p.ty.element_kind().is_none())
    }

    /// Records the whole run on `mesh`. Input errors (a wrong structure, an
    /// id the mesh lacks) come back as messages. An algorithm that changes
    /// the mesh runs on a copy; the trace's changes then move the shown mesh
    /// step by step ([`TraceSession::changes_wanted`]).
    pub fn start(&self, mesh: &Mesh) -> Result<TraceSession, String> {
        let inputs: Vec<(&str, Value)> = self
            .inputs
            .iter()
            .map(|(name, value)| (name.as_str(), *value))
            .collect();
        let trace = if self.algorithm.edits() {
            let mut copy = mesh.clone();
            lang::run_editing(&self.algorithm, &mut copy, &inputs, RunOptions::default())
        } else {
            lang::run(&self.algorithm, mesh, &inputs, RunOptions::default())
        };
        Ok(TraceSession::new(trace.map_err(|err| err.to_string())?))
    }
}

/// A recorded trace and where the user is in it.
#[derive(Debug)]
pub struct TraceSession {
    pub trace: Trace,
    /// From 0 to `trace.len()`; see [`super::frame`].
    step: usize,
    pub playing: bool,
    /// egui time of the last automatic step.
    pub last_auto_step: f64,
    /// The run's questions, posed once the app has its question sets.
    pub quiz: Option<super::quiz::Quiz>,
}

impl TraceSession {
    pub fn new(trace: Trace) -> Self {
        Self {
            trace,
            step: 0,
            playing: false,
            last_auto_step: 0.0,
            quiz: None,
        }
    }

    pub fn step(&self) -> usize {
        self.step
    }

    /// How deep in calls the current step is (0 in the started algorithm).
    pub fn depth(&self) -> usize {
        self.step
            .checked_sub(1)
            .and_then(|index| self.trace.depth(index))
            .unwrap_or(0)
    }

    /// Runs the call on the next step as one step: to the next step no
    /// deeper than the current one (or the end).
    pub fn step_over(&mut self) {
        let target = match self.step.checked_sub(1) {
            None => 1,
            Some(index) => self.trace.step_over(index).map_or(self.steps(), |i| i + 1),
        };
        self.goto(target);
    }

    /// Runs to the step after the current call returns; refused outside
    /// calls.
    pub fn step_out(&mut self) -> Result<(), String> {
        let index = self
            .step
            .checked_sub(1)
            .ok_or("the algorithm has not started; there is no call to step out of")?;
        let target = self
            .trace
            .step_out(index)
            .map(|i| i + 1)
            .ok_or("this step is not inside a call; there is nothing to step out of")?;
        self.goto(target);
        Ok(())
    }

    /// Whether the algorithm changes the mesh.
    pub fn edits(&self) -> bool {
        self.trace.algorithm().edits()
    }

    /// How many of the trace's changes the mesh shows at the current step.
    pub fn changes_wanted(&self) -> usize {
        self.trace.changes_through(self.step.checked_sub(1))
    }

    /// The number of operations; the last step number.
    pub fn steps(&self) -> usize {
        self.trace.len()
    }

    pub fn at_end(&self) -> bool {
        self.step >= self.steps()
    }

    /// Moves to step `k`, clamped to the trace.
    pub fn goto(&mut self, k: usize) {
        self.step = k.min(self.steps());
        if self.at_end() {
            self.playing = false;
        }
    }

    pub fn forward(&mut self, n: usize) {
        self.goto(self.step.saturating_add(n));
    }

    pub fn back(&mut self, n: usize) {
        self.goto(self.step.saturating_sub(n));
    }

    /// The source line shown at step `k` (0 has none).
    fn line_at(&self, k: usize) -> Option<u32> {
        k.checked_sub(1).and_then(|index| self.trace.line(index))
    }

    /// The next step after the current one whose line has a breakpoint, or
    /// the end.
    pub fn next_breakpoint(&self, breakpoints: &BTreeSet<u32>) -> usize {
        breakpoints
            .iter()
            .filter_map(|&line| self.trace.next_on_line(self.step.saturating_sub(1), line))
            .map(|index| index + 1)
            .filter(|&k| k > self.step)
            .min()
            .unwrap_or(self.steps())
    }

    /// The last step before the current one whose line has a breakpoint, or
    /// the start.
    pub fn previous_breakpoint(&self, breakpoints: &BTreeSet<u32>) -> usize {
        breakpoints
            .iter()
            .filter_map(|&line| {
                self.trace
                    .previous_on_line(self.step.saturating_sub(1), line)
            })
            .map(|index| index + 1)
            .filter(|&k| k < self.step)
            .max()
            .unwrap_or(0)
    }

    /// One automatic step; stops playing at a breakpoint, a question not
    /// yet answered, or the end.
    pub fn auto_step(&mut self, breakpoints: &BTreeSet<u32>) {
        self.forward(1);
        let at_breakpoint = self
            .line_at(self.step)
            .is_some_and(|line| breakpoints.contains(&line));
        let asked = self
            .quiz
            .as_ref()
            .is_some_and(|quiz| quiz.stops_at(self.step));
        if at_breakpoint || asked {
            self.playing = false;
        }
    }
}

/// What the algorithm panel is doing.
#[derive(Debug, Default)]
pub enum Run {
    #[default]
    Idle,
    Picking(PendingRun),
    Tracing(Box<TraceSession>),
}

/// One argument of `run(name, args)` as JavaScript or a URL gives it.
#[derive(Clone, Debug, PartialEq)]
pub enum Argument {
    Number(f64),
    Boolean(bool),
}

impl Argument {
    /// Reads `true`, `false` or a finite number, as links and the command
    /// line write an input.
    pub fn parse(text: &str) -> Option<Self> {
        match text {
            "true" => Some(Self::Boolean(true)),
            "false" => Some(Self::Boolean(false)),
            // Rust also reads "inf" and "NaN"; no input has a use for them.
            _ => text
                .parse::<f64>()
                .ok()
                .filter(|x| x.is_finite())
                .map(Self::Number),
        }
    }
}

/// The inputs `args` give `algorithm`, each read for its parameter's type;
/// a name it does not have, or a value that does not fit, is refused with
/// the parameters or the type it wants.
pub fn argument_inputs(
    algorithm: &Algorithm,
    args: &[(String, Argument)],
) -> Result<Vec<(String, Value)>, String> {
    let mut inputs = Vec::with_capacity(args.len());
    for (arg_name, arg) in args {
        let Some(param) = algorithm.params().find(|p| p.name == *arg_name) else {
            let names: Vec<&str> = algorithm.params().map(|p| p.name.as_str()).collect();
            return Err(format!(
                "{} has no parameter `{arg_name}` (its parameters: {})",
                algorithm.name,
                names.join(", ")
            ));
        };
        let (number, boolean) = match arg {
            Argument::Number(n) => (Some(*n), None),
            Argument::Boolean(b) => (None, Some(*b)),
        };
        let Some(value) = argument_value(param.ty, number, boolean) else {
            let what = match arg {
                Argument::Number(n) => n.to_string(),
                Argument::Boolean(b) => b.to_string(),
            };
            return Err(format!(
                "parameter `{arg_name}` of {} is {}, which `{what}` is not",
                algorithm.name,
                type_phrase(param.ty)
            ));
        };
        inputs.push((arg_name.clone(), value));
    }
    Ok(inputs)
}

/// "a Vertex id", "an Integer", "true or false".
fn type_phrase(ty: Type) -> &'static str {
    match ty {
        Type::Vertex => "a Vertex id",
        Type::Edge => "an Edge id",
        Type::Face => "a Face id",
        Type::Integer => "an Integer",
        Type::Boolean => "true or false",
        Type::Float => "a number",
        Type::Vector => "a Vector",
        Type::Null => "null",
        Type::Array(_) => "nothing: an array starts empty",
    }
}

/// Reads a JavaScript or URL argument for parameter type `ty`: an element
/// id, an integer, a number, or true/false.
pub fn argument_value(ty: Type, number: Option<f64>, boolean: Option<bool>) -> Option<Value> {
    match (ty, number, boolean) {
        (Type::Boolean, _, Some(b)) => Some(Value::Boolean(b)),
        (Type::Float, Some(n), _) if n.is_finite() && n.abs() <= f64::from(f32::MAX) => {
            Some(Value::Float(n as f32))
        }
        (ty, Some(n), _) if n.fract() == 0.0 => {
            let kind = ty.element_kind();
            match kind {
                Some(kind) if n >= 0.0 && n <= f64::from(u32::MAX) => {
                    Some(Value::from(ElementRef::new(kind, n as u32)))
                }
                None if ty == Type::Integer
                    && n >= f64::from(i32::MIN)
                    && n <= f64::from(i32::MAX) =>
                {
                    Some(Value::Integer(n as i32))
                }
                _ => None,
            }
        }
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use edgewise_core::{mesh::generate, schema::Structure};

    use super::*;
    use crate::algorithm::library::AlgorithmLibrary;

    /// The sample tetrahedron: the journal's Table 2 as printed.
    fn tetrahedron() -> Mesh {
        Mesh::Winged(generate::table_2())
    }

    #[test]
    fn picking_checks_the_kind_then_starts() {
        let library = AlgorithmLibrary::shipped();
        let algorithm = library
            .find("vertexAdjacentEdge", Structure::WingedEdge)
            .expect("shipped");
        let mut pending = PendingRun::new(Arc::clone(algorithm));
        assert_eq!(pending.wanted_kind(), Some(ElementKind::Vertex));
        assert_eq!(
            pending.prompt().as_deref(),
            Some("vertexAdjacentEdge: pick a Vertex for v")
        );
        let err = pending
            .pick(ElementRef {
                kind: ElementKind::Face,
                id: 0,
            })
            .expect_err("a face is not a vertex");
        assert_eq!(err, "vertexAdjacentEdge needs a Vertex for v, not a face");
        pending
            .pick(ElementRef {
                kind: ElementKind::Vertex,
                id: 1,
            })
            .expect("a vertex");
        assert!(pending.prompt().is_none());
        let mesh = tetrahedron();
        let mut session = pending.start(&mesh).expect("runs");
        assert_eq!(session.step(), 0);
        assert!(session.steps() > 10);
        session.forward(1000);
        assert!(session.at_end());
        session.back(3);
        assert_eq!(session.step(), session.steps() - 3);
    }

    #[test]
    fn breakpoints_stop_play_and_jump() {
        let library = AlgorithmLibrary::shipped();
        let algorithm = library
            .find("vertexAdjacentEdge", Structure::WingedEdge)
            .expect("shipped");
        let mut pending = PendingRun::new(Arc::clone(algorithm));
        pending.set("v", Value::Vertex(0));
        let mesh = tetrahedron();
        let mut session = pending.start(&mesh).expect("runs");
        // The `e.mark` line of the shipped algorithm.
        let mark_line = (0..session.steps())
            .find_map(|i| {
                let view = session.trace.step(i)?;
                matches!(view.kind, lang::StepKind::Mark { .. }).then_some(view.line)
            })
            .expect("the algorithm marks");
        let breakpoints = BTreeSet::from([mark_line]);
        let first = session.next_breakpoint(&breakpoints);
        assert_eq!(session.trace.line(first - 1), Some(mark_line));
        session.playing = true;
        while session.playing {
            session.auto_step(&breakpoints);
        }
        assert_eq!(session.step(), first, "play pauses on the breakpoint");
        let second = session.next_breakpoint(&breakpoints);
        assert!(second > first);
        session.goto(second);
        assert_eq!(session.previous_breakpoint(&breakpoints), first);
    }

    #[test]
    fn arguments_are_read_by_parameter_type() {
        assert_eq!(
            argument_value(Type::Vertex, Some(3.0), None),
            Some(Value::Vertex(3))
        );
        assert_eq!(
            argument_value(Type::Integer, Some(-2.0), None),
            Some(Value::Integer(-2))
        );
        assert_eq!(
            argument_value(Type::Boolean, None, Some(true)),
            Some(Value::Boolean(true))
        );
        assert_eq!(argument_value(Type::Edge, Some(1.5), None), None);
        assert_eq!(argument_value(Type::Face, Some(-1.0), None), None);
    }
}
