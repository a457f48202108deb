//! Series that are not functions of θ: the Belcour–Bati–Barla singular-value spectrum,
//! coefficient paths and manifolds over Gulbrandsen's (r, g), the directional albedo of an NDF
//! family over (μ, r) on Cycles' grid, an engine's published table against the exact one,
//! literal tables, and differences with a sampled side.
//!
//! A dataset is validated data (like a curve) and evaluates to points; it never draws or writes.

use crate::model::albedo::{RoughnessMap, albedo_table, lobe, surface_of};
use crate::model::curve::{Curve, DiffOp};
use crate::model::engine_table::PublishedTable;
use crate::model::fresnel::{basis, gulbrandsen};
use crate::model::masking::G2Model;
use crate::model::metrics::ThetaRange;
use crate::model::metrics::sampled::{Operand, Samples, nodes};
use crate::model::metrics::table::Cell;
use crate::model::names::named;
use crate::model::ndf::Family;
use serde::ser::{Serialize, SerializeMap, Serializer};

named! {
    /// Which number of the spectrum a spectrum series shows (docs/maths.md, basis step 6).
    pub enum SpectrumQuantity {
        /// The singular values s_k.
        SingularValue = "singular_value",
        /// s_k / Σ s.
        Normalized = "normalized",
        /// Running sums of the normalized values.
        Cumulative = "cumulative",
    }
}

named! {
    /// A decomposition coefficient, as an axis of a Gulbrandsen dataset.
    pub enum Coefficient {
        /// c₀ = F₀.
        C0 = "c0",
        /// c₁ = 1 − c₀.
        C1 = "c1",
        /// c₂.
        C2 = "c2",
        /// c₃.
        C3 = "c3",
    }
}

impl Coefficient {
    fn of(self, c: &basis::Coefficients) -> f64 {
        match self {
            Coefficient::C0 => c.c0,
            Coefficient::C1 => c.c1,
            Coefficient::C2 => c.c2,
            Coefficient::C3 => c.c3,
        }
    }
}

named! {
    /// Which number of the directional albedo an albedo dataset shows.
    pub enum AlbedoValue {
        /// E(μ, r) itself.
        Albedo = "E",
        /// 1 − E(μ, r): the energy single scattering loses.
        Loss = "loss",
    }
}

/// A non-θ series.
#[derive(Debug, Clone, PartialEq)]
pub enum Dataset {
    /// The first `count` entries of the spectrum of 100 dielectrics, at x = 0, 1, … (the
    /// notebook's index axis).
    Spectrum {
        /// Which number to show.
        quantity: SpectrumQuantity,
        /// How many leading entries.
        count: usize,
    },
    /// Coefficients of materials given by Gulbrandsen's (r, g) over the product r × g (r outer,
    /// g inner): points (x, y) and, with `z`, a third coordinate.
    Gulbrandsen {
        /// Coefficient on the x axis.
        x: Coefficient,
        /// Coefficient on the y axis.
        y: Coefficient,
        /// Coefficient on the z axis (3D panels).
        z: Option<Coefficient>,
        /// Reflectivities, each in [0, 1).
        r: Vec<f64>,
        /// Edge tints, each in [0, 1].
        g: Vec<f64>,
        /// Use ḡ = 1 − (1 − g)³.
        g_remap: bool,
    },
    /// Points read from a CSV file, x being θ (stored in radians): a renderer's or a measurement's
    /// values to overlay on analytic curves.
    Csv {
        /// The file as the spec names it (relative to the spec's folder).
        path: String,
        /// Column holding θ.
        x_column: String,
        /// Column holding the values.
        y_column: String,
        /// Whether the file's θ are in degrees (converted to radians on reading).
        degrees: bool,
        /// θ in radians, in file order.
        x: Vec<f64>,
        /// Values, in file order.
        y: Vec<f64>,
    },
    /// The directional albedo E (or the loss 1 − E) of the single-scattering BRDF with F = 1 of
    /// a one-parameter NDF family whose parameter is its width α, on Cycles' grid
    /// ([`albedo_table`]): μ_i = i/(mu − 1) (rows, x) by r_j = j/(r − 1) (columns, y), α = map(r);
    /// z per point. The r = 0 column is the mirror limit (the families' limit at α = 0, [`lobe`])
    /// and the μ = 0 row the grazing limit.
    Albedo {
        /// The NDF family (its one parameter is α).
        family: Family,
        /// How r maps to α.
        map: RoughnessMap,
        /// How masking and shadowing combine.
        g2: G2Model,
        /// E or 1 − E.
        value: AlbedoValue,
        /// Points on the μ axis, at least 2.
        mu: usize,
        /// Points on the r axis, at least 2.
        r: usize,
    },
    /// An engine's published table against the exact one: |engine − exact| over (μ, r) on the
    /// engine's grid, the cells computed once by [`PublishedTable::audit`].
    Audit {
        /// The table.
        table: PublishedTable,
        /// Its cells in file order.
        cells: Vec<Cell>,
    },
    /// Literal points.
    Table {
        /// x values.
        x: Vec<f64>,
        /// y values, as many as x.
        y: Vec<f64>,
    },
    /// op(a, b) where a side is sampled (a [`Dataset::Csv`] or a [`Dataset::Table`] whose x is θ),
    /// at the nodes of [`nodes`]: the sampled side's θ, the curve side evaluated there exactly;
    /// when both are sampled, `a`'s θ inside `b`'s span with `b` linear between its samples (θ of
    /// `a` outside that span are left out). Values may be non-finite (a ratio where b is 0).
    Difference {
        /// How the two values combine.
        op: DiffOp,
        /// The first operand.
        a: Box<Side>,
        /// The second operand.
        b: Box<Side>,
    },
}

