// D of ABC for the interactive page: the port of `eval` in abc.rs, in its stable form and
// operation order. An expression: parameters (in the family's order) → θ → D(θ).
(() => {
  const ABC_SERIES_MAX_LN_U = 1;
  const ABC_SERIES_MAX_TERMS = 40;
  function abcNormalization(a1, a2) {
    const lnU = Math.log1p(a1);
    if (lnU <= ABC_SERIES_MAX_LN_U) {
      const c = (2 - a2) * lnU;
      let sum = 0;
      let lnUPower = 1;
      for (let m = 0; m < ABC_SERIES_MAX_TERMS; m++) {
        const term = lnUPower * phi(m + 2, c);
        sum += term;
        if (term <= EPS * sum) break;
        lnUPower *= lnU;
      }
      return 2 * PI * powi(lnU / a1, 2) * sum;
    }
    const bracketOverA1 = (1 + 1 / a1) * exprel((1 - a2) * lnU) - exprel((2 - a2) * lnU) / a1;
    return 2 * PI * (lnU / a1) * bracketOverA1;
  }
  return ([a1, a2]) => {
    const lnPeak = -Math.log(abcNormalization(a1, a2));
    return (t) => Math.exp(lnPeak - a2 * Math.log1p(a1 * (2 * powi(Math.sin(0.5 * t), 2))));
  };
})()
