/* Kernel-free control panel (chapter 7): LQR weight, ideal skyhook gain, input shaper and frequency error.
 * Colours and line styles come from Python (data-styles: the book's cases passive, LQR and skyhook, and the
 * chapter's shaper styles); the plots are drawn by the book's helper window.VibPlot (presentation/assets/plot.js).
 * Closed forms only, mirrored from vibration.physics.control and vibration.physics.exact; the functions are
 * exposed as window.vibrationControl so the tests compare them with Python. Units: SI (kg, N s/m, N/m, N,
 * rad/s, s, m). */
(function () {
  "use strict";
  if (window.vibrationControl) { return; }

  /* LQR gains [K_x (N/m), K_v (N s/m)] of u = -K [x, v] for int (q_x x^2 + q_v v^2 + r u^2) dt. */
  function lqrGains(m, c, k, qx, qv, r) {
    var a = qx / r;
    var k0 = a / (Math.hypot(k, Math.sqrt(a)) + k);
    var b = qv / r + 2 * m * k0;
    var root = Math.sqrt(c * c + b);
    var k1 = c > 0 ? b / (root + c) : root - c;
    return [k0, k1];
  }

  /* Free response factors: x(t) = e^{-s t} (x0 C(t) + (v0 + s x0) S(t)), every regime. */
  function freeXV(m, c, k, x0, v0, t) {
    var s = c / (2 * m), q = k / m - s * s, e = Math.exp(-s * t), C, S, dC, dS;
    if (q > 1e-14 * (k / m)) {
      var wd = Math.sqrt(q);
      C = Math.cos(wd * t); S = Math.sin(wd * t) / wd; dC = -wd * Math.sin(wd * t); dS = Math.cos(wd * t);
    } else if (q < -1e-14 * (k / m)) {
      var mu = Math.sqrt(-q), ep = Math.exp((mu - s) * t), em = Math.exp(-(mu + s) * t);
      /* e^{-s t} cosh(mu t) etc. without overflow */
      var ch = 0.5 * (ep + em), sh = 0.5 * (ep - em) / mu;
      var x = x0 * ch + (v0 + s * x0) * sh;
      var v = x0 * (0.5 * mu * (ep - em)) + (v0 + s * x0) * ch - s * x;
      return [x, v];
    } else {
      C = 1; S = t; dC = 0; dS = 1;
    }
    var A = x0, B = v0 + s * x0;
    var xf = e * (A * C + B * S);
    var vf = e * (A * dC + B * dS) - s * xf;
    return [xf, vf];
  }

  /* Response from rest to F0 sin(w t): steady state plus free response. Returns {x: [], v: []}. */
  function response(m, c, k, F0, w, ts) {
    var re = k - m * w * w, im = c * w, den = re * re + im * im;
    var hr = F0 * re / den, hi = -F0 * im / den;  /* H = F0 / (re + i im) */
    var xs0 = hi, vs0 = w * hr;                     /* Im(H e^{iwt}) and its derivative at 0 */
    var xs = [], vs = [];
    for (var i = 0; i < ts.length; i++) {
      var t = ts[i], cw = Math.cos(w * t), sw = Math.sin(w * t);
      var fr = freeXV(m, c, k, -xs0, -vs0, t);
      xs.push(hr * sw + hi * cw + fr[0]);
      vs.push(w * (hr * cw - hi * sw) + fr[1]);
    }
    return { x: xs, v: vs };
  }

  /* Ideal-skyhook transmissibility |k + i c w| / |k - m w^2 + i (c + c_sky) w|. */
  function skyhook(m, c, k, csky, ws) {
    return ws.map(function (w) {
      return Math.hypot(k, c * w) / Math.hypot(k - m * w * w, (c + csky) * w);
    });
  }

  function shaper(kind, m, c, k) {
    if (kind === "none") { return { times: [0], amps: [1] }; }
    var wn = Math.sqrt(k / m), z = c / (2 * Math.sqrt(k * m));
    if (!(z >= 0 && z < 1)) { return null; }
    var wd = wn * Math.sqrt(1 - z * z), K = Math.exp(-z * Math.PI / Math.sqrt(1 - z * z));
    if (kind === "ZV") { return { times: [0, Math.PI / wd], amps: [1 / (1 + K), K / (1 + K)] }; }
    if (kind === "ZVD") {
      var d = (1 + K) * (1 + K);
      return { times: [0, Math.PI / wd, 2 * Math.PI / wd], amps: [1 / d, 2 * K / d, K * K / d] };
    }
    return { times: [0], amps: [1] };
  }

  /* Residual vibration ratio of a shaper on the oscillator (m, c, k). */
  function residual(sh, m, c, k) {
    var wn = Math.sqrt(k / m), z = c / (2 * Math.sqrt(k * m)), s = z * wn, wd = wn * Math.sqrt(1 - z * z);
    var tn = sh.times[sh.times.length - 1], C = 0, S = 0;
    for (var i = 0; i < sh.times.length; i++) {
      var e = sh.amps[i] * Math.exp(-s * (tn - sh.times[i]));
      C += e * Math.cos(wd * sh.times[i]); S += e * Math.sin(wd * sh.times[i]);
    }
    return Math.hypot(C, S);
  }

  /* Shaped move of D (m) on the oscillator (m, c, k): command k D sum A_i H(t - t_i). */
  function shapedMove(sh, m, c, k, D, ts) {
    return ts.map(function (t) {
      var x = 0;
      for (var i = 0; i < sh.times.length; i++) {
        if (t >= sh.times[i]) { x += sh.amps[i] * D * (1 + freeXV(m, c, k, -1, 0, t - sh.times[i])[0]); }
      }
      return x;
    });
  }

  function linspace(a, b, n) { var o = []; for (var i = 0; i < n; i++) { o.push(a + (b - a) * i / (n - 1)); } return o; }
  function geomspace(a, b, n) { return linspace(Math.log(a), Math.log(b), n).map(Math.exp); }

  /* Two curves over (x, y) with their legend, drawn by the book's plotting helper (window.VibPlot). */
  function plot(svg, a, b, axes) {
    var line = function (s) {
      return {type: "line", x: s.x, y: s.y, color: s.style.color, dash: s.style.dash, width: s.width || 1.6,
        label: s.style.label, cls: s.cls};
    };
    var second = line(b);
    if (b.style.label === a.style.label) { second.label = ""; } // the same curve twice: one legend entry
    window.VibPlot.draw(svg, {height: 220, aspect: 0.7, x: axes.x, y: axes.y, series: [line(a), second]});
  }

  function mount(root) {
    var p = JSON.parse(root.getAttribute("data-params"));
    var st = JSON.parse(root.getAttribute("data-styles"));
    var fmt = window.VibPlot.fmt;
    var q = function (sel) { return root.querySelector(sel); };
    var ts = linspace(0, p.t_end, 1001);
    function updateActive() {
      var r = Math.pow(10, parseFloat(q(".vc-logr").value));
      var K = lqrGains(p.m, p.c, p.k, p.q_x, p.q_v, r);
      var cl = response(p.m, p.c + K[1], p.k + K[0], p.F0, p.omega, ts);
      var pas = response(p.m, p.c, p.k, p.F0, p.omega, ts);
      plot(q("svg.vc-active"), { x: ts, y: pas.x, style: st.passive, width: 1.2, cls: "vc-passive" },
        { x: ts, y: cl.x, style: st.LQR, cls: "vc-lqr" }, { x: { label: "t (s)", pad: 0 }, y: { label: "x (m)" } });
      var re = p.k + K[0] - p.m * p.omega * p.omega, im = (p.c + K[1]) * p.omega;
      var X = p.F0 / Math.hypot(re, im), U = X * Math.hypot(K[0], p.omega * K[1]);
      q(".vc-r-out").textContent = "r = " + fmt(r, 3) + " 1/N²";
      q(".vc-active-read").innerHTML = "K<sub>x</sub> = " + fmt(K[0]) + " N/m, K<sub>v</sub> = " + fmt(K[1])
        + " N s/m; steady amplitude " + fmt(X) + " m (passive "
        + fmt(p.F0 / Math.hypot(p.k - p.m * p.omega * p.omega, p.c * p.omega)) + " m), steady force amplitude "
        + fmt(U) + " N";
    }
    var ws = geomspace(0.3, 4, 300).map(function (v) { return v * Math.sqrt(p.k / p.m); });
    var ratios = ws.map(function (w) { return w / Math.sqrt(p.k / p.m); });
    function updateSky() {
      var cs = parseFloat(q(".vc-csky").value);
      var Ts = skyhook(p.m, p.c, p.k, cs, ws), Tp = skyhook(p.m, p.c, p.k, 0, ws);
      plot(q("svg.vc-sky"), { x: ratios, y: Tp, style: st.passive, width: 1.2, cls: "vc-passive" },
        { x: ratios, y: Ts, style: st.skyhook, cls: "vc-skyhook" },
        { x: { label: "ω/ω_n", log: true, pad: 0 }, y: { label: "|X/Y|", log: true } });
      var wn = Math.sqrt(p.k / p.m);
      q(".vc-csky-out").innerHTML = "c<sub>sky</sub> = " + fmt(cs, 3) + " N s/m";
      q(".vc-sky-read").innerHTML = "at ω = ω<sub>n</sub>: |X/Y| = " + fmt(skyhook(p.m, p.c, p.k, cs, [wn])[0]) + " (passive "
        + fmt(skyhook(p.m, p.c, p.k, 0, [wn])[0]) + ", every passive damper > 1)";
    }
    var tm = linspace(0, 10, 801);
    function updateShaper() {
      var kind = q(".vc-kind").value, err = parseFloat(q(".vc-err").value) / 100;
      var sh = shaper(kind, p.m, p.c, p.k), ka = p.k * (1 + err) * (1 + err);
      var x0 = shapedMove(shaper("none"), p.m, p.c, ka, p.move, tm), x = shapedMove(sh, p.m, p.c, ka, p.move, tm);
      plot(q("svg.vc-shape"), { x: tm, y: x0, style: st.none, width: 1.2, cls: "vc-unshaped" },
        { x: tm, y: x, style: st[kind], cls: "vc-shaped" }, { x: { label: "t (s)", pad: 0 }, y: { label: "x (m)" } });
      q(".vc-err-out").textContent = (err >= 0 ? "+" : "") + fmt(100 * err, 3) + " %";
      q(".vc-shape-read").textContent = kind === "none" ? "unshaped step: residual vibration 100 %" :
        kind + ": residual vibration " + fmt(100 * residual(sh, p.m, p.c, ka), 3) + " % of the unshaped, added delay " + fmt(sh.times[sh.times.length - 1]) + " s";
    }
    q(".vc-logr").addEventListener("input", updateActive);
    q(".vc-csky").addEventListener("input", updateSky);
    q(".vc-kind").addEventListener("change", updateShaper);
    q(".vc-err").addEventListener("input", updateShaper);
    updateActive(); updateSky(); updateShaper();
  }

  window.vibrationControl = {
    lqrGains: lqrGains, response: response, skyhook: skyhook, shaper: shaper, residual: residual,
    shapedMove: shapedMove, mount: mount
  };
})();