/// One operand of a [`Dataset::Difference`].
#[derive(Debug, Clone, PartialEq)]
pub enum Side {
    /// An analytic curve, defined at every θ.
    Curve(Curve),
    /// Samples of θ (radians) and values: a [`Dataset::Csv`] or a [`Dataset::Table`].
    Sampled(Dataset),
}

impl Side {
    /// The side as a comparison operand: a curve, or the sampled side's points sorted by θ.
    pub fn operand(&self) -> Operand {
        match self {
            Side::Curve(curve) => Operand::Curve(curve.clone()),
            Side::Sampled(Dataset::Table { x, y } | Dataset::Csv { x, y, .. }) => {
                Operand::Samples(Samples::new(x, y).unwrap_or_else(Samples::empty))
            }
            Side::Sampled(other) => unreachable!("only a series of θ is a side: {other:?}"),
        }
    }

    fn len(&self) -> usize {
        match self {
            Side::Curve(_) => 0,
            Side::Sampled(dataset) => dataset.len(),
        }
    }
}

impl Serialize for Side {
    /// The curve's canonical JSON, or the sampled series'.
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        match self {
            Side::Curve(curve) => curve.serialize(serializer),
            Side::Sampled(dataset) => dataset.serialize(serializer),
        }
    }
}

/// Points of a dataset: (x, y), optional z per point, and the grid shape when the points form
/// a row-major grid.
#[derive(Debug, Clone, PartialEq)]
pub struct DataPoints {
    /// (x, y) per point.
    pub points: Vec<(f64, f64)>,
    /// z per point, for datasets with a z axis.
    pub z: Option<Vec<f64>>,
    /// `Some((rows, cols))` when the points form a grid of at least 2 × 2.
    pub grid: Option<(usize, usize)>,
}

impl Dataset {
    /// Whether the dataset's x is θ in radians (so it shares axes with curves).
    pub fn is_theta(&self) -> bool {
        matches!(self, Dataset::Csv { .. } | Dataset::Difference { .. })
    }

    /// Whether the dataset has a z coordinate (for surface and heat-map panels).
    pub fn has_z(&self) -> bool {
        matches!(
            self,
            Dataset::Gulbrandsen { z: Some(_), .. }
                | Dataset::Albedo { .. }
                | Dataset::Audit { .. }
        )
    }

    /// Whether the dataset is z over a rectilinear grid, x varying along its rows and y along its
    /// columns (what a heat-map panel draws).
    pub fn is_map(&self) -> bool {
        matches!(self, Dataset::Albedo { .. } | Dataset::Audit { .. })
    }

    /// How many points the dataset has, known without computing them (but for a CSV file's,
    /// known once read).
    pub fn len(&self) -> usize {
        match self {
            Dataset::Spectrum { count, .. } => *count,
            Dataset::Gulbrandsen { r, g, .. } => r.len() * g.len(),
            Dataset::Albedo { mu, r, .. } => mu * r,
            Dataset::Audit { cells, .. } => cells.len(),
            Dataset::Table { x, .. } | Dataset::Csv { x, .. } => x.len(),
            Dataset::Difference { a, b, .. } => a.len().max(b.len()),
        }
    }

