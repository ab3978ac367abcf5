//! Input size limits: `--max-points` (files and pipes), overlong lines, and that the
//! limit applies to every command that reads points.

use super::*;

#[test]
fn max_points_refuses_at_the_first_line_over_the_limit() {
    let dir = tempdir();
    write_points(dir.path(), "gon.xy", &circle(50, 1.0));
    sigdt_in(dir.path(), &["reconstruct", "gon.xy", "--max-points", "50"], None).ok();
    for command in [
        &["reconstruct", "gon.xy"][..],
        &["graph", "gon.xy", "--kind", "dt"],
        &["view", "gon.xy", "-o", "v.html"],
    ] {
        let args = [command, &["--max-points", "10"]].concat();
        sigdt_in(dir.path(), &args, None).error(&["gon.xy:11:", "more than the 10 points"]);
    }
    let text: String = circle(50, 1.0).iter().map(|[x, y]| format!("{x} {y}\n")).collect();
    sigdt_in(dir.path(), &["--max-points", "20", "reconstruct", "-"], Some(&text))
        .error(&["<stdin>:21:", "--max-points"]);
    sigdt_in(dir.path(), &["reconstruct", "gon.xy", "--max-points", "0"], None).usage_error();
    assert!(!dir.path().join("v.html").exists());
}

#[test]
fn an_overlong_line_on_a_pipe_is_refused_without_reading_it_whole() {
    let line = "1".repeat(3 << 20);
    sigdt(&["reconstruct", "-"]).expect(0);
    sigdt_in(tempdir().path(), &["reconstruct", "-"], Some(&line))
        .error(&["<stdin>:1:", "longer than"]);
}
