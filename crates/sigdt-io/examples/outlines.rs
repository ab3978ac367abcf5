//! The outlines of a GeoPackage's points, written as a GeoPackage in their coordinate system:
//! `cargo run -p sigdt-io --example outlines -- data/gis/islands_4326.gpkg islands.gpkg`.
use sigdt_io::gis::{gpkg, layers::Layers, local::why_degrees};
use sigdt_io::{read_file, ReadOptions};

fn main() -> anyhow::Result<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [input, output] = args.as_slice() else {
        anyhow::bail!("usage: outlines POINTS.gpkg OUTLINES.gpkg");
    };
    anyhow::ensure!(!std::path::Path::new(output).exists(), "{output} exists: not overwritten");
    let read = read_file(input.as_ref(), &ReadOptions::at_most(10_000_000))?;
    let options = sigdt::Options::default();
    // Longitude and latitude are reconstructed in a local plane, written back in degrees
    // (cut at the antimeridian).
    let rec = read.reconstruct(&options)?;
    let degrees = why_degrees(read.crs.as_ref(), read.lon_lat).is_some();
    let layers = Layers::new(options.method, &read.points, &rec, degrees);
    std::fs::write(output, gpkg::write(&layers, read.crs.as_ref())?)?;
    let crs = read.crs.map_or("no coordinate system".to_string(), |crs| crs.to_string());
    println!(
        "{output}: {} loops, {} paths ({}), {crs}",
        rec.loops.len(),
        rec.paths.len(),
        rec.status
    );
    Ok(())
}
