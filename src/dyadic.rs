//! The interactive page's sampling rule: adaptive samples of one curve on a dyadic θ grid, judged
//! for the linear and the log view alike (the page toggles the y scale).
//!
//! θ_k = lo + k·((hi − lo)/2^[`FINE_LEVELS`]); the [`COARSE_LEVELS`] first bisection levels are
//! always taken (33 evenly spaced samples), and each deeper interval is bisected when its midpoint
//! sits farther from the chord than [`LINEAR_TOLERANCE`] of the curve's largest |value| (the
//! linear view) or, where the values lie within [`LOG_DECADES`] of that largest value,
//! [`LOG_TOLERANCE`] in ln (the log view). Unlike the figure sampler ([`crate::adaptive`]) the
//! grid is dyadic, so that the tree of bisections encodes θ in one bit per interval
//! (`output::html` packs it). It evaluates only the closure it is handed.

/// Levels of the finest θ grid: 2^14 intervals, θ steps of 9.6e-5 rad over [0, π/2].
pub const FINE_LEVELS: u32 = 14;
/// Levels always bisected: 2^5 = 32 initial intervals of 0.05 rad over [0, π/2], so that a lobe
/// cannot hide between samples: every NDF lobe of the catalogue peaks at θ = 0 or π/2 or is wider,
/// and the chord test then resolves even Phong α_p = 8000 (half-width 0.016 rad) at θ = 0.
pub const COARSE_LEVELS: u32 = 5;
/// Largest midpoint distance from the chord, as a fraction of the curve's largest |value|: half a
/// pixel on a 1000 px tall plot.
const LINEAR_TOLERANCE: f64 = 5e-4;
/// Largest midpoint distance from the chord of ln y: 1 %, a fifth of a pixel on a 400 px plot
/// spanning [`LOG_DECADES`].
const LOG_TOLERANCE: f64 = 0.01;
/// Decades below the largest value that the log view shows; the page clips below them.
pub const LOG_DECADES: f64 = 12.0;

/// The samples of one curve: grid indices and values, θ increasing.
#[derive(Debug, Clone, PartialEq)]
pub struct Samples {
    /// Grid indices k, θ_k = lo + k·((hi − lo)/2^FINE_LEVELS).
    pub ks: Vec<u32>,
    /// Values f(θ_k).
    pub values: Vec<f64>,
    /// The bisection tree in pre-order (true = split).
    pub tree: Vec<bool>,
}

/// θ of grid index `k` over `(lo, hi)`; `page.js` computes the same expression.
pub fn theta((lo, hi): (f64, f64), k: u32) -> f64 {
    lo + f64::from(k) * ((hi - lo) / f64::from(1u32 << FINE_LEVELS))
}

/// Samples `f` adaptively over `range`; `Err` names the first non-finite value.
pub fn sample(f: &dyn Fn(f64) -> f64, range: (f64, f64)) -> Result<Samples, String> {
    let eval = |k: u32| {
        let theta = theta(range, k);
        let y = f(theta);
        if y.is_finite() {
            Ok(y)
        } else {
            Err(format!("non-finite value {y} at θ = {theta:?}"))
        }
    };
    let coarse = 1u32 << (FINE_LEVELS - COARSE_LEVELS);
    let nodes: Vec<f64> = (0..=1u32 << COARSE_LEVELS)
        .map(|j| eval(j * coarse))
        .collect::<Result<_, _>>()?;
    let mut refiner = Refiner {
        eval: &eval,
        scale: nodes.iter().fold(0.0, |m: f64, y| m.max(y.abs())),
        samples: Samples {
            ks: vec![0],
            values: vec![nodes[0]],
            tree: Vec::new(),
        },
    };
    for (j, pair) in nodes.windows(2).enumerate() {
        let (a, b) = (j as u32 * coarse, (j as u32 + 1) * coarse);
        refiner.refine((a, pair[0]), (b, pair[1]), COARSE_LEVELS)?;
        refiner.samples.ks.push(b);
        refiner.samples.values.push(pair[1]);
    }
    Ok(refiner.samples)
}

struct Refiner<'a> {
    eval: &'a dyn Fn(u32) -> Result<f64, String>,
    /// Largest |value| seen so far.
    scale: f64,
    samples: Samples,
}

impl Refiner<'_> {
    /// Bisects (a, b) at `level` while [`needs_split`] says so, pushing the inner samples in order.
    fn refine(
        &mut self,
        (a, ya): (u32, f64),
        (b, yb): (u32, f64),
        level: u32,
    ) -> Result<(), String> {
        if level >= FINE_LEVELS {
            return Ok(());
        }
        let m = (a + b) / 2;
        let ym = (self.eval)(m)?;
        self.scale = self.scale.max(ym.abs());
        let split = needs_split(ya, ym, yb, self.scale);
        self.samples.tree.push(split);
        if split {
            self.refine((a, ya), (m, ym), level + 1)?;
            self.samples.ks.push(m);
            self.samples.values.push(ym);
            self.refine((m, ym), (b, yb), level + 1)?;
        }
        Ok(())
    }
}

/// Whether the chord from `ya` to `yb` misses the midpoint value `ym` visibly, linearly or in log.
fn needs_split(ya: f64, ym: f64, yb: f64, scale: f64) -> bool {
    if (ym - 0.5 * (ya + yb)).abs() > LINEAR_TOLERANCE * scale {
        return true;
    }
    let floor = scale * 10f64.powf(-LOG_DECADES);
    let shown = [ya, ym, yb].map(|y| y > floor);
    match shown {
        [true, true, true] => (ym.ln() - 0.5 * (ya.ln() + yb.ln())).abs() > LOG_TOLERANCE,
        [false, false, false] => false,
        // The log view's curve leaves the plot here: find where.
        _ => true,
    }
}
