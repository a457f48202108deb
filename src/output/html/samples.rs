//! One precomputed curve of an interactive page: adaptive samples on a dyadic θ grid and their
//! compact byte encoding, which `page.js` decodes.
//!
//! Sampling: θ_k = lo + k·((hi − lo)/2^[`FINE_LEVELS`]); the [`COARSE_LEVELS`] first bisection
//! levels are always taken (33 evenly spaced samples), and each deeper interval is bisected when its midpoint sits farther from the chord than
//! [`LINEAR_TOLERANCE`] of the curve's largest |value| (the linear view) or, where the values lie
//! within [`LOG_DECADES`] of that largest value, [`LOG_TOLERANCE`] in ln (the log view). Unlike the
//! figure sampler, the grid is dyadic and judged for both y scales, because the page toggles the
//! scale and the tree of bisections encodes θ in one bit per interval.
//!
//! Encoding, byte after byte:
//! 1. one flag byte: bit 0 set when some value is 0 or negative;
//! 2. the bisection tree in pre-order, one bit per interval that may still split (1 = split),
//!    packed most significant bit first and padded to a whole byte;
//! 3. with flag bit 0, one class byte per sample: 0 zero, 1 positive, 2 negative;
//! 4. per sample, the zigzag LEB128 varint of q_i − p_i, where q = round(ln|y| / [`LOG_STEP`]) and
//!    p_i the linear extrapolation from the two previous samples, in integers:
//!    p_i = q_{i−1} + floor((q_{i−1} − q_{i−2})·(k_i − k_{i−1}) / (k_{i−1} − k_{i−2})), p_1 = q_0,
//!    p_0 = 0; a zero value takes q_i = p_i.
//!
//! A decoded value e^{q·LOG_STEP} is within e^{LOG_STEP/2} − 1 < [`PRECISION`] of the value
//! `Curve::eval` gave, relative. The module evaluates only the closure it is handed.

/// Levels of the finest θ grid: 2^14 intervals, θ steps of 9.6e-5 rad over [0, π/2].
pub const FINE_LEVELS: u32 = 14;
/// Levels always bisected: 2^5 = 32 initial intervals of 0.05 rad over [0, π/2], so that a lobe
/// cannot hide between samples: every NDF lobe of the catalogue peaks at θ = 0 or π/2 or is wider,
/// and the chord test then resolves even Phong α_p = 8000 (half-width 0.016 rad) at θ = 0.
pub const COARSE_LEVELS: u32 = 5;
/// Relative precision of every drawn value against `Curve::eval` (README, page note).
pub const PRECISION: f64 = 1e-4;
/// Quantization step of ln|y|: rounding errs by at most half a step, e^{0.9e-4} − 1 = 9.0004e-5,
/// which leaves 10 % of [`PRECISION`] for the f64 rounding of ln, exp and the product q·step.
pub const LOG_STEP: f64 = 1.8e-4;
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

/// The quantized ln|y| of a non-zero value.
fn quantize(y: f64) -> i64 {
    (y.abs().ln() / LOG_STEP).round() as i64
}

/// p_i of sample `i` at grid index `k`, from the two previous (k, q) in `history` (oldest first).
fn predict(i: usize, history: &[(i64, i64); 2], k: i64) -> i64 {
    let [(k2, q2), (k1, q1)] = *history;
    match i {
        0 => 0,
        1 => q1,
        _ => q1 + ((q1 - q2) * (k - k1)).div_euclid(k1 - k2),
    }
}

/// The byte encoding of `samples` described in the module header.
pub fn encode(samples: &Samples) -> Vec<u8> {
    let signed = samples.values.iter().any(|&y| y <= 0.0);
    let mut bytes = vec![u8::from(signed)];
    for chunk in samples.tree.chunks(8) {
        bytes.push(
            chunk
                .iter()
                .enumerate()
                .fold(0u8, |byte, (i, &bit)| byte | (u8::from(bit) << (7 - i))),
        );
    }
    if signed {
        bytes.extend(samples.values.iter().map(|&y| match y {
            0.0 => 0u8,
            y if y > 0.0 => 1,
            _ => 2,
        }));
    }
    let mut history: [(i64, i64); 2] = [(0, 0); 2];
    for (i, (&k, &y)) in samples.ks.iter().zip(&samples.values).enumerate() {
        let k = i64::from(k);
        let prediction = predict(i, &history, k);
        let q = if y == 0.0 { prediction } else { quantize(y) };
        let residual = q - prediction;
        history = [history[1], (k, q)];
        let mut zigzag = (residual << 1 ^ residual >> 63) as u64;
        loop {
            let low = (zigzag & 0x7f) as u8;
            zigzag >>= 7;
            if zigzag == 0 {
                bytes.push(low);
                break;
            }
            bytes.push(low | 0x80);
        }
    }
    bytes
}

