//! `ndfplot albedo --against FILE --layout KEY=VALUE,…`: an engine's albedo table compared with the
//! exact one on the engine's own grid — `max_abs`, `rms`, `max_rel` and the worst cell on standard
//! output, and with `-o DIR` the per-cell CSV and the error heat map.
//!
//! Owns the shape of the engine's grid (from the counts given, the CSV's lines, or a square), the
//! exact values at its cells and the text of the report; the file's layout and decoding are
//! [`crate::spec::lut`]'s, the integrals [`crate::model::albedo`]'s, the statistics
//! [`crate::model::metrics::table`]'s.

use std::path::Path;
use std::sync::Arc;

use super::Surface;
use crate::error::{Error, Result};
use crate::model::albedo::{self, Table};
use crate::model::curve::Curve;
use crate::model::curve::quantity::fresnel_table;
use crate::model::engine_table::{EngineGrid, compare};
use crate::model::math::quad::QuadError;
use crate::model::metrics::table::{Cell, RELATIVE_FLOOR, TableAudit};
use crate::output::plot;
use crate::output::write;
use crate::pipeline::figure::{Figure, Panel, Series};
use crate::pipeline::progress::Progress;
use crate::pipeline::provenance::Provenance;
use crate::problem::{Problem, Problems};
use crate::spec::datafile::{MAX_DATA_FILE_BYTES, read_regular};
use crate::spec::look::{
    Axes, Canvas, Dash, Face, Mark, PanelKind, Rgb, Scale, Style, Theme, XUnit,
};
use crate::spec::lut::{DecodeError, Layout, LutAxis, LutFresnel, LutValue, decode};

/// The files `-o DIR` receives (the heat map only for tables with a μ axis).
const OUTPUTS: [&str; 3] = ["audit.csv", "audit.svg", "audit.png"];

/// The heat map's size in CSS pixels.
const CANVAS: Canvas = Canvas {
    width_px: 640,
    height_px: 560,
    png_scale: 1.0,
    font_px: 15.0,
    print: None,
    transparent: false,
    face: Face::Sans,
};

/// An engine's table, read and decoded: its values in file order and the grid they sit on.
#[derive(Debug, Clone)]
pub struct Against {
    /// The file as given.
    pub path: String,
    /// What its numbers are.
    pub layout: Layout,
    /// The audited channel's values, row-major in the file's order.
    pub values: Vec<f64>,
    /// Points on the μ axis (`None` for the average table).
    pub n_mu: Option<usize>,
    /// Points on the r axis.
    pub n_r: usize,
}

/// An input problem about the file `path`.
fn file_problem(path: &str, message: String) -> Error {
    Error::input(Problems {
        source: path.into(),
        list: vec![Problem::new("", message)],
    })
}

