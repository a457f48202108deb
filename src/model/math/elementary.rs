//! Branch-free f64 exp, log1p, ln and sin/cos, written so that a loop over many arguments vectorizes, and
//! [`map_lanes`], which runs such a loop in the widest instruction set the processor has. ln and log1p also
//! come as unevaluated sums hi + lo ([`ln_parts`], [`ln_1p_parts`]), for powers of large logarithms.
//!
//! The algorithms are fdlibm's (Sun Microsystems 1993, as kept in FreeBSD's and musl's libm: `e_exp.c`,
//! `s_log1p.c`, `e_log.c`, `k_sin.c`, `k_cos.c`, `e_rem_pio2.c`), with their coefficients and error bounds
//! (below 1 ulp each; exp's rational is replaced by a polynomial, with no division), rewritten without
//! branches: every case is computed and the right one selected, and integer work is done on the bits of
//! doubles with 64-bit integer operations SSE2 has. Every operation is a correctly rounded IEEE 754
//! operation — the fused multiply-adds are explicit ([`f64::mul_add`]: one instruction where the processor
//! has FMA, the same correctly rounded value computed in software where it has not) and nothing else is
//! contracted — so a value is the same bits whether it is computed alone, in a 2-, 4- or 8-lane loop, on
//! any x86-64 processor or any other target: one kernel serves the point-by-point and the block evaluation
//! of every output. The tests below hold each function to its ulp bound against the platform libm (itself
//! within 1 ulp) over its whole domain, and the unevaluated sums to theirs against mpmath.

// The coefficients are quoted digit for digit from their sources, so that they can be checked there.
#![allow(clippy::excessive_precision)]

/// 1.5 · 2⁵²: x + this rounds x to an integer, which the low bits of the sum hold (|x| < 2⁵¹).
const ROUND_MAGIC: f64 = 6_755_399_441_055_744.0;

/// ln 2 in two parts (fdlibm): the first has 32 significant bits, so k · it is exact for |k| < 2²¹.
const LN2_HI: f64 = 6.931_471_803_691_238_164_90e-1;
/// ln 2 − [`LN2_HI`].
const LN2_LO: f64 = 1.908_214_929_270_587_700_02e-10;

/// Rounds `x` (|x| < 2⁵¹) to the nearest integer, ties to even: the integer as a double and its bits'
/// offset from [`ROUND_MAGIC`]'s, which is the integer itself in two's complement.
#[inline(always)]
fn round_to_integer(x: f64) -> (f64, i64) {
    let shifted = x + ROUND_MAGIC;
    (
        shifted - ROUND_MAGIC,
        (shifted.to_bits() as i64).wrapping_sub(ROUND_MAGIC.to_bits() as i64),
    )
}

/// 2^k for −1022 ≤ k ≤ 1023, built from its exponent bits.
#[inline(always)]
fn two_to(k: i64) -> f64 {
    f64::from_bits((k.wrapping_add(1023) as u64) << 52)
}

