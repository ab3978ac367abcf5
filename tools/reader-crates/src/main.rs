//! Harness: feed one input file to one reader, print the outcome and the time.
//!
//! usage: h READER FILE [MAX_POINTS] [REPEAT]
//! READER: ours (sigdt_io::read_points_bytes, name from FILE's extension),
//!         ours-file (sigdt_io::read_file, streamed from disk),
//!         ours-wkb (sigdt_io::gis::wkb::read_vertices on a raw WKB blob),
//!         wkt, geojson (GeoJson::from_str), geojson-reader (GeoJson::from_reader, streamed),
//!         geojson-features (FeatureReader, feature by feature), shapefile,
//!         wkb (wkb::reader::read_wkb on a raw WKB blob),
//!         geozero (GeomProcessor on a raw WKB blob, limit checked per coordinate),
//!         geozero-geo (geozero ToGeo, the usual way to get geo-types)
//! Crates' readers parse first; the max-points limit is then applied by walking the result,
//! which is the only place a caller can apply it (except geozero's push processor and
//! FeatureReader's per-feature loop).
use std::io::Cursor;
use std::time::Instant;

use geo_traits::*;

type P = [f64; 2];

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let reader = args[1].as_str();
    let file = args[2].as_str();
    let max: usize = args.get(3).map(|s| s.parse().unwrap()).unwrap_or(1000);
    let repeat: usize = args.get(4).map(|s| s.parse().unwrap()).unwrap_or(1);
    let mut times = Vec::new();
    for _ in 0..repeat {
        let bytes = if reader == "ours-file" || reader == "geojson-reader" || reader == "geojson-features" {
            Vec::new()
        } else {
            std::fs::read(file).unwrap()
        };
        let start = Instant::now();
        let result = run(reader, file, &bytes, max);
        let elapsed = start.elapsed().as_secs_f64();
        times.push(elapsed);
        if times.len() == repeat {
            match &result {
                Ok((points, note)) => {
                    let first: Vec<_> = points.iter().take(3).collect();
                    let nonfinite = points.iter().filter(|p| !p[0].is_finite() || !p[1].is_finite()).count();
                    println!("OK {} points, {} non-finite, first {:?} {}", points.len(), nonfinite, first, note)
                }
                Err(e) => println!("ERR {}", e.replace('\n', "\\n")),
            }
        }
        drop(result);
    }
    let status = std::fs::read_to_string("/proc/self/status").unwrap();
    let mem: Vec<_> = status.lines().filter(|l| l.starts_with("VmPeak") || l.starts_with("VmHWM")).map(|l| l.split_whitespace().collect::<Vec<_>>().join(" ")).collect();
    println!("mem {}", mem.join(", "));
    times.sort_by(|a, b| a.partial_cmp(b).unwrap());
    println!("time {:.3} s (median of {}; all {:?})", times[times.len() / 2], repeat, times.iter().map(|t| format!("{t:.3}")).collect::<Vec<_>>());
}

