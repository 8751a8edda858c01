//! `cargo xtask tidy`: the invariants ARCHITECTURE.md states, checked on the
//! source itself so that the document cannot drift from the code.
//!
//! - Within each crate, sibling modules never import each other both ways
//!   (directly or round a longer loop): a module's place in its folder says
//!   what it may use.
//! - A record column is named only in core's `schema/column.rs`.
//! - `impl EdgewiseApp` blocks live in the app's `app/` folder.
//! - Dependencies among the workspace's crates point down the layers, and
//!   ARCHITECTURE.md describes every crate there is.
//! - The crates below the UI (core, pictures, model) and the CLI name no
//!   windowing, GPU or UI crate.
//!
//! The reading is lexical (comments and literals skipped, `use` trees and
//! `crate::`/`super::`/`self::` paths followed), which is enough here: the
//! code names modules by path, never through glob re-exports of siblings.

mod lexer;
mod modules;

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use anyhow::{Context as _, bail};

use lexer::Token;

/// The workspace's crates from the bottom layer up, with their folders. A
/// crate may depend only on crates of lower layers; the build tool depends
/// on none.
pub const LAYERS: &[(&str, &str, u8)] = &[
    ("edgewise-core", "crates/core", 0),
    ("edgewise-bench-wasm", "crates/bench-wasm", 1),
    ("edgewise-pictures", "crates/pictures", 1),
    ("edgewise-model", "crates/model", 2),
    ("edgewise-renderer", "crates/renderer", 2),
    ("edgewise-app", "crates/app", 3),
    ("edgewise-cli", "crates/cli", 4),
    ("edgewise-browser-tests", "web/browser-tests", 4),
];
const BUILD_TOOL: (&str, &str) = ("xtask", "crates/xtask");

/// The one file allowed to name a record column.
const COLUMN_FILE: &str = "crates/core/src/schema/column.rs";

/// Runs every check and reports all the broken invariants at once.
pub fn run(root: &Path) -> anyhow::Result<()> {
    let problems = problems(root)?;
    if problems.is_empty() {
        eprintln!("==> tidy: every invariant of ARCHITECTURE.md holds");
        return Ok(());
    }
    let mut report = String::new();
    for problem in &problems {
        let _ = writeln!(report, "- {problem}");
    }
    bail!(
        "{} invariant(s) of ARCHITECTURE.md broken:\n{report}",
        problems.len()
    )
}

/// Every broken invariant, in words that name the file and line.
pub fn problems(root: &Path) -> anyhow::Result<Vec<String>> {
    let mut problems = Vec::new();
    let column_names = column_names(&root.join(COLUMN_FILE))?;
    for &(_, folder, _) in LAYERS
        .iter()
        .chain(std::iter::once(&(BUILD_TOOL.0, BUILD_TOOL.1, 0)))
    {
        let src = root.join(folder).join("src");
        let files = modules::source_files(&src)?;
        problems.extend(modules::cycles(root, &files));
        for file in &files {
            let shown = relative(root, &file.path);
            if shown != COLUMN_FILE {
                problems.extend(named_columns(&shown, &file.tokens, &column_names));
            }
            if folder == "crates/app" {
                problems.extend(app_impls(&shown, &file.module, &file.tokens));
            }
        }
    }
    problems.extend(members_have_layers(root)?);
    problems.extend(headless_manifests(root)?);
    problems.extend(dependency_arrows(root)?);
    problems.extend(crate_map(root)?);
    Ok(problems)
}

/// `path` from the repository's root, with forward slashes.
fn relative(root: &Path, path: &Path) -> String {
    path.strip_prefix(root)
        .unwrap_or(path)
        .to_string_lossy()
        .replace('\\', "/")
}

/// The distinctive names of the columns in `schema/column.rs`: record names
/// (`left_predecessor`), role labels ("Left Predecessor") and the camel-case
/// keys (`leftPredecessor`). One-word names ("face", "next") are everyday
/// words and are not checked.
fn column_names(path: &Path) -> anyhow::Result<Vec<String>> {
    let text =
        std::fs::read_to_string(path).with_context(|| format!("cannot read {}", path.display()))?;
    let mut names: Vec<String> = lexer::tokens(&text)
        .into_iter()
        .filter_map(|(token, _)| match token {
            Token::Str(text) => Some(text),
            _ => None,
        })
        .filter(|text| is_column_like(text))
        .collect();
    names.sort();
    names.dedup();
    Ok(names)
}

