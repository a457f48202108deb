//! Exact Fresnel reflectance of a smooth interface, from a medium of index 1 onto η̃ = η + iκ.
//!
//! Formula (docs/maths.md "Fresnel", the normative form): with c = cos θ and the principal complex root
//! w = √(η̃² − 1 + c²) = √(η̃² − sin²θ) (Re w ≥ 0; w = η̃ cos θ_t),
//! r_s = (c − w)/(c + w),   r_p = (η̃² c − w)/(η̃² c + w),   F = (|r_s|² + |r_p|²)/2.
//!
//! Domain: any (η, κ) for which η̃² neither overflows nor underflows (see `Ior` in `mod.rs`); the
//! basis training set also calls it with η < 0 (docs/maths.md step 2), where the principal root is what
//! makes F₀ = 0.99998. Behaviour: F(θ = 0) = ((η − 1)² + κ²)/((η + 1)² + κ²), F → 1 at θ → π/2.
//!
//! Stable forms and why:
//! - The index is an [`Index`]: η together with η − 1, so that a = η̃² − 1 = (η̃ − 1)(η̃ + 1) is
//!   formed from η − 1 directly. For an index given as η, η − 1 is exact for η ∈ [0.5, 2]; an index
//!   given by Gulbrandsen's (r, g) carries η − 1 from its own closed form, since η itself rounds
//!   η − 1 ~ √r away for small r.
//! - Both numerators cancel near η̃ = 1. Multiplying through by the conjugate denominators:
//!   r_s = −a/(c + w)², r_p = a (η̃² c² − sin²θ)/(η̃² c + w)² (η̃² c² − sin²θ is docs/maths.md's
//!   c²(η̃² + 1) − 1). These are used everywhere: the denominators never cancel (Re w ≥ 0, c ≥ 0),
//!   so they are at least as accurate as the raw ratios. |a| = |η̃ − 1| |η̃ + 1|, a product of norms.
//! - The angle is an [`Incidence`]: c = cos θ and sin²θ, each accurate relative to itself. From θ,
//!   sin²θ = (sin θ)²; from a c given exactly (the basis grid), (1 − c)(1 + c). Forming sin²θ from
//!   a rounded cos θ keeps only ε absolute near θ = 0, where a tiny η̃² − sin²θ needs it relative.
//! - w² = η̃² − sin²θ = c² + a is a sum of two terms either way: c² + a loses nothing when η̃ ≈ 1
//!   (η̃² − sin²θ would subtract two numbers near 1 at grazing incidence and leave the rounding of
//!   η̃² in w² ≈ η̃² − 1), and η̃² − sin²θ loses nothing when η̃ is tiny (c² + a would lose η̃²
//!   against 1 near normal incidence). The split with the smaller terms,
//!   |a| + c² against |η̃²| + sin²θ, is taken: its rounding is ε (|a| + c²) or ε (|η̃²| + sin²θ),
//!   no more than what a relative rounding of c or η̃ alone does to w². Near a critical angle
//!   (κ = 0, η < 1, w → 0) F is ill-conditioned in θ itself: its relative error grows like
//!   ε max(c, sin θ)/|w| there, whatever the evaluation.
//! - Only moduli are formed, each as a ratio of hypot-based norms: no complex division, and no
//!   overflow for |η̃| up to 1e150.
//! - η̃ = 1 exactly gives F ≡ 0 (the conjugate form is 0/0 at c = 0): a guard.
//! - κ = 0 with η² ≤ sin²θ is total internal reflection: w is purely imaginary, r_s and r_p are
//!   ratios of complex conjugates and F = 1 exactly: a guard.
//! - Rounding can put F an ulp above 1 near grazing incidence; the result is clamped to ≤ 1.
//! - 1 − F is also offered without cancellation (`one_minus_reflectance`): the basis training set
//!   divides by 1 − F₀ = 2e-5 for one material, which would amplify the rounding of F 5e4-fold.
//! - The normalized curve v = (F − F₀)/(1 − F₀) (`normalized_reflectance`) vanishes like θ⁴ at
//!   normal incidence (the θ² terms of |r_s|² and |r_p|² cancel), so F − F₀ formed from two rounded
//!   reflectances keeps a relative accuracy of only ~ε/θ⁴. With S = c + w, P = η̃c + w,
//!   Q = η̃²c + w and r₀ = (1 − η̃)/(1 + η̃), the closed forms
//!   r_s − r₀ = −2 sin²θ (η̃ − 1)/(S P), r_s + r₀ = 2(c − η̃w)/(S (1 + η̃)),
//!   r_p + r₀ = −2η̃ sin²θ (η̃ − 1)/(Q P), r_p − r₀ = 2(η̃³c − w)/(Q (1 + η̃))
//!   (from c η̃ − w = −sin²θ a/P) turn |r|² − |r₀|² = Re((r − r₀) conj(r + r₀)) into
//!   |r_s|² − |r₀|² = 4 sin²θ |a|² (η + c Re w)/(|1 + η̃|² |S|² |P|²) and
//!   |r_p|² − |r₀|² = −4 sin²θ |a|² (c|η̃|²(cη + Re w) − η sin²θ)/(|1 + η̃|² |Q|² |P|²). Writing
//!   Q = η̃S − sin²θ (η̃ − 1)a/P, their sum cancels its θ² term exactly, and with
//!   1 − F₀ = 4η/|1 + η̃|² and R = −(η̃ − 1)a/(P S):
//!   v = sin⁴θ |a|² M / (2η |P|² |S|² |Q|²),
//!   M/(|P|² |S|²) = η(|η̃|² + 1)/|P|² + (η + c Re w)(2 Re(η̃ R̄) + sin²θ |R|²)/|P|².
//!   Every factor but M is a product of norms; M is a sum of two terms of either sign, whose
//!   rounding is ε times the same sum with every term taken positive. Near grazing incidence on a
//!   large |η̃|, M cancels ~min(1/cos θ, |η̃|²)-fold while |v| grows as large; there
//!   v = 1 − (1 − F)/(1 − F₀) from `one_minus_reflectance`, rounded to ~ε|1 − v|, is the more
//!   accurate, and whichever of the two bounds is the smaller decides. Left: real η = 2 ± √3,
//!   where the θ⁴ coefficient (2η − (η − 1)²)/(2η³) F₀/(1 − F₀) vanishes and v ~ θ⁶ near θ = 0
//!   (and likewise along a curve of complex indices): v is then ill-conditioned in η itself, its
//!   relative error growing like ε η²/|2η − (η − 1)²| (~6e-13 at η = 3.73), whatever the
//!   evaluation; and indices whose
//!   1 − F₀ = 4η/|1 + η̃|² underflows (η ≲ |η̃|² 1e-308), where only the θ⁴ form is available and
//!   its rounding grows like ε/cos θ near grazing incidence.

