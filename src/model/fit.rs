//! Fitting the free parameters of an NDF family to a target curve (`ndfplot fit`, scene `{"fit": …}`):
//! `peak` equates the values at the normal, D(0) — the notebook's manual method; `max` equates the maxima
//! over θ; `l2` minimizes `l2_projected` (docs/contracts.md, docs/maths.md "Parameter equivalences and fits").
//! Peak and max match one number, so they fit exactly one free parameter; L2 fits every parameter not
//! fixed.
//!
//! A free parameter is searched within the domain its family states ([`Param`]), on a log scale for
//! parameters bounded below by 0 or more (u = ln x) and a linear one for the others (u = x, SGD's a₂).
//! Peak and max fits bracket the root of a log-like mismatch by geometric expansion and solve it with
//! Brent's method ([`crate::model::math::roots`]); L2 fits of one parameter bracket the minimum by a downhill
//! walk and refine it by golden-section search ([`crate::model::metrics::golden_section_max`]); L2 fits of
//! several run Nelder–Mead in u ([`crate::model::math::simplex`]) from a few deterministic, peak-matched
//! starts and keep the best. Several targets are fitted in parallel, in input order ([`FitSpec::fit_all`]).
//! Results are cached per process. No I/O.

use crate::model::curve::Curve;
use crate::model::domain::{DomainError, Param};
use crate::model::math::roots::{RootError, brent, expand_bracket_log};
use crate::model::math::simplex::{self, Bounds};
use crate::model::metrics::{self, MetricError, golden_section_max, lobe_width, maximum};
use crate::model::names::named;
use crate::model::ndf::Family;
use crate::problem::suggestion;
use rayon::prelude::*;
use std::collections::HashMap;
use std::fmt;
use std::sync::{Mutex, OnceLock};

named! {
    /// How a fit matches its target (`"by"` of a fitted parameter, `fit --by`); [`fit`] carries it out.
    pub enum By {
        /// D_fit(0) = D_target(0).
        Peak = "peak",
        /// max_θ D_fit = max_θ D_target.
        Max = "max",
        /// Minimal `l2_projected`.
        L2 = "l2",
    }
}

impl By {
    /// The name of the residual the fit reports (`residual=<x> (<metric>)`): the relative mismatch of
    /// D(0) (`d0_rel`), of the maxima (`dmax_rel`), or `l2_projected`.
    pub fn residual_name(self) -> &'static str {
        match self {
            By::Peak => "d0_rel",
            By::Max => "dmax_rel",
            By::L2 => "l2_projected",
        }
    }
}

/// Ratio of successive points of the bracket expansion: a factor 2 in the parameter (or a step of ln 2 in a
/// linear one) keeps the number of steps modest over domains spanning 600 decades.
const BRACKET_FACTOR: f64 = 2.0;

/// Smallest |d ln P / d ln x| (P the matched value, x the free parameter) accepted at a root. Values are
/// computed to ~1e-15 relative, so at this slope the root is still determined to ~1e-9 relative; below it
/// the target equals the family's limiting value to within rounding (Torrance–Sparrow's uniform limit as
/// α_ts → ∞), which no parameter in the domain actually reaches. L2 fits apply the same bound to the rise
/// of l2_projected around the minimum per unit u, relative to the target's D(0).
const MIN_SLOPE: f64 = 1e-6;

/// Step in u (ln x, or x for a linear parameter) of the central difference measuring that slope: 0.1 %
/// changes keep the difference far above rounding and its truncation error far below [`MIN_SLOPE`].
const SLOPE_STEP: f64 = 1e-3;

/// Absolute tolerance in u of Brent's method for peak and max fits: a few ulps of u near u = 0 (x = 1),
/// where the solver's own relative term 2ε|u| vanishes.
const U_TOL: f64 = 4.0 * f64::EPSILON;

/// The starting point of every search: u = 0, that is x = 1 for a log parameter (inside every family's
/// natural range; the bound + 1 above an open positive bound, STD's γ = 2.5) and x = 0 for a linear one
/// (SGD's a₂).
const U_START: f64 = 0.0;

/// Growth of the steps of the downhill walk that brackets an L2 minimum: the golden ratio φ, the classic
/// choice of bracketing before a golden-section search.
const GROWTH: f64 = 1.618_033_988_749_895;

