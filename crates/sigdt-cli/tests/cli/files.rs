//! Output files: extension inference, atomic replacement, refusing to overwrite the input,
//! special files, symbolic links and broken pipes.

use super::*;

#[test]
fn output_file_and_extension_inference() {
    let dir = tempdir();
    write_points(dir.path(), "square.xy", &square());
    let read = |name: &str| fs::read_to_string(dir.path().join(name)).unwrap();
    sigdt_in(dir.path(), &["reconstruct", "square.xy", "-o", "out.svg"], None).ok().stdout_is("");
    assert!(read("out.svg").starts_with("<svg") || read("out.svg").starts_with("<?xml"));
    sigdt_in(dir.path(), &["reconstruct", "square.xy", "--output", "out.wkt"], None).ok();
    assert!(read("out.wkt").starts_with("POLYGON (("), "{}", read("out.wkt"));
    // An explicit --format wins over the extension; no extension means edges.
    let args = ["reconstruct", "square.xy", "-o", "out.svg", "--format", "edges"];
    sigdt_in(dir.path(), &args, None).ok();
    assert_eq!(read("out.svg"), SQUARE_EDGES);
    sigdt_in(dir.path(), &["reconstruct", "square.xy", "-o", "result"], None).ok();
    assert_eq!(read("result"), SQUARE_EDGES);
    // `.png` is the picture; an extension that names no format is refused, not filled
    // with edge text.
    sigdt_in(dir.path(), &["reconstruct", "square.xy", "-o", "out.png"], None).ok();
    assert!(fs::read(dir.path().join("out.png")).unwrap().starts_with(b"\x89PNG\r\n"));
    for name in ["out.jpg", "out.result"] {
        let run = sigdt_in(dir.path(), &["reconstruct", "square.xy", "-o", name], None);
        assert!(run.usage_error().stderr.contains("names no output format"), "{run}");
        assert!(!dir.path().join(name).exists());
    }
    let args = ["reconstruct", "square.xy", "-o", "out.result", "--format", "edges"];
    sigdt_in(dir.path(), &args, None).ok();
    assert_eq!(read("out.result"), SQUARE_EDGES);
    // `-o -` is stdout.
    sigdt_in(dir.path(), &["reconstruct", "square.xy", "-o", "-"], None)
        .ok()
        .stdout_is(SQUARE_EDGES);
    assert_no_temporary_files(dir.path());
}

#[test]
fn output_in_missing_directory() {
    let dir = tempdir();
    write_points(dir.path(), "square.xy", &square());
    let args = ["reconstruct", "square.xy", "-o", "missing/out.edges"];
    sigdt_in(dir.path(), &args, None).error(&["missing"]);
    assert!(!dir.path().join("missing").exists());
    fs::create_dir(dir.path().join("adir")).unwrap();
    sigdt_in(dir.path(), &["reconstruct", "square.xy", "-o", "adir"], None).error(&["adir"]);
}

#[test]
fn output_equal_to_input_is_refused() {
    let dir = tempdir();
    let input = write_points(dir.path(), "square.xy", &square());
    let before = fs::read(&input).unwrap();
    fs::create_dir(dir.path().join("sub")).unwrap();
    let input_abs = input.to_str().unwrap().to_string();
    for out in ["square.xy", "./sub/../square.xy", input_abs.as_str()] {
        sigdt_in(dir.path(), &["reconstruct", "square.xy", "-o", out], None).error(&["input"]);
        sigdt_in(dir.path(), &["graph", "square.xy", "--kind", "dt", "-o", out], None)
            .error(&["input"]);
        assert_eq!(fs::read(&input).unwrap(), before, "input changed (-o {out})");
    }
    #[cfg(unix)]
    {
        std::os::unix::fs::symlink(&input, dir.path().join("link.xy")).unwrap();
        sigdt_in(dir.path(), &["reconstruct", "link.xy", "-o", "square.xy"], None)
            .error(&["input"]);
        sigdt_in(dir.path(), &["reconstruct", "square.xy", "-o", "link.xy"], None)
            .error(&["input"]);
        assert_eq!(fs::read(&input).unwrap(), before);
    }
    assert_no_temporary_files(dir.path());
}