fn run(reader: &str, file: &str, bytes: &[u8], max: usize) -> Result<(Vec<P>, String), String> {
    let name = std::path::Path::new(file).file_name().unwrap().to_str().unwrap();
    match reader {
        "ours" => sigdt_io::read_points_bytes(bytes, name, None, max).map(|p| (p, String::new())).map_err(|e| e.to_string()),
        "ours-file" => sigdt_io::read_file(file.as_ref(), &sigdt_io::ReadOptions::at_most(max))
            .map(|p| (p.points, String::new()))
            .map_err(|e| sigdt_io::one_line(&e)),
        "ours-wkb" => {
            let mut out = Vec::new();
            sigdt_io::gis::wkb::read_vertices(strip_gp(bytes), &mut out, max).map(|()| (out, String::new()))
        }
        "wkt" => {
            let text = std::str::from_utf8(bytes).map_err(|e| format!("utf8: {e}"))?;
            let geometry: wkt::Wkt<f64> = text.parse().map_err(|e: &str| e.to_string())?;
            let mut out = Vec::new();
            let dims = format!("dim {:?}", geometry.dimension());
            walk(&geometry, &mut out, max)?;
            Ok((out, dims))
        }
        "geojson" => {
            let text = std::str::from_utf8(bytes).map_err(|e| format!("utf8: {e}"))?;
            let g: geojson::GeoJson = text.parse().map_err(|e: geojson::Error| e.to_string())?;
            geojson_points(&g, max)
        }
        "geojson-reader" => {
            let f = std::io::BufReader::new(std::fs::File::open(file).unwrap());
            let g = geojson::GeoJson::from_reader(f).map_err(|e| e.to_string())?;
            geojson_points(&g, max)
        }
        "geojson-features" => {
            let f = std::io::BufReader::new(std::fs::File::open(file).unwrap());
            let mut out = Vec::new();
            let mut extra = 0;
            for feature in geojson::FeatureReader::from_reader(f).features() {
                let feature = feature.map_err(|e| e.to_string())?;
                if let Some(g) = &feature.geometry {
                    gj_value(&g.value, &mut out, max, &mut extra)?;
                }
            }
            Ok((out, format!("max extra dims {extra}")))
        }
        "shapefile" => {
            let mut reader = shapefile::ShapeReader::new(Cursor::new(bytes)).map_err(|e| e.to_string())?;
            let mut out = Vec::new();
            let mut kinds = std::collections::BTreeSet::new();
            for shape in reader.iter_shapes() {
                let shape = shape.map_err(|e| e.to_string())?;
                kinds.insert(format!("{}", shape.shapetype()));
                shp_points(&shape, &mut out, max)?;
            }
            Ok((out, format!("shapes {kinds:?}")))
        }
        "wkb" => {
            let g = wkb::reader::read_wkb(strip_gp(bytes)).map_err(|e| e.to_string())?;
            let mut out = Vec::new();
            let dims = format!("dim {:?}", g.dim());
            walk(&g, &mut out, max)?;
            Ok((out, dims))
        }
        "geozero" => {
            use geozero::GeozeroGeometry;
            let mut p = Collect { out: Vec::new(), max };
            if bytes.starts_with(b"GP") {
                geozero::wkb::GpkgWkb(bytes).process_geom(&mut p)
            } else {
                geozero::wkb::Wkb(bytes).process_geom(&mut p)
            }
            .map_err(|e| e.to_string())?;
            Ok((p.out, String::new()))
        }
        "geozero-geo" => {
            use geozero::ToGeo;
            let g = if bytes.starts_with(b"GP") {
                geozero::wkb::GpkgWkb(bytes).to_geo()
            } else {
                geozero::wkb::Wkb(bytes).to_geo()
            }
            .map_err(|e| e.to_string())?;
            let mut out = Vec::new();
            walk(&g, &mut out, max)?;
            Ok((out, String::new()))
        }
        other => panic!("unknown reader {other}"),
    }
}

/// The WKB inside a GeoPackage blob (GP header with its envelope), or the bytes as they are.
fn strip_gp(bytes: &[u8]) -> &[u8] {
    if bytes.starts_with(b"GP") && bytes.len() >= 8 {
        let env = match (bytes[3] >> 1) & 7 {
            0 => 0,
            1 => 32,
            2 | 3 => 48,
            4 => 64,
            _ => 0,
        };
        &bytes[(8 + env).min(bytes.len())..]
    } else {
        bytes
    }
}

fn push(out: &mut Vec<P>, p: P, max: usize) -> Result<(), String> {
    if out.len() == max {
        return Err(format!("[harness] more than {max} points"));
    }
    out.push(p);
    Ok(())
}

fn coords<'a, C: CoordTrait<T = f64> + 'a>(cs: impl Iterator<Item = C>, out: &mut Vec<P>, max: usize) -> Result<(), String> {
    for c in cs {
        push(out, [c.x(), c.y()], max)?;
    }
    Ok(())
}

/// Every vertex of a geo-traits geometry (not dropping ring closures: counts only).
fn walk<G: GeometryTrait<T = f64>>(g: &G, out: &mut Vec<P>, max: usize) -> Result<(), String> {
    match g.as_type() {
        GeometryType::Point(p) => {
            if let Some(c) = p.coord() {
                push(out, [c.x(), c.y()], max)?;
            }
        }
        GeometryType::LineString(l) => coords(l.coords(), out, max)?,
        GeometryType::Polygon(y) => {
            if let Some(r) = y.exterior() {
                coords(r.coords(), out, max)?;
            }
            for r in y.interiors() {
                coords(r.coords(), out, max)?;
            }
        }
        GeometryType::MultiPoint(m) => {
            for p in m.points() {
                if let Some(c) = p.coord() {
                    push(out, [c.x(), c.y()], max)?;
                }
            }
        }
        GeometryType::MultiLineString(m) => {
            for l in m.line_strings() {
                coords(l.coords(), out, max)?;
            }
        }
        GeometryType::MultiPolygon(m) => {
            for y in m.polygons() {
                if let Some(r) = y.exterior() {
                    coords(r.coords(), out, max)?;
                }
                for r in y.interiors() {
                    coords(r.coords(), out, max)?;
                }
            }
        }
        GeometryType::GeometryCollection(c) => {
            for g in c.geometries() {
                walk(&g, out, max)?;
            }
        }
        _ => return Err("[harness] unexpected geometry type".into()),
    }
    Ok(())
}

