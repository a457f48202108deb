//! Gulbrandsen's artist-friendly parameterization of a complex index: reflectivity r and edge tint
//! g, both in [0, 1], mapped to (η, κ) and back.
//!
//! Source: O. Gulbrandsen, "Artist Friendly Metallic Fresnel", JCGT 3(4), 2014; docs/maths.md "Fresnel".
//! With n_min = (1 − r)/(1 + r) and n_max = (1 + √r)/(1 − √r):
//!   η = g n_min + (1 − g) n_max,   κ² = (r (1 + η)² − (η − 1)²)/(1 − r)   (0 when g ≤ 0),
//! and the inverse r = ((η − 1)² + κ²)/((η + 1)² + κ²), g = (n_max − η)/(n_max − n_min).
//! The notebook's remap ḡ = 1 − (1 − g)³ spreads the edge tint more evenly.
//!
//! Domain: r ∈ [0, 1) (r = 1 is singular: n_max = ∞), g ∈ [0, 1]; validation lives in `Ior`.
//! The basis training set calls the forward map with r slightly above 1 and g = 1 (docs/maths.md step 2),
//! where the n_max term has weight 0 and the result is finite.
//!
//! Stable forms and why:
//! - n_max = (1 + √r)²/(1 − r): 1 − √r cancels as r → 1, while 1 − r is exact for r ≥ 1/2.
//! - n_max − n_min = 2√r (1 + √r)²/(1 − r²): the difference of the two forms cancels for small r.
//! - ḡ = g (3 − 3g + g²), the expansion of 1 − (1 − g)³, which cancels for small g.
//! - [`to_eta_kappa`] keeps the notebook's operation order (it feeds the basis training set bit for
//!   bit): κ² is clamped at 0 (it cancels to ±ε as g → 0), and r = 0 maps to (1, 0) for every g, as
//!   in the notebook (the formula would round η to 1 ± ulp).
//! - [`index`], the map every curve uses, carries η − 1 rather than η (for small r, η = 1 + O(√r)
//!   rounds η − 1 away) and κ² in a form with no cancellation at all. With n_min − 1 = −2r/(1 + r)
//!   and n_max − 1 = 2√r (1 + √r)/(1 − r) (1 − r rather than 1 − √r, as for n_max):
//!   η − 1 = −2gr/(1 + r) + 2(1 − g)√r (1 + √r)/(1 − r),
//!   κ² = 4gr [g/(1 + r)² + 2(1 − g)(1 + √r)²/((1 + r)(1 − r)²)],
//!   the second from r(1 + η)² − (η − 1)² = (√r(1 + η) − (η − 1))(√r(1 + η) + (η − 1)), whose
//!   factors are 2g√r(1 + √r)/(1 + r) and 2√r [g(1 − √r)/(1 + r) + 2(1 − g)(1 + √r)/(1 − r)].

use super::exact::Index;

/// Gulbrandsen's forward map (r, g) → (η, κ) of docs/maths.md in the notebook's operation order, κ²
/// clamped at 0; (1, 0) at r = 0. The basis training set's rounding; curves use [`index`].
///
/// Meaningful for r ∈ [0, 1), g ∈ [0, 1] (and r slightly above 1 with g = 1); not validated here.
pub fn to_eta_kappa(r: f64, g: f64) -> (f64, f64) {
    if r == 0.0 {
        return (1.0, 0.0);
    }
    let eta = eta(r, g);
    let kappa2 = if g <= 0.0 {
        0.0
    } else {
        (r * (1.0 + eta) * (1.0 + eta) - (eta - 1.0) * (eta - 1.0)) / (1.0 - r)
    };
    (eta, kappa2.max(0.0).sqrt())
}

/// η = g n_min + (1 − g) n_max with n_min = (1 − r)/(1 + r) and n_max = (1 + √r)²/(1 − r): a sum of
/// two non-negative terms (for r ≤ 1), accurate to a few ulps of η.
fn eta(r: f64, g: f64) -> f64 {
    let sqrt_r = r.sqrt();
    let eta_min = (1.0 - r) / (1.0 + r);
    let eta_max = (1.0 + sqrt_r) * (1.0 + sqrt_r) / (1.0 - r);
    g * eta_min + (1.0 - g) * eta_max
}

