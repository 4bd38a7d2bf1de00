//! Every relative link and image of the documents leads somewhere: the
//! README, `docs/*.md`, `validation/README.md` and the crates' READMEs name
//! files that exist in the checkout (a `#fragment` is not followed).

use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// The documents checked: every `.md` at the root, in `docs/`, in
/// `validation/` and at the top of each crate.
fn documents() -> Vec<PathBuf> {
    let root = root();
    let mut dirs = vec![root.clone(), root.join("docs"), root.join("validation")];
    if let Ok(crates) = std::fs::read_dir(root.join("crates")) {
        dirs.extend(crates.flatten().map(|e| e.path()));
    }
    let mut found = Vec::new();
    for dir in dirs {
        let Ok(entries) = std::fs::read_dir(&dir) else {
            continue;
        };
        for entry in entries.flatten() {
            let path = entry.path();
            if path.extension().is_some_and(|e| e == "md") {
                found.push(path);
            }
        }
    }
    found.sort();
    found
}

/// The targets of the inline links `[text](target)` and images
/// `![alt](target)` of `text`, outside code spans and fenced blocks.
fn targets(text: &str) -> Vec<String> {
    let mut found = Vec::new();
    let mut fenced = false;
    for line in text.lines() {
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
            continue;
        }
        if fenced {
            continue;
        }
        // Code spans hold examples, not links.
        let prose: String = line
            .split('`')
            .enumerate()
            .filter(|(i, _)| i % 2 == 0)
            .map(|(_, part)| part)
            .collect::<Vec<_>>()
            .join(" ");
        let mut rest = prose.as_str();
        while let Some(i) = rest.find("](") {
            let after = &rest[i + 2..];
            let Some(end) = after.find(')') else { break };
            found.push(after[..end].trim().to_owned());
            rest = &after[end..];
        }
    }
    found
}

fn is_local(target: &str) -> bool {
    !(target.is_empty()
        || target.starts_with('#')
        || target.contains("://")
        || target.starts_with("mailto:"))
}

#[test]
fn every_relative_link_and_image_of_the_documents_exists() {
    let documents = documents();
    assert!(documents.len() >= 5, "{documents:?}");
    let mut broken = Vec::new();
    let mut checked = 0;
    for doc in &documents {
        let text = std::fs::read_to_string(doc).expect("a readable document");
        let dir = doc.parent().expect("a directory");
        for target in targets(&text).into_iter().filter(|t| is_local(t)) {
            let file = target.split('#').next().unwrap_or(&target);
            checked += 1;
            if !dir.join(file).exists() {
                broken.push(format!("{}: {target}", doc.display()));
            }
        }
    }
    assert!(
        checked > 20,
        "only {checked} links found: the parser is broken"
    );
    assert!(
        broken.is_empty(),
        "links to nothing:\n{}",
        broken.join("\n")
    );
}

#[test]
fn the_link_reader_finds_links_and_images_but_not_code() {
    let text = "see [a](docs/a.md#x) and ![b](img/b.png)\n`[c](no.md)` then\n```\n[d](no.md)\n```\n[e](https://x.org)";
    assert_eq!(targets(text), ["docs/a.md#x", "img/b.png", "https://x.org"]);
}
