//! `edgewise check-alg` and `edgewise check` on hostile files: long chains,
//! deep nesting and huge files exit 1 with a located message, never with a
//! stack overflow (exit 134) or a hang.

use std::path::PathBuf;
use std::process::{Command, Output};

use crate::common::scratch;

fn check(command: &str, name: &str, contents: &str) -> Output {
    let dir = scratch(&format!("hostile-{name}"));
    let path: PathBuf = dir.join(name);
    std::fs::write(&path, contents).expect("writable");
    Command::new(env!("CARGO_BIN_EXE_edgewise"))
        .arg(command)
        .arg(&path)
        .current_dir(&*dir)
        .output()
        .expect("edgewise runs")
}

fn algorithm(params: &str, body: &str) -> String {
    format!("algorithm a({params}) : HalfEdge;\nbegin\n{body}\nend\n")
}

/// Exit 1, and the first line of stderr is `name:line:column: error: …`.
fn assert_refused(output: &Output, name: &str, located: &str, message: &str) {
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(1), "{name}: {stderr}");
    let first = stderr.lines().next().unwrap_or_default();
    assert!(
        first.contains(&format!("{name}:{located}: error: {message}")),
        "{first}"
    );
}

#[test]
fn check_alg_refuses_long_chains_with_their_place() {
    let cases = [
        (
            "plus.alg",
            "n : Integer",
            format!("n := n{};", " + 1".repeat(100_000)),
            "3:400",
        ),
        (
            "and.alg",
            "b : Boolean",
            format!("b := b{};", " and b".repeat(100_000)),
            "3:596",
        ),
        (
            "or.alg",
            "b : Boolean",
            format!("b := b{};", " or b".repeat(100_000)),
            "3:498",
        ),
        (
            "lookups.alg",
            "v : Vertex",
            format!("v := v{};", ".incidentEdge.endVertex".repeat(20_000)),
            "3:1134",
        ),
    ];
    for (name, params, body, located) in cases {
        let output = check("check-alg", name, &algorithm(params, &body));
        assert_refused(&output, name, located, "this expression is too long");
    }
}

#[test]
fn check_alg_refuses_deep_nesting_with_its_place() {
    let cases = [
        (
            "parens.alg",
            "n : Integer",
            format!("n := {}1{};", "(".repeat(100_000), ")".repeat(100_000)),
            "3:105",
        ),
        (
            "nots.alg",
            "b : Boolean",
            format!("b := {}b;", "not ".repeat(100_000)),
            "3:402",
        ),
        (
            "ifs.alg",
            "b : Boolean",
            format!(
                "{}b := true;{}",
                "if b then ".repeat(50_000),
                " end".repeat(50_000)
            ),
            "3:994",
        ),
    ];
    for (name, params, body, located) in cases {
        let output = check("check-alg", name, &algorithm(params, &body));
        assert_refused(&output, name, located, "this is nested too deeply");
    }
}

#[test]
fn check_alg_refuses_a_file_over_the_limit_by_its_size() {
    let text = format!("// {}\n", "x".repeat(2 << 20));
    let output = check("check-alg", "huge.alg", &text);
    assert_refused(&output, "huge.alg", "1:1", "this text is 2097156 bytes");
}

#[test]
fn check_reports_a_one_megabyte_line_in_a_few_words() {
    let obj = format!("v 0 0 0\nv 1 0 {}\nv 0 1 0\nf 1 2 3\n", "x".repeat(1 << 20));
    let output = check("check", "long.obj", &obj);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(1), "{stderr}");
    assert!(stderr.len() < 200, "{stderr}");
    assert!(
        stderr.contains("long.obj:2:7: expected a finite number for z"),
        "{stderr}"
    );
}

/// `edgewise trace` on a committed runaway algorithm, under a 2 GB address
/// space limit: it stops with its reason, never by running out of memory.
fn trace_runaway(file: &str, name: &str, limits: &[&str]) -> Output {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..");
    let script = format!(
        "ulimit -v 2000000; exec \"$0\" trace {} {name} {} --arg v=0 {} > /dev/null",
        root.join("tests/hostile").join(file).display(),
        root.join("meshes/cube.htb").display(),
        limits.join(" ")
    );
    Command::new("sh")
        .arg("-c")
        .arg(script)
        .arg(env!("CARGO_BIN_EXE_edgewise"))
        .output()
        .expect("edgewise runs")
}

#[test]
fn trace_stops_a_run_at_its_memory_budget() {
    let output = trace_runaway(
        "run-long-messages.alg",
        "chatter",
        &["--memory-limit", "16"],
    );
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.contains(
            "run-long-messages.alg:7: error: stopped after 7792 operations: the run would need \
             more than 16 MB of memory"
        ),
        "{stderr}"
    );
    assert!(
        stderr.contains("(most of it for the texts of its messages)"),
        "{stderr}"
    );
}

#[test]
fn trace_stops_calls_that_set_up_too_much() {
    let output = trace_runaway(
        "run-calls-300-variables.alg",
        "spin",
        &["--step-limit", "20000"],
    );
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.contains(
            "the calls of this run set up more than 1280000 variables and intermediate values"
        ),
        "{stderr}"
    );
}
