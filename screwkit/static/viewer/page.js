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