/// Golden-section tolerance in u for L2 fits: the minimum of a smooth L2 distance is located only to
/// ~√(1e-12) ≈ 1e-6 relative by quadrature values accurate to `QUAD_REL_TOL`, so 1e-9 resolves all there is.
const L2_U_TOL: f64 = 1e-9;

/// Distance in u = ln x of the first and last of the three starts of each log shape parameter (all free
/// parameters but the first) from its family's example value: a factor 4 either way (ABC's
/// a₂ = 0.4375 … 7, GTR's γ = 0.375 … 6), spanning the shapes the notebooks draw.
const START_SPREAD_LOG: f64 = 2.0 * std::f64::consts::LN_2;

/// The same for a linear shape parameter: ±1 around the example (SGD's a₂ = −0.5 … 1.5, the notebook's
/// 0 … 1.5 and beyond).
const START_SPREAD_LINEAR: f64 = 1.0;

/// Most objective evaluations of one Nelder–Mead run: a two-parameter fit converges to [`L2_U_TOL`] in a
/// few hundred; the cap only bounds a run that creeps along a flat valley.
const SIMPLEX_MAX_EVALUATIONS: usize = 2000;

/// Which input a fit problem is about.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Subject {
    /// The target curve.
    Target,
    /// The fixed parameters.
    Fixed,
}

/// Why a fit failed: the input at fault, the key concerned and a message with `(got …, expected …)`.
#[derive(Debug, Clone, PartialEq)]
pub struct FitError {
    /// The input at fault.
    pub subject: Subject,
    /// The parameter key concerned (or the target's model key).
    pub key: String,
    /// What is wrong.
    pub message: String,
}

impl FitError {
    fn new(subject: Subject, key: impl Into<String>, message: impl Into<String>) -> FitError {
        FitError {
            subject,
            key: key.into(),
            message: message.into(),
        }
    }
}

impl fmt::Display for FitError {
    /// `<key>: <message>`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.key, self.message)
    }
}

impl std::error::Error for FitError {}

/// A fitted curve.
#[derive(Debug, Clone, PartialEq)]
pub struct Fit {
    /// The fitted NDF, fixed parameters included.
    pub curve: Curve,
    /// The free parameters' names with their fitted values, in the family's parameter order.
    pub free: Vec<(&'static str, f64)>,
    /// The residual named by [`By::residual_name`].
    pub residual: f64,
}

impl Fit {
    /// Every parameter of the fitted NDF with its value, in the family's order, fixed ones included.
    pub fn params(&self) -> Vec<(&'static str, f64)> {
        match &self.curve {
            Curve::Ndf(d) => d
                .family()
                .param_names()
                .into_iter()
                .zip(d.params())
                .collect(),
            _ => Vec::new(),
        }
    }
}

/// The search interval of a free parameter: [lo, hi] within its family's stated domain, searched in
/// u = ln(x − offset) (`log`) or u = x. The offset is the lower bound of a domain open at a positive
/// value (STD's γ > 1.5: u = ln(γ − 1.5)), so that every u is inside the domain; 0 otherwise.
#[derive(Debug, Clone, Copy)]
struct SearchDomain {
    param: &'static Param,
    lo: f64,
    hi: f64,
    log: bool,
    offset: f64,
}

impl SearchDomain {
    /// The domain of parameter `index` of `family`. A log search starts at the smallest normal double
    /// when the domain reaches down to 0 (Phong's α_p ≥ 0, whose 0 is checked exactly; ABC's a > 0),
    /// and just above an open positive lower bound.
    fn of(family: Family, index: usize) -> SearchDomain {
        let param = &family.params()[index];
        let min = param.min.value;
        let log = min >= 0.0;
        let offset = if log && !param.min.inclusive {
            min
        } else {
            0.0
        };
        let lo = match (log, param.min.inclusive) {
            (false, _) => min,
            (true, true) => min.max(f64::MIN_POSITIVE),
            // The next double above min ≥ 0 (f64::next_up needs Rust 1.86; the crate builds on 1.85).
            (true, false) => f64::from_bits(min.to_bits() + 1).max(f64::MIN_POSITIVE),
        };
        SearchDomain {
            param,
            lo,
            hi: param.max.value,
            log,
            offset,
        }
    }

    /// Whether the domain holds 0, which a log search cannot reach (Phong's uniform α_p = 0).
    fn holds_zero(self) -> bool {
        self.log && self.param.contains(0.0)
    }

    /// The searched u interval.
    fn u_bounds(self) -> (f64, f64) {
        (self.u(self.lo), self.u(self.hi))
    }