/// eˣ within 1 ulp for every double: +∞ above 709.78, 0 below −745.13, NaN for NaN. x = k ln 2 + r with
/// |r| ≤ ½ ln 2 (fdlibm `e_exp.c`'s reduction: k ln 2 in two parts, r = hi − lo), then
/// e^r = 1 + hi + (r² P(r) − lo) with P the Taylor polynomial of (e^r − 1 − r)/r² to r¹¹ (truncation
/// below 5e-18 relative), evaluated by Estrin's scheme, and 1 + hi summed with its rounding error kept:
/// the result carries one rounding of 1 + (…) plus ~2⁻⁵⁸ relative. The scaling by 2^k is done in two halves,
/// so that a subnormal result is rounded once more at most.
#[inline(always)]
pub fn exp(x: f64) -> f64 {
    const INV_LN2: f64 = std::f64::consts::LOG2_E;
    /// 1/(j + 2)! for j = 0 … 11.
    const C: [f64; 12] = [
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
    // Past these, e^x is +∞ or 0 anyway; the bounds keep k within two normal halves (NaN stays NaN).
    let x = x.clamp(-746.0, 710.0);
    let (k_float, k) = round_to_integer(x * INV_LN2);
    let hi = x - k_float * LN2_HI;
    let lo = k_float * LN2_LO;
    let r = hi - lo;
    let r2 = r * r;
    let r4 = r2 * r2;
    let a0 = r.mul_add(C[1], C[0]);
    let a1 = r.mul_add(C[3], C[2]);
    let a2 = r.mul_add(C[5], C[4]);
    let a3 = r.mul_add(C[7], C[6]);
    let a4 = r.mul_add(C[9], C[8]);
    let a5 = r.mul_add(C[11], C[10]);
    let b0 = r2.mul_add(a1, a0);
    let b1 = r2.mul_add(a3, a2);
    let b2 = r2.mul_add(a5, a4);
    let p = r4.mul_add(r4.mul_add(b2, b1), b0);
    let one_hi = 1.0 + hi;
    let one_hi_error = (1.0 - one_hi) + hi;
    let e_r = one_hi + (one_hi_error + r2.mul_add(p, -lo));
    // k ∈ [−1077, 1025]: k₁ = ⌊k/2⌋ by a logical shift of the non-negative k + 2048, k₂ = k − k₁.
    let k1 = ((k.wrapping_add(2048) as u64) >> 1) as i64 - 1024;
    e_r * two_to(k1) * two_to(k.wrapping_sub(k1))
}

/// The reduction of the logarithms (musl's, on the high word): a positive normal u = 2^k m with
/// √2/2 ≤ m < √2, as (k, m), both exact.
#[inline(always)]
fn log_reduce(u: f64) -> (f64, f64) {
    /// 2⁵² + 1023: the double whose low bits are a biased exponent, minus this, is the exponent.
    const EXPONENT_MAGIC: f64 = 4_503_599_627_371_519.0;
    let bits = u.to_bits();
    // The high word shifted so that its exponent field is k with the mantissa reduced to [√2/2, √2).
    let high = (bits >> 32).wrapping_add(0x3ff0_0000 - 0x3fe6_a09e);
    let k = f64::from_bits(0x4330_0000_0000_0000 | ((high >> 20) & 0xfff)) - EXPONENT_MAGIC;
    let m = f64::from_bits((((high & 0x000f_ffff) + 0x3fe6_a09e) << 32) | (bits & 0xffff_ffff));
    (k, m)
}

/// R(z) in ln(1 + f) = f − f²/2 + s (f²/2 + R(z)), s = f/(2 + f), z = s² (musl's `s_log1p.c`: the
/// polynomial of degree 7 in z, within 2⁻⁵⁸·⁴⁵ of the true R for |s| ≤ 0.1716), split into its even and
/// odd parts in z².
#[inline(always)]
fn log_polynomial(z: f64) -> f64 {
    const LG1: f64 = 6.666_666_666_666_735_130e-1;
    const LG2: f64 = 3.999_999_999_940_941_908e-1;
    const LG3: f64 = 2.857_142_874_366_239_149e-1;
    const LG4: f64 = 2.222_219_843_214_978_396e-1;
    const LG5: f64 = 1.818_357_216_161_805_012e-1;
    const LG6: f64 = 1.531_383_769_920_937_332e-1;
    const LG7: f64 = 1.479_819_860_511_658_591e-1;
    let w = z * z;
    let t1 = w * w.mul_add(w.mul_add(LG6, LG4), LG2);
    let t2 = z * w.mul_add(w.mul_add(w.mul_add(LG7, LG5), LG3), LG1);
    t2 + t1
}

/// ln(1 + x) within 1 ulp (musl's `s_log1p.c`: 1 + x = 2^k (1 + f) with √2/2 ≤ 1 + f < √2, ln(1 + f) by
/// s = f/(2 + f) and a polynomial of degree 14 in s, and a first-order correction for the rounding of
/// 1 + x), for every double: −∞ at −1, NaN below −1 and for NaN, +∞ at +∞. For 1 + x already in
/// [√2/2, √2) it takes f = x, exactly.
#[inline(always)]
pub fn ln_1p(x: f64) -> f64 {
    let u = 1.0 + x;
    let (k, reduced) = log_reduce(u);
    let correction = if k >= 2.0 {
        1.0 - (u - x)
    } else {
        x - (u - 1.0)
    };
    let correction = if k < 54.0 { correction / u } else { 0.0 };
    // 1 + x in [√2/2, √2): f = x exactly, no correction (the bounds are musl's, on x's high word).
    let near_one = x > LOG1P_NEAR_ONE_MIN && x < LOG1P_NEAR_ONE_MAX;
    let (f, c, k) = if near_one {
        (x, 0.0, 0.0)
    } else {
        (reduced - 1.0, correction, k)
    };
    let hfsq = 0.5 * f * f;
    let s = f / (2.0 + f);
    let value =
        s.mul_add(hfsq + log_polynomial(s * s), k.mul_add(LN2_LO, c)) - hfsq + f + k * LN2_HI;
    if x == f64::INFINITY {
        f64::INFINITY
    } else if x == -1.0 {
        f64::NEG_INFINITY
    } else if x < -1.0 || x.is_nan() {
        f64::NAN
    } else {
        value
    }
}

/// The open interval of x around 0 where 1 + x lies in [√2/2, √2) (musl's bounds, on x's high word).
const LOG1P_NEAR_ONE_MIN: f64 = -0.292_893_218_813_452_4;
/// See [`LOG1P_NEAR_ONE_MIN`].
const LOG1P_NEAR_ONE_MAX: f64 = 0.414_213_562_373_095_1;

/// ln(2^k (1 + f) (1 + c)) = k ln 2 + ln(1 + f) + c (to c², for |c| ≲ 2⁻⁵³) as an unevaluated sum hi + lo
/// with |lo| ≤ ulp(hi)/2, for √2/2 − 1 ≤ f < √2 − 1 exact and k an integer (|k| < 2²¹). ln(1 + f) is
/// f − f²/2 + s (f²/2 + R(s²)) ([`log_polynomial`]): k ln 2 ([`LN2_HI`] exact), f and the double nearest
/// f²/2 are summed exactly (TwoSum, and the error of f²/2 by a fused multiply-add), so only the small
/// term s (f²/2 + R) + k [`LN2_LO`] + c, the first part below 0.019, carries roundings: hi + lo is within
/// 2⁻⁵⁶ absolute and 2⁻⁵⁵ relative of the truth (measured 6.9e-18 and 1.9e-17 against mpmath), where a
/// rounded double carries ½ ulp of the logarithm itself (up to 2⁻⁴⁴ at |k| = 1000).
#[inline(always)]
fn log_parts(f: f64, k: f64, c: f64) -> (f64, f64) {
    let half_f = 0.5 * f;
    let hfsq = half_f * f;
    let hfsq_error = half_f.mul_add(f, -hfsq);
    let s = f / (2.0 + f);
    let small = s.mul_add(
        hfsq + log_polynomial(s * s),
        k.mul_add(LN2_LO, c) - hfsq_error,
    );
    let (head, head_error) = two_sum(k * LN2_HI, f);
    let (sum, sum_error) = two_sum(head, -hfsq);
    two_sum(sum, small + (head_error + sum_error))
}

/// ln x within 1 ulp for every double: the head of [`ln_parts`], which is hi + lo rounded (within
/// ½ ulp + 2⁻⁵⁵ relative). −∞ at ±0, NaN below 0 and for NaN, +∞ at +∞.
#[inline(always)]
pub fn ln(x: f64) -> f64 {
    ln_parts(x).0
}

/// ln x as an unevaluated sum hi + lo (|lo| ≤ ulp(hi)/2) within 2⁻⁵⁶ absolute and 2⁻⁵⁵ relative of the
/// truth, for every double: x = 2^k m with √2/2 ≤ m < √2 (subnormals scaled by 2⁵⁴ first) and ln m by [`log_parts`] with
/// f = m − 1, exact. (−∞, 0) at ±0, (+∞, 0) at +∞, (NaN, NaN) below 0 and for NaN. Exponentiating it
/// as e^{hi} (1 + lo) carries no rounding of the logarithm, so a power p ln x of a large logarithm keeps
/// the relative accuracy of a single product.
#[inline(always)]
pub fn ln_parts(x: f64) -> (f64, f64) {
    /// 2⁵⁴: a subnormal times this is normal.
    const TWO_TO_54: f64 = 18_014_398_509_481_984.0;
    let subnormal = x < f64::MIN_POSITIVE;
    let (k, m) = log_reduce(if subnormal { x * TWO_TO_54 } else { x });
    let k = if subnormal { k - 54.0 } else { k };
    let value = log_parts(m - 1.0, k, 0.0);
    if x == f64::INFINITY {
        (f64::INFINITY, 0.0)
    } else if x == 0.0 {
        (f64::NEG_INFINITY, 0.0)
    } else if x < 0.0 || x.is_nan() {
        (f64::NAN, f64::NAN)
    } else {
        value
    }
}

/// ln(1 + x) as an unevaluated sum hi + lo (|lo| ≤ ulp(hi)/2) within 2⁻⁵⁶ absolute and 2⁻⁵⁵ relative of
/// the truth, for every double: [`ln_1p`]'s reduction 1 + x = u (1 + c) with u = 2^k m rounded and c its first-order
/// correction (kept for every k: it is 1/u where 1 + x rounds to x), then [`log_parts`]; for 1 + x in
/// [√2/2, √2), f = x exactly. (+∞, 0) at +∞, (−∞, 0) at −1, (NaN, NaN) below −1 and for NaN. For
/// ln((1 + x)^p) = p ln(1 + x) with a large logarithm (see [`ln_parts`]).
#[inline(always)]
pub fn ln_1p_parts(x: f64) -> (f64, f64) {
    let u = 1.0 + x;
    let (k, m) = log_reduce(u);
    let correction = if k >= 2.0 {
        1.0 - (u - x)
    } else {
        x - (u - 1.0)
    } / u;
    let near_one = x > LOG1P_NEAR_ONE_MIN && x < LOG1P_NEAR_ONE_MAX;
    let (f, c, k) = if near_one {
        (x, 0.0, 0.0)
    } else {
        (m - 1.0, correction, k)
    };
    let value = log_parts(f, k, c);
    if x == f64::INFINITY {
        (f64::INFINITY, 0.0)
    } else if x == -1.0 {
        (f64::NEG_INFINITY, 0.0)
    } else if x < -1.0 || x.is_nan() {
        (f64::NAN, f64::NAN)
    } else {
        value
    }
}

/// sin(x + y) for |x| ≤ π/4 and |y| ≲ ulp(x) (fdlibm `k_sin.c`, polynomial of degree 13, < 1 ulp).
#[inline(always)]
fn sin_kernel(x: f64, y: f64) -> f64 {
    const S1: f64 = -1.666_666_666_666_663_243_48e-1;
    const S2: f64 = 8.333_333_333_322_489_461_24e-3;
    const S3: f64 = -1.984_126_982_985_794_931_34e-4;
    const S4: f64 = 2.755_731_370_707_006_767_89e-6;
    const S5: f64 = -2.505_076_025_340_686_341_95e-8;
    const S6: f64 = 1.589_690_995_211_550_102_21e-10;
    let z = x * x;
    let v = z * x;
    let r = z.mul_add(z.mul_add(z.mul_add(z.mul_add(S6, S5), S4), S3), S2);
    x - ((z * (0.5 * y - v * r) - y) - v * S1)
}

/// cos(x + y) for |x| ≤ π/4 and |y| ≲ ulp(x) (FreeBSD `k_cos.c`, polynomial of degree 14, < 1 ulp).
#[inline(always)]
fn cos_kernel(x: f64, y: f64) -> f64 {
    const C1: f64 = 4.166_666_666_666_660_190_37e-2;
    const C2: f64 = -1.388_888_888_887_410_957_49e-3;
    const C3: f64 = 2.480_158_728_947_672_941_78e-5;
    const C4: f64 = -2.755_731_435_139_066_330_35e-7;
    const C5: f64 = 2.087_572_321_298_174_827_90e-9;
    const C6: f64 = -1.135_964_755_778_819_482_65e-11;
    let z = x * x;
    let w = z * z;
    let r = z * z.mul_add(z.mul_add(C3, C2), C1) + w * w * z.mul_add(z.mul_add(C6, C5), C4);
    let hz = 0.5 * z;
    let w = 1.0 - hz;
    w + (((1.0 - w) - hz) + (z * r - x * y))
}

/// a + b as the rounded sum and its exact error (Knuth's TwoSum): s + e = a + b exactly, s = fl(a + b).
#[inline(always)]
pub fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let b_virtual = s - a;
    let a_virtual = s - b_virtual;
    (s, (a - a_virtual) + (b - b_virtual))
}

