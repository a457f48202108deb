//! Batch evaluation of NDFs on uniform θ grids: the fast path for throughput, built so that the
//! compiler vectorizes it (AVX-512 or AVX2 when the CPU has them, chosen at run time).
//!
//! Owns the angle recurrence ([`fill_grid`]) and branch-free `exp` and `log1p` ([`exp`], [`ln_1p`]).
//! It must not replace `eval`: the single-point forms stay the accurate reference, and
//! `tests/cli/sampling.rs` checks this path against them over every family's domain.
//!
//! - Angles: θ_i = θ₀ + i Δθ in blocks of ≈ √n points (at most [`BLOCK`]; see [`block_len`]). Each
//!   block seeds sin and cos from libm at its first point θ_s and at θ_e, the next block's first point
//!   (the grid's last point for the last block), so one `sin_cos` per block, and rotates by tabulated
//!   sin(kΔθ), cos(kΔθ) (libm, once per grid): sin forward from θ_s,
//!   sin(θ_s + kΔθ) = sin θ_s cos kΔθ + cos θ_s sin kΔθ, and cos backward from θ_e,
//!   cos(θ_e − kΔθ) = cos θ_e cos kΔθ + sin θ_e sin kΔθ. For θ, kΔθ ∈ [0, π/2] both are sums of
//!   non-negative terms: no cancellation, a few ulp relative error at every point, and no error
//!   accumulates along the block (each point is one rotation from a seed). The seeds' angles are
//!   rounded once, so a point's abscissa is θ₀ + iΔθ to within an ulp.
//! - `exp`: Cody–Waite reduction x = k ln 2 + r, |r| ≤ ln 2/2, eʳ = 1 + r + r² q(r) with q a degree-9
//!   Chebyshev fit (0.07 ulp), scaling by 2ᵏ in the exponent field: ≤ 2 ulp for normal results.
//!   Results below 2⁻¹⁰²² are flushed to 0, an absolute error under 2.3e-308 (MATH.md measures
//!   errors absolutely below 1e-280); a second scaling factor for gradual underflow cost a fifth
//!   of the throughput of Beckmann's grid.
//! - `ln_1p`: u = 1 + x with the rounding error (x − (u − 1))/u carried, u = 2^k m with m ∈ [√½, √2),
//!   ln m = 2 atanh(f/(2 + f)) = 2s + s³ R(s²) with R a degree-6 Chebyshev fit on s² ≤ 0.0295
//!   (0.02 ulp): ≤ 2 ulp.
//! - Polynomials are evaluated by Estrin's scheme with fused multiply-adds: fewer operations and a
//!   shorter dependency chain than Horner's rule without them.
//!
//! Fused multiply-adds are explicit (`mul_add`; Rust never contracts a·b + c by itself), so every
//! SIMD width gives the same bits. Both vector paths require FMA hardware; the portable fallback,
//! for CPUs without AVX2 and FMA, gets the same bits from a software `fma`, slowly.

/// Most points per block: the libm `sin_cos` seed of each block (~30 ns) costs ~0.06 ns per point at
/// this size, and the block's sin, cos and rotation tables (5 × 4 KiB) stay in L1.
pub const BLOCK: usize = 512;
/// Fewest points per block (below it the seeds cost more than the points).
const MIN_BLOCK: usize = 16;

/// Doubles in an AVX-512 vector (two AVX2 vectors): blocks are a multiple of it, so that only the
/// grid's last block leaves a scalar remainder (a scalar `exp` costs about as much as a vector one).
const LANES: usize = 8;

/// Points per block for a grid of `n`: a grid costs one `sin_cos` per table entry (the block length
/// b) plus one per block (n/b), least at b = √n, rounded up to a multiple of 8 (`LANES`); 32 for a
/// 1000-point plot, [`BLOCK`] from 2¹⁸ points on.
pub fn block_len(n: usize) -> usize {
    ((n as f64).sqrt() as usize)
        .next_multiple_of(LANES)
        .clamp(MIN_BLOCK, BLOCK)
}

