//! Fitting the one free parameter of an NDF family to a target curve (`ndfplot fit`, scene `{"fit": …}`):
//! `peak` equates the values at the normal, D(0) — the notebook's manual method; `max` equates the maxima
//! over θ; `l2` minimizes `l2_projected` (CONTRACTS.md, MATH.md "Parameter equivalences and fits").
//!
//! The free parameter is searched within the domain its family states ([`Param`]), on a log scale for
//! parameters bounded below by 0 or more (ln x) and a linear one for the others (SGD's a₂). Peak and max fits bracket the root of a log-like
//! mismatch by geometric expansion and solve it with Brent's method ([`crate::math::roots`]); L2 fits
//! bracket the minimum by a downhill walk and refine it by golden-section search
//! ([`crate::metrics::golden_section_max`]). Results are cached per process. No I/O.

pub use crate::curve::By;
use crate::curve::Curve;
use crate::domain::{DomainError, Param};
use crate::math::roots::{RootError, brent, expand_bracket_log};
use crate::metrics::{self, MetricError, golden_section_max, lobe_width, maximum};
use crate::ndf::Family;
use crate::problem::suggestion;
use std::collections::HashMap;
use std::fmt;
use std::sync::{Mutex, OnceLock};

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
/// natural range) and x = 0 for a linear one (SGD's a₂).
const U_START: f64 = 0.0;

/// Growth of the steps of the downhill walk that brackets an L2 minimum: the golden ratio φ, the classic
/// choice of bracketing before a golden-section search.
const GROWTH: f64 = 1.618_033_988_749_895;

/// Golden-section tolerance in u for L2 fits: the minimum of a smooth L2 distance is located only to
/// ~√(1e-12) ≈ 1e-6 relative by quadrature values accurate to `QUAD_REL_TOL`, so 1e-9 resolves all there is.
const L2_U_TOL: f64 = 1e-9;

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
    /// The free parameter's name.
    pub key: &'static str,
    /// Its fitted value.
    pub value: f64,
    /// The residual named by [`By::residual_name`].
    pub residual: f64,
}

/// The search interval of a free parameter: [lo, hi] within its family's stated domain, searched in
/// u = ln x (`log`) or u = x.
#[derive(Debug, Clone, Copy)]
struct SearchDomain {
    param: &'static Param,
    lo: f64,
    hi: f64,
    log: bool,
}

impl SearchDomain {
    /// The domain of parameter `index` of `family`. A log search starts at the smallest normal double
    /// when the domain reaches down to 0 (Phong's α_p ≥ 0, whose 0 is checked exactly; ABC's a > 0).
    fn of(family: Family, index: usize) -> SearchDomain {
        let param = &family.params()[index];
        let log = param.min.value >= 0.0;
        let lo = if log {
            param.min.value.max(f64::MIN_POSITIVE)
        } else {
            param.min.value
        };
        SearchDomain {
            param,
            lo,
            hi: param.max.value,
            log,
        }
    }

    /// Whether the domain holds 0, which a log search cannot reach (Phong's uniform α_p = 0).
    fn holds_zero(self) -> bool {
        self.log && self.param.contains(0.0)
    }

    /// The searched u interval.
    fn u_bounds(self) -> (f64, f64) {
        if self.log {
            (self.lo.ln(), self.hi.ln())
        } else {
            (self.lo, self.hi)
        }
    }

    /// x of u, clamped into the searched interval.
    fn x(self, u: f64) -> f64 {
        if self.log {
            u.exp().clamp(self.lo, self.hi)
        } else {
            u.clamp(self.lo, self.hi)
        }
    }

