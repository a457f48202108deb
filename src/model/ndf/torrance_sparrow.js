// D of Torrance–Sparrow for the interactive page: the port of `eval` in torrance_sparrow.rs, in its stable form and
// operation order. An expression: parameters (in the family's order) → θ → D(θ).
(() => {
  // Torrance–Sparrow N = π ∫₀^{π/2} e^{−θ²/α²} sin 2θ dθ. For α ≤ 0.01 the tail beyond π/2 is
  // below e^{−24674} and N = π α F(α) with Dawson's series F(α) = α − 2α³/3 + 4α⁵/15 − 8α⁷/105
  // (next term 16α⁹/945 < 2e-18 relative). Beyond, the integrand is below 2.4e-19 of its peak
  // for θ > 6.5α: 16 panels of 20 Gauss nodes over [0, min(π/2, 6.5α)] resolve it to ~1e-16.
  const TS_SERIES_MAX_ALPHA = 0.01;
  const TS_CUTOFF_WIDTHS = 6.5;
  const TS_PANELS = 16;
  function torranceSparrowNormalization(alpha) {
    if (alpha <= TS_SERIES_MAX_ALPHA) {
      const a2 = alpha * alpha;
      return PI * a2 * (1 + a2 * (-2 / 3 + a2 * (4 / 15 - (8 / 105) * a2)));
    }
    const hi = Math.min(PI / 2, TS_CUTOFF_WIDTHS * alpha);
    return PI * integrate((t) => Math.exp(-powi(t / alpha, 2)) * Math.sin(2 * t), 0, hi, TS_PANELS);
  }
  return ([alphaTs]) => {
    const lnPeak = -Math.log(torranceSparrowNormalization(alphaTs));
    return (t) => Math.exp(lnPeak - powi(t / alphaTs, 2));
  };
})()
