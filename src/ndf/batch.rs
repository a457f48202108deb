//! Batch evaluation of NDFs on uniform θ grids: the fast path for throughput, built so that the
//! compiler vectorizes it (AVX-512 or AVX2 when the CPU has them, chosen at run time).
//!
//! Owns the angle recurrence ([`fill_grid`]) and branch-free `exp` and `log1p` ([`exp`], [`ln_1p`]).
//! It must not replace `eval`: the single-point forms stay the accurate reference, and
//! `tests/sampling.rs` checks this path against them over every family's domain.
//!
//! - Angles: θ_i = θ₀ + i Δθ in blocks of ≈ √(2n) points (at most [`BLOCK`]; see [`block_len`]). Each block seeds sin and cos from libm at
//!   its two ends and rotates by tabulated sin(kΔθ), cos(kΔθ) (libm, once per grid): sin forward from
//!   the first point, sin(θ_s + kΔθ) = sin θ_s cos kΔθ + cos θ_s sin kΔθ, and cos backward from the last,
//!   cos(θ_e − kΔθ) = cos θ_e cos kΔθ + sin θ_e sin kΔθ. For θ, kΔθ ∈ [0, π/2] both are sums of
//!   non-negative terms: no cancellation, a few ulp relative error at every point, and no error
//!   accumulates along the block (each point is one rotation from a seed). The seeds' angles are
//!   rounded once, so a point's abscissa is θ₀ + iΔθ to within an ulp.
//! - `exp`: Cody–Waite reduction x = k ln 2 + r, |r| ≤ ln 2/2, degree-13 Taylor polynomial (truncation
//!   ≤ 0.35¹⁴/14! ≈ 4e-18), scaling by 2^k as two exact power-of-two factors so subnormal results round
//!   once: ≤ 2 ulp.
//! - `ln_1p`: u = 1 + x with the rounding error (x − (u − 1))/u carried, u = 2^k m with m ∈ [√½, √2),
//!   ln m = 2 atanh(f/(2 + f)) by its odd series (s² ≤ 0.0295, 12 terms): ≤ 2 ulp.
//!
//! No FMA is used (Rust never contracts a·b + c), so every SIMD width gives the same bits.

/// Most points per block: two libm `sin_cos` seeds per block cost ~0.1 ns per point at this size, and
/// the block's sin, cos and rotation tables (4 × 4 KiB) stay in L1.
pub const BLOCK: usize = 512;
/// Fewest points per block (below it the seeds cost more than the points).
const MIN_BLOCK: usize = 16;

/// Points per block for a grid of `n`: a grid costs one `sin_cos` per table entry (the block length
/// b) plus two per block (2n/b), least at b = √(2n); 45 for a 1000-point plot, [`BLOCK`] from
/// 2¹⁷ points on.
pub fn block_len(n: usize) -> usize {
    ((2.0 * n as f64).sqrt() as usize).clamp(MIN_BLOCK, BLOCK)
}

/// 1.5 × 2⁵²: adding it rounds a double of magnitude < 2⁵¹ to an integer held in the low mantissa bits.
const ROUND_SHIFTER: f64 = 6_755_399_441_055_744.0;
/// ln 2 split so that k · LN2_HI is exact for |k| < 2¹¹ (fdlibm's constants).
const LN2_HI: f64 = 6.931_471_803_691_238_2e-1;
const LN2_LO: f64 = 1.908_214_929_270_587_7e-10;
/// exp underflows to 0 below −745.2 and overflows above 709.8; clamping to ±800 keeps k in the
/// two-factor scaling's range and maps ±∞ to 0 and +∞ alike.
const EXP_ARG_LIMIT: f64 = 800.0;
/// Taylor coefficients 1/n! for n = 2 … 13 (exact reciprocals of factorials, rounded).
const EXP_TAYLOR: [f64; 12] = [
    1.0 / 2.0,
    1.0 / 6.0,
    1.0 / 24.0,
    1.0 / 120.0,
    1.0 / 720.0,
    1.0 / 5040.0,
    1.0 / 40320.0,
    1.0 / 362880.0,
    1.0 / 3628800.0,
    1.0 / 39916800.0,
    1.0 / 479001600.0,
    1.0 / 6227020800.0,
];
/// The mantissa field of a double.
const MANTISSA_MASK: u64 = 0x000f_ffff_ffff_ffff;
/// √2, the upper end of the mantissa interval of `ln_1p`.
const SQRT_2: f64 = std::f64::consts::SQRT_2;
/// Coefficients 2/(2n + 1) for n = 1 … 12 of ln m = 2s + Σ 2 s^{2n+1}/(2n + 1), s = f/(2 + f):
/// with s² ≤ (3 − 2√2)² = 0.0295 the next term is below 2⁻⁵⁷ of the sum.
const LN_SERIES: [f64; 12] = [
    2.0 / 3.0,
    2.0 / 5.0,
    2.0 / 7.0,
    2.0 / 9.0,
    2.0 / 11.0,
    2.0 / 13.0,
    2.0 / 15.0,
    2.0 / 17.0,
    2.0 / 19.0,
    2.0 / 21.0,
    2.0 / 23.0,
    2.0 / 25.0,
];

