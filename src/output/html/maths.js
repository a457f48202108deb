// The curve maths of an interactive ndfplot page: a line-by-line port of the Rust definitions that
// `ndfplot eval` uses (src/model/ndf/*.rs, src/model/fresnel/{exact,approx,gulbrandsen,basis}.rs,
// src/model/math/special.rs), in the same stable forms and operation order, so that a page's values agree
// with `eval` to 1e-12 relative (src/output/html/maths.rs tests this over every family's domain).
// The one change of method is the Torrance–Sparrow normalization: Rust forms it from Dawson's and
// the Faddeeva function, which have no compact JavaScript port; here it is a Gauss–Legendre
// quadrature of the same integral (or its small-α series), equal to ~1e-15.
// Parameter domains and the Fresnel basis are not written here: the page embeds them from the Rust
// registry and basis. Defines `ndfplotMaths(domains, basis)`.
"use strict";
function ndfplotMaths(domains, basis) {
  const PI = Math.PI;
  const EPS = 2.220446049250313e-16;
  const MAX_TERMS = 1000;

  // x^n for a whole n ≥ 1 by binary powering, the multiplication order of Rust's powi.
  function powi(x, n) {
    let result = 1;
    let base = x;
    for (let k = n; ; ) {
      if (k & 1) result *= base;
      k >>= 1;
      if (k === 0) return result;
      base *= base;
    }
  }

  // ---- src/model/math/special.rs ----
  function exprel(x) {
    return x === 0 ? 1 : Math.expm1(x) / x;
  }
  function invFactorial(n) {
    let acc = 1;
    for (let i = 1; i <= n; i++) acc /= i;
    return acc;
  }
  function phi(k, z) {
    if (z >= 0) {
      let term = invFactorial(k);
      let sum = term;
      for (let j = 1; j < MAX_TERMS; j++) {
        term *= z / (k + j);
        sum += term;
        if (term <= EPS * sum) break;
      }
      return sum;
    }
    const x = -z;
    if (k < x) {
      let phiI = exprel(z);
      let invFactI = 1;
      for (let i = 1; i < k; i++) {
        phiI = (phiI - invFactI) / z;
        invFactI /= i + 1;
      }
      return phiI;
    }
    let powerOverFact = 1;
    let sum = 1 / k;
    for (let j = 1; j < MAX_TERMS; j++) {
      powerOverFact *= x / j;
      const term = powerOverFact / (k + j);
      sum += term;
      if (j > x && term <= EPS * sum) break;
    }
    return Math.exp(-x) * invFactorial(k - 1) * sum;
  }
  // Taylor coefficients of 1/Γ(1 + s) (special.rs INV_GAMMA_1P_TAYLOR, same digits).
  const INV_GAMMA_1P_TAYLOR = [
    1.0, 0.57721566490153286061, -0.65587807152025388108, -0.042002635034095235529,
    0.1665386113822914895, -0.042197734555544336748, -0.0096219715278769735621,
    0.0072189432466630995424, -0.0011651675918590651121, -0.00021524167411495097282,
    0.00012805028238811618615, -0.000020134854780788238656, -1.2504934821426706573e-6,
    1.1330272319816958824e-6, -2.0563384169776071035e-7, 6.1160951044814158179e-9,
    5.0020076444692229301e-9, -1.1812745704870201446e-9, 1.0434267116911005105e-10,
    7.782263439905071254e-12, -3.6968056186422057082e-12, 5.100370287454475979e-13,
    -2.0583260535665067832e-14, -5.3481225394230179824e-15, 1.2267786282382607902e-15,
    -1.1812593016974587695e-16, 1.1866922547516003326e-18,
  ];
  function gamma1pMinusOneOverS(s) {
    let h = 0;
    for (let k = INV_GAMMA_1P_TAYLOR.length - 1; k >= 1; k--) h = h * s + INV_GAMMA_1P_TAYLOR[k];
    return -h / (1 + s * h);
  }
  function upperGammaSmallX(s, x) {
    const lnX = Math.log(x);
    let powerOverFact = 1;
    let tail = 0;
    for (let n = 1; n < MAX_TERMS; n++) {
      powerOverFact *= -x / n;
      const term = powerOverFact / (s + n);
      tail += term;
      if (Math.abs(term) <= EPS * Math.abs(tail)) break;
    }
    return gamma1pMinusOneOverS(s) - lnX * exprel(s * lnX) - Math.pow(x, s) * tail;
  }
  function upperGammaScaledCf(s, x) {
    const tiny = 2.2250738585072014e-308 / EPS;
    let b = x + 1 - s;
    let c = 1 / tiny;
    let d = 1 / b;
    let h = d;
    for (let i = 1; i < MAX_TERMS; i++) {
      const an = -i * (i - s);
      b += 2;
      d = an * d + b;
      if (Math.abs(d) < tiny) d = tiny;
      c = b + an / c;
      if (Math.abs(c) < tiny) c = tiny;
      d = 1 / d;
      const delta = d * c;
      h *= delta;
      if (Math.abs(delta - 1) <= EPS) break;
    }
    return Math.pow(x, s) * h;
  }
  // eˣ Γ(s, x) for x > 0 and every real s (special.rs upper_gamma_scaled).
  function upperGammaScaled(s, x) {
    if (s < 1 && x >= 1) return upperGammaScaledCf(s, x);
    if (s < 0 && x < 1) {
      // Rust's f64::round rounds half away from zero; Math.round rounds half up.
      const steps = -Math.sign(s) * Math.round(Math.abs(s));
      const s0 = s + steps;
      let g = upperGammaSmallX(s0, x) * Math.exp(x);
      for (let j = 0; j < steps; j++) {
        const sj = s0 - j;
        g = (g - Math.pow(x, sj - 1)) / (sj - 1);
      }
      return g;
    }
    const steps = Math.floor(s);
    const s0 = s - steps;
    let g = x >= 1 ? upperGammaScaledCf(s0, x) : upperGammaSmallX(s0, x) * Math.exp(x);
    for (let j = 0; j < steps; j++) {
      const sj = s0 + j;
      g = sj * g + Math.pow(x, sj);
    }
    return g;
  }

  // Gauss–Legendre nodes and weights on [−1, 1] (Newton on P_n from Chebyshev guesses).
  function gaussLegendre(n) {
    const nodes = [];
    const weights = [];
    for (let i = 1; i <= n; i++) {
      let x = Math.cos((PI * (i - 0.25)) / (n + 0.5));
      let dp = 0;
      for (let iter = 0; iter < 100; iter++) {
        let p0 = 1;
        let p1 = x;
        for (let k = 2; k <= n; k++) [p0, p1] = [p1, ((2 * k - 1) * x * p1 - (k - 1) * p0) / k];
        dp = (n * (x * p1 - p0)) / (x * x - 1);
        const step = p1 / dp;
        x -= step;
        if (Math.abs(step) <= 1e-17) break;
      }
      nodes.push(x);
      weights.push(2 / ((1 - x * x) * dp * dp));
    }
    return { nodes, weights };
  }
  const GAUSS = gaussLegendre(20);
  // ∫ f over [a, b] by `panels` equal panels of the 20-node Gauss–Legendre rule.
  function integrate(f, a, b, panels) {
    const width = (b - a) / panels;
    let sum = 0;
    for (let p = 0; p < panels; p++) {
      const mid = a + (p + 0.5) * width;
      for (let i = 0; i < GAUSS.nodes.length; i++) sum += GAUSS.weights[i] * f(mid + 0.5 * width * GAUSS.nodes[i]);
    }
    return 0.5 * width * sum;
  }

  // ---- the NDF families: each family's PAGE_FORMULA (src/model/ndf/<family>.js), assembled by
  // src/output/html/maths.rs from the registry into {name: parameters → θ → D(θ)} ----
  const NDFS = NDF_FORMULAS;

  // ---- src/model/fresnel/exact.rs: complex numbers as [re, im] ----
  const cMul = (a, b) => [a[0] * b[0] - a[1] * b[1], a[0] * b[1] + a[1] * b[0]];
  const cNorm = (z) => Math.hypot(z[0], z[1]);
  function principalSqrt(z) {
    if (z[0] === 0 && z[1] === 0) return z;
    const t = Math.sqrt((Math.abs(z[0]) + cNorm(z)) / 2);
    if (z[0] >= 0) return [t, z[1] / (2 * t)];
    const signed = z[1] < 0 || Object.is(z[1], -0) ? -t : t;
    return [Math.abs(z[1]) / (2 * t), signed];
  }
  const NORMAL = { cos: 1, sin2: 0 };
  const fromTheta = (t) => ({ cos: Math.cos(t), sin2: powi(Math.sin(t), 2) });
  const fromCos = (c) => ({ cos: c, sin2: (1 - c) * (1 + c) });
  // The interface of exact.rs: "index1", "tir", or {c, sin2, eta2, w}.
  function interfaceOf(incidence, index) {
    const { eta, etaMinusOne, kappa } = index;
    if (etaMinusOne === 0 && kappa === 0) return "index1";
    const c = incidence.cos;
    const cos2 = c * c;
    const eta2 = cMul([eta, kappa], [eta, kappa]);
    const a = [etaMinusOne * (eta + 1) - kappa * kappa, 2 * eta * kappa];
    const w2 =
      Math.abs(a[0]) + Math.abs(a[1]) + cos2 <= Math.abs(eta2[0]) + Math.abs(eta2[1]) + incidence.sin2
        ? [a[0] + cos2, a[1]]
        : [eta2[0] - incidence.sin2, eta2[1]];
    if (kappa === 0 && w2[0] <= 0) return "tir";
    return { c, sin2: incidence.sin2, eta2, w: principalSqrt(w2) };
  }
  function reflectance(incidence, index) {
    const i = interfaceOf(incidence, index);
    if (i === "index1") return 0;
    if (i === "tir") return 1;
    const absA = Math.hypot(index.etaMinusOne, index.kappa) * Math.hypot(index.eta + 1, index.kappa);
    const absSDen = cNorm([i.w[0] + i.c, i.w[1]]);
    const rS = absA / absSDen / absSDen;
    const absPDen = cNorm([i.eta2[0] * i.c + i.w[0], i.eta2[1] * i.c + i.w[1]]);
    const cc = i.c * i.c;
    const rP = (absA / absPDen) * (cNorm([i.eta2[0] * cc - i.sin2, i.eta2[1] * cc]) / absPDen);
    return Math.min(0.5 * (rS * rS + rP * rP), 1);
  }

  // ---- src/model/fresnel/gulbrandsen.rs ----
  function gulbrandsenEta(r, g) {
    const sqrtR = Math.sqrt(r);
    const etaMin = (1 - r) / (1 + r);
    const etaMax = ((1 + sqrtR) * (1 + sqrtR)) / (1 - r);
    return g * etaMin + (1 - g) * etaMax;
  }
  function gulbrandsenIndex(r, g) {
    if (r === 0) return { eta: 1, etaMinusOne: 0, kappa: 0 };
    const sqrtR = Math.sqrt(r);
    const q = (1 + sqrtR) / (1 - r);
    const etaMinusOne = (-2 * g * r) / (1 + r) + 2 * (1 - g) * sqrtR * q;
    const kappa = 2 * Math.sqrt(g * r) * Math.sqrt(g / ((1 + r) * (1 + r)) + (2 * (1 - g) * q * q) / (1 + r));
    return { eta: gulbrandsenEta(r, g), etaMinusOne, kappa };
  }
  // The index of a curve's material: (eta, kappa) or Gulbrandsen's (r, g, g_remap).
  function indexOf(p) {
    if (p.r === undefined) return { eta: p.eta, etaMinusOne: p.eta - 1, kappa: p.kappa };
    const g = p.g_remap ? p.g * (3 - 3 * p.g + p.g * p.g) : p.g;
    return gulbrandsenIndex(p.r, g);
  }

  // ---- src/model/fresnel/approx.rs ----
  const LAZANYI_TERM_PEAK = (1 / 7) * (6 / 7) * (6 / 7) * (6 / 7) * (6 / 7) * (6 / 7) * (6 / 7);
  function oneMinusCos(t) {
    if (t < PI / 3) {
      const sinHalf = Math.sin(0.5 * t);
      return 2 * sinHalf * sinHalf;
    }
    return 1 - Math.cos(t);
  }
  const schlick = (f0, t) => f0 + (1 - f0) * powi(oneMinusCos(t), 5);
  function lazanyi(f0, a, t) {
    const x = oneMinusCos(t);
    return Math.min(Math.max(f0 + (1 - f0) * powi(x, 5) - a * Math.cos(t) * powi(x, 6), 0), 1);
  }
  // [a_min, a_max] of Lazanyi–Schlick for F₀ (approx.rs lazanyi_a_range).
  function lazanyiARange(f0) {
    const h = (x) => (f0 + (1 - f0) * powi(x, 5)) / ((1 - x) * powi(x, 6));
    const dLnH = (x) => (5 * (1 - f0) * powi(x, 4)) / (f0 + (1 - f0) * powi(x, 5)) + 1 / (1 - x) - 6 / x;
    let [lo, hi] = [0, 1];
    for (;;) {
      const mid = 0.5 * (lo + hi);
      if (mid <= lo || mid >= hi) break;
      if (dLnH(mid) < 0) lo = mid;
      else hi = mid;
    }
    return [-5 * (1 - f0), Math.min(h(lo), h(hi))];
  }

  // ---- src/model/fresnel/basis.rs: the embedded basis (null on pages without Belcour curves), linear
  // in c between its 1000 nodes ----
  const GRID = basis ? basis.functions[0].length : 0;
  const cosGrid = Array.from({ length: GRID }, (_, i) => (i + 1 === GRID ? 1 : i * (1 / (GRID - 1))));
  function locate(c) {
    const last = GRID - 1;
    const floored = Math.floor(c * last);
    const i = Math.min(floored > 0 ? floored : 0, last - 1);
    return [i, (c - cosGrid[i]) / (cosGrid[i + 1] - cosGrid[i])];
  }
  function basisCoefficients(index) {
    const [b1, b2, b3] = basis.functions.slice(1);
    const [i1, i2] = basis.critical;
    const c0 = reflectance(NORMAL, index);
    const c1 = c0 !== 0 ? 1 - c0 : 0;
    const df1 = reflectance(fromCos(cosGrid[i1]), index) - (c0 + c1 * b1[i1]);
    const df2 = reflectance(fromCos(cosGrid[i2]), index) - (c0 + c1 * b1[i2]);
    const det = b2[i1] * b3[i2] - b3[i1] * b2[i2];
    return [c0, c1, (df1 * b3[i2] - df2 * b3[i1]) / det, (b2[i1] * df2 - b2[i2] * df1) / det];
  }
  const combine = (k, j) => k[0] * 1 + k[1] * basis.functions[1][j] + k[2] * basis.functions[2][j] + k[3] * basis.functions[3][j];
  function l2Grid(k, index) {
    let sum = 0;
    for (let j = 0; j < GRID; j++) sum += powi(reflectance(fromCos(cosGrid[j]), index) - combine(k, j), 2);
    return Math.sqrt(sum);
  }

  // Each Fresnel model: the parameter names it takes, and its evaluator from those values.
  const FRESNELS = {
    exact: (p) => {
      const index = indexOf(p);
      return { eval: (t) => reflectance(fromTheta(t), index) };
    },
    schlick: (p) => {
      const f0 = p.f0 !== undefined ? p.f0 : reflectance(NORMAL, indexOf(p));
      return { eval: (t) => schlick(f0, t) };
    },
    lazanyi: (p) => ({ eval: (t) => lazanyi(p.f0, p.a, t) }),
    lazanyi_term: () => ({ eval: (t) => Math.min((Math.cos(t) * powi(oneMinusCos(t), 6)) / LAZANYI_TERM_PEAK, 1) }),
    basis: (p) => {
      const b = basis.functions[p.index];
      return {
        eval: (t) => {
          const [i, w] = locate(Math.cos(t));
          return (1 - w) * b[i] + w * b[i + 1];
        },
      };
    },
    belcour: (p) => {
      const index = indexOf(p);
      const k = basisCoefficients(index);
      return {
        eval: (t) => {
          const [i, w] = locate(Math.cos(t));
          return (1 - w) * combine(k, i) + w * combine(k, i + 1);
        },
        coefficients: k,
        l2: l2Grid(k, index),
        index,
      };
    },
  };

  // ---- domains (src/model/domain.rs Param::contains), embedded from the Rust registry ----
  function contains(domain, v) {
    const above = domain.min_inclusive ? v >= domain.min : v > domain.min;
    const below = domain.max_inclusive ? v <= domain.max : v < domain.max;
    return Number.isFinite(v) && above && below;
  }
  // The domain problem of one parameter value, or null.
  function domainProblem(model, name, v, params) {
    let domain = domains[model][name];
    if (model === "lazanyi" && name === "a") {
      const [aMin, aMax] = lazanyiARange(params.f0);
      domain = { min: aMin, max: aMax, min_inclusive: true, max_inclusive: true, expected: "in [" + aMin + ", " + aMax + "] for this f0" };
    }
    return domain && !contains(domain, v) ? name + " must be " + domain.expected + " (got " + v + ")" : null;
  }

  // A number as Rust's {:?} prints it (docs/contracts.md "Numbers"): shortest round-trip digits, in
  // exponent form below 1e-4 and from 1e16, else decimal with at least one fractional digit.
  function formatNumber(v) {
    if (v === 0) return Object.is(v, -0) ? "-0.0" : "0.0";
    const [mantissa, exponentText] = Math.abs(v).toExponential().split("e");
    const exponent = Number(exponentText);
    const digits = mantissa.replace(".", "");
    const sign = v < 0 ? "-" : "";
    if (exponent < -4 || exponent >= 16) return sign + mantissa + "e" + exponent;
    if (exponent < 0) return sign + "0." + "0".repeat(-exponent - 1) + digits;
    if (digits.length <= exponent + 1) return sign + digits + "0".repeat(exponent + 1 - digits.length) + ".0";
    return sign + digits.slice(0, exponent + 1) + "." + digits.slice(exponent + 1);
  }

  // A curve from its canonical members ({"ndf": family, …} or {"fresnel": model, …}, parameters in
  // canonical order): {canonical, eval(θ), …extras}, or {problem} naming the first parameter outside
  // its domain.
  function build(members) {
    const entries = Object.entries(members);
    const [key, model] = entries[0];
    const params = Object.fromEntries(entries.slice(1));
    for (const [name, v] of entries.slice(1)) {
      if (typeof v !== "number") continue;
      const problem = domainProblem(model, name, v, params);
      if (problem) return { problem };
    }
    const canonical =
      "{" + entries.map(([k, v]) => JSON.stringify(k) + ":" + (typeof v === "number" ? formatNumber(v) : JSON.stringify(v))).join(",") + "}";
    if (key === "ndf") {
      const evaluate = NDFS[model](entries.slice(1).map(([, v]) => v));
      return { canonical, eval: evaluate };
    }
    return Object.assign({ canonical }, FRESNELS[model](params));
  }

  return { build, formatNumber, contains, integrate, phongFromBeckmann: (b) => 2 / (b * b) - 2 };
}
if (typeof module !== "undefined") module.exports = ndfplotMaths;
