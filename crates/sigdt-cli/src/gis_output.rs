//! The GIS files `sigdt reconstruct` writes: its four layers ([`Layers`]) as one GeoPackage,
//! or as FlatGeobuf, which holds one layer a file: `areas` in the file named, and `paths`,
//! `networks` and `left_out` in `STEM.paths.fgb`, `STEM.networks.fgb` and
//! `STEM.left_out.fgb` beside it (all four always, empty ones included, so a reader finds
//! every layer). Every file is checked before any work is done, as the one output of the
//! other formats is ([`Output::new`]): none may be the input, and a GeoPackage holding a
//! user's other tables is not replaced. Each file is written whole.

use std::path::{Path, PathBuf};

use anyhow::{bail, Result};
use sigdt_io::gis::layers::{Layer, Layers};
use sigdt_io::gis::{fgb, gpkg, Crs};

use crate::format::OutputFormat;
use crate::messages::UsageError;
use crate::output::{is_dash, Output};

/// Where the layers go: one destination per file, with the layers it holds.
#[derive(Debug)]
pub struct GisFiles {
    files: Vec<File>,
}

#[derive(Debug)]
struct File {
    /// The layer, for FlatGeobuf; `None` for a GeoPackage of them all.
    layer: Option<Layer>,
    /// The path as shown (`<stdout>` for standard output).
    shown: String,
    output: Output,
}

impl GisFiles {
    /// The files of `format` (GeoPackage or FlatGeobuf) for `out` as given (`None` or `-`:
    /// standard output, for a GeoPackage only), checked against `input`.
    pub fn new(format: OutputFormat, out: Option<&Path>, input: &Path) -> Result<GisFiles> {
        let given = out.filter(|p| !is_dash(p));
        let shown = |path: &Path| path.display().to_string();
        match (format, given) {
            (OutputFormat::GeoPackage, _) => {
                if let Some(out) = given {
                    refuse_foreign_tables(out)?;
                }
                let output = Output::new(given, input)?;
                let shown = given.map_or("<stdout>".to_string(), shown);
                Ok(GisFiles { files: vec![File { layer: None, shown, output }] })
            }
            (OutputFormat::FlatGeobuf, Some(out)) => {
                let mut files = Vec::new();
                for layer in Layer::ALL {
                    let path = layer_file(out, layer);
                    let output = Output::new(Some(&path), input)?;
                    if layer != Layer::Areas {
                        refuse_other_files(&path, layer)?;
                    }
                    files.push(File { layer: Some(layer), shown: shown(&path), output });
                }
                Ok(GisFiles { files })
            }
            (OutputFormat::FlatGeobuf, None) => Err(UsageError {
                command: "reconstruct",
                kind: clap::error::ErrorKind::ArgumentConflict,
                message: "--format fgb: FlatGeobuf holds one layer a file, and sigdt writes \
                          four (areas, paths, networks, left_out): give -o NAME.fgb (the others \
                          go beside it), or write a GeoPackage (-o NAME.gpkg)"
                    .to_string(),
            }
            .into()),
            _ => bail!("{format} is not a GIS format"),
        }
    }

    /// Writes `layers` in the system `crs`; every file is made before the first is written.
    /// Returns one line per file written, for `--verbose`.
    pub fn write(&self, layers: &Layers, crs: Option<&Crs>) -> Result<Vec<String>> {
        let mut made = Vec::with_capacity(self.files.len());
        for file in &self.files {
            let bytes = match file.layer {
                None => gpkg::write(layers, crs)?,
                Some(layer) => fgb::write(layers, layer, crs)?,
            };
            made.push(bytes);
        }
        let mut written = Vec::new();
        for (file, bytes) in self.files.iter().zip(made) {
            file.output.write(|w| w.write_all(&bytes))?;
            let count = |layer: Layer| {
                let n = layers.len(layer);
                format!("{} {n} feature{}", layer.name(), if n == 1 { "" } else { "s" })
            };
            let held = match file.layer {
                Some(layer) => vec![count(layer)],
                None => Layer::ALL.map(count).to_vec(),
            };
            written.push(format!(
                "written:                   {} ({})",
                file.shown,
                held.join(", ")
            ));
        }
        Ok(written)
    }
}

/// The FlatGeobuf file of `layer` for the output `out`: `out` itself for `areas`, else
/// `STEM.LAYER.fgb` beside it.
fn layer_file(out: &Path, layer: Layer) -> PathBuf {
    if layer == Layer::Areas {
        return out.to_path_buf();
    }
    let stem = out.file_stem().map_or_else(Default::default, |s| s.to_os_string());
    let mut name = stem;
    name.push(format!(".{}.fgb", layer.name()));
    out.with_file_name(name)
}

/// Refuses to write the layer file `path` the user did not name when something other than
/// a FlatGeobuf file is there: `-o out.fgb` may replace an earlier run's `out.paths.fgb`,
/// never a file of another kind that happens to have that name.
fn refuse_other_files(path: &Path, layer: Layer) -> Result<()> {
    let Ok(mut file) = std::fs::File::open(path) else { return Ok(()) };
    let mut magic = [0u8; 3];
    let is_flatgeobuf =
        std::io::Read::read_exact(&mut file, &mut magic).is_ok() && magic == fgb::MAGIC[..3];
    if !is_flatgeobuf {
        bail!(
            "{}: sigdt writes the {} layer there, beside -o, but it holds something other \
             than a FlatGeobuf file: move it, or choose another -o",
            path.display(),
            layer.name()
        );
    }
    Ok(())
}

/// Refuses to replace the GeoPackage `out` when it holds tables sigdt does not write: the
/// file is replaced whole, so a user's other layers in it would be lost.
fn refuse_foreign_tables(out: &Path) -> Result<()> {
    let foreign = gpkg::foreign_tables(out);
    if !foreign.is_empty() {
        let names: Vec<_> = foreign.iter().map(|t| sigdt_io::text::quoted(t)).collect();
        bail!(
            "{}: a GeoPackage holding other tables ({}); writing the result replaces it \
             whole: refusing (choose another file)",
            out.display(),
            names.join(", ")
        );
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_other_layers_go_beside_the_file_named() {
        let file = |out: &str, layer| layer_file(Path::new(out), layer);
        assert_eq!(file("d/o.fgb", Layer::Areas), Path::new("d/o.fgb"));
        assert_eq!(file("d/o.fgb", Layer::Paths), Path::new("d/o.paths.fgb"));
        assert_eq!(file("o.fgb", Layer::LeftOut), Path::new("o.left_out.fgb"));
        assert_eq!(file("d/o", Layer::Networks), Path::new("d/o.networks.fgb"));
    }
}
