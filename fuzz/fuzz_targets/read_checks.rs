//! What the reader targets (`read_wkt`, `read_geojson`, `read_npy`, `read_table`) check of
//! `sigdt_io::read_points_bytes`, included by each with `#[path]` (not a target itself).
//!
//! - No panic (implicit).
//! - `Ok`: at most `max_points` points, every coordinate finite.
//! - `Err`: the message, as the command line and the Python package show it, is one line
//!   (no `'\n'`), names the file (`name` appears in it), holds no control character (input is
//!   echoed through `sigdt_io::text::quoted`, which escapes them), and is at most [`MAX_MESSAGE`]
//!   characters long, not counting the JSON path of a GeoJSON message (see [`json_path`]).
//!
//! With the environment variable `SIGDT_FUZZ_KNOWN` set (to anything), a message that holds
//! one of the target's `known` texts, which mark findings reported and not yet fixed, is only
//! checked to name the file: a long run can go on past them and look for anything else.
//! Without it every message is checked, and the findings' seeds fail.

use std::sync::OnceLock;

use sigdt_io::Error as ReadError;

/// The most points a target asks for: small enough that libFuzzer's inputs (4096 bytes by
/// default) can hold more, so that "more than N points" is reached too.
pub const MAX_POINTS: usize = 100;

/// The longest message allowed, in characters. A message quotes at most two pieces of input
/// (a header name and a field of a table; one token elsewhere), each through
/// `sigdt_io::text::quoted`, which shows at most 40 characters, each escaped to at most 8
/// (`\u{3000}`; control characters, at most `\u{9f}`, take 6), plus its quotes and
/// `...' (N characters)`: at most 2 + 320 + 30 = 352 characters a piece. Two pieces, the
/// file name, a line number and the fixed text (under 200 characters) stay under 1000.
pub const MAX_MESSAGE: usize = 1000;

/// The longest JSON path allowed in a GeoJSON message, in bytes: a step a level of nesting
/// (serde_json stops at 127), each at most `.coordinates` or an index of 20 digits in
/// brackets (22 bytes).
pub const MAX_JSON_PATH: usize = 127 * 22;

/// The JSON path of a GeoJSON message, `{name}: GeoJSON: PATH: ...`, such as
/// `features[3].geometry.coordinates[0]`. It grows with the nesting: 62
/// `GeometryCollection`s give a path of 868 bytes (seed
/// `read_geojson/deep-geometrycollection-path.geojson`, whose message has 1233 characters),
/// so [`MAX_MESSAGE`] is checked without it, and the path is checked to be made of member
/// names and indices only (no input echoed in it) and at most [`MAX_JSON_PATH`] long.
pub fn json_path<'m>(msg: &'m str, name: &str) -> Option<&'m str> {
    let rest = msg.strip_prefix(name)?.strip_prefix(": GeoJSON: ")?;
    let path = &rest[..rest.find(": ")?];
    (path != "the document").then_some(path)
}

/// The message of `err` as shown to a person: `sigdt: <message>` on stderr, or the Python
/// exception's text.
pub fn message(err: &ReadError) -> String {
    match err {
        ReadError::Io(io) => io.to_string(),
        ReadError::Usage(message) | ReadError::Data(message) => message.clone(),
    }
}

/// Whether `SIGDT_FUZZ_KNOWN` is set: messages of known findings are let through.
fn known_allowed() -> bool {
    static ALLOWED: OnceLock<bool> = OnceLock::new();
    *ALLOWED.get_or_init(|| std::env::var_os("SIGDT_FUZZ_KNOWN").is_some())
}

/// Reads `bytes` named `name` with `columns` and checks the answer; `known` marks the
/// messages of known findings. See the module docs.
#[allow(dead_code)] // read_gpkg reads whole files through check_result
pub fn check(bytes: &[u8], name: &str, columns: Option<&str>, known: &[&str]) {
    check_result(sigdt_io::read_points_bytes(bytes, name, columns, MAX_POINTS), name, known);
}

/// Checks a reader's answer for the input named `name` (module docs).
pub fn check_result(
    read: Result<Vec<[f64; 2]>, sigdt_io::Error>,
    name: &str,
    known: &[&str],
) {
    match read {
        Ok(points) => {
            assert!(points.len() <= MAX_POINTS, "{} points, over the limit", points.len());
            assert!(
                points.iter().flatten().all(|c| c.is_finite()),
                "non-finite point read: {points:?}"
            );
        }
        Err(err) => {
            let msg = message(&err);
            assert!(msg.contains(name), "message does not name the file {name}: {err:?}");
            if known_allowed() && known.iter().any(|k| msg.contains(k)) {
                return;
            }
            assert!(!msg.contains('\n'), "message of several lines: {err:?}");
            assert!(!msg.chars().any(|c| c.is_control()), "control character in {err:?}");
            let path = json_path(&msg, name).map_or(0, |path| {
                let plain = |c: char| c.is_ascii_alphanumeric() || matches!(c, '.' | '[' | ']');
                assert!(path.chars().all(plain), "JSON path {path:?} in {err:?}");
                assert!(path.len() <= MAX_JSON_PATH, "JSON path of {} bytes: {err:?}", path.len());
                path.len()
            });
            let chars = msg.chars().count() - path;
            assert!(chars <= MAX_MESSAGE, "message of {chars} characters and a path: {err:?}");
        }
    }
}