use num_complex::Complex;

/// A complex index η̃ = η + iκ together with η − 1, the form every function of this module takes.
///
/// Build it with [`Index::new`] from η, or field by field where η − 1 is known more accurately than
/// η − 1 computed from η (`gulbrandsen::index` for small r). Not validated: `Ior` in `mod.rs` does.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Index {
    /// Real part η.
    pub eta: f64,
    /// η − 1, accurate to a few ulps of itself (not only of η).
    pub eta_minus_one: f64,
    /// Extinction coefficient κ.
    pub kappa: f64,
}

impl Index {
    /// η̃ = η + iκ, with η − 1 by subtraction (exact for η ∈ [0.5, 2], a correctly rounded
    /// difference elsewhere).
    pub fn new(eta: f64, kappa: f64) -> Index {
        Index {
            eta,
            eta_minus_one: eta - 1.0,
            kappa,
        }
    }

    /// |a| = |η̃² − 1| = |η̃ − 1| |η̃ + 1|, a product of norms: no cancellation near η̃ = 1.
    fn abs_eta2_minus_one(&self) -> f64 {
        self.eta_minus_one.hypot(self.kappa) * (self.eta + 1.0).hypot(self.kappa)
    }
}

/// The angle of incidence θ ∈ [0, π/2] as the exact form uses it: c = cos θ and sin²θ.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Incidence {
    cos_theta: f64,
    sin2_theta: f64,
}

