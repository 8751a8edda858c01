//! The algorithm language of the journal paper's Appendix A, also accepting
//! the dialect of the half-edge paper's Figure 5, extended with Integer,
//! Boolean, Float and Vector values, `null`, `message`, and the papers'
//! future work: changing the mesh (writes into records, `new`, `delete`
//! and `refuse`), algorithms that call one another, and arrays.
//!
//! Pipeline: [`lexer`] → [`parser`] (syntax tree in [`ast`]) → [`checker`]
//! (names and types) → [`compiler`] (linear code, listed by [`disasm`]) →
//! [`vm`] (runs on any [`Topology`]) → [`Trace`] (steps to walk through).
//!
//! ```text
//! file        := algorithm-decl [ ";" ] { algorithm-decl [ ";" ] }
//! algorithm-decl :=
//!     "algorithm" ident "(" [ params ] ")" [ ":" mesh-type ]
//!         [ "returns" type ] [ ";" ]
//!     [ "structuretype" mesh-type [ ";" ] ]        (one of the two forms)
//!     [ "description" string [ ";" ] ]
//!     { "var" decls }
//!     "begin" statement-list "end"
//! params      := ident-list ":" type { (";" | ",") ident-list ":" type }
//! decls       := ident-list ":" type { ";" ident-list ":" type } [ ";" ]
//! statement-list := { statement ";" }     (";" optional before end/else/while)
//! statement   := ident ":=" expr
//!              | expr "." lookup ":=" expr             (a write into a record)
//!              | expr "[" expr "]" ":=" expr           (a write into an array)
//!              | ident "(" [ expr { "," expr } ] ")"   (a call; `append(a, x)`)
//!              | "return" [ expr ]
//!              | "delete" expr
//!              | "refuse" item { "," item }            (stops: a precondition failed)
//!              | "if" expr "then" statement-list
//!                    { "else" "if" expr "then" statement-list }
//!                    [ "else" statement-list ] "end"
//!              | "if" "(" expr ")" statement [ "else" statement ]
//!              | "while" expr "do" statement-list "end"
//!              | "do" statement-list "while" expr
//!              | "do" statement-list "end"             (repeat until break)
//!              | "begin" statement-list "end"
//!              | "break" | "continue"
//!              | ("mark" | "highlight") expr | expr "." ("mark" | "highlight")
//!              | "message" item { "," item }       item := string | expr
//! expr        := or-expr;  "or" < "and" < "not" < comparisons
//!                (= == <> < <= > >=, not chained) < + - < * / div mod < unary -
//!                < postfix (expr "." lookup, expr "[" expr "]") < primary
//! primary     := ident | integer | float | "true" | "false" | "null"
//!              | "new" ("Vertex" | "Edge" | "Face")
//!              | ident "(" [ expr { "," expr } ] ")"
//!                    (a built-in: vector, float, sqrt, length, id; or an
//!                     algorithm of the file that returns a value)
//!              | "(" expr ")"
//! mesh-type   := "WingedEdge" | "HalfEdge"
//! type        := scalar-type | "Array" "of" scalar-type
//! scalar-type := "Vertex" | "Edge" | "Face" | "Integer" | "Boolean"
//!              | "Float" | "Vector"
//! ```
//! A Float literal has a point with digits after it (`0.5`). `/` divides
//! numbers as Floats; `div` and `mod` are for Integers. An Integer widens to
//! a Float where one is expected. Vectors add, subtract, and scale by a
//! number; `p.x`, `p.y` and `p.z` are their coordinates, and `v.position` a
//! vertex's (readable and writable). `new Edge` makes a winged edge, or a
//! pair of half-edges whose `pair`s name each other; `delete` of a half-edge
//! deletes its pair too. A deleted row keeps its id as a gap. A write may
//! leave the tables inconsistent for a while; the tools say where.
//!
//! Calls: an algorithm calls any algorithm of its file that walks the same
//! structure, by name, with one argument per parameter (an Integer widens to
//! a Float). One declared `returns T` gives a value with `return expr` and
//! can be used in expressions; every way through it must end in `return`
//! (or `refuse`). A plain `return` leaves one without a result early. A
//! call to one that returns nothing is a statement of its own. Calls may
//! recurse, up to [`vm::MAX_CALL_DEPTH`] algorithms running at once. A
//! `return` in the algorithm that was started goes on to its `end`.
//!
//! Arrays: `Array of T` holds any type but an array. A variable of it
//! starts as a new empty array; `a[i]` (from 0) reads and writes an item,
//! `length(a)` counts them, the statement `append(a, x)` adds one at the
//! end. Assigning or passing an array shares it (the callee's `append` is
//! seen by the caller); an array parameter of the algorithm started begins
//! empty. An index out of range stops the run, naming the index and the
//! length; one run makes at most [`vm::MAX_ARRAY_ITEMS`] items (each new
//! array counts as one). Arrays cannot be compared, marked or looked into.
//! `id(x)` is the row number of a vertex, edge or face as an Integer: an
//! array indexed by it holds a value per element (a whole-mesh algorithm's
//! "visited" flags or new positions), and comparing ids picks the lower one.
//!
//! Keywords, type names, structure names and lookup names ignore case, and
//! so do the names of called algorithms where that is not ambiguous;
//! variable names do not. `//` starts a comment. Element variables start as
//! `null`, Integers (32-bit, overflow is a run-time error) as 0, Booleans as
//! false, Floats as 0.0, Vectors as (0, 0, 0). `and` and `or` short-circuit.
//! Half-edge lookups accept the aliases `face`, `vertex` (end vertex),
//! `pair`, `twin`, `successor`, `next`, `predecessor` and `prev`.
//!
//! Limits, so that no text can exhaust the stack or freeze a page (see
//! docs/limits.md): at most [`MAX_SOURCE_BYTES`] of text; nesting plus the
//! operators and lookups of a chain at most [`parser::MAX_NESTING`] deep;
//! names at most [`lexer::MAX_NAME_CHARS`] long; reading stops after
//! [`diagnostic::MAX_ERRORS`] errors. Calls keep their frames in a list, not on
//! the stack, so no recursion in an algorithm recurses in the VM.