    /// x of u, clamped into the searched interval.
    fn x(self, u: f64) -> f64 {
        if self.log {
            (self.offset + u.exp()).clamp(self.lo, self.hi)
        } else {
            u.clamp(self.lo, self.hi)
        }
    }

    /// u of x.
    fn u(self, x: f64) -> f64 {
        if self.log { (x - self.offset).ln() } else { x }
    }

    /// The parameter and its domain: `alpha_ts in [1e-150, 1e150]`.
    fn describe(self) -> String {
        format!("{} {}", self.param.name, self.param.interval())
    }
}

/// A fit problem: the family, which parameter is free, the fixed values.
struct FitProblem<'a> {
    family: Family,
    free: usize,
    fixed: Vec<f64>,
    target: &'a Curve,
    domain: SearchDomain,
}

impl FitProblem<'_> {
    fn key(&self) -> &'static str {
        self.family.param_names()[self.free]
    }

    /// The family's NDF with the free parameter at x (inside the domain).
    fn curve(&self, x: f64) -> Result<Curve, DomainError> {
        let mut params = self.fixed.clone();
        params.insert(self.free, x);
        Ok(Curve::Ndf(self.family.build(&params)?))
    }

    fn curve_at_u(&self, u: f64) -> Curve {
        self.curve(self.domain.x(u))
            .expect("the fixed values were validated and x is clamped into the domain")
    }

    /// l2_projected between the family's NDF at u and the target, breakpoints at their values at the
    /// normal.
    fn l2(&self, u: f64) -> Result<f64, FitError> {
        let curve = self.curve_at_u(u);
        metrics::l2_projected_with(&curve, self.target, curve.eval(0.0), self.target.eval(0.0))
            .map_err(|e| {
                FitError::new(
                    Subject::Target,
                    self.key(),
                    format!("cannot compute the fit: {e}"),
                )
            })
    }
}

/// The value a peak or max fit matches.
fn matched_value(curve: &Curve, by: By) -> Result<f64, MetricError> {
    match by {
        By::Max => Ok(maximum(|t| curve.eval(t), lobe_width(curve.eval(0.0)))?.value),
        _ => Ok(curve.eval(0.0)),
    }
}

/// A bounded, sign-preserving stand-in for ln(p/q): r − 1 for r = p/q ≤ 1, 1 − 1/r above. It equals
/// ln r to first order at the root and stays finite when p underflows to 0.
fn mismatch(p: f64, q: f64) -> f64 {
    let r = p / q;
    if r <= 1.0 { r - 1.0 } else { 1.0 - 1.0 / r }
}

/// A fit checked against its family before any target is read: which parameters are free, the values
/// of the fixed ones, the method. Every problem of the fixed keys and of the method is found here, so a
/// batch reports it once.
#[derive(Debug, Clone)]
pub struct FitSpec {
    family: Family,
    by: By,
    /// Indices of the free parameters, in the family's order.
    free: Vec<usize>,
    /// Every parameter's value in the family's order; the free ones hold u = [`U_START`]'s value.
    values: Vec<f64>,
    /// The fixed keys as given, `key=value` joined by commas: part of the cache key.
    fixed_text: String,
}

/// Checks that every key of `fixed` (`--fix`) is a parameter of `family` and is fixed at most
/// once; the error names the first key that is not.
pub fn check_fixed_keys(family: Family, fixed: &[(String, f64)]) -> Result<(), FitError> {
    let names = family.param_names();
    for (i, (key, value)) in fixed.iter().enumerate() {
        if !names.contains(&key.as_str()) {
            return Err(FitError::new(
                Subject::Fixed,
                key,
                format!(
                    "not a parameter of {} (got {key}={value:?}, expected one of: {}){}",
                    family.name(),
                    names.join(", "),
                    suggestion(key, names.iter().copied())
                ),
            ));
        }
        if fixed[..i].iter().any(|(k, _)| k == key) {
            return Err(FitError::new(
                Subject::Fixed,
                key,
                format!("fixed twice (got {key}={value:?} again)"),
            ));
        }
    }
    Ok(())
}