impl Incidence {
    /// Normal incidence: c = 1, sin²θ = 0.
    pub const NORMAL: Incidence = Incidence {
        cos_theta: 1.0,
        sin2_theta: 0.0,
    };

    /// From θ ∈ [0, π/2]: c = cos θ and sin²θ = (sin θ)², each within an ulp or two of itself.
    pub fn from_theta(theta: f64) -> Incidence {
        let sin_theta = theta.sin();
        Incidence {
            cos_theta: theta.cos(),
            sin2_theta: sin_theta * sin_theta,
        }
    }

    /// From c = cos θ ∈ [0, 1] taken as exact (the basis grid): sin²θ = (1 − c)(1 + c).
    pub fn from_cos(cos_theta: f64) -> Incidence {
        Incidence {
            cos_theta,
            sin2_theta: (1.0 - cos_theta) * (1.0 + cos_theta),
        }
    }
}

/// Exact unpolarized reflectance F(c; η̃) of docs/maths.md's normative form, in [0, 1].
///
/// `incidence` is the angle of incidence θ (c = cos θ); `index` is η̃ = η + iκ, the medium entered
/// from index 1. Exactly 0 for η̃ = 1, exactly 1 under total internal reflection (κ = 0,
/// η ≤ sin θ).
pub fn reflectance(incidence: Incidence, index: Index) -> f64 {
    match Interface::new(incidence, index) {
        Interface::Index1 => 0.0,
        Interface::TotalInternalReflection => 1.0,
        Interface::General(General {
            c,
            sin2_theta,
            eta2,
            w,
            ..
        }) => {
            let abs_a = index.abs_eta2_minus_one();
            let abs_s_den = (w + c).norm();
            let r_s = abs_a / abs_s_den / abs_s_den;
            let abs_p_den = (eta2 * c + w).norm();
            let r_p = (abs_a / abs_p_den) * ((eta2 * (c * c) - sin2_theta).norm() / abs_p_den);
            (0.5 * (r_s * r_s + r_p * r_p)).min(1.0)
        }
    }
}

/// 1 − F(c; η̃) without cancellation, in [0, 1]: from |A + B|² − |A − B|² = 4 Re(A B̄),
/// 1 − |r_s|² = 4c Re w / |c + w|² and 1 − |r_p|² = 4c Re(η̃² w̄) / |η̃² c + w|², so
/// 1 − F = 2c [Re w / |c + w|² + Re(η̃² w̄) / |η̃² c + w|²].
///
/// Accurate to a few ulps relative where F is close to 1 (conductors, grazing incidence), where
/// 1 − `reflectance` keeps only the absolute accuracy of F. Same domain and guards as [`reflectance`].
pub fn one_minus_reflectance(incidence: Incidence, index: Index) -> f64 {
    match Interface::new(incidence, index) {
        Interface::Index1 => 1.0,
        Interface::TotalInternalReflection => 0.0,
        Interface::General(General { c, eta2, w, .. }) => {
            let abs_s_den = (w + c).norm();
            let abs_p_den = (eta2 * c + w).norm();
            // Each factor divided by |denominator| separately: no overflow for |η̃| up to 1e150.
            let t_s = w.re / abs_s_den / abs_s_den;
            let t_p = ((eta2 / abs_p_den) * (w.conj() / abs_p_den)).re;
            (2.0 * c * (t_s + t_p)).clamp(0.0, 1.0)
        }
    }
}