fn is_column_like(text: &str) -> bool {
    let words = |separator: char| {
        let parts: Vec<&str> = text.split(separator).collect();
        parts.len() == 2
            && parts
                .iter()
                .all(|part| !part.is_empty() && part.chars().all(char::is_alphabetic))
    };
    let snake = words('_') && text.chars().all(|c| c == '_' || c.is_ascii_lowercase());
    let title = words(' ')
        && text
            .split(' ')
            .all(|word| word.starts_with(|c: char| c.is_ascii_uppercase()));
    let camel = text.chars().all(|c| c.is_ascii_alphabetic())
        && text.starts_with(|c: char| c.is_ascii_lowercase())
        && text.chars().filter(char::is_ascii_uppercase).count() == 1;
    snake || title || camel
}

/// Literals naming a column, outside unit tests (which may check a name).
fn named_columns(shown: &str, tokens: &[(Token, u32)], names: &[String]) -> Vec<String> {
    let tests = lexer::test_modules(tokens);
    tokens
        .iter()
        .enumerate()
        .filter(|(i, _)| !tests.iter().any(|range| range.contains(i)))
        .filter_map(|(_, (token, line))| match token {
            Token::Str(text) if names.binary_search(text).is_ok() => Some(format!(
                "{shown}:{line}: \"{text}\" names a record column: take it from \
                 `Column` ({COLUMN_FILE}), the one place a column is named"
            )),
            _ => None,
        })
        .collect()
}

/// `impl EdgewiseApp` (or a trait's impl for it) outside `app.rs` and `app/`.
fn app_impls(shown: &str, module: &[String], tokens: &[(Token, u32)]) -> Vec<String> {
    if module.first().is_some_and(|first| first == "app") {
        return Vec::new();
    }
    let mut problems = Vec::new();
    for (i, (token, line)) in tokens.iter().enumerate() {
        if !matches!(token, Token::Ident(word) if word == "impl") {
            continue;
        }
        // An item starts after a `;`, a block or an attribute; `impl` after
        // `:`, `(` or `,` is a type (`impl FnOnce(&EdgewiseApp)`).
        let item = i == 0 || matches!(tokens[i - 1].0, Token::Punct(';' | '{' | '}' | ']'));
        if !item {
            continue;
        }
        let header = tokens[i + 1..]
            .iter()
            .take_while(|(token, _)| !matches!(token, Token::Punct('{' | ';')));
        if header
            .clone()
            .any(|(token, _)| matches!(token, Token::Ident(word) if word == "EdgewiseApp"))
        {
            problems.push(format!(
                "{shown}:{line}: an `impl` for EdgewiseApp outside crates/app/src/app/: \
                 the app's methods live beside it there"
            ));
        }
    }
    problems
}

/// Every member of the workspace has its place in [`LAYERS`] (or is the
/// build tool), so that no crate escapes the layer check.
fn members_have_layers(root: &Path) -> anyhow::Result<Vec<String>> {
    let manifest = root.join("Cargo.toml");
    let text = std::fs::read_to_string(&manifest)
        .with_context(|| format!("cannot read {}", manifest.display()))?;
    let Some(list) = text
        .split_once("members = [")
        .and_then(|(_, rest)| rest.split_once(']'))
        .map(|(list, _)| list)
    else {
        bail!("Cargo.toml: no `members = [...]` list");
    };
    Ok(list
        .split(',')
        .map(|member| member.trim().trim_matches('"'))
        .filter(|member| !member.is_empty())
        .filter(|member| {
            *member != BUILD_TOOL.1 && !LAYERS.iter().any(|&(_, folder, _)| folder == *member)
        })
        .map(|member| {
            format!(
                "Cargo.toml: the member {member} has no layer in tidy.rs's LAYERS (ARCHITECTURE.md)"
            )
        })
        .collect())
}

