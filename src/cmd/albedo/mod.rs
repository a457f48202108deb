//! `ndfplot albedo`: the tables renderers precompute from an NDF — the directional albedo E(μ, r)
//! with Turquin's factor, the average E_avg(r) with Kulla–Conty's normalisation and Fresnel
//! colouring, and the Belcour–Bati–Barla split-sum tables E_0 … E_3 — with metadata naming what
//! they are, as CSV or JSON, several in one run.
//!
//! Owns the reading of the command's arguments into a [`Request`] (the tables, the family, its
//! fixed parameters, the roughness map, the grid, the Fresnel factor) and each table's rows and
//! metadata ([`Output`]); their text in each shape and format is [`print`]'s, the integrals and the
//! grids are [`crate::model::albedo`]'s.

pub mod audit;
pub mod print;

use serde::ser::{Serialize, SerializeMap, Serializer};

use crate::error::{Error, Result};
use crate::model::albedo::{
    self, NoLobe, RoughnessMap, Table, average_albedo_table, dfg_tables, kulla_conty_fresnel,
    kulla_conty_lobe, split_sum_tables, turquin_factor, unit_grid,
};
use crate::model::albedo::{AVERAGE_E_TOL, AVERAGE_TOL, SMOOTHED_CELLS};
use crate::model::curve::quantity::fresnel_table;
use crate::model::curve::{Curve, Kind};
use crate::model::masking::G2Model;
use crate::model::math::quad::QuadError;
use crate::model::math::tolerance::{ALBEDO_QUAD_REL_TOL, ALBEDO_TOL};
use crate::model::ndf::{Family, Ndf, ZeroLimit};
use crate::output::report::{Cell, Report};
use crate::pipeline::progress::Progress;
use crate::problem::{Problem, Problems};

/// Most points on one axis of a table.
pub const MAX_AXIS: usize = 1024;
/// Most cells (μ × r) of a table: 512 × 512.
pub const MAX_CELLS: usize = 1 << 18;
/// Points per axis when neither `--size` nor a count is given: Cycles' 32.
pub const DEFAULT_AXIS: usize = 32;

/// A family whose first parameter is the mapped roughness and whose others are fixed.
#[derive(Debug, Clone, PartialEq)]
pub struct Surface {
    family: Family,
    map: RoughnessMap,
    /// Every parameter's value in the family's order; the first is replaced by map(r).
    params: Vec<f64>,
}

impl Surface {
    /// The surface of `family` with `fixed` (`--fix`) giving every parameter but the first, which
    /// `map` fills from r. Errs naming `--fix` for an unknown, repeated, missing or mapped key.
    pub fn new(family: Family, fixed: &[(String, f64)], map: RoughnessMap) -> Result<Surface> {
        crate::model::fit::check_fixed_keys(family, fixed).map_err(super::fit::fit_error)?;
        let names = family.param_names();
        let (mapped, others) = (names[0], &names[1..]);
        let fix_problem = |at: &str, message: String| {
            Error::input(Problems {
                source: "--fix".into(),
                list: vec![Problem::new(at, message)],
            })
        };
        if let Some((_, value)) = fixed.iter().find(|(key, _)| key == mapped) {
            return Err(fix_problem(
                mapped,
                if others.is_empty() {
                    format!(
                        "the roughness r maps to it (got {mapped}={value:?}, expected no --fix: it is {}'s only parameter)",
                        family.name()
                    )
                } else {
                    format!(
                        "the roughness r maps to it (got {mapped}={value:?}, expected --fix only for {}'s other parameters: {})",
                        family.name(),
                        others.join(", ")
                    )
                },
            ));
        }
        let mut params = vec![f64::NAN];
        for &name in others {
            match fixed.iter().find(|(key, _)| key == name) {
                Some(&(_, value)) => params.push(value),
                None => {
                    return Err(fix_problem(
                        name,
                        format!(
                            "missing (got no --fix {name}=…, expected a value for every parameter of {} but {mapped}, which r maps to)",
                            family.name()
                        ),
                    ));
                }
            }
        }
        Ok(Surface {
            family,
            map,
            params,
        })
    }

