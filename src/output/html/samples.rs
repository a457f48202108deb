//! The compact byte encoding of one curve's dyadic samples ([`crate::dyadic`]) on an
//! interactive page, which `page.js` decodes.
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
//! A decoded value e^{q·LOG_STEP} is within e^{LOG_STEP/2} − 1 < [`PRECISION`] of the sampled
//! value, relative. Pure serialization: it evaluates nothing.

use crate::dyadic::Samples;

/// Relative precision of every drawn value against `Curve::eval` (README, page note).
pub const PRECISION: f64 = 1e-4;
/// Quantization step of ln|y|: rounding errs by at most half a step, e^{0.9e-4} − 1 = 9.0004e-5,
/// which leaves 10 % of [`PRECISION`] for the f64 rounding of ln, exp and the product q·step.
pub const LOG_STEP: f64 = 1.8e-4;

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
    use crate::dyadic::{COARSE_LEVELS, FINE_LEVELS, sample, theta};
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
