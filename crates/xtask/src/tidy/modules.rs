//! The module graph of one crate, read from its files, and the cycles among
//! sibling modules in it.
//!
//! A reference from module `a::b::c` to module `a::d::e` is an arrow from
//! `b` to `d`, the two siblings under `a` that hold them. A reference to an
//! ancestor or a descendant is no arrow: a parent declares and re-exports
//! its children, and a child may use its parent's items.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use anyhow::Context as _;

use super::lexer::{self, Token};

/// One source file: its module path and tokens.
pub struct SourceFile {
    pub path: PathBuf,
    /// `["mesh", "builder"]` for `src/mesh/builder.rs`; empty for the root.
    pub module: Vec<String>,
    pub tokens: Vec<(Token, u32)>,
}

/// Every `.rs` file under `src`, except the extra binaries of `src/bin/`.
pub fn source_files(src: &Path) -> anyhow::Result<Vec<SourceFile>> {
    let mut files = Vec::new();
    let mut folders = vec![src.to_path_buf()];
    while let Some(folder) = folders.pop() {
        let entries = std::fs::read_dir(&folder)
            .with_context(|| format!("cannot read {}", folder.display()))?;
        for entry in entries {
            let path = entry?.path();
            if path.is_dir() {
                if path != src.join("bin") {
                    folders.push(path);
                }
                continue;
            }
            if path.extension().is_none_or(|ext| ext != "rs") {
                continue;
            }
            let text = std::fs::read_to_string(&path)
                .with_context(|| format!("cannot read {}", path.display()))?;
            files.push(SourceFile {
                module: module_of(src, &path),
                tokens: lexer::tokens(&text),
                path,
            });
        }
    }
    files.sort_by(|a, b| a.path.cmp(&b.path));
    Ok(files)
}

fn module_of(src: &Path, path: &Path) -> Vec<String> {
    let relative = path.strip_prefix(src).unwrap_or(path).with_extension("");
    let mut module: Vec<String> = relative
        .components()
        .map(|part| part.as_os_str().to_string_lossy().into_owned())
        .collect();
    if matches!(
        module.last().map(String::as_str),
        Some("lib" | "main" | "mod")
    ) && (module.len() == 1 || module.last().is_some_and(|last| last == "mod"))
    {
        module.pop();
    }
    module
}

/// An arrow between two sibling modules, and where it was first seen.
struct Arrow {
    file: String,
    line: u32,
}

/// The cycles among sibling modules of the crate whose files are `files`,
/// one message each: the folder, the modules (sorted) and each arrow of the
/// loop with its first file and line.
pub fn cycles(root: &Path, files: &[SourceFile]) -> Vec<String> {
    let modules: Vec<&[String]> = files.iter().map(|file| file.module.as_slice()).collect();
    // (parent, from, to) → the first place it is seen.
    let mut arrows: BTreeMap<(Vec<String>, String, String), Arrow> = BTreeMap::new();
    for file in files {
        for (path, line) in referenced_paths(&file.module, &file.tokens) {
            let Some(target) = longest_module(&modules, &path) else {
                continue;
            };
            let source = &file.module;
            let common = source
                .iter()
                .zip(target)
                .take_while(|(a, b)| a == b)
                .count();
            if common == source.len() || common == target.len() {
                continue;
            }
            let key = (
                source[..common].to_vec(),
                source[common].clone(),
                target[common].clone(),
            );
            arrows.entry(key).or_insert_with(|| Arrow {
                file: super::relative(root, &file.path),
                line,
            });
        }
    }
    let mut by_parent: BTreeMap<&[String], BTreeMap<&str, Vec<&str>>> = BTreeMap::new();
    for (parent, from, to) in arrows.keys() {
        by_parent
            .entry(parent.as_slice())
            .or_default()
            .entry(from.as_str())
            .or_default()
            .push(to.as_str());
    }
    let mut messages = Vec::new();
    for (parent, graph) in by_parent {
        for component in strongly_connected(&graph) {
            let crate_folder = files
                .first()
                .map(|file| super::relative(root, &file.path))
                .and_then(|shown| shown.split("/src/").next().map(str::to_owned))
                .unwrap_or_default();
            let place = if parent.is_empty() {
                format!("{crate_folder}/src")
            } else {
                format!("{crate_folder}/src/{}", parent.join("/"))
            };
            let mut steps = Vec::new();
            for from in &component {
                for to in &graph[from] {
                    if component.contains(to) {
                        let key = (parent.to_vec(), (*from).to_owned(), (*to).to_owned());
                        let arrow = &arrows[&key];
                        steps.push(format!("{from} → {to} ({}:{})", arrow.file, arrow.line));
                    }
                }
            }
            messages.push(format!(
                "modules {} in {place} import each other: {}",
                component.join(", "),
                steps.join("; ")
            ));
        }
    }
    messages
}

