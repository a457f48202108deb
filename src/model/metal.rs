//! Measured complex indices of refraction η̃ = η + iκ of five metals, by name: the tables of
//! `data/published/pbrt-v4/metal_ior.csv` (Apache-2.0, pbrt-v4 `src/pbrt/util/spectrum.cpp`; notice
//! in `data/published/README.md`), embedded verbatim and read on first use.
//!
//! Between two tabulated wavelengths λ₀ < λ < λ₁, η and κ are each interpolated linearly in λ
//! (docs/maths.md "Metals", as pbrt-v4's piecewise-linear spectra do); at a tabulated wavelength the
//! table's value is returned unchanged. Outside the table's range there is no value: a metal's
//! index is refused there, never extrapolated.
//!
//! This module holds the data and interpolates; the curve format ([`crate::spec::curve`]) reads the
//! names and builds the Fresnel curve from the index.

use std::sync::OnceLock;

/// A metal of the table (`"metal": "<symbol or name>"`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Metal {
    /// Silver.
    Ag,
    /// Aluminium.
    Al,
    /// Gold.
    Au,
    /// Copper.
    Cu,
    /// Brass, a copper–zinc alloy.
    CuZn,
}

impl Metal {
    /// Every metal, in the table's order.
    pub const ALL: [Metal; 5] = [Metal::Ag, Metal::Al, Metal::Au, Metal::Cu, Metal::CuZn];

    /// The chemical symbol, as the table and legends write it (`Au`, `CuZn`).
    pub fn symbol(self) -> &'static str {
        match self {
            Metal::Ag => "Ag",
            Metal::Al => "Al",
            Metal::Au => "Au",
            Metal::Cu => "Cu",
            Metal::CuZn => "CuZn",
        }
    }

    /// The English names, the first one listed (aluminium also answers to aluminum).
    pub fn names(self) -> &'static [&'static str] {
        match self {
            Metal::Ag => &["silver"],
            Metal::Al => &["aluminium", "aluminum"],
            Metal::Au => &["gold"],
            Metal::Cu => &["copper"],
            Metal::CuZn => &["brass"],
        }
    }

    /// Every symbol and name a metal answers to, in the order messages list them.
    pub fn all_names() -> impl Iterator<Item = &'static str> {
        Metal::ALL
            .into_iter()
            .flat_map(|m| std::iter::once(m.symbol()).chain(m.names().iter().copied()))
    }

    /// Looks a metal up by symbol or English name, in any case.
    pub fn from_name(name: &str) -> Option<Metal> {
        Metal::ALL.into_iter().find(|m| {
            m.symbol().eq_ignore_ascii_case(name)
                || m.names().iter().any(|n| n.eq_ignore_ascii_case(name))
        })
    }

    /// The tabulated wavelengths' range [λ_min, λ_max] in nm.
    pub fn range_nm(self) -> (f64, f64) {
        let table = table(self);
        (
            table.wavelengths[0],
            table.wavelengths[table.wavelengths.len() - 1],
        )
    }

    /// How many wavelengths the table holds (each with η and κ).
    pub fn samples(self) -> usize {
        table(self).wavelengths.len()
    }

    /// (η, κ) at `wavelength_nm`, interpolated linearly in λ between the two tabulated samples
    /// around it (a tabulated wavelength gives the table's values exactly); `None` outside
    /// [`Metal::range_nm`] or for a non-finite wavelength.
    pub fn index_at(self, wavelength_nm: f64) -> Option<(f64, f64)> {
        let table = table(self);
        let (min, max) = self.range_nm();
        if !(min..=max).contains(&wavelength_nm) {
            return None;
        }
        // The last sample at or below λ: λ lies in [λ_i, λ_{i+1}), or is the last sample.
        let i = table.wavelengths.partition_point(|&l| l <= wavelength_nm) - 1;
        if table.wavelengths[i] == wavelength_nm {
            return Some((table.eta[i], table.kappa[i]));
        }
        let (l0, l1) = (table.wavelengths[i], table.wavelengths[i + 1]);
        let t = (wavelength_nm - l0) / (l1 - l0);
        let lerp = |v: &[f64]| v[i] + t * (v[i + 1] - v[i]);
        Some((lerp(&table.eta), lerp(&table.kappa)))
    }
}

