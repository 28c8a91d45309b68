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

  function degrees(angles) {
    return angles.map(function (x) {
      return (x * 180) / Math.PI;
    });
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
  function jointMarker(stage, kind, size, opacity) {
    var prismatic = kind === "P" || kind === "prismatic";
    var helical = kind === "H" || kind === "helical";
    var colour = prismatic
      ? COLOURS.prismatic
      : helical
        ? COLOURS.helical
        : COLOURS.revolute;
    var mesh = stage.mesh(
      prismatic ? stage.unitBox : stage.unitCylinder,
      colour,
      opacity
    );
    return {
      mesh: mesh,
      length: (prismatic ? 0.17 : 0.12) * size,
      width: (prismatic ? 0.075 : 0.05) * size
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
  function gripper(stage, approach, size, opacity) {
    var THREE = stage.THREE,
      a = approach[0],
      sign = approach[1] < 0 ? -1 : 1,
      j = a === 1 ? 2 : 1,
      t = 3 - a - j;
    var group = new THREE.Group();
    group.matrixAutoUpdate = false;
    stage.scene.add(group);
    function box(colour, from, to, jaw, across, offset) {
      var mesh = new THREE.Mesh(stage.unitBox, stage.material(colour, opacity)),
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

  // An arm on the stage: a rod per link in `colour`, a marker per joint (coloured by its
  // kind) and the gripper on the tool frame; an opacity below 1 draws a ghost
  function Arm(stage, model, size, colour, opacity) {
    this.model = model;
    this.stage = stage;
    this.radius = 0.028 * size;
    this.links = [];
    for (var i = 0; i <= model.screws.length; i++)
      this.links.push(stage.rod(colour, opacity));
    this.joints = model.joints.map(function (kind) {
      return jointMarker(stage, kind, size, opacity);
    });
    this.gripper = gripper(stage, model.approach || [2, 1], size, opacity);
  }

  // The arm at `pose` (chainPose), through its `points` (chainPoints)
  Arm.prototype.place = function (pose, points) {
    var S = this.stage,
      m = this.model,
      n = m.screws.length,
      i;
    for (i = 0; i <= n; i++)
      S.between(this.links[i], points[i], points[i + 1], this.radius);
    for (i = 0; i < n; i++)
      placeJoint(S, this.joints[i], points[i + 1], rotate(pose.before[i], m.axes[i]));
    var g = this.gripper.group;
    g.matrix.set.apply(g.matrix, pose.tool);
    g.matrixWorldNeedsUpdate = true;
  };

  // A chain's stand: a pedestal from the floor up to the base frame when the floor is
  // below it, and a flat foot on the floor
  function pedestal(stage, floorZ, size) {
    if (floorZ < -1e-9)
      stage.between(stage.rod(COLOURS.base), [0, 0, floorZ], [0, 0, 0], 0.0616 * size);
    stage.between(
      stage.rod(COLOURS.base),
      [0, 0, floorZ],
      [0, 0, floorZ + 0.03 * size],
      0.16 * size
    );
  }

  function RobotFigure(model, stage) {
    this.model = model;
    this.stage = stage;
    var q0 = model.sliders.map(function (s) {
        return s.value * s.scale;
      });
    var pose = chainPose(model, q0),
      first = this.points(pose);
    var size = (this.size = bounds(first.concat([[0, 0, 0]])).size / 2);
    this.floorZ = floorUnder(stage, first, 2 * size, 0.45 * model.radius);
    pedestal(stage, this.floorZ, size);
    this.arm = new Arm(stage, model, size, COLOURS.link);
    this.links = this.arm.links;
    this.joints = this.arm.joints;
    this.gripper = this.arm.gripper;
    this.tags = model.joints.map(function (_, i) {
      return stage.tag(String(i + 1));
    });
    this.toolFrame = stage.frame();
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
    return chainPoints(this.model, pose);
  };

  RobotFigure.prototype.draw = function (q) {
    var m = this.model,
      S = this.stage,
      pose = chainPose(m, q),
      points = this.points(pose);
    this.arm.place(pose, points);
    var off = 0.09 * this.size; // each joint's number beside it, off its axis
    for (var i = 0; i < m.screws.length; i++) {
      var o = points[i + 1];
      this.tags[i].at = [o[0] + off * 0.5, o[1] - off * 0.5, o[2] + off];
    }
    S.placeFrame(this.toolFrame, pose.tool, 0.3 * this.size);
    var tool = origin(pose.tool);
    this.toolTag.at = [tool[0], tool[1], tool[2] - 0.08 * this.size];
    var text =
        "Tool at " +
        fixed(tool, 3) +
        " m. Roll, pitch, yaw " +
        fixed(degrees(rollPitchYaw(pose.tool)), 1) +
        " deg.",
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
    if (model.planar) {
      // from above, x to the right and y up: the plane of the motion, seen whole
      stage.azimuth0 = stage.azimuth = -Math.PI / 2;
      stage.elevation0 = stage.elevation = 1.5;
    }
    var v0 = model.sliders.map(function (s) {
      return s.value * s.scale;
    });
    var T0 = platformPose(model, v0);
    var top = model.platform.map(function (b) {
      return apply(T0, b);
    });
    var size = (this.size = stage.size = bounds(model.base.concat(top)).size / 2);
    this.floorZ = floorUnder(stage, model.base.concat(top), 2 * size);
    // seen from above, a planar base is a light plate under its legs and platform
    plate(stage, model.base, COLOURS.base, model.planar ? 0.3 : 0.9);
    var THREE = stage.THREE;
    this.group = new THREE.Group();
    this.group.matrixAutoUpdate = false;
    stage.scene.add(this.group);
    var local = plate(stage, model.platform, COLOURS.platform, 0.75, false);
    stage.scene.remove(local.mesh);
    this.group.add(local.mesh);
    // a planar platform moves in the base's plane: its plate drawn a hair above the
    // base's, so that where they overlap seen from above it shows whole
    if (model.planar) local.mesh.position.z = 0.004 * size;
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

  // A plate through 3 or more points (k, 3), a rod between 2
  function outline(stage, points, colour, opacity, size) {
    if (points.length >= 3) plate(stage, points, colour, opacity);
    else if (points.length === 2)
      stage.between(stage.rod(colour), points[0], points[1], 0.012 * size);
  }

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
    outline(stage, model.base, COLOURS.base, 0.55, size);
    outline(stage, model.platform, COLOURS.platform, 0.6, size);
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


  // Arms that play precomputed joint trajectories, one per path (the first solid, the
  // others ghosts), each link and tool path in its path's colour, each path named at
  // its middle. The page only interpolates q between the samples (sampleAt).
  function TrajectoryFigure(model, stage) {
    this.model = model;
    this.stage = stage;
    var THREE = stage.THREE,
      self = this;
    this.colours = model.paths.map(function (_, k) {
      return PATH_COLOURS[k % PATH_COLOURS.length];
    });
    var tools = model.paths.map(function (p) {
      return toolPath(model, p.q);
    });
    var reach = [[0, 0, 0]];
    model.paths.forEach(function (p) {
      p.q.forEach(function (q) {
        reach = reach.concat(chainPoints(model, chainPose(model, q)));
      });
      reach = corners(bounds(reach)); // the box is what frames the view
    });
    var size = (this.size = stage.size = bounds(reach).size / 2);
    this.floorZ = floorUnder(stage, reach, 2 * size, 0.45 * model.radius);
    pedestal(stage, this.floorZ, size);
    this.arms = model.paths.map(function (_, k) {
      return new Arm(stage, model, size, self.colours[k], k ? 0.35 : undefined);
    });
    var grip = [];
    tools.forEach(function (points, k) {
      var curve = new THREE.CatmullRomCurve3(
        points.map(function (p) {
          return new THREE.Vector3(p[0], p[1], p[2]);
        })
      );
      var tube = new THREE.TubeGeometry(
        curve,
        Math.min(4 * points.length, 600),
        0.008 * size,
        8
      );
      stage.scene.add(new THREE.Mesh(tube, stage.material(self.colours[k], 0.9)));
      var tag = stage.tag(model.paths[k].label);
      tag.at = points[Math.floor(points.length / 2)];
      tag.span.style.borderColor = "#" + ("00000" + self.colours[k].toString(16)).slice(-6);
    });
    model.paths.forEach(function (p, k) {
      p.q.forEach(function (q) {
        var tool = chainPose(model, q).tool;
        self.arms[k].gripper.reach.forEach(function (g) {
          grip.push(apply(tool, g));
        });
      });
    });
    stage.fit(
      padded(corners(bounds(reach.concat(grip))), 0.07 * size).concat([
        [0, 0, this.floorZ]
      ])
    );
  }

  // Every arm at time t (s): q interpolated between its samples
  TrajectoryFigure.prototype.draw = function (values) {
    var m = this.model,
      t = values[0],
      self = this;
    var text = m.paths.map(function (p, k) {
      var pose = chainPose(m, sampleAt(m.times, p.q, t));
      self.arms[k].place(pose, chainPoints(m, pose));
      return p.label + ": tool at " + fixed(origin(pose.tool), 3) + " m";
    });
    this.time = t;
    this.stage.render();
    return "t = " + t.toFixed(2) + " s. " + text.join("; ") + ".";
  };
