//! Coordinate reference systems as GIS files carry them: an authority code (`EPSG:27700`)
//! and, where the file gives one, the WKT definition. sigdt does not transform coordinates
//! between systems; it carries the system from the input to every GIS output, and tells
//! geographic (longitude/latitude) systems apart, whose degrees are not lengths.

use std::fmt;

use super::geographic_codes::GEOGRAPHIC;

/// A coordinate reference system.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Crs {
    /// The EPSG code, when known (`OGC:CRS84` counts as 4326: the same datum and units).
    pub epsg: Option<u32>,
    /// The WKT definition, when the file gave one.
    pub wkt: Option<String>,
}

/// The largest code a GeoPackage can store (its `srs_id` is a 32-bit signed integer); EPSG
/// codes stay far below it.
pub const MAX_CODE: u32 = i32::MAX as u32;

/// The WKT of EPSG:4326, written to GeoPackages (whose definition column may not be empty)
/// when only the code is known.
pub const WGS84_WKT: &str = r#"GEOGCS["WGS 84",DATUM["WGS_1984",SPHEROID["WGS 84",6378137,298.257223563,AUTHORITY["EPSG","7030"]],AUTHORITY["EPSG","6326"]],PRIMEM["Greenwich",0,AUTHORITY["EPSG","8901"]],UNIT["degree",0.0174532925199433,AUTHORITY["EPSG","9122"]],AXIS["Latitude",NORTH],AXIS["Longitude",EAST],AUTHORITY["EPSG","4326"]]"#;

impl Crs {
    /// The system with EPSG code `code`.
    pub fn epsg(code: u32) -> Crs {
        Crs { epsg: Some(code), wkt: None }
    }

    /// `--crs` and GeoJSON's legacy `crs` name: `EPSG:NNNN` (any case), `OGC:CRS84` or
    /// `CRS84`, a bare number (an EPSG code), and the OGC names of those: URNs
    /// (`urn:ogc:def:crs:EPSG::27700`, with or without a version such as `6.6`) and http
    /// URIs (`http://www.opengis.net/def/crs/EPSG/0/27700`).
    pub fn parse(text: &str) -> Result<Crs, String> {
        let text = text.trim();
        let upper = text.to_ascii_uppercase();
        // OGC's two spellings of authority, version and code, as `AUTHORITY:CODE`.
        let urn = upper.strip_prefix("URN:OGC:DEF:CRS:").and_then(|rest| {
            let (authority, rest) = rest.split_once(':')?;
            let (_version, code) = rest.rsplit_once(':')?;
            Some(format!("{authority}:{code}"))
        });
        let uri = ["HTTP://WWW.OPENGIS.NET/DEF/CRS/", "HTTPS://WWW.OPENGIS.NET/DEF/CRS/"]
            .iter()
            .find_map(|prefix| upper.strip_prefix(prefix))
            .and_then(|rest| match rest.split('/').collect::<Vec<_>>()[..] {
                [authority, _version, code] => Some(format!("{authority}:{code}")),
                _ => None,
            });
        let upper = urn.or(uri).unwrap_or(upper);
        if matches!(upper.as_str(), "OGC:CRS84" | "CRS84") {
            return Ok(Crs::epsg(4326));
        }
        let code = upper.strip_prefix("EPSG:").unwrap_or(&upper);
        match code.parse::<u32>() {
            // GeoPackage stores codes as 32-bit signed integers.
            Ok(code) if code > 0 && code <= MAX_CODE => Ok(Crs::epsg(code)),
            _ => Err(format!(
                "{} is not a coordinate reference system sigdt knows: give EPSG:NNNN (for \
                 example EPSG:4326 for longitude/latitude, EPSG:27700 for the British grid)",
                crate::text::quoted(text)
            )),
        }
    }

