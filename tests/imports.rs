//! The files of every crate form a tree of uses, never a circle: in each
//! crate of the workspace (the shared crates, every chapter and its
//! figures crate), no file uses an item of a file that, directly or
//! through others, uses an item of it.
//!
//! A use is a `use` of the crate's own items (`crate::…`, `super::…`, a
//! child module) or such a path in the code, resolved through re-exports
//! to the file that defines the item: `use crate::Bvh` in a chapter uses
//! the file defining `Bvh`, not `lib.rs` that re-exports it. A `lib.rs`
//! or `mod.rs` re-exporting its modules' items does not use them; test
//! modules (`#[cfg(test)]`) are left out. Items are found by parsing each
//! file with `syn`; a macro's body is not read.
use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

use syn::visit::Visit;

/// A module path from the crate's root: `["bvh", "build"]`.
type ModPath = Vec<String>;

/// What one module holds: where it is written, and what it names.
#[derive(Default)]
struct Module {
    file: PathBuf,
    /// Is its file a `lib.rs`, `main.rs` or `mod.rs` (a folder's index)?
    index: bool,
    children: BTreeSet<String>,
    /// Items defined here (functions, types, traits, constants, macros).
    defined: BTreeSet<String>,
    /// Names brought in by `use`: name → the path as written.
    bindings: BTreeMap<String, Vec<String>>,
    /// `use x::*` paths, as written.
    globs: Vec<Vec<String>>,
    /// Paths this module uses, as written, and whether each is a `pub use`.
    uses: Vec<(Vec<String>, bool)>,
}

/// Every module of one crate, by path.
#[derive(Default)]
struct Crate {
    modules: BTreeMap<ModPath, Module>,
}

impl Crate {
    /// Reads the crate whose root file is `root` (`src/lib.rs`).
    fn read(root: &Path) -> Crate {
        let mut krate = Crate::default();
        krate.read_file(root, Vec::new());
        krate
    }

    fn read_file(&mut self, file: &Path, path: ModPath) {
        let text = std::fs::read_to_string(file)
            .unwrap_or_else(|e| panic!("{}: {e}", file.display()));
        let parsed = syn::parse_file(&text)
            .unwrap_or_else(|e| panic!("{}: {e}", file.display()));
        let stem = file.file_stem().and_then(|s| s.to_str()).unwrap_or("");
        let index = matches!(stem, "lib" | "main" | "mod");
        let dir = file.parent().unwrap();
        let children_dir = if index {
            dir.to_path_buf()
        } else {
            dir.join(stem)
        };
        self.read_items(&parsed.items, file, index, &children_dir, path);
    }

    fn read_items(
        &mut self, items: &[syn::Item], file: &Path, index: bool,
        children_dir: &Path, path: ModPath,
    ) {
        let mut module = Module {
            file: file.to_path_buf(),
            index,
            ..Module::default()
        };
        let mut nested = Vec::new();
        for item in items {
            match item {
                syn::Item::Mod(m) if is_test(&m.attrs) => {}
                syn::Item::Mod(m) => {
                    let name = m.ident.to_string();
                    module.children.insert(name.clone());
                    nested.push((m, name));
                }
                syn::Item::Use(u) => {
                    let public = !matches!(u.vis, syn::Visibility::Inherited);
                    let mut flat = Vec::new();
                    flatten(&u.tree, Vec::new(), &mut flat);
                    for (segments, binding) in flat {
                        match binding {
                            Some(name) => {
                                module.bindings.insert(name, segments.clone())
                            }
                            None => {
                                module.globs.push(segments.clone());
                                None
                            }
                        };
                        module.uses.push((segments, public));
                    }
                }
                other => {
                    if let Some(name) = defined_name(other) {
                        module.defined.insert(name);
                    }
                    let mut paths = Paths::default();
                    paths.visit_item(other);
                    module.uses.extend(paths.0.into_iter().map(|p| (p, false)));
                }
            }
        }
        self.modules.insert(path.clone(), module);
        for (m, name) in nested {
            let mut child = path.clone();
            child.push(name.clone());
            match &m.content {
                // An inline module: part of this file.
                Some((_, items)) => {
                    let dir = children_dir.join(&name);
                    self.read_items(items, file, false, &dir, child);
                }
                None => {
                    let flat = children_dir.join(format!("{name}.rs"));
                    let folder = children_dir.join(&name).join("mod.rs");
                    let found = if flat.is_file() { flat } else { folder };
                    self.read_file(&found, child);
                }
            }
        }
    }

    /// `written`, as written in module `at`, from the crate's root; `None`
    /// for a path of another crate.
    fn absolute(&self, at: &ModPath, written: &[String]) -> Option<ModPath> {
        let module = &self.modules[at];
        let first = written.first()?;
        let mut base = at.clone();
        let rest = match first.as_str() {
            "crate" => {
                base.clear();
                &written[1..]
            }
            "self" => &written[1..],
            "super" => {
                let supers =
                    written.iter().take_while(|s| *s == "super").count();
                base.truncate(base.len().saturating_sub(supers));
                &written[supers..]
            }
            name if module.children.contains(name)
                || module.defined.contains(name) =>
            {
                written
            }
            _ => return None,
        };
        base.extend(rest.iter().cloned());
        Some(base)
    }