    /// The lobe at roughness parameter α (the mapped first parameter) — `None` for the mirror —
    /// or why there is none ([`albedo::lobe`]: at α = 0 the family's own limit).
    pub fn lobe(&self, alpha: f64) -> std::result::Result<Option<Ndf>, NoLobe> {
        let mut params = self.params.clone();
        params[0] = alpha;
        albedo::lobe(self.family, &params)
    }

    /// What the r = 0 column is, for the metadata: the family's lobe at α = 0 when that is in its
    /// domain, else its limit there.
    fn zero_column(&self) -> String {
        let mapped = &self.family.params()[0];
        if mapped.contains(self.map.alpha(0.0)) {
            format!("r = 0 is {} = 0, inside the family's domain", mapped.name)
        } else if self.family.zero_limit(&self.params[1..]) == ZeroLimit::Uniform {
            "r = 0 is the limit alpha -> 0+, the uniform lobe D = 1/pi".to_string()
        } else {
            "r = 0 is the mirror limit alpha -> 0+".to_string()
        }
    }

    /// Checks that every r of an `n_r`-point axis gives a lobe (at r = 0 the family's limit): an
    /// error names `--fix` for a fixed value out of its domain (or one for which the family has no
    /// limit at r = 0 that ndfplot evaluates), `--map` for a mapped one, with r.
    pub fn check(&self, n_r: usize) -> Result<()> {
        self.check_at(&unit_grid(n_r))
    }

    /// [`Surface::check`] at the roughness coordinates `roughness`.
    pub fn check_at(&self, roughness: &[f64]) -> Result<()> {
        let mapped = self.family.params()[0].name;
        let others = &self.family.param_names()[1..];
        for &r in roughness {
            let e = match self.lobe(self.map.alpha(r)) {
                Ok(_) => continue,
                Err(NoLobe::Limit(what)) => {
                    let fixed: Vec<String> = others
                        .iter()
                        .zip(&self.params[1..])
                        .map(|(name, value)| format!("{name}={value:?}"))
                        .collect();
                    return Err(Error::input(Problems {
                        source: "--fix".into(),
                        list: vec![Problem::new(
                            others.first().copied().unwrap_or(mapped),
                            format!(
                                "no limit at r = 0, where {mapped} = 0 (got {}: {what}; expected values whose lobe tends to the mirror or the uniform lobe as {mapped} -> 0, as every table has an r = 0 column)",
                                fixed.join(", ")
                            ),
                        )],
                    }));
                }
                Err(NoLobe::Domain(e)) => e,
            };
            let (source, message) = if e.param == mapped {
                (
                    "--map",
                    format!(
                        "out of domain at r = {r:?} (got {} = {:?} from {}, expected {})",
                        e.param,
                        e.value,
                        self.map.name(),
                        e.expected
                    ),
                )
            } else {
                (
                    "--fix",
                    format!("out of domain (got {:?}, expected {})", e.value, e.expected),
                )
            };
            return Err(Error::input(Problems {
                source: source.into(),
                list: vec![Problem::new(e.param, message)],
            }));
        }
        Ok(())
    }

    /// The description of the NDF in canonical curve JSON's order, the mapped parameter written as
    /// its map (`{"ndf":"gtr","alpha_gtr":"r^2","gamma_gtr":1.5}`).
    pub fn description(&self) -> String {
        crate::spec::json::to_string(self)
    }
}

impl Serialize for Surface {
    fn serialize<S: Serializer>(&self, serializer: S) -> std::result::Result<S::Ok, S::Error> {
        let names = self.family.param_names();
        let mut map = serializer.serialize_map(Some(names.len() + 1))?;
        map.serialize_entry("ndf", self.family.name())?;
        map.serialize_entry(names[0], self.map.expression())?;
        for (name, value) in names.iter().zip(&self.params).skip(1) {
            map.serialize_entry(name, value)?;
        }
        map.end()
    }
}

