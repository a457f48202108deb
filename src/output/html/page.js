// The script of an interactive ndfplot page: decodes the values ndfplot embedded (see
// src/output/html/samples.rs for the encoding), builds one slider per parameter, and redraws the
// plot, legend and readouts whenever a slider or the y-scale toggle changes. It computes no curve:
// every drawn value is a decoded sample. window.ndfplot.current() returns what is drawn.
"use strict";
(function () {
  const data = JSON.parse(document.getElementById("ndfplot-data").textContent);
  const [coarseLevels, fineLevels] = data.levels;
  const [thetaLo, thetaHi] = data.theta;
  const gridStep = (thetaHi - thetaLo) / 2 ** fineLevels;
  const positions = data.sliders.map((s) => s.start);
  const decoded = new Map();
  const canvas = document.getElementById("plot");
  const logToggle = document.getElementById("log-y");

  // Math text as the drawn figures typeset it (src/output/plot/mathtext.rs): `_` and `^` with one
  // character or a {…} group make a sub- or superscript, groups nest, and a backslash escapes.
  const SCRIPT_SCALE = 0.7;
  const SUB_DROP = 0.2;
  const SUP_RISE = 0.38;
  function mathRuns(text) {
    const chars = Array.from(text);
    const runs = [];
    const push = (c, scale, rise) => {
      const last = runs[runs.length - 1];
      if (last && last.scale === scale && last.rise === rise) last.text += c;
      else runs.push({ text: c, scale, rise });
    };
    const groupEnd = (open) => {
      let depth = 0;
      for (let i = open; i < chars.length; i++) {
        if (chars[i] === "\\") i++;
        else if (chars[i] === "{") depth++;
        else if (chars[i] === "}" && --depth === 0) return i;
      }
      return chars.length;
    };
    const parse = (lo, hi, scale, rise) => {
      let i = lo;
      while (i < hi) {
        const c = chars[i];
        if (c === "\\" && i + 1 < hi) {
          push(chars[i + 1], scale, rise);
          i += 2;
        } else if ((c === "_" || c === "^") && i + 1 < hi && !/\s/.test(chars[i + 1])) {
          const shift = c === "_" ? -SUB_DROP : SUP_RISE;
          const [s, r] = [scale * SCRIPT_SCALE, rise + shift * scale];
          if (chars[i + 1] === "{") {
            const end = Math.min(groupEnd(i + 1), hi);
            parse(i + 2, end, s, r);
            i = end + 1;
          } else {
            push(chars[i + 1], s, r);
            i += 2;
          }
        } else {
          push(c, scale, rise);
          i += 1;
        }
      }
    };
    parse(0, chars.length, 1, 0);
    return runs;
  }
  // The label as DOM nodes: one span per script run, sized and raised relative to the label.
  function mathNode(text) {
    const fragment = document.createDocumentFragment();
    for (const run of mathRuns(text)) {
      if (run.scale === 1 && run.rise === 0) {
        fragment.append(document.createTextNode(run.text));
      } else {
        const span = document.createElement("span");
        span.textContent = run.text;
        span.style.fontSize = run.scale + "em";
        span.style.verticalAlign = run.rise / run.scale + "em";
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
    const widths = runs.map((run) => {
      ctx.font = font.replace(/^[\d.]+px/, size * run.scale + "px");
      return ctx.measureText(run.text).width;
    });
    const total = widths.reduce((a, b) => a + b, 0);
    let left = align === "center" ? x - total / 2 : align === "right" ? x - total : x;
    const [savedAlign, savedBaseline] = [ctx.textAlign, ctx.textBaseline];
    ctx.textAlign = "left";
    ctx.textBaseline = "alphabetic";
    runs.forEach((run, i) => {
      ctx.font = font.replace(/^[\d.]+px/, size * run.scale + "px");
      ctx.fillText(run.text, left, y - run.rise * size);
      left += widths[i];
    });
    ctx.font = font;
    [ctx.textAlign, ctx.textBaseline] = [savedAlign, savedBaseline];
  }

  // Grid index k to θ exactly as ndfplot computes it: lo + k·((hi − lo)/2^levels).
  const thetaOf = (k) => thetaLo + k * gridStep;

  function bytesOf(base64) {
    const text = atob(base64);
    const bytes = new Uint8Array(text.length);
    for (let i = 0; i < text.length; i++) bytes[i] = text.charCodeAt(i);
    return bytes;
  }

  // Decodes one curve: the bisection tree gives the grid indices, the varints the quantized logs.
  function decode(base64) {
    const bytes = bytesOf(base64);
    let bit = 0;
    const readBit = () => {
      const value = (bytes[1 + (bit >> 3)] >> (7 - (bit & 7))) & 1;
      bit++;
      return value;
    };
    const ks = [0];
    const walk = (a, b, level) => {
      if (level >= fineLevels || !readBit()) return;
      const m = (a + b) / 2;
      walk(a, m, level + 1);
      ks.push(m);
      walk(m, b, level + 1);
    };
    const coarse = 2 ** (fineLevels - coarseLevels);
    for (let j = 0; j < 2 ** coarseLevels; j++) {
      walk(j * coarse, (j + 1) * coarse, coarseLevels);
      ks.push((j + 1) * coarse);
    }
    let pos = 1 + ((bit + 7) >> 3);
    const n = ks.length;
    let classes = null;
    if (bytes[0] & 1) {
      classes = bytes.subarray(pos, pos + n);
      pos += n;
    }
    const theta = new Array(n);
    const y = new Array(n);
    let [k2, q2, k1, q1] = [0, 0, 0, 0];
    for (let i = 0; i < n; i++) {
      let u = 0;
      let scale = 1;
      let byte;
      do {
        byte = bytes[pos++];
        u += (byte & 0x7f) * scale;
        scale *= 128;
      } while (byte & 0x80);
      // The residual from the linear extrapolation of the two previous samples (exact integers).
      const k = ks[i];
      const prediction = i === 0 ? 0 : i === 1 ? q1 : q1 + Math.floor(((q1 - q2) * (k - k1)) / (k1 - k2));
      const q = prediction + (u % 2 === 0 ? u / 2 : -(u + 1) / 2);
      [k2, q2, k1, q1] = [k1, q1, k, q];
      theta[i] = thetaOf(k);
      const cls = classes ? classes[i] : 1;
      y[i] = cls === 0 ? 0 : (cls === 2 ? -1 : 1) * Math.exp(q * data.log_step);
    }
    return { theta, y };
  }

  // The frame of an entry at the current positions: row-major over its sliders, last fastest.
  function frameIndex(entry) {
    let index = 0;
    for (const s of entry.sliders) index = index * data.sliders[s].values.length + positions[s];
    return index;
  }

  // The series drawn at the current slider positions, decoded once and cached.
  function currentSeries() {
    const series = [];
    data.entries.forEach((entry, e) => {
      const index = frameIndex(entry);
      entry.frames[index].curves.forEach((curve, c) => {
        const key = e + ":" + index + ":" + c;
        if (!decoded.has(key)) decoded.set(key, decode(curve.data));
        const points = decoded.get(key);
        series.push({ label: curve.label, curve: curve.curve, style: data.styles[curve.style], theta: points.theta, y: points.y });
      });
    });
    return series;
  }

  function readouts() {
    return data.entries.map((entry) => entry.frames[frameIndex(entry)].readout).filter((r) => r !== undefined);
  }

  // A number for people: at most 6 significant digits, trailing zeros dropped.
  function pretty(v) {
    if (v === 0) return "0";
    const magnitude = Math.floor(Math.log10(Math.abs(v)));
    if (magnitude < -4 || magnitude >= 6) return String(Number(v.toExponential(5))).replace("e+", "e");
    return String(Number(v.toFixed(Math.max(0, 5 - magnitude))));
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

  function yExtent(series, log) {
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
      low = Math.max(low, max * 10 ** -data.log_decades);
      const top = Math.ceil(Math.log10(max) - 1e-12);
      const bottom = Math.min(Math.floor(Math.log10(low) + 1e-12), top - 1);
      return [bottom, top];
    }
    if (!isFinite(max)) return [0, 1];
    const lo = Math.min(0, min);
    const hi = max > lo ? max : lo + 1;
    return [lo, hi + 0.05 * (hi - lo)];
  }

  const dashes = { solid: [], dashed: [7, 4], dotted: [1.5, 3] };

  function draw(series, log) {
    const width = data.width;
    const height = data.height;
    const ratio = window.devicePixelRatio || 1;
    canvas.width = Math.round(width * ratio);
    canvas.height = Math.round(height * ratio);
    canvas.style.width = width + "px";
    canvas.style.height = height + "px";
    const ctx = canvas.getContext("2d");
    ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
    ctx.clearRect(0, 0, width, height);
    const font = data.font_px;
    const titled = data.panel_title !== "";
    const box = { left: 4.8 * font, right: width - font, top: (titled ? 2.2 : 0.8) * font, bottom: height - 3.4 * font };
    const degrees = data.degrees ? 180 / Math.PI : 1;
    const [xLo, xHi] = [thetaLo * degrees, thetaHi * degrees];
    const [yLo, yHi] = yExtent(series, log);
    const px = (x) => box.left + ((x - xLo) / (xHi - xLo)) * (box.right - box.left);
    const py = (v) => box.bottom - ((v - yLo) / (yHi - yLo)) * (box.bottom - box.top);

    ctx.font = font + "px system-ui, sans-serif";
    ctx.fillStyle = "#1e1e1e";
    ctx.strokeStyle = "#e6e6e6";
    ctx.lineWidth = 1;
    // Grid and tick labels.
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
    // Axis labels and the panel title.
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
  }

  function legend(series) {
    const list = document.getElementById("legend");
    list.hidden = !data.legend;
    list.replaceChildren(
      ...series.map((s) => {
        const item = document.createElement("li");
        const svg = document.createElementNS("http://www.w3.org/2000/svg", "svg");
        svg.setAttribute("width", "30");
        svg.setAttribute("height", "10");
        const line = document.createElementNS("http://www.w3.org/2000/svg", "line");
        for (const [k, v] of [["x1", 1], ["y1", 5], ["x2", 29], ["y2", 5], ["stroke", s.style.colour], ["stroke-width", 1.5 * s.style.width]]) line.setAttribute(k, v);
        if (s.style.dash !== "solid") line.setAttribute("stroke-dasharray", dashes[s.style.dash].map((d) => d * s.style.width).join(" "));
        svg.append(line);
        item.append(svg, mathNode(s.label));
        return item;
      })
    );
  }

  function update() {
    data.sliders.forEach((s, i) => {
      document.getElementById("value-" + i).replaceChildren(mathNode(s.label + " = " + pretty(s.values[positions[i]])));
    });
    const series = currentSeries();
    draw(series, logToggle.checked);
    legend(series);
    document.getElementById("readouts").replaceChildren(
      ...readouts().map((text) => {
        const p = document.createElement("p");
        p.textContent = text;
        return p;
      })
    );
  }

  function build() {
    document.title = mathRuns(data.title || data.id).map((r) => r.text).join("");
    document.getElementById("title").replaceChildren(mathNode(data.title));
    const box = document.getElementById("sliders");
    data.sliders.forEach((s, i) => {
      const label = document.createElement("label");
      label.htmlFor = "slider-" + i;
      label.append(mathNode(s.label));
      const input = document.createElement("input");
      Object.assign(input, { type: "range", id: "slider-" + i, name: s.name, min: 0, max: s.values.length - 1, step: 1, value: s.start });
      input.addEventListener("input", () => {
        positions[i] = Number(input.value);
        update();
      });
      const output = document.createElement("output");
      output.id = "value-" + i;
      output.htmlFor = input.id;
      box.append(label, input, output);
    });
    logToggle.checked = data.y_scale === "log";
    logToggle.addEventListener("change", update);
    document.getElementById("note").textContent =
      "Every value drawn was computed by ndfplot at each slider position and embedded in this page " +
      "(relative precision " + data.precision + "); nothing is computed or loaded here.";
    update();
  }

  window.ndfplot = {
    // What the page draws now: slider values, scale, and each series' θ (radians) and values.
    current() {
      const params = {};
      data.sliders.forEach((s, i) => (params[s.name] = s.values[positions[i]]));
      return {
        params,
        scale: logToggle.checked ? "log" : "linear",
        readouts: readouts(),
        series: currentSeries().map((s) => ({ label: s.label, curve: s.curve, theta: s.theta.slice(), y: s.y.slice() })),
      };
    },
  };
  build();
})();