/// eˣ to ≤ 2 ulp for every x (0 below −745.2, +∞ above 709.8), branch-free so that loops of it
/// vectorize.
#[inline(always)]
pub fn exp(x: f64) -> f64 {
    let x = x.clamp(-EXP_ARG_LIMIT, EXP_ARG_LIMIT);
    let k = round(x * std::f64::consts::LOG2_E);
    let r = (x - k * LN2_HI) - k * LN2_LO;
    let mut q = EXP_TAYLOR[11];
    for &c in EXP_TAYLOR[..11].iter().rev() {
        q = q * r + c;
    }
    let p = 1.0 + (r + r * r * q);
    let k_half = round(0.5 * k);
    p * pow2(k_half) * pow2(k - k_half)
}

/// The integer nearest to `x` (ties to even), for |x| < 2⁵¹, by [`ROUND_SHIFTER`]: float adds only,
/// so that it vectorizes without SSE4.1's `round`.
#[inline(always)]
fn round(x: f64) -> f64 {
    (x + ROUND_SHIFTER) - ROUND_SHIFTER
}

/// 2ᵏ for an integer k ∈ [−1022, 1023] given as a double: k + 1023 lands in the low mantissa bits
/// of k + 1023 + [`ROUND_SHIFTER`], and a shift by 52 moves those 11 bits into the exponent field.
/// A shift of unsigned 64-bit lanes, which AVX2 has (unlike 64-bit arithmetic shifts and
/// integer-to-double conversions).
#[inline(always)]
fn pow2(k: f64) -> f64 {
    f64::from_bits((k + (EXPONENT_BIAS + ROUND_SHIFTER)).to_bits() << 52)
}

/// The exponent bias of doubles.
const EXPONENT_BIAS: f64 = 1023.0;

/// ln(1 + x) to ≤ 2 ulp for x ≥ 0 (+∞ at +∞), branch-free so that loops of it vectorize.
#[inline(always)]
pub fn ln_1p(x: f64) -> f64 {
    let u = 1.0 + x;
    // The rounding error of 1 + x, relative to u: ln(1 + x) = ln u + ln(1 + c) ≈ ln u + c.
    let c = (x - (u - 1.0)) / u;
    let bits = u.to_bits();
    // Exponent field e (as a double, via the shifter: no integer-to-double conversion) and mantissa
    // m ∈ [1, 2); then m into [√½, √2) by moving one factor 2 to the exponent.
    let e = f64::from_bits((bits >> 52) | ROUND_SHIFTER.to_bits()) - ROUND_SHIFTER;
    let m = f64::from_bits((bits & MANTISSA_MASK) | 1f64.to_bits());
    let high = m > SQRT_2;
    let m = if high { 0.5 * m } else { m };
    let k = e - EXPONENT_BIAS + if high { 1.0 } else { 0.0 };
    let f = m - 1.0;
    let s = f / (2.0 + f);
    let s2 = s * s;
    let mut q = LN_SERIES[11];
    for &coefficient in LN_SERIES[..11].iter().rev() {
        q = q * s2 + coefficient;
    }
    let ln_m = 2.0 * s + s * s2 * q;
    let ln_u = k * LN2_HI + (k * LN2_LO + c + ln_m);
    if u.is_infinite() { u } else { ln_u }
}

/// Tabulated rotations cos(kΔθ), sin(kΔθ) for k below the block length.
struct Rotations {
    cos: [f64; BLOCK],
    sin: [f64; BLOCK],
    /// k as a double (integer-to-double conversions of 64-bit lanes need AVX-512DQ).
    index: [f64; BLOCK],
}

impl Rotations {
    fn new(dtheta: f64, len: usize) -> Rotations {
        let mut rotations = Rotations {
            cos: [0.0; BLOCK],
            sin: [0.0; BLOCK],
            index: [0.0; BLOCK],
        };
        for k in 0..len {
            rotations.index[k] = k as f64;
            let (s, c) = (k as f64 * dtheta).sin_cos();
            rotations.sin[k] = s;
            rotations.cos[k] = c;
        }
        rotations
    }
}

