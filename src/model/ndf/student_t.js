// D of the Student-t slope distribution for the interactive page: the port of `eval` in student_t.rs, in its
// stable form and operation order. An expression: parameters (in the family's order) → θ → D(θ).
([alpha, gamma]) => {
  const MIN_POSITIVE = 2.2250738585072014e-308;
  const LN_1P_SQUARE_LOG_MIN = 1e150;
  const sqrtGammaM1 = Math.sqrt(gamma - 1);
  const sin2Weight = 1 / (alpha * (gamma - 1));
  const dExponentRatio = (gamma - 2) / (gamma - 1);
  return (t) => {
    const [s, c] = [Math.sin(t), Math.cos(t)];
    const q = alpha * c * c + s * s * sin2Weight;
    const r = Math.tan(t) / alpha;
    const v = r / sqrtGammaM1;
    let exponent;
    if (v < 1) {
      const v2 = v * v;
      exponent = -dExponentRatio * (r * r) * (v2 === 0 ? 1 : Math.log1p(v2) / v2);
    } else {
      exponent = -(gamma - 2) * (v < LN_1P_SQUARE_LOG_MIN ? Math.log1p(v * v) : 2 * Math.log(v));
    }
    const invQ = 1 / q;
    const base = invQ * invQ * (1 / PI);
    if (Number.isFinite(base) && base >= MIN_POSITIVE && exponent > Math.log(MIN_POSITIVE)) return base * Math.exp(exponent);
    return Math.exp(exponent - 2 * Math.log(q) - Math.log(PI));
  };
}
