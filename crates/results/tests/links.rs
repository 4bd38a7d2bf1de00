//! Every relative link and image of the documents leads somewhere: the
//! README, `docs/*.md`, `validation/README.md` and the crates' READMEs name
//! files that exist in the checkout, and a `#fragment` into a Markdown
//! document (another, or the same one) names one of its headings as GitHub
//! writes their anchors, or an explicit `<a id>`.

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
    for line in prose_lines(text) {
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

/// The lines of `text` outside fenced code blocks.
fn prose_lines(text: &str) -> impl Iterator<Item = &str> {
    let mut fenced = false;
    text.lines().filter(move |line| {
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
            return false;
        }
        !fenced
    })
}

/// GitHub's anchor of a heading's text: its rendered words (code spans'
/// contents, links' texts) lower-cased, every character but a letter, a
/// digit, `_`, `-` or a space dropped, and each space a `-`.
fn slug(heading: &str) -> String {
    let mut text = String::new();
    let mut rest = heading;
    // A link `[words](target)` shows its words only.
    while let Some(open) = rest.find('[') {
        text += &rest[..open];
        let after = &rest[open + 1..];
        match after.find("](").and_then(|close| {
            let tail = &after[close + 2..];
            tail.find(')').map(|end| (close, &tail[end + 1..]))
        }) {
            Some((close, tail)) => {
                text += &after[..close];
                rest = tail;
            }
            None => {
                text.push('[');
                rest = after;
            }
        }
    }
    text += rest;
    text.to_lowercase()
        .chars()
        .filter(|c| c.is_alphanumeric() || matches!(c, '_' | '-' | ' '))
        .map(|c| if c == ' ' { '-' } else { c })
        .collect()
}

/// The anchors of a Markdown document: its headings' slugs, a repeated one
/// numbered `-1`, `-2`, … as GitHub numbers them, and its `<a id="…">` and
/// `<a name="…">`.
fn anchors(text: &str) -> std::collections::HashSet<String> {
    let mut found = std::collections::HashSet::new();
    let mut seen = std::collections::HashMap::<String, usize>::new();
    for line in prose_lines(text) {
        let hashes = line.chars().take_while(|&c| c == '#').count();
        if (1..=6).contains(&hashes) && line[hashes..].starts_with(' ') {
            let base = slug(line[hashes..].trim());
            let n = seen.entry(base.clone()).or_insert(0);
            found.insert(if *n == 0 {
                base.clone()
            } else {
                format!("{base}-{n}")
            });
            *n += 1;
        }
        for key in ["<a id=\"", "<a name=\""] {
            let mut rest = line;
            while let Some(i) = rest.find(key) {
                let after = &rest[i + key.len()..];
                let Some(end) = after.find('"') else { break };
                found.insert(after[..end].to_owned());
                rest = &after[end..];
            }
        }
    }
    found
}

fn is_local(target: &str) -> bool {
    !(target.is_empty() || target.contains("://") || target.starts_with("mailto:"))
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
            let (file, fragment) = match target.split_once('#') {
                Some((file, fragment)) => (file, Some(fragment)),
                None => (target.as_str(), None),
            };
            checked += 1;
            let path = if file.is_empty() {
                doc.clone()
            } else {
                dir.join(file)
            };
            if !path.exists() {
                broken.push(format!("{}: {target}", doc.display()));
                continue;
            }
            let Some(fragment) = fragment else { continue };
            if path.extension().is_some_and(|e| e == "md") {
                let linked = std::fs::read_to_string(&path).expect("a readable document");
                if !anchors(&linked).contains(fragment) {
                    broken.push(format!("{}: {target} (no such heading)", doc.display()));
                }
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
fn anchors_are_githubs_slugs_of_the_headings_numbered_when_repeated() {
    let text = "# Is Schlick good enough?\n## `optics validate`: the report\n\
                ### [The missing light](x.md) — 5.85×\n## Notes\n## Notes\n\
                <a id=\"kept\"></a>\n```\n# not a heading\n```\n#not-a-heading";
    let mut got: Vec<String> = anchors(text).into_iter().collect();
    got.sort();
    assert_eq!(
        got,
        [
            "is-schlick-good-enough",
            "kept",
            "notes",
            "notes-1",
            "optics-validate-the-report",
            "the-missing-light--585",
        ]
    );
}

#[test]
fn the_link_reader_finds_links_and_images_but_not_code() {
    let text = "see [a](docs/a.md#x) and ![b](img/b.png)\n`[c](no.md)` then\n```\n[d](no.md)\n```\n[e](https://x.org)";
    assert_eq!(targets(text), ["docs/a.md#x", "img/b.png", "https://x.org"]);
}

/// The headings' slugs of a Markdown document, in order, repeats kept.
fn heading_slugs(text: &str) -> Vec<String> {
    prose_lines(text)
        .filter_map(|line| {
            let hashes = line.chars().take_while(|&c| c == '#').count();
            ((1..=6).contains(&hashes) && line[hashes..].starts_with(' '))
                .then(|| slug(line[hashes..].trim()))
        })
        .collect()
}

/// No two headings of a document share an anchor: a link to the second
/// would land on the first (GitHub numbers it `-1`, which no reader
/// guesses).
#[test]
fn no_two_headings_of_a_document_share_an_anchor() {
    let mut repeated = Vec::new();
    for path in documents() {
        let text = std::fs::read_to_string(&path).unwrap();
        let mut seen = std::collections::HashSet::new();
        for slug in heading_slugs(&text) {
            if !seen.insert(slug.clone()) {
                repeated.push(format!("{}: #{slug}", path.display()));
            }
        }
    }
    assert!(
        repeated.is_empty(),
        "headings sharing an anchor:\n{}",
        repeated.join("\n")
    );
    let doubled = "## The missing light\n\n### Detail\n\n## The missing light\n";
    assert_eq!(
        heading_slugs(doubled),
        ["the-missing-light", "detail", "the-missing-light"]
    );
}
