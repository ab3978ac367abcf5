//! The bundled inputs of `data/inputs` come back exact, and the README's claims about input
//! ranges hold. (The README's Rust example itself runs as a doctest of the crate.)
use sigdt::internals::check_reconstruction;
use sigdt::{reconstruct, Error, Options, Status};
use std::path::PathBuf;

fn bundled(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../data/inputs").join(name)
}

#[test]
fn bundled_glyph_sigma_is_exact() -> Result<(), Error> {
    let points = sigdt_io::text::read_points(&bundled("glyph_sigma.xy"))?;
    let rec = sigdt::reconstruct(&points, &sigdt::Options::default())?;
    assert!(rec.status.is_manifold());
    assert_eq!((rec.edges.len(), rec.loops.len()), (245, 1));
    let graph = sigdt::proximity_graph(&points, sigdt::GraphKind::SigDt)?;
    assert!(graph.len() >= rec.edges.len());
    // Inflating and leaf elimination may add Delaunay edges beyond SIGDT; all are Delaunay.
    let dt = sigdt::proximity_graph(&points, sigdt::GraphKind::Dt)?;
    assert!(rec.edges.iter().all(|e| dt.binary_search(e).is_ok()));
    assert_eq!(rec.edges, sigdt_io::text::read_edges(&bundled("glyph_sigma.gt"))?);
    Ok(())
}

#[test]
fn bundled_demo_is_exact() -> Result<(), Error> {
    let points = sigdt_io::text::read_points(&bundled("glyph_n_tilde.xy"))?;
    let rec = reconstruct(&points, &Options::default())?;
    assert_eq!(rec.status, Status::Polygons);
    assert_eq!(rec.edges, sigdt_io::text::read_edges(&bundled("glyph_n_tilde.gt"))?);
    Ok(())
}

#[test]
fn any_finite_coordinate_range_gives_the_same_result() {
    let base: Vec<[f64; 2]> = sigdt::samplers::random_closed_curve(3, 300).shuffled(1).points;
    let expected = reconstruct(&base, &Options::default()).unwrap();
    assert_eq!(expected.status, Status::Polygon);
    for scale in [1e-300, 1e-150, 1e150, 1e300] {
        let pts: Vec<[f64; 2]> = base.iter().map(|&[x, y]| [x * scale, y * scale]).collect();
        let rec = reconstruct(&pts, &Options::default()).unwrap();
        check_reconstruction(&pts, &rec).unwrap();
        assert_eq!(rec.edges, expected.edges, "scale {scale:e}");
    }
    // Offset by 1e9 with millimetre spacing: exact predicates still see the curve.
    let far: Vec<[f64; 2]> = base.iter().map(|&[x, y]| [1e9 + x, 1e9 + y]).collect();
    assert_eq!(reconstruct(&far, &Options::default()).unwrap().edges, expected.edges);
}

#[test]
fn non_finite_and_impossible_ranges_are_clear_errors() {
    let e = reconstruct(&[[0.0, 0.0], [1.0, f64::NAN], [0.0, 1.0]], &Options::default());
    assert_eq!(e.unwrap_err().to_string(), "point 1 has a non-finite coordinate (1, NaN)");
    let e = reconstruct(&[[1e300, 0.0], [1e-300, 1.0], [0.0, 1.0]], &Options::default());
    let message = e.unwrap_err().to_string();
    assert!(message.starts_with("point 1 has a coordinate (1e-300)"), "{message}");
}