/// (sin x, cos x) within 1 ulp each for |x| < 2²⁰ (the NDFs' θ ∈ [0, π/2] takes n ∈ {0, 1} below):
/// x = n π/2 + r with r a double-double, by π/2 in four parts (fdlibm `e_rem_pio2.c`'s 33 + 33 + 53 + 53
/// bits: n times each of the first two is exact), then the kernels of r and the quadrant n mod 4 selected
/// by bit operations. The reduction is exact to ~2⁻¹¹⁸ for n = 1, so even sin and cos of the double nearest
/// π/2 (cos = 6.12e-17) keep full relative accuracy. Beyond 2²⁰ the reduction loses accuracy gradually.
#[inline(always)]
pub fn sin_cos(x: f64) -> (f64, f64) {
    const FRAC_2_PI: f64 = std::f64::consts::FRAC_2_PI;
    const PIO2_1: f64 = 1.570_796_326_734_125_614_17;
    const PIO2_2: f64 = 6.077_100_506_303_965_976_60e-11;
    const PIO2_3: f64 = 2.022_266_248_711_166_455_80e-21;
    const PIO2_3T: f64 = 8.478_427_660_368_899_569_97e-32;
    let (n_float, n) = round_to_integer(x * FRAC_2_PI);
    let (hi, tail) = two_sum(x - n_float * PIO2_1, -(n_float * PIO2_2));
    let lo = tail - n_float.mul_add(PIO2_3, n_float * PIO2_3T);
    let (s, c) = (sin_kernel(hi, lo), cos_kernel(hi, lo));
    // Quadrant n mod 4: (s, c), (c, −s), (−s, −c), (−c, s).
    let q = n as u64;
    let swap = (q & 1).wrapping_neg();
    let (s_bits, c_bits) = (s.to_bits(), c.to_bits());
    let sin_bits = (c_bits & swap) | (s_bits & !swap);
    let cos_bits = (s_bits & swap) | (c_bits & !swap);
    (
        f64::from_bits(sin_bits ^ ((q & 2) << 62)),
        f64::from_bits(cos_bits ^ ((q.wrapping_add(1) & 2) << 62)),
    )
}

