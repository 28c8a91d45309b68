  // ---- the stage: renderer, camera, orbit, zoom, labels -----------------------------
  // Joints as in the mobility figures (screwkit/_mechanism_plot.py, JOINT_STYLES):
  // revolute tab:blue, prismatic tab:orange, helical tab:purple
  var COLOURS = {
    link: 0x6b7785,
    revolute: 0x1f77b4,
    prismatic: 0xff7f0e,
    helical: 0x9467bd,
    base: 0x4a5360,
    platform: 0x3ba9c9,
    leg: 0x56606b,
    bad: 0xd0312d,
    ellipsoid: 0x17becf,
    x: 0xd62728,
    y: 0x2ca02c,
    z: 0x1f5fbf,
    path: 0x8c564b,
    axis: 0x7f7f7f,
    twistR: 0xd62728,
    twistT: 0x2ca02c,
    gripper: 0x5d6f8c,
    finger: 0x2b3038
  };

  // A trajectory viewer's arms and their tool paths, in order (tab:red, tab:green,
  // tab:brown, tab:pink): none is a joint's colour
  var PATH_COLOURS = [0xd62728, 0x2ca02c, 0x8c564b, 0xe377c2];

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