    /// The system a WKT definition describes: its EPSG code when the definition names one
    /// for the whole system (the root's last `AUTHORITY["EPSG","N"]` in WKT 1, `ID["EPSG",N]`
    /// in WKT 2), and the definition itself.
    pub fn from_wkt(wkt: &str) -> Crs {
        // A byte-order mark is no part of the definition (Windows tools write one).
        let wkt = wkt.trim_start_matches('\u{feff}').trim();
        Crs { epsg: root_epsg(wkt), wkt: (!wkt.is_empty()).then(|| wkt.to_string()) }
    }

    /// Whether the definition is a WKT coordinate system: a CRS keyword of WKT 1 or 2, then
    /// brackets (or parentheses) that close at the end. A `.prj` that is not one is refused
    /// rather than copied into outputs as a definition.
    pub fn is_wkt_definition(&self) -> bool {
        const KEYWORDS: [&str; 17] = [
            "GEOGCS",
            "PROJCS",
            "GEOCCS",
            "COMPD_CS",
            "VERT_CS",
            "LOCAL_CS",
            "GEOGCRS",
            "GEOGRAPHICCRS",
            "PROJCRS",
            "PROJECTEDCRS",
            "GEODCRS",
            "GEODETICCRS",
            "BOUNDCRS",
            "COMPOUNDCRS",
            "VERTCRS",
            "ENGCRS",
            "ENGINEERINGCRS",
        ];
        let Some(wkt) = &self.wkt else { return false };
        let open = wkt.find(['[', '(']).unwrap_or(wkt.len());
        let keyword = wkt[..open].trim().to_ascii_uppercase();
        let mut depth = 0i64;
        let mut quoted = false;
        for (k, c) in wkt.char_indices().skip_while(|&(k, _)| k < open) {
            match c {
                '"' => quoted = !quoted,
                '[' | '(' if !quoted => depth += 1,
                ']' | ')' if !quoted => {
                    depth -= 1;
                    if depth == 0 {
                        return KEYWORDS.contains(&keyword.as_str())
                            && wkt[k + 1..].trim().is_empty();
                    }
                }
                _ => {}
            }
        }
        false
    }

    /// Whether coordinates are longitude and latitude in degrees: `Some(true)` for a
    /// geographic system (a WKT `GEOGCS`/`GEOGCRS`, or an EPSG code of the registry's
    /// geographic systems, `geographic_codes.rs`), `Some(false)` for any other (projected,
    /// geocentric: the code is not among them), `None` when nothing says.
    pub fn is_geographic(&self) -> Option<bool> {
        if let Some(wkt) = &self.wkt {
            let head = wkt.trim_start().to_ascii_uppercase();
            if head.starts_with("GEOGCS") || head.starts_with("GEOGCRS") {
                return Some(true);
            }
            if head.starts_with("PROJCS") || head.starts_with("PROJCRS") {
                return Some(false);
            }
        }
        self.epsg.map(|code| GEOGRAPHIC.binary_search(&code).is_ok())
    }
}

impl fmt::Display for Crs {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.epsg {
            Some(code) => write!(f, "EPSG:{code}"),
            None => f.write_str("a coordinate system without an EPSG code"),
        }
    }
}

/// The EPSG code of the whole system in a WKT definition: the authority clause that closes
/// the root (the last one at depth one), not those of its datum or units.
fn root_epsg(wkt: &str) -> Option<u32> {
    let bytes = wkt.as_bytes();
    let mut depth = 0usize;
    let mut found = None;
    let mut i = 0;
    while i < bytes.len() {
        match bytes[i] {
            b'[' | b'(' => depth += 1,
            b']' | b')' => depth = depth.saturating_sub(1),
            b'"' => {
                // Skip a quoted string ("" escapes a quote).
                i += 1;
                while i < bytes.len() && !(bytes[i] == b'"' && bytes.get(i + 1) != Some(&b'"')) {
                    i += if bytes[i] == b'"' { 2 } else { 1 };
                }
            }
            _ if depth == 1 => {
                let rest = &bytes[i..];
                let starts =
                    |p: &[u8]| rest.get(..p.len()).is_some_and(|r| r.eq_ignore_ascii_case(p));
                if starts(b"AUTHORITY[") || starts(b"ID[") {
                    // `i` is at an ASCII letter: a character boundary.
                    found = authority_code(&wkt[i..]).or(found);
                }
            }
            _ => {}
        }
        i += 1;
    }
    found
}

