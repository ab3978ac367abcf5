//! Reading a byte stream, for every reader of binary or streamed formats.

use std::io::{ErrorKind, Read, Result};

/// Reads into `buf` until it is full or the input ends; the number of bytes read (fewer
/// than `buf.len()` only at the end).
pub fn read_full(reader: &mut impl Read, buf: &mut [u8]) -> Result<usize> {
    let mut got = 0;
    while got < buf.len() {
        match reader.read(&mut buf[got..]) {
            Ok(0) => break,
            Ok(n) => got += n,
            Err(e) if e.kind() == ErrorKind::Interrupted => {}
            Err(e) => return Err(e),
        }
    }
    Ok(got)
}
