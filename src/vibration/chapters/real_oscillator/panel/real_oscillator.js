/*
 * Kernel-free panel of the real-oscillator chapter: the exact free decay with viscous and Coulomb
 * friction (the same piecewise closed form as vibration.physics.lab.free_decay_response) drawn over
 * one measured decay embedded in the page. No library, no network.
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

  var SVG = "http://www.w3.org/2000/svg";
  function el(name, attrs) {
    var n = document.createElementNS(SVG, name);
    for (var a in attrs) n.setAttribute(a, attrs[a]);
    return n;
  }

  function draw(svg, data, model) {
    while (svg.firstChild) svg.removeChild(svg.firstChild);
    var W = 640, H = 300, L = 48, R = 10, T = 10, B = 34;
    var t = data.t, y = data.angle;
    var t0 = t[0], t1 = t[t.length - 1];
    var lo = Math.min.apply(null, y), hi = Math.max.apply(null, y);
    var pad = 0.08 * (hi - lo);
    lo -= pad; hi += pad;
    function X(v) { return L + (W - L - R) * (v - t0) / (t1 - t0); }
    function Y(v) { return T + (H - T - B) * (hi - v) / (hi - lo); }
    svg.appendChild(el("line", {x1: L, y1: H - B, x2: W - R, y2: H - B, class: "vro-axis"}));
    svg.appendChild(el("line", {x1: L, y1: T, x2: L, y2: H - B, class: "vro-axis"}));
    for (var s = Math.ceil(t0 / 2) * 2; s <= t1; s += 2) {
      var lab = el("text", {x: X(s), y: H - B + 14, class: "vro-tick", "text-anchor": "middle"});
      lab.textContent = String(s);
      svg.appendChild(lab);
    }
    var xl = el("text", {x: (L + W - R) / 2, y: H - 4, class: "vro-label", "text-anchor": "middle"});
    xl.textContent = "t (s)";
    svg.appendChild(xl);
    var yl = el("text", {x: 12, y: (T + H - B) / 2, class: "vro-label", transform: "rotate(-90 12 " + (T + H - B) / 2 + ")", "text-anchor": "middle"});
    yl.textContent = "θ (rad)";
    svg.appendChild(yl);
    var pts = [];
    for (var i = 0; i < t.length; i++) {
      svg.appendChild(el("circle", {cx: X(t[i]).toFixed(1), cy: Y(y[i]).toFixed(1), r: 1.6, class: "vro-meas"}));
    }
    for (i = 0; i < model.t.length; i++) pts.push(X(model.t[i]).toFixed(1) + "," + Y(model.y[i]).toFixed(1));
    svg.appendChild(el("polyline", {points: pts.join(" "), class: "vro-model"}));
  }

  function mount(panel) {
    var data = JSON.parse(panel.getAttribute("data-decay"));
    var q = function (c) { return panel.querySelector(c); };
    var inputs = {wn: q(".vro-wn"), zeta: q(".vro-zeta"), fr: q(".vro-fr")};
    var outs = {wn: q(".vro-wn-out"), zeta: q(".vro-zeta-out"), fr: q(".vro-fr-out")};
    var svg = q("svg.vro-plot");
    function update() {
      var wn = parseFloat(inputs.wn.value), zeta = parseFloat(inputs.zeta.value), fr = parseFloat(inputs.fr.value);
      outs.wn.textContent = wn.toFixed(3) + " rad/s";
      outs.zeta.textContent = zeta.toFixed(4);
      outs.fr.textContent = fr.toFixed(3) + " rad";
      var n = 1500, tm = [];
      for (var i = 0; i < n; i++) tm.push(data.t_start + (data.t_end - data.t_start) * i / (n - 1));
      var ym = response(tm, wn, zeta, fr, data.offset, data.theta0, data.t0);
      draw(svg, data, {t: tm, y: ym});
      var inWin = [], tw = [];
      for (i = 0; i < data.t.length; i++) {
        if (data.t[i] >= data.t_start && data.t[i] <= data.t_end) { tw.push(data.t[i]); inWin.push(data.angle[i]); }
      }
      var yw = response(tw, wn, zeta, fr, data.offset, data.theta0, data.t0), ss = 0;
      for (i = 0; i < tw.length; i++) ss += (inWin[i] - yw[i]) * (inWin[i] - yw[i]);
      q(".vro-rms").textContent = Math.sqrt(ss / tw.length).toFixed(3) + " rad";
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
