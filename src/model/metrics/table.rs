//! How far an engine's table is from the exact one, cell by cell (`ndfplot albedo --against`):
//! the largest absolute difference, the root mean square, the largest relative difference where
//! the exact value is not near 0, and the cells where they occur.

/// Exact values below this magnitude are left out of the relative difference: a relative error of
/// a value near 0 (the loss 1 − E of a smooth lobe, DFG2 at normal incidence) says nothing.
pub const RELATIVE_FLOOR: f64 = 1e-3;

/// One cell: its coordinates (μ, r), the engine's value and the exact one.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cell {
    /// μ = cos θo of the cell as the engine's grid places it (NaN in an average table, which has
    /// no μ axis).
    pub mu: f64,
    /// The roughness coordinate r of the cell as the engine's grid places it.
    pub r: f64,
    /// The engine's value.
    pub engine: f64,
    /// The exact value.
    pub exact: f64,
}

impl Cell {
    /// engine − exact.
    pub fn error(&self) -> f64 {
        self.engine - self.exact
    }
}

/// The comparison of a table's cells.
#[derive(Debug, Clone, PartialEq)]
pub struct TableAudit {
    /// max |engine − exact| over the cells.
    pub max_abs: f64,
    /// √(Σ (engine − exact)² / n).
    pub rms: f64,
    /// max |engine − exact| / |exact| over the cells with |exact| ≥ [`RELATIVE_FLOOR`]; `None` if
    /// there is no such cell.
    pub max_rel: Option<f64>,
    /// Index of the cell of `max_abs` (the first of equals).
    pub worst: usize,
    /// Index of the cell of `max_rel`.
    pub worst_rel: Option<usize>,
}

impl TableAudit {
    /// The audit of `cells` (at least one; every value finite).
    pub fn of(cells: &[Cell]) -> TableAudit {
        assert!(!cells.is_empty(), "a table has cells");
        let mut worst = 0;
        let mut worst_rel: Option<(usize, f64)> = None;
        let mut squares = 0.0;
        for (k, cell) in cells.iter().enumerate() {
            let error = cell.error().abs();
            squares += error * error;
            if error > cells[worst].error().abs() {
                worst = k;
            }
            if cell.exact.abs() >= RELATIVE_FLOOR {
                let relative = error / cell.exact.abs();
                if worst_rel.is_none_or(|(_, r)| relative > r) {
                    worst_rel = Some((k, relative));
                }
            }
        }
        TableAudit {
            max_abs: cells[worst].error().abs(),
            rms: (squares / cells.len() as f64).sqrt(),
            max_rel: worst_rel.map(|(_, r)| r),
            worst,
            worst_rel: worst_rel.map(|(k, _)| k),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_worst_cells_and_the_mean_square_are_found() {
        let cell = |engine, exact| Cell {
            mu: 0.5,
            r: 0.5,
            engine,
            exact,
        };
        let cells = [
            cell(1.0, 1.0),
            cell(0.7, 1.0),
            cell(0.0, 1e-4),
            cell(0.5, 0.4),
        ];
        let audit = TableAudit::of(&cells);
        assert_eq!(audit.worst, 1);
        assert!((audit.max_abs - 0.3).abs() < 1e-15);
        // (0.3² + 1e-8 + 0.1²)/4 under the root; the 1e-4 cell is below the relative floor.
        assert!((audit.rms - ((0.09 + 1e-8 + 0.01) / 4f64).sqrt()).abs() < 1e-15);
        assert_eq!(audit.worst_rel, Some(1));
        assert!((audit.max_rel.unwrap() - 0.3).abs() < 1e-15);
    }
}
