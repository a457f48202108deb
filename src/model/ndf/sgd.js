// D of SGD for the interactive page: the port of `eval` in sgd.rs, in its stable form and
// operation order. An expression: parameters (in the family's order) → θ → D(θ).
([a1, a2]) => {
  const lnPeak = -(a2 + 1) * Math.log(a1) - Math.log(upperGammaScaled(1 - a2, a1)) - Math.log(PI);
  return (t) => {
    const tan = Math.tan(t);
    const tan2 = tan * tan;
    return Math.exp(lnPeak - tan2 / a1 - a2 * Math.log1p(powi(tan / a1, 2)) + 2 * Math.log1p(tan2));
  };
}
