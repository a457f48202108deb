// Math text of an interactive page, set as the drawn figures set it (src/output/plot/mathtext.rs):
// `_` and `^` with one character or a {…} group make a sub- or superscript, groups nest, a
// backslash escapes; a letter standing alone within its run (not part of a word, nor the end of an
// elided word such as notebook's, nor a version such as pbrt-v4) is a variable, set in italics, except a lone a, A or I before a
// word, a panel letter opening the label, and π, Σ and Π. ndfplotMathRuns(text) →
// [{text, scale, rise, italic}].
"use strict";
const ndfplotMathRuns = (function () {
  const SCRIPT_SCALE = 0.7;
  const SUB_DROP = 0.2;
  const SUP_RISE = 0.38;
  const letter = (c) => c !== undefined && /\p{L}/u.test(c);

  function scripts(text) {
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

  // Splits every run so that each variable is a run of its own, marked italic.
  function slant(runs) {
    const out = [];
    const add = (text, run, italic) => {
      if (!text) return;
      const last = out[out.length - 1];
      if (last && last.scale === run.scale && last.rise === run.rise && last.italic === italic) last.text += text;
      else out.push({ text, scale: run.scale, rise: run.rise, italic });
    };
    runs.forEach((run, index) => {
      const chars = Array.from(run.text);
      const close = chars.indexOf(")");
      const panelLetter = index === 0 && chars[0] === "(" && close >= 2 && close <= 3
        && chars.slice(1, close).every((c) => /[a-z]/.test(c));
      let piece = "";
      chars.forEach((c, i) => {
        const elided = i > 1 && (chars[i - 1] === "'" || chars[i - 1] === "\u2019") && letter(chars[i - 2]);
        const versioned = i > 1 && chars[i - 1] === "-" && letter(chars[i - 2]) && /[0-9]/.test(chars[i + 1] || "");
        const alone = letter(c) && !letter(chars[i - 1]) && !letter(chars[i + 1]) && !elided && !versioned;
        const prose = (c === "a" || c === "A" || c === "I") && chars[i + 1] === " "
          && letter(chars[i + 2]) && letter(chars[i + 3]);
        const constant = c === "π" || c === "Σ" || c === "Π";
        const named = panelLetter && i < 4;
        if (alone && !prose && !constant && !named) {
          add(piece, run, false);
          piece = "";
          add(c, run, true);
        } else {
          piece += c;
        }
      });
      add(piece, run, false);
    });
    return out;
  }

  return (text) => slant(scripts(text));
})();