/// tan x = sin x/cos x by [`sin_cos`], within 2 ulps (one more rounding), for |x| < 2²⁰.
#[inline(always)]
pub fn tan(x: f64) -> f64 {
    let (sin_x, cos_x) = sin_cos(x);
    sin_x / cos_x
}

/// arctan x within 1 ulp for every double (fdlibm `s_atan.c`): |x| is reduced to [0, 7/16) by one of
/// atan x = atan c + atan((x − c)/(1 + c x)) with c = ½, 1, 3/2 or ∞ (thresholds 7/16, 11/16, 19/16,
/// 39/16; arctan c in two parts), each case computed and the right one selected, then the odd
/// polynomial of degree 23 split into even and odd parts in x⁴. ±π/2 at ±∞, NaN for NaN.
#[inline(always)]
pub fn atan(x: f64) -> f64 {
    /// arctan c for c = ½, 1, 3/2, ∞: high parts (π/4 and π/2 the doubles fdlibm quotes), then the
    /// rest.
    const ATAN_HI: [f64; 4] = [
        4.636_476_090_008_060_935_15e-1,
        std::f64::consts::FRAC_PI_4,
        9.827_937_232_473_290_540_82e-1,
        std::f64::consts::FRAC_PI_2,
    ];
    const ATAN_LO: [f64; 4] = [
        2.269_877_745_296_168_709_24e-17,
        3.061_616_997_868_383_017_93e-17,
        1.390_331_103_123_099_845_16e-17,
        6.123_233_995_736_766_035_87e-17,
    ];
    const AT: [f64; 11] = [
        3.333_333_333_333_293_180_27e-1,
        -1.999_999_999_987_648_324_76e-1,
        1.428_571_427_250_346_637_11e-1,
        -1.111_111_040_546_235_578_80e-1,
        9.090_887_133_436_506_561_96e-2,
        -7.691_876_205_044_829_994_95e-2,
        6.661_073_137_387_531_206_69e-2,
        -5.833_570_133_790_573_486_45e-2,
        4.976_877_994_615_932_360_17e-2,
        -3.653_157_274_421_691_552_70e-2,
        1.628_582_011_536_578_236_23e-2,
    ];
    let a = x.abs();
    // The case: −1 (no reduction) below 7/16, then 0 … 3; each reduced argument as num/den.
    let (num, den, hi, lo) = if a < 0.4375 {
        (a, 1.0, 0.0, 0.0)
    } else if a < 0.6875 {
        (2.0 * a - 1.0, 2.0 + a, ATAN_HI[0], ATAN_LO[0])
    } else if a < 1.1875 {
        (a - 1.0, a + 1.0, ATAN_HI[1], ATAN_LO[1])
    } else if a < 2.4375 {
        (a - 1.5, 1.0 + 1.5 * a, ATAN_HI[2], ATAN_LO[2])
    } else {
        (-1.0, a, ATAN_HI[3], ATAN_LO[3])
    };
    let r = num / den;
    let z = r * r;
    let w = z * z;
    let s1 = z * w.mul_add(
        w.mul_add(
            w.mul_add(w.mul_add(w.mul_add(AT[10], AT[8]), AT[6]), AT[4]),
            AT[2],
        ),
        AT[0],
    );
    let s2 = w * w.mul_add(
        w.mul_add(w.mul_add(w.mul_add(AT[9], AT[7]), AT[5]), AT[3]),
        AT[1],
    );
    let value = hi - ((r * (s1 + s2) - lo) - r);
    // NaN stays NaN (every comparison above is false and selects the last case, −1/NaN).
    let value = if a.is_nan() { x } else { value };
    f64::from_bits(value.to_bits() | (x.to_bits() & (1 << 63)))
}