/// Reads and decodes `path` by `layout` for `table`, and fixes its grid: the counts of `--size`
/// or `--mu-count`/`--r-count` when given, else the CSV's lines and columns, else a square (a
/// line of values for the average table). Errs naming the file (not regular, too large, not
/// decodable, a count that does not match) or `--layout` (a value that does not fit the table).
pub fn read(
    path: &Path,
    layout: Layout,
    table: Table,
    (size, mu_count, r_count): (Option<usize>, Option<usize>, Option<usize>),
) -> Result<Against> {
    let name = path.display().to_string();
    let values_fit = match table {
        Table::E | Table::Average => matches!(layout.value, LutValue::E | LutValue::OneMinusE),
        Table::Dfg => matches!(layout.value, LutValue::Dfg1 | LutValue::Dfg2),
        Table::SplitSum => false,
    };
    if !values_fit {
        return Err(Error::input(Problems {
            source: "--layout".into(),
            list: vec![Problem::new(
                "value",
                format!(
                    "not a value of the {} table (got value={}, expected {})",
                    table.name(),
                    layout.value.name(),
                    match table {
                        Table::Dfg => "dfg1 or dfg2",
                        Table::SplitSum => "no --against: split-sum tables are not audited",
                        _ => "e or 1-e",
                    }
                ),
            )],
        }));
    }
    let bytes = read_regular(path, MAX_DATA_FILE_BYTES)
        .map_err(|refused| file_problem(&name, refused.to_string()))?;
    let decoded = decode(&bytes, &layout, super::MAX_AXIS).map_err(|e| match e {
        DecodeError::File(message) => file_problem(&name, message),
        DecodeError::Layout(key, message) => Error::input(Problems {
            source: "--layout".into(),
            list: vec![Problem::new(key, format!("{message} in {name}"))],
        }),
    })?;
    let layout = decoded.layout.clone();
    if decoded.values.len() % layout.channels != 0 {
        return Err(file_problem(
            &name,
            format!(
                "not a whole number of cells (got {} numbers, expected a multiple of channels={})",
                decoded.values.len(),
                layout.channels
            ),
        ));
    }
    let values: Vec<f64> = decoded
        .values
        .iter()
        .skip(layout.channel)
        .step_by(layout.channels)
        .copied()
        .collect();
    if let Some(bad) = values.iter().position(|v| !v.is_finite()) {
        return Err(file_problem(
            &name,
            format!("cell {bad} is not finite (expected finite values)"),
        ));
    }
    let cells = values.len();
    let count_problem = |expected: String| {
        file_problem(
            &name,
            format!("the grid does not fit (got {cells} cells, expected {expected})"),
        )
    };
    let in_range = |n: usize| (2..=super::MAX_AXIS).contains(&n);
    let (n_mu, n_r) = if table == Table::Average {
        let n = r_count.or(size).unwrap_or(cells);
        if n != cells || !in_range(n) {
            return Err(count_problem(format!(
                "{n} values of E_avg(r), 2 to {}",
                super::MAX_AXIS
            )));
        }
        (None, n)
    } else {
        let given = match (size, mu_count, r_count) {
            (Some(n), _, _) => Some((n, n)),
            (None, Some(m), Some(r)) => Some((m, r)),
            (None, Some(m), None) => Some((m, cells / m.max(1))),
            (None, None, Some(r)) => Some((cells / r.max(1), r)),
            (None, None, None) => None,
        };
        let (rows, cols) = match given {
            Some((m, r)) if layout.rows == LutAxis::Mu => (m, r),
            Some((m, r)) => (r, m),
            None => decoded.shape.unwrap_or_else(|| {
                let n = (cells as f64).sqrt().round() as usize;
                (n, n)
            }),
        };
        if rows * cols != cells || !in_range(rows) || !in_range(cols) {
            return Err(count_problem(format!(
                "{rows} x {cols} (from {}), each axis 2 to {}",
                if given.is_some() {
                    "the counts given"
                } else if decoded.shape.is_some() {
                    "the file's lines"
                } else {
                    "a square; give --size or --mu-count and --r-count otherwise"
                },
                super::MAX_AXIS
            )));
        }
        match layout.rows {
            LutAxis::Mu => (Some(rows), cols),
            LutAxis::R => (Some(cols), rows),
        }
    };
    Ok(Against {
        path: name,
        layout,
        values,
        n_mu,
        n_r,
    })
}

/// The audit: the cells in file order with the exact values, and their statistics.
#[derive(Debug, Clone)]
pub struct Audit {
    /// The engine's table.
    pub against: Against,
    /// Every cell in file order.
    pub cells: Vec<Cell>,
    /// Their comparison.
    pub audit: TableAudit,
    /// What the exact table is, for the report.
    pub exact: String,
    /// The exact value's symbol (`E`, `1 - E`, `DFG1`, …).
    pub symbol: &'static str,
}

impl Against {
    /// The engine's grid: its counts and the layout's order, placement and clamp.
    pub fn grid(&self) -> EngineGrid {
        EngineGrid {
            n_mu: self.n_mu,
            n_r: self.n_r,
            rows: self.layout.rows,
            grid: self.layout.grid,
            clamp: self.layout.clamp,
        }
    }

