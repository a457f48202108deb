// D of Phong for the interactive page: the port of `eval` in phong.rs, in its stable form and
// operation order. An expression: parameters (in the family's order) → θ → D(θ).
([alphaP]) => {
  const lnInvN = Math.log((alphaP + 2) / (2 * PI));
  return (t) => Math.exp(lnInvN - 0.5 * alphaP * Math.log1p(powi(Math.tan(t), 2)));
}