/// arsinh x = sign(x) ln(1 + |x| + x²/(1 + √(1 + x²))) by [`ln_1p`], within 2 ulps for |x| up to
/// 1e150 (x² overflows beyond 1.3e154), NaN for NaN.
#[inline(always)]
pub fn asinh(x: f64) -> f64 {
    let a = x.abs();
    let square = a * a;
    let value = ln_1p(a + square / (1.0 + (1.0 + square).sqrt()));
    f64::from_bits(value.to_bits() | (x.to_bits() & (1 << 63)))
}

/// Something evaluated one double at a time by branch-free code: [`map_lanes`] runs it over a block and
/// [`at_one`] at one point, both on the fused multiply-add of the processor where it has one.
pub trait Lanewise {
    /// The value at `x`, computed by code with no branch that depends on `x` beyond selects, so that a
    /// loop over it vectorizes.
    fn at(&self, x: f64) -> f64;
}

/// Whether the processor has fused multiply-add, which [`f64::mul_add`] otherwise computes in software
/// (the same correctly rounded value, some 20 times slower).
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn has_fma() -> bool {
    std::arch::is_x86_feature_detected!("fma")
}

/// `f.at(x)`, compiled with fused multiply-add where the processor has it: the same bits either way.
#[inline(always)]
pub fn at_one<F: Lanewise>(f: &F, x: f64) -> f64 {
    #[cfg(target_arch = "x86_64")]
    if has_fma() {
        // SAFETY: the processor has FMA, checked just above.
        return unsafe { at_fma(f, x) };
    }
    f.at(x)
}

/// [`at_one`] with FMA instructions.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "fma")]
fn at_fma<F: Lanewise>(f: &F, x: f64) -> f64 {
    f.at(x)
}

/// `out[i] = f.at(xs[i])` for every i (the lengths must be equal), run by [`widest`]: the value of each
/// element is the same bits on each path and equals [`at_one`]'s (module header); only the speed depends
/// on the processor.
#[inline(always)]
pub fn map_lanes<F: Lanewise>(f: &F, xs: &[f64], out: &mut [f64]) {
    assert_eq!(xs.len(), out.len(), "one output per argument");
    widest(&mut Map { f, xs, out })
}

/// [`map_lanes`]'s loop.
struct Map<'a, F> {
    f: &'a F,
    xs: &'a [f64],
    out: &'a mut [f64],
}

impl<F: Lanewise> Block for Map<'_, F> {
    #[inline(always)]
    fn run(&mut self) {
        for (o, &x) in self.out.iter_mut().zip(self.xs) {
            *o = self.f.at(x);
        }
    }
}

/// Work over a block of arguments, written with this module's branch-free kernels so that its loops
/// vectorize: [`widest`] compiles it for each instruction set. Its `run` must be `#[inline(always)]`,
/// so that it is compiled inside [`widest`]'s instruction set rather than called from it.
pub trait Block {
    /// Does the work.
    fn run(&mut self);
}

/// `block.run()` compiled for AVX-512F, AVX2 (each with FMA) and the baseline and run in the widest the
/// processor has, so that its loops over this module's kernels run 8, 4 or 2 lanes at a time. Every
/// operation rounds once and the fused multiply-adds are explicit, so its values are the same bits on
/// each path.
#[inline(always)]
pub fn widest<B: Block>(block: &mut B) {
    #[cfg(target_arch = "x86_64")]
    if has_fma() {
        if std::arch::is_x86_feature_detected!("avx512f") {
            // SAFETY: the processor has AVX-512F and FMA, checked just above.
            return unsafe { widest_avx512(block) };
        }
        if std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: the processor has AVX2 and FMA, checked just above.
            return unsafe { widest_avx2(block) };
        }
    }
    block.run()
}

