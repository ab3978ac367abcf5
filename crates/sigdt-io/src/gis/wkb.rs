//! Well-known binary (OGC 06-103r4 §8, ISO 13249-3), the geometry encoding of GeoPackage:
//! read for the vertices of any geometry, written for the layers of a result.
//!
//! Reading accepts both byte orders, the ISO Z/M/ZM type codes (1001, 2001, 3001, ...) and
//! the extended-WKB flags (Z, M and SRID bits), as GDAL and PostGIS write them; Z and M
//! values are skipped. Every count is checked against the bytes left before anything is
//! allocated, so a hostile count costs nothing. As in the WKT reader, a polygon ring's
//! closing vertex (a repeat of its first) is not a point, and an empty point (NaN
//! coordinates, GeoPackage's encoding) is skipped.

use sigdt::Point;

/// Collections nested deeper than this are refused (as the WKT reader's limit).
const MAX_DEPTH: usize = 128;

/// The vertices of the WKB geometry `bytes`, appended to `out`, refusing more than `max`
/// points in all; the error says what is wrong and where (a byte offset).
pub fn read_vertices(bytes: &[u8], out: &mut Vec<Point>, max: usize) -> Result<(), String> {
    let mut reader = Reader { bytes, at: 0, out, max };
    reader.geometry(0)?;
    if reader.at != bytes.len() {
        return Err(format!("{} bytes after the geometry", bytes.len() - reader.at));
    }
    Ok(())
}

struct Reader<'a, 'b> {
    bytes: &'a [u8],
    at: usize,
    out: &'b mut Vec<Point>,
    max: usize,
}

impl Reader<'_, '_> {
    fn take<const N: usize>(&mut self) -> Result<[u8; N], String> {
        let end = self.at.checked_add(N).filter(|&end| end <= self.bytes.len());
        let Some(end) = end else {
            return Err(format!("the geometry ends at byte {} inside a value", self.bytes.len()));
        };
        let value = self.bytes[self.at..end].try_into().expect("N bytes");
        self.at = end;
        Ok(value)
    }

    fn u32(&mut self, little: bool) -> Result<u32, String> {
        let b = self.take::<4>()?;
        Ok(if little { u32::from_le_bytes(b) } else { u32::from_be_bytes(b) })
    }

    fn f64(&mut self, little: bool) -> Result<f64, String> {
        let b = self.take::<8>()?;
        Ok(if little { f64::from_le_bytes(b) } else { f64::from_be_bytes(b) })
    }

    /// A count of items of at least `item` bytes each, checked against the bytes left.
    fn count(&mut self, little: bool, item: usize, what: &str) -> Result<usize, String> {
        let at = self.at;
        let n = self.u32(little)? as usize;
        let left = self.bytes.len() - self.at;
        if n.checked_mul(item).is_none_or(|need| need > left) {
            return Err(format!("byte {at}: {n} {what}, more than the {left} bytes left hold"));
        }
        Ok(n)
    }

    fn geometry(&mut self, depth: usize) -> Result<(), String> {
        if depth > MAX_DEPTH {
            return Err(format!("collections nested more than {MAX_DEPTH} deep"));
        }
        let start = self.at;
        let little = match self.take::<1>()? {
            [0] => false,
            [1] => true,
            [b] => return Err(format!("byte {start}: byte order {b} (0 or 1 expected)")),
        };
        let code = self.u32(little)?;
        // Extended WKB: flags in the high bits; ISO: thousands.
        let (ewkb_z, ewkb_m, srid) =
            (code & 0x8000_0000 != 0, code & 0x4000_0000 != 0, code & 0x2000_0000 != 0);
        let iso = code & 0x0fff_ffff;
        let (kind, iso_dims) = (iso % 1000, iso / 1000);
        let extra = match (iso_dims, ewkb_z || ewkb_m) {
            (0, _) => usize::from(ewkb_z) + usize::from(ewkb_m),
            (1 | 2, false) => 1,
            (3, false) => 2,
            _ => return Err(format!("byte {start}: geometry type {code} is not WKB")),
        };
        if srid {
            self.take::<4>()?;
        }
        let dims = 2 + extra;
        match kind {
            1 => self.point(little, dims, true),
            2 => self.points(little, dims, false),
            3 => {
                let rings = self.count(little, 4, "rings")?;
                (0..rings).try_for_each(|_| self.points(little, dims, true))
            }
            4..=7 => {
                let parts = self.count(little, 9, "parts")?;
                (0..parts).try_for_each(|_| self.geometry(depth + 1))
            }
            _ => Err(format!(
                "byte {start}: geometry type {code} (only points, lines, polygons and their \
                 collections hold points)"
            )),
        }
    }

