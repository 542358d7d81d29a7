/*
 * Kernel-free panel of the digital-twin chapter: noise and record-length sliders over
 * identifications precomputed by vibration.physics.twin.estimate_grid (embedded as JSON in
 * data-grid). Nothing is estimated here; the script looks results up and draws them with the book's helper
 * window.VibPlot (presentation/assets/plot.js), in the styles passed from Python (data-styles).
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

  /* Relative errors of m, c and k with their 95 % intervals, one row each, drawn by window.VibPlot. */
  function draw(svg, grid, rel, st) {
    var lim = 0, p;
    for (p = 0; p < 3; p++) {
      lim = Math.max(lim, Math.abs(rel.lo[p]), Math.abs(rel.hi[p]), Math.abs(rel.est[p]));
    }
    lim = lim > 0 ? 1.15 * lim : 1;
    var step = window.VibPlot.niceStep(2 * lim, 4);
    lim = Math.ceil(lim / step) * step;
    var bars = [], rows = [], ys = [];
    for (p = 0; p < 3; p++) {
      var y = 2.5 - p;
      ys.push(y);
      rows.push({v: y, label: grid.names[p]});
      bars.push([rel.lo[p], y, rel.hi[p], y], [rel.lo[p], y - 0.13, rel.lo[p], y + 0.13],
        [rel.hi[p], y - 0.13, rel.hi[p], y + 0.13]);
    }
    window.VibPlot.draw(svg, {
      height: 200,
      x: {label: "relative error (%)", min: -lim, max: lim},
      y: {min: 0, max: 3, ticks: rows, grid: false, tickStyle: {size: 15, italic: true, color: "#1d2733"}},
      series: [
        {type: "vline", x: 0, color: st.truth.color, dash: st.truth.dash, width: 1.2, label: st.truth.label,
          cls: "twin-truth"},
        {type: "segments", segs: bars, color: st.interval.color, width: 2.2, label: st.interval.label, cls: "twin-bar"},
        {type: "points", x: rel.est, y: ys, r: 4.5, color: st.estimate.color, label: st.estimate.label, cls: "twin-dot"},
      ],
    });
  }

  function mount(root) {
    if (!root || root.dataset.twinMounted) { return; }
    root.dataset.twinMounted = "1";
    var grid = JSON.parse(root.getAttribute("data-grid"));
    var styles = JSON.parse(root.getAttribute("data-styles"));
    var fmt = window.VibPlot.fmt;
    var noise = root.querySelector(".twin-noise");
    var len = root.querySelector(".twin-len");
    var svg = root.querySelector(".twin-plot");
    var rows = root.querySelectorAll(".twin-estimates tbody tr");
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
      draw(svg, grid, relative(grid, c), styles);
    }
    noise.addEventListener("input", update);
    len.addEventListener("input", update);
    update();
  }

  window.vibrationTwin = { cell: cell, relative: relative, mount: mount };
})();