impl FitSpec {
    /// Checks `fixed` (key, value) pairs against `family`'s parameters for a fit by `by`.
    ///
    /// Errors ([`Subject::Fixed`]): a key the family lacks (with a suggestion), a key fixed twice, no free
    /// parameter left, more than one free parameter for `peak` or `max` (which match one number), a
    /// fixed value out of its domain.
    pub fn new(family: Family, fixed: &[(String, f64)], by: By) -> Result<FitSpec, FitError> {
        check_fixed_keys(family, fixed)?;
        let names = family.param_names();
        let fixed_value = |name: &str| fixed.iter().find(|(k, _)| k == name).map(|&(_, v)| v);
        let free: Vec<usize> = (0..names.len())
            .filter(|&i| fixed_value(names[i]).is_none())
            .collect();
        let open: Vec<&str> = free.iter().map(|&i| names[i]).collect();
        if free.is_empty() {
            return Err(FitError::new(
                Subject::Fixed,
                names.join(", "),
                format!(
                    "no free parameter left for {} (got all of {} fixed, expected at least one of them free)",
                    family.name(),
                    names.join(", ")
                ),
            ));
        }
        if free.len() > 1 && by != By::L2 {
            return Err(FitError::new(
                Subject::Fixed,
                open.join(", "),
                format!(
                    "{} has {} free parameters (got {} fixed, expected all but one fixed: --by {} matches one number, so add --fix for all but one of {}, or fit them all --by l2)",
                    family.name(),
                    open.len(),
                    fixed.len(),
                    by.name(),
                    open.join(", ")
                ),
            ));
        }
        let values: Vec<f64> = (0..names.len())
            .map(|i| {
                fixed_value(names[i]).unwrap_or_else(|| SearchDomain::of(family, i).x(U_START))
            })
            .collect();
        // The free values are inside their domains, so a domain error names a fixed value.
        family.build(&values).map_err(|e| {
            FitError::new(
                Subject::Fixed,
                e.param,
                format!("out of domain (got {:?}, expected {})", e.value, e.expected),
            )
        })?;
        let fixed_text: Vec<String> = fixed.iter().map(|(k, v)| format!("{k}={v:?}")).collect();
        Ok(FitSpec {
            family,
            by,
            free,
            values,
            fixed_text: fixed_text.join(","),
        })
    }

    /// The family fitted.
    pub fn family(&self) -> Family {
        self.family
    }

    /// The method.
    pub fn by(&self) -> By {
        self.by
    }

    /// Fits the free parameters to `target`. Results are cached per process, keyed by the target's
    /// canonical JSON, the family, the fixed values and the method.
    ///
    /// Errors ([`Subject::Target`]): a target that is not an NDF, or that the family cannot reach in its
    /// domain.
    pub fn fit(&self, target: &Curve) -> Result<Fit, FitError> {
        static CACHE: OnceLock<Mutex<HashMap<String, Result<Fit, FitError>>>> = OnceLock::new();
        let key = format!(
            "{}|{}|{}|{}",
            target.canonical_json(),
            self.family.name(),
            self.fixed_text,
            self.by.name()
        );
        let cache = CACHE.get_or_init(|| Mutex::new(HashMap::new()));
        if let Some(hit) = cache
            .lock()
            .expect("no panic while holding the lock")
            .get(&key)
        {
            return hit.clone();
        }
        let result = self.fit_uncached(target);
        cache
            .lock()
            .expect("no panic while holding the lock")
            .insert(key, result.clone());
        result
    }

    /// [`FitSpec::fit`] of every target, in parallel; the results in the targets' order, identical to
    /// fitting them one by one.
    pub fn fit_all(&self, targets: &[Curve]) -> Vec<Result<Fit, FitError>> {
        targets.par_iter().map(|target| self.fit(target)).collect()
    }

