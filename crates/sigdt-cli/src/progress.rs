//! Progress of one long run (`view`, `render`, `eval`) on stderr: a spinner line naming the stage and
//! the time so far, drawn only when stderr is a terminal and cleared when the run ends, so
//! scripts and pipes see nothing of it.

use std::time::Duration;

use indicatif::{ProgressBar, ProgressStyle};

/// The spinner of one command; dropping it clears the line.
pub struct Stages {
    bar: ProgressBar,
}

impl Stages {
    /// A spinner for `sigdt COMMAND`; hidden unless stderr is a terminal.
    pub fn new(command: &str) -> Stages {
        let bar = ProgressBar::new_spinner();
        let template = format!("{{spinner}} sigdt {command}: {{msg}} ({{elapsed}})");
        bar.set_style(ProgressStyle::with_template(&template).expect("a valid progress template"));
        bar.enable_steady_tick(Duration::from_millis(100));
        Stages { bar }
    }

    /// Names the stage that starts now, for example `triangulating 1,000,000 points`.
    pub fn stage(&self, what: impl Into<String>) {
        self.bar.set_message(what.into());
    }

    /// Writes a note to stderr without the spinner line getting in its way.
    pub fn note(&self, text: &str) {
        self.bar.suspend(|| crate::messages::note(text));
    }
}

impl Drop for Stages {
    fn drop(&mut self) {
        self.bar.finish_and_clear();
    }
}

/// `1234567` as `1,234,567`.
pub fn thousands(n: usize) -> String {
    let digits = n.to_string();
    let mut out = String::with_capacity(digits.len() + digits.len() / 3);
    for (k, c) in digits.chars().enumerate() {
        if k > 0 && (digits.len() - k).is_multiple_of(3) {
            out.push(',');
        }
        out.push(c);
    }
    out
}

/// A file size for people: `49 kB`, `75 MB` (decimal units, rounded up).
pub fn size(bytes: usize) -> String {
    match bytes {
        0..1_000_000 => format!("{} kB", bytes.div_ceil(1000)),
        _ => format!("{} MB", bytes.div_ceil(1_000_000)),
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn size() {
        assert_eq!(super::size(49_307), "50 kB");
        assert_eq!(super::size(999_999), "1000 kB");
        assert_eq!(super::size(74_559_694), "75 MB");
    }

    #[test]
    fn thousands() {
        assert_eq!(super::thousands(0), "0");
        assert_eq!(super::thousands(999), "999");
        assert_eq!(super::thousands(1000), "1,000");
        assert_eq!(super::thousands(1234567), "1,234,567");
    }
}
