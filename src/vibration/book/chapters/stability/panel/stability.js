/*
 * Kernel-free panel of the stability chapter: damping ratio (log) and base frequency sliders
 * moving the transmissibility curve, the step response and the poles together.
 * SI units (kg, N/m, rad/s, s). No libraries, no network: the plots are drawn by the book's helper
 * window.VibPlot (presentation/assets/plot.js), in the colours passed from Python. The closed forms are those of
 * vibration.physics.stability (transmissibility, poles, step_response, step_metrics):
 *
 *   T(w) = sqrt((1 + (2 zeta r)^2) / ((1 - r^2)^2 + (2 zeta r)^2)),  r = w / wn (scaled form for r > 1);
 *   1 - y(t) = exp(-sigma t) (cos wd t + sigma/wd sin wd t)            (oscillating roots),
 *            = (1 + sigma t) exp(-sigma t)                              (double root),
 *            = e_hi ((2 + em)/2 - sigma em / (2 mu)), em = expm1(-2 mu t) (real roots);
 *   settling: true last exit from the band, after the last extremum larger than it.
 *
 * window.vibrationStability = {poles, transmissibility, stepResponse, stepMetrics, compute, mount}.
 */
(function () {
  "use strict";
  if (window.vibrationStability) {
    return;
  }
  var BAND = 0.02;

  function coeffs(p) {
    var c = 2 * p.zeta * Math.sqrt(p.k * p.m);
    var sigma = c / (2 * p.m);
    var wn2 = p.k / p.m;
    return { c: c, sigma: sigma, wn2: wn2, wn: Math.sqrt(wn2), q: wn2 - sigma * sigma };
  }

  /** Poles [[re, im], [re, im]] in 1/s, ordered as vibration.poles. */
  function poles(p) {
    var s = coeffs(p);
    if (s.q > 0) {
      var wd = Math.sqrt(s.q);
      return [[0 - s.sigma, wd], [0 - s.sigma, -wd]];
    }
    if (s.q === 0) {
      return [[-s.sigma, 0], [-s.sigma, 0]];
    }
    var mu = Math.sqrt(-s.q);
    return [[-s.wn2 / (s.sigma + mu), 0], [-(s.sigma + mu), 0]];
  }

  /** Base-excitation transmissibility |X/Y| at w (rad/s). */
  function transmissibility(p, w) {
    var s = coeffs(p);
    var r = w / s.wn;
    var zeta = p.zeta;
    if (r > 1) {
      var inv = 1 / r;
      var bz = 2 * zeta * inv;
      return Math.hypot(inv * inv, bz) / Math.hypot((inv - 1) * (inv + 1), bz);
    }
    var b = 2 * zeta * r;
    return Math.hypot(1, b) / Math.hypot((1 - r) * (1 + r), b);
  }

  function oneMinusY(p) {
    var s = coeffs(p);
    var sigma = s.sigma;
    if (s.q > 0) {
      var wd = Math.sqrt(s.q);
      return function (t) {
        return Math.exp(-sigma * t) * (Math.cos(wd * t) + (sigma / wd) * Math.sin(wd * t));
      };
    }
    if (s.q === 0) {
      return function (t) {
        return (1 + sigma * t) * Math.exp(-sigma * t);
      };
    }
    var mu = Math.sqrt(-s.q);
    var sHi = -s.wn2 / (sigma + mu);
    return function (t) {
      var eHi = Math.exp(sHi * t);
      var em = Math.expm1(-2 * mu * t);
      return eHi * (0.5 * (2 + em) - (sigma * em) / (2 * mu));
    };
  }

  /** Normalised step response k x / F at t (s). */
  function stepResponse(p, t) {
    return 1 - oneMinusY(p)(t);
  }

  /** Root of g on [a, b] (g changes sign) by bisection to the last bit. */
  function solve(g, a, b) {
    var ga = g(a);
    if (ga === 0) {
      return a;
    }
    if (g(b) === 0) {
      return b;
    }
    for (var i = 0; i < 200; i++) {
      var mid = 0.5 * (a + b);
      if (mid <= a || mid >= b) {
        break;
      }
      var gm = g(mid);
      if (gm === 0) {
        return mid;
      }
      if ((gm > 0) === (ga > 0)) {
        a = mid;
        ga = gm;
      } else {
        b = mid;
      }
    }
    return 0.5 * (a + b);
  }

  /** {overshoot, peak_time (s, Infinity if none), rise_time (s), settling_time (s)}, as vibration.step_metrics. */
  function stepMetrics(p) {
    var s = coeffs(p);
    var f = oneMinusY(p);
    var crossing = function (level, a, b) {
      return solve(function (t) { return f(t) - (1 - level); }, a, b);
    };
    var lb = Math.log(BAND);
    if (s.q > 0) {
      var wd = Math.sqrt(s.q);
      var half = Math.PI / wd;
      var logMp = -s.sigma * half;
      var n = 0;
      if (logMp >= lb) {
        n = Math.max(1, Math.ceil(lb / logMp) - 1);
        while (n > 1 && n * logMp <= lb) { n -= 1; }
        while ((n + 1) * logMp > lb) { n += 1; }
        if (n * logMp <= lb) { n = 0; }
      }
      var level = BAND * Math.exp(-n * logMp);
      var tau = solve(function (t) { return f(t) - level; }, 0, half);
      return {
        overshoot: Math.exp(logMp),
        peak_time: half,
        rise_time: crossing(0.9, 0, half) - crossing(0.1, 0, half),
        settling_time: n * half + tau,
      };
    }
    var tc;
    if (s.q === 0) {
      tc = 1 / s.sigma;
    } else {
      var mu = Math.sqrt(-s.q);
      tc = (s.sigma + mu) / s.wn2;
    }
    var hi = tc;
    while (f(hi) > Math.min(BAND, 0.1)) { hi *= 2; }
    return {
      overshoot: 0,
      peak_time: Infinity,
      rise_time: crossing(0.9, 0, hi) - crossing(0.1, 0, hi),
      settling_time: crossing(1 - BAND, 0, hi),
    };
  }

  /** Everything the panel shows: params {m (kg), k (N/m), zeta, omega (rad/s)}. */
  function compute(params) {
    var p = { m: +params.m, k: +params.k, zeta: +params.zeta, omega: +params.omega };
    var s = coeffs(p);
    var st = stepMetrics(p);
    return {
      c: s.c,
      wn: s.wn,
      T: transmissibility(p, p.omega),
      poles: poles(p),
      overshoot: st.overshoot,
      peak_time: st.peak_time,
      rise_time: st.rise_time,
      settling_time: st.settling_time,
    };
  }

  /* ---------------------------------------------------------------- drawing (window.VibPlot) */

  var fmt = function (v, d) { return window.VibPlot.fmt(v, d); };

  /** Transmissibility on a logarithmic axis from 0.01 to 1000, the operating point and √2 ω_n. */
  function drawTrans(svg, p, wMax, st) {
    var wn = Math.sqrt(p.k / p.m);
    var ws = [], ts = [];
    for (var i = 0; i <= 600; i++) { ws.push((wMax * i) / 600); }
    for (var j = -80; j <= 80; j++) { ws.push(wn * (1 + (Math.max(p.zeta, 0.002) * 6 * j) / 80)); }
    ws = ws.filter(function (w) { return w >= 0 && w <= wMax; }).sort(function (a, b) { return a - b; });
    ws.forEach(function (w) { ts.push(transmissibility(p, w)); });
    var lo = 0.01, hi = 1000, T = Math.min(Math.max(transmissibility(p, p.omega), lo), hi);
    window.VibPlot.draw(svg, {
      height: 260, aspect: 0.8,
      x: {label: "base frequency ω (rad/s)", min: 0, max: wMax},
      y: {label: "|X/Y| (log)", log: true, min: lo, max: hi, ticks: [0.01, 0.1, 1, 10, 100, 1000]},
      series: [
        {type: "vline", x: Math.SQRT2 * wn, color: st.reference.color, dash: "4 3", cls: "vst-mark"},
        {type: "line", x: ws, y: ts, color: st.curve.color, dash: st.curve.dash, width: 1.4, cls: "vst-curve"},
        {type: "points", x: [p.omega], y: [T], r: 5, color: st.point.color, cls: "vst-op"},
      ],
    });
  }

  /** Normalised step response with its ±2 % band and the settling time. */
  function drawStep(svg, p, r, st) {
    var tEnd = Math.max((12 * 2 * Math.PI) / r.wn, Math.min(1.2 * r.settling_time, 400 * (2 * Math.PI) / r.wn));
    var n = 1500, ts = [], ys = [];
    var f = oneMinusY(p);
    for (var i = 0; i <= n; i++) {
      var t = (tEnd * i) / n;
      ts.push(t);
      ys.push(1 - f(t));
    }
    var series = [
      {type: "band", y0: 1 - BAND, y1: 1 + BAND, color: "#d9dde2", cls: "vst-band"},
      {type: "line", x: ts, y: ys, color: st.curve.color, dash: st.curve.dash, width: 1.4, cls: "vst-curve"},
    ];
    if (r.settling_time <= tEnd) {
      series.push({type: "vline", x: r.settling_time, color: st.reference.color, dash: "1.5 3", cls: "vst-mark"});
    }
    window.VibPlot.draw(svg, {
      height: 260, aspect: 0.8,
      x: {label: "time t (s)", min: 0, max: tEnd},
      y: {label: "k x / F", min: -0.05, max: 2.05, ticks: [0, 0.5, 1, 1.5, 2]},
      series: series,
    });
  }

  /** Poles in the complex plane, equal scales, with the circle of radius ω_n. */
  function drawPoles(svg, p, r, st) {
    var wn = r.wn, pl = r.poles;
    var R = Math.max(1.2 * wn, (-pl[1][0] * 1.1) / 1.75);
    var cx = [], cy = [];
    for (var i = 0; i <= 120; i++) {
      var a = (Math.PI * i) / 120 + Math.PI / 2;
      cx.push(wn * Math.cos(a));
      cy.push(wn * Math.sin(a));
    }
    window.VibPlot.draw(svg, {
      height: 260, aspect: 1, equal: true,
      x: {label: "Re s (1/s)", min: -1.75 * R, max: 0.25 * R},
      y: {label: "Im s (1/s)", min: -R, max: R},
      series: [
        {type: "line", x: cx, y: cy, color: st.locus.color, dash: "3 3", width: 1, cls: "vst-circle"},
        {type: "vline", x: 0, color: st.reference.color, width: 1, cls: "vst-axis0"},
        {type: "points", marker: "cross", r: 5, width: 2.2, x: pl.map(function (q) { return q[0]; }),
          y: pl.map(function (q) { return q[1]; }), color: st.point.color, cls: "vst-pole"},
      ],
    });
  }

  function text(panel, cls, v) {
    var el = panel.querySelector("." + cls);
    if (el) { el.textContent = v; }
  }

  function poleText(pl) {
    if (pl[0][1] !== 0) {
      return fmt(pl[0][0], 4) + " \u00b1 " + fmt(Math.abs(pl[0][1]), 4) + "i";
    }
    return fmt(pl[0][0], 4) + ", " + fmt(pl[1][0], 4);
  }

  /** Attach one panel (div.vst-panel with data-params JSON). */
  function mount(panel) {
    var data = window.VibPlot.claim(panel, "vstMounted");
    if (!data) { return null; }
    var cfg = data.cfg, styles = data.styles;
    var zIn = panel.querySelector("input.vst-zeta");
    var wIn = panel.querySelector("input.vst-omega");
    var nPos = +zIn.max;
    var state = { m: cfg.m, k: cfg.k, zeta: cfg.zeta, omega: cfg.omega };
    function posToZeta(pos) {
      return cfg.zeta_min * Math.pow(cfg.zeta_max / cfg.zeta_min, pos / nPos);
    }
    function update() {
      var r = compute(state);
      text(panel, "vst-zeta-out", fmt(state.zeta, 4));
      panel.querySelector(".vst-omega-out").innerHTML = fmt(state.omega, 4) + " rad/s (" + fmt(state.omega / r.wn, 3) +
        " \u03c9<sub>n</sub>)";
      text(panel, "vst-r-c", fmt(r.c, 4) + " N s/m");
      text(panel, "vst-r-t", fmt(r.T, 4));
      text(panel, "vst-r-poles", poleText(r.poles) + " 1/s");
      text(panel, "vst-r-os", fmt(100 * r.overshoot, 4) + " %");
      text(panel, "vst-r-tr", fmt(r.rise_time, 4) + " s");
      text(panel, "vst-r-ts", fmt(r.settling_time, 4) + " s");
      drawTrans(panel.querySelector("svg.vst-trans"), state, cfg.w_max, styles);
      drawStep(panel.querySelector("svg.vst-step"), state, r, styles);
      drawPoles(panel.querySelector("svg.vst-poles"), state, r, styles);
      return r;
    }
    zIn.addEventListener("input", function () { state.zeta = posToZeta(+zIn.value); update(); });
    wIn.addEventListener("input", function () { state.omega = +wIn.value; update(); });
    update();
    return { update: update, state: state };
  }

  window.vibrationStability = {poles: poles, transmissibility: transmissibility, stepResponse: stepResponse,
    stepMetrics: stepMetrics, compute: compute, mount: mount};
})();