/// The tables of `--table`: names separated by commas, matched case-insensitively, each at most
/// once, in the order given. Errs naming `--table` for an empty, unknown or repeated name.
pub fn parse_tables(text: &str) -> Result<Vec<Table>> {
    let names = || Table::NAMES.map(|(name, _)| name);
    let mut tables: Vec<Table> = Vec::new();
    for item in text.split(',') {
        let item = item.trim();
        let Some(table) = Table::from_name(item) else {
            return Err(Error::Usage(format!(
                "--table: unknown table (got \"{}\", expected a comma-separated list of {}){}",
                crate::problem::excerpt(item),
                names().join(", "),
                crate::problem::suggestion(item, names())
            )));
        };
        if tables.contains(&table) {
            return Err(Error::Usage(format!(
                "--table: {} given twice (got \"{}\", expected each table at most once)",
                table.name(),
                crate::problem::excerpt(text)
            )));
        }
        tables.push(table);
    }
    Ok(tables)
}

/// Whether `table` has a μ axis (every table but [`Table::Average`]).
pub fn has_mu_axis(table: Table) -> bool {
    table != Table::Average
}

/// The grid `(n_μ, n_r)` of `--size` or `--mu-count`/`--r-count` (each [`DEFAULT_AXIS`] unless
/// given) shared by `tables`; n_μ is `None` when every table is [`Table::Average`], which has no μ
/// axis (`--mu-count` refused). Each count must be 2 … [`MAX_AXIS`] and the cells at most
/// [`MAX_CELLS`].
pub fn grid(
    tables: &[Table],
    size: Option<usize>,
    mu_count: Option<usize>,
    r_count: Option<usize>,
) -> Result<(Option<usize>, usize)> {
    let axis = |flag: &str, n: Option<usize>| match n {
        None => Ok(DEFAULT_AXIS),
        Some(n) if (2..=MAX_AXIS).contains(&n) => Ok(n),
        Some(n) => Err(Error::Usage(format!(
            "{flag}: points per axis out of range (got {n}, expected 2 to {MAX_AXIS})"
        ))),
    };
    let (mu_flag, r_flag) = match size {
        Some(_) => ("--size", "--size"),
        None => ("--mu-count", "--r-count"),
    };
    let n_r = axis(r_flag, size.or(r_count))?;
    if !tables.iter().copied().any(has_mu_axis) {
        return match mu_count {
            Some(n) => Err(Error::Usage(format!(
                "--mu-count: the average table has no mu axis (got {n}, expected no --mu-count with --table average)"
            ))),
            None => Ok((None, n_r)),
        };
    }
    let n_mu = axis(mu_flag, size.or(mu_count))?;
    if n_mu * n_r > MAX_CELLS {
        return Err(Error::Usage(format!(
            "{}: too many cells (got {n_mu} x {n_r} = {}, expected at most {MAX_CELLS})",
            if size.is_some() {
                "--size"
            } else {
                "--mu-count, --r-count"
            },
            n_mu * n_r
        )));
    }
    Ok((Some(n_mu), n_r))
}

/// The Fresnel factor of `--fresnel`: its one curve, which must be a Fresnel curve.
pub fn fresnel_factor(curves: Vec<Curve>) -> Result<Curve> {
    let problem = |message: String| {
        Error::input(Problems {
            source: "--fresnel".into(),
            list: vec![Problem::new("", message)],
        })
    };
    let count = curves.len();
    let Ok([curve]) = <[Curve; 1]>::try_from(curves) else {
        return Err(problem(format!(
            "one Fresnel curve (got {count} curves, expected one)"
        )));
    };
    if curve.kind() != Kind::Fresnel {
        return Err(problem(format!(
            "the Fresnel factor is a Fresnel curve (got {}, expected {{\"fresnel\": <model>, …}})",
            curve.kind().describe()
        )));
    }
    Ok(curve)
}