/// Gulbrandsen's forward map (r, g) → η̃ with η, η − 1 and κ in their cancellation-free forms (module
/// documentation): η − 1 = −2gr/(1 + r) + 2(1 − g)√r (1 + √r)/(1 − r),
/// κ = 2√(gr) √(g/(1 + r)² + 2(1 − g)(1 + √r)²/((1 + r)(1 − r)²)), and η itself as the notebook
/// forms it (1 + (η − 1) would lose a small η = n_min for g ≈ 1 and r → 1). η̃ = 1 exactly at r = 0.
///
/// Accurate to a few ulps of η, η − 1 and κ for r ∈ [0, 1), g ∈ [0, 1]; not validated here.
pub fn index(r: f64, g: f64) -> Index {
    if r == 0.0 {
        return Index::new(1.0, 0.0);
    }
    let sqrt_r = r.sqrt();
    // (1 + √r)/(1 − r) = 1/(1 − √r), with 1 − r exact for r ≥ 1/2.
    let q = (1.0 + sqrt_r) / (1.0 - r);
    let eta_minus_one = -2.0 * g * r / (1.0 + r) + 2.0 * (1.0 - g) * sqrt_r * q;
    let kappa = 2.0
        * (g * r).sqrt()
        * (g / ((1.0 + r) * (1.0 + r)) + 2.0 * (1.0 - g) * q * q / (1.0 + r)).sqrt();
    Index {
        eta: eta(r, g),
        eta_minus_one,
        kappa,
    }
}

/// Gulbrandsen's inverse map (η, κ) → (r, g): r = ((η − 1)² + κ²)/((η + 1)² + κ²),
/// g = (n_max − η)/(n_max − n_min).
///
/// Exact inverse of [`to_eta_kappa`] for r ∈ (0, 1); g lies outside [0, 1] when (η, κ) is not in
/// the image of the forward map. At r = 0 (η̃ = 1) every g maps to the same index; 0 is returned.
pub fn from_eta_kappa(eta: f64, kappa: f64) -> (f64, f64) {
    let kappa2 = kappa * kappa;
    let r = ((eta - 1.0) * (eta - 1.0) + kappa2) / ((eta + 1.0) * (eta + 1.0) + kappa2);
    if r == 0.0 {
        return (0.0, 0.0);
    }
    let sqrt_r = r.sqrt();
    let eta_max = (1.0 + sqrt_r) * (1.0 + sqrt_r) / (1.0 - r);
    let eta_spread = 2.0 * sqrt_r * (1.0 + sqrt_r) * (1.0 + sqrt_r) / ((1.0 - r) * (1.0 + r));
    (r, (eta_max - eta) / eta_spread)
}

/// The notebook's edge-tint remap ḡ = 1 − (1 − g)³, evaluated as g (3 − 3g + g²).
///
/// Maps [0, 1] onto [0, 1] monotonically, with ḡ(0) = 0 and ḡ(1) = 1.
pub fn remap_edge_tint(g: f64) -> f64 {
    g * (3.0 - 3.0 * g + g * g)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn endpoints_of_the_edge_tint() {
        // g = 0 is the dielectric of reflectivity r, g = 1 the conductor with η = n_min.
        let (eta, kappa) = to_eta_kappa(0.04, 0.0);
        assert!((eta - 1.5).abs() < 1e-15 && kappa == 0.0, "{eta} {kappa}");
        let (eta, _) = to_eta_kappa(0.04, 1.0);
        assert!((eta - 0.96 / 1.04).abs() < 1e-15, "{eta}");
        assert_eq!(to_eta_kappa(0.0, 0.7), (1.0, 0.0));
        assert_eq!(remap_edge_tint(0.0), 0.0);
        assert_eq!(remap_edge_tint(1.0), 1.0);
    }

    #[test]
    fn index_agrees_with_the_notebook_map() {
        for r in [1e-12, 1e-6, 0.04, 0.5, 0.9] {
            for g in [0.0, 0.3, 0.7, 1.0] {
                let (eta, kappa) = to_eta_kappa(r, g);
                let index = index(r, g);
                // The notebook map's η carries an absolute rounding of ~ε; its κ² cancels as g → 0.
                assert!(
                    (index.eta - eta).abs() <= 4.0 * f64::EPSILON * eta,
                    "{r} {g}"
                );
                assert!(
                    (index.kappa - kappa).abs() <= 1e-7 * index.kappa.max(1e-300),
                    "{r} {g}: {index:?} vs {kappa}"
                );
                let eta_minus_one = index.eta - 1.0;
                assert!(
                    (index.eta_minus_one - eta_minus_one).abs() <= 4.0 * f64::EPSILON * index.eta,
                    "{r} {g}"
                );
            }
        }
        assert_eq!(index(0.0, 0.4), Index::new(1.0, 0.0));
    }
}