/// Fills `out[i] = kernel(θ_i, sin θ_i, cos θ_i)` for θ_i = θ₀ + iΔθ ∈ [0, π/2] (module header for the
/// recurrence). `kernel` must be branch-free arithmetic for the loop to vectorize.
#[inline(always)]
fn fill_blocks(theta0: f64, dtheta: f64, out: &mut [f64], kernel: impl Fn(f64, f64, f64) -> f64) {
    let len = block_len(out.len());
    let rotations = Rotations::new(dtheta, len);
    let mut sin = [0.0; BLOCK];
    let mut cos = [0.0; BLOCK];
    for (b, block) in out.chunks_mut(len).enumerate() {
        let first = b * len;
        let last = block.len() - 1;
        let (sin_s, cos_s) = (theta0 + first as f64 * dtheta).sin_cos();
        let (sin_e, cos_e) = (theta0 + (first + last) as f64 * dtheta).sin_cos();
        for k in 0..block.len() {
            sin[k] = sin_s * rotations.cos[k] + cos_s * rotations.sin[k];
        }
        for k in 0..block.len() {
            cos[k] = cos_e * rotations.cos[last - k] + sin_e * rotations.sin[last - k];
        }
        let first_float = first as f64;
        for (o, ((&s, &c), &k)) in block
            .iter_mut()
            .zip(sin.iter().zip(&cos).zip(&rotations.index))
        {
            *o = kernel(theta0 + (first_float + k) * dtheta, s, c);
        }
    }
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,avx512dq,avx512vl")]
fn fill_avx512(theta0: f64, dtheta: f64, out: &mut [f64], kernel: impl Fn(f64, f64, f64) -> f64) {
    fill_blocks(theta0, dtheta, out, kernel);
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn fill_avx2(theta0: f64, dtheta: f64, out: &mut [f64], kernel: impl Fn(f64, f64, f64) -> f64) {
    fill_blocks(theta0, dtheta, out, kernel);
}

/// `out[i] = kernel(θ_i, sin θ_i, cos θ_i)` for θ_i = θ₀ + iΔθ, every θ_i within [0, π/2], using the
/// widest vector unit the CPU has. Identical results on every path (no FMA, lane-wise IEEE ops).
#[inline(always)]
pub fn fill_grid(theta0: f64, dtheta: f64, out: &mut [f64], kernel: impl Fn(f64, f64, f64) -> f64) {
    #[cfg(target_arch = "x86_64")]
    {
        if std::is_x86_feature_detected!("avx512f")
            && std::is_x86_feature_detected!("avx512dq")
            && std::is_x86_feature_detected!("avx512vl")
        {
            // SAFETY: the CPU supports AVX-512F, DQ and VL, checked just above.
            return unsafe { fill_avx512(theta0, dtheta, out, kernel) };
        }
        if std::is_x86_feature_detected!("avx2") && std::is_x86_feature_detected!("fma") {
            // SAFETY: the CPU supports AVX2 and FMA, checked just above.
            return unsafe { fill_avx2(theta0, dtheta, out, kernel) };
        }
    }
    fill_blocks(theta0, dtheta, out, kernel);
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ulps(a: f64, b: f64) -> f64 {
        ((a - b) / b).abs() / f64::EPSILON
    }

    #[test]
    fn exp_is_within_two_ulp_of_libm() {
        for i in 0..=200_000 {
            let x = -708.0 + 1417.0 * f64::from(i) / 200_000.0;
            assert!(
                ulps(exp(x), x.exp()) <= 2.0,
                "exp({x}) = {} vs {}",
                exp(x),
                x.exp()
            );
        }
        assert_eq!(exp(f64::NEG_INFINITY), 0.0);
        assert_eq!(exp(-746.0), 0.0);
        assert!(exp(710.0).is_infinite());
        assert_eq!(exp(0.0), 1.0);
    }

    #[test]
    fn ln_1p_is_within_two_ulp_of_libm() {
        for i in 0..=200_000 {
            let x = 10f64.powf(-300.0 + 600.0 * f64::from(i) / 200_000.0);
            assert!(
                ulps(ln_1p(x), x.ln_1p()) <= 2.0,
                "ln_1p({x}) = {} vs {}",
                ln_1p(x),
                x.ln_1p()
            );
        }
        assert_eq!(ln_1p(0.0), 0.0);
        assert!(ln_1p(f64::INFINITY).is_infinite());
    }

    #[test]
    fn the_recurrence_matches_libm_sin_and_cos() {
        let n = 3 * BLOCK + 7;
        let dtheta = std::f64::consts::FRAC_PI_2 / (n - 1) as f64;
        let mut sin = vec![0.0; n];
        let mut cos = vec![0.0; n];
        fill_grid(0.0, dtheta, &mut sin, |_, s, _| s);
        fill_grid(0.0, dtheta, &mut cos, |_, _, c| c);
        for i in 1..n - 1 {
            let theta = i as f64 * dtheta;
            // A 1-ulp change of θ moves sin by cos θ · ulp(θ) and cos by sin θ · ulp(θ).
            let slack = 2.0 * theta * f64::EPSILON;
            assert!(
                (sin[i] - theta.sin()).abs()
                    <= 4.0 * f64::EPSILON * theta.sin() + slack * theta.cos(),
                "sin at {i}"
            );
            assert!(
                (cos[i] - theta.cos()).abs()
                    <= 4.0 * f64::EPSILON * theta.cos() + slack * theta.sin(),
                "cos at {i}"
            );
        }
    }
}