/// Everything `ndfplot albedo` computes from, validated.
#[derive(Debug, Clone)]
pub struct Request {
    /// Which tables, in output order.
    pub tables: Vec<Table>,
    /// The NDF family with its fixed parameters and roughness map.
    pub surface: Surface,
    /// The G2 model.
    pub g2: G2Model,
    /// Points on the μ axis (`None` when every table is [`Table::Average`]).
    pub n_mu: Option<usize>,
    /// Points on the r axis.
    pub n_r: usize,
    /// The Fresnel factor F(θd) (`None`: F = 1); never with [`Table::SplitSum`] or [`Table::Dfg`].
    pub fresnel: Option<Curve>,
}

impl Request {
    /// The request, checked: no Fresnel factor with the split-sum tables, no engine's Fresnel
    /// where it would be integrated (an engine's own F_avg is taken, not integrated), every NDF of
    /// the grid in its domain.
    pub fn new(
        tables: Vec<Table>,
        surface: Surface,
        g2: G2Model,
        (n_mu, n_r): (Option<usize>, usize),
        fresnel: Option<Curve>,
    ) -> Result<Request> {
        if let Some(&table) = tables
            .iter()
            .find(|t| matches!(t, Table::SplitSum | Table::Dfg))
            && let Some(curve) = &fresnel
        {
            return Err(Error::input(Problems {
                source: "--fresnel".into(),
                list: vec![Problem::new(
                    "",
                    format!(
                        "the {} tables are Fresnel-independent, their weights are fixed (got {}, expected no --fresnel with --table {})",
                        table.name(),
                        crate::problem::excerpt(&curve.canonical_json()),
                        table.name()
                    ),
                )],
            }));
        }
        if let Some(curve) = &fresnel
            && curve.emulated()
        {
            let integrated = tables.contains(&Table::E)
                || (tables.contains(&Table::Average) && engine_fresnel_average(curve).is_none());
            if integrated {
                return Err(engine_fresnel_refused(curve));
            }
        }
        surface.check(n_r)?;
        Ok(Request {
            tables,
            surface,
            g2,
            n_mu,
            n_r,
            fresnel,
        })
    }

    /// The μ count of `table`: `None` for [`Table::Average`].
    fn mu_count(&self, table: Table) -> Option<usize> {
        self.n_mu.filter(|_| has_mu_axis(table))
    }

    /// The number of progress steps: the cells of every table, r values for [`Table::Average`].
    pub fn steps(&self) -> usize {
        self.tables
            .iter()
            .map(|&t| self.mu_count(t).unwrap_or(1) * self.n_r)
            .sum()
    }

    /// Computes every table with its metadata, in the order asked: the tables side by side and
    /// their cells in parallel, so one table's last slow cells overlap another's (`progress`
    /// counts the cells of all).
    pub fn compute(&self, progress: &Progress) -> Result<Vec<Output>> {
        use rayon::prelude::*;
        self.tables
            .par_iter()
            .map(|&table| self.compute_table(table, progress))
            .collect()
    }

