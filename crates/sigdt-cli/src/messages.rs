//! What goes to stderr: notes, the one-line error message, and usage errors that only a
//! command can see.
//!
//! Data goes to stdout or files ([`output`](crate::output)); everything meant for the person
//! at the terminal comes through here.

use std::fmt;
use std::io::{self, Write};

use clap::error::ErrorKind;

/// Writes `text` and a newline to stderr; a closed stderr is ignored.
pub fn note(text: &str) {
    let _ = writeln!(io::stderr().lock(), "{text}");
}

/// The one-line message for an error: its own text, then each cause whose text it does not
/// already contain, all on one line (the readers' errors are made the same way).
pub use sigdt_io::one_line;

/// A usage error that clap cannot express, such as a flag allowed only with some value of
/// another: `main` has clap report it for `command`, with exit status 2.
#[derive(Debug)]
pub struct UsageError {
    /// The subcommand whose usage is shown.
    pub command: &'static str,
    /// What clap calls the problem.
    pub kind: ErrorKind,
    /// The message, without clap's `error: ` prefix.
    pub message: String,
}

impl UsageError {
    /// Has clap report the error with the usage of its subcommand of `cli`, the way it
    /// reports its own usage errors, and exits with status 2.
    pub fn exit(&self, mut cli: clap::Command) -> ! {
        cli.build();
        match cli.find_subcommand_mut(self.command) {
            Some(sub) => sub.error(self.kind, &self.message).exit(),
            None => cli.error(self.kind, &self.message).exit(),
        }
    }
}

impl fmt::Display for UsageError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for UsageError {}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn causes_join_one_line_without_repeating() {
        let err = anyhow::anyhow!("a.xy: no such file").context("cannot read\n the input");
        assert_eq!(one_line(&err), "cannot read the input: a.xy: no such file");
        let err = anyhow::anyhow!("a.xy:3: bad").context("a.xy:3: bad");
        assert_eq!(one_line(&err), "a.xy:3: bad");
    }
}
