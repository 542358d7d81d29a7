/* Kernel-free harmonic-balance panel of the Duffing chapter (vibration.book.chapters.duffing.panel).
   The same closed forms as vibration.physics.duffing: the amplitude cubic (hbAmplitudes), the
   amplitude-parametrised response curve (responseCurve), its peak and folds. No network, no library: the plot
   is drawn by the book's helper window.VibPlot (presentation/assets/plot.js), loaded before this script. */
(function () {
  "use strict";
  if (window.vibrationDuffing) { return; }

  function cubicRealRoots(b, c1, d) {
    // real roots of y^3 + b y^2 + c1 y + d: closed form, then three Newton steps (as in Python)
    const p = c1 - b * b / 3, q = 2 * b * b * b / 27 - b * c1 / 3 + d;
    const disc = (q / 2) * (q / 2) + (p / 3) * (p / 3) * (p / 3);
    const shift = -b / 3;
    let roots;
    if (disc < 0 && p < 0) {
      const r = 2 * Math.sqrt(-p / 3);
      const arg = Math.max(-1, Math.min(1, 3 * q / (p * r)));
      const phi = Math.acos(arg) / 3;
      roots = [0, 1, 2].map(j => r * Math.cos(phi - 2 * Math.PI * j / 3) + shift);
    } else {
      const s = Math.sqrt(Math.max(disc, 0));
      const u = -Math.sign(q || 1) * (Math.abs(q) / 2 + s);
      const a = Math.cbrt(u);
      roots = [(a !== 0 ? a - p / (3 * a) : 0) + shift];
    }
    return roots.map(y => {
      for (let i = 0; i < 3; i++) {
        const f = ((y + b) * y + c1) * y + d, fp = (3 * y + 2 * b) * y + c1;
        if (fp === 0 || !isFinite(f)) { break; }
        const st = f / fp;
        if (!isFinite(st)) { break; }
        y -= st;
      }
      return y;
    });
  }

  function hbAmplitudes(p, omega) {
    // [[A (m), stable], ...] ascending, as vibration.physics.duffing.hb_amplitudes
    const s = p.k - p.m * omega * omega, cw2 = (p.c * omega) * (p.c * omega), kap = 0.75 * p.k3;
    if (p.F0 === 0) { return [[0, true]]; }
    if (kap === 0) { const den = s * s + cw2; return den > 0 ? [[p.F0 / Math.sqrt(den), true]] : []; }
    const out = [];
    for (const y of cubicRealRoots(2 * s, s * s + cw2, -kap * p.F0 * p.F0)) {
      const z = y / kap;
      if (!(z > 0 && isFinite(z))) { continue; }
      out.push([Math.sqrt(z), (s + y) * (s + 3 * y) + cw2 > 0]);
    }
    out.sort((u, v) => u[0] - v[0]);
    const uniq = [];
    for (const r of out) {
      if (uniq.length && Math.abs(r[0] - uniq[uniq.length - 1][0]) <= 1e-12 * r[0]) { continue; }
      uniq.push(r);
    }
    return uniq;
  }

  function peak(p) {
    // [A_peak (m), omega_peak (rad/s)] where the two branches meet, or [NaN, NaN]
    const m = p.m, c = p.c, k = p.k, kap = 0.75 * p.k3, F0 = p.F0;
    const qa = c * c * kap / m, qb = c * c * k / m - c * c * c * c / (4 * m * m), qc = -F0 * F0;
    let zs = [];
    if (qa === 0) { if (qb > 0) { zs = [-qc / qb]; } } else {
      const disc = qb * qb - 4 * qa * qc;
      if (disc >= 0) {
        const sq = Math.sqrt(disc);
        const r1 = qb !== 0 ? (-qb - Math.sign(qb) * sq) / (2 * qa) : sq / (2 * Math.abs(qa));
        const r2 = r1 !== 0 ? qc / (qa * r1) : NaN;
        zs = [r1, r2].filter(z => z > 0 && isFinite(z)).sort((a, b) => a - b);
      }
    }
    for (const z of zs) {
      const w2 = (k + kap * z - c * c / (2 * m)) / m;
      if (w2 > 0) { return [Math.sqrt(z), Math.sqrt(w2)]; }
    }
    return [NaN, NaN];
  }

  function branch(p, z, sign) {
    // omega^2 on branch sign (-1 low, +1 high) at A^2 = z, and d(omega^2)/dz; NaN where absent
    const m = p.m, c = p.c, kap = 0.75 * p.k3, kz = p.k + kap * z;
    const B = 2 * m * kz - c * c;
    const D = c * c * c * c - 4 * m * c * c * kz + 4 * m * m * p.F0 * p.F0 / z;
    if (D < 0) { return [NaN, NaN]; }
    const sq = Math.sqrt(D), dD = -4 * m * c * c * kap - 4 * m * m * p.F0 * p.F0 / (z * z);
    return [(B + sign * sq) / (2 * m * m), (2 * m * kap + sign * dD / (2 * sq)) / (2 * m * m)];
  }

  function folds(p) {
    // {omega_low, omega_high, amplitude_low, amplitude_high} (NaN when single-valued), as Python's folds()
    const [ap] = peak(p);
    const kap = 0.75 * p.k3;
    const none = {omega_low: NaN, omega_high: NaN, amplitude_low: NaN, amplitude_high: NaN};
    if (kap === 0 || !isFinite(ap)) { return none; }
    const found = [];
    const n = 4000, zTop = ap * ap, zLow = zTop * 1e-8;
    for (const sign of [-1, 1]) {
      let zPrev = zLow, gPrev = branch(p, zPrev, sign)[1];
      for (let i = 1; i <= n; i++) {
        const z = zLow * Math.pow(zTop / zLow, i / n) * (i === n ? (1 - 1e-12) : 1);
        const g = branch(p, z, sign)[1];
        if (isFinite(g) && isFinite(gPrev) && (g > 0) !== (gPrev > 0)) {
          let lo = zPrev, hi = z, glo = gPrev;
          for (let it = 0; it < 200 && hi - lo > 1e-15 * hi; it++) {
            const mid = 0.5 * (lo + hi), gm = branch(p, mid, sign)[1];
            if ((gm > 0) === (glo > 0)) { lo = mid; glo = gm; } else { hi = mid; }
          }
          const zf = 0.5 * (lo + hi), w2 = branch(p, zf, sign)[0];
          if (w2 > 0) { found.push([Math.sqrt(w2), Math.sqrt(zf)]); }
        }
        zPrev = z; gPrev = g;
      }
    }
    found.sort((u, v) => u[0] - v[0]);
    if (found.length < 2) { return none; }
    const lo = found[0], hi = found[found.length - 1];
    return {omega_low: lo[0], omega_high: hi[0], amplitude_low: lo[1], amplitude_high: hi[1]};
  }

  function responseCurve(p, n) {
    // {omega, A, stable} along the curve, as response_curve(): low branch up to the peak, high branch down
    const [ap, wp] = peak(p);
    let aTop = ap;
    if (!(isFinite(ap) && wp > 0)) {
      aTop = p.k3 < 0 ? 1.5 * Math.sqrt(-p.k / p.k3) : 3 * p.F0 / p.k;
    }
    const lows = hbAmplitudes(p, p.omega_max).map(r => r[0]);
    const aLow = Math.min(lows.length ? Math.min(...lows) : 0.001 * aTop, 0.999 * aTop);
    const W = [], A = [];
    for (const [sign, order] of [[-1, 1], [1, -1]]) {
      for (let j = 0; j < n; j++) {
        const i = order > 0 ? j : n - 1 - j;
        const s = 0.5 * (1 - Math.cos(Math.PI * i / (n - 1)));
        const a = aLow + (aTop - aLow) * s, z = a * a;
        const m = p.m, c = p.c, kz = p.k + 0.75 * p.k3 * z;
        const B = 2 * m * kz - c * c;
        const D = c * c * c * c - 4 * m * c * c * kz + 4 * m * m * p.F0 * p.F0 / z;
        const w2 = (B + sign * Math.sqrt(Math.max(D, 0))) / (2 * m * m);
        if (w2 > 0 && D >= 0 && Math.sqrt(w2) <= p.omega_max) { W.push(w2); A.push(a); }
      }
    }
    const omega = W.map(Math.sqrt);
    const stable = W.map((w2, i) => {
      const s = p.k - p.m * w2, y = 0.75 * p.k3 * A[i] * A[i];
      return (s + y) * (s + 3 * y) + p.c * p.c * w2 > 0;
    });
    return {omega: omega, A: A, stable: stable};
  }

  function backbone(p, a) {
    const w2 = (p.k + 0.75 * p.k3 * a * a) / p.m;
    return w2 >= 0 ? Math.sqrt(w2) : NaN;
  }

  /* The curve (stable solid, unstable dashed), the backbone and the folds, drawn by window.VibPlot in the
     book's colour of the hardening or softening spring (data-styles, from presentation.style.CASES). */
  function draw(panel, p) {
    const P = window.VibPlot, fmt = P.fmt;
    const st = JSON.parse(panel.getAttribute("data-styles"));
    const cur = responseCurve(p, 700);
    const aMax = Math.max(...cur.A, 1e-12) * 1.12;
    const spring = p.k3 >= 0 ? st.hardening : st.softening;
    const series = [];
    const bw = [], ba = [];
    for (let i = 0; i <= 200; i++) {
      const a = aMax * i / 200, w = backbone(p, a);
      if (isFinite(w) && w <= p.omega_max) { bw.push(w); ba.push(a); }
    }
    series.push({type: "line", x: bw, y: ba, color: st.backbone.color, dash: st.backbone.dash, width: 1,
      label: st.backbone.label, cls: "vd-backbone"});
    // the curve, split where its stability changes (each piece starts at the last point of the one before)
    const named = {true: false, false: false};
    let xs = [], ys = [], stable = null;
    const flush = () => {
      if (xs.length > 1) {
        const look = stable ? st.stable : st.unstable;
        series.push({type: "line", x: xs, y: ys, color: spring.color, dash: look.dash, width: stable ? 2 : 1.4,
          label: named[stable] ? "" : spring.label + ", " + look.label, cls: stable ? "vd-stable" : "vd-unstable"});
        named[stable] = true;
      }
    };
    for (let i = 0; i < cur.omega.length; i++) {
      if (stable !== null && cur.stable[i] !== stable) {
        xs.push(cur.omega[i]); ys.push(cur.A[i]); flush();
        xs = [xs[xs.length - 1]]; ys = [ys[ys.length - 1]];
      }
      stable = cur.stable[i]; xs.push(cur.omega[i]); ys.push(cur.A[i]);
    }
    flush();
    const f = folds(p);
    const fw = [f.omega_low, f.omega_high].filter(isFinite), fa = [f.amplitude_low, f.amplitude_high].filter(isFinite);
    series.push({type: "points", x: fw, y: fa, r: 4, color: "#fff", stroke: st.folds.color, label: fw.length ?
      st.folds.label : "", cls: "vd-fold"});
    P.draw(panel.querySelector("svg.vd-plot"), {
      height: 270, aspect: 0.8,
      x: {label: "forcing frequency ω (rad/s)", min: 0, max: p.omega_max},
      y: {label: "amplitude A (m)", min: 0, max: aMax},
      series: series,
    });
    const [ap, wp] = peak(p);
    panel.querySelector("p.vd-readout").textContent = (isFinite(f.omega_low)
      ? `Folds at ${fmt(f.omega_low, 5)} and ${fmt(f.omega_high, 5)} rad/s: two stable amplitudes coexist between them. `
      : "No folds: one amplitude at every frequency. ") +
      (isFinite(ap) ? `Peak ${fmt(ap, 4)} m at ${fmt(wp, 4)} rad/s.` : "The curve does not close (softening spring beyond its barrier).");
    panel.querySelector("output.vd-k3-out").textContent = `${fmt(p.k3, 3)} N/m³`;
    panel.querySelector("output.vd-F0-out").textContent = `${fmt(p.F0, 3)} N`;
  }

  function mount(panel) {
    const p = JSON.parse(panel.getAttribute("data-params"));
    const k3 = panel.querySelector("input.vd-k3"), F0 = panel.querySelector("input.vd-F0");
    const update = () => { p.k3 = parseFloat(k3.value); p.F0 = parseFloat(F0.value); draw(panel, p); };
    k3.addEventListener("input", update);
    F0.addEventListener("input", update);
    update();
  }

  window.vibrationDuffing = {hbAmplitudes: hbAmplitudes, responseCurve: responseCurve, peak: peak, folds: folds,
    backbone: backbone, mount: mount};
})();
