//! What the README shows is what runs: each `console` block's commands (in
//! the README and `docs/cli.md`) print exactly the lines below them, the Rust snippet builds against the
//! crates and prints what it says, and the Python snippet, through `optics
//! batch`, prints what it says.

use std::path::{Path, PathBuf};
use std::process::Command;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn readme() -> String {
    std::fs::read_to_string(root().join("README.md")).expect("the README reads")
}

/// The fenced blocks of `text` whose info string is `lang`, in order.
fn blocks(text: &str, lang: &str) -> Vec<String> {
    let mut found = Vec::new();
    let mut current: Option<String> = None;
    for line in text.lines() {
        match (&mut current, line.trim_start().strip_prefix("```")) {
            (None, Some(info)) if info.trim() == lang => current = Some(String::new()),
            (Some(block), Some("")) => {
                found.push(std::mem::take(block));
                current = None;
            }
            (Some(block), _) => {
                block.push_str(line);
                block.push('\n');
            }
            _ => {}
        }
    }
    found
}

/// A transcript's commands and what each prints: `$ optics …` lines, each
/// followed by its output up to the next `$`.
fn transcript(block: &str) -> Vec<(Vec<String>, String)> {
    let mut runs: Vec<(Vec<String>, String)> = Vec::new();
    for line in block.lines() {
        if let Some(command) = line.strip_prefix("$ ") {
            let words: Vec<String> = command.split_whitespace().map(str::to_owned).collect();
            assert_eq!(words[0], "optics", "a transcript runs optics: {line}");
            runs.push((words[1..].to_vec(), String::new()));
        } else {
            let (_, printed) = runs.last_mut().expect("a transcript opens with a command");
            printed.push_str(line);
            printed.push('\n');
        }
    }
    runs
}

/// What the text says a snippet prints: the rest of its line after
/// `prints: `.
fn says_it_prints(snippet: &str) -> String {
    let at = snippet
        .find("prints: ")
        .expect("the snippet says what it prints");
    let rest = &snippet[at + "prints: ".len()..];
    rest.lines().next().unwrap_or_default().to_owned()
}

#[test]
fn documented_transcripts_print_what_they_show() {
    let cli = std::fs::read_to_string(root().join("docs/cli.md")).expect("docs/cli.md reads");
    let readme_commands = blocks(&readme(), "console")
        .iter()
        .map(|b| transcript(b).len())
        .sum::<usize>();
    assert!(
        readme_commands >= 3,
        "the README's try-it block shows {readme_commands} commands"
    );
    let transcripts = [blocks(&readme(), "console"), blocks(&cli, "console")].concat();
    // The transcripts name the checkout's files by relative path and write
    // their outputs beside them: they run in a scratch folder that sees the
    // checkout's `crates`, so nothing they write lands in the checkout.
    let scratch = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("transcripts");
    let _ = std::fs::remove_dir_all(&scratch);
    std::fs::create_dir_all(&scratch).unwrap();
    std::os::unix::fs::symlink(root().join("crates"), scratch.join("crates")).unwrap();
    let mut commands = 0;
    for block in transcripts {
        for (args, shown) in transcript(&block) {
            let output = Command::new(env!("CARGO_BIN_EXE_optics"))
                .args(&args)
                .current_dir(&scratch)
                .output()
                .expect("optics runs");
            let printed = String::from_utf8_lossy(&output.stdout).into_owned()
                + &String::from_utf8_lossy(&output.stderr);
            // A blank line between two commands is the transcript's, not
            // their output's.
            let (printed, shown) = (printed.trim_end(), shown.trim_end());
            assert_eq!(printed, shown, "optics {}", args.join(" "));
            commands += 1;
        }
    }
    assert!(
        commands > readme_commands,
        "docs/cli.md shows transcripts too"
    );
}

/// The transcript reader fails a block whose output differs: a changed
/// line is not the same text.
#[test]
fn a_transcript_is_read_as_commands_and_their_lines() {
    let block = "$ optics quiz f0 --n 1.4\nline one\nline two\n$ optics reflect\nthree\n";
    let runs = transcript(block);
    assert_eq!(runs.len(), 2);
    assert_eq!(runs[0].0, ["quiz", "f0", "--n", "1.4"]);
    assert_eq!(runs[0].1, "line one\nline two\n");
    assert_ne!(runs[1].1, "three \n");
}

/// The README's dependency line and program, as a crate of its own against
/// the checkout's `radiometry`, build and print what the program says.
#[test]
fn readme_rust_snippet_builds_against_the_crates_and_prints_what_it_says() {
    let text = readme();
    let manifest = blocks(&text, "toml")
        .into_iter()
        .next()
        .expect("a [dependencies] block");
    let program = blocks(&text, "rust")
        .into_iter()
        .next()
        .expect("a Rust program");
    let radiometry = root().join("crates/radiometry").canonicalize().unwrap();
    let dependencies = manifest.replace(
        "\"optics/crates/radiometry\"",
        &format!("{:?}", radiometry.display().to_string()),
    );
    assert_ne!(
        dependencies, manifest,
        "the snippet names the radiometry crate's path"
    );
    let target = PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
    let dir = target.join("readme-consumer");
    std::fs::create_dir_all(dir.join("src")).unwrap();
    let cargo_toml = format!(
        "[package]\nname = \"readme-consumer\"\nversion = \"0.0.0\"\nedition = \"2021\"\n\n\
         {dependencies}\n[workspace]\n"
    );
    std::fs::write(dir.join("Cargo.toml"), cargo_toml).unwrap();
    std::fs::write(dir.join("src/main.rs"), &program).unwrap();
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".to_owned());
    let output = Command::new(cargo)
        .args(["run", "--quiet", "--offline"])
        .current_dir(&dir)
        .env("CARGO_TARGET_DIR", target.join("readme-consumer-target"))
        .output()
        .expect("cargo runs");
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(output.status.success(), "the consumer crate: {stderr}");
    let printed = String::from_utf8_lossy(&output.stdout);
    assert_eq!(printed.trim_end(), says_it_prints(&program));
}

/// The README's Python snippet, with `optics` on the PATH, prints what it
/// says. It needs Python with numpy: the pinned `.venv` that `optics
/// validate` and CI set up, else a `python3` that has numpy; without
/// either it says so and checks nothing.
#[test]
fn readme_python_snippet_prints_what_it_says_through_optics_batch() {
    let snippet = blocks(&readme(), "python")
        .into_iter()
        .next()
        .expect("a Python snippet");
    let venv = root().join(".venv/bin/python");
    let has_numpy = |python: &Path| {
        Command::new(python)
            .args(["-c", "import numpy"])
            .output()
            .is_ok_and(|o| o.status.success())
    };
    let python = [venv, PathBuf::from("python3")]
        .into_iter()
        .find(|p| has_numpy(p));
    let Some(python) = python else {
        eprintln!("skipped: no Python with numpy here (`optics validate` sets up .venv)");
        return;
    };
    let bin = Path::new(env!("CARGO_BIN_EXE_optics"))
        .parent()
        .unwrap()
        .to_owned();
    let path = std::env::join_paths(std::iter::once(bin).chain(std::env::split_paths(
        &std::env::var_os("PATH").unwrap_or_default(),
    )))
    .unwrap();
    let output = Command::new(python)
        .args(["-c", &snippet])
        .env("PATH", path)
        .output()
        .expect("python runs");
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(output.status.success(), "the Python snippet: {stderr}");
    let printed = String::from_utf8_lossy(&output.stdout);
    assert_eq!(printed.trim_end(), says_it_prints(&snippet));
}
