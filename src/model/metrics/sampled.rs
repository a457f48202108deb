//! `ndfplot compare` when a side is a sampled series (a renderer's or a measurement's values read from
//! a CSV file) rather than a curve: the same metrics, taken where the samples are.
//!
//! The nodes are the θ of the sampled side (when both sides are sampled, those of `a` inside `b`'s θ
//! span); a sampled side is read between its samples by linear interpolation in θ, the way the plot
//! draws it. No I/O.

use super::{
    Comparison, Extremum, MetricError, ThetaRange, l2_grid_nodes, log_ratio, peak_over,
    relative_difference, scaled_norm,
};
use crate::model::curve::Curve;
use std::f64::consts::PI;

/// Values at θ, sorted by θ: one side of a comparison that was measured rather than computed.
#[derive(Debug, Clone, PartialEq)]
pub struct Samples {
    theta: Vec<f64>,
    value: Vec<f64>,
}

impl Samples {
    /// Pairs `theta[i]` (radians) with `value[i]` and sorts them by θ (stable, so repeated θ keep file
    /// order). `None` when the lists are empty or of different lengths.
    pub fn new(theta: &[f64], value: &[f64]) -> Option<Samples> {
        if theta.is_empty() || theta.len() != value.len() {
            return None;
        }
        let mut pairs: Vec<(f64, f64)> = theta.iter().copied().zip(value.iter().copied()).collect();
        pairs.sort_by(|p, q| p.0.total_cmp(&q.0));
        Some(Samples {
            theta: pairs.iter().map(|p| p.0).collect(),
            value: pairs.iter().map(|p| p.1).collect(),
        })
    }

    /// No samples: a side with nothing to compare, which shares no θ with any other.
    pub fn empty() -> Samples {
        Samples {
            theta: Vec::new(),
            value: Vec::new(),
        }
    }

    /// The θ interval the samples cover.
    pub fn span(&self) -> (f64, f64) {
        (self.theta[0], self.theta[self.theta.len() - 1])
    }

    /// The value at θ within [`Samples::span`], linear in θ between neighbouring samples (at a repeated
    /// θ, the first of its samples).
    pub fn at(&self, theta: f64) -> f64 {
        let i = self.theta.partition_point(|&t| t < theta);
        if i == 0 {
            return self.value[0];
        }
        if i == self.theta.len() {
            return self.value[i - 1];
        }
        let (t0, t1) = (self.theta[i - 1], self.theta[i]);
        if t1 == theta {
            return self.value[i];
        }
        let w = (theta - t0) / (t1 - t0);
        self.value[i - 1] + w * (self.value[i] - self.value[i - 1])
    }

    /// The largest sample inside `range` and its θ (the first one on ties); `None` when no sample is
    /// inside it.
    pub fn peak_over(&self, range: ThetaRange) -> Option<Extremum> {
        (0..self.value.len())
            .filter(|&i| range.contains(self.theta[i]))
            .fold(None, |best: Option<usize>, i| match best {
                Some(b) if self.value[b] >= self.value[i] => Some(b),
                _ => Some(i),
            })
            .map(|i| Extremum {
                theta: self.theta[i],
                value: self.value[i],
            })
    }
}

/// One side of a comparison.
#[derive(Debug, Clone, PartialEq)]
pub enum Operand {
    /// An analytic curve, defined at every θ.
    Curve(Curve),
    /// Measured values, defined on their θ span.
    Samples(Samples),
}

impl Operand {
    /// The value at θ: the curve's, or the samples' by [`Samples::at`].
    pub fn at(&self, theta: f64) -> f64 {
        match self {
            Operand::Curve(curve) => curve.eval(theta),
            Operand::Samples(samples) => samples.at(theta),
        }
    }

    fn peak(&self, range: ThetaRange) -> Result<Extremum, MetricError> {
        match self {
            Operand::Curve(curve) => peak_over(curve, range),
            Operand::Samples(samples) => samples.peak_over(range).ok_or(MetricError::OutsideRange),
        }
    }
}

