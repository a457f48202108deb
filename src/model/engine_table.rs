//! An engine's albedo table compared with the exact one: where the engine places its grid, what its
//! numbers are, and the cells (engine value, exact value) with their statistics — the one
//! computation behind `ndfplot albedo --against` and the `{"data": "audit"}` heat map
//! (docs/contracts.md "Auditing an engine's table").
//!
//! Also holds the published tables shipped with the binary ([`PublishedTable`]): Cycles'
//! `table_ggx_E`, embedded from `data/published/cycles/ggx_E.csv` (Apache-2.0, Blender
//! Foundation; provenance in the file's header), and Adobe openpbr-bsdf's ideal-metal energy
//! table, embedded from `data/published/openpbr/` (Apache-2.0, Adobe; provenance in its `LICENSE`).
//!
//! How a file spells a table (its layout keys, its bytes) is [`crate::spec::lut`]'s; the integrals
//! are [`crate::model::albedo`]'s, the statistics [`crate::model::metrics::table`]'s.

use std::sync::OnceLock;

use crate::model::albedo::{
    self, Density, Fresnel, Lambda, Microfacet, ProgressFn, RoughnessMap, Table, albedo_table_at,
    average_albedo_table_at, dfg_tables,
};
use crate::model::masking::G2Model;
use crate::model::math::quad::QuadError;
use crate::model::metrics::table::Cell;
use crate::model::names::named;
use crate::model::ndf::Family;

named! {
    /// A table axis: μ = cos θo or the roughness coordinate r.
    pub enum LutAxis {
        /// μ = cos θo.
        Mu = "mu",
        /// The roughness coordinate r, α = map(r).
        R = "r",
    }
}

named! {
    /// Where the n points of an axis sit in [0, 1].
    pub enum LutGrid {
        /// i/(n − 1): both ends on the grid (Cycles, Adobe).
        Endpoints = "endpoints",
        /// (i + ½)/n: texel centres (a texture sampled at its pixel centres: Filament, Unreal).
        Centers = "centers",
    }
}

named! {
    /// What each number of the table is.
    pub enum LutValue {
        /// E (E_avg for `--table average`).
        E = "e",
        /// 1 − E: the energy single scattering loses (Adobe's tables).
        OneMinusE = "1-e",
        /// DFG1 = E_F with F = 1 − (1 − cos θd)⁵ (`--table dfg`).
        Dfg1 = "dfg1",
        /// DFG2 = E_F with F = (1 − cos θd)⁵ (`--table dfg`).
        Dfg2 = "dfg2",
    }
}

impl LutValue {
    /// The exact value's symbol in `table` (`E`, `1 - E`, `E_avg`, `DFG1`, …).
    pub fn symbol(self, table: Table) -> &'static str {
        match (table, self) {
            (Table::Average, LutValue::OneMinusE) => "1 - E_avg",
            (Table::Average, _) => "E_avg",
            (_, LutValue::OneMinusE) => "1 - E",
            (_, LutValue::Dfg1) => "DFG1",
            (_, LutValue::Dfg2) => "DFG2",
            _ => "E",
        }
    }
}

/// The grid an engine's table sits on, and the order of its numbers.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EngineGrid {
    /// Points on the μ axis (`None` for the average table, which has none).
    pub n_mu: Option<usize>,
    /// Points on the r axis.
    pub n_r: usize,
    /// The axis along each row of the numbers (the other runs down the columns).
    pub rows: LutAxis,
    /// Where the points of each axis sit.
    pub grid: LutGrid,
    /// The engine evaluates its grid at max(coordinate, clamp) (Cycles: 1e-4).
    pub clamp: f64,
}

impl EngineGrid {
    /// The coordinates (μ, r) the engine places its grid at (μ empty for the average table).
    pub fn coordinates(&self) -> (Vec<f64>, Vec<f64>) {
        (
            self.n_mu.map_or_else(Vec::new, |n| axis(self.grid, n)),
            axis(self.grid, self.n_r),
        )
    }

    /// The coordinates the engine evaluates: max(c, clamp) of [`EngineGrid::coordinates`].
    pub fn evaluated(&self) -> (Vec<f64>, Vec<f64>) {
        let clamp = |v: Vec<f64>| v.into_iter().map(|c| c.max(self.clamp)).collect();
        let (mu, r) = self.coordinates();
        (clamp(mu), clamp(r))
    }

    /// The (μ index, r index) of the k-th number in file order.
    pub fn cell(&self, k: usize) -> (usize, usize) {
        match (self.n_mu, self.rows) {
            (None, _) => (0, k),
            (Some(_), LutAxis::Mu) => (k / self.n_r, k % self.n_r),
            (Some(n_mu), LutAxis::R) => (k % n_mu, k / n_mu),
        }
    }
}

