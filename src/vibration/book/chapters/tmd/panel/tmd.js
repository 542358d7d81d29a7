/*
 * Kernel-free panel of the tuned-mass-damper chapter: sliders for the mass ratio mu, the tuning
 * ratio f, the absorber damping zeta_a and the primary damping zeta_p move the primary's
 * magnification curve |X_p| / (F0/k_p) against r = w / w_p, with the curve without absorber,
 * Den Hartog's fixed points P and Q (undamped primary), the peak and the three rules' tunings.
 * Dimensionless groups as in vibration.physics.tmd; zeta_a = c_a / (2 m_a w_a) (absorber's own
 * frequency). No libraries, no network: the plot is drawn by the book's helper window.VibPlot
 * (presentation/assets/plot.js), in the styles and legend words passed from Python. The formulas are those of
 * vibration.physics.tmd:
 *
 *   H(r) = N / D,  N = f^2 - r^2 + 2i zeta_a f r,
 *                  D = (1 - r^2 + 2i zeta_p r) N - mu r^2 (f^2 + 2i zeta_a f r)   (tmd_magnification);
 *   fixed points: (2 + mu) r^4 - 2 (1 + f^2 (1 + mu)) r^2 + 2 f^2 = 0, height |1 / (1 - (1 + mu) r^2)|;
 *   Den Hartog: f = 1/(1+mu), zeta_a = sqrt(3 mu / (8 (1+mu)));
 *   H-infinity (Nishihara and Asami 2002), s = sqrt(4 + 3 mu), q = 64 + 80 mu + 27 mu^2:
 *     f = 2/(1+mu) sqrt(2 (16 + 23 mu + 9 mu^2 + 2 (2+mu) s) / (3 q)), zeta_a = sqrt((8 + 9 mu - 4 s)/(1+mu)) / 4,
 *     1/peak^2 = mu (1024 + 2880 mu + 2592 mu^2 + 729 mu^3 + 128 s^3) / q^2;
 *   H2 (Warburton 1982): f = sqrt(1 + mu/2)/(1+mu), zeta_a = sqrt(mu (1 + 3 mu/4) / (4 (1+mu)(1+mu/2))).
 *
 * The peak max_r |H| (tmd_peak in Python, exact through the stationary polynomial) is found here on a
 * dense grid with a golden-section refinement of every local maximum.
 *
 * window.vibrationTMD = {magnification, bare, fixedPoints, denHartog, hinf, h2, peak, compute, mount}.
 */