/// Where a side is sampled, the θ at which `a` and `b` are compared (and a figure draws their
/// difference), increasing: the sampled side's θ inside `range`, or, when both are sampled, `a`'s θ
/// inside `range` and `b`'s span. Empty for two curves (they are compared at every θ). No sample
/// inside `range` is [`MetricError::OutsideRange`]; two series with no node in common,
/// [`MetricError::Disjoint`].
pub fn nodes(a: &Operand, b: &Operand, range: ThetaRange) -> Result<Vec<f64>, MetricError> {
    let in_range = |s: &Samples| -> Result<Vec<f64>, MetricError> {
        let nodes: Vec<f64> = s
            .theta
            .iter()
            .copied()
            .filter(|&t| range.contains(t))
            .collect();
        if nodes.is_empty() {
            Err(MetricError::OutsideRange)
        } else {
            Ok(nodes)
        }
    };
    let nodes: Vec<f64> = match (a, b) {
        (Operand::Curve(_), Operand::Curve(_)) => return Ok(Vec::new()),
        (Operand::Samples(s), Operand::Curve(_)) | (Operand::Curve(_), Operand::Samples(s)) => {
            in_range(s)?
        }
        (Operand::Samples(sa), Operand::Samples(sb)) => {
            in_range(sb)?;
            let (lo, hi) = sb.span();
            in_range(sa)?
                .into_iter()
                .filter(|t| (lo..=hi).contains(t))
                .collect()
        }
    };
    if nodes.is_empty() {
        return Err(MetricError::Disjoint);
    }
    Ok(nodes)
}