    /// Compares the table with the exact one of `surface` (whose map is the layout's) under the
    /// layout's G2 and Fresnel (`fresnel`, the `--fresnel` curve, must be given exactly when the
    /// layout says `fresnel=given`); `progress` counts exact cells.
    pub fn audit(
        self,
        surface: &Surface,
        table: Table,
        fresnel: Option<&Curve>,
        progress: &Progress,
    ) -> Result<Audit> {
        let layout = &self.layout;
        let fresnel = match (layout.fresnel, fresnel) {
            (LutFresnel::None, None) => None,
            (LutFresnel::Given, Some(curve)) => Some(curve),
            (wanted, _) => {
                return Err(Error::input(Problems {
                    source: "--layout".into(),
                    list: vec![Problem::new(
                        "fresnel",
                        format!(
                            "does not match --fresnel (got fresnel={} {} --fresnel, expected fresnel=given with --fresnel, fresnel=none without)",
                            wanted.name(),
                            if fresnel.is_some() { "with" } else { "without" }
                        ),
                    )],
                }));
            }
        };
        if let Some(curve) = fresnel.filter(|curve| curve.emulated()) {
            return Err(super::engine_fresnel_refused(curve));
        }
        let grid = self.grid();
        surface.check_at(&grid.evaluated().1)?;
        let tick = |_: usize, _: usize| progress.advance(1);
        let lobe = |alpha: f64| {
            surface
                .lobe(alpha)
                .expect("every alpha of the grid was checked")
                .map(|ndf| albedo::surface_of(ndf, layout.g2))
        };
        let evaluate = fresnel.map(|curve| move |theta: f64| curve.eval(theta));
        let fresnel_table = fresnel.and_then(fresnel_table);
        let fresnel_fn: albedo::Fresnel = evaluate
            .as_ref()
            .map(|f| albedo::FresnelFactor::new(f, fresnel_table.as_ref()));
        let cells = compare(
            &self.values,
            &grid,
            (table, layout.value),
            surface.map,
            lobe,
            fresnel_fn,
            Some(&tick),
        )
        .map_err(|e: QuadError| {
            Error::Numerics(format!(
                "albedo --against: {e} (expected a convergent integral)"
            ))
        })?;
        let map = surface.map;
        let audit = TableAudit::of(&cells);
        let what = layout.value.symbol(table);
        let exact = format!(
            "{what} of {}, {} G2, {}, {}",
            surface.description(),
            layout.g2.name(),
            match fresnel {
                Some(curve) => format!("F = {}", curve.canonical_json()),
                None => "F = 1".into(),
            },
            map.name()
        );
        Ok(Audit {
            against: self,
            cells,
            audit,
            exact,
            symbol: what,
        })
    }
}

/// A number for the report: 4 significant digits in scientific notation.
fn sci(v: f64) -> String {
    format!("{v:.3e}")
}

impl Audit {
    /// The location of cell `k` for the report: `mu = …, r = … (engine …, exact …)`.
    fn at(&self, k: usize) -> String {
        let cell = &self.cells[k];
        let mu = if cell.mu.is_nan() {
            String::new()
        } else {
            format!("mu = {:.6}, ", cell.mu)
        };
        format!(
            "at {mu}r = {:.6} (engine {:.7}, exact {:.7})",
            cell.r, cell.engine, cell.exact
        )
    }

    /// The report on standard output: what was compared, then `cells`, `max_abs`, `rms` and
    /// `max_rel` lines, and a `note` when the worst cell is on the μ = 0 line compared with the
    /// limit μ → 0⁺ (no `clamp`): engines tabulate that line at a small μ of their own.
    pub fn report(&self) -> String {
        let against = &self.against;
        let layout = &against.layout;
        let grid = match against.n_mu {
            Some(n_mu) => format!(
                "{} x {} ({} mu x {} r)",
                if layout.rows == LutAxis::Mu {
                    n_mu
                } else {
                    against.n_r
                },
                if layout.rows == LutAxis::Mu {
                    against.n_r
                } else {
                    n_mu
                },
                n_mu,
                against.n_r
            ),
            None => format!("{} (r)", against.n_r),
        };
        let mut text = format!(
            "# against: {}\n# layout: rows={},cols={},grid={},map={},value={},encoding={},g2={},fresnel={},file={},clamp={},channels={},channel={}\n# exact: {}\ncells: {grid}\n",
            against.path,
            layout.rows.name(),
            layout.cols.name(),
            layout.grid.name(),
            match layout.map {
                albedo::RoughnessMap::Squared => "r2",
                albedo::RoughnessMap::Linear => "alpha",
                albedo::RoughnessMap::Root => "sqrt",
            },
            layout.value.name(),
            layout.encoding.name(),
            layout.g2.name(),
            layout.fresnel.name(),
            layout.file.name(),
            layout.clamp,
            layout.channels,
            layout.channel,
            self.exact,
        );
        let audit = &self.audit;
        text.push_str(&format!(
            "max_abs: {} {}\nrms: {}\n",
            sci(audit.max_abs),
            self.at(audit.worst),
            sci(audit.rms)
        ));
        text.push_str(&match (audit.max_rel, audit.worst_rel) {
            (Some(rel), Some(k)) => format!(
                "max_rel: {} where |exact| >= {RELATIVE_FLOOR:e}, {}\n",
                sci(rel),
                self.at(k)
            ),
            _ => format!("max_rel: none (no cell with |exact| >= {RELATIVE_FLOOR:e})\n"),
        });
        if layout.clamp == 0.0 && self.cells[audit.worst].mu == 0.0 {
            text.push_str(
                "note: the worst cell is at mu = 0, compared with the limit mu -> 0+; an engine that tabulated that line at a small mu says where with clamp= (Cycles 1e-4, Adobe's openpbr-bsdf 1e-3)\n",
            );
        }
        text
    }