    /// A sequence of points; a ring's closing repeat of its first is dropped.
    fn points(&mut self, little: bool, dims: usize, ring: bool) -> Result<(), String> {
        let n = self.count(little, 8 * dims, "points")?;
        let first = self.out.len();
        for _ in 0..n {
            self.point(little, dims, false)?;
        }
        if ring && self.out.len() > first + 1 && self.out.last() == self.out.get(first) {
            self.out.pop();
        }
        Ok(())
    }

    fn point(&mut self, little: bool, dims: usize, may_be_empty: bool) -> Result<(), String> {
        let at = self.at;
        let p = [self.f64(little)?, self.f64(little)?];
        for _ in 2..dims {
            self.f64(little)?;
        }
        if may_be_empty && p[0].is_nan() && p[1].is_nan() {
            return Ok(());
        }
        if !p.iter().all(|c| c.is_finite()) {
            return Err(format!("byte {at}: coordinate {:?} {:?} is not finite", p[0], p[1]));
        }
        if self.out.len() == self.max {
            return Err(format!("more than {} points (raise --max-points to read more)", self.max));
        }
        self.out.push(p);
        Ok(())
    }
}

/// Writes well-known binary, little-endian and two-dimensional.
pub struct Writer(pub Vec<u8>);

impl Writer {
    fn header(&mut self, kind: u32) {
        self.0.push(1);
        self.0.extend_from_slice(&kind.to_le_bytes());
    }

    fn count(&mut self, n: usize) {
        let n = u32::try_from(n).expect("fewer than 2^32 items: sigdt indexes points by u32");
        self.0.extend_from_slice(&n.to_le_bytes());
    }

    fn coordinates(&mut self, points: impl ExactSizeIterator<Item = Point>) {
        self.count(points.len());
        for [x, y] in points {
            self.0.extend_from_slice(&x.to_le_bytes());
            self.0.extend_from_slice(&y.to_le_bytes());
        }
    }

    /// A point.
    pub fn point(&mut self, [x, y]: Point) {
        self.header(1);
        self.0.extend_from_slice(&x.to_le_bytes());
        self.0.extend_from_slice(&y.to_le_bytes());
    }

    /// A line string through `path`.
    pub fn line_string(&mut self, path: &[Point]) {
        self.header(2);
        self.coordinates(path.iter().copied());
    }

    /// A multi-polygon of `polygons` (each as [`Writer::polygon`] takes it); empty when
    /// there are none.
    pub fn multi_polygon(&mut self, polygons: &[Vec<Vec<Point>>]) {
        self.header(6);
        self.count(polygons.len());
        polygons.iter().for_each(|rings| self.polygon(rings));
    }

    /// A multi-line string of `lines`.
    pub fn multi_line_string(&mut self, lines: &[Vec<Point>]) {
        self.header(5);
        self.count(lines.len());
        lines.iter().for_each(|line| self.line_string(line));
    }

    /// A polygon of `rings` (the shell, then its holes), each closed here by repeating its
    /// first point.
    pub fn polygon(&mut self, rings: &[Vec<Point>]) {
        self.header(3);
        self.count(rings.len());
        for ring in rings {
            let closing = ring.first().copied();
            self.coordinates(ring.iter().copied().chain(closing).collect::<Vec<_>>().into_iter());
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn read(bytes: &[u8]) -> Result<Vec<Point>, String> {
        let mut out = Vec::new();
        read_vertices(bytes, &mut out, 100).map(|()| out)
    }

    #[test]
    fn what_is_written_reads_back() {
        let ring = vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]];
        let mut w = Writer(Vec::new());
        w.polygon(std::slice::from_ref(&ring));
        assert_eq!(read(&w.0).unwrap(), ring, "the closing repeat is not a point");
        let mut w = Writer(Vec::new());
        w.line_string(&ring);
        assert_eq!(read(&w.0).unwrap(), ring);
        let mut w = Writer(Vec::new());
        w.point([2.5, -1.0]);
        assert_eq!(read(&w.0).unwrap(), vec![[2.5, -1.0]]);
        let mut w = Writer(Vec::new());
        w.multi_polygon(&[vec![ring.clone()], vec![ring.clone()]]);
        assert_eq!(read(&w.0).unwrap(), [ring.clone(), ring.clone()].concat());
        let mut w = Writer(Vec::new());
        w.multi_line_string(&[ring.clone(), ring.clone()]);
        assert_eq!(read(&w.0).unwrap(), [ring.clone(), ring.clone()].concat());
        let mut w = Writer(Vec::new());
        w.multi_polygon(&[]);
        assert_eq!(w.0, [1, 6, 0, 0, 0, 0, 0, 0, 0], "an empty multi-polygon");
    }

