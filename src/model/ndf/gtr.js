// D of GTR for the interactive page: the port of `eval` in gtr.rs, in its stable form and
// operation order. An expression: parameters (in the family's order) → θ → D(θ).
(() => {
  function gtrPeak(k, gamma) {
    if (k === 0) return 1 / PI;
    const m = Math.log1p(k);
    const y = (1 - gamma) * m;
    if (y > 1) return ((1 - gamma) * k) / (PI * ((1 + k) * Math.pow(1 + k, -gamma) - 1));
    return k / m / (PI * exprel(y));
  }
  return ([alpha, gamma]) => {
    const [kSin, kCos] = alpha < 1 ? [((1 - alpha) * (1 + alpha)) / (alpha * alpha), 0] : [0, (alpha - 1) * (alpha + 1)];
    const peak = gtrPeak(kSin + kCos, gamma);
    const scale = gamma <= 1 ? peak : Math.pow(peak, 1 / gamma);
    return (t) => {
      const [s, c] = [Math.sin(t), Math.cos(t)];
      const q = 1 + kSin * s * s + kCos * c * c;
      return gamma <= 1 ? scale * Math.pow(q, -gamma) : Math.pow(scale / q, gamma);
    };
  };
})()