fn geojson_points(g: &geojson::GeoJson, max: usize) -> Result<(Vec<P>, String), String> {
    let mut out = Vec::new();
    let mut extra = 0;
    match g {
        geojson::GeoJson::Geometry(g) => gj_value(&g.value, &mut out, max, &mut extra)?,
        geojson::GeoJson::Feature(f) => {
            if let Some(g) = &f.geometry {
                gj_value(&g.value, &mut out, max, &mut extra)?
            }
        }
        geojson::GeoJson::FeatureCollection(c) => {
            for f in &c.features {
                if let Some(g) = &f.geometry {
                    gj_value(&g.value, &mut out, max, &mut extra)?
                }
            }
        }
    }
    Ok((out, format!("max extra dims {extra}")))
}

fn gj_pos(p: &geojson::Position, out: &mut Vec<P>, max: usize, extra: &mut usize) -> Result<(), String> {
    let s = p.as_slice();
    *extra = (*extra).max(s.len().saturating_sub(2));
    push(out, [s[0], s[1]], max)
}

fn gj_value(v: &geojson::GeometryValue, out: &mut Vec<P>, max: usize, extra: &mut usize) -> Result<(), String> {
    use geojson::GeometryValue as V;
    match v {
        V::Point { coordinates } => gj_pos(coordinates, out, max, extra)?,
        V::MultiPoint { coordinates } | V::LineString { coordinates } => {
            for p in coordinates {
                gj_pos(p, out, max, extra)?
            }
        }
        V::MultiLineString { coordinates } | V::Polygon { coordinates } => {
            for l in coordinates {
                for p in l {
                    gj_pos(p, out, max, extra)?
                }
            }
        }
        V::MultiPolygon { coordinates } => {
            for y in coordinates {
                for l in y {
                    for p in l {
                        gj_pos(p, out, max, extra)?
                    }
                }
            }
        }
        V::GeometryCollection { geometries } => {
            for g in geometries {
                gj_value(&g.value, out, max, extra)?
            }
        }
    }
    Ok(())
}

fn shp_points(shape: &shapefile::Shape, out: &mut Vec<P>, max: usize) -> Result<(), String> {
    use shapefile::Shape as S;
    macro_rules! pts {
        ($it:expr) => {
            for p in $it {
                push(out, [p.x, p.y], max)?;
            }
        };
    }
    match shape {
        S::NullShape => {}
        S::Point(p) => push(out, [p.x, p.y], max)?,
        S::PointM(p) => push(out, [p.x, p.y], max)?,
        S::PointZ(p) => push(out, [p.x, p.y], max)?,
        S::Polyline(l) => pts!(l.parts().iter().flatten()),
        S::PolylineM(l) => pts!(l.parts().iter().flatten()),
        S::PolylineZ(l) => pts!(l.parts().iter().flatten()),
        S::Polygon(y) => pts!(y.rings().iter().flat_map(|r| r.points())),
        S::PolygonM(y) => pts!(y.rings().iter().flat_map(|r| r.points())),
        S::PolygonZ(y) => pts!(y.rings().iter().flat_map(|r| r.points())),
        S::Multipoint(m) => pts!(m.points()),
        S::MultipointM(m) => pts!(m.points()),
        S::MultipointZ(m) => pts!(m.points()),
        S::Multipatch(m) => pts!(m.patches().iter().flat_map(|p| p.points())),
    }
    Ok(())
}

/// A geozero processor that keeps x and y, and stops at the point after `max`.
struct Collect {
    out: Vec<P>,
    max: usize,
}

impl geozero::GeomProcessor for Collect {
    fn xy(&mut self, x: f64, y: f64, _idx: usize) -> geozero::error::Result<()> {
        if self.out.len() == self.max {
            return Err(geozero::error::GeozeroError::Geometry(format!("[harness] more than {} points", self.max)));
        }
        self.out.push([x, y]);
        Ok(())
    }
}
