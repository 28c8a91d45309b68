/* screwkit viewer: interactive kinematics figures computed in the page, in three.js.
 *
 * Python (screwkit/viewer.py) hands each figure its parameters as JSON: a chain's joint
 * screws S_i = [omega; v] and home pose M (product of exponentials), a screw (s, r, h),
 * a parallel platform's attachment points, a mechanism's joints, or precomputed frames.
 * This script computes the kinematics in double precision (exponentials of twists,
 * forward kinematics, the position Jacobian and its ellipsoid, leg lengths) and draws
 * with three.js (window.THREE, vendored from npm, shipped once per page by viewer.py).
 * Drag to orbit; Ctrl+wheel, pinch or the buttons to zoom; arrow keys and +/- when
 * focused. Nothing is loaded from the network. Units: m and rad (sliders show deg).
 */
(function () {
  "use strict";
  var VERSION = "2";
  if (window.screwkit && window.screwkit.version === VERSION) {
    window.screwkit.mountAll();
    return;
  }

  // ---- small linear algebra: 4x4 row-major arrays of 16 numbers ---------------------
  function identity() {
    return [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1];
  }

  function matmul(A, B) {
    var C = new Array(16);
    for (var i = 0; i < 4; i++) {
      for (var j = 0; j < 4; j++) {
        C[4 * i + j] =
          A[4 * i] * B[j] +
          A[4 * i + 1] * B[4 + j] +
          A[4 * i + 2] * B[8 + j] +
          A[4 * i + 3] * B[12 + j];
      }
    }
    return C;
  }

  function apply(T, p) {
    // the point p (3) moved by T
    return [
      T[0] * p[0] + T[1] * p[1] + T[2] * p[2] + T[3],
      T[4] * p[0] + T[5] * p[1] + T[6] * p[2] + T[7],
      T[8] * p[0] + T[9] * p[1] + T[10] * p[2] + T[11]
    ];
  }

  function rotate(T, d) {
    // the direction d (3) turned by the rotation of T
    return [
      T[0] * d[0] + T[1] * d[1] + T[2] * d[2],
      T[4] * d[0] + T[5] * d[1] + T[6] * d[2],
      T[8] * d[0] + T[9] * d[1] + T[10] * d[2]
    ];
  }

  function cross(a, b) {
    return [
      a[1] * b[2] - a[2] * b[1],
      a[2] * b[0] - a[0] * b[2],
      a[0] * b[1] - a[1] * b[0]
    ];
  }

  function sub(a, b) {
    return [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
  }
  function norm(a) {
    return Math.hypot(a[0], a[1], a[2]);
  }
  function flat(rows) {
    return [].concat.apply([], rows);
  }
  function origin(T) {
    return [T[3], T[7], T[11]];
  }

  // exp([S] theta) for a twist S = [omega; v] (any |omega|; omega = 0 is a translation)
  function expTwist(S, theta) {
    var w = [S[0], S[1], S[2]],
      v = [S[3], S[4], S[5]];
    var n = Math.hypot(w[0], w[1], w[2]);
    if (n < 1e-12) {
      return [
        1,
        0,
        0,
        v[0] * theta,
        0,
        1,
        0,
        v[1] * theta,
        0,
        0,
        1,
        v[2] * theta,
        0,
        0,
        0,
        1
      ];
    }
    w = [w[0] / n, w[1] / n, w[2] / n];
    v = [v[0] / n, v[1] / n, v[2] / n];
    var t = theta * n,
      s = Math.sin(t),
      c = 1 - Math.cos(t),
      g = t - Math.sin(t);
    var K = [0, -w[2], w[1], w[2], 0, -w[0], -w[1], w[0], 0];
    var K2 = new Array(9);
    for (var i = 0; i < 3; i++) {
      for (var j = 0; j < 3; j++) {
        K2[3 * i + j] =
          K[3 * i] * K[j] + K[3 * i + 1] * K[3 + j] + K[3 * i + 2] * K[6 + j];
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

  // The chain at q: before[i] = exp([S_1]q_1)...exp([S_{i-1}]q_{i-1}); tool = product M
  function chainPose(model, q) {
    var T = identity(),
      before = [];
    for (var i = 0; i < model.screws.length; i++) {
      before.push(T);
      T = matmul(T, expTwist(model.screws[i], q[i]));
    }
    return { before: before, tool: matmul(T, flat(model.home)) };
  }

  // Rows v of the geometric Jacobian (3 x n) at the tool point: v_i + omega_i x p
  function positionJacobian(model, pose) {
    var p = origin(pose.tool),
      columns = [];
    for (var i = 0; i < model.screws.length; i++) {
      var T = pose.before[i],
        S = model.screws[i];
      var w = rotate(T, S.slice(0, 3)),
        o = origin(T);
      var v = rotate(T, S.slice(3, 6)),
        ow = cross(o, w),
        wp = cross(w, p);
      columns.push([v[0] + ow[0] + wp[0], v[1] + ow[1] + wp[1], v[2] + ow[2] + wp[2]]);
    }
    return columns;
  }

  // Eigen-decomposition of a symmetric 3x3 matrix A (9, row-major), cyclic Jacobi
  function symmetricEigen(A) {
    var a = A.slice(),
      V = [1, 0, 0, 0, 1, 0, 0, 0, 1];
    for (var sweep = 0; sweep < 50; sweep++) {
      var off = a[1] * a[1] + a[2] * a[2] + a[5] * a[5];
      if (off < 1e-30) break;
      for (var p = 0; p < 2; p++) {
        for (var r = p + 1; r < 3; r++) {
          var apr = a[3 * p + r];
          if (Math.abs(apr) < 1e-300) continue;
          var theta = (a[3 * r + r] - a[3 * p + p]) / (2 * apr);
          var t =
            Math.sign(theta || 1) / (Math.abs(theta) + Math.sqrt(theta * theta + 1));
          var c = 1 / Math.sqrt(t * t + 1),
            s = t * c;
          for (var k = 0; k < 3; k++) {
            // a <- a J, then J^T a, V <- V J
            var akp = a[3 * k + p],
              akr = a[3 * k + r];
            a[3 * k + p] = c * akp - s * akr;
            a[3 * k + r] = s * akp + c * akr;
          }
          for (k = 0; k < 3; k++) {
            var apk = a[3 * p + k],
              ark = a[3 * r + k];
            a[3 * p + k] = c * apk - s * ark;
            a[3 * r + k] = s * apk + c * ark;
          }
          for (k = 0; k < 3; k++) {
            var vkp = V[3 * k + p],
              vkr = V[3 * k + r];
            V[3 * k + p] = c * vkp - s * vkr;
            V[3 * k + r] = s * vkp + c * vkr;
          }
        }
      }
    }
    return { values: [a[0], a[4], a[8]], vectors: V }; // eigenvector k is column k of V
  }

  // The translational manipulability ellipsoid: radii (m/s), axes (columns),
  // w = sqrt(det J J^T)
  function ellipsoid(model, pose) {
    var J = positionJacobian(model, pose),
      A = [0, 0, 0, 0, 0, 0, 0, 0, 0];
    J.forEach(function (col) {
      for (var i = 0; i < 3; i++)
        for (var j = 0; j < 3; j++) A[3 * i + j] += col[i] * col[j];
    });
    var eig = symmetricEigen(A);
    var radii = eig.values.map(function (x) {
      return Math.sqrt(Math.max(x, 0));
    });
    return { radii: radii, axes: eig.vectors, w: radii[0] * radii[1] * radii[2] };
  }

  // Rotations about the fixed axes (row-major 4x4)
  function rotX(t) {
    var c = Math.cos(t),
      s = Math.sin(t);
    return [1, 0, 0, 0, 0, c, -s, 0, 0, s, c, 0, 0, 0, 0, 1];
  }
  function rotY(t) {
    var c = Math.cos(t),
      s = Math.sin(t);
    return [c, 0, s, 0, 0, 1, 0, 0, -s, 0, c, 0, 0, 0, 0, 1];
  }
  function rotZ(t) {
    var c = Math.cos(t),
      s = Math.sin(t);
    return [c, -s, 0, 0, s, c, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1];
  }

  // A platform's pose from its slider offsets (SI): p = p_home + d, R = Rz Ry Rx R_home
  // (spatial: x, y, z, roll, pitch, yaw; planar: x, y, phi)
  function platformPose(model, values) {
    var H = flat(model.home),
      d,
      R;
    if (model.planar) {
      d = [values[0], values[1], 0];
      R = rotZ(values[2]);
    } else {
      d = [values[0], values[1], values[2]];
      R = matmul(rotZ(values[5]), matmul(rotY(values[4]), rotX(values[3])));
    }
    var T = matmul(R, [
      H[0],
      H[1],
      H[2],
      0,
      H[4],
      H[5],
      H[6],
      0,
      H[8],
      H[9],
      H[10],
      0,
      0,
      0,
      0,
      1
    ]);
    T[3] = H[3] + d[0];
    T[7] = H[7] + d[1];
    T[11] = H[11] + d[2];
    return T;
  }

  // Leg i's length |p + R b_i - a_i| (m) at the platform pose T
  function legLengths(model, T) {
    return model.base.map(function (a, i) {
      return norm(sub(apply(T, model.platform[i]), a));
    });
  }

  // ---- page styles, once per document -----------------------------------------------
  var CSS = [
    ".screwkit-viewer{font:14px/1.4 system-ui,sans-serif;color:inherit;max-width:100%;",
    "margin:.5em 0}",
    ".screwkit-stage{position:relative;width:100%;background:#f7f8fa;",
    "border:1px solid #d8dce2;",
    "border-radius:6px;overflow:hidden;box-sizing:border-box}",
    ".screwkit-stage canvas{display:block;width:100%;height:100%;touch-action:pan-y;",
    "cursor:grab;outline:none}",
    ".screwkit-stage canvas:focus-visible{box-shadow:inset 0 0 0 3px #2b6cb0}",
    ".screwkit-labels{position:absolute;inset:0;pointer-events:none;overflow:hidden}",
    ".screwkit-labels span{position:absolute;transform:translate(-50%,-50%);",
    "font:600 12px/1 ",
    "system-ui,sans-serif;background:rgba(255,255,255,.88);color:#1a1a1a;",
    "border:1px solid #8a94a3;",
    "border-radius:9px;padding:2px 5px;white-space:nowrap}",
    ".screwkit-labels span.screwkit-bad{background:#fde2e1;border-color:#c53030;",
    "color:#9b2c2c}",
    ".screwkit-buttons{position:absolute;top:6px;right:6px;display:flex;gap:4px}",
    ".screwkit-buttons button{width:32px;height:32px;",
    "font:600 17px/1 system-ui,sans-serif;",
    "border:1px solid #9aa3ad;border-radius:5px;background:rgba(255,255,255,.92);",
    "color:#222;",
    "cursor:pointer;padding:0}",
    ".screwkit-caption{margin:.35em 0;font-variant-numeric:tabular-nums;",
    "min-height:2.8em}",
    ".screwkit-controls{display:grid;",
    "grid-template-columns:max-content minmax(5rem,1fr) ",
    "max-content max-content;gap:.15em .6em;align-items:center;max-width:40rem}",
    ".screwkit-controls label{font-weight:600;white-space:nowrap}",
    ".screwkit-controls input[type=range]{width:100%;min-width:0;margin:0;height:26px}",
    ".screwkit-controls output{text-align:right;font-variant-numeric:tabular-nums;",
    "font-family:ui-monospace,monospace;display:inline-block}",
    ".screwkit-controls .screwkit-unit{opacity:.75}",
    ".screwkit-frame img{max-width:100%;height:auto}",
    ".screwkit-note{padding:1em;opacity:.8}"
  ].join("");

  function addStyle() {
    if (document.getElementById("screwkit-viewer-style")) return;
    var style = document.createElement("style");
    style.id = "screwkit-viewer-style";
    style.textContent = CSS;
    (document.head || document.documentElement).appendChild(style);
  }

  function el(tag, attrs, parent) {
    var node = document.createElement(tag);
    Object.keys(attrs || {}).forEach(function (k) {
      node.setAttribute(k, attrs[k]);
    });
    if (parent) parent.appendChild(node);
    return node;
  }

  // ---- the stage: renderer, camera, orbit, zoom, labels -----------------------------
  var COLOURS = {
    link: 0x6b7785,
    revolute: 0xe8891c,
    prismatic: 0x7b52c7,
    helical: 0x2f9e8f,
    base: 0x4a5360,
    platform: 0x3ba9c9,
    leg: 0x56606b,
    bad: 0xd0312d,
    ellipsoid: 0x17becf,
    x: 0xd62728,
    y: 0x2ca02c,
    z: 0x1f5fbf,
    path: 0x9467bd,
    axis: 0x7f7f7f,
    twistR: 0xd62728,
    twistT: 0x2ca02c,
    gripper: 0x5d6f8c,
    finger: 0x2b3038
  };

  function Stage(root, model, label) {
    var THREE = window.THREE;
    this.THREE = THREE;
    this.model = model;
    this.aspect = model.height / model.width;
    var stage = (this.node = el("div", { class: "screwkit-stage" }, root));
    var canvas = (this.canvas = el(
      "canvas",
      {
        role: "img",
        "aria-label": label,
        tabindex: "0",
        "aria-roledescription": "3D view"
      },
      stage
    ));
    this.labels = el("div", { class: "screwkit-labels", "aria-hidden": "true" }, stage);
    var buttons = el("div", { class: "screwkit-buttons" }, stage);
    var self = this;
    [
      [
        "+",
        "Zoom in",
        function () {
          self.zoomBy(1 / 1.25);
        }
      ],
      [
        "\u2212",
        "Zoom out",
        function () {
          self.zoomBy(1.25);
        }
      ],
      [
        "\u27f2",
        "Reset view",
        function () {
          self.reset();
        }
      ]
    ].forEach(function (b) {
      var button = el(
        "button",
        { type: "button", "aria-label": b[1], title: b[1] },
        buttons
      );
      button.textContent = b[0];
      button.addEventListener("click", b[2]);
    });
    try {
      this.renderer = new THREE.WebGLRenderer({
        canvas: canvas,
        antialias: true,
        preserveDrawingBuffer: true
      });
    } catch (error) {
      this.renderer = null;
      var note = el("div", { class: "screwkit-note" }, stage);
      note.textContent = "This 3D view needs WebGL, which this browser does not offer.";
    }
    if (this.renderer) this.renderer.setClearColor(0xf7f8fa, 1);
    this.scene = new THREE.Scene();
    this.camera = new THREE.PerspectiveCamera(30, 1 / this.aspect, 0.01, 1000);
    this.camera.up.set(0, 0, 1);
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x8a8f99, 1.6));
    var sun = new THREE.DirectionalLight(0xffffff, 1.8);
    sun.position.set(2, -3, 5);
    this.scene.add(sun);
    var fill = new THREE.DirectionalLight(0xffffff, 0.5);
    fill.position.set(-3, 2, 1);
    this.scene.add(fill);
    this.unitCylinder = new THREE.CylinderGeometry(1, 1, 1, 24);
    this.unitBox = new THREE.BoxGeometry(1, 1, 1);
    this.unitSphere = new THREE.SphereGeometry(1, 24, 16);
    this.unitCone = new THREE.ConeGeometry(1, 1, 20);
    this.materials = {};
    this.tags = [];
    this.size = 1;
    this.azimuth0 = -0.95;
    this.elevation0 = 0.38;
    this.reset(true);
    this.bindInput();
  }

  Stage.prototype.material = function (colour, opacity) {
    var key = colour + ":" + (opacity || 1);
    if (!this.materials[key]) {
      this.materials[key] = new this.THREE.MeshStandardMaterial({
        color: colour,
        roughness: 0.55,
        metalness: 0.15,
        transparent: opacity !== undefined && opacity < 1,
        opacity: opacity === undefined ? 1 : opacity
      });
    }
    return this.materials[key];
  };

  Stage.prototype.mesh = function (geometry, colour, opacity) {
    var mesh = new this.THREE.Mesh(geometry, this.material(colour, opacity));
    this.scene.add(mesh);
    return mesh;
  };

  // Place a unit mesh (along its local y) from a to b with cross-section `width`
  Stage.prototype.between = function (mesh, a, b, width, depth) {
    var THREE = this.THREE,
      d = sub(b, a),
      length = norm(d);
    mesh.visible = length > 1e-9;
    if (!mesh.visible) return mesh;
    mesh.position.set((a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2);
    mesh.scale.set(width, length, depth === undefined ? width : depth);
    mesh.quaternion.setFromUnitVectors(
      new THREE.Vector3(0, 1, 0),
      new THREE.Vector3(d[0] / length, d[1] / length, d[2] / length)
    );
    return mesh;
  };

  Stage.prototype.rod = function (colour, opacity) {
    return this.mesh(this.unitCylinder, colour, opacity);
  };

  // A coordinate frame: three shaded arrows (x red, y green, z blue)
  Stage.prototype.frame = function (opacity) {
    var parts = [];
    for (var k = 0; k < 3; k++) {
      var colour = [COLOURS.x, COLOURS.y, COLOURS.z][k];
      parts.push([
        this.rod(colour, opacity),
        this.mesh(this.unitCone, colour, opacity)
      ]);
    }
    return parts;
  };

  Stage.prototype.placeFrame = function (parts, T, length) {
    var o = origin(T),
      width = 0.045 * length;
    for (var k = 0; k < 3; k++) {
      var e = [T[k], T[4 + k], T[8 + k]];
      var tip = [
        o[0] + 0.78 * length * e[0],
        o[1] + 0.78 * length * e[1],
        o[2] + 0.78 * length * e[2]
      ];
      var end = [o[0] + length * e[0], o[1] + length * e[1], o[2] + length * e[2]];
      this.between(parts[k][0], o, tip, width);
      this.between(parts[k][1], tip, end, 2.3 * width);
    }
  };

  // A text tag pinned to a point of the scene (drawn in HTML over the canvas)
  Stage.prototype.tag = function (text) {
    var span = el("span", {}, this.labels);
    span.textContent = text;
    var tag = { span: span, at: [0, 0, 0], visible: true };
    this.tags.push(tag);
    return tag;
  };

  // The floor: a light square with a grid, at height z, around (x, y), half-size `half`
  Stage.prototype.floor = function (z, centre, half) {
    var THREE = this.THREE;
    var step = Math.pow(10, Math.floor(Math.log10(half / 2)));
    if (half / step > 8) step *= 5;
    else if (half / step > 4) step *= 2;
    half = Math.ceil(half / step) * step;
    var cx = Math.round(centre[0] / step) * step,
      cy = Math.round(centre[1] / step) * step;
    var grid = new THREE.GridHelper(
      2 * half,
      Math.round((2 * half) / step),
      0x9aa3ad,
      0xd3d8de
    );
    grid.rotation.x = Math.PI / 2;
    grid.position.set(cx, cy, z + 1e-4 * half);
    this.scene.add(grid);
    var plane = new THREE.Mesh(
      new THREE.PlaneGeometry(2 * half, 2 * half),
      new THREE.MeshStandardMaterial({ color: 0xe9ecf0, roughness: 1, metalness: 0 })
    );
    plane.position.set(cx, cy, z);
    this.scene.add(plane);
  };

  // Frame the scene's points (k, 3) to fill the canvas from the current view direction
  Stage.prototype.fit = function (points) {
    if (points) this.points = points;
    var pts = this.points || [[0, 0, 0]];
    var ca = Math.cos(this.azimuth),
      sa = Math.sin(this.azimuth);
    var ce = Math.cos(this.elevation),
      se = Math.sin(this.elevation);
    var back = [ce * ca, ce * sa, se],
      right = [-sa, ca, 0],
      up = cross(back, right);
    var lo = [Infinity, Infinity],
      hi = [-Infinity, -Infinity];
    pts.forEach(function (p) {
      var x = p[0] * right[0] + p[1] * right[1] + p[2] * right[2];
      var y = p[0] * up[0] + p[1] * up[1] + p[2] * up[2];
      lo = [Math.min(lo[0], x), Math.min(lo[1], y)];
      hi = [Math.max(hi[0], x), Math.max(hi[1], y)];
    });
    var cx = (lo[0] + hi[0]) / 2,
      cy = (lo[1] + hi[1]) / 2,
      target = [0, 0, 0];
    var mid = pts.reduce(
      function (s, p) {
        return [s[0] + p[0], s[1] + p[1], s[2] + p[2]];
      },
      [0, 0, 0]
    );
    var depth = (mid[0] * back[0] + mid[1] * back[1] + mid[2] * back[2]) / pts.length;
    for (var k = 0; k < 3; k++)
      target[k] = cx * right[k] + cy * up[k] + depth * back[k];
    var tv = Math.tan((this.camera.fov * Math.PI) / 360) / 1.16,
      th = tv * this.camera.aspect;
    var distance = 0;
    pts.forEach(function (p) {
      var d = sub(p, target);
      var x = Math.abs(d[0] * right[0] + d[1] * right[1]);
      var y = Math.abs(d[0] * up[0] + d[1] * up[1] + d[2] * up[2]);
      var z = d[0] * back[0] + d[1] * back[1] + d[2] * back[2];
      distance = Math.max(distance, z + x / th, z + y / tv);
    });
    this.target = target;
    this.distance = Math.max(distance, 1e-3);
  };

  // Keep the points (k, 3) of the pose just drawn in the picture. The view is framed on
  // the first pose; a pose that reaches beyond the box of everything framed so far is
  // framed again together with it (the view grows, never shrinks by itself: the reset
  // button and a double-click frame it anew). Returns whether the view changed.
  Stage.prototype.keepInView = function (points) {
    var framed = this.points || [],
      box = bounds(framed.length ? framed : points),
      margin = 0.01 * box.size;
    var outside = points.some(function (p) {
      for (var k = 0; k < 3; k++)
        if (p[k] < box.lo[k] - margin || p[k] > box.hi[k] + margin) return true;
      return false;
    });
    if (!outside) return false;
    var all = framed.concat(points);
    if (all.length > 600) all = corners(bounds(all)); // a long session: its box suffices
    this.fit(all);
    return true;
  };

  Stage.prototype.reset = function (quiet) {
    this.azimuth = this.azimuth0;
    this.elevation = this.elevation0;
    this.zoom = 1;
    this.fit();
    if (!quiet) this.render();
  };

  Stage.prototype.zoomBy = function (factor) {
    this.zoom = Math.max(0.15, Math.min(8, this.zoom * factor));
    this.render();
  };

  Stage.prototype.orbit = function (dAzimuth, dElevation) {
    this.azimuth += dAzimuth;
    this.elevation = Math.max(-1.5, Math.min(1.5, this.elevation + dElevation));
    this.render();
  };

  Stage.prototype.resize = function () {
    var width = this.node.clientWidth || this.model.width;
    var cap = Math.max(260, 0.78 * (window.innerHeight || 800));
    // phones: taller
    var tall = Math.max(width * this.aspect, Math.min(0.95 * width, 360));
    var height = Math.round(Math.max(200, Math.min(tall, cap)));
    if (width === this.width && height === this.height) return;
    this.width = width;
    this.height = height;
    this.node.style.height = height + "px";
    this.camera.aspect = width / height;
    if (this.renderer) {
      this.renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 3));
      this.renderer.setSize(width, height, false);
    }
    this.fit();
  };

  Stage.prototype.render = function () {
    var THREE = this.THREE,
      c = this.camera,
      t = this.target,
      d = this.distance * this.zoom;
    var ce = Math.cos(this.elevation);
    c.position.set(
      t[0] + d * ce * Math.cos(this.azimuth),
      t[1] + d * ce * Math.sin(this.azimuth),
      t[2] + d * Math.sin(this.elevation)
    );
    c.near = d / 100;
    c.far = d * 100;
    c.lookAt(t[0], t[1], t[2]);
    c.updateProjectionMatrix();
    c.updateMatrixWorld();
    if (this.renderer) this.renderer.render(this.scene, c);
    // tags: projected, then pushed down past any tag placed already: none overlap
    var placed = [],
      w = this.width,
      h = this.height,
      v = new THREE.Vector3();
    this.tags.forEach(function (tag) {
      v.set(tag.at[0], tag.at[1], tag.at[2]).project(c);
      var show =
        tag.visible && v.z < 1 && Math.abs(v.x) <= 1.05 && Math.abs(v.y) <= 1.05;
      tag.span.style.display = show ? "" : "none";
      if (!show) return;
      var x = ((v.x + 1) / 2) * w,
        y = ((1 - v.y) / 2) * h;
      var bw = tag.span.offsetWidth || 20,
        bh = (tag.span.offsetHeight || 16) + 2;
      for (var tries = 0; tries < 8; tries++) {
        var hit = placed.some(function (r) {
          return (
            Math.abs(r[0] - x) < (r[2] + bw) / 2 && Math.abs(r[1] - y) < (r[3] + bh) / 2
          );
        });
        if (!hit) break;
        y += bh;
      }
      placed.push([x, y, bw, bh]);
      tag.span.style.left = x.toFixed(1) + "px";
      tag.span.style.top = y.toFixed(1) + "px";
    });
  };

  Stage.prototype.bindInput = function () {
    var self = this,
      canvas = this.canvas,
      pointers = {},
      pinch = null;
    canvas.addEventListener("pointerdown", function (e) {
      pointers[e.pointerId] = [e.clientX, e.clientY];
      if (e.pointerType === "mouse" && canvas.setPointerCapture)
        canvas.setPointerCapture(e.pointerId);
      canvas.style.cursor = "grabbing";
    });
    canvas.addEventListener("pointermove", function (e) {
      var last = pointers[e.pointerId];
      if (!last) return;
      var ids = Object.keys(pointers);
      pointers[e.pointerId] = [e.clientX, e.clientY];
      if (ids.length === 2) {
        // pinch: zoom by the change of the fingers' distance
        var a = pointers[ids[0]],
          b = pointers[ids[1]],
          gap = Math.hypot(a[0] - b[0], a[1] - b[1]);
        if (pinch) self.zoomBy(pinch / Math.max(gap, 1));
        pinch = gap;
        return;
      }
      self.orbit(-0.01 * (e.clientX - last[0]), 0.01 * (e.clientY - last[1]));
    });
    var up = function (e) {
      delete pointers[e.pointerId];
      pinch = null;
      canvas.style.cursor = "grab";
    };
    ["pointerup", "pointercancel", "pointerleave"].forEach(function (name) {
      canvas.addEventListener(name, up);
    });
    // the wheel scrolls the page; Ctrl+wheel (and a trackpad's pinch) zooms the view
    canvas.addEventListener(
      "wheel",
      function (e) {
        if (!e.ctrlKey) return;
        e.preventDefault();
        self.zoomBy(Math.exp(0.002 * e.deltaY));
      },
      { passive: false }
    );
    canvas.addEventListener("dblclick", function () {
      self.reset();
    });
    canvas.addEventListener("keydown", function (e) {
      var step = (5 * Math.PI) / 180,
        keys = {
          ArrowLeft: function () {
            self.orbit(step, 0);
          },
          ArrowRight: function () {
            self.orbit(-step, 0);
          },
          ArrowUp: function () {
            self.orbit(0, step);
          },
          ArrowDown: function () {
            self.orbit(0, -step);
          },
          "+": function () {
            self.zoomBy(1 / 1.25);
          },
          "=": function () {
            self.zoomBy(1 / 1.25);
          },
          "-": function () {
            self.zoomBy(1.25);
          },
          _: function () {
            self.zoomBy(1.25);
          },
          0: function () {
            self.reset();
          },
          Home: function () {
            self.reset();
          }
        };
      if (!keys[e.key] || e.ctrlKey || e.metaKey || e.altKey) return;
      e.preventDefault();
      keys[e.key]();
    });
    if (window.ResizeObserver) {
      new ResizeObserver(function () {
        var w = self.width,
          h = self.height;
        self.resize();
        if (w !== self.width || h !== self.height) self.render();
      }).observe(this.node);
    }
    window.addEventListener("resize", function () {
      self.resize();
      self.render();
    });
  };

  // ---- figures ----------------------------------------------------------------------
  function fixed(values, digits) {
    return (
      "(" +
      values
        .map(function (x) {
          return (Math.abs(x) < 0.5 * Math.pow(10, -digits) ? 0 : x).toFixed(digits);
        })
        .join(", ") +
      ")"
    );
  }

  function bounds(points) {
    var lo = [Infinity, Infinity, Infinity],
      hi = [-Infinity, -Infinity, -Infinity];
    points.forEach(function (p) {
      for (var k = 0; k < 3; k++) {
        lo[k] = Math.min(lo[k], p[k]);
        hi[k] = Math.max(hi[k], p[k]);
      }
    });
    return { lo: lo, hi: hi, size: Math.max(norm(sub(hi, lo)), 0.05) };
  }

  // The floor under everything drawn at the first pose, never above the base frame. A
  // mechanism that reaches below its base frame (a PUMA's frame 0 is on its shoulder)
  // stands on a pedestal: the floor then lies at least `drop` below the base frame.
  function floorUnder(stage, points, size, drop) {
    var b = bounds(points),
      z = Math.min(0, b.lo[2] - 0.03 * size);
    if (drop && b.lo[2] < -0.01 * size) z = Math.min(z, -drop);
    var half = 0.65 * Math.max(b.hi[0] - b.lo[0], b.hi[1] - b.lo[1], 0.5 * size);
    stage.floor(z, [(b.lo[0] + b.hi[0]) / 2, (b.lo[1] + b.hi[1]) / 2], half);
    return z;
  }

  // The eight corners of a box from bounds()
  function corners(box) {
    var out = [];
    for (var i = 0; i < 8; i++) {
      out.push([
        i & 1 ? box.hi[0] : box.lo[0],
        i & 2 ? box.hi[1] : box.lo[1],
        i & 4 ? box.hi[2] : box.lo[2]
      ]);
    }
    return out;
  }

  // The points (k, 3) grown by `pad` along each axis: room for what is drawn there
  function padded(points, pad) {
    var out = [];
    points.forEach(function (p) {
      for (var k = 0; k < 3; k++) {
        for (var sign = -1; sign <= 1; sign += 2) {
          var q = p.slice();
          q[k] += sign * pad;
          out.push(q);
        }
      }
    });
    return out;
  }

  // A joint marker: a cylinder along the axis (revolute, helical) or a box (prismatic)
  function jointMarker(stage, kind, size) {
    var prismatic = kind === "P" || kind === "prismatic";
    var helical = kind === "H" || kind === "helical";
    var colour = prismatic
      ? COLOURS.prismatic
      : helical
        ? COLOURS.helical
        : COLOURS.revolute;
    var mesh = stage.mesh(prismatic ? stage.unitBox : stage.unitCylinder, colour);
    return {
      mesh: mesh,
      length: (prismatic ? 0.17 : 0.12) * size,
      width: (prismatic ? 0.075 : 0.05) * size * (prismatic ? 1 : 1)
    };
  }

  function placeJoint(stage, marker, point, axis) {
    var h = marker.length / 2;
    stage.between(
      marker.mesh,
      [point[0] - h * axis[0], point[1] - h * axis[1], point[2] - h * axis[2]],
      [point[0] + h * axis[0], point[1] + h * axis[1], point[2] + h * axis[2]],
      marker.width
    );
  }

  // A two-finger gripper on the tool frame, in tool coordinates: a short stub along the
  // approach axis from the frame's origin, a palm across the jaw axis and two fingers
  // along the approach, so that the tool's orientation shows (its roll about the approach
  // too). approach = [axis 0, 1 or 2 of the tool frame, sign]; the jaws open along y
  // (along z when the approach is y). Returns the group and the points it reaches.
  function gripper(stage, approach, size) {
    var THREE = stage.THREE,
      a = approach[0],
      sign = approach[1] < 0 ? -1 : 1,
      j = a === 1 ? 2 : 1,
      t = 3 - a - j;
    var group = new THREE.Group();
    group.matrixAutoUpdate = false;
    stage.scene.add(group);
    function box(colour, from, to, jaw, across, offset) {
      var mesh = new THREE.Mesh(stage.unitBox, stage.material(colour)),
        scale = [0, 0, 0],
        at = [0, 0, 0];
      scale[a] = (to - from) * size;
      scale[j] = jaw * size;
      scale[t] = across * size;
      at[a] = (sign * (from + to) * size) / 2;
      at[j] = offset * size;
      mesh.scale.set(scale[0], scale[1], scale[2]);
      mesh.position.set(at[0], at[1], at[2]);
      group.add(mesh);
    }
    box(COLOURS.gripper, 0, 0.07, 0.045, 0.045, 0); // stub
    box(COLOURS.gripper, 0.07, 0.1, 0.23, 0.065, 0); // palm
    box(COLOURS.finger, 0.1, 0.24, 0.035, 0.05, -0.0975); // fingers
    box(COLOURS.finger, 0.1, 0.24, 0.035, 0.05, 0.0975);
    var reach = [-1, 1].map(function (side) {
      var p = [0, 0, 0];
      p[a] = sign * 0.24 * size;
      p[j] = side * 0.115 * size;
      return p;
    });
    return { group: group, reach: reach };
  }

  function RobotFigure(model, stage) {
    this.model = model;
    this.stage = stage;
    var n = model.screws.length,
      q0 = model.sliders.map(function (s) {
        return s.value * s.scale;
      });
    var pose = chainPose(model, q0),
      first = this.points(pose);
    var size = (this.size = bounds(first.concat([[0, 0, 0]])).size / 2);
    this.floorZ = floorUnder(stage, first, 2 * size, 0.45 * model.radius);
    var r = 0.028 * size;
    this.linkRadius = r;
    if (this.floorZ < -1e-9) {
      // a pedestal from the floor up to the base frame
      stage.between(stage.rod(COLOURS.base), [0, 0, this.floorZ], [0, 0, 0], 2.2 * r);
    }
    stage.between(
      stage.rod(COLOURS.base),
      [0, 0, this.floorZ],
      [0, 0, this.floorZ + 0.03 * size],
      0.16 * size
    );
    this.links = [];
    for (var i = 0; i <= n; i++) this.links.push(stage.rod(COLOURS.link));
    this.joints = model.joints.map(function (kind) {
      return jointMarker(stage, kind, size);
    });
    this.tags = model.joints.map(function (_, i) {
      return stage.tag(String(i + 1));
    });
    this.toolFrame = stage.frame();
    this.gripper = gripper(stage, model.approach || [2, 1], size);
    this.toolTag = stage.tag("tool");
    if (model.ellipsoid) {
      this.ellipsoidMesh = stage.mesh(stage.unitSphere, COLOURS.ellipsoid, 0.35);
      this.ellipsoidMesh.matrixAutoUpdate = false;
    }
    var e = model.ellipsoid ? ellipsoid(model, pose) : null;
    stage.fit(this.framePoints(pose, first, e).concat([[0, 0, this.floorZ]]));
  }

  // What must stay in the picture at a pose: the links and joints (padded by the markers'
  // size), the tool frame's arrows, the gripper and the ellipsoid's axes
  RobotFigure.prototype.framePoints = function (pose, points, e) {
    var size = this.size,
      tool = pose.tool;
    var out = padded(points, 0.07 * size);
    [0, 1, 2].forEach(function (k) {
      var end = [0, 0, 0];
      end[k] = 0.3 * size;
      out.push(apply(tool, end));
    });
    this.gripper.reach.forEach(function (p) {
      out.push(apply(tool, p));
    });
    if (e) {
      var t = origin(tool),
        s = this.model.ellipsoid_scale,
        V = e.axes;
      for (var k = 0; k < 3; k++) {
        for (var sign = -1; sign <= 1; sign += 2) {
          var rk = sign * e.radii[k] * s;
          out.push([t[0] + rk * V[k], t[1] + rk * V[3 + k], t[2] + rk * V[6 + k]]);
        }
      }
    }
    return out;
  };

  RobotFigure.prototype.points = function (pose) {
    var points = [[0, 0, 0]],
      m = this.model;
    for (var i = 0; i < m.screws.length; i++)
      points.push(apply(pose.before[i], m.points[i]));
    points.push(origin(pose.tool));
    return points;
  };

  RobotFigure.prototype.draw = function (q) {
    var m = this.model,
      S = this.stage,
      pose = chainPose(m, q),
      points = this.points(pose);
    var r = this.linkRadius,
      n = m.screws.length,
      i;
    for (i = 0; i <= n; i++) S.between(this.links[i], points[i], points[i + 1], r);
    for (i = 0; i < n; i++) {
      var z = rotate(pose.before[i], m.axes[i]),
        o = points[i + 1];
      placeJoint(S, this.joints[i], o, z);
      var off = 0.09 * this.size; // the number beside the joint, off its axis
      this.tags[i].at = [o[0] + off * 0.5, o[1] - off * 0.5, o[2] + off];
    }
    S.placeFrame(this.toolFrame, pose.tool, 0.3 * this.size);
    var g = this.gripper.group;
    g.matrix.set.apply(g.matrix, pose.tool);
    g.matrixWorldNeedsUpdate = true;
    var tool = origin(pose.tool);
    this.toolTag.at = [tool[0], tool[1], tool[2] - 0.08 * this.size];
    var text = "Tool at " + fixed(tool, 3) + " m.",
      e = null;
    if (m.ellipsoid) {
      e = ellipsoid(m, pose);
      var s = m.ellipsoid_scale,
        V = e.axes,
        M = this.ellipsoidMesh.matrix;
      var a = e.radii.map(function (x) {
        return Math.max(x * s, 1e-4 * this.size);
      }, this);
      M.set(
        V[0] * a[0],
        V[1] * a[1],
        V[2] * a[2],
        tool[0],
        V[3] * a[0],
        V[4] * a[1],
        V[5] * a[2],
        tool[1],
        V[6] * a[0],
        V[7] * a[1],
        V[8] * a[2],
        tool[2],
        0,
        0,
        0,
        1
      );
      text +=
        " Ellipsoid radii " +
        fixed(
          e.radii.slice().sort(function (x, y) {
            return y - x;
          }),
          3
        ) +
        " m/s, w = " +
        e.w.toFixed(4) +
        ".";
      this.lastEllipsoid = e;
    }
    S.keepInView(this.framePoints(pose, points, e));
    this.lastPose = pose;
    S.render();
    return text;
  };

  function ScrewFigure(model, stage) {
    this.model = model;
    this.stage = stage;
    var s = model.s,
      r = model.r;
    this.twist =
      model.h === null
        ? [0, 0, 0, s[0], s[1], s[2]]
        : [s[0], s[1], s[2]].concat(
            cross(r, s).map(function (x, i) {
              return x + model.h * s[i];
            })
          );
    var start = flat(model.start),
      t0 = model.slider.value * model.slider.scale;
    var moved = this.pose(t0),
      self = this;
    var pts = [[0, 0, 0], origin(start), origin(moved), r];
    for (var k = 0; k <= 24; k++)
      pts.push(apply(expTwist(this.twist, (t0 * k) / 24), origin(start)));
    var size = (this.size = stage.size = Math.max(bounds(pts).size / 2, 0.25));
    var L = (this.length = 0.45 * size),
      R = 1.3 * size;
    var a = [r[0] - R * s[0], r[1] - R * s[1], r[2] - R * s[2]];
    var b = [r[0] + R * s[0], r[1] + R * s[1], r[2] + R * s[2]];
    var frames = [[0, 0, 0], origin(start), origin(moved)];
    [identity(), start, moved].forEach(function (T) {
      for (var j = 0; j < 3; j++) {
        var e = [0, 0, 0];
        e[j] = L;
        frames.push(apply(T, e));
      }
    });
    this.floorZ = floorUnder(stage, pts.concat(frames), 2 * size);
    stage.between(stage.rod(COLOURS.axis, 0.85), a, b, 0.012 * size);
    stage.between(
      stage.mesh(stage.unitCone, COLOURS.axis),
      b,
      [b[0] + 0.12 * size * s[0], b[1] + 0.12 * size * s[1], b[2] + 0.12 * size * s[2]],
      0.035 * size
    );
    stage.tag("screw axis").at = b;
    stage.placeFrame(stage.frame(0.5), identity(), 0.8 * L);
    stage.tag("0").at = [0, 0, -0.1 * size];
    stage.placeFrame(stage.frame(0.35), start, L);
    stage.tag("start").at = apply(start, [0, 0, -0.15 * size]);
    this.frameParts = stage.frame();
    this.movedTag = stage.tag("moved");
    this.dot = stage.mesh(stage.unitSphere, COLOURS.path);
    this.dot.scale.setScalar(0.035 * size);
    this.pathMaterial = stage.material(COLOURS.path, 0.9);
    this.path = null;
    stage.fit(
      padded(pts.concat(frames), 0.05 * size).concat([[r[0], r[1], this.floorZ]])
    );
    void self;
  }

  ScrewFigure.prototype.pose = function (theta) {
    return matmul(expTwist(this.twist, theta), flat(this.model.start));
  };

  ScrewFigure.prototype.draw = function (values) {
    var m = this.model,
      S = this.stage,
      THREE = S.THREE,
      theta = values[0],
      start = flat(m.start);
    var points = [];
    for (var k = 0; k <= 48; k++) {
      var p = apply(expTwist(this.twist, (theta * k) / 48), origin(start));
      points.push(new THREE.Vector3(p[0], p[1], p[2]));
    }
    if (this.path) {
      S.scene.remove(this.path);
      this.path.geometry.dispose();
      this.path = null;
    }
    if (points[0].distanceTo(points[48]) > 1e-6 || Math.abs(theta) > 1e-9) {
      var tube = new THREE.TubeGeometry(
        new THREE.CatmullRomCurve3(points),
        96,
        0.01 * this.size,
        8
      );
      this.path = new THREE.Mesh(tube, this.pathMaterial);
      S.scene.add(this.path);
    }
    var T = this.pose(theta),
      o = origin(T);
    S.placeFrame(this.frameParts, T, this.length);
    this.dot.position.set(o[0], o[1], o[2]);
    this.movedTag.at = apply(T, [0, 0, -0.15 * this.size]);
    var L = this.length;
    S.keepInView(
      padded([o], 0.05 * this.size).concat(
        [0, 1, 2].map(function (k) {
          var end = [0, 0, 0];
          end[k] = L;
          return apply(T, end);
        })
      )
    );
    this.lastPose = T;
    S.render();
    return (
      m.slider.label +
      " = " +
      (theta / m.slider.scale).toFixed(m.slider.digits) +
      " " +
      m.slider.unit +
      ": frame origin at " +
      fixed(o, 3) +
      " m."
    );
  };

  // The points (k, 3) in the order of their angle about their centroid, in their plane
  function aroundCentre(points) {
    var k = points.length,
      c = [0, 0, 0],
      n = [0, 0, 0];
    points.forEach(function (p) {
      c = [c[0] + p[0] / k, c[1] + p[1] / k, c[2] + p[2] / k];
    });
    for (var i = 0; i < k; i++) {
      // the largest normal of the fan's triangles
      var m = cross(sub(points[i], c), sub(points[(i + 1) % k], c));
      if (norm(m) > norm(n)) n = m;
    }
    if (norm(n) < 1e-12) return points.slice();
    n = n.map(function (x) {
      return x / norm(n);
    });
    var u = sub(points[0], c);
    for (i = 0; i < k && norm(u) < 1e-12; i++) u = sub(points[i], c);
    u = u.map(function (x) {
      return x / norm(u);
    });
    var v = cross(n, u);
    return points.slice().sort(function (a, b) {
      var da = sub(a, c),
        db = sub(b, c);
      var ta = Math.atan2(
        da[0] * v[0] + da[1] * v[1] + da[2] * v[2],
        da[0] * u[0] + da[1] * u[1] + da[2] * u[2]
      );
      var tb = Math.atan2(
        db[0] * v[0] + db[1] * v[1] + db[2] * v[2],
        db[0] * u[0] + db[1] * u[1] + db[2] * u[2]
      );
      return ta - tb;
    });
  }

  // A fan of triangles from the centroid: a plate through the points (k, 3), with edges
  function plate(stage, points, colour, opacity, edges) {
    var THREE = stage.THREE,
      k = points.length,
      c = [0, 0, 0];
    points = aroundCentre(points);
    points.forEach(function (p) {
      c = [c[0] + p[0] / k, c[1] + p[1] / k, c[2] + p[2] / k];
    });
    var data = [];
    for (var i = 0; i < k; i++) {
      var a = points[i],
        b = points[(i + 1) % k];
      data.push(c[0], c[1], c[2], a[0], a[1], a[2], b[0], b[1], b[2]);
    }
    var geometry = new THREE.BufferGeometry();
    geometry.setAttribute("position", new THREE.Float32BufferAttribute(data, 3));
    geometry.computeVertexNormals();
    var material = new THREE.MeshStandardMaterial({
      color: colour,
      roughness: 0.7,
      metalness: 0.05,
      side: THREE.DoubleSide,
      transparent: opacity < 1,
      opacity: opacity
    });
    var mesh = new THREE.Mesh(geometry, material);
    stage.scene.add(mesh);
    if (edges !== false) {
      for (i = 0; i < k; i++)
        stage.between(
          stage.rod(colour),
          points[i],
          points[(i + 1) % k],
          0.012 * stage.size
        );
    }
    return { mesh: mesh, order: points };
  }

  function PlatformFigure(model, stage) {
    this.model = model;
    this.stage = stage;
    var v0 = model.sliders.map(function (s) {
      return s.value * s.scale;
    });
    var T0 = platformPose(model, v0);
    var top = model.platform.map(function (b) {
      return apply(T0, b);
    });
    var size = (this.size = stage.size = bounds(model.base.concat(top)).size / 2);
    this.floorZ = floorUnder(stage, model.base.concat(top), 2 * size);
    plate(stage, model.base, COLOURS.base, 0.9);
    var THREE = stage.THREE;
    this.group = new THREE.Group();
    this.group.matrixAutoUpdate = false;
    stage.scene.add(this.group);
    var local = plate(stage, model.platform, COLOURS.platform, 0.75, false);
    stage.scene.remove(local.mesh);
    this.group.add(local.mesh);
    this.order = local.order;
    this.edges = model.platform.map(function () {
      return stage.rod(COLOURS.platform);
    });
    this.legs = model.base.map(function () {
      return stage.rod(COLOURS.leg);
    });
    this.feet = model.base.map(function (a) {
      var m = stage.mesh(stage.unitSphere, COLOURS.revolute);
      m.position.set(a[0], a[1], a[2]);
      m.scale.setScalar(0.035 * size);
      return m;
    });
    this.heads = model.platform.map(function () {
      var m = stage.mesh(stage.unitSphere, COLOURS.revolute);
      m.scale.setScalar(0.035 * size);
      return m;
    });
    this.tags = model.base.map(function (_, i) {
      return stage.tag(String(i + 1));
    });
    this.frameParts = stage.frame();
    stage.fit(this.framePoints(T0, top).concat([[0, 0, this.floorZ]]));
  }

  PlatformFigure.prototype.pose = function (values) {
    return platformPose(this.model, values);
  };

  // What must stay in the picture: the base, the platform's points and its frame's arrows
  PlatformFigure.prototype.framePoints = function (T, top) {
    var size = this.size;
    return padded(this.model.base.concat(top), 0.05 * size).concat(
      [0, 1, 2].map(function (k) {
        var end = [0, 0, 0];
        end[k] = 0.25 * size;
        return apply(T, end);
      })
    );
  };

  PlatformFigure.prototype.draw = function (values) {
    var m = this.model,
      S = this.stage,
      T = this.pose(values),
      size = this.size;
    var lengths = legLengths(m, T),
      bad = [];
    this.group.matrix.set.apply(this.group.matrix, T);
    this.group.matrixWorldNeedsUpdate = true;
    var top = m.platform.map(function (b) {
      return apply(T, b);
    });
    for (var i = 0; i < top.length; i++) {
      var limits = m.limits ? m.limits[i] : null;
      var out =
        limits && (lengths[i] < limits[0] - 1e-12 || lengths[i] > limits[1] + 1e-12);
      if (out) bad.push(i + 1);
      this.legs[i].material = S.material(out ? COLOURS.bad : COLOURS.leg);
      S.between(this.legs[i], m.base[i], top[i], (out ? 0.032 : 0.024) * size);
      var e0 = apply(T, this.order[i]),
        e1 = apply(T, this.order[(i + 1) % top.length]);
      S.between(this.edges[i], e0, e1, 0.012 * size);
      this.heads[i].position.set(top[i][0], top[i][1], top[i][2]);
      var a = m.base[i];
      this.tags[i].at = [
        (a[0] + top[i][0]) / 2,
        (a[1] + top[i][1]) / 2,
        (a[2] + top[i][2]) / 2
      ];
      this.tags[i].span.className = out ? "screwkit-bad" : "";
      this.tags[i].span.textContent = out ? i + 1 + " !" : String(i + 1);
    }
    S.placeFrame(this.frameParts, T, 0.25 * size);
    S.keepInView(this.framePoints(T, top));
    this.lastPose = T;
    this.lastLengths = lengths;
    S.render();
    var text =
      "Platform at " +
      fixed(origin(T), 3) +
      " m. Leg lengths (m): " +
      lengths
        .map(function (x) {
          return x.toFixed(3);
        })
        .join(", ") +
      ".";
    if (m.limits) {
      text += bad.length
        ? " Outside the limits: leg" +
          (bad.length > 1 ? "s " : " ") +
          bad.join(", ") +
          "."
        : " All legs within their limits.";
    }
    return text;
  };

  function MechanismFigure(model, stage) {
    this.model = model;
    this.stage = stage;
    stage.elevation0 = stage.elevation = 0.6;
    var all = [];
    model.limbs.forEach(function (limb) {
      limb.forEach(function (j) {
        all.push(j.point);
      });
    });
    var size = (this.size = stage.size = Math.max(bounds(all).size / 2, 0.2));
    var ends = [];
    model.twists.forEach(function (t) {
      var reach = (t.kind === "rotation" ? 1.65 : 1.5) * model.length;
      ends.push(
        t.start.map(function (x, k) {
          return x + reach * t.direction[k];
        })
      );
    });
    var floorZ = floorUnder(stage, all, 2 * size);
    if (model.base.length >= 3) plate(stage, model.base, COLOURS.base, 0.55);
    else if (model.base.length === 2)
      stage.between(
        stage.rod(COLOURS.base),
        model.base[0],
        model.base[1],
        0.012 * size
      );
    if (model.platform.length >= 3) plate(stage, model.platform, COLOURS.platform, 0.6);
    else if (model.platform.length === 2)
      stage.between(
        stage.rod(COLOURS.platform),
        model.platform[0],
        model.platform[1],
        0.012 * size
      );
    var r = 0.018 * size,
      L = model.length;
    model.limbs.forEach(function (limb, i) {
      model.segments[i].forEach(function (seg) {
        stage.between(
          stage.rod(COLOURS.link),
          limb[seg[0]].point,
          limb[seg[1]].point,
          r
        );
      });
      limb.forEach(function (j) {
        var marker = jointMarker(stage, j.kind, size);
        marker.length = (j.kind === "prismatic" ? 0.7 : 0.35) * L;
        marker.width = (j.kind === "prismatic" ? 0.07 : 0.035) * size;
        placeJoint(stage, marker, j.point, j.axis);
        if (j.kind !== "prismatic") {
          // the axis itself, thin, as far as the drawing goes
          stage.between(
            stage.rod(COLOURS.axis, 0.7),
            sub(
              j.point,
              j.axis.map(function (x) {
                return 0.5 * L * x;
              })
            ),
            j.point.map(function (x, k) {
              return x + 0.5 * L * j.axis[k];
            }),
            0.005 * size
          );
        }
      });
      var p = limb[0].point;
      stage.tag("limb " + (i + 1)).at = [p[0], p[1], p[2] - 0.08 * size];
    });
    model.twists.forEach(function (t, k) {
      var rotation = t.kind === "rotation",
        colour = rotation ? COLOURS.twistR : COLOURS.twistT;
      // a rotation's arrow passes a translation's on its axis
      var reach = rotation ? 1.35 : 1.2;
      var tip = t.start.map(function (x, k2) {
        return x + reach * L * t.direction[k2];
      });
      var end = ends[k];
      stage.between(stage.rod(colour), t.start, tip, (rotation ? 0.016 : 0.012) * size);
      stage.between(stage.mesh(stage.unitCone, colour), tip, end, 0.035 * size);
      if (rotation) {
        // a ring around the axis: this arrow is a rotation
        var THREE = stage.THREE;
        var ring = new THREE.Mesh(
          new THREE.TorusGeometry(0.07 * size, 0.009 * size, 10, 40),
          stage.material(colour)
        );
        var at = t.start.map(function (x, k2) {
          return x + 0.8 * L * t.direction[k2];
        });
        ring.position.set(at[0], at[1], at[2]);
        ring.quaternion.setFromUnitVectors(
          new THREE.Vector3(0, 0, 1),
          new THREE.Vector3(t.direction[0], t.direction[1], t.direction[2])
        );
        stage.scene.add(ring);
      }
    });
    stage.fit(padded(all, 0.05 * size).concat(ends, [[all[0][0], all[0][1], floorZ]]));
  }

  MechanismFigure.prototype.draw = function () {
    this.stage.render();
    return this.model.caption;
  };

  // ---- mounting: one figure per <div class="screwkit-viewer"> -----------------------
  function digits(step) {
    // decimals that show every grid value of a slider exactly
    var d = 0;
    while (
      d < 6 &&
      Math.abs(step * Math.pow(10, d) - Math.round(step * Math.pow(10, d))) > 1e-9
    )
      d++;
    return d;
  }

  function addSlider(spec, parent, onInput, id) {
    spec.digits = digits(spec.step);
    var label = el("label", { for: id }, parent);
    label.textContent = spec.label;
    var input = el(
      "input",
      {
        type: "range",
        id: id,
        min: spec.min,
        max: spec.max,
        step: spec.step,
        value: spec.value,
        "aria-label": spec.label + " (" + spec.unit + ")"
      },
      parent
    );
    var chars = Math.max(
      spec.min.toFixed(spec.digits).length,
      spec.max.toFixed(spec.digits).length
    );
    var readout = el(
      "output",
      { for: id, style: "min-width:" + (chars + 0.5) + "ch" },
      parent
    );
    el("span", { class: "screwkit-unit" }, parent).textContent = spec.unit;
    input.addEventListener("input", onInput);
    return { input: input, readout: readout, spec: spec };
  }

  function mountSteps(root, model) {
    var view = el("div", { class: "screwkit-frame", "aria-live": "polite" }, root);
    var controls = el("div", { class: "screwkit-controls" }, root);
    var show = function (index) {
      view.innerHTML = model.frames[index];
    };
    var control;
    if (model.choices) {
      var label = el("label", { for: root.id + "-choice" }, controls);
      label.textContent = model.label;
      control = el(
        "select",
        {
          id: root.id + "-choice",
          "aria-label": model.label,
          style: "grid-column:span 3"
        },
        controls
      );
      model.choices.forEach(function (name, i) {
        var option = el("option", { value: i }, control);
        option.textContent = name;
        if (i === model.index) option.selected = true;
      });
      control.addEventListener("change", function () {
        show(+control.value);
      });
    } else {
      var s = model.slider,
        values = model.values;
      control = addSlider(
        s,
        controls,
        function () {
          var i = Math.round((+control.input.value - s.min) / s.step);
          control.readout.textContent = values[i].toFixed(s.digits);
          show(i);
        },
        root.id + "-s0"
      );
      control.readout.textContent = s.value.toFixed(s.digits);
    }
    show(model.index);
    return { show: show };
  }

  var FIGURES = {
    robot: RobotFigure,
    screw: ScrewFigure,
    platform: PlatformFigure,
    mechanism: MechanismFigure
  };

  function mount(root) {
    if (!root || root.getAttribute("data-mounted")) return null;
    addStyle();
    var model = JSON.parse(
      root.querySelector("script[type='application/json']").textContent
    );
    if (model.kind === "steps") {
      root.setAttribute("data-mounted", "1");
      return register(root, mountSteps(root, model));
    }
    // three.js comes with the first 3D viewer: wait for it
    if (!window.THREE) return null;
    var note = root.querySelector(".screwkit-note");
    if (note) note.remove();
    root.setAttribute("data-mounted", "1");
    var stage = new Stage(root, model, model.label || model.name || "3D view");
    var caption = el("div", { class: "screwkit-caption", "aria-live": "polite" }, root);
    var controls = el("div", { class: "screwkit-controls" }, root);
    stage.resize();
    var figure = new FIGURES[model.kind](model, stage);
    stage.resize();
    stage.fit();
    var specs = model.sliders || (model.slider ? [model.slider] : []);
    var sliders = [];
    var redraw = function () {
      var values = sliders.map(function (s) {
        return +s.input.value * s.spec.scale;
      });
      sliders.forEach(function (s) {
        s.readout.textContent = (+s.input.value).toFixed(s.spec.digits);
      });
      var start = performance.now();
      caption.textContent = figure.draw(values);
      viewer.lastDrawMs = performance.now() - start;
    };
    specs.forEach(function (spec, k) {
      sliders.push(addSlider(spec, controls, redraw, root.id + "-s" + k));
    });
    if (!specs.length) controls.remove();
    var viewer = {
      figure: figure,
      redraw: redraw,
      sliders: sliders,
      stage: stage,
      camera: stage
    };
    redraw();
    return register(root, viewer);
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
    version: VERSION,
    viewers: {},
    mount: mount,
    mountAll: mountAll,
    expTwist: expTwist,
    chainPose: chainPose,
    positionJacobian: positionJacobian,
    symmetricEigen: symmetricEigen,
    ellipsoid: ellipsoid,
    platformPose: platformPose,
    legLengths: legLengths
  };
  mountAll();
})();