#[test]
fn the_files_beside_an_input_shapefile_are_not_overwritten() {
    // Issue 47, O2: `-o s.prj` replaced the input's .prj (a sidecar is input too).
    let dir = tempdir();
    let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/gis");
    for ext in ["shp", "shx", "dbf", "prj", "cpg"] {
        fs::copy(data.join(format!("sigma_27700.{ext}")), dir.path().join(format!("s.{ext}")))
            .unwrap();
    }
    let prj = fs::read(dir.path().join("s.prj")).unwrap();
    for out in ["s.prj", "s.dbf", "./s.shx"] {
        let run = sigdt_in(dir.path(), &["reconstruct", "s.shp", "-o", out], None);
        run.error(&["belongs with the input Shapefile; refusing to overwrite it"]);
    }
    assert_eq!(fs::read(dir.path().join("s.prj")).unwrap(), prj);
    sigdt_in(dir.path(), &["reconstruct", "s.shp", "-o", "s.wkt"], None).expect(0);
}

#[test]
fn failed_run_leaves_existing_output_untouched() {
    let dir = tempdir();
    fs::write(dir.path().join("bad.xy"), "0 0\n1 0\n1 oops\n").unwrap();
    let out = dir.path().join("out.edges");
    let precious = b"precious\ncontent\n";
    fs::write(&out, precious).unwrap();
    sigdt_in(dir.path(), &["reconstruct", "bad.xy", "-o", "out.edges"], None).error(&["bad.xy:3:"]);
    sigdt_in(dir.path(), &["reconstruct", "nope.xy", "-o", "out.edges"], None).error(&["nope.xy"]);
    sigdt_in(dir.path(), &["graph", "bad.xy", "--kind", "dt", "-o", "out.edges"], None)
        .error(&["bad.xy"]);
    sigdt_in(dir.path(), &["reconstruct", "-", "-o", "out.edges"], Some("1 nan\n"))
        .error(&["<stdin>:1:"]);
    assert_eq!(fs::read(&out).unwrap(), precious, "a failed run changed the existing output");
    assert_no_temporary_files(dir.path());
    // A successful run replaces it.
    write_points(dir.path(), "square.xy", &square());
    sigdt_in(dir.path(), &["reconstruct", "square.xy", "-o", "out.edges"], None).ok();
    assert_eq!(fs::read_to_string(&out).unwrap(), SQUARE_EDGES);
    assert_no_temporary_files(dir.path());
}

#[test]
fn broken_pipe_is_quiet_success() {
    let dir = tempdir();
    write_points(dir.path(), "big.xy", &circle(20_000, 100.0));
    for read_first_line in [false, true] {
        let mut child = sigdt_command()
            .args(["reconstruct", "big.xy"])
            .current_dir(dir.path())
            .stdin(Stdio::null())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .expect("cannot start sigdt");
        let stdout = child.stdout.take().expect("stdout is piped");
        if read_first_line {
            let mut line = String::new();
            BufReader::new(stdout).read_line(&mut line).unwrap();
            assert_eq!(line, "0 1\n");
        } else {
            drop(stdout);
        }
        let out = child.wait_with_output().unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(
            out.status.success() && stderr.is_empty(),
            "closed pipe (after a line: {read_first_line}): status {:?}\n--- stderr ---\n{stderr}",
            out.status
        );
    }
}

#[cfg(unix)]
#[test]
fn special_files_and_symlinks_as_output() {
    use std::os::unix::fs::FileTypeExt;
    let dir = tempdir();
    write_points(dir.path(), "square.xy", &square());
    // `/dev/null` is written in place, never replaced by a regular file.
    sigdt_in(dir.path(), &["reconstruct", "square.xy", "-o", "/dev/null"], None).ok();
    let meta = fs::metadata("/dev/null").unwrap();
    assert!(meta.file_type().is_char_device(), "/dev/null is no longer a device");
    // A symbolic link is written through: the link stays, its target gets the output.
    fs::write(dir.path().join("target.edges"), "old\n").unwrap();
    std::os::unix::fs::symlink("target.edges", dir.path().join("link.edges")).unwrap();
    sigdt_in(dir.path(), &["reconstruct", "square.xy", "-o", "link.edges"], None).ok();
    let link = fs::symlink_metadata(dir.path().join("link.edges")).unwrap();
    assert!(link.file_type().is_symlink(), "the link was replaced");
    assert_eq!(fs::read_to_string(dir.path().join("target.edges")).unwrap(), SQUARE_EDGES);
    assert_no_temporary_files(dir.path());
}

