//! Points from a NumPy `.npy` file (format versions 1.0 to 3.0): an `(n, 2)` array of
//! floats or integers, in C or Fortran order, little- or big-endian.
//!
//! Read dtypes: `f8`, `f4`, `i8`, `i4`, `i2`, `i1`, `u8`, `u4`, `u2`, `u1`. Anything else
//! (objects, complex numbers, structured arrays) and any shape other than `(n, 2)` is
//! refused, saying what was found and how to save what sigdt reads.
//!
//! Integers beyond 2^53 in magnitude, which a float64 cannot hold exactly, are refused.
//!
//! # Complexity
//! O(n); the data are read in one pass, in blocks, so memory grows with the data that are
//! there, whatever the header's shape claims.

use std::io::Read;

use crate::text::quoted;
use anyhow::{bail, Context, Result};
use sigdt::Point;

/// The magic bytes of a `.npy` file.
pub const MAGIC: &[u8] = b"\x93NUMPY";

/// The points of the `.npy` stream `reader`; see the module docs.
pub fn read(mut reader: impl Read, name: &str, max_points: usize) -> Result<Vec<Point>> {
    let mut preamble = [0u8; 8];
    reader.read_exact(&mut preamble).with_context(|| format!("{name}: truncated .npy header"))?;
    let header_len = match preamble[6] {
        1 => {
            let mut len = [0u8; 2];
            reader
                .read_exact(&mut len)
                .with_context(|| format!("{name}: truncated .npy header"))?;
            usize::from(u16::from_le_bytes(len))
        }
        2 | 3 => {
            let mut len = [0u8; 4];
            reader
                .read_exact(&mut len)
                .with_context(|| format!("{name}: truncated .npy header"))?;
            u32::from_le_bytes(len) as usize
        }
        v => bail!("{name}: .npy format version {v} is not one sigdt reads (1 to 3)"),
    };
    if header_len > 1 << 20 {
        bail!("{name}: .npy header of {header_len} bytes: not a .npy file?");
    }
    let mut header = vec![0u8; header_len];
    reader.read_exact(&mut header).with_context(|| format!("{name}: truncated .npy header"))?;
    let header = String::from_utf8_lossy(&header);
    let descr = value_of(&header, "descr")
        .with_context(|| format!("{name}: .npy header without 'descr'"))?;
    let fortran = value_of(&header, "fortran_order") == Some("True");
    let shape = value_of(&header, "shape")
        .with_context(|| format!("{name}: .npy header without 'shape'"))?;
    let dims: Vec<usize> = shape
        .trim_matches(['(', ')'])
        .split(',')
        .map(str::trim)
        .filter(|d| !d.is_empty())
        .map(|d| d.parse::<usize>())
        .collect::<Result<_, _>>()
        .with_context(|| format!("{name}: .npy shape {} is not a tuple of sizes", quoted(shape)))?;
    let n = match dims.as_slice() {
        [n, 2] => *n,
        [0] => 0,
        _ => bail!(
            "{name}: the array has shape {}; sigdt reads (n, 2) arrays of x and y: save \
             points[:, :2] (np.save(path, np.asarray(points)[:, :2]))",
            quoted(shape)
        ),
    };
    if n > max_points {
        bail!("{name}: more than {max_points} points ({n}; raise --max-points to read more)");
    }
    let descr = descr.trim_matches(['\'', '"']);
    let dtype = Dtype::parse(descr).with_context(|| {
        format!(
            "{name}: .npy dtype {} is not a real number type sigdt reads (save as float64: \
             np.save(path, points.astype(float)))",
            quoted(descr)
        )
    })?;
    let values = read_values(&mut reader, &dtype, n, fortran, name)?;
    let points: Vec<Point> =
        (0..n)
            .map(|i| {
                if fortran {
                    [values[i], values[n + i]]
                } else {
                    [values[2 * i], values[2 * i + 1]]
                }
            })
            .collect();
    if let Some(i) = points.iter().position(|p| !p.iter().all(|v| v.is_finite())) {
        bail!("{name}: row {i} is {:?}: every coordinate must be finite", points[i]);
    }
    Ok(points)
}

