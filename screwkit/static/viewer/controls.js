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

