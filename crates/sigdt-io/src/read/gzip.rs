//! Decompressing gzip input as it is read: every member of a multi-member file (as `cat a.gz
//! b.gz` makes), zero bytes after the last member ignored as `gzip -d` ignores them (tape and
//! block-device padding), and anything else after it refused.
//!
//! # Complexity
//! O(length of the input), streamed: memory is the decoder's window and one buffer.

use std::io::{self, BufRead, Read};

use flate2::bufread::GzDecoder;

/// The gzip magic bytes.
pub const MAGIC: &[u8] = &[0x1f, 0x8b];

/// A reader of the decompressed members of `R`; see the module docs.
pub struct Members<R: BufRead> {
    /// The member being read; `None` once the input has ended.
    member: Option<GzDecoder<R>>,
}

impl<R: BufRead> Members<R> {
    /// The members of `reader`, which starts with [`MAGIC`].
    pub fn new(reader: R) -> Self {
        Members { member: Some(GzDecoder::new(reader)) }
    }

    /// After a member's end: the next member, or the end of input (with nothing after the
    /// last member but zero bytes).
    fn next_member(&mut self, mut inner: R) -> io::Result<Option<GzDecoder<R>>> {
        loop {
            let rest = inner.fill_buf()?;
            if rest.is_empty() {
                return Ok(None);
            }
            if rest.starts_with(MAGIC) {
                return Ok(Some(GzDecoder::new(inner)));
            }
            if rest.iter().any(|&b| b != 0) {
                return Err(io::Error::new(
                    io::ErrorKind::InvalidData,
                    "data after the last gzip member are not gzip (a truncated or \
                     concatenated file?)",
                ));
            }
            let n = rest.len();
            inner.consume(n);
        }
    }
}

impl<R: BufRead> Read for Members<R> {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        while let Some(member) = self.member.as_mut() {
            let n = member.read(buf)?;
            if n > 0 || buf.is_empty() {
                return Ok(n);
            }
            let member = self.member.take().expect("a member is being read");
            self.member = self.next_member(member.into_inner())?;
        }
        Ok(0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::Write;

    fn gz(bytes: &[u8]) -> Vec<u8> {
        let mut e = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::fast());
        e.write_all(bytes).unwrap();
        e.finish().unwrap()
    }

    fn read(bytes: &[u8]) -> io::Result<String> {
        let mut text = String::new();
        Members::new(bytes).read_to_string(&mut text)?;
        Ok(text)
    }

    #[test]
    fn members_zero_padding_and_what_is_refused() {
        // Issue 30, G26: zero padding gave "invalid gzip header".
        let two = [gz(b"0 0\n"), gz(b"1 1\n")].concat();
        assert_eq!(read(&two).unwrap(), "0 0\n1 1\n");
        let padded = [gz(b"0 0\n"), vec![0; 100_000]].concat();
        assert_eq!(read(&padded).unwrap(), "0 0\n");
        let trailing = [gz(b"0 0\n"), b"junk".to_vec()].concat();
        assert!(read(&trailing).unwrap_err().to_string().contains("after the last gzip member"));
        assert_eq!(read(&gz(b"")).unwrap(), "");
    }
}