    /// The file defining what `path` (from the root) names, through
    /// modules, bindings and glob imports.
    fn defining_file(&self, path: &[String], depth: usize) -> Option<&Path> {
        if depth > 16 {
            return None;
        }
        let mut at: ModPath = Vec::new();
        let mut i = 0;
        while i < path.len()
            && self.modules.contains_key(&extend(&at, &path[i]))
        {
            at.push(path[i].clone());
            i += 1;
        }
        let module = &self.modules[&at];
        if i == path.len() || module.defined.contains(&path[i]) {
            return Some(&module.file);
        }
        let through = |written: &[String], tail: &[String]| {
            let mut target = self.absolute(&at, written)?;
            target.extend(tail.iter().cloned());
            self.defining_file(&target, depth + 1)
        };
        if let Some(written) = module.bindings.get(&path[i]) {
            return through(written, &path[i + 1..]);
        }
        module
            .globs
            .iter()
            .find_map(|glob| through(glob, &path[i..]))
    }

    /// Every use between two files: (from, to) → a path that makes it.
    fn edges(&self) -> BTreeMap<(PathBuf, PathBuf), String> {
        let mut edges = BTreeMap::new();
        for (at, module) in &self.modules {
            for (written, public) in &module.uses {
                if module.index && *public {
                    continue; // a re-export, not a use
                }
                let Some(path) = self.absolute(at, written) else {
                    continue;
                };
                let Some(to) = self.defining_file(&path, 0) else {
                    continue;
                };
                if to != module.file {
                    edges
                        .entry((module.file.clone(), to.to_path_buf()))
                        .or_insert_with(|| written.join("::"));
                }
            }
        }
        edges
    }
}

fn extend(at: &ModPath, name: &str) -> ModPath {
    let mut path = at.clone();
    path.push(name.to_string());
    path
}

/// Is it `#[cfg(test)]`?
fn is_test(attrs: &[syn::Attribute]) -> bool {
    attrs.iter().any(|a| {
        a.path().is_ident("cfg")
            && a.meta.require_list().is_ok_and(|l| {
                l.tokens.to_string().split_whitespace().next() == Some("test")
            })
    })
}

/// A `use` tree as paths, each with the name it binds (`None`: a glob).
fn flatten(
    tree: &syn::UseTree, prefix: Vec<String>,
    out: &mut Vec<(Vec<String>, Option<String>)>,
) {
    let with = |name: String| {
        let mut path = prefix.clone();
        path.push(name);
        path
    };
    match tree {
        syn::UseTree::Path(p) => {
            flatten(&p.tree, with(p.ident.to_string()), out)
        }
        syn::UseTree::Name(n) if n.ident == "self" => {
            let name = prefix.last().cloned();
            out.push((prefix.clone(), name));
        }
        syn::UseTree::Name(n) => {
            out.push((with(n.ident.to_string()), Some(n.ident.to_string())))
        }
        syn::UseTree::Rename(r) => {
            out.push((with(r.ident.to_string()), Some(r.rename.to_string())))
        }
        syn::UseTree::Glob(_) => out.push((prefix.clone(), None)),
        syn::UseTree::Group(g) => {
            for tree in &g.items {
                flatten(tree, prefix.clone(), out);
            }
        }
    }
}

/// The name an item defines, if it defines one a path can name.
fn defined_name(item: &syn::Item) -> Option<String> {
    let ident = match item {
        syn::Item::Const(i) => &i.ident,
        syn::Item::Enum(i) => &i.ident,
        syn::Item::Fn(i) => &i.sig.ident,
        syn::Item::Static(i) => &i.ident,
        syn::Item::Struct(i) => &i.ident,
        syn::Item::Trait(i) => &i.ident,
        syn::Item::Type(i) => &i.ident,
        syn::Item::Union(i) => &i.ident,
        syn::Item::Macro(i) => i.ident.as_ref()?,
        _ => return None,
    };
    Some(ident.to_string())
}

/// The paths in code that start at this crate: `crate::…`, `super::…`,
/// `self::…` (a path through a child module is found by its `use`).
#[derive(Default)]
struct Paths(Vec<Vec<String>>);

impl<'ast> Visit<'ast> for Paths {
    fn visit_path(&mut self, path: &'ast syn::Path) {
        let segments: Vec<String> =
            path.segments.iter().map(|s| s.ident.to_string()).collect();
        if segments.len() > 1
            && matches!(segments[0].as_str(), "crate" | "super" | "self")
        {
            self.0.push(segments);
        }
        syn::visit::visit_path(self, path);
    }

    fn visit_item_mod(&mut self, _: &'ast syn::ItemMod) {
        // a module inside a function body: rare, and not ours to follow
    }
}

