// D of Beckmann for the interactive page: the port of `eval` in beckmann.rs, in its stable form and
// operation order. An expression: parameters (in the family's order) → θ → D(θ).
([alphaB]) => {
  const lnPeak = -Math.log(PI) - 2 * Math.log(alphaB);
  return (t) => {
    const tan = Math.tan(t);
    return Math.exp(lnPeak - powi(tan / alphaB, 2) + 2 * Math.log1p(tan * tan));
  };
}
