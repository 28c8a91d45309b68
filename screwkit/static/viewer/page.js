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
    mechanism: MechanismFigure,
    trajectory: TrajectoryFigure
  };

  // Play and pause a trajectory: its time slider advances in real time and stops at
  // the end (play there starts again). The root's data-time is the time drawn; while
  // playing, data-playing is set and the caption is not read aloud at every frame.
  // The button says what it does next (Play, Pause), so it carries no aria-pressed.
  function addPlayer(root, controls, viewer, caption) {
    var slider = viewer.sliders[0],
      spec = slider.spec,
      playing = false,
      last = null,
      clock = spec.value;
    var button = el(
      "button",
      { type: "button", class: "screwkit-play" },
      null
    );
    controls.insertBefore(button, controls.firstChild);
    function show(t) {
      clock = t;
      slider.input.value = t;
      slider.readout.textContent = t.toFixed(spec.digits);
      var start = performance.now();
      caption.textContent = viewer.figure.draw([t]);
      viewer.lastDrawMs = performance.now() - start;
      root.setAttribute("data-time", t.toFixed(3));
    }
    function label() {
      button.textContent = "";
      el("span", { "aria-hidden": "true" }, button).textContent = playing
        ? "\u275a\u275a "
        : "\u25b6 ";
      button.appendChild(document.createTextNode(playing ? "Pause" : "Play"));
      caption.setAttribute("aria-live", playing ? "off" : "polite");
      if (playing) root.setAttribute("data-playing", "1");
      else root.removeAttribute("data-playing");
    }
    function tick(now) {
      if (!playing) return;
      if (last !== null) show(Math.min(clock + (now - last) / 1000, spec.max));
      last = now;
      if (clock >= spec.max) {
        playing = false;
        label();
        return;
      }
      window.requestAnimationFrame(tick);
    }
    function play(on) {
      if (on === playing) return;
      playing = on;
      last = null;
      if (playing && clock >= spec.max) show(spec.min);
      label();
      if (playing) window.requestAnimationFrame(tick);
    }
    button.addEventListener("click", function () {
      play(!playing);
    });
    slider.input.addEventListener("input", function () {
      clock = +slider.input.value;
      root.setAttribute("data-time", clock.toFixed(3));
      play(false);
    });
    label();
    root.setAttribute("data-time", clock.toFixed(3));
    viewer.play = play;
    viewer.show = show;
  }

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
    if (model.kind === "trajectory") addPlayer(root, controls, viewer, caption);
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
    legLengths: legLengths,
    chainPoints: chainPoints,
    rollPitchYaw: rollPitchYaw,
    sampleAt: sampleAt,
    toolPath: toolPath
  };
  mountAll();
})();
