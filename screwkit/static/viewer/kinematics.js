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

  // A platform's pose from its sliders (SI), absolute: T = Trans(x, y, z) Rz(yaw)
  // Ry(pitch) Rx(roll) (spatial: x, y, z, roll, pitch, yaw); planar: x, y, phi, the
  // platform in the plane z = z_home, T = Trans(x, y, z_home) Rz(phi)
  function platformPose(model, values) {
    var T;
    if (model.planar) {
      T = rotZ(values[2]);
      T[3] = values[0];
      T[7] = values[1];
      T[11] = flat(model.home)[11];
    } else {
      T = matmul(rotZ(values[5]), matmul(rotY(values[4]), rotX(values[3])));
      T[3] = values[0];
      T[7] = values[1];
      T[11] = values[2];
    }
    return T;
  }

  // Leg i's length |p + R b_i - a_i| (m) at the platform pose T
  function legLengths(model, T) {
    return model.base.map(function (a, i) {
      return norm(sub(apply(T, model.platform[i]), a));
    });
  }


  // The points a chain's drawing joins: the base origin, each joint's point (moved by
  // the joints before it) and the tool's origin, (n + 2, 3)
  function chainPoints(model, pose) {
    var points = [[0, 0, 0]];
    for (var i = 0; i < model.screws.length; i++)
      points.push(apply(pose.before[i], model.points[i]));
    points.push(origin(pose.tool));
    return points;
  }

  // (roll, pitch, yaw) (rad) of the rotation of T: R = Rz(yaw) Ry(pitch) Rx(roll),
  // pitch in [-pi/2, pi/2]; at pitch = +-pi/2 (gimbal lock) yaw = 0 and roll carries
  // the turn (as screwkit.orientation.rpy_from_rotation)
  function rollPitchYaw(T) {
    var c = Math.hypot(T[0], T[4]),
      pitch = Math.atan2(-T[8], c);
    if (c < 1e-9) {
      var roll = T[8] < 0 ? Math.atan2(T[1], T[5]) : Math.atan2(-T[1], T[5]);
      return [roll, pitch, 0];
    }
    return [Math.atan2(T[9], T[10]), pitch, Math.atan2(T[4], T[0])];
  }

  // The joint values at time t of a trajectory sampled at increasing times (K,) as
  // rows Q (K, n): linear between the samples around t, the first or last row outside
  function sampleAt(times, Q, t) {
    var K = times.length;
    if (t <= times[0]) return Q[0].slice();
    if (t >= times[K - 1]) return Q[K - 1].slice();
    var lo = 0,
      hi = K - 1;
    while (hi - lo > 1) {
      var mid = (lo + hi) >> 1;
      if (times[mid] <= t) lo = mid;
      else hi = mid;
    }
    var w = (t - times[lo]) / (times[hi] - times[lo]);
    return Q[lo].map(function (x, j) {
      return x + w * (Q[hi][j] - x);
    });
  }

  // The tool's origin (K, 3) along a joint trajectory Q (K, n)
  function toolPath(model, Q) {
    return Q.map(function (q) {
      return origin(chainPose(model, q).tool);
    });
  }