    fn fit_uncached(&self, target: &Curve) -> Result<Fit, FitError> {
        let model = target.model();
        // An NDF, or the D a renderer computes for one.
        let is_d = match target {
            Curve::Ndf(_) => true,
            Curve::Emulated(_) => target.kind() == crate::model::curve::Kind::Ndf("d"),
            _ => false,
        };
        if !is_d {
            return Err(FitError::new(
                Subject::Target,
                model.key(),
                format!(
                    "a fit needs an NDF target showing D (got {} \"{}\", expected an ndf curve)",
                    model.key(),
                    model.name()
                ),
            ));
        }
        let values = match self.free[..] {
            [free] => {
                let line = self.line(free, &self.values, target);
                let value = match self.by {
                    By::Peak | By::Max => solve_match(&line, self.by)?,
                    By::L2 => minimize_l2(&line)?,
                };
                let mut values = self.values.clone();
                values[free] = value;
                values
            }
            _ => self.minimize_l2_joint(target)?,
        };
        let key = self.family.param_names()[self.free[0]];
        let metric_error = |e: MetricError| {
            FitError::new(Subject::Target, key, format!("cannot compute the fit: {e}"))
        };
        let curve = Curve::Ndf(
            self.family
                .build(&values)
                .expect("the fitted values lie in the domain"),
        );
        let residual = match self.by {
            By::Peak | By::Max => {
                let (p, q) = (
                    matched_value(&curve, self.by).map_err(metric_error)?,
                    matched_value(target, self.by).map_err(metric_error)?,
                );
                metrics::relative_difference(p, q)
            }
            By::L2 => metrics::l2_projected(&curve, target).map_err(metric_error)?,
        };
        let names = self.family.param_names();
        Ok(Fit {
            curve,
            free: self.free.iter().map(|&i| (names[i], values[i])).collect(),
            residual,
        })
    }

    /// The one-parameter problem of parameter `index`, every other parameter at its value in `values`.
    fn line<'a>(&self, index: usize, values: &[f64], target: &'a Curve) -> FitProblem<'a> {
        let mut fixed = values.to_vec();
        fixed.remove(index);
        FitProblem {
            family: self.family,
            free: index,
            fixed,
            target,
            domain: SearchDomain::of(self.family, index),
        }
    }

    /// Every parameter's value with the free ones at u.
    fn values_at(&self, u: &[f64]) -> Vec<f64> {
        let mut values = self.values.clone();
        for (&i, &u) in self.free.iter().zip(u) {
            values[i] = SearchDomain::of(self.family, i).x(u);
        }
        values
    }

    /// The starts of a joint L2 fit, in u: every combination of three values of each shape parameter
    /// (the free ones after the first) around the family's example ([`START_SPREAD_LOG`]), the first
    /// free parameter peak-matched to the target for that shape (its example value where no peak match
    /// exists).
    fn starts(&self, target: &Curve) -> Vec<Vec<f64>> {
        let example = self.family.example();
        let mut starts: Vec<Vec<f64>> = vec![vec![]];
        for &i in &self.free[1..] {
            let domain = SearchDomain::of(self.family, i);
            let spread = if domain.log {
                START_SPREAD_LOG
            } else {
                START_SPREAD_LINEAR
            };
            let centre = domain.u(example[i]);
            starts = starts
                .into_iter()
                .flat_map(|start| {
                    [-spread, 0.0, spread]
                        .map(|offset| [start.as_slice(), &[centre + offset]].concat())
                })
                .collect();
        }
        let scale = self.free[0];
        let domain = SearchDomain::of(self.family, scale);
        starts
            .into_iter()
            .map(|shape| {
                let mut u = [&[domain.u(example[scale])], shape.as_slice()].concat();
                let line = self.line(scale, &self.values_at(&u), target);
                if let Ok(x) = solve_match(&line, By::Peak)
                    && (x > 0.0 || !domain.log)
                {
                    u[0] = domain.u(x);
                }
                u
            })
            .collect()
    }

    /// Minimizes l2_projected(fit(u), target) over every free parameter: Nelder–Mead from each of
    /// [`FitSpec::starts`], keeping the lowest value (the earliest start on a tie). A minimum on a domain
    /// bound, or flat along a parameter, is not a fit (as for one parameter, [`check_l2_minimum`]).
    fn minimize_l2_joint(&self, target: &Curve) -> Result<Vec<f64>, FitError> {
        let score = |u: &[f64]| {
            let line = self.line(self.free[0], &self.values_at(u), target);
            line.l2(u[0]).map(|v| v * v)
        };
        let domains: Vec<SearchDomain> = self
            .free
            .iter()
            .map(|&i| SearchDomain::of(self.family, i))
            .collect();
        let (lower, upper): (Vec<f64>, Vec<f64>) = domains.iter().map(|d| d.u_bounds()).unzip();
        let step = vec![BRACKET_FACTOR.ln(); domains.len()];
        let bounds = Bounds {
            lower: &lower,
            upper: &upper,
            step: &step,
            x_tol: L2_U_TOL,
            max_evaluations: SIMPLEX_MAX_EVALUATIONS,
        };
        let minima = self
            .starts(target)
            .iter()
            .map(|start| simplex::minimize(score, start, bounds))
            .collect::<Result<Vec<_>, _>>()?;
        let best = minima
            .iter()
            .reduce(|best, m| if m.value < best.value { m } else { best })
            .expect("there is at least one start");
        let values = self.values_at(&best.x);
        // Another start ending far from the best point at the same distance (to [`MIN_SLOPE`]) found a
        // valley along which l2_projected no longer moves: a limit of the family, or parameters the target
        // does not determine (GTR with α = 1 is uniform for every γ), not a minimum.
        let target_peak = target.eval(0.0);
        for other in &minima {
            let apart = other
                .x
                .iter()
                .zip(&best.x)
                .map(|(a, b)| (a - b).abs())
                .fold(0.0, f64::max);
            let rise = other.value.sqrt() - best.value.sqrt();
            if apart > SLOPE_STEP && rise / (apart * target_peak) < MIN_SLOPE {
                let names = self.family.param_names();
                let keys: Vec<&str> = self.free.iter().map(|&i| names[i]).collect();
                let at = |values: &[f64]| {
                    let text: Vec<String> = self
                        .free
                        .iter()
                        .map(|&i| format!("{} = {:?}", names[i], values[i]))
                        .collect();
                    text.join(", ")
                };
                return Err(FitError::new(
                    Subject::Target,
                    keys.join(", "),
                    format!(
                        "{} cannot determine its parameters: l2_projected stays flat along a valley, towards a limit of the family or where the parameters do not matter (got the same distance at {} and at {}, expected a single minimum inside the domain)",
                        self.family.name(),
                        at(&values),
                        at(&self.values_at(&other.x))
                    ),
                ));
            }
        }
        for (k, &i) in self.free.iter().enumerate() {
            check_l2_minimum(&self.line(i, &values, target), best.x[k])?;
        }
        Ok(values)
    }
}