pub mod ast;
pub mod builtin;
pub mod checker;
pub mod compiler;
pub mod diagnostic;
pub mod disasm;
pub mod lexer;
pub mod library;
pub mod parser;
pub mod question;
mod recorder;
pub mod token;
pub mod topology;
pub mod trace;
pub mod types;
pub mod vm;

pub use compiler::{Algorithm, Routine};
pub use diagnostic::{Diagnostic, Severity, Span, render_all};
pub use disasm::{disassemble, disassemble_all};
pub use topology::Topology;
pub use trace::{FrameView, Outcome, RuntimeError, RuntimeErrorKind, StepKind, StepView, Trace};
pub use types::{Type, Value};
pub use vm::{
    DEFAULT_MEMORY_LIMIT, DEFAULT_STEP_LIMIT, Execution, InputError, RunOptions, execute,
    execute_editing, run, run_editing,
};

use std::sync::Arc;

/// The compiled algorithms of one source file.
#[derive(Clone, Debug)]
pub struct Program {
    pub source: Arc<str>,
    pub algorithms: Vec<Arc<Algorithm>>,
}

impl Program {
    /// Finds an algorithm by name (exact case first, then ignoring case).
    pub fn algorithm(&self, name: &str) -> Option<&Arc<Algorithm>> {
        self.algorithms.iter().find(|a| a.name == name).or_else(|| {
            self.algorithms
                .iter()
                .find(|a| a.name.eq_ignore_ascii_case(name))
        })
    }

    /// The algorithms' names, in file order.
    pub fn names(&self) -> impl Iterator<Item = &str> {
        self.algorithms.iter().map(|a| a.name.as_str())
    }
}

/// Every problem in a file, at once: lexing, parsing and type errors.
/// An empty list means [`compile`] will succeed.
pub fn check(source: &str) -> Vec<Diagnostic> {
    match compile(source) {
        Ok(_) => Vec::new(),
        Err(diagnostics) => diagnostics,
    }
}

/// The largest algorithm text compiled, in bytes. The library's files are
/// about 10 KB; the limit keeps one compile well under a second.
pub const MAX_SOURCE_BYTES: usize = 1 << 20;

/// Parses, checks and compiles every algorithm in `source`.
pub fn compile(source: &str) -> Result<Program, Vec<Diagnostic>> {
    if source.len() > MAX_SOURCE_BYTES {
        return Err(vec![size_error(source.len())]);
    }
    let (file, mut diagnostics) = parser::parse(source);
    let scopes = checker::check_file(&file, source, &mut diagnostics);
    if file.algorithms.is_empty() && diagnostics.is_empty() {
        diagnostics.push(
            Diagnostic::error(
                Span::new(source.len(), source.len()),
                "this file holds no algorithm",
            )
            .with_hint("an algorithm starts with `algorithm name(v : Vertex) : HalfEdge;`"),
        );
    }
    if diagnostics.iter().any(Diagnostic::is_error) {
        diagnostics.sort_by_key(|d| (d.span.start, d.span.end));
        return Err(diagnostics);
    }
    let shared: Arc<str> = Arc::from(source);
    let lines = diagnostic::LineIndex::new(source);
    let algorithms = compiler::compile_file(&file, &scopes, &shared, &lines)?;
    Ok(Program {
        source: shared,
        algorithms,
    })
}

/// An algorithm file's bytes as text, or the rendered error that names where
/// the first byte that is not UTF-8 is (`file:line:column`). Larger files
/// than [`MAX_SOURCE_BYTES`] are refused before decoding.
pub fn source_text<'b>(bytes: &'b [u8], file: Option<&str>) -> Result<&'b str, String> {
    if bytes.len() > MAX_SOURCE_BYTES {
        return Err(render_all(&[size_error(bytes.len())], "", file));
    }
    std::str::from_utf8(bytes).map_err(|error| {
        let at = error.valid_up_to();
        let valid = std::str::from_utf8(&bytes[..at]).unwrap_or_default();
        let byte = bytes.get(at).copied().unwrap_or_default();
        let diagnostic = Diagnostic::error(
            Span::new(at, at),
            format!("byte {at} (\\x{byte:02X}) is not UTF-8 text; algorithm files are UTF-8 text"),
        );
        render_all(&[diagnostic], valid, file)
    })
}

fn size_error(size: usize) -> Diagnostic {
    Diagnostic::error(
        Span::new(0, 0),
        format!(
            "this text is {size} bytes; algorithm files may hold at most {MAX_SOURCE_BYTES} \
             bytes (1 MiB)"
        ),
    )
}

/// Compiles `source` and renders any errors the way `edgewise check-alg`
/// prints them, with `file` (if given) in front of each location.
pub fn compile_rendered(source: &str, file: Option<&str>) -> Result<Program, String> {
    compile(source).map_err(|diagnostics| render_all(&diagnostics, source, file))
}