/// The normalized curve v = (F(c) − F₀)/(1 − F₀), F₀ = F(1), of the `normalized` curve model and
/// the spectrum check, accurate to a few ulps relative at every θ (module documentation: except
/// at small θ near η = 2 ± √3, where v is ill-conditioned in η, and where 1 − F₀ underflows):
/// v = sin⁴θ |a|² M / (2η |P|² |S|² |Q|²) with S = c + w, P = η̃c + w, Q = η̃²c + w,
/// R = −(η̃ − 1)a/(P S) and
/// M/(|P|² |S|²) = η(|η̃|² + 1)/|P|² + (η + c Re w)(2 Re(η̃ R̄) + sin²θ |R|²)/|P|², or
/// v = 1 − (1 − F)/(1 − F₀) from [`one_minus_reflectance`] where that is rounded less (near grazing
/// incidence on a large |η̃|). 0 for η̃ = 1, 1 under total internal reflection. η < 0 (the basis
/// training set's quirky row) is evaluated as |η| + iκ, which has the same F at every angle: F
/// depends on η̃ only through η̃² and the moduli of conjugate-symmetric ratios.
pub fn normalized_reflectance(incidence: Incidence, index: Index) -> f64 {
    let index = if index.eta < 0.0 {
        Index {
            eta: -index.eta,
            eta_minus_one: -index.eta - 1.0,
            kappa: index.kappa,
        }
    } else {
        index
    };
    match Interface::new(incidence, index) {
        Interface::Index1 => 0.0,
        Interface::TotalInternalReflection => 1.0,
        Interface::General(general) => {
            let (v, rounding) = normalized_quartic_form(index, general);
            if rounding <= (1.0 - v).abs() {
                return v;
            }
            let one_minus_f0 = one_minus_reflectance(Incidence::NORMAL, index);
            if one_minus_f0 == 0.0 {
                v
            } else {
                1.0 - one_minus_reflectance(incidence, index) / one_minus_f0
            }
        }
    }
}

/// v = sin⁴θ |a|² M / (2η |P|² |S|² |Q|²) of [`normalized_reflectance`] for η ≥ 0 outside the
/// guarded cases, and its rounding bound in units of ε: the same expression with every term of M
/// taken positive. Each quotient is taken factor by factor: no overflow for |η̃| up to 1e150.
fn normalized_quartic_form(index: Index, general: General) -> (f64, f64) {
    let Index {
        eta,
        eta_minus_one,
        kappa,
    } = index;
    let General {
        c,
        sin2_theta,
        eta2,
        a,
        w,
    } = general;
    let eta_c = Complex::new(eta, kappa);
    let s = w + c;
    let p = eta_c * c + w;
    let abs_p = p.norm();
    let r = -(Complex::new(eta_minus_one, kappa) * divide(a, p));
    let r = divide(r, s);
    let positive = eta * ((eta_c.norm_sqr() + 1.0) / abs_p / abs_p);
    let weight = (eta + c * w.re) / abs_p;
    let (e_r_re, e_r_im) = (eta_c.re * r.re, eta_c.im * r.im);
    let m = positive + weight * ((2.0 * (e_r_re + e_r_im) + sin2_theta * r.norm_sqr()) / abs_p);
    let m_bound = positive
        + weight * ((2.0 * (e_r_re.abs() + e_r_im.abs()) + sin2_theta * r.norm_sqr()) / abs_p);
    let scale = sin2_theta * (index.abs_eta2_minus_one() / (eta2 * c + w).norm());
    let scale = scale * scale / (2.0 * eta);
    (scale * m, scale * m_bound)
}

/// z/d with both parts of z d̄ scaled by |d| before the division: no overflow where |z| |d|
/// would exceed f64::MAX.
fn divide(z: Complex<f64>, d: Complex<f64>) -> Complex<f64> {
    let abs_d = d.norm();
    z * (d.conj() / abs_d) / abs_d
}

/// The cases of the interface at one angle, with the shared quantities of the general case.
enum Interface {
    /// η̃ = 1: no interface, F ≡ 0.
    Index1,
    /// κ = 0 and η² ≤ sin²θ: w is purely imaginary and F = 1 exactly.
    TotalInternalReflection,
    /// Any other interface.
    General(General),
}

/// The quantities of an interface's general case: c = cos θ, sin²θ, η̃², a = η̃² − 1 and the
/// principal root w = √(η̃² − sin²θ).
#[derive(Clone, Copy)]
struct General {
    c: f64,
    sin2_theta: f64,
    eta2: Complex<f64>,
    a: Complex<f64>,
    w: Complex<f64>,
}