/// The `2n` values after the header, read in blocks so that memory grows with the data
/// actually there, never with what a header claims.
fn read_values(
    reader: &mut impl Read,
    dtype: &Dtype,
    n: usize,
    fortran: bool,
    name: &str,
) -> Result<Vec<f64>> {
    let row = |k: usize| if fortran { k % n.max(1) } else { k / 2 };
    let count = n.checked_mul(2).context("too many values")?;
    let mut values = Vec::with_capacity(count.min(1 << 16));
    let mut block = vec![0u8; (1 << 16) * dtype.size];
    while values.len() < count {
        let want = (count - values.len()).min(1 << 16) * dtype.size;
        let got = crate::stream::read_full(reader, &mut block[..want])
            .with_context(|| format!("{name}: cannot read the .npy data"))?;
        for b in block[..got].chunks_exact(dtype.size) {
            let value = dtype.value(b).with_context(|| {
                format!(
                    "{name}: row {}: an integer beyond 2^53, which a float64 cannot hold \
                     exactly",
                    row(values.len())
                )
            })?;
            values.push(value);
        }
        if got < want {
            bail!(
                "{name}: the .npy data end after {} of the {n} x 2 values its header announces",
                values.len()
            );
        }
    }
    Ok(values)
}

/// The value text of `key` in the header's Python dict literal: `'key': value`.
fn value_of<'h>(header: &'h str, key: &str) -> Option<&'h str> {
    let start = header.find(&format!("'{key}'"))? + key.len() + 2;
    let rest = header[start..].trim_start().strip_prefix(':')?.trim_start();
    let end = if rest.starts_with('(') {
        rest.find(')')? + 1
    } else {
        rest.find([',', '}']).unwrap_or(rest.len())
    };
    Some(rest[..end].trim())
}

/// A numeric dtype: kind, size and byte order.
struct Dtype {
    kind: char,
    size: usize,
    big_endian: bool,
}

impl Dtype {
    fn parse(descr: &str) -> Option<Dtype> {
        let (order, rest) = descr.split_at(descr.find(|c: char| c.is_ascii_alphabetic())?);
        let big_endian = match order {
            "<" | "|" | "=" | "" => false,
            ">" => true,
            _ => return None,
        };
        let kind = rest.chars().next()?;
        let size: usize = rest[1..].parse().ok()?;
        let known = matches!((kind, size), ('f', 4 | 8) | ('i' | 'u', 1 | 2 | 4 | 8));
        known.then_some(Dtype { kind, size, big_endian })
    }