/// Fits the free parameters of `family` (those not in `fixed`) to `target` by `by`: [`FitSpec::new`]
/// then [`FitSpec::fit`], whose errors it returns.
pub fn fit(
    target: &Curve,
    family: Family,
    fixed: &[(String, f64)],
    by: By,
) -> Result<Fit, FitError> {
    FitSpec::new(family, fixed, by)?.fit(target)
}

/// Solves P_fit(x) = P_target (P = D(0) or max D) for x in the domain.
fn solve_match(problem: &FitProblem, by: By) -> Result<f64, FitError> {
    let key = problem.key();
    let what = if by == By::Peak { "D(0)" } else { "maximum" };
    let numerics =
        |e: String| FitError::new(Subject::Target, key, format!("cannot compute the fit: {e}"));
    let target = matched_value(problem.target, by).map_err(|e| numerics(e.to_string()))?;
    let domain = problem.domain;
    // Evaluation failures (which the NDFs' domains exclude) surface as NaN, which the root finder reports.
    let g = |u: f64| {
        matched_value(&problem.curve_at_u(u), by).map_or(f64::NAN, |p| mismatch(p, target))
    };
    // A lower bound of 0 (Phong's uniform α_p = 0) lies outside the log search: try it exactly.
    if domain.holds_zero() {
        let at_zero = problem.curve(0.0).expect("0 is in the domain");
        if matched_value(&at_zero, by).map_err(|e| numerics(e.to_string()))? == target {
            return Ok(0.0);
        }
    }
    let (u_lo, u_hi) = domain.u_bounds();
    let u0 = U_START;
    // Expand in s = e^u, so that expand_bracket_log's geometric steps are steps of ln 2 in u.
    let steps = ((u_hi - u0).max(u0 - u_lo) / BRACKET_FACTOR.ln()).ceil() as usize + 1;
    let g_s = |s: f64| g(s.ln().clamp(u_lo, u_hi));
    let unreachable = || {
        let (p_lo, p_hi) = (
            matched_value(&problem.curve_at_u(u_lo), by),
            matched_value(&problem.curve_at_u(u_hi), by),
        );
        let (p_lo, p_hi) = (p_lo.unwrap_or(f64::NAN), p_hi.unwrap_or(f64::NAN));
        FitError::new(
            Subject::Target,
            key,
            format!(
                "{} cannot reach the target's {what} (got {target:?}, expected a value strictly between {:?} and {:?}, which {} gives)",
                problem.family.name(),
                p_lo.min(p_hi),
                p_lo.max(p_hi),
                domain.describe()
            ),
        )
    };
    let (s_a, s_b) = match expand_bracket_log(g_s, u0.exp(), BRACKET_FACTOR, steps) {
        Ok(bracket) => bracket,
        Err(RootError::NoConvergence) => return Err(unreachable()),
        Err(e) => return Err(numerics(e.to_string())),
    };
    let (u_a, u_b) = (s_a.ln().clamp(u_lo, u_hi), s_b.ln().clamp(u_lo, u_hi));
    let u = brent(g, u_a, u_b, U_TOL).map_err(|e| numerics(e.to_string()))?;
    // A root where the matched value no longer moves with the parameter is the family's limit, not a fit.
    let (u_minus, u_plus) = ((u - SLOPE_STEP).max(u_lo), (u + SLOPE_STEP).min(u_hi));
    let slope = (g(u_plus) - g(u_minus)) / (u_plus - u_minus);
    if slope.is_nan() || slope.abs() < MIN_SLOPE {
        return Err(unreachable());
    }
    Ok(domain.x(u))
}

