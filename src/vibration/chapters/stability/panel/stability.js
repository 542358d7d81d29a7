/*
 * Kernel-free panel of the stability chapter: damping ratio (log) and base frequency sliders
 * moving the transmissibility curve, the step response and the poles together.
 * SI units (kg, N/m, rad/s, s). No libraries, no network. The closed forms are those of
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

  /* ---------------------------------------------------------------- drawing */

  function fmt(v, d) {
    if (!isFinite(v)) {
      return v > 0 ? "\u221e" : "\u2013";
    }
    var t = Number(v).toPrecision(d || 4);
    if (t.indexOf("e") < 0 && t.indexOf(".") >= 0) {
      t = t.replace(/0+$/, "").replace(/\.$/, "");
    }
    return t.replace("-", "\u2212");
  }

  function niceTicks(lo, hi, n) {
    var raw = (hi - lo) / Math.max(1, n);
    var mag = Math.pow(10, Math.floor(Math.log10(raw)));
    var r = raw / mag;
    var st = (r <= 1 ? 1 : r <= 2 ? 2 : r <= 5 ? 5 : 10) * mag;
    var out = [];
    for (var v = Math.ceil(lo / st - 1e-9) * st; v <= hi + 1e-9 * st; v += st) {
      out.push(Math.abs(v) < 1e-12 * st ? 0 : v);
    }
    return out;
  }

  var PAD = { l: 50, r: 10, t: 12, b: 38 };

  function axes(w, h, xt, yt, sx, sy, xl, yl, yfmt) {
    var s = [];
    var x0 = PAD.l, x1 = w - PAD.r, y0 = h - PAD.b, y1 = PAD.t;
    s.push('<rect class="vst-area" x="' + x0 + '" y="' + y1 + '" width="' + (x1 - x0) + '" height="' + (y0 - y1) + '"></rect>');
    xt.forEach(function (v) {
      var X = sx(v).toFixed(1);
      s.push('<line class="vst-grid" x1="' + X + '" x2="' + X + '" y1="' + y1 + '" y2="' + y0 + '"></line>');
      s.push('<text class="vst-tick" x="' + X + '" y="' + (y0 + 14) + '" text-anchor="middle">' + fmt(v, 3) + "</text>");
    });
    yt.forEach(function (v) {
      var Y = sy(v).toFixed(1);
      s.push('<line class="vst-grid" x1="' + x0 + '" x2="' + x1 + '" y1="' + Y + '" y2="' + Y + '"></line>');
      s.push('<text class="vst-tick" x="' + (x0 - 4) + '" y="' + Y + '" dy="0.32em" text-anchor="end">' +
        (yfmt ? yfmt(v) : fmt(v, 3)) + "</text>");
    });
    s.push('<text class="vst-label" x="' + ((x0 + x1) / 2) + '" y="' + (h - 6) + '" text-anchor="middle">' + xl + "</text>");
    s.push('<text class="vst-label" transform="translate(14,' + ((y0 + y1) / 2) + ') rotate(-90)" text-anchor="middle">' +
      yl + "</text>");
    return s.join("");
  }

  function line(cls, xs, ys, sx, sy) {
    var pts = xs.map(function (x, i) { return sx(x).toFixed(1) + "," + sy(ys[i]).toFixed(1); });
    return '<polyline class="' + cls + '" points="' + pts.join(" ") + '"></polyline>';
  }

  function drawTrans(svg, p, wMax) {
    var W = 420, H = 260;
    var wn = Math.sqrt(p.k / p.m);
    var ws = [], ts = [];
    for (var i = 0; i <= 600; i++) { ws.push((wMax * i) / 600); }
    for (var j = -80; j <= 80; j++) { ws.push(wn * (1 + (Math.max(p.zeta, 0.002) * 6 * j) / 80)); }
    ws = ws.filter(function (w) { return w >= 0 && w <= wMax; }).sort(function (a, b) { return a - b; });
    ws.forEach(function (w) { ts.push(transmissibility(p, w)); });
    var d0 = -2, d1 = 3;
    var sx = function (v) { return PAD.l + (v / wMax) * (W - PAD.l - PAD.r); };
    var sy = function (v) {
      var l = Math.min(Math.max(Math.log10(v), d0 - 0.2), d1 + 0.2);
      return PAD.t + ((d1 - l) / (d1 - d0)) * (H - PAD.t - PAD.b);
    };
    var yt = [0.01, 0.1, 1, 10, 100, 1000];
    var s = [axes(W, H, niceTicks(0, wMax, 5), yt, sx, sy, "base frequency \u03c9 (rad/s)", "|X/Y| (log)",
      function (v) { return String(v); })];
    var Xi = sx(Math.SQRT2 * wn).toFixed(1);
    s.push('<line class="vst-mark" x1="' + Xi + '" x2="' + Xi + '" y1="' + PAD.t + '" y2="' + (H - PAD.b) + '"></line>');
    s.push(line("vst-curve", ws, ts, sx, sy));
    s.push('<circle class="vst-op" cx="' + sx(p.omega).toFixed(1) + '" cy="' + sy(transmissibility(p, p.omega)).toFixed(1) +
      '" r="5"></circle>');
    svg.innerHTML = s.join("");
  }

  function drawStep(svg, p, r) {
    var W = 420, H = 260;
    var tEnd = Math.max((12 * 2 * Math.PI) / r.wn, Math.min(1.2 * r.settling_time, 400 * (2 * Math.PI) / r.wn));
    var n = 1500, ts = [], ys = [];
    var f = oneMinusY(p);
    for (var i = 0; i <= n; i++) {
      var t = (tEnd * i) / n;
      ts.push(t);
      ys.push(1 - f(t));
    }
    var sx = function (v) { return PAD.l + (v / tEnd) * (W - PAD.l - PAD.r); };
    var sy = function (v) { return PAD.t + ((2.05 - v) / 2.1) * (H - PAD.t - PAD.b); };
    var s = [axes(W, H, niceTicks(0, tEnd, 5), [0, 0.5, 1, 1.5, 2], sx, sy, "time t (s)", "k x / F")];
    s.push('<rect class="vst-band" x="' + PAD.l + '" y="' + sy(1 + BAND).toFixed(1) + '" width="' + (W - PAD.l - PAD.r) +
      '" height="' + (sy(1 - BAND) - sy(1 + BAND)).toFixed(1) + '"></rect>');
    s.push(line("vst-curve", ts, ys, sx, sy));
    if (r.settling_time <= tEnd) {
      var X = sx(r.settling_time).toFixed(1);
      s.push('<line class="vst-mark" x1="' + X + '" x2="' + X + '" y1="' + PAD.t + '" y2="' + (H - PAD.b) + '"></line>');
    }
    svg.innerHTML = s.join("");
  }

  function drawPoles(svg, p, r) {
    var W = 260, H = 260;
    var wn = r.wn;
    var pl = r.poles;
    var R = Math.max(1.2 * wn, (-pl[1][0] * 1.1) / 1.75);
    // equal scales on both axes (the plot area is about square): Re s from -1.75 R to 0.25 R, Im s from -R to R
    var sx = function (v) { return PAD.l + ((v + 1.75 * R) / (2 * R)) * (W - PAD.l - PAD.r); };
    var sy = function (v) { return PAD.t + ((R - v) / (2 * R)) * (H - PAD.t - PAD.b); };
    var s = [axes(W, H, niceTicks(-1.75 * R, 0.25 * R, 4), niceTicks(-R, R, 4), sx, sy, "Re s (1/s)", "Im s (1/s)")];
    var circ = [];
    for (var i = 0; i <= 120; i++) {
      var a = (Math.PI * i) / 120 + Math.PI / 2;
      circ.push(sx(wn * Math.cos(a)).toFixed(1) + "," + sy(wn * Math.sin(a)).toFixed(1));
    }
    s.push('<polyline class="vst-circle" points="' + circ.join(" ") + '"></polyline>');
    var X0 = sx(0).toFixed(1);
    s.push('<line class="vst-axis0" x1="' + X0 + '" x2="' + X0 + '" y1="' + PAD.t + '" y2="' + (H - PAD.b) + '"></line>');
    pl.forEach(function (q) {
      var x = sx(q[0]), y = sy(q[1]);
      s.push('<path class="vst-pole" d="M' + (x - 5) + "," + (y - 5) + "L" + (x + 5) + "," + (y + 5) + "M" + (x - 5) + "," +
        (y + 5) + "L" + (x + 5) + "," + (y - 5) + '"></path>');
    });
    svg.innerHTML = s.join("");
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
    if (!panel || panel.dataset.vstMounted) {
      return null;
    }
    panel.dataset.vstMounted = "1";
    var cfg = JSON.parse(panel.dataset.params);
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
      text(panel, "vst-omega-out", fmt(state.omega, 4) + " rad/s (" + fmt(state.omega / r.wn, 3) + " \u03c9n)");
      text(panel, "vst-r-c", fmt(r.c, 4) + " N s/m");
      text(panel, "vst-r-t", fmt(r.T, 4));
      text(panel, "vst-r-poles", poleText(r.poles) + " 1/s");
      text(panel, "vst-r-os", fmt(100 * r.overshoot, 4) + " %");
      text(panel, "vst-r-tr", fmt(r.rise_time, 4) + " s");
      text(panel, "vst-r-ts", fmt(r.settling_time, 4) + " s");
      drawTrans(panel.querySelector("svg.vst-trans"), state, cfg.w_max);
      drawStep(panel.querySelector("svg.vst-step"), state, r);
      drawPoles(panel.querySelector("svg.vst-poles"), state, r);
      return r;
    }
    zIn.addEventListener("input", function () { state.zeta = posToZeta(+zIn.value); update(); });
    wIn.addEventListener("input", function () { state.omega = +wIn.value; update(); });
    update();
    return { update: update, state: state };
  }

  window.vibrationStability = {
    poles: poles,
    transmissibility: transmissibility,
    stepResponse: stepResponse,
    stepMetrics: stepMetrics,
    compute: compute,
    mount: mount,
  };
})();
