//! Errors (exit status 1, one line on stderr) and usage errors (exit status 2).

use super::*;

#[test]
fn missing_input_file_is_named() {
    let dir = tempdir();
    sigdt_in(dir.path(), &["reconstruct", "nope.xy"], None).error(&["nope.xy", "No such file"]);
    sigdt_in(dir.path(), &["graph", "nope.xy", "--kind", "dt"], None).error(&["nope.xy"]);
}

#[test]
fn parse_errors_name_file_and_line() {
    let dir = tempdir();
    let cases = [
        ("token.xy", "0 0\n1 0\n1 zz\n0 1\n", "token.xy:3:", "zz"),
        ("one.xy", "0 0\n1\n1 1\n", "one.xy:2:", "found 1"),
        ("three.xy", "0 0\n1 0\n1 1 7\n", "three.xy:3:", "found 3"),
        ("nan.xy", "0 0\n1 0\nNaN 1\n0 1\n", "nan.xy:3:", "NaN"),
        ("inf.xy", "0 0\n1 0\n1 1\n0 -inf\n", "inf.xy:4:", "inf"),
    ];
    for (name, text, place, detail) in cases {
        fs::write(dir.path().join(name), text).unwrap();
        sigdt_in(dir.path(), &["reconstruct", name], None).error(&[place, detail]);
        sigdt_in(dir.path(), &["graph", name, "--kind", "sigdt"], None).error(&[place]);
    }
    sigdt_in(dir.path(), &["reconstruct", "-"], Some("0 0\n1 x\n")).error(&["<stdin>:2:"]);
}

#[test]
fn usage_errors_exit_2() {
    let dir = tempdir();
    write_points(dir.path(), "square.xy", &square());
    let cases: &[&[&str]] = &[
        &[],
        &["frobnicate"],
        &["reconstruct"],
        &["reconstruct", "square.xy", "--format", "xml"],
        &["reconstruct", "square.xy", "--method", "gathan"],
        &["bench"],
        &["sample", "x.svg"],
        &["perturb", "square.xy"],
        &["sweep", "wobble", "."],
        &["reconstruct", "square.xy", "--bogus"],
        &["graph", "square.xy"],
        &["graph", "square.xy", "--kind", "delaunay"],
        &["graph", "square.xy", "--kind", "knn"],
        &["graph", "square.xy", "--kind", "knn", "-k", "0"],
        &["graph", "square.xy", "--kind", "knn", "-k", "two"],
        &["graph", "square.xy", "--kind", "dt", "-k", "2"],
    ];
    for args in cases {
        sigdt_in(dir.path(), args, None).usage_error();
    }
}