/// [`widest`] with 8 lanes.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,fma")]
fn widest_avx512<B: Block>(block: &mut B) {
    block.run()
}

/// [`widest`] with 4 lanes.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn widest_avx2<B: Block>(block: &mut B) {
    block.run()
}

/// `many(xs, out)` run inside [`widest`] (so in the widest instruction set the processor has) into
/// a fresh output of `xs.len()` values: for tests comparing a block path with its single values.
/// `many` must be an `#[inline(always)]` closure, as a [`Block`]'s `run` must be.
#[cfg(test)]
pub(crate) fn widest_many(xs: &[f64], many: impl Fn(&[f64], &mut [f64])) -> Vec<f64> {
    struct Many<'a, F> {
        many: F,
        xs: &'a [f64],
        out: Vec<f64>,
    }
    impl<F: Fn(&[f64], &mut [f64])> Block for Many<'_, F> {
        #[inline(always)]
        fn run(&mut self) {
            (self.many)(self.xs, &mut self.out);
        }
    }
    let mut block = Many {
        many,
        xs,
        out: vec![0.0; xs.len()],
    };
    widest(&mut block);
    block.out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The distance in ulps from `got` to the libm value `want`, measured in units of the spacing of
    /// doubles at `want` (at least the smallest subnormal): libm is itself within 1 ulp of the truth, so a
    /// bound of b here is b + 1 from the truth at most.
    fn ulps(got: f64, want: f64) -> f64 {
        if got == want || (got.is_nan() && want.is_nan()) {
            return 0.0;
        }
        let spacing = (f64::from_bits(want.abs().to_bits() + 1) - want.abs()).max(5e-324);
        ((got - want) / spacing).abs()
    }

    /// Doubles spread over [lo, hi]: an even grid, and a geometric one when both ends have one sign.
    fn spread(lo: f64, hi: f64, n: usize) -> Vec<f64> {
        let mut xs: Vec<f64> = (0..=n)
            .map(|i| lo + (hi - lo) * i as f64 / n as f64)
            .collect();
        if lo > 0.0 {
            xs.extend((0..=n).map(|i| lo * (hi / lo).powf(i as f64 / n as f64)));
        }
        xs
    }

    fn worst(xs: &[f64], f: impl Fn(f64) -> f64, libm: impl Fn(f64) -> f64) -> (f64, f64) {
        xs.iter()
            .map(|&x| (ulps(f(x), libm(x)), x))
            .fold((0.0, 0.0), |a, b| if b.0 > a.0 { b } else { a })
    }

    #[test]
    fn exp_is_within_one_ulp_of_libm_everywhere() {
        let mut xs = spread(-745.2, 709.8, 400_000);
        xs.extend(spread(1e-300, 1.0, 100_000).iter().flat_map(|&x| [x, -x]));
        xs.extend([
            0.0, -0.0, 709.78, 709.79, -745.13, -745.14, -708.4, -708.3, 1e-320,
        ]);
        let (e, at) = worst(&xs, exp, f64::exp);
        assert!(e <= 1.0, "{e} ulps at {at:e}");
        assert_eq!(exp(f64::INFINITY), f64::INFINITY);
        assert_eq!(exp(f64::NEG_INFINITY), 0.0);
        assert_eq!(exp(710.0), f64::INFINITY);
        assert!(exp(f64::NAN).is_nan());
    }

    #[test]
    fn ln_1p_is_within_one_ulp_of_libm_everywhere() {
        let mut xs = spread(-1.0 + 1e-16, 4.0, 400_000);
        xs.extend(spread(1e-320, f64::MAX, 400_000));
        xs.extend(spread(1e-320, 0.999, 100_000).iter().map(|&x| -x));
        xs.extend([
            0.0,
            -0.0,
            0.414_213_562_373_095_1,
            -0.292_893_218_813_452_4,
            1.0,
            3.0,
        ]);
        let (e, at) = worst(&xs, ln_1p, f64::ln_1p);
        assert!(e <= 1.0, "{e} ulps at {at:e}");
        assert_eq!(ln_1p(f64::INFINITY), f64::INFINITY);
        assert_eq!(ln_1p(-1.0), f64::NEG_INFINITY);
        assert!(ln_1p(-2.0).is_nan() && ln_1p(f64::NAN).is_nan());
    }

    #[test]
    fn ln_is_within_one_ulp_of_libm_everywhere() {
        let mut xs = spread(5e-324, f64::MAX, 400_000);
        xs.extend(spread(0.25, 4.0, 400_000));
        xs.extend(spread(5e-324, f64::MIN_POSITIVE, 20_000));
        xs.extend((0..64).flat_map(|i| {
            [
                1.0 + i as f64 * f64::EPSILON,
                1.0 - i as f64 * f64::EPSILON / 2.0,
            ]
        }));
        xs.extend([
            std::f64::consts::FRAC_1_SQRT_2,
            std::f64::consts::SQRT_2,
            f64::MAX,
        ]);
        let (e, at) = worst(&xs, ln, f64::ln);
        assert!(e <= 1.0, "{e} ulps at {at:e}");
        assert_eq!(ln(f64::INFINITY), f64::INFINITY);
        assert_eq!(ln(0.0), f64::NEG_INFINITY);
        assert_eq!(ln(-0.0), f64::NEG_INFINITY);
        assert_eq!(ln(1.0).to_bits(), 0.0f64.to_bits());
        assert!(ln(-1.0).is_nan() && ln(f64::NAN).is_nan() && ln(f64::NEG_INFINITY).is_nan());
        assert_eq!(ln_1p_parts(f64::INFINITY), (f64::INFINITY, 0.0));
        assert_eq!(ln_1p_parts(-1.0), (f64::NEG_INFINITY, 0.0));
        assert!(ln_1p_parts(-2.0).0.is_nan() && ln_1p_parts(f64::NAN).1.is_nan());
    }

    /// ln x and ln(1 + x) as hi + lo against 60-digit mpmath values split the same way (`float(v)` and
    /// `float(v − float(v))`), at the subnormals, the ends of the reduction's interval, the largest
    /// logarithms and the worst points of a 11 000-point scan: within 2⁻⁵⁶ absolute or 2⁻⁵⁵ relative (the
    /// scan's worst: 6.9e-18 and 1.9e-17), where a rounded double is off by up to ½ ulp of |ln x| ≤ 745.
    #[test]
    // The references are mpmath's digits as Python prints them, ln 2 and e among them.
    #[allow(clippy::approx_constant)]
    fn ln_parts_are_within_2_to_the_minus_56_of_mpmath() {
        let ln_reference: [(f64, f64, f64); 24] = [
            (5e-324, -744.4400719213812, -4.422444340918698e-14),
            (1e-310, -713.8013788281542, -8.592254740270771e-15),
            (
                2.2250738585072014e-308,
                -708.3964185322641,
                -2.7475416721234714e-14,
            ),
            (1e-300, -690.7755278982137, -2.3670096176709832e-14),
            (1e-150, -345.38776394910684, -1.1841282276040347e-14),
            (1e-20, -46.051701859880914, 7.339520394182075e-16),
            (0.1, -2.3025850929940455, -1.7150243628057985e-16),
            (0.5, -0.6931471805599453, -2.3190468138462996e-17),
            (0.7071, -0.346583180371942, 2.3156292029870996e-17),
            (0.75, -0.2876820724517809, -2.607160616442564e-17),
            (0.99, -0.01005033585350145, 4.341832787901688e-19),
            (
                0.9999999999999999,
                -1.1102230246251565e-16,
                -6.162975822039155e-33,
            ),
            (
                1.0000000000000002,
                2.2204460492503128e-16,
                3.649214750845877e-48,
            ),
            (1.01, 0.009950330853168092, -3.736425524726216e-19),
            (
                1.3990402107003306,
                0.33578643772942307,
                -1.7112780484829254e-18,
            ),
            (1.5, 0.4054651081081644, -2.8811380259626426e-18),
            (2.0, 0.6931471805599453, 2.3190468138462996e-17),
            (2.718281828459045, 1.0, -5.318237706605891e-17),
            (10.0, 2.302585092994046, -2.1707562233822494e-16),
            (100000.0, 11.512925464970229, -1.971996919909995e-16),
            (
                1.144706534540248e+32,
                73.8178712782532,
                9.645010861749592e-16,
            ),
            (1e+150, 345.38776394910684, 1.1828413230444957e-14),
            (1e+300, 690.7755278982137, 2.3747660028800243e-14),
            (
                1.7976931348623157e+308,
                709.782712893384,
                2.3636017071323592e-14,
            ),
        ];
        let ln_1p_reference: [(f64, f64, f64); 23] = [
            (1e-300, 1e-300, 0.0),
            (1e-20, 1e-20, -5e-41),
            (1e-08, 9.999999950000001e-09, -4.779087200456198e-25),
            (0.001, 0.0009995003330835331, 3.8971025988294614e-20),
            (0.1, 0.09531017980432487, -3.808451650416249e-19),
            (0.29, 0.25464221837358075, -2.1836189499910014e-17),
            (
                0.40176942717779623,
                0.3377353151571359,
                2.4843878107526082e-17,
            ),
            (
                0.4142135623730951,
                0.3465735902799727,
                -1.4810142052501475e-17,
            ),
            (0.5, 0.4054651081081644, -2.8811380259626426e-18),
            (1.0, 0.6931471805599453, 2.3190468138462996e-17),
            (3.0, 1.3862943611198906, 4.638093627692599e-17),
            (1000.0, 6.90875477931522, 1.6736394835204341e-16),
            (9007199254740992.0, 36.7368005696771, 7.850056014884762e-16),
            (9007199254740994.0, 36.7368005696771, 1.0070502064135074e-15),
            (
                1.8014398509481984e+16,
                37.42994775023705,
                -1.1346942234670848e-15,
            ),
            (1e+20, 46.051701859880914, -7.88788767963998e-16),
            (1e+100, 230.25850929940458, -1.1033518306311232e-14),
            (1e+300, 690.7755278982137, 2.3747660028800243e-14),
            (-0.29, -0.3424903089467759, -1.7582174471307058e-17),
            (-0.3, -0.35667494393873234, -2.6895094047056423e-17),
            (-0.5, -0.6931471805599453, -2.3190468138462996e-17),
            (-0.9, -2.302585092994046, -4.968982586806388e-18),
            (
                -0.9999999999999999,
                -36.7368005696771,
                -6.739832990259606e-16,
            ),
        ];
        let check = |name: &str, f: fn(f64) -> (f64, f64), reference: &[(f64, f64, f64)]| {
            for &(x, want_hi, want_lo) in reference {
                let (hi, lo) = f(x);
                assert!(lo.abs() <= 0.5 * (f64::from_bits(hi.abs().to_bits() + 1) - hi.abs()));
                let error = ((hi - want_hi) + (lo - want_lo)).abs();
                let bound = 2f64.powi(-56).max(2f64.powi(-55) * want_hi.abs());
                assert!(
                    error <= bound,
                    "{name}({x:e}): {hi:e} + {lo:e}, off by {error:e}"
                );
                // The head alone is the logarithm rounded to nearest, but for the pair's error.
                let spacing = f64::from_bits(want_hi.abs().to_bits() + 1) - want_hi.abs();
                assert!(
                    ((hi - want_hi) - want_lo).abs() <= (0.5 + 2f64.powi(-3)) * spacing,
                    "{name}({x:e}) head {hi:e}"
                );
            }
        };
        check("ln_parts", ln_parts, &ln_reference);
        check("ln_1p_parts", ln_1p_parts, &ln_1p_reference);
    }

    #[test]
    fn sin_cos_are_within_one_ulp_of_libm_over_the_ndf_range_and_beyond() {
        let half_pi = std::f64::consts::FRAC_PI_2;
        let mut xs = spread(0.0, half_pi, 400_000);
        xs.extend(spread(1e-300, half_pi, 100_000));
        // Towards π/2 from below, down to the double nearest it.
        xs.extend((1..=100_000).map(|i| half_pi - half_pi * 2f64.powf(-(i as f64) / 2000.0)));
        xs.extend((0..64).map(|i| f64::from_bits(half_pi.to_bits() - i)));
        xs.extend(spread(-1e5, 1e5, 400_000));
        let (e, at) = worst(&xs, |x| sin_cos(x).0, f64::sin);
        assert!(e <= 1.0, "sin: {e} ulps at {at:e}");
        let (e, at) = worst(&xs, |x| sin_cos(x).1, f64::cos);
        assert!(e <= 1.0, "cos: {e} ulps at {at:e}");
        let (e, at) = worst(&xs, tan, f64::tan);
        assert!(e <= 2.0, "tan: {e} ulps at {at:e}");
        assert!(sin_cos(f64::NAN).0.is_nan() && sin_cos(f64::INFINITY).1.is_nan());
    }

    #[test]
    fn atan_is_within_one_ulp() {
        let mut xs = spread(1e-300, 1e300, 20_000);
        xs.extend(spread(0.0, 4.0, 40_000));
        xs.extend([
            0.4375,
            0.6875,
            1.1875,
            2.4375,
            1.0,
            0.5,
            1.5,
            f64::MAX,
            5e-324,
        ]);
        xs.extend(xs.clone().iter().map(|x| -x));
        let (e, at) = worst(&xs, atan, f64::atan);
        assert!(e <= 1.0, "atan: {e} ulps at {at:e}");
        assert_eq!(atan(f64::INFINITY), std::f64::consts::FRAC_PI_2);
        assert_eq!(atan(f64::NEG_INFINITY), -std::f64::consts::FRAC_PI_2);
        assert!(atan(f64::NAN).is_nan());
        assert_eq!(atan(-0.0).to_bits(), (-0.0f64).to_bits());
    }

    #[test]
    fn asinh_is_within_two_ulps() {
        let mut xs = spread(1e-300, 1e150, 20_000);
        xs.extend(spread(0.0, 10.0, 20_000));
        xs.extend(xs.clone().iter().map(|x| -x));
        let (e, at) = worst(&xs, asinh, f64::asinh);
        assert!(e <= 2.0, "asinh: {e} ulps at {at:e}");
        assert!(asinh(f64::NAN).is_nan());
        assert_eq!(asinh(-0.0).to_bits(), (-0.0f64).to_bits());
    }

    /// The block loop gives the bits of the one-at-a-time call, whatever instruction set it runs in:
    /// the dispatched one (AVX-512 or AVX2 with FMA here) and the baseline's, with FMA in software.
    #[test]
    fn blocks_equal_single_calls() {
        struct Chain;
        impl Lanewise for Chain {
            fn at(&self, x: f64) -> f64 {
                let (s, c) = sin_cos(x);
                exp(-ln_1p(s / c * (s / c)) * 3.0)
            }
        }
        let xs = spread(0.0, std::f64::consts::FRAC_PI_2, 10_007);
        let (mut out, mut baseline) = (vec![0.0; xs.len()], vec![0.0; xs.len()]);
        map_lanes(&Chain, &xs, &mut out);
        for (b, &x) in baseline.iter_mut().zip(&xs) {
            *b = Chain.at(x);
        }
        for ((&x, &o), &b) in xs.iter().zip(&out).zip(&baseline) {
            assert_eq!(o.to_bits(), Chain.at(x).to_bits(), "at {x:e}");
            assert_eq!(o.to_bits(), at_one(&Chain, x).to_bits(), "at {x:e}");
            assert_eq!(o.to_bits(), b.to_bits(), "at {x:e}");
        }
    }
}
