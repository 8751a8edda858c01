//! The algorithms the Algorithm menu offers: the shipped library plus
//! whatever the user loads. A later algorithm with the same name and
//! structure replaces the earlier one, so a student can fix and reload.

use edgewise_core::schema::Structure;
use std::sync::Arc;

use edgewise_core::lang::{self, Algorithm};

/// Where an algorithm came from, for the menu.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Origin {
    Library,
    /// Loaded by the user: a file name, "editor" or "page".
    User(String),
}

/// One menu entry.
#[derive(Clone, Debug)]
pub struct Entry {
    pub algorithm: Arc<Algorithm>,
    pub origin: Origin,
}

/// Every algorithm known, in load order.
#[derive(Clone, Debug, Default)]
pub struct AlgorithmLibrary {
    entries: Vec<Entry>,
}

impl AlgorithmLibrary {
    /// The shipped library. Its files are checked by core's tests, so a
    /// failure here is a bug; it is logged and the library left empty rather
    /// than stopping the app.
    pub fn shipped() -> Self {
        let mut library = Self::default();
        match lang::library::load() {
            Ok(programs) => {
                for program in programs {
                    library.add(&program, &Origin::Library);
                }
            }
            Err(message) => log::error!("the algorithm library does not compile: {message}"),
        }
        library
    }

    /// Compiles `source` and adds its algorithms; returns their names, or
    /// the rendered errors (with `file` in front of each location).
    pub fn load(&mut self, source: &str, file: &str) -> Result<Vec<String>, String> {
        let program = lang::compile_rendered(source, Some(file))?;
        Ok(self.add(&program, &Origin::User(file.to_owned())))
    }

    /// Adds compiled algorithms, replacing same-named ones of the same
    /// structure in place (so the menu order stays put).
    pub fn add(&mut self, program: &lang::Program, origin: &Origin) -> Vec<String> {
        let mut names = Vec::new();
        for algorithm in &program.algorithms {
            let entry = Entry {
                algorithm: Arc::clone(algorithm),
                origin: origin.clone(),
            };
            match self.entries.iter_mut().find(|e| {
                e.algorithm.name == algorithm.name && e.algorithm.structure == algorithm.structure
            }) {
                Some(existing) => *existing = entry,
                None => self.entries.push(entry),
            }
            names.push(algorithm.name.clone());
        }
        names
    }

    pub fn entries(&self) -> &[Entry] {
        &self.entries
    }

    /// The algorithm called `name` for `structure`: exact case first, then
    /// ignoring case.
    pub fn find(&self, name: &str, structure: Structure) -> Option<&Arc<Algorithm>> {
        let of_structure = || {
            self.entries
                .iter()
                .filter(move |e| e.algorithm.structure == structure)
        };
        of_structure()
            .find(|e| e.algorithm.name == name)
            .or_else(|| of_structure().find(|e| e.algorithm.name.eq_ignore_ascii_case(name)))
            .map(|e| &e.algorithm)
    }
    /// [`Self::find`], explaining a miss: the algorithm is written for the
    /// other structure, or there is none of that name.
    pub fn find_or_explain(
        &self,
        name: &str,
        structure: Structure,
    ) -> Result<Arc<Algorithm>, String> {
        if let Some(algorithm) = self.find(name, structure) {
            return Ok(Arc::clone(algorithm));
        }
        if self.exists_anywhere(name) {
            return Err(format!(
                "`{name}` is written for the {} structure and the mesh is {}; switch the structure to run it",
                structure.other().prose(),
                structure.prose()
            ));
        }
        Err(format!(
            "there is no algorithm called `{name}`; the Algorithm menu lists them"
        ))
    }

    /// Whether an algorithm of this name exists for some structure at all.
    pub fn exists_anywhere(&self, name: &str) -> bool {
        self.entries
            .iter()
            .any(|e| e.algorithm.name.eq_ignore_ascii_case(name))
    }

    /// The user's own algorithms' source files, for saving: each distinct
    /// source once, in load order.
    pub fn user_sources(&self) -> Vec<Arc<str>> {
        let mut sources: Vec<Arc<str>> = Vec::new();
        for entry in &self.entries {
            if matches!(entry.origin, Origin::User(_))
                && !sources
                    .iter()
                    .any(|s| Arc::ptr_eq(s, &entry.algorithm.source))
            {
                sources.push(Arc::clone(&entry.algorithm.source));
            }
        }
        sources
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const MINE: &str = "algorithm vertexAdjacentEdge(v : Vertex) : HalfEdge;\n\
        var e : Edge;\nbegin\n  e := v.incidentEdge;\n  e.mark\nend\n";

    #[test]
    fn the_shipped_library_has_both_structures() {
        let library = AlgorithmLibrary::shipped();
        for structure in [Structure::WingedEdge, Structure::HalfEdge] {
            let found = library
                .find("vertexAdjacentEdge", structure)
                .expect("shipped");
            assert_eq!(found.structure, structure);
        }
        assert!(
            library
                .find("VERTEXADJACENTEDGE", Structure::HalfEdge)
                .is_some()
        );
        assert!(library.find("nothing", Structure::HalfEdge).is_none());
    }

    #[test]
    fn a_later_algorithm_replaces_the_same_name_and_structure() {
        let mut library = AlgorithmLibrary::shipped();
        let count = library.entries().len();
        let names = library.load(MINE, "mine.alg").expect("compiles");
        assert_eq!(names, ["vertexAdjacentEdge"]);
        assert_eq!(library.entries().len(), count, "replaced, not added");
        let half = library
            .find("vertexAdjacentEdge", Structure::HalfEdge)
            .expect("present");
        assert_eq!(half.code.len(), 4, "the new, shorter one: {:?}", half.code);
        let winged = library
            .find("vertexAdjacentEdge", Structure::WingedEdge)
            .expect("present");
        assert!(winged.code.len() > 4, "the winged-edge one is untouched");
        assert_eq!(library.user_sources().len(), 1);
    }

    #[test]
    fn a_broken_file_adds_nothing_and_says_where() {
        let mut library = AlgorithmLibrary::default();
        let err = library
            .load(
                "algorithm a(v : Vertex);\nbegin\n  v.mark\n  x := 1\nend",
                "bad.alg",
            )
            .expect_err("does not compile");
        assert!(err.contains("bad.alg:"), "{err}");
        assert!(library.entries().is_empty());
    }
}
