/* screwkit viewer: interactive kinematics figures computed in the page, in three.js.
 *
 * Python (screwkit/viewer.py) hands each figure its parameters as JSON: a chain's joint
 * screws S_i = [omega; v] and home pose M (product of exponentials), a screw (s, r, h),
 * a parallel platform's attachment points, a mechanism's joints, precomputed joint
 * trajectories to play, or precomputed frames.
 * This script computes the kinematics in double precision (exponentials of twists,
 * forward kinematics, the position Jacobian and its ellipsoid, leg lengths) and draws
 * with three.js (window.THREE, vendored from npm, shipped once per page by viewer.py).
 * Drag to orbit; Ctrl+wheel, pinch or the buttons to zoom; arrow keys and +/- when
 * focused. Nothing is loaded from the network. Units: m and rad (sliders show deg).
 */
(function () {
  "use strict";
  var VERSION = "3";
  if (window.screwkit && window.screwkit.version === VERSION) {
    window.screwkit.mountAll();
    return;
  }