/// Minimizes l2_projected(fit(x), target) over the domain.
fn minimize_l2(problem: &FitProblem) -> Result<f64, FitError> {
    let domain = problem.domain;
    let (u_lo, u_hi) = domain.u_bounds();
    // −L2², which golden_section_max maximizes.
    let score = |u: f64| problem.l2(u).map(|v| -v * v);
    // Start from the peak fit where there is one: the L2 optimum is usually close to it.
    let u_start = match solve_match(problem, By::Peak) {
        Ok(x) if x > 0.0 || !domain.log => domain.u(x),
        _ => U_START,
    };
    let step = BRACKET_FACTOR.ln();
    let (mut a, mut b) = ((u_start - step).max(u_lo), u_start);
    let (mut fa, mut fb) = (score(a)?, score(b)?);
    if fa > fb {
        (a, b, fa, fb) = (b, a, fb, fa);
    }
    // Walk downhill (increasing score) from b, away from a, with growing steps until the score drops.
    let direction = if b >= a { 1.0 } else { -1.0 };
    let mut width = step;
    let u = loop {
        let c = (b + direction * width).clamp(u_lo, u_hi);
        let fc = score(c)?;
        if fc < fb || c == b {
            let ((lo, f_lo), (hi, f_hi)) = if a < c {
                ((a, fa), (c, fc))
            } else {
                ((c, fc), (a, fa))
            };
            let best = golden_section_max(score, (lo, f_lo), (hi, f_hi), L2_U_TOL)?;
            break if fb > best.value { b } else { best.theta };
        }
        (a, fa, b, fb) = (b, fb, c, fc);
        width *= GROWTH;
    };
    check_l2_minimum(problem, u)?;
    Ok(domain.x(u))
}

