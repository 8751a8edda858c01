//! Hostile algorithm text: long chains, deep nesting, floods of errors, huge
//! names and files. Each is refused with a located message, or compiles, and
//! nothing recurses as deep as the text is long.

use edgewise_core::lang::{self, Diagnostic, MAX_SOURCE_BYTES, lexer::MAX_NAME_CHARS};

/// The stack of a wasm32 build (the linker's default), which is far smaller
/// than a native main thread's. Checking on a thread this small shows the
/// bounds hold where they matter most, even in a debug build.
const WASM_STACK: usize = 1 << 20;

fn check_on_small_stack(source: String) -> Vec<Diagnostic> {
    std::thread::Builder::new()
        .stack_size(WASM_STACK)
        .spawn(move || lang::check(&source))
        .expect("thread starts")
        .join()
        .expect("checking finishes without overflowing the stack")
}

fn algorithm(params: &str, body: &str) -> String {
    format!("algorithm a({params}) : HalfEdge;\nbegin\n{body}\nend\n")
}

fn messages(diagnostics: &[Diagnostic]) -> Vec<&str> {
    diagnostics.iter().map(|d| d.message.as_str()).collect()
}

/// The one error a refused chain gives, and where it points.
fn assert_chain_refused(source: &str, operator: &str) {
    let diagnostics = check_on_small_stack(source.to_owned());
    assert_eq!(diagnostics.len(), 1, "{:?}", messages(&diagnostics));
    let error = &diagnostics[0];
    assert!(
        error
            .message
            .starts_with("this expression is too long (more than 100 operators"),
        "{}",
        error.message
    );
    assert_eq!(error.span.text(source), operator);
}

#[test]
fn a_chain_of_100000_additions_is_refused_where_it_passes_the_limit() {
    let source = algorithm("n : Integer", &format!("n := n{};", " + 1".repeat(100_000)));
    assert_chain_refused(&source, "+");
    let rendered = lang::compile_rendered(&source, Some("long.alg")).expect_err("refused");
    // The statement and the expression are two levels, so the 99th `+` is the
    // first too many; after `n := n`, the k-th ` + 1` puts its `+` at 4k + 4.
    assert!(
        rendered.starts_with("long.alg:3:400: error: this expression is too long"),
        "{rendered}"
    );
}

#[test]
fn long_and_or_and_lookup_chains_are_refused() {
    let ands = algorithm(
        "b : Boolean",
        &format!("b := b{};", " and b".repeat(100_000)),
    );
    assert_chain_refused(&ands, "and");
    let ors = algorithm(
        "b : Boolean",
        &format!("b := b{};", " or b".repeat(100_000)),
    );
    assert_chain_refused(&ors, "or");
    let lookups = algorithm(
        "v : Vertex",
        &format!("v := v{};", ".incidentEdge.startVertex".repeat(20_000)),
    );
    assert_chain_refused(&lookups, ".");
    let products = algorithm("n : Integer", &format!("n := n{};", " * 2".repeat(100_000)));
    assert_chain_refused(&products, "*");
}

#[test]
fn chains_within_the_limit_compile_and_run_deep_enough() {
    // 99 operators inside 40 parentheses: the deepest tree the parser allows
    // is checked, compiled and dropped on a wasm-sized stack.
    let chain = format!(
        "({}n{}){}",
        "(".repeat(39),
        ")".repeat(39),
        " + 1".repeat(60)
    );
    let source = algorithm("n : Integer", &format!("n := {chain};"));
    assert_eq!(messages(&check_on_small_stack(source)), Vec::<&str>::new());
    let lookups = algorithm(
        "v : Vertex",
        &format!("v := v{};", ".incidentEdge.endVertex".repeat(49)),
    );
    assert_eq!(messages(&check_on_small_stack(lookups)), Vec::<&str>::new());
}

#[test]
fn deep_nesting_of_every_kind_is_refused_on_a_small_stack() {
    let cases = [
        algorithm(
            "n : Integer",
            &format!("n := {}1{};", "(".repeat(100_000), ")".repeat(100_000)),
        ),
        algorithm("b : Boolean", &format!("b := {}b;", "not ".repeat(100_000))),
        algorithm("n : Integer", &format!("n := {}1;", "- ".repeat(100_000))),
        algorithm(
            "b : Boolean",
            &format!("{}{}", "if b then ".repeat(20_000), "end ".repeat(20_000)),
        ),
        algorithm(
            "b : Boolean",
            &format!(
                "{}b := true{}",
                "while b do ".repeat(50_000),
                " end".repeat(50_000)
            ),
        ),
        algorithm(
            "b : Boolean",
            &format!("{}b := true;", "if (b) ".repeat(20_000)),
        ),
        // Calls and array items nest like parentheses.
        algorithm(
            "n : Integer",
            &format!("n := {}n{};", "sqrt(".repeat(100_000), ")".repeat(100_000)),
        ),
    ];
    for source in cases {
        let diagnostics = check_on_small_stack(source);
        assert_eq!(
            messages(&diagnostics),
            ["this is nested too deeply (more than 100 levels); the rest of the file was not read"]
        );
    }
}