/// Standard base64 (RFC 4648, with padding), for embedding the bytes in the page's JSON.
pub fn base64(bytes: &[u8]) -> String {
    const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut text = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let n = chunk
            .iter()
            .enumerate()
            .fold(0u32, |n, (i, &b)| n | u32::from(b) << (16 - 8 * i));
        for i in 0..4 {
            if i <= chunk.len() {
                text.push(char::from(ALPHABET[(n >> (18 - 6 * i) & 0x3f) as usize]));
            } else {
                text.push('=');
            }
        }
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::FRAC_PI_2;

    /// Decodes [`encode`]'s bytes as `page.js` does.
    fn decode(bytes: &[u8]) -> (Vec<u32>, Vec<f64>) {
        let mut bit = 0usize;
        let mut read_bit = || {
            let b = bytes[1 + bit / 8] >> (7 - bit % 8) & 1;
            bit += 1;
            b == 1
        };
        fn walk(a: u32, b: u32, level: u32, read_bit: &mut dyn FnMut() -> bool, ks: &mut Vec<u32>) {
            if level < FINE_LEVELS && read_bit() {
                let m = (a + b) / 2;
                walk(a, m, level + 1, read_bit, ks);
                ks.push(m);
                walk(m, b, level + 1, read_bit, ks);
            }
        }
        let coarse = 1u32 << (FINE_LEVELS - COARSE_LEVELS);
        let mut ks = vec![0];
        for j in 0..1u32 << COARSE_LEVELS {
            walk(
                j * coarse,
                (j + 1) * coarse,
                COARSE_LEVELS,
                &mut read_bit,
                &mut ks,
            );
            ks.push((j + 1) * coarse);
        }
        let mut pos = 1 + bit.div_ceil(8);
        let classes = (bytes[0] & 1 == 1).then(|| {
            pos += ks.len();
            bytes[pos - ks.len()..pos].to_vec()
        });
        let mut history = [(0i64, 0i64); 2];
        let mut values = Vec::new();
        for i in 0..ks.len() {
            let (mut u, mut shift) = (0u64, 0);
            loop {
                let byte = bytes[pos];
                pos += 1;
                u |= u64::from(byte & 0x7f) << shift;
                shift += 7;
                if byte & 0x80 == 0 {
                    break;
                }
            }
            let k = i64::from(ks[i]);
            let q = predict(i, &history, k) + ((u >> 1) as i64 ^ -((u & 1) as i64));
            history = [history[1], (k, q)];
            let class = classes.as_ref().map_or(1, |c| c[i]);
            values.push(match class {
                0 => 0.0,
                1 => (q as f64 * LOG_STEP).exp(),
                _ => -(q as f64 * LOG_STEP).exp(),
            });
        }
        assert_eq!(pos, bytes.len());
        (ks, values)
    }

    #[test]
    fn decoded_values_are_within_the_precision_and_refined_where_curves_bend() {
        let range = (0.0, FRAC_PI_2);
        let beckmann = |t: f64| {
            (-(t.tan() / 0.1).powi(2)).exp() / (std::f64::consts::PI * 0.01 * t.cos().powi(4))
        };
        let signed = |t: f64| (3.0 * t).sin() - 0.5;
        for f in [&beckmann as &dyn Fn(f64) -> f64, &signed] {
            let samples = sample(f, range).unwrap();
            let (ks, values) = decode(&encode(&samples));
            assert_eq!(ks, samples.ks);
            assert!(
                ks.windows(2).all(|w| w[0] < w[1])
                    && ks[0] == 0
                    && *ks.last().unwrap() == 1 << FINE_LEVELS
            );
            for ((&k, &y), &exact) in ks.iter().zip(&values).zip(&samples.values) {
                assert_eq!(exact, f(theta(range, k)));
                assert!(
                    (y - exact).abs() <= PRECISION * exact.abs(),
                    "{y} vs {exact}"
                );
            }
        }
        // The narrow Beckmann lobe is refined beyond the coarse grid, its flat tail is not.
        let samples = sample(&beckmann, range).unwrap();
        let coarse = 1 << (FINE_LEVELS - COARSE_LEVELS);
        let fine_near_peak = samples
            .ks
            .iter()
            .filter(|&&k| k < 1 << (FINE_LEVELS - 3) && k % coarse != 0)
            .count();
        assert!(fine_near_peak > 10, "{fine_near_peak}");
        assert!(samples.ks.len() < 600, "{}", samples.ks.len());
    }

    #[test]
    fn non_finite_values_are_errors_and_base64_matches_rfc_4648() {
        assert!(
            sample(&|t| if t > 1.0 { f64::NAN } else { 1.0 }, (0.0, FRAC_PI_2))
                .unwrap_err()
                .contains("non-finite")
        );
        assert_eq!(base64(b"f"), "Zg==");
        assert_eq!(base64(b"fo"), "Zm8=");
        assert_eq!(base64(b"foobar"), "Zm9vYmFy");
        assert_eq!(base64(&[0xfb, 0xff]), "+/8=");
    }
}
