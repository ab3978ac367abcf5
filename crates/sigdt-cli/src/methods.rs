//! `--method`: the one place where the command line turns method names into [`Method`]s.
//!
//! A single method (`reconstruct`, `eval`, `render`, `view`, the bench worker) is checked by
//! clap against [`Method::ALL`], and the lists of `bench` and `sweep` (`M1,M2,...` or `all`)
//! by [`list_parser`]; either way a wrong name is a usage error (exit status 2) that lists
//! the names. Both go through [`Method`]'s `FromStr`.

use clap::builder::{PossibleValuesParser, TypedValueParser};
use sigdt::Method;

/// The value parser of a single `--method`: the names of [`Method::ALL`], shown in the help.
pub fn parser() -> impl TypedValueParser<Value = Method> {
    let names = Method::ALL.iter().map(|m| m.name());
    PossibleValuesParser::new(names).try_map(|s| s.parse::<Method>())
}

/// The value parser of a `--method` list: the text as given, once [`list`] accepts it.
pub fn list_parser() -> impl TypedValueParser<Value = String> {
    clap::builder::StringValueParser::new().try_map(|text| list(&text).map(|_| text))
}

/// The methods of a `--method` list: comma-separated names (repeats dropped), or `all`.
pub fn list(text: &str) -> Result<Vec<Method>, sigdt::Error> {
    if text.trim() == "all" {
        return Ok(Method::ALL.to_vec());
    }
    let mut methods = Vec::new();
    for name in text.split(',').map(str::trim).filter(|s| !s.is_empty()) {
        let method: Method = name.parse()?;
        if !methods.contains(&method) {
            methods.push(method);
        }
    }
    if methods.is_empty() {
        return Err(sigdt::Error::InvalidOption("--method lists no method".into()));
    }
    Ok(methods)
}

/// [`list`] as the kebab-case names the bench workers are given.
pub fn names(text: &str) -> Result<Vec<String>, sigdt::Error> {
    Ok(list(text)?.iter().map(|m| m.to_string()).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lists_parse() {
        assert_eq!(list("all").unwrap(), Method::ALL);
        assert_eq!(names(" crust, sig-auto,crust,").unwrap(), ["crust", "sig-auto"]);
        assert!(list(",").unwrap_err().to_string().contains("lists no method"));
        assert!(list("crust,nope").unwrap_err().to_string().contains("unknown method 'nope'"));
    }
}
