//! `optics`: the suite's command line (see the library's docs).

fn main() -> std::process::ExitCode {
    optics::main_entry()
}
