//! Rules c and d over one crate's import arrows: a circle of files (a
//! strongly connected component of more than one file, found by Tarjan's
//! algorithm), and an upward import (a file importing a name defined in
//! the file of one of its ancestor modules: the crate root or a parent
//! module file; the parent is the floor above its children). An arrow
//! already ends at the defining file, so a name an ancestor only
//! re-exports is no upward import.

use std::collections::{BTreeMap, BTreeSet};
use std::path::PathBuf;

use crate::imports::Arrow;
use crate::offender::{Offender, Place, Rule};
use crate::tree::CrateTree;

/// Rule d: one offender per (file, ancestor) pair, at the first import,
/// naming every path it imports from there.
pub(crate) fn upward(
    tree: &CrateTree,
    arrows: &[Arrow],
    rel: impl Fn(&PathBuf) -> PathBuf,
) -> Vec<Offender> {
    let mut pairs: BTreeMap<(PathBuf, PathBuf), (usize, Vec<String>)> = BTreeMap::new();
    for arrow in arrows {
        let (Some(from), Some(to)) = (tree.files.get(&arrow.from), tree.files.get(&arrow.to))
        else {
            continue;
        };
        if to.len() < from.len() && from.starts_with(to) {
            let entry = pairs
                .entry((arrow.from.clone(), arrow.to.clone()))
                .or_insert((arrow.line, Vec::new()));
            entry.0 = entry.0.min(arrow.line);
            if !entry.1.contains(&arrow.written) {
                entry.1.push(arrow.written.clone());
            }
        }
    }
    pairs
        .into_iter()
        .map(|((from, to), (line, written))| Offender {
            rule: Rule::UpwardImport,
            place: Place::Import {
                from: rel(&from),
                line,
                to: rel(&to),
                written: written.join("`, `"),
            },
        })
        .collect()
}

/// Rule c: every strongly connected component of more than one file.
pub(crate) fn circles(arrows: &[Arrow], rel: impl Fn(&PathBuf) -> PathBuf) -> Vec<Offender> {
    let mut next: BTreeMap<&PathBuf, BTreeSet<&PathBuf>> = BTreeMap::new();
    for arrow in arrows {
        next.entry(&arrow.from).or_default().insert(&arrow.to);
        next.entry(&arrow.to).or_default();
    }
    let nodes: Vec<&PathBuf> = next.keys().copied().collect();
    let index: BTreeMap<&PathBuf, usize> = nodes.iter().enumerate().map(|(i, n)| (*n, i)).collect();
    let edges: Vec<Vec<usize>> = nodes
        .iter()
        .map(|n| next[n].iter().map(|m| index[m]).collect())
        .collect();
    strongly_connected(&edges)
        .into_iter()
        .filter(|component| component.len() > 1)
        .map(|component| {
            let mut files: Vec<PathBuf> = component.iter().map(|&i| rel(nodes[i])).collect();
            files.sort();
            Offender {
                rule: Rule::ImportCircle,
                place: Place::Circle { files },
            }
        })
        .collect()
}

/// Tarjan's strongly connected components, iteratively (no deep recursion
/// on a long chain of files).
fn strongly_connected(edges: &[Vec<usize>]) -> Vec<Vec<usize>> {
    const UNSEEN: usize = usize::MAX;
    let n = edges.len();
    let (mut index, mut low, mut on_stack) = (vec![UNSEEN; n], vec![0; n], vec![false; n]);
    let (mut stack, mut components, mut counter) = (Vec::new(), Vec::new(), 0);
    for start in 0..n {
        if index[start] != UNSEEN {
            continue;
        }
        // Each frame: a node and how many of its arrows were followed.
        let mut frames = vec![(start, 0)];
        while let Some(&mut (v, ref mut followed)) = frames.last_mut() {
            if *followed == 0 && index[v] == UNSEEN {
                (index[v], low[v]) = (counter, counter);
                counter += 1;
                stack.push(v);
                on_stack[v] = true;
            }
            if let Some(&w) = edges[v].get(*followed) {
                *followed += 1;
                if index[w] == UNSEEN {
                    frames.push((w, 0));
                } else if on_stack[w] {
                    low[v] = low[v].min(index[w]);
                }
                continue;
            }
            frames.pop();
            if let Some(&(parent, _)) = frames.last() {
                low[parent] = low[parent].min(low[v]);
            }
            if low[v] == index[v] {
                let mut component = Vec::new();
                while let Some(w) = stack.pop() {
                    on_stack[w] = false;
                    component.push(w);
                    if w == v {
                        break;
                    }
                }
                components.push(component);
            }
        }
    }
    components
}