    /// Computes `table` with its metadata.
    fn compute_table(&self, table: Table, progress: &Progress) -> Result<Output> {
        let tick = |_: usize, _: usize| progress.advance(1);
        let surface = |alpha: f64| {
            self.surface
                .lobe(alpha)
                .expect("every alpha of the grid was checked by Request::new")
                .map(|ndf| albedo::surface_of(ndf, self.g2))
        };
        let evaluate = self
            .fresnel
            .as_ref()
            .map(|curve| move |theta: f64| curve.eval(theta));
        let fresnel_table = self.fresnel.as_ref().and_then(fresnel_table);
        let fresnel: albedo::Fresnel = evaluate
            .as_ref()
            .map(|f| albedo::FresnelFactor::new(f, fresnel_table.as_ref()));
        let map = self.surface.map;
        let failed = |e: QuadError| {
            Error::Numerics(format!(
                "albedo: --table {}: {e} (expected a convergent integral)",
                table.name()
            ))
        };
        let report = match (table, self.mu_count(table)) {
            (Table::E, Some(n_mu)) => {
                let table =
                    albedo::albedo_table(n_mu, self.n_r, map, surface, fresnel, Some(&tick))
                        .map_err(failed)?;
                let columns: &[&str] = match fresnel {
                    Some(_) => &["mu", "r", "alpha", "E_F"],
                    None => &["mu", "r", "alpha", "E", "turquin_f0_1"],
                };
                let mut report = Report::new(columns.iter().copied());
                for (i, &mu) in table.mu.iter().enumerate() {
                    for (j, &r) in table.roughness.iter().enumerate() {
                        let e = table.get(i, j);
                        let mut row = numbers(&[mu, r, map.alpha(r), e]);
                        if fresnel.is_none() {
                            row.push(finite(turquin_factor(1.0, e)));
                        }
                        report.push(row);
                    }
                }
                report
            }
            (Table::Dfg, Some(n_mu)) => {
                let tables = dfg_tables(
                    unit_grid(n_mu),
                    unit_grid(self.n_r),
                    map,
                    surface,
                    Some(&tick),
                )
                .map_err(failed)?;
                cell_report(&["DFG1", "DFG2"], &tables)
            }
            (Table::SplitSum, Some(n_mu)) => {
                let tables =
                    split_sum_tables(n_mu, self.n_r, map, surface, Some(&tick)).map_err(failed)?;
                cell_report(&["E_0", "E_1", "E_2", "E_3"], &tables)
            }
            _ => {
                let e_avg = average_albedo_table(self.n_r, map, surface, None, Some(&tick))
                    .map_err(failed)?;
                let f_avg = match (&self.fresnel, fresnel) {
                    (Some(curve), Some(f)) => Some(match engine_fresnel_average(curve) {
                        Some(f_avg) => f_avg,
                        None => f.average().map_err(failed)?,
                    }),
                    _ => None,
                };
                let columns: &[&str] = match f_avg {
                    Some(_) => &["r", "alpha", "E_avg", "kulla_conty_norm", "F_avg", "F_ms"],
                    None => &["r", "alpha", "E_avg", "kulla_conty_norm"],
                };
                let mut report = Report::new(columns.iter().copied());
                for (r, e_avg) in unit_grid(self.n_r).into_iter().zip(e_avg) {
                    let mut row = numbers(&[r, map.alpha(r), e_avg]);
                    // f_ms's normalisation 1/(π(1 − E_avg)) is the lobe at E(μo) = E(μi) = 0;
                    // undefined for the mirror (E_avg = 1), which scatters once.
                    row.push(if e_avg < 1.0 {
                        finite(kulla_conty_lobe(0.0, 0.0, e_avg))
                    } else {
                        Cell::Missing
                    });
                    if let Some(f_avg) = f_avg {
                        row.extend(numbers(&[f_avg, kulla_conty_fresnel(f_avg, e_avg)]));
                    }
                    report.push(row);
                }
                report
            }
        };
        let roughness = unit_grid(self.n_r);
        Ok(Output {
            table,
            metadata: self.metadata(table),
            mu: self.mu_count(table).map(unit_grid),
            roughness,
            report,
        })
    }