    /// u of x.
    fn u(self, x: f64) -> f64 {
        if self.log { x.ln() } else { x }
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

/// Splits `fixed` (key, value) pairs against the family's parameters: the free index and the fixed values
/// in parameter order.
fn free_parameter(family: Family, fixed: &[(String, f64)]) -> Result<(usize, Vec<f64>), FitError> {
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
    let free: Vec<usize> = (0..names.len())
        .filter(|&i| !fixed.iter().any(|(k, _)| k == names[i]))
        .collect();
    match free[..] {
        [index] => {
            let values = names
                .iter()
                .filter_map(|n| fixed.iter().find(|(k, _)| k == n).map(|&(_, v)| v))
                .collect();
            Ok((index, values))
        }
        [] => Err(FitError::new(
            Subject::Fixed,
            names.join(", "),
            format!(
                "no free parameter left for {} (got all of {} fixed, expected exactly one of them free)",
                family.name(),
                names.join(", ")
            ),
        )),
        _ => {
            let open: Vec<&str> = free.iter().map(|&i| names[i]).collect();
            Err(FitError::new(
                Subject::Fixed,
                open.join(", "),
                format!(
                    "{} has {} free parameters (got {} fixed, expected all but one fixed: add --fix for all but one of {})",
                    family.name(),
                    open.len(),
                    fixed.len(),
                    open.join(", ")
                ),
            ))
        }
    }
}

/// Fits the free parameter of `family` (the one not in `fixed`) to `target` by `by`. Results are cached per
/// process, keyed by the target's canonical JSON, the family, the fixed values and the method.
///
/// Errors: a fixed key the family lacks, fixed twice or out of domain, no or several free parameters (all
/// [`Subject::Fixed`]); a target that is not an NDF, or that the family cannot reach in its domain
/// ([`Subject::Target`]).
pub fn fit(
    target: &Curve,
    family: Family,
    fixed: &[(String, f64)],
    by: By,
) -> Result<Fit, FitError> {
    static CACHE: OnceLock<Mutex<HashMap<String, Result<Fit, FitError>>>> = OnceLock::new();
    let fixed_text: Vec<String> = fixed.iter().map(|(k, v)| format!("{k}={v:?}")).collect();
    let key = format!(
        "{}|{}|{}|{}",
        target.canonical_json(),
        family.name(),
        fixed_text.join(","),
        by.name()
    );
    let cache = CACHE.get_or_init(|| Mutex::new(HashMap::new()));
    if let Some(hit) = cache
        .lock()
        .expect("no panic while holding the lock")
        .get(&key)
    {
        return hit.clone();
    }
    let result = fit_uncached(target, family, fixed, by);
    cache
        .lock()
        .expect("no panic while holding the lock")
        .insert(key, result.clone());
    result
}

fn fit_uncached(
    target: &Curve,
    family: Family,
    fixed: &[(String, f64)],
    by: By,
) -> Result<Fit, FitError> {
    let model = target.model();
    if !matches!(target, Curve::Ndf(_)) {
        return Err(FitError::new(
            Subject::Target,
            model.key(),
            format!(
                "a fit needs an NDF target (got {} \"{}\", expected an ndf curve)",
                model.key(),
                model.name()
            ),
        ));
    }
    let (free, values) = free_parameter(family, fixed)?;
    let problem = FitProblem {
        family,
        free,
        fixed: values,
        target,
        domain: SearchDomain::of(family, free),
    };
    let probe = problem.domain.x(U_START);
    problem.curve(probe).map_err(|e| {
        FitError::new(
            Subject::Fixed,
            e.param,
            format!("out of domain (got {:?}, expected {})", e.value, e.expected),
        )
    })?;
    let metric_error = |e: MetricError| {
        FitError::new(
            Subject::Target,
            problem.key(),
            format!("cannot compute the fit: {e}"),
        )
    };
    let value = match by {
        By::Peak | By::Max => solve_match(&problem, by)?,
        By::L2 => minimize_l2(&problem)?,
    };
    let curve = problem
        .curve(value)
        .expect("the fitted value lies in the domain");
    let residual = match by {
        By::Peak | By::Max => {
            let (p, q) = (
                matched_value(&curve, by).map_err(metric_error)?,
                matched_value(target, by).map_err(metric_error)?,
            );
            metrics::relative_difference(p, q)
        }
        By::L2 => metrics::l2_projected(&curve, target).map_err(metric_error)?,
    };
    Ok(Fit {
        curve,
        key: problem.key(),
        value,
        residual,
    })
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
    let key = problem.key();
    let domain = problem.domain;
    let (u_lo, u_hi) = domain.u_bounds();
    let target_peak = problem.target.eval(0.0);
    let numerics = |e: MetricError| {
        FitError::new(Subject::Target, key, format!("cannot compute the fit: {e}"))
    };
    let l2 = |u: f64| -> Result<f64, FitError> {
        let curve = problem.curve_at_u(u);
        metrics::l2_projected_with(&curve, problem.target, curve.eval(0.0), target_peak)
            .map_err(numerics)
    };
    // −L2², which golden_section_max maximizes.
    let score = |u: f64| l2(u).map(|v| -v * v);
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
    // A minimum at the domain bound, or where l2_projected no longer moves with the parameter (rounding
    // noise along the family's limit), is not a fit.
    let (u_minus, u_plus) = ((u - SLOPE_STEP).max(u_lo), (u + SLOPE_STEP).min(u_hi));
    let rise = l2(u_minus)?.max(l2(u_plus)?) - l2(u)?;
    if u <= u_lo || u >= u_hi || rise / (SLOPE_STEP * target_peak) < MIN_SLOPE {
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
    Ok(domain.x(u))
}
