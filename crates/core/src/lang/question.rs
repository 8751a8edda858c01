//! Stop-and-think questions: a prompt attached to a source line or a step,
//! asked before the line runs and answered from the recorded trace.
//!
//! A question on a line is asked the first time the line runs, at the step
//! before its first operation, so the student predicts what the line will
//! do. Its answer is the line's outcome in that run: the last value its
//! operations (and the calls they make) produced (what `e := e.successorEdge` assigns, whether
//! `e <> se` holds, which edge `e.mark` marks). A question on step `k` is
//! asked at step `k − 1` and answered by step `k`'s own outcome.
//!
//! Questions come from `//?` comments, which attach to the next line with
//! code, and from question sets ([`parse_set`]): lines of `line 7: prompt`
//! or `step 12: prompt`, carried by a course link or given through the
//! JavaScript API. The expected answer is never written down, so it cannot
//! disagree with what the algorithm does.

use std::fmt;

use super::compiler::Routine;
use super::trace::Trace;
use super::types::Value;

/// The most questions one algorithm or set may hold.
pub const MAX_QUESTIONS: usize = 100;
/// The longest prompt, in characters.
pub const MAX_PROMPT_CHARS: usize = 300;
/// The longest question set, in bytes.
pub const MAX_SET_BYTES: usize = 64 * 1024;
/// The comment that starts a question in algorithm source.
pub const COMMENT: &str = "//?";

/// Where a question is asked.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum QuestionAt {
    /// Before the first run of a 1-based source line of the file.
    Line(u32),
    /// Before a 1-based step of the trace.
    Step(usize),
}

impl fmt::Display for QuestionAt {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            QuestionAt::Line(line) => write!(f, "line {line}"),
            QuestionAt::Step(step) => write!(f, "step {step}"),
        }
    }
}

#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Question {
    pub at: QuestionAt,
    pub prompt: String,
}

/// A line of a question set that could not be read, with its 1-based line
/// and column in the set's text.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct QuestionSetError {
    pub line: usize,
    pub column: usize,
    pub message: String,
}

impl fmt::Display for QuestionSetError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}: {}", self.line, self.column, self.message)
    }
}

impl std::error::Error for QuestionSetError {}

/// Reads a question set: one `line N: prompt` or `step N: prompt` per line;
/// blank lines and lines starting with `#` are skipped.
pub fn parse_set(text: &str) -> Result<Vec<Question>, QuestionSetError> {
    if text.len() > MAX_SET_BYTES {
        return Err(QuestionSetError {
            line: 1,
            column: 1,
            message: format!("the set is {} bytes; at most {MAX_SET_BYTES}", text.len()),
        });
    }
    let mut questions = Vec::new();
    for (number, raw) in text.lines().enumerate() {
        let line = number + 1;
        let indent = raw.len() - raw.trim_start().len();
        let trimmed = raw.trim();
        if trimmed.is_empty() || trimmed.starts_with('#') {
            continue;
        }
        let error = |column: usize, message: String| QuestionSetError {
            line,
            column: indent + column + 1,
            message,
        };
        let Some((place, prompt)) = trimmed.split_once(':') else {
            return Err(error(
                0,
                "expected `line N: prompt` or `step N: prompt`".to_owned(),
            ));
        };
        let mut words = place.split_whitespace();
        let (Some(keyword), Some(number), None) = (words.next(), words.next(), words.next()) else {
            return Err(error(
                0,
                format!(
                    "expected `line N` or `step N` before the colon, found `{}`",
                    shorten(place.trim())
                ),
            ));
        };
        let column = place.find(number).unwrap_or(0);
        let Some(n) = number.parse::<u32>().ok().filter(|&n| n >= 1) else {
            return Err(error(
                column,
                format!(
                    "`{}` is not a line or step number (1 or more)",
                    shorten(number)
                ),
            ));
        };
        let at = match keyword.to_ascii_lowercase().as_str() {
            "line" => QuestionAt::Line(n),
            "step" => QuestionAt::Step(n as usize),
            _ => {
                return Err(error(
                    0,
                    format!("expected `line` or `step`, found `{}`", shorten(keyword)),
                ));
            }
        };
        let prompt_column = place.len() + 1 + (prompt.len() - prompt.trim_start().len());
        let prompt = checked_prompt(prompt).map_err(|message| error(prompt_column, message))?;
        if questions.len() == MAX_QUESTIONS {
            return Err(error(
                0,
                format!("a set holds at most {MAX_QUESTIONS} questions"),
            ));
        }
        questions.push(Question { at, prompt });
    }
    Ok(questions)
}