/// 1.5 × 2⁵²: adding it rounds a double of magnitude < 2⁵¹ to an integer held in the low mantissa bits.
const ROUND_SHIFTER: f64 = 6_755_399_441_055_744.0;
/// ln 2 split so that k · LN2_HI is exact for |k| < 2¹¹ (fdlibm's constants).
const LN2_HI: f64 = 6.931_471_803_691_238e-1;
const LN2_LO: f64 = 1.908_214_929_270_587_7e-10;
/// Clamping the argument to ±800 keeps k = round(x/ln 2) within ±1155, where [`pow2`]'s shifter
/// arithmetic is exact, and maps ±∞ to finite arguments (whose results are then selected or overflow).
const EXP_ARG_LIMIT: f64 = 800.0;
/// Below this x, eˣ < 2⁻¹⁰²² is subnormal (ln 2⁻¹⁰²² = −708.396…): [`exp`] returns 0 there, an
/// absolute error under 2.3e-308 (MATH.md compares absolutely below 1e-280).
const EXP_NORMAL_MIN: f64 = -708.396_418_532_264_1;
/// Coefficients, lowest first, of q(r) ≈ (eʳ − 1 − r)/r² on |r| ≤ ln 2/2: mpmath's degree-9 Chebyshev
/// fit, rounded to doubles (`tests/data/batch_polynomials.py`); 1 + r + r² q(r) is within 1.6e-17
/// (0.07 ulp) of eʳ there.
const EXP_POLY: [f64; 10] = [
    0.5000000000000001,
    0.16666666666666669,
    0.041666666666624164,
    0.008333333333330065,
    0.0013888888917196719,
    0.00019841269863040545,
    2.4801521322368692e-05,
    2.7557268480310024e-06,
    2.7620075879983367e-07,
    2.5100375832561234e-08,
];
/// The mantissa field of a double.
const MANTISSA_MASK: u64 = 0x000f_ffff_ffff_ffff;
/// √2, the upper end of the mantissa interval of `ln_1p`.
const SQRT_2: f64 = std::f64::consts::SQRT_2;
/// Coefficients, lowest first, of R(z) ≈ (2 atanh √z − 2√z)/z^{3/2} (the atanh series after 2s, in
/// z = s²) on z ≤ (3 − 2√2)² = 0.0295: mpmath's degree-6 Chebyshev fit, rounded to doubles
/// (`tests/data/batch_polynomials.py`); 2s + s³ R(s²) is within 4.6e-18 (0.02 ulp) of ln m.
const LN_POLY: [f64; 7] = [
    0.666666666666667,
    0.39999999999899505,
    0.28571428625975487,
    0.2222221113479508,
    0.18182889125261723,
    0.15331721600556042,
    0.14616449685043406,
];

/// eˣ to ≤ 2 ulp for −708.39 ≤ x ≤ 709.43 (every normal result up to 2¹⁰²³·√2); 0 below (subnormal
/// results are flushed: absolute error < 2.3e-308) and +∞ above (eˣ itself overflows from 709.78; the
/// NDFs' exponents never exceed ln D(0) < 708). Branch-free so that loops of it vectorize.
#[inline(always)]
pub fn exp(x: f64) -> f64 {
    let x = x.clamp(-EXP_ARG_LIMIT, EXP_ARG_LIMIT);
    let k = round(x * std::f64::consts::LOG2_E);
    let r = (-k).mul_add(LN2_LO, (-k).mul_add(LN2_HI, x));
    // q(r) by Estrin's scheme: pairs, then powers r², r⁴, r⁸ (a shorter dependency chain than Horner's).
    let r2 = r * r;
    let r4 = r2 * r2;
    let [c0, c1, c2, c3, c4, c5, c6, c7, c8, c9] = EXP_POLY;
    let low = c3.mul_add(r, c2).mul_add(r2, c1.mul_add(r, c0));
    let high = c7.mul_add(r, c6).mul_add(r2, c5.mul_add(r, c4));
    let q = c9.mul_add(r, c8).mul_add(r4 * r4, high.mul_add(r4, low));
    let p = 1.0 + r2.mul_add(q, r);
    // 2ᵏ is a normal double for k ∈ [−1022, 1023]; k = 1024 (x > 709.43) gives +∞, and the select
    // covers every k below −1022.
    let scaled = p * pow2(k);
    if x < EXP_NORMAL_MIN { 0.0 } else { scaled }
}

