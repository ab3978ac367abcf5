//! End-to-end tests of the `sigdt` binary: outputs, formats, exit statuses, error messages,
//! output-file safety and the documented results for degenerate input. With `SIGDT_CLI` set
//! they test that command instead (`make wheel-test`: the wheel's `sigdt` script and
//! `python -m sigdt`).
//!
//! Exit statuses: 0 success, 1 error, 2 usage error. An unknown `--method` is a usage error
//! (2): clap checks it against `Method::ALL` before anything runs.
//!
//! `main.rs` holds the helpers; `results` checks outputs (formats, graphs, degenerate input,
//! help), `formats` the input formats (WKT, GeoJSON, `.npy`, CSV tables, gzip), `errors` the
//! error messages and exit statuses, `files` output-file safety and broken pipes.

use std::fs;
use std::io::{BufRead, BufReader, Write};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use tempfile::TempDir;

mod bench;
mod determinism;
mod errors;
mod files;
mod formats;
mod gis;
mod groups;
mod limits;
mod pictures;
mod results;

/// What one run of the binary did.
struct Run {
    code: Option<i32>,
    stdout: String,
    stderr: String,
    what: String,
}

impl Run {
    /// Asserts exit status `code`, printing the whole run otherwise.
    fn expect(&self, code: i32) -> &Run {
        assert_eq!(self.code, Some(code), "{}: wrong exit status\n{self}", self.what);
        if code != 0 {
            assert!(!self.stderr.contains("panicked"), "{}: panic\n{self}", self.what);
        }
        self
    }

    /// Asserts success with nothing on stderr.
    fn ok(&self) -> &Run {
        self.expect(0);
        assert_eq!(self.stderr, "", "{}: unexpected stderr\n{self}", self.what);
        self
    }

    /// Asserts an error: status 1, one line `sigdt: ...` on stderr containing every
    /// string in `needles`, nothing on stdout.
    fn error(&self, needles: &[&str]) -> &Run {
        self.expect(1);
        assert!(
            self.stderr.starts_with("sigdt: ") && self.stderr.lines().count() == 1,
            "{}: expected one line 'sigdt: ...' on stderr\n{self}",
            self.what
        );
        for needle in needles {
            assert!(self.stderr.contains(needle), "{}: stderr lacks {needle:?}\n{self}", self.what);
        }
        assert_eq!(self.stdout, "", "{}: data on stdout despite the error\n{self}", self.what);
        self
    }

    /// Asserts a usage error: status 2, a message on stderr, nothing on stdout.
    fn usage_error(&self) -> &Run {
        self.expect(2);
        assert!(!self.stderr.is_empty(), "{}: usage error without a message\n{self}", self.what);
        assert_eq!(self.stdout, "", "{}: data on stdout\n{self}", self.what);
        self
    }

    /// Asserts that stdout is exactly `expected`.
    fn stdout_is(&self, expected: &str) -> &Run {
        assert_eq!(
            self.stdout, expected,
            "{}: wrong stdout\n--- expected ---\n{expected}--- got ---\n{}--- stderr ---\n{}",
            self.what, self.stdout, self.stderr
        );
        self
    }
}

impl std::fmt::Display for Run {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let stdout: String = self.stdout.chars().take(2000).collect();
        write!(
            f,
            "--- exit status ---\n{:?}\n--- stdout (first 2000 chars) ---\n{stdout}\n--- stderr ---\n{}",
            self.code, self.stderr
        )
    }
}

/// The command under test: the cargo-built binary, or the command in `SIGDT_CLI` (a program
/// and its leading arguments, separated by spaces), such as the Python package's `sigdt`
/// script or `python -m sigdt`, which must behave exactly the same.
fn sigdt_command() -> Command {
    match std::env::var("SIGDT_CLI") {
        Ok(command) if !command.trim().is_empty() => {
            let mut words = command.split_whitespace();
            let mut c = Command::new(words.next().expect("a program"));
            c.args(words);
            c
        }
        _ => Command::new(env!("CARGO_BIN_EXE_sigdt")),
    }
}

/// Runs `sigdt args...` in `dir` with `stdin` as standard input (empty if `None`).
fn sigdt_in(dir: &Path, args: &[&str], stdin: Option<&str>) -> Run {
    let mut child = sigdt_command()
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("cannot start the sigdt binary");
    let mut pipe = child.stdin.take().expect("stdin is piped");
    // The binary may exit without reading (usage errors): ignore a broken pipe here.
    let _ = pipe.write_all(stdin.unwrap_or("").as_bytes());
    drop(pipe);
    let out = child.wait_with_output().expect("cannot wait for sigdt");
    Run {
        code: out.status.code(),
        stdout: String::from_utf8_lossy(&out.stdout).into_owned(),
        stderr: String::from_utf8_lossy(&out.stderr).into_owned(),
        what: format!("sigdt {}", args.join(" ")),
    }
}

/// Runs `sigdt args...` in a fresh empty directory.
fn sigdt(args: &[&str]) -> Run {
    sigdt_in(tempdir().path(), args, None)
}

fn tempdir() -> TempDir {
    tempfile::tempdir().expect("cannot create a temporary directory")
}

/// Writes `points` as `x y` lines (shortest round-trip decimals) to `dir/name`.
fn write_points(dir: &Path, name: &str, points: &[[f64; 2]]) -> PathBuf {
    let text: String = points.iter().map(|[x, y]| format!("{x:?} {y:?}\n")).collect();
    let path = dir.join(name);
    fs::write(&path, text).expect("cannot write a test input");
    path
}

fn edges_text(edges: &[[usize; 2]]) -> String {
    edges.iter().map(|[i, j]| format!("{i} {j}\n")).collect()
}

fn square() -> Vec<[f64; 2]> {
    vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
}

/// `n` points on a circle of radius `r`, counter-clockwise from angle 0.
fn circle(n: usize, r: f64) -> Vec<[f64; 2]> {
    (0..n)
        .map(|i| {
            let a = std::f64::consts::TAU * i as f64 / n as f64;
            [r * a.cos(), r * a.sin()]
        })
        .collect()
}

/// The sorted edges of the cycle `0, 1, ..., n-1`.
fn cycle_edges(n: usize) -> Vec<[usize; 2]> {
    let mut edges: Vec<_> = (0..n).map(|i| [i.min((i + 1) % n), i.max((i + 1) % n)]).collect();
    edges.sort_unstable();
    edges
}

/// Two triangles 9 apart; every graph's edge count follows by hand (see `graph_kinds`).
fn two_triangles() -> Vec<[f64; 2]> {
    vec![[0.0, 0.0], [1.0, 0.0], [0.5, 1.0], [10.0, 0.0], [11.0, 0.0], [10.5, 1.0]]
}

const SQUARE_EDGES: &str = "0 1\n0 3\n1 2\n2 3\n";

fn assert_no_temporary_files(dir: &Path) {
    let names: Vec<String> = fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert!(!names.iter().any(|n| n.ends_with(".tmp")), "temporary file left behind: {names:?}");
}

/// The labelled curves of the repository (`data/curves`, beside `data/inputs`).
fn labelled_curves() -> PathBuf {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/curves");
    assert!(
        dir.is_dir(),
        "test data missing: expected {} (data/curves of the repository)",
        dir.display()
    );
    dir
}
