// screwkit's self-checking answer boxes (screwkit/exercises.py renders them).
// Each box is a <div class="sk-answer-box"> holding its key as JSON; this script reads
// the student's text with a small parser (numbers, pi, sqrt, trigonometric functions,
// units, comma-separated vectors; never eval) and checks it with the rules of
// sk.exercises.check: tolerance, accepted forms, and why a wrong answer is wrong.
(function () {
  "use strict";
  if (window.screwkitExercises) return;

  const DEG = Math.PI / 180;
  // The units (a factor to SI and a dimension, the exponents of (kg, m, s, rad)), their
  // other names and what each dimension is called: one table, exercises.py's _UNITS,
  // _UNIT_NAMES and _QUANTITIES, written here by sk.exercises.exercises_script()
  const TABLES = /*SCREWKIT-UNIT-TABLES*/ {units: {}, names: {}, quantities: {}};
  const UNITS = TABLES.units;
  const UNIT_NAMES = TABLES.names;
  const QUANTITIES = TABLES.quantities;
  const SLIPS = [
    ["rad", DEG, "looks like degrees, radians expected"],
    ["deg", 1 / DEG, "looks like radians, degrees expected"],
    ["m", 1e-3, "looks like millimetres, metres expected"],
    ["mm", 1e3, "looks like metres, millimetres expected"],
  ];
  const FUNCTIONS = {
    sqrt: Math.sqrt, sin: Math.sin, cos: Math.cos, tan: Math.tan, asin: Math.asin,
    acos: Math.acos, atan: Math.atan, atan2: Math.atan2, exp: Math.exp, ln: Math.log,
    log: Math.log, abs: Math.abs,
  };
  const CONSTANTS = { pi: Math.PI, "π": Math.PI, e: Math.E };
  const TOKEN = new RegExp(
    "^\\s*(?:((?:\\d+\\.?\\d*|\\.\\d+)(?:[eE][+-]?\\d+)?)" +
    "|([A-Za-zπ°_][A-Za-z0-9_]*)|(\\*\\*|[-+*/^(),;\\[\\]]))");
  const KINDS = ["number", "name", "op"];
  const own = (table, key) => Object.prototype.hasOwnProperty.call(table, key);
  const unitName = (word) => (own(UNIT_NAMES, word) ? UNIT_NAMES[word] : word);
  const isUnitWord = (word) => own(UNITS, unitName(word));
  const article = (name) => ("aeiou".includes(name[0]) ? "an " : "a ") + name;
  const quantity = (dimension) => {
    const key = dimension.join(",");
    return article(own(QUANTITIES, key) ? QUANTITIES[key] : "quantity");
  };
  const sameDimension = (a, b) => a.every((v, i) => v === b[i]);

  function tokenize(text) {
    text = text.replace(/−/g, "-").replace(/[×·⋅]/g, "*").replace(/√/g, "sqrt");
    text = text.replace(/²/g, "^2").replace(/³/g, "^3");
    const tokens = [];
    let rest = text;
    while (rest.trim() !== "") {
      const match = TOKEN.exec(rest);
      if (!match || match[0].length === 0) {
        throw new Error("cannot read '" + rest.trim().slice(0, 12) + "'");
      }
      const group = [1, 2, 3].find((i) => match[i] !== undefined);
      // the third entry: whitespace before the token
      const spaced = match[0].length > match[group].length;
      tokens.push([KINDS[group - 1], match[group], spaced]);
      rest = rest.slice(match[0].length);
    }
    return tokens;
  }

  function parse(text) {
    const tokens = tokenize(text);
    let at = 0;
    if (tokens.length === 0) throw new Error("the answer is empty");
    const peek = () => tokens[at] || [null, null];
    const take = (value) => {
      const token = peek();
      if (token[0] === null || (value !== undefined && token[1] !== value)) {
        const found = token[0] === null ? "the end" : "'" + token[1] + "'";
        throw new Error("expected '" + value + "', found " + found);
      }
      at += 1;
      return token;
    };
    const isUnit = (token) => token[0] === "name" && isUnitWord(token[1]);
    // a unit word right after the operator at the current token ("/s")
    const unitAfter = () => at + 1 < tokens.length && isUnit(tokens[at + 1]);
    const spaceBefore = () => at < tokens.length && tokens[at][2];
    const startsItem = () => {
      const [kind, token] = peek();
      return kind === "number" || kind === "name" ||
        ["(", "[", "+", "-"].includes(token);
    };
    // a sign after whitespace and glued to what follows ("1 -2") opens a new item
    const signStartsItem = () =>
      spaceBefore() && at + 1 < tokens.length && !tokens[at + 1][2];

    // items separated by commas, semicolons or whitespace (as NumPy prints arrays);
    // brackets and parentheses around several items group them; each item is a pair
    // [value in SI, unit or null]; a unit after the last item only applies to all
    function items() {
      let pairs = item();
      for (;;) {
        if (peek()[1] === "," || peek()[1] === ";") {
          take();
        } else if (!(spaceBefore() && startsItem())) {
          break;
        }
        pairs = pairs.concat(item());
      }
      const last = pairs[pairs.length - 1][1];
      if (pairs.length > 1 && last !== null &&
          pairs.slice(0, -1).every((p) => p[1] === null)) {
        pairs = pairs.slice(0, -1).map((p) => [p[0] * last.factor, last])
          .concat([pairs[pairs.length - 1]]);
      }
      return pairs;
    }
    // a parenthesis that holds a list: a comma or semicolon inside it, outside any
    // inner parenthesis; decided by looking ahead, so nothing is parsed twice
    function isGroup() {
      let depth = 0;
      for (let i = at; i < tokens.length; i++) {
        const token = tokens[i][1];
        if (token === "(" || token === "[") {
          depth += 1;
        } else if (token === ")" || token === "]") {
          depth -= 1;
          if (depth === 0) return false;
        } else if ((token === "," || token === ";") && depth === 1) {
          return true;
        }
      }
      return false;
    }
    // the pairs of a bracketed list, [1, 2] or (2, 0, 0)
    function group() {
      const closing = take()[1] === "[" ? "]" : ")";
      const pairs = items();
      take(closing);
      return pairs;
    }
    function item() {
      if (peek()[1] === "[" || (peek()[1] === "(" && isGroup())) {
        const pairs = group();
        const u = unit(); // "(2, 0, 0) m": the unit of every entry
        if (u === null) return pairs;
        if (pairs.some((p) => p[1] !== null)) {
          throw new Error("a unit is written twice for one number");
        }
        return pairs.map((p) => [p[0] * u.factor, u]);
      }
      const value = expression();
      const u = unit();
      return [[u === null ? value : value * u.factor, u]];
    }
    // a unit at the current token: a unit word, "/s", or "1/s" after a space
    function unitStarts() {
      if (isUnit(peek()) || (peek()[1] === "/" && unitAfter())) return true;
      const [kind, token] = peek();
      return kind === "number" && token === "1" && spaceBefore() &&
        at + 2 < tokens.length && tokens[at + 1][1] === "/" && !tokens[at + 1][2] &&
        isUnit(tokens[at + 2]);
    }
    // the unit written after a value ("N m", "N*m", "m/s^2", "/s", "1/s"), or null
    function unit() {
      if (!unitStarts()) return null;
      let factor = 1;
      let dimension = [0, 0, 0, 0];
      if (peek()[0] === "number") take(); // the 1 of "1/s"
      let text = peek()[1] === "/" ? "1" : "";
      for (;;) {
        let sign = 1;
        if ((peek()[1] === "*" || peek()[1] === "/") && unitAfter()) {
          const operator = take()[1];
          sign = operator === "/" ? -1 : 1;
          text += operator === "/" ? "/" : " ";
        } else if (text && !(spaceBefore() && isUnit(peek()))) {
          break;
        } else if (text) {
          text += " ";
        }
        const word = take()[1];
        const [f, d] = UNITS[unitName(word)];
        text += word;
        let power = 1;
        if (peek()[1] === "^" || peek()[1] === "**") {
          take();
          const negative = peek()[1] === "-";
          if (negative) take();
          const [kind, digits] = take();
          if (kind !== "number" || !/^[0-9]+$/.test(digits)) {
            throw new Error("a unit's power must be an integer, got '" + digits + "'");
          }
          power = negative ? -parseInt(digits, 10) : parseInt(digits, 10);
          text += "^" + power;
        }
        factor *= Math.pow(f, sign * power);
        dimension = dimension.map((a, i) => a + sign * power * d[i]);
      }
      return { factor, dimension, text };
    }
    function expression() {
      let value = term();
      while ((peek()[1] === "+" || peek()[1] === "-") && !signStartsItem()) {
        const sign = take()[1];
        const right = term();
        value = sign === "+" ? value + right : value - right;
      }
      return value;
    }
    function term() {
      const start = at;
      let value = signed();
      let literal = at === start + 1 && tokens[start][0] === "number";
      for (;;) {
        const token = peek();
        if ((token[1] === "*" || token[1] === "/") && unitAfter()) {
          return value; // a unit follows: "10 N*m", "200/s"
        }
        if (literal && (token[1] === "pi" || token[1] === "π")) {
          take();
          value *= Math.PI; // "0.6667 pi", a number times pi
          literal = false;
          continue;
        }
        if (token[1] === "*" || token[1] === "/") {
          take();
          const right = signed();
          value = token[1] === "*" ? value * right : value / right;
        } else if (!spaceBefore() && (token[0] === "number" || token[1] === "(" ||
                   (token[0] === "name" && !isUnit(token)))) {
          value *= power(); // implicit product, written glued: 2pi
        } else {
          return value;
        }
      }
    }
    function signed() {
      if (peek()[1] === "+" || peek()[1] === "-") {
        const sign = take()[1];
        const value = signed();
        return sign === "+" ? value : -value;
      }
      return power();
    }
    function power() {
      let value = atom();
      if (peek()[1] === "^" || peek()[1] === "**") {
        take();
        value = Math.pow(value, signed());
      }
      return value;
    }
    function atom() {
      const [kind, token] = peek();
      if (kind === "number") {
        take();
        return parseFloat(token);
      }
      if (token === "(") {
        take("(");
        const value = expression();
        take(")");
        return value;
      }
      if (kind === "name" && own(FUNCTIONS, token)) {
        take();
        take("(");
        const args = [expression()];
        while (peek()[1] === ",") {
          take();
          args.push(expression());
        }
        take(")");
        return FUNCTIONS[token](...args);
      }
      if (kind === "name" && own(CONSTANTS, token)) {
        take();
        return CONSTANTS[token];
      }
      const found = kind === null ? "the end" : "'" + token + "'";
      throw new Error("expected a number, found " + found);
    }

    const pairs = items();
    const values = pairs.map((p) => p[0]);
    const units = pairs.map((p) => p[1]);
    if (peek()[0] !== null) throw new Error("unexpected '" + peek()[1] + "'");
    if (values.some((v) => !Number.isFinite(v))) {
      throw new Error("it is not a finite real number");
    }
    return { values, units };
  }

  function period(key) {
    return key.unit === "deg" ? 360 : 2 * Math.PI;
  }
  function wrap(d, p) {
    return ((((d + p / 2) % p) + p) % p) - p / 2;
  }
  function close(x, a, key) {
    const modulo = key.forms.includes("modulo 2pi");
    return x.every((v, i) => {
      let d = v - a[i];
      if (modulo) d = wrap(d, period(key));
      return Math.abs(d) <= key.tolerance + key.rtol * Math.abs(a[i]) + 1e-12;
    });
  }
  const sorted = (v) => v.slice().sort((p, q) => p - q);

  function matches(x, key) {
    let candidates = [key.values].concat(key.alternatives);
    if (key.forms.includes("either sign")) {
      candidates = candidates.concat(candidates.map((c) => c.map((v) => -v)));
    }
    return candidates.some((a) => {
      if (a.length !== x.length) return false;
      if (key.forms.includes("any order")) {
        if (key.forms.includes("modulo 2pi")) {
          const w = (v) => sorted(v.map((u) => wrap(u, period(key))));
          return close(w(x), w(a), key);
        }
        return close(sorted(x), sorted(a), key);
      }
      return close(x, a, key);
    });
  }

  function inRange(x, key) {
    const bounds = key.range;
    return !bounds || x.every((v) => bounds.low - key.tolerance <= v &&
                              v <= bounds.high + key.tolerance);
  }

  function diagnose(x, key) {
    const n = key.values.length;
    // a unit slip only explains an answer that is not zero (any small number fits 0)
    const nonzero = key.values.some((v) => Math.abs(v) > key.tolerance);
    for (const [unit, factor, text] of SLIPS) {
      if (nonzero && key.unit === unit && matches(x.map((v) => v * factor), key)) {
        return text + ".";
      }
    }
    if (matches(x.map((v) => -v), key)) return "the sign is flipped.";
    if (n > 1 && close(x.map(Math.abs), key.values.map(Math.abs), key)) {
      return "the magnitudes are right but some signs are wrong.";
    }
    if (n > 1 && !key.forms.includes("any order") &&
        close(sorted(x), sorted(key.values), key)) {
      return "the right numbers in the wrong order.";
    }
    if (!inRange(x, key)) {
      return "the answer is outside the range asked for, " + key.range.text + ".";
    }
    return null;
  }

  // the unit of a key ("N m", "1/s"; "" for a pure number)
  function keyUnit(text) {
    if (text === "") return { factor: 1, dimension: [0, 0, 0, 0], text: "" };
    return parse(text.startsWith("1/") ? text : "1 " + text).units[0];
  }

  // the factor from a typed unit to the key's, or null where they measure different
  // things; as _convert in exercises.py (the radian is 1 between other dimensions)
  function convert(unit, target) {
    if (sameDimension(unit.dimension, target.dimension)) {
      return unit.factor / target.factor;
    }
    const rest = unit.dimension.slice(0, 3);
    const keyRest = target.dimension.slice(0, 3);
    if (sameDimension(rest, keyRest) && rest.some((v) => v !== 0)) {
      return unit.factor / target.factor;
    }
    return null;
  }

  // a hint for "4,05" (read as two numbers): only where the text with decimal
  // points has the n numbers the key asks for
  function decimalComma(text, n) {
    if (!/\d,\d/.test(text)) return "";
    const fixed = text.replace(/(\d),(\d)/g, "$1.$2");
    try {
      if (parse(fixed).values.length !== n) return "";
    } catch (error) {
      return "";
    }
    return " Use a decimal point: " + fixed + ".";
  }


  function formatG(v) {
    // Python's "{:g}": six significant digits, no trailing zeros
    const [mantissa, e] = v.toExponential(5).split("e");
    const exponent = parseInt(e, 10);
    const strip = (text) => (text.includes(".") ? text.replace(/\.?0+$/, "") : text);
    if (exponent < -4 || exponent >= 6) {
      const digits = String(Math.abs(exponent)).padStart(2, "0");
      return strip(mantissa) + "e" + (exponent < 0 ? "-" : "+") + digits;
    }
    return strip(v.toFixed(Math.max(0, 5 - exponent)));
  }

  // The verdict on a typed answer: {correct, message}, the same as sk.exercises.check.
  function verdict(text, key) {
    let parsed;
    try {
      parsed = parse(String(text));
    } catch (error) {
      return { correct: false, message: "Could not read the answer: " + error.message };
    }
    const target = keyUnit(key.unit);
    // a key with "per" also takes the answer per unit of it (4.05 N per N m: 1/m)
    let per = null;
    if (key.per) {
      const of = keyUnit(key.per);
      per = { factor: target.factor / of.factor,
              dimension: target.dimension.map((v, i) => v - of.dimension[i]) };
    }
    // a vector of mixed units has one unit per number (a twist: rad/s and m/s)
    const texts = key.units || parsed.values.map(() => key.unit);
    const x = [];
    for (let i = 0; i < parsed.values.length; i++) {
      const unit = parsed.units[i];
      if (unit === null || texts.length !== parsed.values.length) {
        x.push(parsed.values[i]);
        continue;
      }
      const own = keyUnit(texts[i]);
      let factor = convert(unit, own);
      if (factor === null && per !== null) {
        factor = convert(unit, per);
        if (factor !== null) factor *= per.factor / own.factor;
      }
      if (factor === null) {
        const expected = quantity(own.dimension) +
          (texts[i] ? " (" + texts[i] + ")" : " (no unit)");
        const found = quantity(unit.dimension) + " (" + unit.text + ")";
        return { correct: false, message: "Expected " + expected + ", found " +
                 found + "." };
      }
      x.push(parsed.values[i] / unit.factor * factor);
    }
    const unit = key.unit ? " " + key.unit : "";
    const tolerance = "±" + formatG(key.tolerance) + unit;
    const n = key.values.length;
    if (x.length === n && inRange(x, key) && matches(x, key)) {
      return { correct: true, message: "Within " + tolerance + " of the answer." };
    }
    // a box in degrees answered in radians without a unit (pi/2, 1.5708)
    const nonzero = key.values.some((v) => Math.abs(v) > key.tolerance);
    if (x.length === n && key.unit === "deg" && nonzero &&
        parsed.units.every((u) => u === null)) {
      const degrees = x.map((v) => v / DEG);
      if (inRange(degrees, key) && matches(degrees, key)) {
        return { correct: true,
                 message: "Within " + tolerance + " of the answer (read as radians)." };
      }
    }
    let reason;
    if (x.length !== n) {
      const what = n === 1 ? "one number" : n + " numbers";
      reason = "expected " + what + ", got " + x.length + "." + decimalComma(String(text), n);
    } else {
      reason = diagnose(x, key) || "not within " + tolerance + " of the answer.";
    }
    const hint = key.hint ? " Hint: " + key.hint : "";
    const message = reason[0].toUpperCase() + reason.slice(1) + hint;
    return { correct: false, message };
  }

  function mount(box) {
    if (!box || box.dataset.mounted) return;
    box.dataset.mounted = "1";
    const data = box.querySelector("script[type='application/json']");
    const key = JSON.parse(data.textContent);
    const input = box.querySelector("input");
    const button = box.querySelector("button");
    const out = box.querySelector(".sk-verdict");
    const run = () => {
      const result = verdict(input.value, key);
      out.textContent = (result.correct ? "✓ Right: " : "✗ Not yet: ") + result.message;
      out.classList.toggle("sk-right", result.correct);
      out.classList.toggle("sk-wrong", !result.correct);
      input.setAttribute("aria-invalid", result.correct ? "false" : "true");
    };
    button.addEventListener("click", run);
    input.addEventListener("keydown", (event) => {
      if (event.key === "Enter") run();
    });
  }

  function mountAll() {
    document.querySelectorAll(".sk-answer-box").forEach(mount);
  }

  // The verdict's colours, light and dark (the book's dark theme, JupyterLab's): each
  // has a contrast of at least 4.5:1 with its theme's background
  const COLOURS = `
.sk-verdict.sk-right { color: #1a7f37; } .sk-verdict.sk-wrong { color: #b35900; }
html[data-theme="dark"] .sk-verdict.sk-right,
body[data-jp-theme-light="false"] .sk-verdict.sk-right { color: #56d364; }
html[data-theme="dark"] .sk-verdict.sk-wrong,
body[data-jp-theme-light="false"] .sk-verdict.sk-wrong { color: #f0883e; }`;
  if (document.head) {
    const style = document.createElement("style");
    style.textContent = COLOURS;
    document.head.appendChild(style);
  }

  window.screwkitExercises = { parse, verdict, mount, mountAll };
  mountAll();
})();