/// Refuses an L2 minimum at u that is on the domain bound, or where l2_projected no longer moves with
/// the parameter (rounding noise along the family's limit): neither is a fit.
fn check_l2_minimum(problem: &FitProblem, u: f64) -> Result<(), FitError> {
    let key = problem.key();
    let domain = problem.domain;
    let (u_lo, u_hi) = domain.u_bounds();
    let (u_minus, u_plus) = ((u - SLOPE_STEP).max(u_lo), (u + SLOPE_STEP).min(u_hi));
    let rise = problem.l2(u_minus)?.max(problem.l2(u_plus)?) - problem.l2(u)?;
    if u <= u_lo || u >= u_hi || rise / (SLOPE_STEP * problem.target.eval(0.0)) < MIN_SLOPE {
        return Err(FitError::new(
            Subject::Target,
            key,
            format!(
                "{} cannot reach the target: l2_projected keeps decreasing towards the family's limit (got {key} = {:?}, expected a minimum inside {})",
                problem.family.name(),
                domain.x(u),
                domain.describe()
            ),
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The `family` NDF of `params`.
    fn target(family: Family, params: &[f64]) -> Curve {
        Curve::Ndf(family.build(params).unwrap())
    }

    /// The L2 fit of every parameter of `family` to `target`.
    fn all_free(target: &Curve, family: Family) -> Result<Fit, FitError> {
        fit(target, family, &[], By::L2)
    }

    #[test]
    fn peak_and_max_need_one_free_parameter_and_l2_fits_them_all() {
        for by in [By::Peak, By::Max] {
            let e = FitSpec::new(Family::Abc, &[], by).unwrap_err();
            assert_eq!(
                (e.subject, e.key.as_str()),
                (Subject::Fixed, "alpha_abc1, alpha_abc2")
            );
            let needle = format!("--by {} matches one number", by.name());
            assert!(e.message.contains(&needle), "{e}");
        }
        let spec = FitSpec::new(Family::Gtr, &[], By::L2).unwrap();
        assert_eq!(spec.free, [0, 1]);
    }

    #[test]
    fn abc_with_both_parameters_free_beats_the_one_parameter_optimum_for_ggx() {
        let ggx = target(Family::TrowbridgeReitz, &[0.3]);
        let one = fit(&ggx, Family::Abc, &[("alpha_abc2".into(), 1.75)], By::L2).unwrap();
        let both = all_free(&ggx, Family::Abc).unwrap();
        assert!((one.residual - 0.014279685).abs() < 1e-9, "{one:?}");
        assert!(both.residual < one.residual * 0.9, "{both:?}");
        let keys: Vec<&str> = both.free.iter().map(|f| f.0).collect();
        assert_eq!(keys, ["alpha_abc1", "alpha_abc2"]);
        // The residual is what `compare` reports for the fitted curve.
        let compared = metrics::compare(&both.curve, &ggx, metrics::ThetaRange::FULL).unwrap();
        assert_eq!(compared.l2_projected, both.residual);
    }

    #[test]
    fn joint_fits_recover_a_target_their_family_holds() {
        // GTR with γ = 2 is GGX; SGD with a₂ = 0 is Beckmann with α_b² = a₁.
        let gtr = all_free(&target(Family::TrowbridgeReitz, &[0.3]), Family::Gtr).unwrap();
        let [(_, alpha), (_, gamma)] = gtr.free[..] else {
            panic!("{gtr:?}")
        };
        assert!((alpha / 0.3 - 1.0).abs() < 1e-8 && (gamma / 2.0 - 1.0).abs() < 1e-8);
        let sgd = all_free(&target(Family::Beckmann, &[0.3]), Family::Sgd).unwrap();
        let [(_, a1), (_, a2)] = sgd.free[..] else {
            panic!("{sgd:?}")
        };
        assert!((a1 / 0.09 - 1.0).abs() < 1e-8 && a2.abs() < 1e-8, "{sgd:?}");
    }

    #[test]
    fn a_valley_of_equal_distances_is_an_error_naming_every_free_parameter() {
        // GGX α = 1 is uniform, as GTR α = 1 is for every γ.
        let uniform = target(Family::TrowbridgeReitz, &[1.0]);
        let e = all_free(&uniform, Family::Gtr).unwrap_err();
        assert_eq!(
            (e.subject, e.key.as_str()),
            (Subject::Target, "alpha_gtr, gamma_gtr")
        );
        assert!(e.message.contains("stays flat along a valley"), "{e}");
        // Beckmann lies beyond GTR's γ bound: the minimum is on it.
        let e = all_free(&target(Family::Beckmann, &[0.3]), Family::Gtr).unwrap_err();
        assert_eq!(e.key, "gamma_gtr", "{e}");
    }

    #[test]
    fn fit_all_keeps_the_targets_order_and_equals_fitting_one_by_one() {
        let spec = FitSpec::new(Family::Abc, &[("alpha_abc2".into(), 1.75)], By::Peak).unwrap();
        let targets: Vec<Curve> = [0.7, 0.1, 0.4, 1.0]
            .iter()
            .map(|&a| target(Family::TrowbridgeReitz, &[a]))
            .collect();
        let all = spec.fit_all(&targets);
        for (target, result) in targets.iter().zip(&all) {
            assert_eq!(result, &spec.fit_uncached(target));
        }
    }

    #[test]
    fn starts_are_three_shapes_each_peak_matched() {
        let ggx = target(Family::TrowbridgeReitz, &[0.3]);
        let spec = FitSpec::new(Family::Abc, &[], By::L2).unwrap();
        let starts = spec.starts(&ggx);
        let shapes: Vec<f64> = starts.iter().map(|u| u[1].exp()).collect();
        for (shape, expected) in shapes.iter().zip([0.4375, 1.75, 7.0]) {
            assert!((shape / expected - 1.0).abs() < 1e-14, "{shapes:?}");
        }
        for u in &starts {
            let start = target(Family::Abc, &spec.values_at(u));
            assert!(
                (start.eval(0.0) / ggx.eval(0.0) - 1.0).abs() < 1e-12,
                "{u:?}"
            );
        }
    }
}