/// The code of `AUTHORITY["EPSG","27700"]` or `ID["EPSG",27700]` at the start of `clause`.
fn authority_code(clause: &str) -> Option<u32> {
    let open = clause.find('[')?;
    let close = clause[open..].find(']')? + open;
    let mut fields = clause[open + 1..close].split(',').map(|f| f.trim().trim_matches('"'));
    let authority = fields.next()?;
    let code = fields.next()?;
    let code = code.parse().ok().filter(|&c| c > 0 && c <= MAX_CODE);
    authority.eq_ignore_ascii_case("EPSG").then_some(code).flatten()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn codes_parse_in_the_spellings_people_use() {
        for text in ["EPSG:27700", "epsg:27700", " 27700 ", "urn:ogc:def:crs:EPSG::27700"] {
            assert_eq!(Crs::parse(text), Ok(Crs::epsg(27700)), "{text}");
        }
        assert_eq!(Crs::parse("OGC:CRS84"), Ok(Crs::epsg(4326)));
        let err = Crs::parse("WGS84").unwrap_err();
        assert!(err.starts_with("'WGS84' is not a coordinate reference system"), "{err}");
        assert!(Crs::parse("EPSG:0").is_err() && Crs::parse("EPSG:-1").is_err());
    }

    #[test]
    fn the_root_authority_names_the_system_not_its_datum() {
        assert_eq!(Crs::from_wkt(WGS84_WKT).epsg, Some(4326));
        assert_eq!(Crs::from_wkt(WGS84_WKT).is_geographic(), Some(true));
        let projected = r#"PROJCS["OSGB36 / British National Grid",GEOGCS["OSGB36",DATUM["x",SPHEROID["Airy 1830",6377563.396,299.3249646,AUTHORITY["EPSG","7001"]]],AUTHORITY["EPSG","4277"]],PROJECTION["Transverse_Mercator"],UNIT["metre",1,AUTHORITY["EPSG","9001"]],AUTHORITY["EPSG","27700"]]"#;
        let crs = Crs::from_wkt(projected);
        assert_eq!((crs.epsg, crs.is_geographic()), (Some(27700), Some(false)));
        // An ESRI .prj names no authority: the definition is kept, the code unknown.
        let esri = r#"PROJCS["British_National_Grid",GEOGCS["GCS_OSGB_1936",DATUM["D_OSGB_1936",SPHEROID["Airy_1830",6377563.396,299.3249646]]],UNIT["Meter",1.0]]"#;
        let crs = Crs::from_wkt(esri);
        assert_eq!((crs.epsg, crs.is_geographic()), (None, Some(false)));
        let wkt2 = r#"GEOGCRS["WGS 84",DATUM["World Geodetic System 1984",ELLIPSOID["WGS 84",6378137,298.257223563]],CS[ellipsoidal,2],ID["EPSG",4326]]"#;
        assert_eq!(Crs::from_wkt(wkt2).epsg, Some(4326));
        assert_eq!(Crs::epsg(27700).is_geographic(), Some(false));
    }

    #[test]
    fn any_text_is_a_definition_without_a_code() {
        // Fuzz finding 15: a FlatGeobuf header's WKT with a multi-byte character at depth one
        // was sliced inside it.
        let odd = "   ]   [   \u{500}  ))) [ \u{500}AUTHORITY[\"EPSG\",\"1\"]";
        assert_eq!(Crs::from_wkt(odd).epsg, Some(1), "the clause at depth one counts");
        assert_eq!(Crs::from_wkt("X[\u{500}ID[\"EPSG\",7]]").epsg, Some(7));
        for text in ["", "[", "]]]", "\"", "X[\"a\"\"b\",AUTHORITY[\"EPSG\"]]"] {
            assert_eq!(Crs::from_wkt(text).epsg, None, "{text:?}");
        }
    }

    #[test]
    fn a_byte_order_mark_does_not_hide_a_geographic_system() {
        // Issue 47, K4: a .prj starting with a byte-order mark was not read as geographic,
        // and degrees were reconstructed as a plane.
        let crs = Crs::from_wkt(&format!("\u{feff}{WGS84_WKT}"));
        assert_eq!((crs.epsg, crs.is_geographic()), (Some(4326), Some(true)));
        assert!(crs.is_wkt_definition());
    }

    #[test]
    fn codes_past_what_a_geopackage_stores_are_refused() {
        // Issue 47, K9: EPSG:3000000000 was accepted and written as a negative srs_id.
        let err = Crs::parse("EPSG:3000000000").unwrap_err();
        assert!(err.starts_with("'EPSG:3000000000' is not a coordinate reference system"), "{err}");
        assert_eq!(Crs::parse("EPSG:2147483647"), Ok(Crs::epsg(2_147_483_647)));
        assert_eq!(Crs::from_wkt("GEOGCS[\"x\",AUTHORITY[\"EPSG\",\"3000000000\"]]").epsg, None);
    }

    #[test]
    fn only_wkt_coordinate_systems_are_definitions() {
        // Issue 47, K7: any text of a .prj was copied into outputs as the definition.
        assert!(Crs::from_wkt(WGS84_WKT).is_wkt_definition());
        let wkt2 = r#"PROJCRS["x",BASEGEOGCRS["y",DATUM["z",ELLIPSOID["w",1,0]]],CS[Cartesian,2]]"#;
        assert!(Crs::from_wkt(wkt2).is_wkt_definition());
        for text in
            ["secret=hunter2", "GEOGCS[\"x\"", "GEOGCS[\"x\"] trailing", "FOO[\"x\"]", "", "[]"]
        {
            assert!(!Crs::from_wkt(text).is_wkt_definition(), "{text:?}");
        }
        // A bracket inside a quoted name does not close the definition.
        assert!(Crs::from_wkt(r#"GEOGCS["a]b",UNIT["degree",0.0174]]"#).is_wkt_definition());
    }

    #[test]
    fn every_ogc_spelling_of_a_code_is_read() {
        // Issue 47, K1: a versioned URN or an OGC http URI was dropped silently.
        for text in [
            "urn:ogc:def:crs:EPSG:6.6:27700",
            "urn:ogc:def:crs:EPSG::27700",
            "http://www.opengis.net/def/crs/EPSG/0/27700",
            "https://www.opengis.net/def/crs/EPSG/9.9.1/27700",
        ] {
            assert_eq!(Crs::parse(text), Ok(Crs::epsg(27700)), "{text}");
        }
        for text in
            ["urn:ogc:def:crs:OGC:1.3:CRS84", "http://www.opengis.net/def/crs/OGC/1.3/CRS84"]
        {
            assert_eq!(Crs::parse(text), Ok(Crs::epsg(4326)), "{text}");
        }
        for text in ["urn:ogc:def:crs:ESRI::102100", "http://www.opengis.net/def/crs/EPSG/27700"] {
            assert!(Crs::parse(text).is_err(), "{text}");
        }
    }

    #[test]
    fn geographic_is_decided_by_the_registry_not_a_range_of_codes() {
        // Issue 47, K2: degrees in EPSG:6318 (NAD83(2011)) and 7844 (GDA2020) were read as a
        // plane, and metres in EPSG:4087 (World Equidistant Cylindrical) and 4978 (WGS 84
        // geocentric) as degrees.
        for code in [4326, 4269, 4258, 6318, 7844, 4979, 10671] {
            assert_eq!(Crs::epsg(code).is_geographic(), Some(true), "EPSG:{code}");
        }
        for code in [4087, 4978, 3857, 27700, 32633, 2154] {
            assert_eq!(Crs::epsg(code).is_geographic(), Some(false), "EPSG:{code}");
        }
        assert!(GEOGRAPHIC.windows(2).all(|w| w[0] < w[1]), "sorted, for the binary search");
    }
}