/// The longest prefix of `path` that is a module of the crate.
fn longest_module<'a>(modules: &[&'a [String]], path: &[String]) -> Option<&'a [String]> {
    modules
        .iter()
        .filter(|module| path.starts_with(module))
        .max_by_key(|module| module.len())
        .copied()
}

/// Every absolute module path the file names through `crate::`, `super::`
/// or `self::`, with `use` trees expanded, each with its line.
fn referenced_paths(module: &[String], tokens: &[(Token, u32)]) -> Vec<(Vec<String>, u32)> {
    let mut found = Vec::new();
    // Unit tests may use anything: they are not part of the layering.
    let tests = lexer::test_modules(tokens);
    // Inline modules (`mod tests { … }`) change what `super` and `self` mean.
    let mut inline: Vec<(String, usize)> = Vec::new();
    let mut depth = 0usize;
    let mut i = 0;
    while i < tokens.len() {
        match &tokens[i].0 {
            Token::Punct('{') => depth += 1,
            Token::Punct('}') => {
                depth = depth.saturating_sub(1);
                if inline.last().is_some_and(|(_, at)| *at == depth) {
                    inline.pop();
                }
            }
            Token::Ident(word) if word == "mod" => {
                if let (Some((Token::Ident(name), _)), Some((Token::Punct('{'), _))) =
                    (tokens.get(i + 1), tokens.get(i + 2))
                {
                    inline.push((name.clone(), depth));
                }
            }
            Token::Ident(word)
                if matches!(word.as_str(), "crate" | "super" | "self")
                    && tokens.get(i + 1).is_some_and(|(t, _)| *t == Token::PathSep)
                    && (i == 0 || tokens[i - 1].0 != Token::PathSep) =>
            {
                let mut here: Vec<String> = module.to_vec();
                here.extend(inline.iter().map(|(name, _)| name.clone()));
                let line = tokens[i].1;
                let mut prefix = Vec::new();
                let mut j = i;
                // `crate`, `self` and runs of `super` set where the path starts.
                loop {
                    match &tokens[j].0 {
                        Token::Ident(w) if w == "crate" && j == i => prefix.clear(),
                        Token::Ident(w) if w == "self" && j == i => prefix.clone_from(&here),
                        Token::Ident(w) if w == "super" => {
                            if j == i {
                                prefix.clone_from(&here);
                            }
                            prefix.pop();
                        }
                        _ => break,
                    }
                    if tokens.get(j + 1).is_some_and(|(t, _)| *t == Token::PathSep) {
                        j += 2;
                    } else {
                        j += 1;
                        break;
                    }
                }
                let (paths, end) = use_tree(tokens, j, prefix);
                if !tests.iter().any(|range| range.contains(&i)) {
                    found.extend(paths.into_iter().map(|path| (path, line)));
                }
                i = end.max(i + 1);
                continue;
            }
            _ => {}
        }
        i += 1;
    }
    found
}

/// Reads a path or `use` tree from `start`, each leaf appended to `prefix`;
/// returns the paths and the index after the tree.
fn use_tree(
    tokens: &[(Token, u32)],
    start: usize,
    prefix: Vec<String>,
) -> (Vec<Vec<String>>, usize) {
    let mut path = prefix;
    let mut i = start;
    loop {
        match tokens.get(i).map(|(t, _)| t) {
            Some(Token::Ident(word)) => {
                path.push(word.clone());
                i += 1;
            }
            Some(Token::Punct('{')) => {
                let mut paths = Vec::new();
                i += 1;
                loop {
                    match tokens.get(i).map(|(t, _)| t) {
                        Some(Token::Punct('}')) | None => {
                            return (paths, i + 1);
                        }
                        Some(Token::Punct(',')) => i += 1,
                        _ => {
                            let (inner, end) = use_tree(tokens, i, path.clone());
                            paths.extend(inner);
                            i = end;
                        }
                    }
                }
            }
            _ => return (vec![path], i),
        }
        if tokens.get(i).is_some_and(|(t, _)| *t == Token::PathSep) {
            i += 1;
        } else {
            return (vec![path], i);
        }
    }
}