/// Each line's key in `folder`'s Cargo.toml, with its line number: a
/// dependency's name where the line names one (`egui.workspace = true`,
/// `wgpu = "30"`).
fn manifest_keys(root: &Path, folder: &str) -> anyhow::Result<Vec<(usize, String)>> {
    let manifest = root.join(folder).join("Cargo.toml");
    let text = std::fs::read_to_string(&manifest)
        .with_context(|| format!("cannot read {}", manifest.display()))?;
    Ok(text
        .lines()
        .enumerate()
        .map(|(index, line)| {
            let key = line.split(['=', '.', ' ']).next().unwrap_or_default();
            (index + 1, key.to_owned())
        })
        .collect())
}

/// The crates that build with no window, GPU or UI: the command line, and
/// everything it stands on.
const HEADLESS: &[&str] = &[
    "crates/core",
    "crates/pictures",
    "crates/model",
    "crates/cli",
];

/// Windowing, GPU and UI crates.
const GUI_CRATES: &[&str] = &[
    "eframe",
    "egui",
    "egui-wgpu",
    "egui_extras",
    "egui_kittest",
    "wgpu",
    "winit",
    "edgewise-renderer",
    "edgewise-app",
];

/// A headless crate whose Cargo.toml names a GUI crate, in any section.
fn headless_manifests(root: &Path) -> anyhow::Result<Vec<String>> {
    let mut problems = Vec::new();
    for folder in HEADLESS {
        for (number, name) in manifest_keys(root, folder)? {
            if GUI_CRATES.contains(&name.as_str()) {
                problems.push(format!(
                    "{folder}/Cargo.toml:{number}: {name} is a windowing, GPU or UI crate, and \
                     {folder} builds without one (ARCHITECTURE.md)"
                ));
            }
        }
    }
    Ok(problems)
}

/// The workspace crates each crate's Cargo.toml depends on, by layer.
fn dependency_arrows(root: &Path) -> anyhow::Result<Vec<String>> {
    let mut problems = Vec::new();
    let layer_of: BTreeMap<&str, u8> = LAYERS
        .iter()
        .map(|&(name, _, layer)| (name, layer))
        .collect();
    let all = LAYERS
        .iter()
        .map(|&(name, folder, layer)| (name, folder, Some(layer)))
        .chain(std::iter::once((BUILD_TOOL.0, BUILD_TOOL.1, None)));
    for (name, folder, layer) in all {
        for (number, dependency) in manifest_keys(root, folder)? {
            let Some(&their_layer) = layer_of.get(dependency.as_str()) else {
                continue;
            };
            let allowed = layer.is_some_and(|layer| their_layer < layer);
            if !allowed {
                problems.push(format!(
                    "{folder}/Cargo.toml:{number}: {name} depends on {dependency}, an arrow \
                     that does not point down the layers (ARCHITECTURE.md)"
                ));
            }
        }
    }
    Ok(problems)
}