    /// The metadata of `table`, in output order.
    fn metadata(&self, table: Table) -> Vec<(&'static str, Meta)> {
        let fresnel = match &self.fresnel {
            Some(curve) => Meta::Json(curve.canonical_json()),
            None => Meta::Absent("none (F = 1)"),
        };
        let what = match (table, &self.fresnel) {
            (Table::E, None) => {
                "directional albedo E(mu) of f = F D G2 / (4 cos(theta_o) cos(theta_i)), one row per (mu, r), and Turquin's compensation factor 1/E (F0 = 1)"
            }
            (Table::E, Some(_)) => {
                "directional albedo E_F(mu) of f = F D G2 / (4 cos(theta_o) cos(theta_i)) with F(theta_d), one row per (mu, r)"
            }
            (Table::Average, None) => {
                "average albedo E_avg = 2 int_0^1 E(mu) mu dmu (F = 1), one row per r, and Kulla-Conty's f_ms normalisation 1/(pi (1 - E_avg)) (empty where E_avg = 1)"
            }
            (Table::Average, Some(_)) => {
                "average albedo E_avg = 2 int_0^1 E(mu) mu dmu (F = 1), one row per r, Kulla-Conty's 1/(pi (1 - E_avg)) (empty where E_avg = 1), F_avg = 2 int_0^1 F mu dmu and F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg))"
            }
            (Table::Dfg, _) => {
                "split-sum pair of Schlick's Fresnel: DFG1 = E_F with F = 1 - Fc and DFG2 = E_F with F = Fc, Fc = (1 - cos(theta_d))^5, one row per (mu, r); F0 DFG1 + F90 DFG2 is the albedo with F = F0 + (F90 - F0) Fc, and DFG1 + DFG2 = E"
            }
            (Table::SplitSum, _) => {
                "Belcour-Bati-Barla split-sum tables E_k(mu): the albedo with F = b_k(theta_d), k = 0..3 (E_0 = E), one row per (mu, r); E_F = sum c_k E_k for F = sum c_k b_k"
            }
        };
        let grid = match self.mu_count(table) {
            Some(_) => {
                "mu = cos(theta_o) = i/(mu_count - 1), r = j/(r_count - 1), alpha = map(r); rows by mu, then r"
            }
            None => "r = j/(r_count - 1), alpha = map(r)",
        };
        let zero = self.surface.zero_column();
        let mirror = self.surface.lobe(self.surface.map.alpha(0.0)) == Ok(None);
        let limits = match (table, mirror) {
            (Table::Average, true) => format!("{zero} (E_avg = 1)"),
            (Table::Average, false) => zero,
            (Table::SplitSum, true) => {
                format!("mu = 0 is the limit mu -> 0+; {zero}, E_k = b_k(theta_o)")
            }
            (Table::Dfg, true) => format!(
                "mu = 0 is the limit mu -> 0+; {zero}, DFG1 = 1 - Fc(theta_o), DFG2 = Fc(theta_o)"
            ),
            (_, true) => format!("mu = 0 is the limit mu -> 0+; {zero}, E = F(theta_o)"),
            (_, false) => format!("mu = 0 is the limit mu -> 0+; {zero}"),
        };
        let accuracy = match table {
            Table::SplitSum => format!(
                "within {ALBEDO_TOL:e} of the exact integrals (the basis, linear between 1000 nodes in cos(theta_d), through a smooth surrogate with its integral over every cell; at mu = 1 split at the nodes; lobes narrower than {SMOOTHED_CELLS} cells in cos(theta_d): plus the albedo of the interpolant's residual against the surrogate, cell by cell)"
            ),
            Table::Average => format!(
                "within {AVERAGE_TOL:e} of the exact integral (fixed Gauss-Legendre rules in mu on panels graded from the lobe width, each E to {AVERAGE_E_TOL:e}; F_avg adaptive to {ALBEDO_QUAD_REL_TOL:e})"
            ),
            _ => format!(
                "within {ALBEDO_TOL:e} of the exact integrals for smooth F (fixed Gauss-Legendre rules graded at the horizon, nested adaptive Gauss-Kronrod to {ALBEDO_QUAD_REL_TOL:e} per level where two levels disagree)"
            ),
        };
        let mut metadata = vec![
            ("table", Meta::Text(table.name().into())),
            ("quantity", Meta::Text(what.into())),
            ("ndf", Meta::Json(self.surface.description())),
            ("g2", Meta::Text(self.g2.name().into())),
            ("map", Meta::Text(self.surface.map.name().into())),
            ("fresnel", fresnel),
        ];
        if let Some(n_mu) = self.mu_count(table) {
            metadata.push(("mu_count", Meta::Count(n_mu)));
        }
        metadata.extend([
            ("r_count", Meta::Count(self.n_r)),
            ("grid", Meta::Text(grid.into())),
            ("limits", Meta::Text(limits)),
            ("accuracy", Meta::Text(accuracy)),
        ]);
        metadata
    }
}