/// The prompt trimmed, or why it cannot be one.
fn checked_prompt(prompt: &str) -> Result<String, String> {
    let prompt = prompt.trim();
    if prompt.is_empty() {
        return Err("the question is empty".to_owned());
    }
    let chars = prompt.chars().count();
    if chars > MAX_PROMPT_CHARS {
        return Err(format!(
            "the question is {chars} characters long; at most {MAX_PROMPT_CHARS}"
        ));
    }
    if prompt.chars().any(char::is_control) {
        return Err("the question holds a control character".to_owned());
    }
    Ok(prompt.to_owned())
}

/// Up to 40 characters of `text`, for messages.
fn shorten(text: &str) -> std::borrow::Cow<'_, str> {
    super::diagnostic::shorten(text, 40)
}

/// The `//?` questions in `routine`'s source, each on the next line with
/// code. One with no code after it in the algorithm, an empty one, or one
/// beyond [`MAX_QUESTIONS`] is dropped.
pub fn from_comments(routine: &Routine) -> Vec<Question> {
    let first = routine.first_line as usize;
    let last = routine.last_line as usize;
    let lines = routine
        .source
        .lines()
        .enumerate()
        .map(|(index, text)| (index + 1, text))
        .skip(first.saturating_sub(1))
        .take(last.saturating_sub(first) + 1);
    let mut questions = Vec::new();
    let mut waiting: Vec<String> = Vec::new();
    for (number, text) in lines {
        let trimmed = text.trim_start();
        if let Some(prompt) = trimmed.strip_prefix(COMMENT) {
            if let Ok(prompt) = checked_prompt(prompt) {
                waiting.push(prompt);
            }
        } else if !trimmed.is_empty() && !trimmed.starts_with("//") {
            let Ok(line) = u32::try_from(number) else {
                break;
            };
            questions.extend(waiting.drain(..).map(|prompt| Question {
                at: QuestionAt::Line(line),
                prompt,
            }));
        }
    }
    questions.truncate(MAX_QUESTIONS);
    questions
}

/// A question as this trace asks it.
#[derive(Clone, Debug, PartialEq)]
pub struct Posed {
    pub question: Question,
    /// The step shown while it is asked (0 to the trace's length): the
    /// operations it asks about come next.
    pub ask_at: usize,
    /// The 0-based indices of the steps that answer it.
    pub answered_by: std::ops::Range<usize>,
    pub expected: Value,
}

impl Posed {
    /// The 1-based source line it asks about.
    pub fn line(&self, trace: &Trace) -> u32 {
        trace.line(self.answered_by.start).unwrap_or(0)
    }

    /// Whether `given` is the expected answer: the same element, truth
    /// value or null, or a number equal to it (Floats to 1 part in 10⁴).
    pub fn accepts(&self, given: Value) -> bool {
        same_answer(self.expected, given)
    }

    /// The steps that answer it, as the trace prints them:
    /// `Step 5: lookup e.successorEdge -> edge 3. Step 6: assign e := edge 3.`
    pub fn explanation(&self, trace: &Trace) -> String {
        self.answered_by
            .clone()
            .map(|index| format!("Step {}: {}.", index + 1, trace.render_operation(index)))
            .collect::<Vec<_>>()
            .join(" ")
    }
}

fn same_answer(expected: Value, given: Value) -> bool {
    let number = |value: Value| match value {
        Value::Integer(n) => Some(f64::from(n)),
        Value::Float(x) => Some(f64::from(x)),
        _ => None,
    };
    match (expected, number(expected), number(given)) {
        (Value::Float(_), Some(e), Some(g)) => (e - g).abs() <= 1e-4 * e.abs().max(1.0),
        (Value::Integer(_), Some(e), Some(g)) => e == g,
        _ => expected == given,
    }
}

