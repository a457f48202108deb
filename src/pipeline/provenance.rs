//! Provenance: which ndfplot drew a figure, and from which spec.
//!
//! The one place that computes the record every drawn output carries: the ndfplot version and the
//! SHA-256 of the spec's bytes exactly as read (for the built-in catalogue, the embedded text of
//! `configs/<id>.json`, which equals the file), so `sha256sum configs/x.json` verifies it. It must
//! not know any output format: exporters embed the fields it names, each in its format's own
//! metadata. Nothing in it varies between runs (no time, no host, no random id), so outputs stay
//! byte-for-byte deterministic.

use sha2::{Digest, Sha256};

/// Key of the ndfplot version in every format's metadata.
pub const VERSION_KEY: &str = "ndfplot-version";
/// Key of the spec's SHA-256 (64 lowercase hex digits) in every format's metadata.
pub const SPEC_SHA256_KEY: &str = "spec-sha256";

/// What a drawn output records about how it was made.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Provenance {
    /// The ndfplot version (`CARGO_PKG_VERSION`).
    pub version: &'static str,
    /// SHA-256 of the spec's bytes as lowercase hex; `None` for figures drawn from no spec
    /// (the timing figure of `bench`).
    pub spec_sha256: Option<String>,
}

impl Provenance {
    /// The record of a figure drawn from the spec whose bytes, exactly as read, are `spec`.
    pub fn of_spec(spec: &[u8]) -> Provenance {
        let digest = Sha256::digest(spec);
        let hex = digest.iter().map(|b| format!("{b:02x}")).collect();
        Provenance {
            version: env!("CARGO_PKG_VERSION"),
            spec_sha256: Some(hex),
        }
    }

    /// The record of a figure that no spec describes: the version only.
    pub fn without_spec() -> Provenance {
        Provenance {
            version: env!("CARGO_PKG_VERSION"),
            spec_sha256: None,
        }
    }

    /// The record as (key, value) pairs, version first: [`VERSION_KEY`], then [`SPEC_SHA256_KEY`]
    /// when there is a spec. Keys and values are ASCII without spaces or `=`.
    pub fn fields(&self) -> Vec<(&'static str, String)> {
        let mut fields = vec![(VERSION_KEY, self.version.to_owned())];
        if let Some(hash) = &self.spec_sha256 {
            fields.push((SPEC_SHA256_KEY, hash.clone()));
        }
        fields
    }

    /// The fields as `key=value` words, e.g. `ndfplot-version=0.1.0`, in [`Provenance::fields`]
    /// order: the form SVG and PDF metadata carry, so `grep -o 'spec-sha256=[0-9a-f]*'` reads it.
    pub fn words(&self) -> Vec<String> {
        self.fields()
            .into_iter()
            .map(|(key, value)| format!("{key}={value}"))
            .collect()
    }

    /// `ndfplot <version>`: the producing program, as PNG `Software` and PDF `Producer` name it.
    pub fn software(&self) -> String {
        format!("ndfplot {}", self.version)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_hash_is_sha256_of_the_bytes_as_given() {
        // FIPS 180-2, appendix B.1: SHA-256("abc").
        let abc = Provenance::of_spec(b"abc");
        assert_eq!(
            abc.spec_sha256.as_deref(),
            Some("ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad")
        );
        assert_eq!(abc.version, env!("CARGO_PKG_VERSION"));
        assert_ne!(Provenance::of_spec(b"abc\n"), abc, "bytes, not parsed JSON");
    }

    #[test]
    fn fields_and_words_name_the_version_then_the_spec() {
        let record = Provenance::of_spec(b"");
        let version = env!("CARGO_PKG_VERSION");
        let empty = "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855";
        assert_eq!(
            record.words(),
            [
                format!("ndfplot-version={version}"),
                format!("spec-sha256={empty}")
            ]
        );
        assert_eq!(
            Provenance::without_spec().fields(),
            [(VERSION_KEY, version.to_owned())]
        );
        assert_eq!(record.software(), format!("ndfplot {version}"));
    }
}