impl Interface {
    fn new(incidence: Incidence, index: Index) -> Interface {
        let Index {
            eta,
            eta_minus_one,
            kappa,
        } = index;
        if eta_minus_one == 0.0 && kappa == 0.0 {
            return Interface::Index1;
        }
        let Incidence {
            cos_theta: c,
            sin2_theta,
        } = incidence;
        let cos2_theta = c * c;
        let eta_c = Complex::new(eta, kappa);
        let eta2 = eta_c * eta_c;
        // a = η̃² − 1 = (η̃ − 1)(η̃ + 1), its real part from η − 1.
        let a = Complex::new(
            eta_minus_one * (eta + 1.0) - kappa * kappa,
            2.0 * eta * kappa,
        );
        let w2 = if a.l1_norm() + cos2_theta <= eta2.l1_norm() + sin2_theta {
            a + cos2_theta
        } else {
            eta2 - sin2_theta
        };
        if kappa == 0.0 && w2.re <= 0.0 {
            return Interface::TotalInternalReflection;
        }
        Interface::General(General {
            c,
            sin2_theta,
            eta2,
            a,
            w: principal_sqrt(w2),
        })
    }
}

/// Principal square root (Re ≥ 0, branch cut on the negative real axis, continuous from the side
/// of the sign of the imaginary zero), by Kahan's formula: t = √((|x| + |z|)/2), then
/// √z = t + i y/(2t) for x ≥ 0 and |y|/(2t) ± i t for x < 0. No cancellation, unlike the polar
/// form, and accurate to a few ulps in both parts.
fn principal_sqrt(z: Complex<f64>) -> Complex<f64> {
    if z.re == 0.0 && z.im == 0.0 {
        return z;
    }
    let t = ((z.re.abs() + z.norm()) / 2.0).sqrt();
    if z.re >= 0.0 {
        Complex::new(t, z.im / (2.0 * t))
    } else {
        Complex::new(z.im.abs() / (2.0 * t), t.copysign(z.im))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn principal_sqrt_matches_the_principal_branch() {
        let cases = [
            (4.0, 0.0),
            (-4.0, 0.0),
            (-4.0, -0.0),
            (3.0, 4.0),
            (-3.0, 4.0),
            (-3.0, -4.0),
        ];
        for (re, im) in cases {
            let z = Complex::new(re, im);
            let root = principal_sqrt(z);
            assert!(root.re >= 0.0, "{z}: {root}");
            assert!(
                (root * root - z).norm() <= 4.0 * f64::EPSILON * z.norm(),
                "{z}: {root}"
            );
        }
        assert_eq!(
            principal_sqrt(Complex::new(-4.0, -0.0)),
            Complex::new(0.0, -2.0)
        );
    }

    #[test]
    fn one_minus_reflectance_is_the_complement() {
        for (eta, kappa) in [
            (1.5, 0.0),
            (0.29, 2.86),
            (1.9, 6.79),
            (0.5, 0.0),
            (1.0, 0.0),
            (-9.99995e-6, 1.0),
        ] {
            for c in [0.0, 0.1, 0.5, 0.9, 1.0] {
                let (f, t) = (
                    reflectance(Incidence::from_cos(c), Index::new(eta, kappa)),
                    one_minus_reflectance(Incidence::from_cos(c), Index::new(eta, kappa)),
                );
                // Both are accurate to a few ulps of 1.
                assert!(
                    (f + t - 1.0).abs() < 8.0 * f64::EPSILON,
                    "η̃ = {eta} + {kappa}i, c = {c}: {f} + {t}"
                );
            }
        }
    }

    #[test]
    fn quirky_training_material_keeps_the_principal_branch() {
        // docs/maths.md step 2: η ≈ −9.99995e-6, κ ≈ 1 gives F₀ = 0.99998 with the principal root.
        let f0 = reflectance(Incidence::NORMAL, Index::new(-9.99995e-6, 1.0));
        assert!((f0 - 0.99998).abs() < 1e-6, "{f0}");
    }
}