/// The integer nearest to `x` (ties to even), for |x| < 2⁵¹, by [`ROUND_SHIFTER`]: float adds only,
/// so that it vectorizes without SSE4.1's `round`.
#[inline(always)]
fn round(x: f64) -> f64 {
    (x + ROUND_SHIFTER) - ROUND_SHIFTER
}

/// 2ᵏ for an integer k ∈ [−1022, 1024] given as a double (+∞ for 1024): k + 1023 lands in the low mantissa bits
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
    let above = m > SQRT_2;
    let m = if above { 0.5 * m } else { m };
    let k = e - EXPONENT_BIAS + if above { 1.0 } else { 0.0 };
    let f = m - 1.0;
    let s = f / (2.0 + f);
    // R(s²) by Estrin's scheme, as in `exp`.
    let z = s * s;
    let z2 = z * z;
    let [c0, c1, c2, c3, c4, c5, c6] = LN_POLY;
    let low = c3.mul_add(z, c2).mul_add(z2, c1.mul_add(z, c0));
    let top = c6.mul_add(z2, c5.mul_add(z, c4));
    let ln_m = (s * z).mul_add(top.mul_add(z2 * z2, low), 2.0 * s);
    let ln_u = k.mul_add(LN2_HI, k.mul_add(LN2_LO, c + ln_m));
    if u.is_infinite() { u } else { ln_u }
}

/// Tabulated rotations cos(kΔθ), sin(kΔθ) for k from 0 to the block length (both included).
struct Rotations {
    cos: [f64; BLOCK + 1],
    sin: [f64; BLOCK + 1],
    /// k as a double (integer-to-double conversions of 64-bit lanes need AVX-512DQ).
    index: [f64; BLOCK + 1],
}

impl Rotations {
    fn new(dtheta: f64, len: usize) -> Rotations {
        let mut rotations = Rotations {
            cos: [0.0; BLOCK + 1],
            sin: [0.0; BLOCK + 1],
            index: [0.0; BLOCK + 1],
        };
        for k in 0..=len {
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
    let n = out.len();
    let len = block_len(n);
    let rotations = Rotations::new(dtheta, len);
    let angle = |i: usize| theta0 + i as f64 * dtheta;
    let mut sin = [0.0; BLOCK];
    let mut cos = [0.0; BLOCK];
    let (mut sin_s, mut cos_s) = angle(0).sin_cos();
    for (b, block) in out.chunks_mut(len).enumerate() {
        let first = b * len;
        // The seed of cos: the next block's first point, whose sin and cos then seed that block, or
        // the grid's last point for the last block.
        let end = (first + len).min(n - 1);
        let (sin_e, cos_e) = angle(end).sin_cos();
        let steps_to_end = end - first;
        let rotate = |k_max: usize| rotations.cos[..=k_max].iter().zip(&rotations.sin[..=k_max]);
        for (s, (&cos_k, &sin_k)) in sin.iter_mut().zip(rotate(block.len() - 1)) {
            *s = sin_s * cos_k + cos_s * sin_k;
        }
        for (c, (&cos_k, &sin_k)) in cos
            .iter_mut()
            .zip(rotate(steps_to_end).rev())
            .take(block.len())
        {
            *c = cos_e * cos_k + sin_e * sin_k;
        }
        let first_float = first as f64;
        for (o, ((&s, &c), &k)) in block
            .iter_mut()
            .zip(sin.iter().zip(&cos).zip(&rotations.index))
        {
            *o = kernel(theta0 + (first_float + k) * dtheta, s, c);
        }
        (sin_s, cos_s) = (sin_e, cos_e);
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
            let x = -708.39 + 1417.82 * f64::from(i) / 200_000.0;
            assert!(
                ulps(exp(x), x.exp()) <= 2.0,
                "exp({x}) = {} vs {}",
                exp(x),
                x.exp()
            );
        }
        assert_eq!(exp(f64::NEG_INFINITY), 0.0);
        assert_eq!(exp(EXP_NORMAL_MIN.next_down()), 0.0);
        assert!(ulps(exp(EXP_NORMAL_MIN), EXP_NORMAL_MIN.exp()) <= 2.0);
        assert!(EXP_NORMAL_MIN.exp() >= f64::MIN_POSITIVE);
        assert!(ulps(exp(709.43), 709.43f64.exp()) <= 2.0);
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
