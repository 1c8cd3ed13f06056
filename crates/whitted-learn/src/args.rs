//! The `whitted` command line's errors in one line.
//!
//! Course book: [The instructor's guide](../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

/// Parses the command line. `--help` and `--version` print and exit 0; any other problem is
/// printed as one line `error: …` (clap's own first line, with the list that follows it when
/// it ends in a colon, such as the arguments missing) with exit status 2.
#[must_use]
pub fn parse_args<T: clap::Parser>() -> T {
    match T::try_parse() {
        Ok(args) => args,
        Err(e) if !e.use_stderr() => {
            // --help, --version: not errors
            let _ = e.print();
            std::process::exit(0);
        }
        Err(e) if e.kind() == clap::error::ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => {
            // a bare `whitted`: the help says what to ask for
            let _ = e.print();
            std::process::exit(2);
        }
        Err(e) => {
            eprintln!("{} (see --help)", one_line(&e.render().to_string()));
            std::process::exit(2);
        }
    }
}

/// clap's error text as one line: its first line, and when that ends in a colon, the list
/// that follows it (up to the usage).
#[must_use]
pub fn one_line(text: &str) -> String {
    let mut lines = text.lines().map(str::trim).filter(|l| !l.is_empty());
    let mut line = lines
        .next()
        .unwrap_or("error: invalid arguments")
        .to_string();
    if line.ends_with(':') {
        let list: Vec<&str> = lines.take_while(|l| !l.starts_with("Usage:")).collect();
        line = format!("{line} {}", list.join(", "));
    }
    line
}
