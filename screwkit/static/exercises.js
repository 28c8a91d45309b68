// screwkit's self-checking answer boxes (screwkit/exercises.py renders them).
// Each box is a <div class="sk-answer-box"> holding its key as JSON; this script reads
// the student's text with a small parser (numbers, pi, sqrt, trigonometric functions,
// units, comma-separated vectors; never eval) and checks it with the rules of
// sk.exercises.check: tolerance, accepted forms, and why a wrong answer is wrong.
(function () {
  "use strict";
  if (window.screwkitExercises) return;

  const DEG = Math.PI / 180;
  const UNITS = {
    rad: [1, "angle"], deg: [DEG, "angle"], "°": [DEG, "angle"],
    m: [1, "length"], cm: [1e-2, "length"], mm: [1e-3, "length"],
    "m/s": [1, "speed"], "mm/s": [1e-3, "speed"],
    "rad/s": [1, "angular speed"], "deg/s": [DEG, "angular speed"],
  };
  const UNIT_NAMES = { degree: "deg", degrees: "deg", radian: "rad", radians: "rad" };
  const FUNCTIONS = {
    sqrt: Math.sqrt, sin: Math.sin, cos: Math.cos, tan: Math.tan, asin: Math.asin,
    acos: Math.acos, atan: Math.atan, atan2: Math.atan2, exp: Math.exp, ln: Math.log,
    log: Math.log, abs: Math.abs,
  };
  const CONSTANTS = { pi: Math.PI, "π": Math.PI, e: Math.E };
  const TOKEN = new RegExp(
    "^\\s*(?:((?:\\d+\\.?\\d*|\\.\\d+)(?:[eE][+-]?\\d+)?)" +
    "|(m/s|mm/s|rad/s|deg/s|°)|([A-Za-zπ_][A-Za-z0-9_]*)|(\\*\\*|[-+*/^(),;\\[\\]]))");
  const KINDS = ["number", "unit", "name", "op"];
  const own = (table, key) => Object.prototype.hasOwnProperty.call(table, key);
  const unitName = (word) => (own(UNIT_NAMES, word) ? UNIT_NAMES[word] : word);

  function tokenize(text) {
    text = text.replace(/−/g, "-").replace(/[×·]/g, "*").replace(/√/g, "sqrt");
    const tokens = [];
    let rest = text;
    while (rest.trim() !== "") {
      const match = TOKEN.exec(rest);
      if (!match || match[0].length === 0) {
        throw new Error("cannot read '" + rest.trim().slice(0, 12) + "'");
      }
      const group = [1, 2, 3, 4].find((i) => match[i] !== undefined);
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
    const units = [];
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
    const isUnit = (token) =>
      (token[0] === "unit" || token[0] === "name") && own(UNITS, unitName(token[1]));
    const spaceBefore = () => at < tokens.length && tokens[at][2];
    const startsItem = () => {
      const [kind, token] = peek();
      return kind === "number" || kind === "name" ||
        ["(", "[", "+", "-"].includes(token);
    };
    // a sign after whitespace and glued to what follows ("1 -2") opens a new item
    const signStartsItem = () =>
      spaceBefore() && at + 1 < tokens.length && !tokens[at + 1][2];

    // items separated by commas, semicolons or whitespace (as NumPy prints arrays)
    function items() {
      let values = item();
      for (;;) {
        if (peek()[1] === "," || peek()[1] === ";") {
          take();
        } else if (!(spaceBefore() && startsItem())) {
          return values;
        }
        values = values.concat(item());
      }
    }
    function item() {
      if (peek()[1] === "[") {
        take("[");
        const values = items();
        take("]");
        return values;
      }
      const value = expression();
      if (isUnit(peek())) {
        const [factor, quantity] = UNITS[unitName(take()[1])];
        units.push(quantity);
        return [value * factor];
      }
      units.push(null);
      return [value];
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
      let value = signed();
      for (;;) {
        const token = peek();
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

    const values = items();
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

  function diagnose(x, key) {
    const n = key.values.length;
    if (x.length !== n) {
      const what = n === 1 ? "one number" : n + " numbers";
      return "expected " + what + ", got " + x.length + ".";
    }
    const slips = [
      ["rad", DEG, "looks like degrees, radians expected"],
      ["deg", 1 / DEG, "looks like radians, degrees expected"],
      ["m", 1e-3, "looks like millimetres, metres expected"],
      ["mm", 1e3, "looks like metres, millimetres expected"],
    ];
    // a unit slip only explains an answer that is not zero (any small number fits 0)
    const nonzero = key.values.some((v) => Math.abs(v) > key.tolerance);
    for (const [unit, factor, text] of slips) {
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
    return null;
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
    let x = parsed.values;
    const [factor, quantity] = own(UNITS, key.unit) ? UNITS[key.unit] : [1, null];
    const given = Array.from(new Set(parsed.units.filter((u) => u !== null))).sort();
    if (given.length > 0) {
      if (quantity === null || given.length !== 1 || given[0] !== quantity) {
        const expected = key.unit ? "in " + key.unit : "a pure number";
        return { correct: false, message: "The answer is " + expected +
                 ", but the units typed are " + given.join(" and ") + "." };
      }
      x = x.map((v, i) => (parsed.units[i] !== null ? v / factor : v));
    }
    const unit = key.unit ? " " + key.unit : "";
    const within = "within ±" + formatG(key.tolerance) + unit;
    if (matches(x, key)) {
      return { correct: true, message: "Within ±" + formatG(key.tolerance) + unit +
               " of the answer." };
    }
    const reason = diagnose(x, key) || "not " + within + " of the answer.";
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
      out.style.color = result.correct ? "#1a7f37" : "#b35900";
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

  window.screwkitExercises = { parse, verdict, mount, mountAll };
  mountAll();
})();
