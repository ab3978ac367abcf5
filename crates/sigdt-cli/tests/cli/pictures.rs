//! `sigdt render` and `sigdt view`: files written, layers present, errors clear. The viewer
//! itself is driven in a real browser by `python/tests/test_viewer.py`.

use super::*;

fn bundled(name: &str) -> String {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/inputs").join(name);
    path.to_str().unwrap().to_string()
}

#[test]
fn render_writes_svg_and_png_with_the_layers_asked_for() {
    let dir = tempdir();
    let (xy, gt) = (bundled("glyph_e_reversed.xy"), bundled("glyph_e_reversed.gt"));
    let args =
        ["render", &xy, "--gt", &gt, "--layers", "points,dt,sig,sigdt,sigdt2,boundary,result,gt"];
    // The default method, SIG-AUTO, has no inflating step of its own to draw.
    sigdt_in(dir.path(), &[&args[..], &["-o", "auto.svg"]].concat(), None)
        .error(&["method sig-auto has no inflating step", "--method sig-connect2d"]);
    let args = [&args[..], &["--method", "sig-connect2d"]].concat();
    sigdt_in(dir.path(), &[&args[..], &["-o", "all.svg"]].concat(), None).ok();
    let svg = fs::read_to_string(dir.path().join("all.svg")).unwrap();
    assert!(svg.starts_with("<svg") || svg.starts_with("<?xml"), "{}", &svg[..80]);
    for label in ["SIGDT", "missing 0", "extra 0"] {
        assert!(svg.contains(label), "legend lacks {label:?}");
    }
    sigdt_in(dir.path(), &["render", &xy, "-o", "pic.png"], None).ok();
    let png = fs::read(dir.path().join("pic.png")).unwrap();
    assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
}

#[test]
fn render_and_view_errors_are_clear() {
    let dir = tempdir();
    let xy = bundled("glyph_sigma.xy");
    sigdt_in(dir.path(), &["render", &xy, "--layers", "gt", "-o", "x.svg"], None)
        .error(&["needs --gt"]);
    sigdt_in(
        dir.path(),
        &["render", &xy, "--layers", "boundary", "--method", "crust", "-o", "x.svg"],
        None,
    )
    .error(&["no inflating"]);
    fs::write(dir.path().join("bad.gt"), "0 1\n1 9999\n").unwrap();
    let run = sigdt_in(dir.path(), &["view", &xy, "--gt", "bad.gt", "-o", "v.html"], None);
    run.error(&["--gt bad.gt:2:", "9999"]);
    let run = sigdt_in(dir.path(), &["view", &xy, "-o", "v.txt"], None);
    run.usage_error();
    assert!(run.stderr.contains(".html or .htm"), "{run}");
    sigdt_in(dir.path(), &["view", &xy, "-o", "v.htm"], None).expect(0);
    let run = sigdt_in(dir.path(), &["render", &xy, "-o", "p.jpg"], None);
    run.usage_error();
    assert!(run.stderr.contains(".svg or .png") && run.stderr.contains("JPEG"), "{run}");
    assert!(!dir.path().join("p.jpg").exists());
    std::fs::remove_file(dir.path().join("v.htm")).unwrap();
    sigdt_in(dir.path(), &["render", &xy, "--layers", "nope", "-o", "x.svg"], None).usage_error();
    assert!(!dir.path().join("x.svg").exists() && !dir.path().join("v.html").exists());
}

#[test]
fn view_embeds_the_data_and_nothing_external() {
    let dir = tempdir();
    let xy = bundled("glyph_e_reversed.xy");
    // The replay of inflating and sculpting is SIG-CONNECT2D's.
    let replay = ["view", &xy, "--method", "sig-connect2d", "-o", "v.html"];
    sigdt_in(dir.path(), &replay, None).ok();
    let html = fs::read_to_string(dir.path().join("v.html")).unwrap();
    assert!(html.contains("glyph_e_reversed (70 points)") && html.contains("\"step_triangles\""));
    // The one address is the namespace of exported SVG pictures, which loads nothing.
    let html = html.replace("xmlns=\"http://www.w3.org/2000/svg\"", "");
    for external in ["<script src", "http://", "https://"] {
        assert!(!html.contains(external), "the page refers to {external}");
    }
    // A method without inflating or sculpting: no trace, still a page.
    sigdt_in(dir.path(), &["view", &xy, "--method", "peel", "-o", "p.html"], None).ok();
    assert!(fs::read_to_string(dir.path().join("p.html")).unwrap().contains("\"trace\": null"));
    // The default method, SIG-AUTO, has no replay.
    sigdt_in(dir.path(), &["view", &xy, "-o", "a.html"], None).ok();
    let auto = fs::read_to_string(dir.path().join("a.html")).unwrap();
    assert!(auto.contains("\"method\": \"sig-auto\"") && auto.contains("\"trace\": null"));
    // --no-steps leaves the replay out.
    let without_steps = ["view", &xy, "--method", "sig-connect2d", "--no-steps", "-o", "n.html"];
    sigdt_in(dir.path(), &without_steps, None).ok();
    let without = fs::read_to_string(dir.path().join("n.html")).unwrap();
    assert!(without.contains("\"trace\": null") && without.len() < html.len());
}

#[test]
fn coordinates_near_the_f64_limit_neither_collapse_a_picture_nor_get_written_as_inf() {
    let dir = tempdir();
    let huge = [[-1.7e308, 0.0], [1.7e308, 0.0], [0.0, 1.7e308]];
    write_points(dir.path(), "huge.xy", &huge);
    sigdt_in(dir.path(), &["render", "huge.xy", "-o", "huge.svg"], None).ok();
    let svg = fs::read_to_string(dir.path().join("huge.svg")).unwrap();
    let height: f64 =
        svg.split("height=\"").nth(1).unwrap().split('"').next().unwrap().parse().unwrap();
    assert!(height > 200.0, "picture of height {height}");
    // A diagonal of 141: moves up to 1.4e310, beyond f64::MAX.
    let big: Vec<[f64; 2]> = square().iter().map(|p| p.map(|v| 100.0 * v)).collect();
    write_points(dir.path(), "sq.xy", &big);
    sigdt_in(dir.path(), &["perturb", "sq.xy", "--noise", "1e308", "-o", "p.xy"], None)
        .error(&["noise level s 1e308 moves point 0 beyond the finite range"]);
    assert!(!dir.path().join("p.xy").exists());
}