    /// The value of `bytes`; `None` for an integer a float64 cannot hold exactly.
    fn value(&self, bytes: &[u8]) -> Option<f64> {
        let mut b = [0u8; 8];
        if self.big_endian {
            b[..self.size].copy_from_slice(bytes);
            b[..self.size].reverse();
        } else {
            b[..self.size].copy_from_slice(bytes);
        }
        const EXACT: u64 = 1 << 53;
        let signed = |bits: u32| {
            let raw = u64::from_le_bytes(b);
            let v = ((raw << (64 - bits)) as i64) >> (64 - bits);
            (v.unsigned_abs() <= EXACT).then_some(v as f64)
        };
        match (self.kind, self.size) {
            ('f', 8) => Some(f64::from_le_bytes(b)),
            ('f', _) => Some(f64::from(f32::from_le_bytes([b[0], b[1], b[2], b[3]]))),
            ('i', size) => signed(8 * size as u32),
            (_, _) => Some(u64::from_le_bytes(b)).filter(|&v| v <= EXACT).map(|v| v as f64),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A version-1 `.npy` file of `values` with `descr`, `shape` and order.
    fn npy(descr: &str, shape: &str, fortran: bool, values: &[u8]) -> Vec<u8> {
        let dict = format!(
            "{{'descr': '{descr}', 'fortran_order': {}, 'shape': {shape}, }}",
            if fortran { "True" } else { "False" }
        );
        let mut header = dict.into_bytes();
        while (10 + header.len() + 1) % 64 != 0 {
            header.push(b' ');
        }
        header.push(b'\n');
        let mut out = MAGIC.to_vec();
        out.extend([1, 0]);
        out.extend((header.len() as u16).to_le_bytes());
        out.extend(header);
        out.extend(values);
        out
    }

    fn parse(bytes: &[u8]) -> Result<Vec<Point>> {
        read(bytes, "t.npy", 1000)
    }

    #[test]
    fn float_and_integer_arrays_in_either_order() {
        let f8: Vec<u8> = [0.5f64, 1.0, 2.0, -3.0].iter().flat_map(|v| v.to_le_bytes()).collect();
        let points = vec![[0.5, 1.0], [2.0, -3.0]];
        assert_eq!(parse(&npy("<f8", "(2, 2)", false, &f8)).unwrap(), points);
        let fortran = vec![[0.5, 2.0], [1.0, -3.0]];
        assert_eq!(parse(&npy("<f8", "(2, 2)", true, &f8)).unwrap(), fortran);
        let be: Vec<u8> = [0.5f32, 1.0, 2.0, -3.0].iter().flat_map(|v| v.to_be_bytes()).collect();
        assert_eq!(parse(&npy(">f4", "(2, 2)", false, &be)).unwrap(), points);
        let i2: Vec<u8> = [7i16, -8, 9, 10].iter().flat_map(|v| v.to_le_bytes()).collect();
        assert_eq!(parse(&npy("<i2", "(2, 2)", false, &i2)).unwrap(), [[7.0, -8.0], [9.0, 10.0]]);
        assert!(parse(&npy("<f8", "(0,)", false, &[])).unwrap().is_empty());
    }

    #[test]
    fn other_arrays_are_refused_saying_why() {
        let err = parse(&npy("<f8", "(2, 3)", false, &[0; 48])).unwrap_err().to_string();
        assert!(err.contains("shape '(2, 3)'") && err.contains("points[:, :2]"), "{err}");
        let err = parse(&npy("<c16", "(1, 2)", false, &[0; 32])).unwrap_err().to_string();
        assert!(err.contains("dtype '<c16'"), "{err}");
        let err = parse(&npy("<f8", "(2, 2)", false, &[0; 20])).unwrap_err().to_string();
        assert!(err.contains("end after 2 of the 2 x 2 values"), "{err}");
        let nan: Vec<u8> = [0.0, f64::NAN].iter().flat_map(|v| v.to_le_bytes()).collect();
        assert!(parse(&npy("<f8", "(1, 2)", false, &nan))
            .unwrap_err()
            .to_string()
            .contains("row 0"));
        let many = read(&npy("<f8", "(2, 2)", false, &[0; 32])[..], "t.npy", 1).unwrap_err();
        assert!(many.to_string().contains("more than 1 points"), "{many}");
    }

    #[test]
    fn a_header_cannot_make_the_reader_allocate_or_overflow() {
        // Issue 30, G5: 10^8 rows announced and no data; 2^60 rows with a raised limit.
        let header = npy("<f8", "(100000000, 2)", false, &[]);
        let err = read(&header[..], "t.npy", usize::MAX).unwrap_err().to_string();
        assert!(err.contains("end after 0 of the 100000000 x 2 values"), "{err}");
        let header = npy("<f8", "(1152921504606846976, 2)", false, &[0; 64]);
        let err = read(&header[..], "t.npy", usize::MAX).unwrap_err().to_string();
        assert!(err.contains("end after 8 of the 1152921504606846976 x 2"), "{err}");
        let header = npy("<f8", "(18446744073709551615, 2)", false, &[]);
        assert!(read(&header[..], "t.npy", usize::MAX).is_err());
    }

    #[test]
    fn integers_a_float64_cannot_hold_are_refused() {
        // Issue 30, G26: they were rounded silently.
        let big: Vec<u8> = [(1i64 << 53) + 1, 0].iter().flat_map(|v| v.to_le_bytes()).collect();
        let err = parse(&npy("<i8", "(1, 2)", false, &big)).unwrap_err().to_string();
        assert!(err.contains("row 0: an integer beyond 2^53"), "{err}");
        let fine: Vec<u8> = [1i64 << 53, -(1 << 53)].iter().flat_map(|v| v.to_le_bytes()).collect();
        assert_eq!(
            parse(&npy("<i8", "(1, 2)", false, &fine)).unwrap(),
            [[9007199254740992.0, -9007199254740992.0]]
        );
    }

    #[test]
    fn header_values_in_messages_are_quoted() {
        // Fuzz finding 12: descr and shape reached the terminal raw (ESC) and whole.
        let err = parse(&npy("\u{1b}[2J", "(1, 2)", false, &[0; 16])).unwrap_err().to_string();
        assert!(err.contains(r"dtype '\u{1b}[2J'"), "{err}");
        let long = format!("({})", vec!["1"; 1000].join(","));
        let err = parse(&npy("<f8", &long, false, &[])).unwrap_err().to_string();
        assert!(err.len() < 300, "{err}");
    }
}