/// The circles among `edges`: each a set of two or more files that reach
/// one another (Tarjan's strongly connected components).
fn circles(edges: &BTreeMap<(PathBuf, PathBuf), String>) -> Vec<Vec<PathBuf>> {
    let mut next: BTreeMap<&PathBuf, Vec<&PathBuf>> = BTreeMap::new();
    for (from, to) in edges.keys() {
        next.entry(from).or_default().push(to);
        next.entry(to).or_default();
    }
    struct State<'a> {
        next: &'a BTreeMap<&'a PathBuf, Vec<&'a PathBuf>>,
        index: BTreeMap<&'a PathBuf, usize>,
        low: BTreeMap<&'a PathBuf, usize>,
        stack: Vec<&'a PathBuf>,
        on_stack: BTreeSet<&'a PathBuf>,
        found: Vec<Vec<PathBuf>>,
    }
    fn visit<'a>(s: &mut State<'a>, v: &'a PathBuf) {
        let n = s.index.len();
        s.index.insert(v, n);
        s.low.insert(v, n);
        s.stack.push(v);
        s.on_stack.insert(v);
        for &w in &s.next[v] {
            if !s.index.contains_key(w) {
                visit(s, w);
                let low = s.low[v].min(s.low[w]);
                s.low.insert(v, low);
            } else if s.on_stack.contains(w) {
                let low = s.low[v].min(s.index[w]);
                s.low.insert(v, low);
            }
        }
        if s.low[v] == s.index[v] {
            let mut component = Vec::new();
            loop {
                let w = s.stack.pop().unwrap();
                s.on_stack.remove(w);
                component.push(w.clone());
                if w == v {
                    break;
                }
            }
            if component.len() > 1 {
                component.sort();
                s.found.push(component);
            }
        }
    }
    let mut state = State {
        next: &next,
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: Vec::new(),
        on_stack: BTreeSet::new(),
        found: Vec::new(),
    };
    for v in next.keys() {
        if !state.index.contains_key(v) {
            visit(&mut state, v);
        }
    }
    state.found
}

/// The root file of every crate of the workspace.
fn crate_roots(workspace: &Path) -> Vec<PathBuf> {
    let mut roots = Vec::new();
    let patterns = [("crates", ""), ("chapters", ""), ("chapters", "figures")];
    for (top, sub) in patterns {
        let mut dirs: Vec<PathBuf> = std::fs::read_dir(workspace.join(top))
            .unwrap()
            .map(|e| e.unwrap().path().join(sub))
            .collect();
        dirs.sort();
        for dir in dirs {
            let lib = dir.join("src/lib.rs");
            let main = dir.join("src/main.rs");
            if lib.is_file() {
                roots.push(lib);
            } else if main.is_file() {
                roots.push(main);
            }
        }
    }
    roots
}

#[test]
fn no_file_uses_a_file_that_uses_it() {
    let workspace = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let workspace = workspace.canonicalize().unwrap();
    let roots = crate_roots(&workspace);
    assert!(roots.len() >= 30, "{} crates found", roots.len());
    let mut report = String::new();
    let mut files = 0;
    for root in &roots {
        let krate = Crate::read(root);
        files += krate
            .modules
            .values()
            .map(|m| &m.file)
            .collect::<BTreeSet<_>>()
            .len();
        let edges = krate.edges();
        for circle in circles(&edges) {
            report.push_str("circle:\n");
            for ((from, to), path) in &edges {
                if circle.contains(from) && circle.contains(to) {
                    let short = |p: &Path| {
                        p.strip_prefix(&workspace)
                            .unwrap()
                            .display()
                            .to_string()
                    };
                    report.push_str(&format!(
                        "  {} -> {} ({path})\n",
                        short(from),
                        short(to)
                    ));
                }
            }
        }
    }
    assert!(files > 250, "{files} files read");
    assert!(report.is_empty(), "{report}");
}

/// The checker itself finds a circle of two files, through a re-export
/// of the crate's root, and none where the uses run one way.
#[test]
fn a_circle_through_a_re_export_is_found() {
    let dir = std::env::temp_dir()
        .join(format!("raystep-imports-{}", std::process::id()));
    let src = dir.join("src");
    std::fs::create_dir_all(&src).unwrap();
    let write = |name: &str, text: &str| {
        std::fs::write(src.join(name), text).unwrap();
    };
    write("lib.rs", "mod a;\nmod b;\npub use a::A;\npub use b::B;\n");
    write("a.rs", "use crate::B;\npub struct A(B);\n");
    write("b.rs", "pub struct B;\n");
    let one_way = circles(&Crate::read(&src.join("lib.rs")).edges());
    write("b.rs", "pub struct B;\nfn f() -> crate::A { todo!() }\n");
    let both_ways = circles(&Crate::read(&src.join("lib.rs")).edges());
    std::fs::remove_dir_all(&dir).unwrap();
    assert!(one_way.is_empty(), "{one_way:?}");
    assert_eq!(both_ways.len(), 1, "{both_ways:?}");
    assert_eq!(both_ways[0], vec![src.join("a.rs"), src.join("b.rs")]);
}
