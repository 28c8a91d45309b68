/* screwkit viewer: interactive kinematics figures computed in the page.
 *
 * Python (screwkit/viewer.py) hands each figure its parameters as JSON: a chain's joint
 * screws S_i = [omega; v] and home pose M (product of exponentials), a screw (s, r, h), or
 * precomputed frames. This script computes the kinematics (exponentials of twists, forward
 * kinematics, the position Jacobian and its ellipsoid) and draws on a 2D canvas with its own
 * orthographic projection: drag to orbit, wheel to zoom, double-click to reset.
 * No dependencies, nothing loaded from the network. Units: m and rad (sliders show deg).
 */
(function () {
  "use strict";
  var VERSION = "1";
  if (window.screwkit && window.screwkit.version === VERSION) return;

  // ---- small linear algebra: 4x4 row-major arrays of 16 numbers -------------------------
  function identity() { return [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]; }

  function matmul(A, B) {
    var C = new Array(16);
    for (var i = 0; i < 4; i++) {
      for (var j = 0; j < 4; j++) {
        C[4 * i + j] = A[4 * i] * B[j] + A[4 * i + 1] * B[4 + j] +
          A[4 * i + 2] * B[8 + j] + A[4 * i + 3] * B[12 + j];
      }
    }
    return C;
  }

  function apply(T, p) {  // the point p (3) moved by T
    return [T[0] * p[0] + T[1] * p[1] + T[2] * p[2] + T[3],
      T[4] * p[0] + T[5] * p[1] + T[6] * p[2] + T[7],
      T[8] * p[0] + T[9] * p[1] + T[10] * p[2] + T[11]];
  }

  function rotate(T, d) {  // the direction d (3) turned by the rotation of T
    return [T[0] * d[0] + T[1] * d[1] + T[2] * d[2],
      T[4] * d[0] + T[5] * d[1] + T[6] * d[2],
      T[8] * d[0] + T[9] * d[1] + T[10] * d[2]];
  }

  function cross(a, b) {
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
  }

  function flat(rows) { return [].concat.apply([], rows); }

  // exp([S] theta) for a twist S = [omega; v] (any |omega|; omega = 0 is a translation)
  function expTwist(S, theta) {
    var w = [S[0], S[1], S[2]], v = [S[3], S[4], S[5]];
    var n = Math.hypot(w[0], w[1], w[2]);
    if (n < 1e-12) {
      return [1, 0, 0, v[0] * theta, 0, 1, 0, v[1] * theta, 0, 0, 1, v[2] * theta, 0, 0, 0, 1];
    }
    w = [w[0] / n, w[1] / n, w[2] / n]; v = [v[0] / n, v[1] / n, v[2] / n];
    var t = theta * n, s = Math.sin(t), c = 1 - Math.cos(t), g = t - Math.sin(t);
    var K = [0, -w[2], w[1], w[2], 0, -w[0], -w[1], w[0], 0];
    var K2 = new Array(9);
    for (var i = 0; i < 3; i++) {
      for (var j = 0; j < 3; j++) {
        K2[3 * i + j] = K[3 * i] * K[j] + K[3 * i + 1] * K[3 + j] + K[3 * i + 2] * K[6 + j];
      }
    }
    var T = identity();
    for (i = 0; i < 3; i++) {
      var p = 0;
      for (j = 0; j < 3; j++) {
        var eye = i === j ? 1 : 0;
        T[4 * i + j] = eye + s * K[3 * i + j] + c * K2[3 * i + j];
        p += (eye * t + c * K[3 * i + j] + g * K2[3 * i + j]) * v[j];
      }
      T[4 * i + 3] = p;
    }
    return T;
  }

  // The chain at q: before[i] is exp([S_1]q_1)...exp([S_{i-1}]q_{i-1}), tool = product @ M
  function chainPose(model, q) {
    var T = identity(), before = [];
    for (var i = 0; i < model.screws.length; i++) {
      before.push(T);
      T = matmul(T, expTwist(model.screws[i], q[i]));
    }
    return { before: before, tool: matmul(T, flat(model.home)) };
  }

  // Rows v of the geometric Jacobian (3 x n) at the tool point: v_i + omega_i x p
  function positionJacobian(model, pose) {
    var p = [pose.tool[3], pose.tool[7], pose.tool[11]], columns = [];
    for (var i = 0; i < model.screws.length; i++) {
      var T = pose.before[i], S = model.screws[i];
      var w = rotate(T, S.slice(0, 3)), o = [T[3], T[7], T[11]];
      var v = rotate(T, S.slice(3, 6)), ow = cross(o, w), wp = cross(w, p);
      columns.push([v[0] + ow[0] + wp[0], v[1] + ow[1] + wp[1], v[2] + ow[2] + wp[2]]);
    }
    return columns;
  }

  // Eigen-decomposition of a symmetric 3x3 matrix A (9, row-major) by cyclic Jacobi rotations
  function symmetricEigen(A) {
    var a = A.slice(), V = [1, 0, 0, 0, 1, 0, 0, 0, 1];
    for (var sweep = 0; sweep < 50; sweep++) {
      var off = a[1] * a[1] + a[2] * a[2] + a[5] * a[5];
      if (off < 1e-30) break;
      for (var p = 0; p < 2; p++) {
        for (var r = p + 1; r < 3; r++) {
          var apr = a[3 * p + r];
          if (Math.abs(apr) < 1e-300) continue;
          var theta = (a[3 * r + r] - a[3 * p + p]) / (2 * apr);
          var t = Math.sign(theta || 1) / (Math.abs(theta) + Math.sqrt(theta * theta + 1));
          var c = 1 / Math.sqrt(t * t + 1), s = t * c;
          for (var k = 0; k < 3; k++) {  // a <- a J, then J^T a, V <- V J
            var akp = a[3 * k + p], akr = a[3 * k + r];
            a[3 * k + p] = c * akp - s * akr; a[3 * k + r] = s * akp + c * akr;
          }
          for (k = 0; k < 3; k++) {
            var apk = a[3 * p + k], ark = a[3 * r + k];
            a[3 * p + k] = c * apk - s * ark; a[3 * r + k] = s * apk + c * ark;
          }
          for (k = 0; k < 3; k++) {
            var vkp = V[3 * k + p], vkr = V[3 * k + r];
            V[3 * k + p] = c * vkp - s * vkr; V[3 * k + r] = s * vkp + c * vkr;
          }
        }
      }
    }
    return { values: [a[0], a[4], a[8]], vectors: V };  // eigenvector k is column k of V
  }

  // The translational manipulability ellipsoid: radii (m/s), axes (columns), w = sqrt(det J J^T)
  function ellipsoid(model, pose) {
    var J = positionJacobian(model, pose), A = [0, 0, 0, 0, 0, 0, 0, 0, 0];
    J.forEach(function (col) {
      for (var i = 0; i < 3; i++) for (var j = 0; j < 3; j++) A[3 * i + j] += col[i] * col[j];
    });
    var eig = symmetricEigen(A);
    var radii = eig.values.map(function (x) { return Math.sqrt(Math.max(x, 0)); });
    return { radii: radii, axes: eig.vectors, w: radii[0] * radii[1] * radii[2] };
  }

  // ---- drawing --------------------------------------------------------------------------
  function Camera(radius, centre) {
    this.radius = radius; this.centre = centre; this.reset();
  }
  Camera.prototype.reset = function () { this.azimuth = -0.9; this.elevation = 0.35; this.zoom = 1; };
  Camera.prototype.basis = function () {
    var ca = Math.cos(this.azimuth), sa = Math.sin(this.azimuth);
    var ce = Math.cos(this.elevation), se = Math.sin(this.elevation);
    this.right = [-sa, ca, 0]; this.up = [-se * ca, -se * sa, ce];
  };
  Camera.prototype.project = function (p, width, height) {
    var d = [p[0] - this.centre[0], p[1] - this.centre[1], p[2] - this.centre[2]];
    var k = this.zoom * Math.min(width, height) / (2.2 * this.radius);
    return [width / 2 + k * (d[0] * this.right[0] + d[1] * this.right[1]),
      height / 2 - k * (d[0] * this.up[0] + d[1] * this.up[1] + d[2] * this.up[2])];
  };

  function Painter(canvas, camera) {
    this.canvas = canvas; this.camera = camera; this.ctx = canvas.getContext("2d");
  }
  Painter.prototype.begin = function () {
    var ratio = window.devicePixelRatio || 1, c = this.canvas;
    this.width = c.clientWidth || c.width; this.height = c.clientHeight || c.height;
    if (c.width !== Math.round(this.width * ratio)) {
      c.width = Math.round(this.width * ratio); c.height = Math.round(this.height * ratio);
    }
    this.ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
    this.ctx.clearRect(0, 0, this.width, this.height);
    this.ctx.lineCap = "round"; this.ctx.lineJoin = "round";
    this.camera.basis();
  };
  Painter.prototype.xy = function (p) { return this.camera.project(p, this.width, this.height); };
  Painter.prototype.line = function (points, colour, width, dash) {
    var ctx = this.ctx;
    ctx.beginPath();
    points.forEach(function (p, i) {
      var s = this.xy(p);
      if (i === 0) ctx.moveTo(s[0], s[1]); else ctx.lineTo(s[0], s[1]);
    }, this);
    ctx.strokeStyle = colour; ctx.lineWidth = width || 1; ctx.setLineDash(dash || []);
    ctx.stroke(); ctx.setLineDash([]);
  };
  Painter.prototype.dot = function (p, colour, size) {
    var s = this.xy(p);
    this.ctx.beginPath(); this.ctx.arc(s[0], s[1], size, 0, 2 * Math.PI);
    this.ctx.fillStyle = colour; this.ctx.fill();
  };
  Painter.prototype.text = function (p, label, colour) {
    var s = this.xy(p);
    this.ctx.fillStyle = colour || "#333"; this.ctx.font = "12px sans-serif";
    this.ctx.fillText(label, s[0] + 4, s[1] - 4);
  };
  Painter.prototype.frame = function (T, length, label, alpha) {
    var o = [T[3], T[7], T[11]], colours = ["#d62728", "#2ca02c", "#1f77b4"];
    this.ctx.globalAlpha = alpha || 1;
    for (var k = 0; k < 3; k++) {
      var e = [T[k] * length, T[4 + k] * length, T[8 + k] * length];
      this.line([o, [o[0] + e[0], o[1] + e[1], o[2] + e[2]]], colours[k], 2.5);
    }
    if (label) this.text(o, label);
    this.ctx.globalAlpha = 1;
  };
  Painter.prototype.grid = function (radius) {
    var r = radius, lines = 4;
    for (var k = -lines; k <= lines; k++) {
      var x = r * k / lines;
      this.line([[x, -r, 0], [x, r, 0]], "#e4e4e4", 1);
      this.line([[-r, x, 0], [r, x, 0]], "#e4e4e4", 1);
    }
  };

  // ---- figures --------------------------------------------------------------------------
  function fixed(values, digits) {
    return "(" + values.map(function (x) { return (Math.abs(x) < 0.5 * Math.pow(10, -digits) ? 0 : x).toFixed(digits); }).join(", ") + ")";
  }

  function RobotFigure(model, painter) {
    this.model = model; this.painter = painter;
  }
  RobotFigure.prototype.draw = function (q) {
    var m = this.model, P = this.painter, pose = chainPose(m, q), r = m.radius;
    P.begin(); P.grid(r); P.frame(identity(), 0.2 * r, "0", 0.5);
    var points = [[0, 0, 0]];
    for (var i = 0; i < m.screws.length; i++) points.push(apply(pose.before[i], m.points[i]));
    var tool = [pose.tool[3], pose.tool[7], pose.tool[11]];
    points.push(tool);
    P.line(points, "#555", 5);
    for (i = 0; i < m.screws.length; i++) {
      var o = points[i + 1], z = rotate(pose.before[i], m.axes[i]), h = 0.06 * r;
      var prismatic = m.joints[i] === "P";
      P.line([[o[0] - h * z[0], o[1] - h * z[1], o[2] - h * z[2]],
        [o[0] + h * z[0], o[1] + h * z[1], o[2] + h * z[2]]], prismatic ? "#9467bd" : "#ff7f0e", 7);
    }
    P.frame(pose.tool, 0.15 * r, "tool");
    var text = "tool at " + fixed(tool, 3) + " m";
    if (m.ellipsoid) {
      var e = ellipsoid(m, pose), scale = m.ellipsoid_scale;
      for (var a = 0; a < 3; a++) {  // the three principal ellipses
        var b = (a + 1) % 3, ring = [];
        for (var k = 0; k <= 48; k++) {
          var t = 2 * Math.PI * k / 48, ca = Math.cos(t) * e.radii[a] * scale,
            cb = Math.sin(t) * e.radii[b] * scale, V = e.axes;
          ring.push([tool[0] + ca * V[a] + cb * V[b], tool[1] + ca * V[3 + a] + cb * V[3 + b],
            tool[2] + ca * V[6 + a] + cb * V[6 + b]]);
        }
        P.line(ring, "#17becf", 1.8);
      }
      text += ", radii " + fixed(e.radii.slice().sort(function (x, y) { return y - x; }), 3) +
        " m/s, w = " + e.w.toFixed(4);
      this.lastEllipsoid = e;
    }
    this.lastPose = pose;
    return text;
  };

  function ScrewFigure(model, painter) {
    this.model = model; this.painter = painter;
    var s = model.s, r = model.r;
    this.twist = model.h === null ? [0, 0, 0, s[0], s[1], s[2]]
      : [s[0], s[1], s[2]].concat(cross(r, s).map(function (x, i) { return x + model.h * s[i]; }));
  }
  ScrewFigure.prototype.pose = function (theta) {
    return matmul(expTwist(this.twist, theta), flat(this.model.start));
  };
  ScrewFigure.prototype.draw = function (values) {
    var m = this.model, P = this.painter, theta = values[0], R = m.radius, s = m.s, r = m.r;
    P.begin(); P.grid(R); P.frame(identity(), 0.25 * R, "0", 0.4);
    P.line([[r[0] - R * s[0], r[1] - R * s[1], r[2] - R * s[2]],
      [r[0] + R * s[0], r[1] + R * s[1], r[2] + R * s[2]]], "#7f7f7f", 1.5, [6, 4]);
    var path = [], start = flat(m.start);
    for (var k = 0; k <= 60; k++) {
      path.push(apply(expTwist(this.twist, theta * k / 60), [start[3], start[7], start[11]]));
    }
    P.line(path, "#9467bd", 2);
    P.frame(start, 0.25 * R, "", 0.35);
    var T = this.pose(theta);
    P.frame(T, 0.25 * R, "moved");
    this.lastPose = T;
    return m.slider.label + " = " + (theta / m.slider.scale).toFixed(m.slider.digits) + " " +
      m.slider.unit + ": frame origin at " + fixed([T[3], T[7], T[11]], 3) + " m";
  };

  // ---- mounting: one figure per <div class="screwkit-viewer"> ---------------------------
  function el(tag, attrs, parent) {
    var node = document.createElement(tag);
    Object.keys(attrs || {}).forEach(function (k) { node.setAttribute(k, attrs[k]); });
    if (parent) parent.appendChild(node);
    return node;
  }

  function digits(step) {  // decimals that show every grid value of a slider exactly
    var d = 0;
    while (d < 6 && Math.abs(step * Math.pow(10, d) - Math.round(step * Math.pow(10, d))) > 1e-9) d++;
    return d;
  }

  function addSlider(spec, parent, onInput) {
    var row = el("label", { "class": "screwkit-slider" }, parent);
    el("span", {}, row).textContent = spec.label + " (" + spec.unit + ")";
    var input = el("input", { type: "range", min: spec.min, max: spec.max, step: spec.step,
      value: spec.value, "aria-label": spec.label + " (" + spec.unit + ")" }, row);
    var readout = el("output", {}, row);
    spec.digits = digits(spec.step);
    input.addEventListener("input", onInput);
    return { input: input, readout: readout, spec: spec };
  }

  function orbit(canvas, camera, redraw) {
    var last = null;
    canvas.addEventListener("pointerdown", function (e) {
      last = [e.clientX, e.clientY];
      if (canvas.setPointerCapture) canvas.setPointerCapture(e.pointerId);
    });
    canvas.addEventListener("pointermove", function (e) {
      if (!last) return;
      camera.azimuth -= 0.01 * (e.clientX - last[0]);
      camera.elevation = Math.max(-1.55, Math.min(1.55, camera.elevation + 0.01 * (e.clientY - last[1])));
      last = [e.clientX, e.clientY]; redraw();
    });
    canvas.addEventListener("pointerup", function () { last = null; });
    canvas.addEventListener("wheel", function (e) {
      e.preventDefault();
      camera.zoom = Math.max(0.2, Math.min(8, camera.zoom * Math.exp(-0.001 * e.deltaY)));
      redraw();
    }, { passive: false });
    canvas.addEventListener("dblclick", function () { camera.reset(); redraw(); });
  }

  function mountSteps(root, model) {
    var view = el("div", { "class": "screwkit-frame" }, root), controls = el("div", {}, root);
    var show = function (index) {
      var frame = model.frames[index];
      view.innerHTML = frame;
    };
    var control;
    if (model.choices) {
      var row = el("label", { "class": "screwkit-slider" }, controls);
      el("span", {}, row).textContent = model.label;
      control = el("select", { "aria-label": model.label }, row);
      model.choices.forEach(function (name, i) {
        var option = el("option", { value: i }, control);
        option.textContent = name;
        if (i === model.index) option.selected = true;
      });
      control.addEventListener("change", function () { show(+control.value); });
    } else {
      var s = model.slider, values = model.values;
      control = addSlider(s, controls, function () {
        var i = Math.round((+control.input.value - s.min) / s.step);
        control.readout.textContent = values[i].toFixed(s.digits);
        show(i);
      });
      control.readout.textContent = s.value.toFixed(s.digits);
    }
    show(model.index);
    return { show: show };
  }

  function mount(root) {
    if (!root || root.getAttribute("data-mounted")) return null;
    root.setAttribute("data-mounted", "1");
    var model = JSON.parse(root.querySelector("script[type='application/json']").textContent);
    if (model.kind === "steps") return register(root, mountSteps(root, model));
    var canvas = el("canvas", { width: model.width, height: model.height,
      style: "width:" + model.width + "px;height:" + model.height + "px;touch-action:none;cursor:grab" }, root);
    var caption = el("div", { "class": "screwkit-caption" }, root);
    var controls = el("div", { "class": "screwkit-controls" }, root);
    var camera = new Camera(model.radius, model.centre || [0, 0, 0]);
    var painter = new Painter(canvas, camera);
    var figure = model.kind === "robot" ? new RobotFigure(model, painter) : new ScrewFigure(model, painter);
    var specs = model.kind === "robot" ? model.sliders : [model.slider];
    var sliders = [];
    var redraw = function () {
      var values = sliders.map(function (s) { return +s.input.value * s.spec.scale; });
      sliders.forEach(function (s) { s.readout.textContent = (+s.input.value).toFixed(s.spec.digits); });
      caption.textContent = figure.draw(values);
    };
    specs.forEach(function (spec) { sliders.push(addSlider(spec, controls, redraw)); });
    orbit(canvas, camera, redraw);
    redraw();
    return register(root, { figure: figure, redraw: redraw, sliders: sliders, camera: camera });
  }

  function register(root, viewer) {
    window.screwkit.viewers[root.id] = viewer;
    return viewer;
  }

  function mountAll() {
    var roots = document.querySelectorAll("div.screwkit-viewer:not([data-mounted])");
    Array.prototype.forEach.call(roots, mount);
  }

  window.screwkit = {
    version: VERSION, viewers: {}, mount: mount, mountAll: mountAll, expTwist: expTwist,
    chainPose: chainPose, positionJacobian: positionJacobian, symmetricEigen: symmetricEigen,
    ellipsoid: ellipsoid
  };
})();