/// One metal's samples: increasing wavelengths (nm) with η and κ at each.
#[derive(Debug, Default)]
struct Table {
    wavelengths: Vec<f64>,
    eta: Vec<f64>,
    kappa: Vec<f64>,
}

/// The embedded CSV: `metal,quantity,wavelength_nm,value` rows, quantity `eta` or `k`.
const CSV: &str = include_str!("../../data/published/pbrt-v4/metal_ior.csv");

/// The samples of `metal`, read from the embedded table on first use.
fn table(metal: Metal) -> &'static Table {
    static TABLES: OnceLock<Vec<Table>> = OnceLock::new();
    let index = Metal::ALL
        .iter()
        .position(|&m| m == metal)
        .expect("ALL lists every metal");
    &TABLES.get_or_init(read_tables)[index]
}

/// Reads every row of [`CSV`] into its metal's table. The η rows and the κ rows of a metal list the
/// same increasing wavelengths (a test checks it); a row that cannot be read is a broken build,
/// caught by the same test.
fn read_tables() -> Vec<Table> {
    let mut tables: Vec<Table> = Metal::ALL.iter().map(|_| Table::default()).collect();
    for line in CSV.lines().skip(1).filter(|l| !l.trim().is_empty()) {
        let fields: Vec<&str> = line.split(',').collect();
        let [symbol, quantity, wavelength, value] = fields[..] else {
            panic!("metal table row without four fields: {line}");
        };
        let metal = Metal::ALL
            .iter()
            .position(|m| m.symbol() == symbol)
            .unwrap_or_else(|| panic!("metal table row of an unknown metal: {line}"));
        let number = |text: &str| -> f64 {
            text.parse()
                .unwrap_or_else(|_| panic!("metal table row with a bad number: {line}"))
        };
        let table = &mut tables[metal];
        match quantity {
            "eta" => {
                table.wavelengths.push(number(wavelength));
                table.eta.push(number(value));
            }
            "k" => table.kappa.push(number(value)),
            _ => panic!("metal table row of an unknown quantity: {line}"),
        }
    }
    tables
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each metal's η and κ rows share their wavelengths, which increase, and every row is read.
    #[test]
    fn every_row_is_read_and_eta_and_kappa_share_increasing_wavelengths() {
        let mut rows = 0;
        for metal in Metal::ALL {
            let table = table(metal);
            let kappa_wavelengths: Vec<f64> = CSV
                .lines()
                .filter_map(|l| l.strip_prefix(&format!("{},k,", metal.symbol())))
                .map(|rest| rest.split(',').next().unwrap().parse().unwrap())
                .collect();
            assert_eq!(table.wavelengths, kappa_wavelengths, "{}", metal.symbol());
            assert_eq!(table.eta.len(), table.kappa.len());
            assert!(table.wavelengths.windows(2).all(|w| w[0] < w[1]));
            rows += 2 * table.wavelengths.len();
        }
        assert_eq!(rows, CSV.lines().skip(1).count());
    }

    #[test]
    fn names_and_symbols_are_found_in_any_case() {
        assert_eq!(Metal::from_name("au"), Some(Metal::Au));
        assert_eq!(Metal::from_name("Gold"), Some(Metal::Au));
        assert_eq!(Metal::from_name("ALUMINUM"), Some(Metal::Al));
        assert_eq!(Metal::from_name("aluminium"), Some(Metal::Al));
        assert_eq!(Metal::from_name("cuzn"), Some(Metal::CuZn));
        assert_eq!(Metal::from_name("brass"), Some(Metal::CuZn));
        assert_eq!(Metal::from_name("platinum"), None);
        assert_eq!(Metal::all_names().count(), 11);
    }

    #[test]
    fn the_range_ends_are_in_and_just_past_them_is_out() {
        for metal in Metal::ALL {
            let (min, max) = metal.range_nm();
            assert!(metal.index_at(min).is_some() && metal.index_at(max).is_some());
            assert!(metal.index_at(min.next_down()).is_none());
            assert!(metal.index_at(max.next_up()).is_none());
            assert!(metal.index_at(f64::NAN).is_none());
        }
    }
}