/// Why an engine's Fresnel curve cannot be a factor inside the albedo integrals: its float32
/// rounding is far above their tolerance.
fn engine_fresnel_refused(curve: &Curve) -> Error {
    Error::input(Problems {
        source: "--fresnel".into(),
        list: vec![Problem::new(
            "",
            format!(
                "an engine's Fresnel carries its float32 rounding, which the albedo integrals (held to {ALBEDO_QUAD_REL_TOL:e}) cannot integrate (got {}, expected a curve without \"engine\"; --table average takes an engine's own F_avg where it has one, as cycles has)",
                crate::problem::excerpt(&curve.canonical_json())
            ),
        )],
    })
}

/// The F_avg an engine's Fresnel curve uses in place of the integral, when its engine has a
/// formula of its own (Cycles' fit for a dielectric, [`crate::model::renderer`]).
fn engine_fresnel_average(curve: &Curve) -> Option<f64> {
    match curve {
        Curve::Emulated(emulation) => emulation.fresnel_average(),
        _ => None,
    }
}

/// One row per (μ, r) cell of `tables` (on one grid): mu, r, alpha, then each table's value under
/// its name in `names`.
fn cell_report(names: &[&str], tables: &[albedo::AlbedoTable]) -> Report {
    let first = &tables[0];
    let mut report = Report::new(["mu", "r", "alpha"].iter().chain(names).copied());
    for (i, &mu) in first.mu.iter().enumerate() {
        for (j, &r) in first.roughness.iter().enumerate() {
            let mut row = numbers(&[mu, r, first.map.alpha(r)]);
            row.extend(tables.iter().map(|t| Cell::Number(t.get(i, j))));
            report.push(row);
        }
    }
    report
}

/// Number cells.
fn numbers(values: &[f64]) -> Vec<Cell> {
    values.iter().map(|&v| Cell::Number(v)).collect()
}

/// A number cell, or an empty one where the value is not finite (never printed, docs/contracts.md).
fn finite(value: f64) -> Cell {
    if value.is_finite() {
        Cell::Number(value)
    } else {
        Cell::Missing
    }
}

/// A metadata value: text, JSON (a curve), a count, or nothing.
#[derive(Debug, Clone, PartialEq)]
pub enum Meta {
    /// No value: JSON `null`, and this text in CSV.
    Absent(&'static str),
    /// Text (a JSON string).
    Text(String),
    /// JSON text, embedded as JSON.
    Json(String),
    /// A whole number.
    Count(usize),
}

impl Serialize for Meta {
    fn serialize<S: Serializer>(&self, serializer: S) -> std::result::Result<S::Ok, S::Error> {
        match self {
            Meta::Absent(_) => serializer.serialize_none(),
            Meta::Text(text) => serializer.serialize_str(text),
            Meta::Json(text) => Cell::Json(text.clone()).serialize(serializer),
            Meta::Count(n) => serializer.serialize_u64(*n as u64),
        }
    }
}

impl std::fmt::Display for Meta {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Meta::Absent(text) => f.write_str(text),
            Meta::Text(text) | Meta::Json(text) => f.write_str(text),
            Meta::Count(n) => write!(f, "{n}"),
        }
    }
}