/// The n coordinates of an axis on `grid`, as the engine places them.
fn axis(grid: LutGrid, n: usize) -> Vec<f64> {
    match grid {
        LutGrid::Endpoints => albedo::unit_grid(n),
        LutGrid::Centers => (0..n).map(|i| (i as f64 + 0.5) / n as f64).collect(),
    }
}

/// The cells of an engine's table `values` (file order, as many as `grid` has cells) against the
/// exact `table` of the surface `lobe(α)` (`None` the mirror) under `map` and `fresnel`, the
/// exact side taken as `value` says (1 − E for `1-e`; DFG1 or DFG2 of the `dfg` pair). Each
/// cell's coordinates are where the engine places it, its exact value where it evaluates it
/// (after the clamp). `progress` counts exact cells.
pub fn compare<D, L>(
    values: &[f64],
    grid: &EngineGrid,
    (table, value): (Table, LutValue),
    map: RoughnessMap,
    lobe: impl Fn(f64) -> Option<Microfacet<D, L>> + Sync,
    fresnel: Fresnel,
    progress: Option<ProgressFn>,
) -> Result<Vec<Cell>, QuadError>
where
    D: Density + Sync + Send,
    L: Lambda + Sync + Send,
{
    let (mu, r) = grid.coordinates();
    let (mu_eval, r_eval) = grid.evaluated();
    // Exact values, μ-major (index i · n_r + j), or by r alone for the average table.
    let exact: Vec<f64> = match table {
        Table::Average => average_albedo_table_at(&r_eval, map, lobe, fresnel, progress)?,
        Table::Dfg => {
            let [dfg1, dfg2] = dfg_tables(mu_eval, r_eval, map, lobe, progress)?;
            match value {
                LutValue::Dfg1 => dfg1.values,
                _ => dfg2.values,
            }
        }
        _ => albedo_table_at(mu_eval, r_eval, map, lobe, fresnel, progress)?.values,
    };
    let complement = value == LutValue::OneMinusE;
    Ok(values
        .iter()
        .enumerate()
        .map(|(k, &engine)| {
            let (i, j) = grid.cell(k);
            let exact = exact[if grid.n_mu.is_some() {
                i * grid.n_r + j
            } else {
                j
            }];
            Cell {
                mu: mu.get(i).copied().unwrap_or(f64::NAN),
                r: r[j],
                engine,
                exact: if complement { 1.0 - exact } else { exact },
            }
        })
        .collect())
}

named! {
    /// An engine's table shipped with ndfplot (`{"data": "audit", "table": …}`).
    pub enum PublishedTable {
        /// Cycles' `table_ggx_E` (`src/scene/shader.tables`): 32 × 32 Monte Carlo E of GGX with
        /// height-correlated G2 and F = 1, rows μ = max(y/31, 1e-4), columns r = max(x/31, 1e-4),
        /// α = r², float32 printed to 6 decimals.
        CyclesGgxE = "cycles-ggx-e",
        /// Adobe openpbr-bsdf's `openpbr_ideal_metal_energy_complement_data.h`: 32 × 32 Monte
        /// Carlo 1 − E of GGX with separable G2 (`impl/openpbr_lobe_utils.h` l.136-139) and F = 1,
        /// unorm16, one line per r = √α = i/31 running over μ = j/31; its μ = 0 column holds E at
        /// μ ≈ 1e-3 (at α = 1 the exact separable 1 − E is 0.386294 in the limit μ → 0⁺, 0.386907
        /// at μ = 1e-3, the table 0.386893), so it is audited at max(μ, 1e-3), max(r, 1e-3).
        OpenpbrMetal1MinusE = "openpbr-metal-1-e",
    }
}

/// `data/published/cycles/ggx_E.csv`: `table,y,x,value` rows after `#` comment lines.
const CYCLES_CSV: &str = include_str!("../../data/published/cycles/ggx_E.csv");

/// Adobe's table as published: 1024 comma-separated unorm16 integers between two `//` lines.
const OPENPBR_METAL: &str =
    include_str!("../../data/published/openpbr/openpbr_ideal_metal_energy_complement_data.h");

