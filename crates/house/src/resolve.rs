//! A path followed to the module that defines the name it ends in.
//!
//! The path is read segment by segment from where it starts (`crate`,
//! `self`, `super`, or a name of the module it is written in). A segment
//! naming a child module steps into it; one naming an item the module
//! defines ends the walk there, so enum variants and associated items
//! (`crate::Lang::En`, `super::Conductor::new`) land on the type's module;
//! one naming a `use` binding follows that path (a re-export, renamed or
//! not, of any visibility) and goes on from where it leads; one found in
//! none of these is looked up in the modules the module globs. A path that
//! ends on a module names that module. A name no module of the crate
//! defines (made by a macro, say) is taken as defined where it was looked
//! up, the module the path names, so no arrow is lost.
//!
//! Re-exports that lead round a loop (not valid Rust) stop after
//! [`MAX_STEPS`] bindings followed.

use crate::scope::{Binding, Scopes};
use crate::tree::CrateTree;

/// The most `use` bindings and globs followed for one path.
const MAX_STEPS: usize = 32;

/// Where a path leads.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) enum Resolved {
    /// The path names a module itself.
    Module(Vec<String>),
    /// The path names an item (or a variant or associated item of one)
    /// defined in this module.
    Defined(Vec<String>),
    /// The name is another crate's.
    Outside,
}

impl Resolved {
    /// The module whose file the path depends on, if it is in this crate.
    pub(crate) fn module(self) -> Option<Vec<String>> {
        match self {
            Resolved::Module(m) | Resolved::Defined(m) => Some(m),
            Resolved::Outside => None,
        }
    }
}

/// Follows paths through one crate's modules.
pub(crate) struct Resolver<'a> {
    pub tree: &'a CrateTree,
    pub scopes: &'a Scopes,
}

impl Resolver<'_> {
    /// Where `segments`, written in module `here`, lead; `None` when they
    /// start at no name of this crate (a local name, another crate's path).
    pub(crate) fn resolve(&self, here: &[String], segments: &[String]) -> Option<Resolved> {
        self.follow(here, segments, 0)
    }

    fn follow(&self, here: &[String], segments: &[String], steps: usize) -> Option<Resolved> {
        if steps > MAX_STEPS {
            return None;
        }
        let first = segments.first()?;
        let (mut module, rest) = match first.as_str() {
            "crate" => (Vec::new(), &segments[1..]),
            "self" => (here.to_vec(), &segments[1..]),
            "super" => {
                let ups = segments.iter().take_while(|s| *s == "super").count();
                let kept = here.len().checked_sub(ups)?;
                (here[..kept].to_vec(), &segments[ups..])
            }
            _ => (here.to_vec(), segments),
        };
        let anchored = rest.len() < segments.len();
        for (i, name) in rest.iter().enumerate() {
            let last = i + 1 == rest.len();
            match self.step(&module, name, last, steps) {
                Some(Resolved::Module(inner)) => module = inner,
                Some(other) => return Some(other),
                None if i == 0 && !anchored => return None,
                None => return Some(Resolved::Defined(module)),
            }
        }
        Some(Resolved::Module(module))
    }

    /// What `name` means in `module`; `last` when nothing follows it, so
    /// an item of that name is meant before a module of the same name.
    fn step(&self, module: &[String], name: &str, last: bool, steps: usize) -> Option<Resolved> {
        let child = [module, &[name.to_string()]].concat();
        let scope = self.scopes.get(module);
        let defined = scope.is_some_and(|s| s.defs.contains(name));
        if self.tree.modules.contains_key(&child) && !(last && defined) {
            return Some(Resolved::Module(child));
        }
        if defined {
            return Some(Resolved::Defined(module.to_vec()));
        }
        let scope = scope?;
        if let Some(binding) = scope.bindings.get(name) {
            return Some(match binding {
                Binding::Outside => Resolved::Outside,
                Binding::Path(path) => self
                    .follow(module, path, steps + 1)
                    .unwrap_or(Resolved::Outside),
            });
        }
        scope
            .globs
            .iter()
            .find_map(|glob| match self.follow(module, glob, steps + 1)? {
                Resolved::Module(globbed) => self.step(&globbed, name, last, steps + 1),
                _ => None,
            })
    }
}