/// The questions `trace` asks, in the order it reaches them, and a sentence
/// for each question it cannot ask: a line or step the run never reaches,
/// or operations that give no value to answer with.
pub fn pose(trace: &Trace, questions: &[Question]) -> (Vec<Posed>, Vec<String>) {
    let steps = trace.len();
    // The first step of each asked-about line, found in one pass.
    let mut lines: Vec<u32> = questions
        .iter()
        .filter_map(|q| match q.at {
            QuestionAt::Line(line) => Some(line),
            QuestionAt::Step(_) => None,
        })
        .collect();
    lines.sort_unstable();
    lines.dedup();
    let mut first_on: Vec<Option<usize>> = vec![None; lines.len()];
    let mut found = 0;
    for index in 0..steps {
        if found == lines.len() {
            break;
        }
        if let Some(line) = trace.line(index)
            && let Ok(slot) = lines.binary_search(&line)
            && first_on[slot].is_none()
        {
            first_on[slot] = Some(index);
            found += 1;
        }
    }
    let mut posed = Vec::new();
    let mut problems = Vec::new();
    for question in questions {
        let answered_by = match question.at {
            QuestionAt::Line(line) => {
                let start = lines
                    .binary_search(&line)
                    .ok()
                    .and_then(|slot| first_on[slot]);
                let Some(start) = start else {
                    problems.push(format!(
                        "{}: the run never reaches it, so \"{}\" is not asked",
                        question.at,
                        shorten(&question.prompt)
                    ));
                    continue;
                };
                // The line's operations, with the calls it makes.
                let depth = trace.depth(start);
                let end = (start..steps)
                    .find(|&index| trace.line(index) != Some(line) && trace.depth(index) <= depth)
                    .unwrap_or(steps);
                start..end
            }
            QuestionAt::Step(step) if step <= steps => step - 1..step,
            QuestionAt::Step(_) => {
                problems.push(format!(
                    "{}: the run has {steps} steps, so \"{}\" is not asked",
                    question.at,
                    shorten(&question.prompt)
                ));
                continue;
            }
        };
        let expected = answered_by
            .clone()
            .rev()
            .filter_map(|index| trace.step(index)?.kind.outcome())
            .next();
        match expected {
            Some(Value::Vector(_) | Value::Array(_)) => {
                problems.push(format!(
                    "{}: its answer would be a Vector or an Array, which no click, button or number gives",
                    question.at
                ));
            }
            Some(expected) => posed.push(Posed {
                question: question.clone(),
                ask_at: answered_by.start,
                answered_by,
                expected,
            }),
            None => problems.push(format!(
                "{}: it gives no value to answer with; ask about a lookup, an assignment, a comparison or a mark",
                question.at
            )),
        }
    }
    posed.sort_by_key(|p| p.ask_at);
    (posed, problems)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_set_reads_lines_and_steps_and_skips_comments() {
        let set =
            parse_set("# vertexAdjacentEdge\n\nline 12: Which edge?\n  Step 3 : Is it true?\n")
                .expect("valid");
        assert_eq!(
            set,
            vec![
                Question {
                    at: QuestionAt::Line(12),
                    prompt: "Which edge?".to_owned()
                },
                Question {
                    at: QuestionAt::Step(3),
                    prompt: "Is it true?".to_owned()
                },
            ]
        );
    }

    #[test]
    fn set_errors_name_the_line_and_column() {
        let cases = [
            (
                "line 3 Which?",
                "1:1: expected `line N: prompt` or `step N: prompt`",
            ),
            (
                "\nlne 3: Which?",
                "2:1: expected `line` or `step`, found `lne`",
            ),
            (
                "line x: Which?",
                "1:6: `x` is not a line or step number (1 or more)",
            ),
            (
                "line 0: Which?",
                "1:6: `0` is not a line or step number (1 or more)",
            ),
            ("  line 2:   ", "1:10: the question is empty"),
            (
                "line 2 3: Which?",
                "1:1: expected `line N` or `step N` before the colon, found `line 2 3`",
            ),
        ];
        for (text, message) in cases {
            let error = parse_set(text).expect_err(text);
            assert_eq!(error.to_string(), message, "{text:?}");
        }
        let long = format!("line 1: {}", "x".repeat(MAX_PROMPT_CHARS + 1));
        assert_eq!(
            parse_set(&long).expect_err("too long").to_string(),
            "1:9: the question is 301 characters long; at most 300"
        );
        let many = "step 1: q\n".repeat(MAX_QUESTIONS + 1);
        assert_eq!(
            parse_set(&many).expect_err("too many").to_string(),
            "101:1: a set holds at most 100 questions"
        );
    }

    #[test]
    fn answers_compare_numbers_by_value() {
        assert!(same_answer(Value::Integer(3), Value::Float(3.0)));
        assert!(!same_answer(Value::Integer(3), Value::Float(3.5)));
        assert!(same_answer(Value::Float(0.3), Value::Float(0.30001)));
        assert!(!same_answer(Value::Edge(3), Value::Vertex(3)));
        assert!(same_answer(Value::Null, Value::Null));
        assert!(!same_answer(Value::Boolean(true), Value::Integer(1)));
    }
}