#[test]
fn deep_array_indices_are_refused_on_a_small_stack() {
    let source = algorithm(
        "a : Array of Integer",
        &format!("a[0] := {}0{};", "a[".repeat(100_000), "]".repeat(100_000)),
    );
    let diagnostics = check_on_small_stack(source);
    assert_eq!(diagnostics.len(), 1, "{:?}", messages(&diagnostics));
    assert!(
        diagnostics[0]
            .message
            .starts_with("this expression is too long (more than 100 operators"),
        "{}",
        diagnostics[0].message
    );
}

#[test]
fn a_flood_of_errors_stops_after_100() {
    let bad_characters = algorithm("n : Integer", &"n := 1 # 2;\n".repeat(50_000));
    let diagnostics = check_on_small_stack(bad_characters);
    assert_eq!(diagnostics.len(), 101);
    assert_eq!(
        diagnostics[100].message,
        "more than 100 errors; the rest of the file was not read"
    );
    let bad_statements = algorithm("n : Integer", &"n = 1;\n".repeat(50_000));
    let diagnostics = check_on_small_stack(bad_statements);
    assert_eq!(diagnostics.len(), 101);
    assert!(diagnostics[100].message.starts_with("more than 100 errors"));
    let bad_types = algorithm("n : Integer", &"n := true;\n".repeat(50_000));
    let diagnostics = check_on_small_stack(bad_types);
    assert_eq!(diagnostics.len(), 101);
    assert_eq!(
        diagnostics[100].message,
        "more than 100 errors; the rest of the file was not checked"
    );
}

#[test]
fn many_variables_and_algorithms_compile() {
    let names: Vec<String> = (0..20_000).map(|i| format!("x{i}")).collect();
    let source = format!(
        "algorithm a() : HalfEdge;\nvar {} : Integer;\nbegin\n{}\nend\n",
        names.join(", "),
        names
            .iter()
            .map(|n| format!("{n} := {n} + 1;"))
            .collect::<String>()
    );
    assert!(lang::compile(&source).is_ok());
    let misspelled = source.replace("begin\n", "begin\ny0 := 1;\n");
    let diagnostics = lang::check(&misspelled);
    assert_eq!(messages(&diagnostics), ["unknown variable `y0`"]);
    assert_eq!(diagnostics[0].hint.as_deref(), Some("did you mean `x0`?"));

    let algorithms: String = (0..20_000)
        .map(|i| format!("algorithm a{i}() : HalfEdge; begin end\n"))
        .collect();
    assert_eq!(
        lang::compile(&algorithms).map(|p| p.algorithms.len()).ok(),
        Some(20_000)
    );
}

#[test]
fn huge_names_numbers_and_files_are_refused_with_their_size() {
    let name = "x".repeat(100_000);
    let diagnostics = lang::check(&algorithm("n : Integer", &format!("{name} := 1;")));
    assert_eq!(
        messages(&diagnostics),
        [format!(
            "this name is {} characters long; names may have at most {MAX_NAME_CHARS}; the rest \
             of the file was not read",
            100_000
        )]
    );

    let number = "9".repeat(500_000);
    let diagnostics = lang::check(&algorithm("n : Integer", &format!("n := {number};")));
    assert_eq!(
        messages(&diagnostics),
        ["the number 99999999999999999999… is too large (Integer holds up to 2147483647)"]
    );

    let big = format!("// {}\n", "x".repeat(MAX_SOURCE_BYTES));
    let diagnostics = lang::check(&big);
    assert_eq!(
        messages(&diagnostics),
        [format!(
            "this text is {} bytes; algorithm files may hold at most 1048576 bytes (1 MiB)",
            big.len()
        )]
    );
}

#[test]
fn an_error_on_a_one_megabyte_line_shows_a_window_of_it() {
    let line = format!("n := 1 {} # 2;", "+ 1 ".repeat(40));
    let source = algorithm("n : Integer", &line);
    let padded = source.replace("n := 1", &format!("n := 1{}", " ".repeat(1_000_000)));
    let rendered = lang::compile_rendered(&padded, None).expect_err("refused");
    let shown = rendered.lines().nth(2).expect("the source line");
    assert!(shown.chars().count() < 140, "{shown}");
    assert!(shown.contains('…'), "{shown}");
    let caret = rendered.lines().nth(3).expect("the caret line");
    let column = caret.find('^').expect("a caret");
    assert_eq!(shown.chars().nth(column), Some('#'), "{rendered}");
}
