// D of Trowbridge–Reitz for the interactive page: the port of `eval` in trowbridge_reitz.rs, in its stable form and
// operation order. An expression: parameters (in the family's order) → θ → D(θ).
([alphaTr]) => {
  const alpha2 = alphaTr * alphaTr;
  return (t) => {
    const [s, c] = [Math.sin(t), Math.cos(t)];
    return powi(alphaTr / (s * s + alpha2 * c * c), 2) * (1 / PI);
  };
}