impl PublishedTable {
    /// The engine's name and the table's, for titles (`Cycles' table_ggx_E`).
    pub fn title(self) -> &'static str {
        match self {
            PublishedTable::CyclesGgxE => "Cycles' table_ggx_E",
            PublishedTable::OpenpbrMetal1MinusE => "Adobe openpbr-bsdf's ideal-metal 1 − E",
        }
    }

    /// Its grid and number order.
    pub fn grid(self) -> EngineGrid {
        match self {
            PublishedTable::CyclesGgxE => EngineGrid {
                n_mu: Some(32),
                n_r: 32,
                rows: LutAxis::Mu,
                grid: LutGrid::Endpoints,
                clamp: 1e-4,
            },
            PublishedTable::OpenpbrMetal1MinusE => EngineGrid {
                n_mu: Some(32),
                n_r: 32,
                rows: LutAxis::R,
                grid: LutGrid::Endpoints,
                clamp: 1e-3,
            },
        }
    }

    /// What it tabulates: the table, its value, the roughness map and the G2 model (GGX, F = 1).
    pub fn meaning(self) -> (Table, LutValue, RoughnessMap, G2Model) {
        match self {
            PublishedTable::CyclesGgxE => (
                Table::E,
                LutValue::E,
                RoughnessMap::Squared,
                G2Model::HeightCorrelated,
            ),
            PublishedTable::OpenpbrMetal1MinusE => (
                Table::E,
                LutValue::OneMinusE,
                RoughnessMap::Squared,
                G2Model::Separable,
            ),
        }
    }

    /// Its cells in file order against the exact table it tabulates ([`compare`]), computed in
    /// parallel.
    pub fn audit(self) -> Result<Vec<Cell>, QuadError> {
        let (table, value, map, g2) = self.meaning();
        let lobe = |alpha: f64| {
            albedo::lobe(Family::TrowbridgeReitz, &[alpha])
                .expect("GGX has a lobe at every alpha of [0, 1]")
                .map(|ndf| albedo::surface_of(ndf, g2))
        };
        compare(
            self.values(),
            &self.grid(),
            (table, value),
            map,
            lobe,
            None,
            None,
        )
    }

    /// Its numbers in file order, read from the embedded file on first use (a number that cannot
    /// be read is a broken build, caught by the tests).
    pub fn values(self) -> &'static [f64] {
        static CYCLES: OnceLock<Vec<f64>> = OnceLock::new();
        static OPENPBR: OnceLock<Vec<f64>> = OnceLock::new();
        match self {
            PublishedTable::CyclesGgxE => CYCLES.get_or_init(|| {
                let mut values = vec![f64::NAN; 32 * 32];
                for line in CYCLES_CSV.lines().filter(|l| l.starts_with("ggx_E,")) {
                    let fields: Vec<&str> = line.split(',').collect();
                    let [_, y, x, value] = fields[..] else {
                        panic!("ggx_E row without four fields: {line}");
                    };
                    let index = |s: &str| s.parse::<usize>().expect("a cell index");
                    values[index(y) * 32 + index(x)] = value.parse().expect("a number");
                }
                assert!(values.iter().all(|v| v.is_finite()), "every cell given");
                values
            }),
            PublishedTable::OpenpbrMetal1MinusE => OPENPBR.get_or_init(|| {
                let values: Vec<f64> = OPENPBR_METAL
                    .lines()
                    .filter(|l| !l.trim_start().starts_with("//"))
                    .flat_map(|l| l.split(','))
                    .filter(|k| !k.trim().is_empty())
                    .map(|k| {
                        f64::from(k.trim().parse::<u16>().expect("a unorm16 integer")) / 65535.0
                    })
                    .collect();
                assert_eq!(values.len(), 32 * 32, "every cell given");
                values
            }),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_published_cycles_table_reads_whole() {
        let values = PublishedTable::CyclesGgxE.values();
        // shader.tables: table_ggx_E[0] = 1.0, [1] = 0.980405, [1023] = the (μ = 1, r = 1) cell.
        assert_eq!(values[0], 1.0);
        assert_eq!(values[1], 0.980405);
        assert_eq!(values.len(), 1024);
        // openpbr_ideal_metal_energy_complement_data.h: its first number 0 (r = 0, μ = 0), the
        // 33rd 7765 (r = 1/31, μ = 0), its last 45425 (r = 1, μ = 1).
        let values = PublishedTable::OpenpbrMetal1MinusE.values();
        assert_eq!(values[0], 0.0);
        assert_eq!(values[32], 7765.0 / 65535.0);
        assert_eq!(values[1023], 45425.0 / 65535.0);
    }

    #[test]
    fn grids_place_and_order_their_cells() {
        let grid = EngineGrid {
            n_mu: Some(3),
            n_r: 2,
            rows: LutAxis::R,
            grid: LutGrid::Centers,
            clamp: 0.2,
        };
        // Texel centres (i + ½)/n: μ 1/6 (clamped to 0.2), 1/2, 5/6; r 1/4, 3/4, above the clamp.
        let (mu, r) = grid.evaluated();
        assert_eq!(mu, [0.2, 0.5, 5.0 / 6.0]);
        assert_eq!(r, [0.25, 0.75]);
        // rows=r: the file runs along μ first.
        assert_eq!(grid.cell(1), (1, 0));
        assert_eq!(grid.cell(3), (0, 1));
    }
}
