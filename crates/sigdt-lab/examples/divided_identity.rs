//! The divide-and-conquer triangulation against the insertion on every point file under
//! the folders given: `cargo run --release -p sigdt-lab --example divided_identity -- data
//! ../shared/data`. Each file with triangles is triangulated by `Triangulation::new` and by
//! `Triangulation::new_divided` in 2, 4 and 8 parts; the invariant checker must pass and
//! the vertices, input indices, duplicates and triangles must be the same. Prints the
//! count checked and names every file that differs (exit 1 if any).
use sigdt::internals::{check_delaunay, FlatArrays};
use sigdt::Triangulation;
use std::path::PathBuf;

fn main() {
    let (mut checked, mut differ) = (0usize, 0usize);
    let mut folders: Vec<PathBuf> = std::env::args().skip(1).map(PathBuf::from).collect();
    while let Some(path) = folders.pop() {
        if path.is_dir() {
            let entries = std::fs::read_dir(&path).into_iter().flatten().flatten();
            folders.extend(entries.map(|e| e.path()));
            continue;
        }
        let Ok(points) = sigdt_io::read_points_file(&path, None, None, 10_000_000) else {
            continue; // not a point file
        };
        let Ok(dt) = Triangulation::new(&points) else { continue };
        if dt.num_triangles() == 0 {
            continue;
        }
        let whole = FlatArrays::of(&dt);
        for halvings in [1, 2, 3] {
            let divided = Triangulation::new_divided(&points, halvings).expect("valid points");
            let parts = FlatArrays::of(&divided);
            checked += 1;
            let same = check_delaunay(&divided).is_ok()
                && (&whole.points, &whole.input_index) == (&parts.points, &parts.input_index)
                && dt.duplicates() == divided.duplicates()
                && whole.triangle_set() == parts.triangle_set();
            if !same {
                differ += 1;
                eprintln!("{}: {} parts differ", path.display(), 1 << halvings);
            }
        }
    }
    println!("{checked} divided triangulations checked, {differ} differ");
    std::process::exit(i32::from(differ > 0));
}