/// Tarjan's strongly connected components with more than one module.
fn strongly_connected<'a>(graph: &BTreeMap<&'a str, Vec<&'a str>>) -> Vec<Vec<&'a str>> {
    struct State<'a> {
        index: BTreeMap<&'a str, usize>,
        low: BTreeMap<&'a str, usize>,
        stack: Vec<&'a str>,
        on_stack: BTreeMap<&'a str, bool>,
        found: Vec<Vec<&'a str>>,
    }
    fn visit<'a>(node: &'a str, graph: &BTreeMap<&'a str, Vec<&'a str>>, state: &mut State<'a>) {
        let index = state.index.len();
        state.index.insert(node, index);
        state.low.insert(node, index);
        state.stack.push(node);
        state.on_stack.insert(node, true);
        for &next in graph.get(node).map(Vec::as_slice).unwrap_or_default() {
            if !state.index.contains_key(next) {
                visit(next, graph, state);
                let low = state.low[node].min(state.low[next]);
                state.low.insert(node, low);
            } else if state.on_stack.get(next).copied().unwrap_or(false) {
                let low = state.low[node].min(state.index[next]);
                state.low.insert(node, low);
            }
        }
        if state.low[node] == state.index[node] {
            let mut component = Vec::new();
            while let Some(top) = state.stack.pop() {
                state.on_stack.insert(top, false);
                component.push(top);
                if top == node {
                    break;
                }
            }
            if component.len() > 1 {
                component.sort_unstable();
                state.found.push(component);
            }
        }
    }
    let mut state = State {
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: Vec::new(),
        on_stack: BTreeMap::new(),
        found: Vec::new(),
    };
    for &node in graph.keys() {
        if !state.index.contains_key(node) {
            visit(node, graph, &mut state);
        }
    }
    state.found
}

#[cfg(test)]
mod tests {
    use super::*;

    fn module(path: &str) -> Vec<String> {
        path.split("::")
            .filter(|s| !s.is_empty())
            .map(str::to_owned)
            .collect()
    }

    fn file(path: &str, text: &str) -> SourceFile {
        SourceFile {
            path: PathBuf::from(format!("crates/x/src/{}.rs", path.replace("::", "/"))),
            module: module(path),
            tokens: lexer::tokens(text),
        }
    }

    #[test]
    fn use_trees_super_and_inline_modules_resolve() {
        let tokens = lexer::tokens(
            "use crate::{mesh::{builder, repair::Repair}, schema};\n\
             use super::lexer::MAX;\n\
             mod tests { use super::super::vm; }\n\
             fn f() { self::inner::g(); }\n\
             #[cfg(test)] mod unit { use crate::anything; }",
        );
        let paths: Vec<String> = referenced_paths(&module("lang::parser"), &tokens)
            .into_iter()
            .map(|(path, line)| format!("{}@{line}", path.join("::")))
            .collect();
        assert_eq!(
            paths,
            [
                "mesh::builder@1",
                "mesh::repair::Repair@1",
                "schema@1",
                "lang::lexer::MAX@2",
                "lang::vm@3",
                "lang::parser::inner::g@4",
            ]
        );
    }

    #[test]
    fn a_loop_between_siblings_is_a_cycle_and_a_parent_is_not() {
        let files = [
            file(
                "lang",
                "pub use self::parser::Parser; use crate::mesh::Mesh;",
            ),
            file("lang::lexer", "use super::parser::MAX_ERRORS;"),
            file(
                "lang::parser",
                "use crate::lang::lexer::Lexer; use super::Helper;",
            ),
            file("mesh", "fn f() { crate::schema::Column::Face; }"),
            file("schema", "use crate::mesh::Mesh;"),
        ];
        let found = cycles(Path::new(""), &files);
        assert_eq!(found.len(), 2, "{found:#?}");
        assert!(
            found[0].starts_with("modules mesh, schema in crates/x/src import"),
            "{found:#?}"
        );
        assert!(!found[0].contains("lang → mesh"), "{found:#?}");
        assert!(
            found[1].starts_with("modules lexer, parser in crates/x/src/lang import")
                && found[1].contains("lexer → parser (crates/x/src/lang/lexer.rs:1)"),
            "{found:#?}"
        );
    }
}
