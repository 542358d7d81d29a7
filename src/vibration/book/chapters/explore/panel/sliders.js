/*
 * Static slider panel for the forced mass-spring-damper
 *   m x'' + c x' + k x = F0 sin(omega t),  x(0) = v(0) = 0,
 * in SI units (kg, N s/m, N/m, N, rad/s, s, m). No libraries, no network: the plots are drawn (and redrawn
 * at the panel's width) by the book's helper window.VibPlot (presentation/assets/plot.js), in the line
 * styles passed from Python (data-styles, the JupyterLab figure's styles).
 *
 * The response from rest is the steady state plus a free transient:
 *   H = F0 / (k - m omega^2 + i c omega) = P + i Q,
 *   x_ss(t) = P sin(omega t) + Q cos(omega t),
 *   x_tr(t) = x0 g'(t) + (v0 + 2 sigma x0) g(t),  x0 = -Q,  v0 = -omega P,
 * where g is the impulse kernel exp(-sigma t) sin(wd t) / wd and its
 * critical / overdamped forms, written exactly as in vibration.physics.exact._kernels
 * (expm1 for the overdamped pair, so the kernels stay accurate near zeta = 1).
 *
 * window.vibrationSliders = {compute, settlingTime, steadyState, regime, mount, mountAll}
 * is defined once per page; every panel (div.vib-panel) is mounted separately, so
 * several panels can share one page.
 */
