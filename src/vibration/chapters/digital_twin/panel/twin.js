/*
 * Kernel-free panel of the digital-twin chapter: noise and record-length sliders over
 * identifications precomputed by vibration.physics.twin.estimate_grid (embedded as JSON in
 * data-grid). Nothing is estimated here; the script looks results up and draws them.
 *
 * window.vibrationTwin = {cell, relative, mount} is defined once per page; every panel
 * (div.twin-panel) is mounted separately.
 */
(function () {
  "use strict";
  if (window.vibrationTwin) {
    return;
  }

  /** Estimates and 95 % intervals at noise index i, length index j: arrays of 3 (m, c, k). */
  function cell(grid, i, j) {
    var est = grid.estimates[i][j];
    var ci = grid.ci95[i][j];
    return {
      est: est.slice(),
      lo: ci.map(function (r) { return r[0]; }),
      hi: ci.map(function (r) { return r[1]; }),
      covers: ci.map(function (r, p) { return r[0] <= grid.truth[p] && grid.truth[p] <= r[1]; })
    };
  }

  /** Relative errors in percent of estimate, low and high ends against the truth. */
  function relative(grid, c) {
    var f = function (v, p) { return 100 * (v - grid.truth[p]) / grid.truth[p]; };
    return { est: c.est.map(f), lo: c.lo.map(f), hi: c.hi.map(f) };
  }

  function fmt(v, digits) {
    var s = Number(v).toPrecision(digits);
    if (s.indexOf("e") < 0 && s.indexOf(".") >= 0) {
      s = s.replace(/0+$/, "").replace(/\.$/, "");
    }
    return s;
  }

  /** SVG markup of one element (attribute values are numbers or fixed class names; text is escaped). */
  function el(name, attrs, text) {
    var a = Object.keys(attrs).map(function (k) { return " " + k + '="' + attrs[k] + '"'; }).join("");
    if (text === undefined) { return "<" + name + a + "/>"; }
    var t = String(text).replace(/&/g, "&amp;").replace(/</g, "&lt;");
    return "<" + name + a + ">" + t + "</" + name + ">";
  }

  function niceStep(span) {
    var raw = span / 4;
    var p = Math.pow(10, Math.floor(Math.log10(raw)));
    var m = raw / p;
    return (m < 1.5 ? 1 : m < 3.5 ? 2 : m < 7.5 ? 5 : 10) * p;
  }

  function draw(svg, grid, rel) {
    var out = [];
    var W = 640, H = 200, left = 70, right = 20, top = 14, bottom = 40;
    var lim = 0;
    for (var p = 0; p < 3; p++) {
      lim = Math.max(lim, Math.abs(rel.lo[p]), Math.abs(rel.hi[p]), Math.abs(rel.est[p]));
    }
    lim = lim > 0 ? 1.15 * lim : 1;
    var step = niceStep(2 * lim);
    lim = Math.ceil(lim / step) * step;
    var x = function (v) { return left + (v + lim) / (2 * lim) * (W - left - right); };
    var rowH = (H - top - bottom) / 3;
    for (var tk = -lim; tk <= lim + 1e-9 * lim; tk += step) {
      out.push(el("line", { x1: x(tk), x2: x(tk), y1: top, y2: H - bottom, class: "twin-grid" }));
      out.push(el("text", { x: x(tk), y: H - bottom + 15, "text-anchor": "middle", class: "twin-tick" },
        fmt(Math.abs(tk) < 1e-12 * lim ? 0 : tk, 3)));
    }
    out.push(el("text", { x: (left + W - right) / 2, y: H - 6, "text-anchor": "middle", class: "twin-axis" },
      "relative error (%)"));
    out.push(el("line", { x1: x(0), x2: x(0), y1: top, y2: H - bottom, class: "twin-truth" }));
    for (p = 0; p < 3; p++) {
      var yc = top + (p + 0.5) * rowH;
      out.push(el("text", { x: left - 10, y: yc + 4, "text-anchor": "end", class: "twin-name" }, grid.names[p]));
      out.push(el("line", { x1: x(rel.lo[p]), x2: x(rel.hi[p]), y1: yc, y2: yc, class: "twin-bar" }));
      out.push(el("line", { x1: x(rel.lo[p]), x2: x(rel.lo[p]), y1: yc - 6, y2: yc + 6, class: "twin-bar" }));
      out.push(el("line", { x1: x(rel.hi[p]), x2: x(rel.hi[p]), y1: yc - 6, y2: yc + 6, class: "twin-bar" }));
      out.push(el("circle", { cx: x(rel.est[p]), cy: yc, r: 4.5, class: "twin-dot" }));
    }
    svg.innerHTML = out.join("");
  }

  function mount(root) {
    if (!root || root.dataset.twinMounted) { return; }
    root.dataset.twinMounted = "1";
    var grid = JSON.parse(root.getAttribute("data-grid"));
    var noise = root.querySelector(".twin-noise");
    var len = root.querySelector(".twin-len");
    var svg = root.querySelector(".twin-plot");
    var rows = root.querySelectorAll(".twin-readout tbody tr");
    function update() {
      var i = Number(noise.value), j = Number(len.value);
      root.querySelector(".twin-noise-out").textContent = fmt(grid.noises[i], 3);
      root.querySelector(".twin-len-out").textContent = fmt(grid.durations[j], 4) + " s";
      var c = cell(grid, i, j);
      for (var p = 0; p < 3; p++) {
        var r = rows[p];
        r.querySelector(".twin-true").textContent = fmt(grid.truth[p], 4);
        r.querySelector(".twin-est").textContent = fmt(c.est[p], 5);
        r.querySelector(".twin-lo").textContent = fmt(c.lo[p], 5);
        r.querySelector(".twin-hi").textContent = fmt(c.hi[p], 5);
        r.querySelector(".twin-in").textContent = c.covers[p] ? "yes" : "no";
      }
      draw(svg, grid, relative(grid, c));
    }
    noise.addEventListener("input", update);
    len.addEventListener("input", update);
    update();
  }

  window.vibrationTwin = { cell: cell, relative: relative, mount: mount };
})();