/// A computed table with its metadata and axes.
#[derive(Debug, Clone, PartialEq)]
pub struct Output {
    /// Which table.
    pub table: Table,
    /// (key, value) pairs naming what the table is, in order.
    pub metadata: Vec<(&'static str, Meta)>,
    /// The μ axis (`None` for the average table).
    pub mu: Option<Vec<f64>>,
    /// The r axis.
    pub roughness: Vec<f64>,
    /// The columns and rows, one row per (μ, r) cell (rows by μ, then r) or per r: the axes'
    /// columns (`mu`, `r`, `alpha`) first, then the values.
    pub report: Report,
}

impl Output {
    /// The table's name, as `--table` takes it.
    pub fn name(&self) -> &'static str {
        self.table.name()
    }

    /// The number of leading columns that are axes (`mu`, `r`, `alpha` or `r`, `alpha`).
    pub fn axis_columns(&self) -> usize {
        if self.mu.is_some() { 3 } else { 2 }
    }

    /// The table's size for people: `32 × 32` (μ × r) or `32` (r).
    pub fn size(&self) -> String {
        match &self.mu {
            Some(mu) => format!("{} × {}", mu.len(), self.roughness.len()),
            None => self.roughness.len().to_string(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fixed(pairs: &[(&str, f64)]) -> Vec<(String, f64)> {
        pairs.iter().map(|&(k, v)| (k.to_string(), v)).collect()
    }

    #[test]
    fn the_ndf_is_described_with_its_map_in_canonical_order() {
        let gtr = Surface::new(
            Family::Gtr,
            &fixed(&[("gamma_gtr", 1.5)]),
            RoughnessMap::Squared,
        )
        .unwrap();
        assert_eq!(
            gtr.description(),
            r#"{"ndf":"gtr","alpha_gtr":"r^2","gamma_gtr":1.5}"#
        );
        let ggx = Surface::new(Family::TrowbridgeReitz, &[], RoughnessMap::Linear).unwrap();
        assert_eq!(
            ggx.description(),
            r#"{"ndf":"trowbridge_reitz","alpha_tr":"r"}"#
        );
    }

    #[test]
    fn grids_are_capped_and_the_average_has_no_mu_axis() {
        let (e, average) = (&[Table::E][..], &[Table::Average][..]);
        assert_eq!(grid(e, None, None, None).unwrap(), (Some(32), 32));
        assert_eq!(grid(e, Some(4), None, None).unwrap(), (Some(4), 4));
        assert_eq!(
            grid(&[Table::SplitSum], None, Some(3), Some(5)).unwrap(),
            (Some(3), 5)
        );
        assert_eq!(grid(average, Some(8), None, None).unwrap(), (None, 8));
        assert_eq!(
            grid(&[Table::Average, Table::E], None, Some(3), Some(5)).unwrap(),
            (Some(3), 5)
        );
        assert!(grid(average, None, Some(8), None).is_err());
        assert!(grid(e, Some(1), None, None).is_err());
        assert!(grid(e, Some(MAX_AXIS + 1), None, None).is_err());
        assert!(grid(e, None, Some(MAX_AXIS), Some(MAX_AXIS)).is_err());
        assert!(grid(average, None, None, Some(MAX_AXIS)).is_ok());
    }

    #[test]
    fn table_lists_are_case_insensitive_and_refuse_repeats() {
        assert_eq!(
            parse_tables("E, Average,dfg").unwrap(),
            [Table::E, Table::Average, Table::Dfg]
        );
        assert!(parse_tables("e,average,E").is_err());
        assert!(parse_tables("e,").is_err());
        assert!(parse_tables("avg").is_err());
    }

    #[test]
    fn table_names_round_trip() {
        for (name, table) in Table::NAMES {
            assert_eq!(Table::from_name(name), Some(table));
            assert_eq!(table.name(), name);
        }
        assert_eq!(RoughnessMap::from_key("r2"), Some(RoughnessMap::Squared));
        assert_eq!(RoughnessMap::from_key("r"), Some(RoughnessMap::Linear));
    }
}