    #[test]
    fn big_endian_iso_z_and_ewkb_flags_read() {
        // A big-endian ISO PointZ (1001): x y z.
        let mut b = vec![0u8];
        b.extend_from_slice(&1001u32.to_be_bytes());
        for v in [1.0f64, 2.0, 99.0] {
            b.extend_from_slice(&v.to_be_bytes());
        }
        assert_eq!(read(&b).unwrap(), vec![[1.0, 2.0]]);
        // An extended-WKB MultiPoint with SRID holding one PointZ.
        let mut b = vec![1u8];
        b.extend_from_slice(&(4u32 | 0x2000_0000).to_le_bytes());
        b.extend_from_slice(&4326u32.to_le_bytes());
        b.extend_from_slice(&1u32.to_le_bytes());
        b.push(1);
        b.extend_from_slice(&(1u32 | 0x8000_0000).to_le_bytes());
        for v in [3.0f64, 4.0, 5.0] {
            b.extend_from_slice(&v.to_le_bytes());
        }
        assert_eq!(read(&b).unwrap(), vec![[3.0, 4.0]]);
    }

    #[test]
    fn mutated_geometries_never_panic_and_stay_bounded() {
        // Random byte changes and cuts of valid geometries (a polygon with a hole, a
        // collection): an answer or a short error, never a panic or more than the limit.
        let mut w = Writer(Vec::new());
        w.polygon(&[
            vec![[0.0, 0.0], [4.0, 0.0], [4.0, 4.0]],
            vec![[1.0, 1.0], [2.0, 1.0], [1.0, 2.0]],
        ]);
        let mut collection = vec![1u8];
        collection.extend_from_slice(&7u32.to_le_bytes());
        collection.extend_from_slice(&2u32.to_le_bytes());
        collection.extend_from_slice(&w.0);
        let mut line = Writer(Vec::new());
        line.line_string(&[[0.0, 0.0], [1.0, 1.0]]);
        collection.extend_from_slice(&line.0);
        let mut rng = sigdt::samplers::Rng::new(3);
        for case in 0..20_000 {
            let mut bytes = if case % 2 == 0 { w.0.clone() } else { collection.clone() };
            for _ in 0..1 + rng.below(4) {
                let at = rng.below(bytes.len());
                bytes[at] = match rng.below(3) {
                    0 => rng.below(256) as u8,
                    1 => 0xff,
                    _ => 0,
                };
            }
            if rng.below(4) == 0 {
                bytes.truncate(rng.below(bytes.len() + 1));
            }
            let mut out = Vec::new();
            match read_vertices(&bytes, &mut out, 5) {
                Ok(()) => assert!(out.len() <= 5 && out.iter().flatten().all(|c| c.is_finite())),
                Err(why) => assert!(why.len() < 200, "case {case}: {why}"),
            }
        }
    }

    #[test]
    fn hostile_geometries_are_refused_saying_why() {
        // A line string claiming 2^32-1 points in 9 bytes: refused before allocating.
        let mut b = vec![1u8];
        b.extend_from_slice(&2u32.to_le_bytes());
        b.extend_from_slice(&u32::MAX.to_le_bytes());
        let err = read(&b).unwrap_err();
        assert_eq!(err, "byte 5: 4294967295 points, more than the 0 bytes left hold");
        assert_eq!(read(&[2]).unwrap_err(), "byte 0: byte order 2 (0 or 1 expected)");
        assert!(read(&[1, 9, 0, 0, 0]).unwrap_err().contains("geometry type 9"));
        assert!(read(&[1, 1, 0]).unwrap_err().contains("inside a value"));
        // Collections nested past the limit.
        let mut b = Vec::new();
        for _ in 0..200 {
            b.push(1);
            b.extend_from_slice(&7u32.to_le_bytes());
            b.extend_from_slice(&1u32.to_le_bytes());
        }
        assert!(read(&b).unwrap_err().contains("nested more than 128"));
        // A non-finite coordinate, and more points than allowed.
        let mut w = Writer(Vec::new());
        w.point([f64::INFINITY, 0.0]);
        assert!(read(&w.0).unwrap_err().contains("is not finite"));
        let mut w = Writer(Vec::new());
        w.line_string(&[[0.0, 0.0]; 101]);
        assert!(read(&w.0).unwrap_err().starts_with("more than 100 points"));
    }
}