/// Every metric of `a` against `b` over `range`: [`super::compare`] for two curves; otherwise, over the
/// nodes (the sampled side's θ inside `range`, or `a`'s θ inside `range` and `b`'s span when both are
/// sampled): `max_abs`, `max_rel`, `max_log_ratio` and their θ at the nodes; `l2_projected` =
/// sqrt(2π ∫ (a − b)² sin θ cos θ dθ) by the trapezoidal rule over the nodes; `l2_grid` over the c-grid
/// nodes θ_i = arccos c_i inside the nodes' span; each peak the curve's maximum over `range` or the
/// largest sample inside it. No series sample inside `range` is [`MetricError::OutsideRange`]; two
/// series with no node in common, [`MetricError::Disjoint`].
pub fn compare_operands(
    a: &Operand,
    b: &Operand,
    range: ThetaRange,
) -> Result<Comparison, MetricError> {
    if let (Operand::Curve(a), Operand::Curve(b)) = (a, b) {
        return super::compare(a, b, range);
    }
    let nodes = nodes(a, b, range)?;
    let difference = |theta: f64| {
        let (va, vb) = (a.at(theta), b.at(theta));
        if va.is_finite() && vb.is_finite() {
            Ok((va, vb))
        } else {
            Err(MetricError::NonFinite { theta })
        }
    };
    let values: Vec<(f64, f64)> = nodes
        .iter()
        .map(|&t| difference(t))
        .collect::<Result<_, _>>()?;
    let largest = |metric: &dyn Fn(f64, f64) -> f64| {
        (0..nodes.len()).fold(
            Extremum {
                theta: nodes[0],
                value: 0.0,
            },
            |best, i| {
                let v = metric(values[i].0, values[i].1);
                if v > best.value {
                    Extremum {
                        theta: nodes[i],
                        value: v,
                    }
                } else {
                    best
                }
            },
        )
    };
    let abs = largest(&|p, q| (p - q).abs());
    let rel = largest(&relative_difference);
    let max_log_ratio = (0..nodes.len())
        .filter_map(|i| log_ratio(values[i].0, values[i].1).map(|v| (i, v)))
        .fold(None, |best: Option<Extremum>, (i, v)| match best {
            Some(b) if b.value >= v => Some(b),
            _ => Some(Extremum {
                theta: nodes[i],
                value: v,
            }),
        });
    // The trapezoidal rule over the nodes: node i weighs (θ_{i+1} − θ_{i−1})/2 · sin θ cos θ.
    let differences: Vec<f64> = values.iter().map(|(p, q)| p - q).collect();
    let last = nodes.len() - 1;
    let l2_projected = scaled_norm(&differences, |d, i| {
        let span = nodes[(i + 1).min(last)] - nodes[i.saturating_sub(1)];
        2.0 * PI * 0.5 * span * d * d * nodes[i].sin() * nodes[i].cos()
    });
    let (lo, hi) = (nodes[0], nodes[last]);
    let grid = l2_grid_nodes(range)
        .filter(|t| (lo..=hi).contains(t))
        .map(|theta| difference(theta).map(|(va, vb)| va - vb))
        .collect::<Result<Vec<f64>, _>>()?;
    Ok(Comparison {
        range,
        max_abs: abs.value,
        max_abs_theta: abs.theta,
        max_rel: rel.value,
        max_rel_theta: rel.theta,
        max_log_ratio,
        l2_projected,
        l2_grid: scaled_norm(&grid, |d, _| d * d),
        a_peak: a.peak(range)?,
        b_peak: b.peak(range)?,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::grid::linspace;
    use crate::model::ndf::Family;
    use std::f64::consts::FRAC_PI_2;

    fn phong(alpha: f64) -> Curve {
        Curve::Ndf(Family::Phong.build(&[alpha]).unwrap())
    }

    fn sampled(curve: &Curve, n: usize, scale: f64) -> Samples {
        let theta = linspace(0.0, FRAC_PI_2, n);
        let value: Vec<f64> = theta.iter().map(|&t| scale * curve.eval(t)).collect();
        Samples::new(&theta, &value).unwrap()
    }

    #[test]
    fn samples_interpolate_linearly_and_sort_by_theta() {
        let s = Samples::new(&[0.2, 0.0, 0.1], &[3.0, 1.0, 2.0]).unwrap();
        assert_eq!(s.span(), (0.0, 0.2));
        assert_eq!(s.at(0.05), 1.5);
        assert_eq!(s.at(0.1), 2.0);
        assert_eq!(
            s.peak_over(ThetaRange::FULL).unwrap(),
            Extremum {
                theta: 0.2,
                value: 3.0
            }
        );
        assert!(Samples::new(&[0.0], &[]).is_none());
    }

    #[test]
    fn a_curve_against_its_own_samples_differs_by_nothing() {
        let curve = phong(20.0);
        let c = compare_operands(
            &Operand::Samples(sampled(&curve, 401, 1.0)),
            &Operand::Curve(curve.clone()),
            ThetaRange::FULL,
        )
        .unwrap();
        assert_eq!((c.max_abs, c.max_rel, c.l2_projected), (0.0, 0.0, 0.0));
        assert_eq!(
            c.a_peak,
            Extremum {
                theta: 0.0,
                value: curve.eval(0.0)
            }
        );
    }

    #[test]
    fn a_scaled_copy_gives_the_scale_in_every_metric() {
        // b = 1.01 a: |a − b| = 0.01 a, so max_abs = 0.01 a(0), max_rel = 0.01/1.01, and
        // l2_projected = 0.01 sqrt(2π ∫ a² sin cos) — for Phong 20, (22/2π)² 2π/42 exactly.
        let curve = phong(20.0);
        let c = compare_operands(
            &Operand::Curve(curve.clone()),
            &Operand::Samples(sampled(&curve, 20001, 1.01)),
            ThetaRange::FULL,
        )
        .unwrap();
        assert!((c.max_abs - 0.01 * curve.eval(0.0)).abs() < 1e-12);
        assert!((c.max_rel - 0.01 / 1.01).abs() < 1e-12);
        let exact = 0.01 * (22.0f64 * 22.0 / (4.0 * PI * PI) * 2.0 * PI / 42.0).sqrt();
        assert!(
            (c.l2_projected / exact - 1.0).abs() < 1e-5,
            "{}",
            c.l2_projected
        );
    }

    #[test]
    fn two_sampled_sides_meet_on_the_overlap_only() {
        let a = Samples::new(&[0.0, 0.5, 1.0, 1.5], &[1.0, 1.0, 1.0, 1.0]).unwrap();
        let b = Samples::new(&[0.4, 1.2], &[2.0, 4.0]).unwrap();
        let c =
            compare_operands(&Operand::Samples(a), &Operand::Samples(b), ThetaRange::FULL).unwrap();
        // Nodes 0.5 and 1.0, where b = 2.25 and 3.5.
        assert_eq!((c.max_abs, c.max_abs_theta), (2.5, 1.0));
        let far = Samples::new(&[1.3], &[1.0]).unwrap();
        let near = Samples::new(&[0.0, 0.1], &[1.0, 1.0]).unwrap();
        assert_eq!(
            compare_operands(
                &Operand::Samples(near),
                &Operand::Samples(far),
                ThetaRange::FULL
            ),
            Err(MetricError::Disjoint)
        );
    }

    #[test]
    fn a_theta_range_keeps_the_samples_inside_it() {
        let s = Samples::new(&[0.0, 0.5, 1.0, 1.5], &[4.0, 2.0, 1.0, 0.0]).unwrap();
        let flat = Samples::new(&[0.0, 0.8, 1.5], &[1.0, 1.0, 1.0]).unwrap();
        let range = ThetaRange::new(0.4, 1.2).unwrap();
        let c =
            compare_operands(&Operand::Samples(s.clone()), &Operand::Samples(flat), range).unwrap();
        // Nodes 0.5 and 1.0: a = 2 and 1 against b = 1.
        assert_eq!((c.max_abs, c.max_abs_theta), (1.0, 0.5));
        assert_eq!(
            c.max_log_ratio,
            Some(Extremum {
                theta: 0.5,
                value: 2f64.ln()
            })
        );
        assert_eq!(
            c.a_peak,
            Extremum {
                theta: 0.5,
                value: 2.0
            }
        );
        let outside = ThetaRange::new(1.51, FRAC_PI_2).unwrap();
        assert_eq!(
            compare_operands(&Operand::Samples(s), &Operand::Curve(phong(1.0)), outside),
            Err(MetricError::OutsideRange)
        );
    }
}