#[cfg(unix)]
#[test]
fn a_read_only_file_is_refused_and_a_dangling_link_is_written_through() {
    use std::os::unix::fs::PermissionsExt;
    let dir = tempdir();
    write_points(dir.path(), "square.xy", &square());
    // Mode 444: a rename would replace it (it needs only the folder's permission), so it is
    // refused, even for root, and left as it was.
    let locked = dir.path().join("locked.edges");
    fs::write(&locked, "keep\n").unwrap();
    fs::set_permissions(&locked, fs::Permissions::from_mode(0o444)).unwrap();
    sigdt_in(dir.path(), &["reconstruct", "square.xy", "-o", "locked.edges"], None)
        .error(&["locked.edges: the file is read-only; refusing to replace it"]);
    assert_eq!(fs::read_to_string(&locked).unwrap(), "keep\n");
    // A dangling link: the link stays, and its target is created (as `>` would).
    std::os::unix::fs::symlink("sub/new.edges", dir.path().join("dangling.edges")).unwrap();
    fs::create_dir(dir.path().join("sub")).unwrap();
    sigdt_in(dir.path(), &["reconstruct", "square.xy", "-o", "dangling.edges"], None).ok();
    let link = fs::symlink_metadata(dir.path().join("dangling.edges")).unwrap();
    assert!(link.file_type().is_symlink(), "the dangling link was replaced");
    assert_eq!(fs::read_to_string(dir.path().join("sub/new.edges")).unwrap(), SQUARE_EDGES);
    assert_no_temporary_files(dir.path());
    assert_no_temporary_files(&dir.path().join("sub"));
}

#[cfg(unix)]
#[test]
fn help_and_version_that_cannot_be_written_fail() {
    for args in [&["--help"][..], &["reconstruct", "--help"], &["--version"]] {
        let full = fs::File::create("/dev/full").unwrap();
        let status = sigdt_command()
            .args(args)
            .stdout(full)
            .stderr(std::process::Stdio::null())
            .status()
            .unwrap();
        assert_eq!(status.code(), Some(1), "sigdt {} > /dev/full", args.join(" "));
    }
    sigdt(&["--version"]).expect(0);
}

#[cfg(unix)]
#[test]
fn a_run_stopped_while_writing_leaves_no_temporary_file() {
    let dir = tempdir();
    fs::write(dir.path().join("dt.edges"), "old\n").unwrap();
    for signal in ["TERM", "INT", "HUP"] {
        // A release build writes the edges of 200,000 points in about 0.1 s, which a busy
        // machine can miss: when the run ends before the signal lands, try again with
        // four times as many points. Only a run that was stopped is judged.
        let stopped = [200_000, 800_000, 3_200_000]
            .into_iter()
            .any(|points| stop_while_writing(dir.path(), points, signal));
        assert!(stopped, "SIG{signal}: every run finished before it could be stopped");
    }
}

/// Runs `sigdt graph --kind dt` on `count` scattered points into `dt.edges` (which holds
/// "old") and sends `signal` once its temporary file appears. Returns false when the run
/// ended first (it must then have written the file whole); otherwise checks that it exited
/// with 130, left no temporary file and kept "old".
#[cfg(unix)]
fn stop_while_writing(dir: &Path, count: usize, signal: &str) -> bool {
    use std::process::{Command, Stdio};
    let mut rng = 0x2545_f491_4f6c_dd1d_u64;
    let mut uniform = || {
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        (rng >> 11) as f64 / (1u64 << 53) as f64
    };
    let points: Vec<[f64; 2]> = (0..count).map(|_| [uniform(), uniform()]).collect();
    write_points(dir, "cloud.xy", &points);
    let mut child = sigdt_command()
        .args(["graph", "cloud.xy", "--kind", "dt", "-o", "dt.edges"])
        .current_dir(dir)
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let tmp = |d: &Path| {
        fs::read_dir(d).unwrap().any(|e| e.unwrap().file_name().to_string_lossy().ends_with(".tmp"))
    };
    let finished_first = |status: std::process::ExitStatus| {
        assert_eq!(status.code(), Some(0), "{count} points: {status:?}");
        assert_no_temporary_files(dir);
        let edges = fs::read_to_string(dir.join("dt.edges")).unwrap();
        assert!(edges.lines().count() > 2 * count, "{count} points: the edges are not whole");
        fs::write(dir.join("dt.edges"), "old\n").unwrap();
        false
    };
    // Wait for the temporary file, then stop the process while it writes.
    let start = std::time::Instant::now();
    while !tmp(dir) {
        if let Some(status) = child.try_wait().unwrap() {
            return finished_first(status);
        }
        assert!(start.elapsed().as_secs() < 120, "no temporary file appeared");
        std::thread::sleep(std::time::Duration::from_micros(200));
    }
    let pid = child.id().to_string();
    Command::new("kill").args([&format!("-{signal}"), &pid]).status().unwrap();
    let status = child.wait().unwrap();
    if status.code() == Some(0) {
        return finished_first(status);
    }
    assert_eq!(status.code(), Some(130), "SIG{signal}: {status:?}");
    assert_no_temporary_files(dir);
    assert_eq!(fs::read_to_string(dir.join("dt.edges")).unwrap(), "old\n");
    true
}