/// Every crate has its `### folder (`name`)` heading in ARCHITECTURE.md, and
/// every such heading names a crate there is.
fn crate_map(root: &Path) -> anyhow::Result<Vec<String>> {
    let path = root.join("ARCHITECTURE.md");
    let text = std::fs::read_to_string(&path)
        .with_context(|| format!("cannot read {}", path.display()))?;
    let mut problems = Vec::new();
    let crates: Vec<(&str, &str)> = LAYERS
        .iter()
        .map(|&(name, folder, _)| (name, folder))
        .chain(std::iter::once(BUILD_TOOL))
        .collect();
    for (name, folder) in &crates {
        let heading = format!("### {folder} ");
        if !text
            .lines()
            .any(|line| line.starts_with(&heading) || line == heading.trim_end())
        {
            problems.push(format!(
                "ARCHITECTURE.md: no `### {folder}` section describes the crate {name}"
            ));
        }
    }
    for (number, line) in text.lines().enumerate() {
        let Some(rest) = line.strip_prefix("### ") else {
            continue;
        };
        let folder = rest.split(' ').next().unwrap_or_default();
        let is_crate_heading = folder.starts_with("crates/") || folder.starts_with("web/");
        if is_crate_heading && !crates.iter().any(|(_, known)| known == &folder) {
            problems.push(format!(
                "ARCHITECTURE.md:{}: `{folder}` is not a crate of the workspace",
                number + 1
            ));
        }
        if is_crate_heading && !PathBuf::from(root).join(folder).join("Cargo.toml").exists() {
            problems.push(format!(
                "ARCHITECTURE.md:{}: {folder}/Cargo.toml does not exist",
                number + 1
            ));
        }
    }
    Ok(problems)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn root() -> PathBuf {
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
    }

    /// The invariants hold on the repository as it is.
    #[test]
    fn the_architecture_holds() {
        let problems = problems(&root()).expect("the sources can be read");
        assert!(
            problems.is_empty(),
            "{} invariant(s) broken:\n{}",
            problems.len(),
            problems.join("\n")
        );
    }

    /// A scratch workspace: `files` as (path, text) under a fresh folder.
    fn scratch_root(name: &str, files: &[(&str, &str)]) -> PathBuf {
        let root =
            std::env::temp_dir().join(format!("edgewise-tidy-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&root);
        for (path, text) in files {
            let path = root.join(path);
            std::fs::create_dir_all(path.parent().expect("a folder")).expect("writable");
            std::fs::write(path, text).expect("writable");
        }
        root
    }

    #[test]
    fn a_gui_crate_under_the_cli_is_refused() {
        let root = scratch_root(
            "headless",
            &[
                (
                    "crates/core/Cargo.toml",
                    "[dependencies]
glam.workspace = true
",
                ),
                (
                    "crates/pictures/Cargo.toml",
                    "[dependencies]
ecolor.workspace = true
",
                ),
                (
                    "crates/model/Cargo.toml",
                    "[dependencies]
egui.workspace = true
",
                ),
                (
                    "crates/cli/Cargo.toml",
                    "[dev-dependencies]
edgewise-app.workspace = true
",
                ),
            ],
        );
        let problems = headless_manifests(&root).expect("reads");
        let _ = std::fs::remove_dir_all(&root);
        assert_eq!(problems.len(), 2, "{problems:?}");
        assert!(
            problems[0].starts_with("crates/model/Cargo.toml:2: egui "),
            "{problems:?}"
        );
        assert!(
            problems[1].starts_with("crates/cli/Cargo.toml:2: edgewise-app "),
            "{problems:?}"
        );
    }

    #[test]
    fn a_member_without_a_layer_is_refused() {
        let root = scratch_root(
            "members",
            &[(
                "Cargo.toml",
                "[workspace]\nmembers = [\n    \"crates/core\",\n    \"crates/extra\",\n    \"crates/xtask\",\n]\n",
            )],
        );
        let problems = members_have_layers(&root).expect("reads");
        let _ = std::fs::remove_dir_all(&root);
        assert_eq!(problems.len(), 1, "{problems:?}");
        assert!(
            problems[0].contains("crates/extra has no layer"),
            "{problems:?}"
        );
    }

    #[test]
    fn column_like_names_are_the_distinctive_ones() {
        for name in [
            "left_predecessor",
            "Left Predecessor",
            "leftPredecessor",
            "pairEdge",
        ] {
            assert!(is_column_like(name), "{name}");
        }
        for name in ["face", "next", "left face", "a_b_c", "Hello world!", "x"] {
            assert!(!is_column_like(name), "{name}");
        }
    }

    #[test]
    fn an_impl_outside_app_is_found() {
        let tokens = lexer::tokens(
            "struct A;\nimpl Default for EdgewiseApp { }\nimpl A {}\nfn f(g: impl Fn(&EdgewiseApp)) {}",
        );
        let module = vec!["tables".to_owned()];
        let problems = app_impls("crates/app/src/tables.rs", &module, &tokens);
        assert_eq!(problems.len(), 1, "{problems:?}");
        assert!(
            problems[0].starts_with("crates/app/src/tables.rs:2:"),
            "{problems:?}"
        );
        let module = vec!["app".to_owned(), "tabs".to_owned()];
        assert!(app_impls("crates/app/src/app/tabs.rs", &module, &tokens).is_empty());
    }
}