    /// Whether the dataset has no points.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Computes the points. The spectrum and Gulbrandsen datasets build the Fresnel basis on
    /// first use; an albedo dataset computes its table in parallel, and a quadrature that fails
    /// gives NaN values, which evaluation reports as non-finite.
    pub fn evaluate(&self) -> DataPoints {
        match self {
            Dataset::Spectrum { quantity, count } => {
                let spectrum = basis::spectrum();
                let values = match quantity {
                    SpectrumQuantity::SingularValue => &spectrum.singular_values,
                    SpectrumQuantity::Normalized => &spectrum.normalized,
                    SpectrumQuantity::Cumulative => &spectrum.cumulative,
                };
                let points = values
                    .iter()
                    .take(*count)
                    .enumerate()
                    .map(|(k, &v)| (k as f64, v))
                    .collect();
                DataPoints {
                    points,
                    z: None,
                    grid: None,
                }
            }
            Dataset::Gulbrandsen {
                x,
                y,
                z,
                r,
                g,
                g_remap,
            } => {
                let coefficients: Vec<basis::Coefficients> = r
                    .iter()
                    .flat_map(|&r| g.iter().map(move |&g| (r, g)))
                    .map(|(r, g)| {
                        let g = if *g_remap {
                            gulbrandsen::remap_edge_tint(g)
                        } else {
                            g
                        };
                        basis::coeffs(gulbrandsen::index(r, g))
                    })
                    .collect();
                let points = coefficients.iter().map(|c| (x.of(c), y.of(c))).collect();
                let z = z.map(|z| coefficients.iter().map(|c| z.of(c)).collect());
                let grid = (r.len() > 1 && g.len() > 1).then_some((r.len(), g.len()));
                DataPoints { points, z, grid }
            }
            Dataset::Albedo {
                family,
                map,
                g2,
                value,
                mu,
                r,
            } => {
                let surface = |alpha: f64| {
                    lobe(*family, &[alpha])
                        .expect("the spec admits only families whose width domain holds (0, 1]")
                        .map(|ndf| surface_of(ndf, *g2))
                };
                match albedo_table(*mu, *r, *map, surface, None, None) {
                    Ok(table) => {
                        let points = table
                            .mu
                            .iter()
                            .flat_map(|&m| table.roughness.iter().map(move |&r| (m, r)))
                            .collect();
                        let z = match value {
                            AlbedoValue::Albedo => table.values,
                            AlbedoValue::Loss => table.values.iter().map(|e| 1.0 - e).collect(),
                        };
                        DataPoints {
                            points,
                            z: Some(z),
                            grid: Some((*mu, *r)),
                        }
                    }
                    // A quadrature that did not converge: one non-finite point, reported.
                    Err(_) => DataPoints {
                        points: vec![(f64::NAN, f64::NAN)],
                        z: None,
                        grid: None,
                    },
                }
            }
            Dataset::Audit { table, cells } => {
                // μ-major, as a heat map's grid runs: cell (i, j) at i · n_r + j.
                let grid = table.grid();
                let n_r = grid.n_r;
                let mut ordered = vec![cells[0]; cells.len()];
                for (k, cell) in cells.iter().enumerate() {
                    let (i, j) = grid.cell(k);
                    ordered[i * n_r + j] = *cell;
                }
                DataPoints {
                    points: ordered.iter().map(|c| (c.mu, c.r)).collect(),
                    z: Some(ordered.iter().map(|c| c.error().abs()).collect()),
                    grid: Some((cells.len() / n_r, n_r)),
                }
            }
            Dataset::Table { x, y } | Dataset::Csv { x, y, .. } => DataPoints {
                points: x.iter().copied().zip(y.iter().copied()).collect(),
                z: None,
                grid: None,
            },
            Dataset::Difference { op, a, b } => {
                let (a, b) = (a.operand(), b.operand());
                let points = nodes(&a, &b, ThetaRange::FULL)
                    .unwrap_or_default()
                    .into_iter()
                    .map(|t| (t, op.apply(a.at(t), b.at(t))))
                    .collect();
                DataPoints {
                    points,
                    z: None,
                    grid: None,
                }
            }
        }
    }
}

impl Serialize for Dataset {
    /// The members of the canonical JSON (see [`Dataset::canonical_json`]); a CSV series is named
    /// by its file and columns, not its values.
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut map = serializer.serialize_map(None)?;
        match self {
            Dataset::Spectrum { quantity, count } => {
                map.serialize_entry("data", "spectrum")?;
                map.serialize_entry("quantity", quantity.name())?;
                map.serialize_entry("count", count)?;
            }
            Dataset::Gulbrandsen {
                x,
                y,
                z,
                r,
                g,
                g_remap,
            } => {
                map.serialize_entry("data", "gulbrandsen")?;
                map.serialize_entry("x", x.name())?;
                map.serialize_entry("y", y.name())?;
                if let Some(z) = z {
                    map.serialize_entry("z", z.name())?;
                }
                map.serialize_entry("r", r)?;
                map.serialize_entry("g", g)?;
                map.serialize_entry("g_remap", g_remap)?;
            }
            Dataset::Albedo {
                family,
                map: roughness,
                g2,
                value,
                mu,
                r,
            } => {
                map.serialize_entry("data", "albedo")?;
                map.serialize_entry("ndf", family.name())?;
                map.serialize_entry("map", roughness.key())?;
                map.serialize_entry("g2", g2.name())?;
                map.serialize_entry("value", value.name())?;
                map.serialize_entry("mu", mu)?;
                map.serialize_entry("r", r)?;
            }
            Dataset::Audit { table, .. } => {
                map.serialize_entry("data", "audit")?;
                map.serialize_entry("table", table.name())?;
            }
            Dataset::Table { x, y } => {
                map.serialize_entry("data", "table")?;
                map.serialize_entry("x", x)?;
                map.serialize_entry("y", y)?;
            }
            Dataset::Csv {
                path,
                x_column,
                y_column,
                degrees,
                ..
            } => {
                map.serialize_entry("data", "csv")?;
                map.serialize_entry("path", path)?;
                map.serialize_entry("x", x_column)?;
                map.serialize_entry("y", y_column)?;
                map.serialize_entry("degrees", degrees)?;
            }
            Dataset::Difference { op, a, b } => {
                map.serialize_entry("difference", op.name())?;
                map.serialize_entry("a", a)?;
                map.serialize_entry("b", b)?;
            }
        }
        map.end()
    }
}
