// The script of an interactive ndfplot page: builds a continuous slider and a number box per
// parameter, evaluates every curve live with ndfplotMaths (maths.js, a port of ndfplot's own
// definitions), and redraws the plot, legend and readouts whenever a value, the y-scale, the
// y-axis lock, a match link or the window size changes. The current values live in the URL
// fragment (#name=value&…). window.ndfplot: params(), set(name, value), current().
"use strict";
(function () {
  const data = JSON.parse(document.getElementById("ndfplot-data").textContent);
  const maths = ndfplotMaths(data.domains, data.basis && decodeBasis(data.basis));
  const [thetaLo, thetaHi] = data.theta;
  const canvas = document.getElementById("plot");
  const logToggle = document.getElementById("log-y");
  const lockToggle = document.getElementById("lock-y");
  const values = data.sliders.map((s) => s.start);
  const matches = comparison();
  let lockedExtent = null;
  let series = [];

  function decodeBasis(basis) {
    const functions = basis.functions.map((text) => {
      const raw = atob(text);
      const view = new DataView(new ArrayBuffer(raw.length));
      for (let i = 0; i < raw.length; i++) view.setUint8(i, raw.charCodeAt(i));
      return Array.from({ length: raw.length / 8 }, (_, i) => view.getFloat64(8 * i, true));
    });
    return { functions, critical: basis.critical };
  }

  const mathRuns = ndfplotMathRuns;
  // The label as DOM nodes: one span per script or slanted run, sized and raised relative to the
  // label, variables in italics.
  function mathNode(text) {
    const fragment = document.createDocumentFragment();
    for (const run of mathRuns(text)) {
      if (run.scale === 1 && run.rise === 0 && !run.italic) {
        fragment.append(document.createTextNode(run.text));
      } else {
        const span = document.createElement("span");
        span.textContent = run.text;
        span.style.fontSize = run.scale + "em";
        span.style.verticalAlign = run.rise / run.scale + "em";
        if (run.italic) span.style.fontStyle = "italic";
        fragment.append(span);
      }
    }
    return fragment;
  }
  // Draws a label on the canvas with its baseline at y, aligned by `align` ("left", "center",
  // "right") at x, in the context's current font of `size` px.
  function fillMath(ctx, text, x, y, align, size) {
    const font = ctx.font;
    const runs = mathRuns(text);
    const fontOf = (run) =>
      (run.italic ? "italic " : "") + font.replace(/^[\d.]+px/, size * run.scale + "px");
    const widths = runs.map((run) => {
      ctx.font = fontOf(run);
      return ctx.measureText(run.text).width;
    });
    const total = widths.reduce((a, b) => a + b, 0);
    let left = align === "center" ? x - total / 2 : align === "right" ? x - total : x;
    const [savedAlign, savedBaseline] = [ctx.textAlign, ctx.textBaseline];
    ctx.textAlign = "left";
    ctx.textBaseline = "alphabetic";
    runs.forEach((run, i) => {
      ctx.font = fontOf(run);
      ctx.fillText(run.text, left, y - run.rise * size);
      left += widths[i];
    });
    ctx.font = font;
    [ctx.textAlign, ctx.textBaseline] = [savedAlign, savedBaseline];
  }

  // Tick values at 1, 2 or 5 × 10^n steps, about `count` of them over [lo, hi].
  function niceTicks(lo, hi, count) {
    const raw = (hi - lo) / Math.max(1, count);
    const power = 10 ** Math.floor(Math.log10(raw));
    const step = [1, 2, 5, 10].map((m) => m * power).find((s) => s >= raw) || raw;
    const ticks = [];
    for (let t = Math.ceil(lo / step - 1e-9) * step; t <= hi + step * 1e-9; t += step) ticks.push(Math.abs(t) < step * 1e-9 ? 0 : t);
    const decimals = Math.max(0, -Math.floor(Math.log10(step) + 1e-9));
    return ticks.map((t) => ({ value: t, text: t.toFixed(decimals) }));
  }

  // A number for people, as ndfplot's legends write it (src/spec/numbers.rs `pretty`): at most 6
  // significant digits, trailing zeros dropped, exponent form below 1e-4 and from 1e6.
  function pretty(v) {
    if (v === 0) return "0";
    const magnitude = Math.floor(Math.log10(Math.abs(v)));
    if (magnitude < -4 || magnitude >= 6) {
      const [mantissa, exponent] = v.toExponential(5).split("e");
      return mantissa.replace(/\.?0+$/, "") + "e" + Number(exponent);
    }
    const text = v.toFixed(Math.max(0, 5 - magnitude));
    return text.includes(".") ? text.replace(/\.?0+$/, "") : text;
  }
  // Fixed decimals without a negative zero ("-0.0000" reads as 0).
  function fixed(v, decimals) {
    const text = v.toFixed(decimals);
    return Number(text) === 0 ? (0).toFixed(decimals) : text;
  }
  const plain = (text) => mathRuns(text).map((r) => r.text).join("");

  // ---- curves at the current values ----
  // The members of curve `c` with the values `at` (default: the current ones), or {problem}.
  function members(c, at) {
    const result = JSON.parse(c.curve);
    for (const b of c.bindings) {
      const v = at[b.slider];
      if (b.from_beckmann && !(v > 0 && v <= 1)) {
        return { problem: "Beckmann-to-Phong conversion needs 0 < α_b ≤ 1 (got " + v + ", α_p = 2/α_b² − 2 would be negative or infinite)" };
      }
      result[b.param] = b.from_beckmann ? maths.phongFromBeckmann(v) : v;
    }
    return result;
  }
  function build(c, at) {
    const m = members(c, at);
    return m.problem ? m : maths.build(m);
  }
  function label(c, curve, m) {
    return c.label.replace(/\{(=?)([a-z0-9_]+)\}/g, (whole, slider, name) => {
      if (slider) {
        const i = data.sliders.findIndex((s) => s.name === name);
        return i < 0 ? whole : pretty(values[i]);
      }
      if (name === "l2" && curve.l2 !== undefined) return fixed(curve.l2, 2);
      return typeof m[name] === "number" ? pretty(m[name]) : m[name] !== undefined ? String(m[name]) : whole;
    });
  }
  // θ where the curves are drawn and reported: 1025 even steps over the panel's range, plus
  // 64 steps per end refined geometrically down to 1e-8 of the range, where narrow lobes sit.
  const thetas = (() => {
    const span = thetaHi - thetaLo;
    const list = Array.from({ length: 1025 }, (_, i) => (i === 1024 ? thetaHi : thetaLo + i * (span / 1024)));
    for (let j = 1; j <= 64; j++) {
      const d = span * 10 ** (-j / 8);
      list.push(thetaLo + d, thetaHi - d);
    }
    return [...new Set(list)].sort((a, b) => a - b);
  })();
  function evaluate() {
    series = data.curves.map((c) => {
      const curve = build(c, values);
      const m = members(c, values);
      return { label: label(c, curve, m), curve: curve.canonical, style: c.style, theta: thetas, y: thetas.map((t) => curve.eval(t)), built: curve };
    });
  }
  // The problem `values` would give, or null: the first curve whose parameters leave their domain.
  function problemAt(at) {
    for (const c of data.curves) {
      const curve = build(c, at);
      if (curve.problem) return curve.problem;
    }
    return null;
  }

  // ---- match links: on a page comparing two NDFs driven by separate sliders, the second
  // curve's first slider-driven parameter follows the first curve, by peak D(0) or by L2 ----
  function comparison() {
    const driven = data.curves.filter((c) => c.bindings.length > 0);
    if (driven.length !== 2 || !driven.every((c) => c.curve.startsWith('{"ndf"'))) return null;
    const [target, fitted] = driven;
    const binding = fitted.bindings.find((b) => !b.from_beckmann);
    const separate = target.bindings.every((b) => !fitted.bindings.some((f) => f.slider === b.slider));
    if (!binding || !separate) return null;
    const family = JSON.parse(fitted.curve).ndf;
    return { target, fitted, slider: binding.slider, domain: data.domains[family][binding.param], by: null };
  }
  // The bracket a match searches: the slider's range widened a millionfold, within the domain.
  function bracket(m) {
    const s = data.sliders[m.slider];
    const lo = Math.max(s.min > 0 ? s.min / 1e6 : 1e-300, m.domain.min_inclusive ? m.domain.min : m.domain.min + 1e-300);
    const hi = Math.min(s.max * 1e6, m.domain.max);
    return [Math.max(lo, 1e-300), hi];
  }
  function withValue(v) {
    const at = values.slice();
    at[matches.slider] = v;
    return at;
  }
  // Peak: D_fitted(0) = D_target(0), a 1D root in ln v found by bisection to the last bit
  // (D(0) is monotone in each family's scale parameter); null when the bracket has no root.
  function matchPeak() {
    const target = build(matches.target, values);
    if (target.problem) return null;
    const goal = Math.log(target.eval(0));
    const f = (v) => {
      const curve = build(matches.fitted, withValue(v));
      return curve.problem ? NaN : Math.log(curve.eval(0)) - goal;
    };
    let [lo, hi] = bracket(matches);
    let [fLo, fHi] = [f(lo), f(hi)];
    if (!(fLo * fHi <= 0)) return null;
    for (let i = 0; i < 400; i++) {
      const mid = Math.sqrt(lo) * Math.sqrt(hi);
      if (!(mid > lo && mid < hi)) break;
      const fMid = f(mid);
      if (fMid === 0) return mid;
      if (fMid * fLo < 0) [hi, fHi] = [mid, fMid];
      else [lo, fLo] = [mid, fMid];
    }
    return Math.abs(fLo) <= Math.abs(fHi) ? lo : hi;
  }
  // L2: the minimum over v of ∫ (a − b)² sin θ cos θ dθ (`l2_projected` without its 2π and
  // root), by a scan of 61 log-spaced values over the slider's range and a golden-section search
  // around the best to 1e-6 relative in v, the integral by 64 panels of 20 Gauss nodes.
  function matchL2() {
    const target = build(matches.target, values);
    if (target.problem) return null;
    const cost = (v) => {
      const curve = build(matches.fitted, withValue(v));
      if (curve.problem) return Infinity;
      return maths.integrate((t) => (curve.eval(t) - target.eval(t)) ** 2 * Math.sin(t) * Math.cos(t), 0, Math.PI / 2, 64);
    };
    const s = data.sliders[matches.slider];
    const [lo, hi] = [Math.max(s.min, bracket(matches)[0]), s.max];
    const log = lo > 0;
    const at = (u) => (log ? Math.exp(u) : u);
    const [uLo, uHi] = log ? [Math.log(lo), Math.log(hi)] : [lo, hi];
    const grid = Array.from({ length: 61 }, (_, i) => uLo + ((uHi - uLo) * i) / 60);
    const costs = grid.map((u) => cost(at(u)));
    const best = costs.indexOf(Math.min(...costs));
    let [a, b] = [grid[Math.max(0, best - 1)], grid[Math.min(60, best + 1)]];
    const golden = (Math.sqrt(5) - 1) / 2;
    while (Math.abs(at(b) - at(a)) > 1e-6 * Math.abs(at(b))) {
      const [c, d] = [b - golden * (b - a), a + golden * (b - a)];
      if (cost(at(c)) <= cost(at(d))) b = d;
      else a = c;
    }
    return at((a + b) / 2);
  }
  // Re-fits the matched parameter when a link is on; returns a message when it cannot.
  function refit() {
    if (!matches || !matches.by) return null;
    const v = matches.by === "peak" ? matchPeak() : matchL2();
    if (v === null || !isFinite(v)) return "no " + matches.by + " match within reach";
    values[matches.slider] = v;
    return null;
  }

  function yExtent(log) {
    if (data.y_range && !(log && data.y_range[0] <= 0)) return log ? data.y_range.map(Math.log10) : data.y_range.slice();
    let max = -Infinity;
    let min = Infinity;
    for (const s of series) for (const y of s.y) {
      max = Math.max(max, y);
      min = Math.min(min, y);
    }
    if (log) {
      if (!(max > 0)) return [-1, 0];
      let low = Infinity;
      for (const s of series) for (const y of s.y) if (y > 0) low = Math.min(low, y);
      // The log view shows 12 decades below the largest value at most.
      low = Math.max(low, max * 1e-12);
      const top = Math.ceil(Math.log10(max) - 1e-12);
      return [Math.min(Math.floor(Math.log10(low) + 1e-12), top - 1), top];
    }
    if (!isFinite(max)) return [0, 1];
    const lo = Math.min(0, min);
    const hi = max > lo ? max : lo + 1;
    return [lo, hi + 0.05 * (hi - lo)];
  }

  const dashes = { solid: [], dashed: [7, 4], dotted: [1.5, 3] };

  // The canvas size: the width its box gets, the figure's aspect ratio, at most 75 % of the
  // window's height and at least 220 px tall.
  function size() {
    const width = Math.max(200, Math.floor(canvas.getBoundingClientRect().width || data.width));
    const height = Math.round(Math.max(220, Math.min((width * data.height) / data.width, 0.75 * window.innerHeight)));
    return [width, height];
  }

  function draw() {
    const log = logToggle.checked;
    const [width, height] = size();
    const ratio = window.devicePixelRatio || 1;
    canvas.width = Math.round(width * ratio);
    canvas.height = Math.round(height * ratio);
    canvas.style.height = height + "px";
    const ctx = canvas.getContext("2d");
    ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
    ctx.clearRect(0, 0, width, height);
    const font = Math.max(11, Math.min(data.font_px, width / 30));
    const titled = data.panel_title !== "";
    const box = { left: 4.8 * font, right: width - font, top: (titled ? 2.2 : 0.8) * font, bottom: height - 3.4 * font };
    const degrees = data.degrees ? 180 / Math.PI : 1;
    const [xLo, xHi] = [thetaLo * degrees, thetaHi * degrees];
    if (!lockToggle.checked || !lockedExtent || lockedExtent.log !== log) lockedExtent = { log, range: yExtent(log) };
    const [yLo, yHi] = lockedExtent.range;
    const px = (x) => box.left + ((x - xLo) / (xHi - xLo)) * (box.right - box.left);
    const py = (v) => box.bottom - ((v - yLo) / (yHi - yLo)) * (box.bottom - box.top);

    ctx.font = font + "px system-ui, sans-serif";
    ctx.fillStyle = "#1e1e1e";
    ctx.strokeStyle = "#e6e6e6";
    ctx.lineWidth = 1;
    ctx.textAlign = "center";
    ctx.textBaseline = "top";
    for (const tick of niceTicks(xLo, xHi, Math.max(3, Math.floor((box.right - box.left) / (5 * font))))) {
      const x = px(tick.value);
      ctx.beginPath();
      ctx.moveTo(x, box.top);
      ctx.lineTo(x, box.bottom);
      ctx.stroke();
      ctx.fillText(tick.text, x, box.bottom + 0.4 * font);
    }
    ctx.textAlign = "right";
    ctx.textBaseline = "middle";
    const yTicks = log
      ? Array.from({ length: yHi - yLo + 1 }, (_, i) => yLo + i)
          .filter((d, i, all) => all.length <= 9 || (d - yLo) % Math.ceil(all.length / 8) === 0)
          .map((d) => ({ value: d, text: "1e" + d }))
      : niceTicks(yLo, yHi, Math.max(3, Math.floor((box.bottom - box.top) / (2.5 * font))));
    for (const tick of yTicks) {
      const y = py(tick.value);
      ctx.beginPath();
      ctx.moveTo(box.left, y);
      ctx.lineTo(box.right, y);
      ctx.stroke();
      ctx.fillText(tick.text, box.left - 0.4 * font, y);
    }
    ctx.strokeStyle = "#1e1e1e";
    ctx.strokeRect(box.left, box.top, box.right - box.left, box.bottom - box.top);
    // Baselines a quarter of the size above where the text's bottom was, a third below its middle.
    const centre = (box.left + box.right) / 2;
    fillMath(ctx, data.x_label, centre, height - 0.55 * font, "center", font);
    if (titled) fillMath(ctx, data.panel_title, centre, box.top - 0.75 * font, "center", font);
    ctx.save();
    ctx.translate(1.2 * font, (box.top + box.bottom) / 2);
    ctx.rotate(-Math.PI / 2);
    fillMath(ctx, data.y_label + (log ? " (log)" : ""), 0, 0.35 * font, "center", font);
    ctx.restore();
    // Curves, clipped to the plot box; non-positive values break the line on a log axis.
    ctx.save();
    ctx.beginPath();
    ctx.rect(box.left, box.top, box.right - box.left, box.bottom - box.top);
    ctx.clip();
    ctx.lineJoin = "round";
    for (const s of series) {
      ctx.strokeStyle = s.style.colour;
      ctx.lineWidth = 1.5 * s.style.width;
      ctx.setLineDash(dashes[s.style.dash].map((d) => d * s.style.width));
      ctx.beginPath();
      let pen = false;
      for (let i = 0; i < s.theta.length; i++) {
        const v = log ? (s.y[i] > 0 ? Math.log10(s.y[i]) : NaN) : s.y[i];
        if (!isFinite(v)) {
          pen = false;
          continue;
        }
        const x = px(s.theta[i] * degrees);
        const y = Math.max(-1e6, Math.min(1e6, py(v)));
        if (pen) ctx.lineTo(x, y);
        else ctx.moveTo(x, y);
        pen = true;
      }
      ctx.stroke();
    }
    ctx.restore();
    canvas.setAttribute(
      "aria-label",
      plain(data.title || data.id) + ": " + plain(data.y_label) + " against " + plain(data.x_label) + (log ? ", log y" : "") +
        "; curves: " + series.map((s) => plain(s.label)).join("; ") +
        "; at " + data.sliders.map((s, i) => plain(s.label) + " = " + pretty(values[i])).join(", ")
    );
  }

  function legend() {
    const list = document.getElementById("legend");
    list.hidden = !data.legend;
    list.replaceChildren(
      ...series.map((s) => {
        const item = document.createElement("li");
        const svg = document.createElementNS("http://www.w3.org/2000/svg", "svg");
        svg.setAttribute("width", "30");
        svg.setAttribute("height", "10");
        svg.setAttribute("aria-hidden", "true");
        const line = document.createElementNS("http://www.w3.org/2000/svg", "line");
        for (const [k, v] of [["x1", 1], ["y1", 5], ["x2", 29], ["y2", 5], ["stroke", s.style.colour], ["stroke-width", 1.5 * s.style.width]]) line.setAttribute(k, v);
        if (s.style.dash !== "solid") line.setAttribute("stroke-dasharray", dashes[s.style.dash].map((d) => d * s.style.width).join(" "));
        svg.append(line);
        // One flex item for the whole label, so its sub- and superscripts sit against their base.
        const label = document.createElement("span");
        label.append(mathNode(s.label));
        item.append(svg, label);
        return item;
      })
    );
  }

  // The Belcour reconstructions' coefficients (and η, κ of a Gulbrandsen material), as printed.
  function readouts() {
    const texts = [];
    for (const s of series) {
      const k = s.built.coefficients;
      if (!k) continue;
      const coefficients = k.map((c, i) => "c" + "₀₁₂₃"[i] + " = " + fixed(c, 4)).join(", ");
      const material = JSON.parse(s.curve);
      texts.push(material.r !== undefined ? "η = " + fixed(s.built.index.eta, 4) + ", κ = " + fixed(s.built.index.kappa, 4) + "; " + coefficients : coefficients);
    }
    return [...new Set(texts)];
  }

  // ---- sliders and number boxes ----
  const STEPS = 1000;
  const position = (s, v) =>
    s.scale === "log" ? (STEPS * Math.log(v / s.min)) / Math.log(s.max / s.min) : (STEPS * (v - s.min)) / (s.max - s.min);
  const valueAt = (s, p) =>
    p >= STEPS ? s.max : s.scale === "log" ? s.min * Math.exp((p / STEPS) * Math.log(s.max / s.min)) : s.min + (p / STEPS) * (s.max - s.min);
  const controls = [];

  function showValues() {
    data.sliders.forEach((s, i) => {
      const { range, box, problem } = controls[i];
      range.value = String(Math.max(0, Math.min(STEPS, position(s, values[i]))));
      range.setAttribute("aria-valuetext", plain(s.label) + " = " + pretty(values[i]));
      if (document.activeElement !== box || problem.textContent === "") box.value = pretty(values[i]);
      const locked = matches && matches.by && matches.slider === i;
      range.disabled = locked;
      box.disabled = locked;
    });
  }

  function update() {
    const problem = refit();
    evaluate();
    showValues();
    draw();
    legend();
    document.getElementById("readouts").replaceChildren(
      ...readouts().concat(problem ? [problem] : []).map((text) => {
        const p = document.createElement("p");
        p.textContent = text;
        return p;
      })
    );
    const fragment = "#" + data.sliders.map((s, i) => s.name + "=" + maths.formatNumber(values[i])).join("&");
    if (location.hash !== fragment) history.replaceState(null, "", fragment);
  }

  // Sets slider `i` to `v` when every curve accepts it; returns the problem otherwise.
  function setValue(i, v) {
    if (typeof v !== "number" || !isFinite(v)) return "not a number (got " + v + ")";
    const at = values.slice();
    at[i] = v;
    const problem = problemAt(at);
    if (problem) return problem;
    values[i] = v;
    update();
    return null;
  }

  function buildControls() {
    const box = document.getElementById("sliders");
    data.sliders.forEach((s, i) => {
      const row = document.createElement("div");
      row.className = "slider";
      const label = document.createElement("label");
      label.htmlFor = "value-" + i;
      label.id = "label-" + i;
      label.append(mathNode(s.label));
      const range = document.createElement("input");
      Object.assign(range, { type: "range", id: "slider-" + i, name: s.name, min: 0, max: STEPS, step: "any" });
      range.setAttribute("aria-labelledby", label.id);
      const text = document.createElement("input");
      Object.assign(text, { type: "text", id: "value-" + i, inputMode: "decimal", spellcheck: false });
      const problem = document.createElement("span");
      problem.className = "problem";
      problem.id = "problem-" + i;
      problem.setAttribute("role", "alert");
      text.setAttribute("aria-describedby", problem.id);
      const report = (message) => {
        problem.textContent = message ? plain(s.label) + ": " + message : "";
        text.setAttribute("aria-invalid", message ? "true" : "false");
      };
      range.addEventListener("input", () => report(setValue(i, valueAt(s, Number(range.value)))));
      text.addEventListener("change", () => {
        const v = text.value.trim() === "" ? NaN : Number(text.value.replace(",", "."));
        report(setValue(i, v));
      });
      row.append(label, range, text, problem);
      box.append(row);
      controls.push({ range, box: text, problem });
    });
  }

  function buildMatches() {
    if (!matches) return;
    const span = document.getElementById("matches");
    const name = plain(data.sliders[matches.slider].label);
    for (const by of ["peak", "L2"]) {
      const toggle = document.createElement("label");
      toggle.className = "toggle";
      const box = document.createElement("input");
      Object.assign(box, { type: "checkbox", id: "match-" + by.toLowerCase() });
      box.addEventListener("change", () => {
        matches.by = box.checked ? by.toLowerCase() : null;
        for (const other of span.querySelectorAll("input")) if (other !== box) other.checked = false;
        update();
      });
      toggle.append(box, " match " + by + " (" + name + " follows)");
      span.append(toggle);
    }
  }

  // Values from the URL fragment (#name=value&…), each kept when the curves accept it.
  function fromFragment() {
    for (const part of location.hash.slice(1).split("&")) {
      const [name, text] = part.split("=");
      const i = data.sliders.findIndex((s) => s.name === decodeURIComponent(name || ""));
      const v = Number(text);
      if (i >= 0 && text !== undefined && text !== "" && isFinite(v)) {
        const at = values.slice();
        at[i] = v;
        if (!problemAt(at)) values[i] = v;
      }
    }
  }

  document.title = plain(data.title || data.id);
  document.getElementById("title").replaceChildren(mathNode(data.title));
  buildControls();
  buildMatches();
  document.getElementById("log-y-toggle").hidden = !data.log_toggle;
  logToggle.checked = data.y_scale === "log";
  logToggle.addEventListener("change", update);
  lockToggle.addEventListener("change", update);
  window.addEventListener("resize", draw);
  document.getElementById("note").textContent =
    "Curves are computed in this page by a port of ndfplot's definitions, within " + data.tolerance +
    " relative of `ndfplot eval`; the values are in the address (#…) for a permalink.";
  fromFragment();
  update();

  window.ndfplot = {
    // Every parameter: its slider's range, current value and scale.
    params() {
      return data.sliders.map((s, i) => ({ name: s.name, min: s.min, max: s.max, value: values[i], scale: s.scale }));
    },
    // Sets parameter `name` to `value` and redraws synchronously; returns null, or the problem
    // (an unknown name, a value outside a curve's domain, or a parameter a match link drives).
    set(name, value) {
      const i = data.sliders.findIndex((s) => s.name === name);
      if (i < 0) return "unknown parameter " + name;
      if (matches && matches.by && matches.slider === i) return name + " follows the " + matches.by + " match";
      return setValue(i, value);
    },
    // Turns a match link on ("peak" or "l2") or off (null); returns the matched parameter's name.
    match(by) {
      if (!matches) return null;
      for (const box of document.querySelectorAll("#matches input")) box.checked = box.id === "match-" + by;
      matches.by = by;
      update();
      return data.sliders[matches.slider].name;
    },
    // What the page draws now: the values, and each curve's label, canonical JSON, θ and values.
    current() {
      const params = {};
      data.sliders.forEach((s, i) => (params[s.name] = values[i]));
      return { params, curves: series.map((s) => ({ label: s.label, curve: s.curve, theta: s.theta.slice(), value: s.y.slice() })) };
    },
  };
})();
