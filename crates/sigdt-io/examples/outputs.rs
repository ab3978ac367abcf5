//! Fingerprints of every method's result on every case of some folders, to check that a
//! change leaves the results unchanged bit for bit.
//!
//! ```text
//! cargo run --release -p sigdt --example outputs -- data/curves data/real > after.txt
//! diff before.txt after.txt
//! ```
//!
//! One line per (case, method): the case's path, the method and a 64-bit FNV-1a hash of the
//! whole `Reconstruction` (its `Debug` text: edges, loops, paths, status, duplicates, points
//! left out, vertices and stats), with the same hash of the Delaunay edges first. Both
//! leaf-elimination settings of SIG-CONNECT2D are covered. A file may stand for a folder;
//! `--full` as the first argument prints the `Debug` text itself.
use sigdt::{Method, Options, Triangulation};
use std::error::Error;
use std::io::Write;
use std::path::PathBuf;

fn main() -> Result<(), Box<dyn Error>> {
    let mut args: Vec<String> = std::env::args().skip(1).collect();
    // `--full`: the `Debug` text itself instead of its hash.
    let full = args.first().is_some_and(|a| a == "--full");
    if full {
        args.remove(0);
    }
    let mut files: Vec<PathBuf> = Vec::new();
    for folder in args {
        let folder = PathBuf::from(folder);
        if folder.is_file() {
            files.push(folder);
            continue;
        }
        for entry in std::fs::read_dir(&folder)? {
            let path = entry?.path();
            if path.extension().is_some_and(|e| e == "xy") {
                files.push(path);
            }
        }
    }
    files.sort();
    let mut out = std::io::BufWriter::new(std::io::stdout().lock());
    for path in &files {
        let points = sigdt_io::text::read_points(path)?;
        let name = path.display();
        let dt = Triangulation::new(&points)?;
        let show = |text: String| if full { text } else { format!("{:016x}", fnv(&text)) };
        writeln!(out, "{name} delaunay {}", show(format!("{:?}", dt.edges())))?;
        let mut runs: Vec<(String, Options)> = Method::ALL
            .iter()
            .map(|&method| (method.to_string(), Options { method, ..Options::default() }))
            .collect();
        runs.push((
            "sig-connect2d/no-leaves".into(),
            Options { method: Method::SigConnect2d, leaf_elimination: false, ..Options::default() },
        ));
        for (label, options) in runs {
            let rec = sigdt::reconstruct(&points, &options)?;
            writeln!(out, "{name} {label} {}", show(format!("{rec:?}")))?;
        }
    }
    out.flush()?;
    Ok(())
}

/// 64-bit FNV-1a.
fn fnv(text: &str) -> u64 {
    text.bytes()
        .fold(0xcbf2_9ce4_8422_2325, |h, b| (h ^ u64::from(b)).wrapping_mul(0x100_0000_01b3))
}
