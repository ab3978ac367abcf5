//! The crate's one error type. Every variant names the offending point, file or line.

/// Everything that can go wrong in `sigdt`. Finishing without reaching a goal (for example
/// sculpting getting stuck) is not an error: it is reported in the result's status.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// A coordinate is NaN or infinite.
    #[error("point {index} has a non-finite coordinate ({x}, {y})")]
    NonFinite {
        /// 0-based index of the point in the input.
        index: usize,
        /// Its x coordinate as given.
        x: f64,
        /// Its y coordinate as given.
        y: f64,
    },
    /// The coordinates span more binary orders of magnitude than exact predicates allow.
    #[error(
        "point {index} has a coordinate ({value:?}) more than about 2^172 times smaller than the \
         largest coordinate ({largest:?}); exact predicates cannot handle that range"
    )]
    CoordinateRange {
        /// 0-based index of the point in the input.
        index: usize,
        /// The offending coordinate.
        value: f64,
        /// The largest absolute coordinate of the input.
        largest: f64,
    },
    /// The input has more points than 32-bit indices can address.
    #[error("{got} points is more than the {max} this build supports")]
    TooManyPoints {
        /// Number of points given.
        got: usize,
        /// Largest supported number.
        max: usize,
    },
    /// An option has a value outside its domain.
    #[error("invalid option: {0}")]
    InvalidOption(String),
    /// A file (or stream) could not be parsed.
    #[error("{path}:{line}: {message}")]
    Parse {
        /// File name as given, or `<stdin>`.
        path: String,
        /// 1-based line number.
        line: usize,
        /// What is wrong on that line.
        message: String,
    },
    /// An I/O error, with the path it concerns.
    #[error("{path}: {source}")]
    Io {
        /// File name as given.
        path: String,
        /// The underlying error.
        #[source]
        source: std::io::Error,
    },
}

/// `Result` with [`Error`] as the default error type.
pub type Result<T, E = Error> = std::result::Result<T, E>;

/// The entry of `all` called `s`, or [`Error::InvalidOption`] naming `what` and listing every
/// name: the one parser behind the kebab-case names of methods and formats.
pub fn find_by_name<T: Copy>(
    all: &[T],
    name: impl Fn(T) -> &'static str,
    s: &str,
    what: &str,
) -> Result<T> {
    all.iter().copied().find(|&x| name(x) == s).ok_or_else(|| {
        let names: Vec<_> = all.iter().map(|&x| name(x)).collect();
        Error::InvalidOption(format!(
            "unknown {what} '{s}' (expected one of: {})",
            names.join(", ")
        ))
    })
}
