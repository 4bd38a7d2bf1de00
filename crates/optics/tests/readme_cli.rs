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

/// A row of `docs/time.md`'s answer table whose first cell starts with
/// `what`: its "measured" cell's numbers of seconds (`104 s to build, 112
/// s to run` is `[104, 112]`).
fn measured_seconds(time_md: &str, what: &str) -> Vec<f64> {
    let row = time_md
        .lines()
        .find(|line| line.starts_with(&format!("| {what}")))
        .unwrap_or_else(|| panic!("docs/time.md has no row `{what}`"));
    let measured = row.split('|').nth(3).expect("a measured cell");
    let words: Vec<&str> = measured.split_whitespace().collect();
    words
        .windows(2)
        .filter(|w| w[1] == "s" || w[1] == "s)")
        .filter_map(|w| w[0].trim_start_matches('(').parse().ok())
        .collect()
}

/// The seconds of a stage of `docs/time.md`'s table of CI's stages.
fn stage_seconds(time_md: &str, stage: &str) -> f64 {
    let row = time_md
        .lines()
        .find(|line| line.starts_with(&format!("| {stage}")))
        .unwrap_or_else(|| panic!("docs/time.md has no stage `{stage}`"));
    row.trim_end_matches('|')
        .rsplit('|')
        .next()
        .and_then(|cell| cell.trim().parse().ok())
        .unwrap_or_else(|| panic!("no seconds in {row}"))
}

/// Seconds in words, to the nearest half minute.
fn about(seconds: f64) -> String {
    const WORDS: [&str; 13] = [
        "no", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten",
        "eleven", "twelve",
    ];
    let halves = (seconds / 30.0).round() as usize;
    match halves {
        0..=2 => "about a minute".to_owned(),
        3 => "about a minute and a half".to_owned(),
        h if h % 2 == 1 => format!("about {} and a half minutes", WORDS[h / 2]),
        h => format!("about {} minutes", WORDS[h / 2]),
    }
}

/// The README's set-up times, download size and Rust version are the
/// measured ones: each phrase is computed from `docs/time.md`'s tables
/// (where the command that measured it is named) and the workspace's
/// `rust-version`, and must stand in the README as computed. A new
/// measurement that moves a time by half a minute fails here until the
/// README says it.
#[test]
fn readme_set_up_numbers_are_the_measured_ones() {
    let time_md = std::fs::read_to_string(root().join("docs/time.md")).unwrap();
    let cargo = std::fs::read_to_string(root().join("Cargo.toml")).unwrap();
    let rust = cargo
        .lines()
        .find_map(|l| l.strip_prefix("rust-version = "))
        .expect("the workspace's rust-version")
        .trim_matches('"');
    let first = measured_seconds(&time_md, "the first run on a fresh machine");
    let later = measured_seconds(&time_md, "`optics validate`, the references current");
    let tests =
        stage_seconds(&time_md, "the tests built") + stage_seconds(&time_md, "the tests run");
    let megabytes = time_md
        .split(" MB installed")
        .next()
        .and_then(|before| before.rsplit(['(', ' ']).next())
        .expect("docs/time.md states the download");
    let phrases = [
        format!("Rust {rust} or newer"),
        format!("builds the suite ({} on 2 cores)", about(first[0])),
        format!("downloads about {megabytes} MB of Python packages"),
        format!("then checks ({})", about(first[1])),
        format!("later runs take {}", about(later[0])),
        format!("{} on 2 cores from a clean checkout", about(tests)),
    ];
    let prose = readme().split_whitespace().collect::<Vec<_>>().join(" ");
    for phrase in phrases {
        assert!(
            prose.contains(&phrase),
            "the README should say \"{phrase}\", as docs/time.md measures it"
        );
    }
}

/// Seconds read as words: the rounding the README's phrases take.
#[test]
fn seconds_are_said_to_the_nearest_half_minute() {
    for (seconds, words) in [
        (40.0, "about a minute"),
        (95.0, "about a minute and a half"),
        (112.0, "about two minutes"),
        (540.0, "about nine minutes"),
        (555.0, "about nine and a half minutes"),
        (590.0, "about ten minutes"),
        (165.0, "about three minutes"),
        (170.0, "about three minutes"),
        (200.0, "about three and a half minutes"),
    ] {
        assert_eq!(about(seconds), words, "{seconds} s");
    }
}
