//! `data/non-manifold` is what its generator writes (`make data-non-manifold`): every file
//! byte for byte, and no case file the generator does not write.
use sigdt_lab::curves::{folder_files, non_manifold_cases, PER_KIND};
use sigdt_lab::dataset::data_dir;

#[test]
fn non_manifold_data_is_generated() {
    let dir = data_dir("non-manifold");
    let files = folder_files(&non_manifold_cases(PER_KIND).unwrap());
    for (name, text) in &files {
        let path = dir.join(name);
        let stored = std::fs::read_to_string(&path)
            .unwrap_or_else(|e| panic!("{}: {e} (run make data-non-manifold)", path.display()));
        assert!(&stored == text, "{} differs from the generator's output", path.display());
    }
    let generated: Vec<&str> = files.iter().map(|(name, _)| name.as_str()).collect();
    for entry in std::fs::read_dir(&dir).unwrap() {
        let name = entry.unwrap().file_name().into_string().unwrap();
        let case_file = [".xy", ".gt", ".svg", ".csv"].iter().any(|e| name.ends_with(e));
        assert!(!case_file || generated.contains(&name.as_str()), "{name} is not generated");
    }
}
