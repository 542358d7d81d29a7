/*
 * Kernel-free panel of the real-oscillator chapter: the exact free decay with viscous and Coulomb
 * friction (the same piecewise closed form as vibration.physics.lab.free_decay_response) drawn over
 * one measured decay embedded in the page. No library, no network; the plot is drawn by the book's helper
 * window.VibPlot (vibration/presentation/assets/plot.js), loaded before this script.
 *
 * window.vibrationRealDecay = {response, mount}.
 */
(function () {
  "use strict";
  if (window.vibrationRealDecay) {
    return;
  }

  function copysign(a, b) {
    return b < 0 || (b === 0 && 1 / b < 0) ? -Math.abs(a) : Math.abs(a);
  }

  /* Angle (rad) at the times t (s): free decay from rest at the extremum theta0 at t0. */
  function response(t, wn, zeta, fr, off, th0, t0) {
    var wd = wn * Math.sqrt(1 - zeta * zeta);
    var half = Math.PI / wd;
    var q = Math.exp(-zeta * wn * half);
    var nHalf = Math.max(0, Math.ceil((t[t.length - 1] - t0) / half)) + 1;
    var e = new Float64Array(nHalf + 1);
    var c = new Float64Array(nHalf);
    var stop = nHalf;
    var j, k;
    e[0] = th0;
    for (k = 0; k < nHalf; k++) {
      var d = e[k] - off;
      if (Math.abs(d) <= fr) {
        stop = k;
        for (j = k + 1; j <= nHalf; j++) e[j] = e[k];
        for (j = k; j < nHalf; j++) c[j] = e[k];
        break;
      }
      c[k] = off + copysign(fr, d);
      e[k + 1] = c[k] - q * (e[k] - c[k]);
    }
    var ratio = zeta / Math.sqrt(1 - zeta * zeta);
    var out = new Array(t.length);
    for (var i = 0; i < t.length; i++) {
      var tau, h;
      if (t[i] < t0) {
        tau = t[i] - t0;
        var d0 = th0 - off;
        var cPrev = d0 !== 0 ? off - copysign(fr, d0) : off;
        h = Math.exp(-zeta * wn * tau) * (Math.cos(wd * tau) + ratio * Math.sin(wd * tau));
        out[i] = cPrev + (th0 - cPrev) * h;
      } else {
        k = Math.min(Math.floor((t[i] - t0) / half), nHalf - 1);
        tau = t[i] - t0 - k * half;
        h = Math.exp(-zeta * wn * tau) * (Math.cos(wd * tau) + ratio * Math.sin(wd * tau));
        out[i] = k >= stop ? e[Math.min(stop, nHalf)] : c[k] + (e[k] - c[k]) * h;
      }
    }
    return out;
  }

  /* The measured dots and the model line, drawn by the book's plotting helper (window.VibPlot). */
  function draw(svg, data, model, styles) {
    var m = styles.measured, f = styles.model;
    window.VibPlot.draw(svg, {
      height: 280, aspect: 0.75,
      x: {label: "t (s)", min: data.t[0], max: data.t[data.t.length - 1]},
      y: {label: "θ (rad)", pad: 0.08},
      series: [
        {type: "points", x: data.t, y: data.angle, r: 1.6, color: m.color, stroke: "none", label: m.label, cls: "vro-meas"},
        {type: "line", x: model.t, y: model.y, color: f.color, dash: f.dash, width: 1.6, label: f.label, cls: "vro-model"},
      ],
    });
  }

  function mount(panel) {
    var data = JSON.parse(panel.getAttribute("data-decay"));
    var styles = JSON.parse(panel.getAttribute("data-styles"));
    var q = function (c) { return panel.querySelector(c); };
    var inputs = {wn: q(".vro-wn"), zeta: q(".vro-zeta"), fr: q(".vro-fr")};
    var outs = {wn: q(".vro-wn-out"), zeta: q(".vro-zeta-out"), fr: q(".vro-fr-out")};
    var svg = q("svg.vro-plot");
    function update() {
      var wn = parseFloat(inputs.wn.value), zeta = parseFloat(inputs.zeta.value), fr = parseFloat(inputs.fr.value);
      var P = window.VibPlot;
      outs.wn.textContent = P.fixed(wn, 3) + " rad/s";
      outs.zeta.textContent = P.fixed(zeta, 4);
      outs.fr.textContent = P.fixed(fr, 3) + " rad";
      var n = 1500, tm = [];
      for (var i = 0; i < n; i++) tm.push(data.t_start + (data.t_end - data.t_start) * i / (n - 1));
      var ym = response(tm, wn, zeta, fr, data.offset, data.theta0, data.t0);
      draw(svg, data, {t: tm, y: ym}, styles);
      var inWin = [], tw = [];
      for (i = 0; i < data.t.length; i++) {
        if (data.t[i] >= data.t_start && data.t[i] <= data.t_end) { tw.push(data.t[i]); inWin.push(data.angle[i]); }
      }
      var yw = response(tw, wn, zeta, fr, data.offset, data.theta0, data.t0), ss = 0;
      for (i = 0; i < tw.length; i++) ss += (inWin[i] - yw[i]) * (inWin[i] - yw[i]);
      q(".vro-rms").textContent = P.fmt(Math.sqrt(ss / tw.length), 3) + " rad";
    }
    for (var k in inputs) inputs[k].addEventListener("input", update);
    q(".vro-reset").addEventListener("click", function () {
      inputs.wn.value = data.fit.omega_n; inputs.zeta.value = data.fit.zeta; inputs.fr.value = data.fit.friction;
      update();
    });
    update();
  }

  window.vibrationRealDecay = {response: response, mount: mount};
})();