    /// `audit.csv` (mu, r, alpha, engine, exact, error per cell in file order) and, for a table
    /// with a μ axis, the heat map of engine − exact as `audit.svg` and `audit.png`, written into
    /// `dir` (checked writable before anything is computed: [`check_outputs`]).
    pub fn write(&self, dir: &Path) -> Result<Vec<std::path::PathBuf>> {
        let map = self.against.layout.map;
        let mut csv = String::from("mu,r,alpha,engine,exact,error\n");
        for cell in &self.cells {
            let mu = if cell.mu.is_nan() {
                String::new()
            } else {
                cell.mu.to_string()
            };
            csv.push_str(&format!(
                "{mu},{},{},{},{},{}\n",
                cell.r,
                map.alpha(cell.r),
                cell.engine,
                cell.exact,
                cell.error()
            ));
        }
        let mut files = vec![("audit.csv", csv.into_bytes())];
        if let Some(figure) = self.heat_map() {
            let drawing_failed =
                |e| Error::Numerics(format!("albedo --against: drawing failed: {e}"));
            let svg = plot::svg(&figure).map_err(drawing_failed)?;
            let png = plot::png(&figure, &svg).map_err(drawing_failed)?;
            files.push(("audit.svg", svg));
            files.push(("audit.png", png));
        }
        write::write_files("-o", dir, &files)
    }

    /// The heat map of engine − exact over (μ, r), or `None` for the average table.
    pub fn heat_map(&self) -> Option<Figure> {
        let n_mu = self.against.n_mu?;
        let n_r = self.against.n_r;
        let mut grid = vec![
            Cell {
                mu: 0.0,
                r: 0.0,
                engine: 0.0,
                exact: 0.0
            };
            n_mu * n_r
        ];
        let (mu, r) = self.against.grid().coordinates();
        for cell in &self.cells {
            let i = mu.iter().position(|&m| m == cell.mu).expect("a grid μ");
            let j = r.iter().position(|&x| x == cell.r).expect("a grid r");
            grid[i * n_r + j] = *cell;
        }
        let points = grid.iter().map(|c| (c.mu, c.r)).collect();
        // Errors far below 1 are drawn in units of 10^k, so the colour bar's ticks stay short.
        let exponent = if self.audit.max_abs > 0.0 {
            (self.audit.max_abs.log10().floor() as i32).min(0)
        } else {
            0
        };
        let unit = 10f64.powi(exponent);
        let z = grid.iter().map(|c| c.error() / unit).collect();
        let z_label = if exponent < -1 {
            format!("engine − exact (10^{{{exponent}}})")
        } else {
            "engine − exact".into()
        };
        let file = std::path::Path::new(&self.against.path)
            .file_name()
            .map_or_else(
                || self.against.path.clone(),
                |f| f.to_string_lossy().into_owned(),
            );
        let escaped: String = file
            .chars()
            .flat_map(|c| match c {
                '_' | '^' | '{' | '}' | '\\' => vec!['\\', c],
                c => vec![c],
            })
            .collect();
        Some(Figure {
            id: "audit".into(),
            title: format!("{escaped} − exact {}", self.symbol),
            rows: 1,
            cols: 1,
            canvas: CANVAS,
            theme: Theme::Notebook,
            provenance: Provenance::without_spec(),
            page: None,
            panels: vec![Panel {
                axes: Axes {
                    kind: PanelKind::Heatmap {
                        z_label,
                        z_range: None,
                    },
                    ..Axes::cartesian("μ = cos θ_o", "roughness r", XUnit::Plain, Scale::Linear)
                },
                series: vec![Series {
                    label: String::new(),
                    curve: String::new(),
                    style: Style {
                        colour: Rgb::from_hex(0x000000),
                        width: 1.0,
                        dash: Dash::Solid,
                        mark: Mark::Line,
                        sweep: None,
                    },
                    points: Arc::new(points),
                    z: Some(Arc::new(z)),
                    grid: Some((n_mu, n_r)),
                }],
            }],
        })
    }
}

/// Checks before anything is read or computed that `dir` can receive the audit's files.
pub fn check_outputs(dir: &Path) -> Result<()> {
    write::refuse_dash_folder("-o", dir, "an audit writes three files")?;
    write::check_writable("-o", dir, &OUTPUTS)
}