(function () {
  "use strict";
  if (window.vibrationSliders) {
    return;
  }

  var CRITICAL_TOL = 1e-12; // |zeta - 1| at or below which the regime is "critically damped"
  var SETTLE_TOL = 0.02; // settling band, fraction of the steady-state amplitude
  var SCAN_POINTS = 4001; // grid of the settling-time scan in non-oscillating regimes

  /** Regime name, as vibration.Oscillator.regime. */
  function regime(m, c, k) {
    if (c < 0) {
      return "unstable";
    }
    if (c === 0) {
      return "undamped";
    }
    var zeta = c / (2 * Math.sqrt(k * m));
    if (Math.abs(zeta - 1) <= CRITICAL_TOL) {
      return "critically damped";
    }
    return zeta < 1 ? "underdamped" : "overdamped";
  }

  /** Free-response kernels [g'(t), g(t)] at one time t (s); g in s, g' dimensionless. */
  function kernel(m, c, k, t) {
    var sigma = c / (2 * m);
    var wn2 = k / m;
    var q = wn2 - sigma * sigma;
    var kc, ks, env;
    if (q > 0) {
      var wd = Math.sqrt(q);
      env = Math.exp(-sigma * t);
      kc = env * Math.cos(wd * t);
      ks = (env * Math.sin(wd * t)) / wd;
    } else if (q === 0) {
      env = Math.exp(-sigma * t);
      kc = env;
      ks = t * env;
    } else {
      var mu = Math.sqrt(-q);
      var sHi = sigma > 0 ? -wn2 / (sigma + mu) : -sigma + mu;
      var eHi = Math.exp(sHi * t);
      var em = Math.expm1(-2 * mu * t);
      kc = 0.5 * eHi * (2 + em);
      ks = (-eHi * em) / (2 * mu);
    }
    return [kc - sigma * ks, ks];
  }

  /** Free displacement (m) at t (s) from x(0) = x0 (m), v(0) = v0 (m/s). */
  function freeX(m, c, k, x0, v0, t) {
    var kr = kernel(m, c, k, t);
    return x0 * kr[0] + (v0 + 2 * (c / (2 * m)) * x0) * kr[1];
  }

  /**
   * Steady state of F0 sin(omega t): H = P + i Q (m), amplitude |H| (m),
   * phase lag atan2(c omega, k - m omega^2) (rad), magnification |H| / (F0/k).
   */
  function steadyState(p) {
    var dr = p.k - p.m * p.omega * p.omega;
    var di = p.c * p.omega;
    var d2 = dr * dr + di * di;
    var P = d2 === 0 ? Infinity : (p.F0 * dr) / d2;
    var Q = d2 === 0 ? -Infinity : (-p.F0 * di) / d2;
    var amp = p.F0 === 0 ? 0 : d2 === 0 ? Infinity : p.F0 / Math.hypot(dr, di);
    return {
      P: P,
      Q: Q,
      amplitude: amp,
      phase: d2 === 0 ? Math.PI / 2 : Math.atan2(di, dr),
      magnification: d2 === 0 ? Infinity : p.k / Math.hypot(dr, di),
      static_deflection: p.F0 / p.k,
    };
  }

  /**
   * Time (s) after which the transient stays below SETTLE_TOL times the steady-state
   * amplitude: the envelope R exp(-sigma t) when underdamped, otherwise the transient
   * itself, scanned on a grid and refined by bisection (as vibration.settling_time).
   */
  function settlingTime(p, ss) {
    var m = p.m, c = p.c, k = p.k, w = p.omega;
    if (c <= 0) {
      return Infinity;
    }
    ss = ss || steadyState(p);
    var A = ss.amplitude;
    if (A === 0) {
      return 0;
    }
    var sigma = c / (2 * m);
    var wn2 = k / m;
    var x0 = A * Math.sin(ss.phase); // transient's initial displacement, m
    var v0 = -w * A * Math.cos(ss.phase); // and velocity, m/s
    var level = SETTLE_TOL * A;
    var reg = regime(m, c, k);
    if (reg === "underdamped") {
      var wd = Math.sqrt(wn2 - sigma * sigma);
      var R = Math.hypot(x0, (v0 + sigma * x0) / wd);
      return Math.max(0, Math.log(R / level) / sigma);
    }
    var tau;
    if (reg === "overdamped") {
      var mu = Math.sqrt(sigma * sigma - wn2);
      tau = (sigma + mu) / wn2;
    } else {
      tau = 1 / sigma;
    }
    var bound = Math.abs(x0) + Math.abs(v0 + sigma * x0) * tau + Math.abs(x0) * sigma * tau;
    var tHi = tau * (Math.max(0, Math.log(Math.max(bound, level) / level)) + 3);
    var n = SCAN_POINTS;
    var step = tHi / (n - 1);
    var last = -1;
    for (var i = 0; i < n; i++) {
      var ti = i === n - 1 ? tHi : i * step;
      if (Math.abs(freeX(m, c, k, x0, v0, ti)) > level) {
        last = i;
      }
    }
    if (last < 0) {
      return 0;
    }
    if (last === n - 1) {
      return tHi;
    }
    var a = last * step;
    var b = last + 1 === n - 1 ? tHi : (last + 1) * step;
    for (var it = 0; it < 200 && b - a > 1e-13; it++) {
      var mid = 0.5 * (a + b);
      if (Math.abs(freeX(m, c, k, x0, v0, mid)) > level) {
        a = mid;
      } else {
        b = mid;
      }
    }
    return 0.5 * (a + b);
  }

  /**
   * Response from rest on linspace(0, t_end, n_points).
   *
   * params: {m (kg), c (N s/m), k (N/m), F0 (N), omega (rad/s), t_end (s), n_points}.
   * Returns {t (s), x (m), v (m/s), peak (m), peak_v (m/s), amplitude (m), velocity_amplitude (m/s),
 * phase (rad), magnification,
   * settling (s), settled (bool), regime, wn (rad/s), zeta, sigma (1/s), wd (rad/s),
   * x_tr0 (m), v_tr0 (m/s)}.
   */
  function compute(params) {
    var p = {
      m: +params.m,
      c: +params.c,
      k: +params.k,
      F0: +params.F0,
      omega: +params.omega,
      t_end: params.t_end === undefined ? 50 : +params.t_end,
      n_points: params.n_points === undefined ? 2001 : Math.round(+params.n_points),
    };
    var ss = steadyState(p);
    var sigma = p.c / (2 * p.m);
    var n = p.n_points;
    var step = p.t_end / (n - 1);
    var t = new Array(n);
    var x = new Array(n);
    var v = new Array(n);
    var x0 = -ss.Q;
    var v0 = -p.omega * ss.P;
    var wn2 = p.k / p.m;
    var peak = 0, peakV = 0;
    for (var i = 0; i < n; i++) {
      var ti = i === n - 1 ? p.t_end : i * step;
      var wt = p.omega * ti;
      var sw = Math.sin(wt), cw = Math.cos(wt);
      var kr = kernel(p.m, p.c, p.k, ti);
      var xi = ss.P * sw + ss.Q * cw + x0 * kr[0] + (v0 + 2 * sigma * x0) * kr[1];
      // free velocity v0 g' - wn^2 x0 g; steady velocity omega (P cos - Q sin)
      var vi = p.omega * (ss.P * cw - ss.Q * sw) + v0 * kr[0] - wn2 * x0 * kr[1];
      t[i] = ti;
      x[i] = xi;
      v[i] = vi;
      if (Math.abs(xi) > peak) {
        peak = Math.abs(xi);
      }
      if (Math.abs(vi) > peakV) {
        peakV = Math.abs(vi);
      }
    }
    var settling = settlingTime(p, ss);
    var q = p.k / p.m - sigma * sigma;
    return {
      t: t,
      x: x,
      v: v,
      peak: peak,
      peak_v: peakV,
      amplitude: ss.amplitude,
      velocity_amplitude: p.omega * ss.amplitude,
      phase: ss.phase,
      magnification: ss.magnification,
      static_deflection: ss.static_deflection,
      settling: settling,
      settled: settling <= p.t_end,
      regime: regime(p.m, p.c, p.k),
      wn: Math.sqrt(p.k / p.m),
      zeta: p.c / (2 * Math.sqrt(p.k * p.m)),
      sigma: sigma,
      wd: q > 0 ? Math.sqrt(q) : 0,
      x_tr0: x0,
      v_tr0: v0,
    };
  }

  /* ---------------------------------------------------------------- drawing (window.VibPlot) */

  var fmt = function (v, d) { return window.VibPlot.fmt(v, d); };

  /** Displacement (which = "x") or velocity ("v") from rest, ± the steady-state amplitude, the settling time. */
  function drawTime(svg, p, r, which, st) {
    var vel = which === "v";
    var ys = vel ? r.v : r.x, amp = vel ? r.velocity_amplitude : r.amplitude;
    var ymax = Math.max(vel ? r.peak_v : r.peak, isFinite(amp) ? amp : 0, 1e-300) * 1.08;
    var series = [];
    if (isFinite(amp) && p.c > 0) {
      [amp, -amp].forEach(function (a) {
        series.push({type: "hline", y: a, color: st.envelope.color, dash: st.envelope.dash, width: 1, cls: "vib-envelope"});
      });
    }
    if (r.settled) {
      series.push({type: "vline", x: r.settling, color: st.settle.color, dash: st.settle.dash, width: 1, cls: "vib-settle"},
        {type: "text", x: r.settling, y: ymax, dy: -5, anchor: r.settling > 0.8 * p.t_end ? "end" : "middle", text: "2 % settled", color: st.settle.color, size: 11,
          cls: "vib-note"});
    }
    series.push({type: "line", x: r.t, y: ys, color: st.response.color, dash: st.response.dash, width: 1.3, cls: "vib-x"});
    window.VibPlot.draw(svg, {
      height: 256, aspect: 0.75, top: 14,
      x: {label: "time t (s)", min: 0, max: p.t_end},
      y: {label: vel ? "velocity v (m/s)" : "displacement x (m)", min: -ymax, max: ymax},
      series: series,
    });
  }

  /** Steady-state magnification against the forcing frequency (logarithmic), ω_n and the operating point. */
  function drawFreq(svg, p, r, wMax, st) {
    var n = 400, ws = [], gs = [];
    var wn = Math.sqrt(p.k / p.m);
    var zeta = p.c / (2 * Math.sqrt(p.k * p.m));
    for (var i = 0; i <= n; i++) {
      ws.push((wMax * i) / n);
    }
    if (zeta < 0.25) { // resolve the resonance peak: 120 more samples within 8 half-bandwidths
      for (var j = -60; j <= 60; j++) {
        var wj = wn * (1 + (8 * zeta * j) / 60);
        if (wj > 0 && wj < wMax) {
          ws.push(wj);
        }
      }
      ws.push(wn * Math.sqrt(1 - 2 * zeta * zeta)); // the true peak of the displacement response
    }
    ws.sort(function (a, b) { return a - b; });
    ws.forEach(function (w) {
      gs.push(steadyState({ m: p.m, c: p.c, k: p.k, F0: p.F0, omega: w }).magnification);
    });
    var gMax = Math.max.apply(null, gs.concat([r.magnification]));
    var gMin = Math.min.apply(null, gs.concat([r.magnification]));
    var d0 = Math.floor(Math.log10(gMin)), d1 = Math.ceil(Math.log10(gMax));
    if (d1 <= d0) {
      d1 = d0 + 1;
    }
    window.VibPlot.draw(svg, {
      height: 270, aspect: 0.8,
      x: {label: "forcing frequency \u03c9 (rad/s)", min: 0, max: wMax},
      y: {label: "magnification |X|/(F_0/k), log", log: true, min: Math.pow(10, d0), max: Math.pow(10, d1)},
      series: [
        {type: "vline", x: r.wn, color: st.natural.color, dash: st.natural.dash, width: 1, cls: "vib-natural"},
        {type: "text", x: r.wn, y: Math.pow(10, d0), dx: 4, dy: -6, text: "\u03c9_n", color: st.natural.color,
          size: 11, cls: "vib-note"},
        {type: "line", x: ws, y: gs, color: st.curve.color, dash: st.curve.dash, width: 1.3, cls: "vib-frf"},
        {type: "points", x: [p.omega], y: [r.magnification], r: 5, color: st.point.color, title: "operating point",
          cls: "vib-op"},
      ],
    });
  }

  function setText(panel, cls, text) {
    var el = panel.querySelector("." + cls);
    if (el) {
      el.textContent = text;
    }
  }

  /** Attach the sliders of one panel (div.vib-panel with data-params JSON). */
  function mount(panel) {
    var data = window.VibPlot.claim(panel, "vibMounted");
    if (!data) { return null; }
    var cfg = data.cfg, styles = data.styles;
    var state = {
      m: cfg.m, c: cfg.c, k: cfg.k, F0: cfg.F0, omega: cfg.omega,
      t_end: cfg.t_end, n_points: cfg.n_points,
    };
    var wIn = panel.querySelector("input.vib-omega");
    var cIn = panel.querySelector("input.vib-logc");
    var reset = panel.querySelector("button.vib-reset");
    var svgT = panel.querySelector("svg.vib-time");
    var svgV = panel.querySelector("svg.vib-vel");
    var svgF = panel.querySelector("svg.vib-freq");
    var cMin = cfg.c_min, cMax = cfg.c_max, nPos = +cIn.max;
    var posToC = function (pos) {
      if (pos <= 0) { return cMin; }
      if (pos >= nPos) { return cMax; }
      return cMin * Math.pow(cMax / cMin, pos / nPos);
    };
    var cToPos = function (c) {
      return Math.round((nPos * Math.log(c / cMin)) / Math.log(cMax / cMin));
    };

    function update() {
      var r = compute(state);
      var hz = state.omega / (2 * Math.PI);
      setText(panel, "vib-omega-out", fmt(state.omega, 4) + " rad/s (" + fmt(hz, 4) + " Hz)");
      setText(panel, "vib-c-out", fmt(state.c, 4) + " N s/m (\u03b6 = " + fmt(r.zeta, 4) + ")");
      setText(panel, "vib-r-wn", fmt(r.wn, 5) + " rad/s (" + fmt(r.wn / (2 * Math.PI), 4) + " Hz)");
      setText(panel, "vib-r-zeta", fmt(r.zeta, 4));
      setText(panel, "vib-r-regime", r.regime);
      setText(panel, "vib-r-ratio", fmt(state.omega / r.wn, 4));
      setText(panel, "vib-r-amp", fmt(r.amplitude, 5) + " m");
      setText(panel, "vib-r-mag", fmt(r.magnification, 4));
      setText(panel, "vib-r-peak", fmt(r.peak, 5) + " m");
      setText(panel, "vib-r-vamp", fmt(r.velocity_amplitude, 5) + " m/s");
      setText(panel, "vib-r-peakv", fmt(r.peak_v, 5) + " m/s");
      setText(panel, "vib-r-settle", fmt(r.settling, 4) + " s");
      setText(panel, "vib-r-settled", r.settled
        ? "yes, after " + fmt(r.settling, 4) + " s of " + fmt(state.t_end, 4) + " s"
        : "no: the transient is still above 2 % at t = " + fmt(state.t_end, 4) + " s");
      panel.vibLast = r;
      draw();
      return r;
    }

    function draw() {
      drawTime(svgT, state, panel.vibLast, "x", styles);
      if (svgV) {
        drawTime(svgV, state, panel.vibLast, "v", styles);
      }
      drawFreq(svgF, state, panel.vibLast, +wIn.max, styles);
    }

    wIn.addEventListener("input", function () {
      state.omega = +wIn.value;
      update();
    });
    cIn.addEventListener("input", function () {
      state.c = posToC(+cIn.value);
      update();
    });
    if (reset) {
      reset.addEventListener("click", function () {
        state.omega = cfg.omega;
        state.c = cfg.c;
        wIn.value = String(cfg.omega);
        cIn.value = String(cToPos(cfg.c));
        update();
      });
    }
    cIn.value = String(cToPos(cfg.c));
    update();
    return { panel: panel, state: state, update: update };
  }

  /** Mount every panel of the page that is not mounted yet. */
  function mountAll(root) {
    var nodes = (root || document).querySelectorAll("div.vib-panel");
    for (var i = 0; i < nodes.length; i++) {
      mount(nodes[i]);
    }
  }

  window.vibrationSliders = {
    compute: compute,
    steadyState: steadyState,
    settlingTime: settlingTime,
    regime: regime,
    mount: mount,
    mountAll: mountAll,
  };
})();