(function () {
  "use strict";
  if (window.vibrationTMD) {
    return;
  }

  /* ---------------------------------------------------------------- physics */

  /** |H(r)|^2 in the factored form, complex products written out. */
  function mag2(mu, f, za, zp, r) {
    var nr = f * f - r * r; // N = nr + i ni
    var ni = 2 * za * f * r;
    var ar = 1 - r * r; // primary factor a = ar + i ai
    var ai = 2 * zp * r;
    var br = mu * r * r * f * f; // coupling b = mu r^2 (f^2 + 2i za f r)
    var bi = mu * r * r * ni;
    var dr = ar * nr - ai * ni - br; // D = a N - b
    var di = ar * ni + ai * nr - bi;
    return (nr * nr + ni * ni) / (dr * dr + di * di);
  }

  /** |X_p| / (F0/k_p) at the frequency ratio r (Infinity at an undamped resonance). */
  function magnification(mu, f, za, r, zp) {
    zp = zp || 0;
    return Math.sqrt(mag2(mu, f, za, zp, r));
  }

  /** The primary without absorber: 1 / |1 - r^2 + 2i zeta_p r|. */
  function bare(r, zp) {
    return 1 / Math.hypot((1 - r) * (1 + r), 2 * (zp || 0) * r);
  }

  /** Den Hartog's fixed points {r: [rP, rQ], h: [hP, hQ]} of the undamped primary. */
  function fixedPoints(mu, f) {
    var a = 2 + mu, b = -2 * (1 + f * f * (1 + mu)), c = 2 * f * f;
    var disc = Math.sqrt(b * b - 4 * a * c);
    var big = (-b + disc) / (2 * a);
    var small = c / (a * big); // product of the roots, no cancellation
    var r = [Math.sqrt(small), Math.sqrt(big)];
    return {
      r: r,
      h: r.map(function (x) { return Math.abs(1 / (1 - (1 + mu) * x * x)); }),
    };
  }

  function denHartog(mu) {
    return { f: 1 / (1 + mu), zeta_a: Math.sqrt((3 * mu) / (8 * (1 + mu))) };
  }

  function hinf(mu) {
    var s = Math.sqrt(4 + 3 * mu);
    var q = 64 + 80 * mu + 27 * mu * mu;
    var f = (2 / (1 + mu)) * Math.sqrt((2 * (16 + 23 * mu + 9 * mu * mu + 2 * (2 + mu) * s)) / (3 * q));
    var za = 0.25 * Math.sqrt((8 + 9 * mu - 4 * s) / (1 + mu));
    var inv2 = (mu * (1024 + mu * (2880 + mu * (2592 + 729 * mu)) + 128 * s * s * s)) / (q * q);
    return { f: f, zeta_a: za, peak: 1 / Math.sqrt(inv2) };
  }

  function h2(mu) {
    return {
      f: Math.sqrt(1 + mu / 2) / (1 + mu),
      zeta_a: Math.sqrt((mu * (1 + 0.75 * mu)) / (4 * (1 + mu) * (1 + mu / 2))),
    };
  }

  /** Largest of g on [a, b] by golden section (g unimodal there), to |b - a| < 1e-13 (1 + b). */
  function golden(g, a, b) {
    var k = (Math.sqrt(5) - 1) / 2;
    var x1 = b - k * (b - a), x2 = a + k * (b - a);
    var g1 = g(x1), g2 = g(x2);
    for (var i = 0; i < 200 && b - a > 1e-13 * (1 + b); i++) {
      if (g1 >= g2) {
        b = x2; x2 = x1; g2 = g1;
        x1 = b - k * (b - a); g1 = g(x1);
      } else {
        a = x1; x1 = x2; g1 = g2;
        x2 = a + k * (b - a); g2 = g(x2);
      }
    }
    var xm = 0.5 * (a + b);
    var best = { r: xm, g: g(xm) };
    [a, b, x1, x2].forEach(function (x) {
      var v = g(x);
      if (v > best.g) { best = { r: x, g: v }; }
    });
    return best;
  }

  /** {peak, r}: max over r >= 0 of |H| (Infinity when both dampings are zero). */
  function peak(mu, f, za, zp) {
    zp = zp || 0;
    if (za === 0 && zp === 0) {
      return { peak: Infinity, r: NaN };
    }
    // the upper undamped coupled frequency bounds every resonant peak
    var bb = 1 + f * f * (1 + mu);
    var rHi = Math.sqrt((bb + Math.sqrt(bb * bb - 4 * f * f)) / 2);
    var R = 1.5 * rHi + 0.5, n = 6000;
    var g = function (r) { return mag2(mu, f, za, zp, r); };
    var gs = [];
    for (var i = 0; i <= n; i++) { gs.push(g((R * i) / n)); }
    var best = { r: 0, g: gs[0] };
    for (var j = 0; j <= n; j++) {
      var left = j > 0 ? gs[j - 1] : -Infinity, right = j < n ? gs[j + 1] : -Infinity;
      if (gs[j] >= left && gs[j] >= right) {
        var cand = golden(g, (R * Math.max(j - 1, 0)) / n, (R * Math.min(j + 1, n)) / n);
        if (cand.g > best.g) { best = cand; }
      }
    }
    return { peak: Math.sqrt(best.g), r: best.r };
  }

  /** Everything the panel shows: params {mu, f, zeta_a, zeta_p}. */
  function compute(params) {
    var mu = +params.mu, f = +params.f, za = +params.zeta_a, zp = +params.zeta_p || 0;
    var pk = peak(mu, f, za, zp);
    var rules = { "Den Hartog": denHartog(mu), "H\u221e": hinf(mu), H2: h2(mu) };
    Object.keys(rules).forEach(function (name) {
      var t = rules[name];
      t.peak0 = name === "H\u221e" ? t.peak : peak(mu, t.f, t.zeta_a, 0).peak;
      t.peak = peak(mu, t.f, t.zeta_a, zp).peak;
    });
    var barePeak = zp >= Math.SQRT1_2 ? 1 : zp === 0 ? Infinity : 1 / (2 * zp * Math.sqrt(1 - zp * zp));
    return { peak: pk.peak, r_peak: pk.r, fixed: fixedPoints(mu, f), rules: rules, bare_peak: barePeak };
  }

  /* ---------------------------------------------------------------- drawing (window.VibPlot) */

  var fmt = function (v, d) { return window.VibPlot.fmt(v, d); };
  var R0 = 0.4, R1 = 1.6;

  /** Upper limit of the y axis: a nice number above the fixed points of Den Hartog's tuning. */
  function yLimit(mu, fx) {
    var ref = Math.max(2 * Math.sqrt(1 + 2 / mu), 1.15 * Math.max(fx.h[0], fx.h[1]));
    var step = window.VibPlot.niceStep(ref, 5);
    return Math.ceil(ref / step) * step;
  }

  function draw(svg, s, res, st) {
    var grid = [];
    for (var i = 0; i <= 1200; i++) { grid.push(R0 + ((R1 - R0) * i) / 1200); }
    function withPoints(extra) {  // the grid plus the points a curve must pass through exactly
      var rs = grid.concat(extra.filter(function (r) { return r > R0 && r < R1; }));
      return rs.sort(function (a, b) { return a - b; });
    }
    var rs = withPoints([res.fixed.r[0], res.fixed.r[1], res.r_peak]);
    var rb = withPoints([1]);
    var opt = hinf(s.mu); // drawn dashed over the sliders' curve, which it equals at an H\u221e start
    var line = function (style, width, x, y, cls) {
      return {type: "line", x: x, y: y, color: style.color, dash: style.dash, width: width, label: style.label, cls: cls};
    };
    var series = [
      line(st.bare, 1.2, rb, rb.map(function (r) { return bare(r, s.zeta_p); }), "vtm-bare"),
      line(st.curve, 2, rs, rs.map(function (r) { return magnification(s.mu, s.f, s.zeta_a, r, s.zeta_p); }), "vtm-curve"),
      line(st.opt, 1.4, grid, grid.map(function (r) { return magnification(s.mu, opt.f, opt.zeta_a, r, s.zeta_p); }),
        "vtm-opt"),
      {type: "points", x: res.fixed.r, y: res.fixed.h, r: 4.5, color: st.fixed.color, label: st.fixed.label,
        cls: "vtm-fixed"},
      {type: "points", x: isFinite(res.peak) ? [res.r_peak] : [], y: isFinite(res.peak) ? [res.peak] : [], r: 4,
        color: st.peak.color, label: st.peak.label, cls: "vtm-peak"},
    ];
    ["P", "Q"].forEach(function (name, j) {
      series.push({type: "text", x: res.fixed.r[j], y: res.fixed.h[j], text: name, dx: j === 0 ? -8 : 8, dy: -8,
        anchor: j === 0 ? "end" : "start", weight: 600, cls: "vtm-fixed-label"});
    });
    window.VibPlot.draw(svg, {
      height: 290, aspect: 0.8,
      x: {label: "frequency ratio r = \u03c9/\u03c9_p", min: R0, max: R1},
      y: {label: "|X_p| / (F_0/k_p)", min: 0, max: yLimit(s.mu, res.fixed)},
      series: series,
    });
  }

  function text(panel, cls, v) {
    var el = panel.querySelector("." + cls);
    if (el) { el.textContent = v; }
  }

  /** Attach one panel (div.vtm-panel with data-params JSON). */
  function mount(panel) {
    var data = window.VibPlot.claim(panel, "vtmMounted");
    if (!data) { return null; }
    var cfg = data.cfg, styles = data.styles;
    var inputs = {
      mu: panel.querySelector("input.vtm-mu"),
      f: panel.querySelector("input.vtm-f"),
      zeta_a: panel.querySelector("input.vtm-za"),
      zeta_p: panel.querySelector("input.vtm-zp"),
    };
    var logs = { mu: true, f: false, zeta_a: true, zeta_p: false };
    var state = { mu: cfg.mu, f: cfg.f, zeta_a: cfg.zeta_a, zeta_p: cfg.zeta_p };
    var svg = panel.querySelector("svg.vtm-plot");
    function read(name) {
      var v = +inputs[name].value;
      return logs[name] ? Math.pow(10, v) : v;
    }
    function write(name, v) {
      var lo = logs[name] ? Math.pow(10, +inputs[name].min) : +inputs[name].min;
      var hi = logs[name] ? Math.pow(10, +inputs[name].max) : +inputs[name].max;
      state[name] = Math.min(Math.max(v, lo), hi);
      inputs[name].value = String(logs[name] ? Math.log10(state[name]) : state[name]);
    }
    function update() {
      var res = compute(state);
      text(panel, "vtm-mu-out", fmt(state.mu, 3));
      text(panel, "vtm-f-out", fmt(state.f, 4));
      panel.querySelector(".vtm-za-out").innerHTML = fmt(state.zeta_a, 3) + " (\u03b6\u2032<sub>a</sub> = f \u03b6<sub>a</sub> = " +
        fmt(state.f * state.zeta_a, 3) + ")";
      text(panel, "vtm-zp-out", fmt(state.zeta_p, 3));
      text(panel, "vtm-r-peak", fmt(res.peak, 4) + (isFinite(res.peak) ? " at r = " + fmt(res.r_peak, 4) : ""));
      text(panel, "vtm-r-bare", fmt(res.bare_peak, 4));
      text(panel, "vtm-r-p", "r = " + fmt(res.fixed.r[0], 4) + ", height " + fmt(res.fixed.h[0], 4));
      text(panel, "vtm-r-q", "r = " + fmt(res.fixed.r[1], 4) + ", height " + fmt(res.fixed.h[1], 4));
      [["Den Hartog", "dh"], ["H\u221e", "hinf"], ["H2", "h2"]].forEach(function (e) {
        var t = res.rules[e[0]];
        text(panel, "vtm-" + e[1] + "-f", fmt(t.f, 4));
        text(panel, "vtm-" + e[1] + "-za", fmt(t.zeta_a, 4));
        text(panel, "vtm-" + e[1] + "-p0", fmt(t.peak0, 5));
        text(panel, "vtm-" + e[1] + "-p", fmt(t.peak, 5));
      });
      draw(svg, state, res, styles);
      return res;
    }
    Object.keys(inputs).forEach(function (name) {
      inputs[name].addEventListener("input", function () { state[name] = read(name); update(); });
    });
    Array.prototype.forEach.call(panel.querySelectorAll("button.vtm-rule"), function (btn) {
      btn.addEventListener("click", function () {
        var t = { dh: denHartog, hinf: hinf, h2: h2 }[btn.dataset.rule](state.mu);
        write("f", t.f);
        write("zeta_a", t.zeta_a);
        update();
      });
    });
    update();
    return { update: update, state: state };
  }

  window.vibrationTMD = {magnification: magnification, bare: bare, fixedPoints: fixedPoints, denHartog: denHartog,
    hinf: hinf, h2: h2, peak: peak, compute: compute, mount: mount};
})();
