/*
 * The book's plotting helper for its kernel-free panels (HTML + JavaScript, no kernel, no library, no
 * network): SVG axes with linear and logarithmic scales, nice ticks, the book's number format, axis labels
 * with subscripts, polylines, markers, bands and reference lines in the book's case styles (colours and
 * dashes come from Python, vibration.book.presentation.panels.case_styles), a legend above the plot area, and
 * redrawing at the container's width (one viewBox unit per CSS pixel, so text keeps its size on a phone).
 *
 * window.VibPlot = {version, fmt, fixed, tickText, niceStep, ticks, logTicks, richText, draw}; loading the
 * script twice is harmless (a newer version replaces an older one, nothing else happens).
 *
 * A panel calls VibPlot.draw(svg, spec) whenever its sliders move:
 *
 *   spec = {
 *     height: 260,                 // px without the legend (its rows add to it); at most aspect * width
 *     aspect: 1,                   // optional
 *     equal: false,                // equal data scales on both axes (the range of one axis widens)
 *     top: 0,                      // px kept free above the plot area (for notes placed there), added to height
 *     x: {label: "t (s)", min, max, log, ticks: 5 | [values] | [{v, label}], grid: true, pad: 0.05,
 *         format: v => text, tickStyle: {size, color, italic}},
 *     y: {...},
 *     series: [                    // in drawing order; every series may carry cls, label (legend), title
 *       {type: "line", x: [], y: [], color, dash, width},
 *       {type: "points", x: [], y: [], marker: "circle" | "cross" | "square", r, color, stroke},
 *       {type: "segments", segs: [[x0, y0, x1, y1], ...], color, dash, width},
 *       {type: "vline", x}, {type: "hline", y}, {type: "band", y0, y1, color, opacity},
 *       {type: "text", x, y, text, dx, dy, anchor, color, size}
 *     ]
 *   }
 *
 * Labels and legend texts take "_" subscripts as the book's tables do: "ω_n (rad/s)" shows n as a
 * subscript. Lines are clipped to the plot area; non-finite values break a line.
 */
(function () {
  "use strict";
  var VERSION = 1;
  if (window.VibPlot && window.VibPlot.version >= VERSION) {
    return;
  }

  var MINUS = "\u2212";
  var SUP = { "-": "\u207b", 0: "\u2070", 1: "\u00b9", 2: "\u00b2", 3: "\u00b3", 4: "\u2074", 5: "\u2075",
    6: "\u2076", 7: "\u2077", 8: "\u2078", 9: "\u2079" };
  var INK = "#1d2733", MUTED = "#5b6673", GRID = "#e3e7ec", FRAME = "#9aa5b1";
  var FONT = { tick: 11, label: 12.5, legend: 11.5, text: 11.5 };
  var MAX_SERIES_POINTS = 200000; // bound on the points drawn per series

  /* ---------------------------------------------------------------- numbers */

  /** Digits of x > 0 rounded to p significant figures, half to even as Python: {d: "ddd", e: exponent}. */
  function roundSig(x, p) {
    var s = x.toExponential(p - 1).split("e");
    var out = { d: s[0].replace(".", ""), e: parseInt(s[1], 10) };
    // toExponential rounds a tie away from zero, Python's format to even: look at the exact expansion
    var full = x.toExponential(100).split("e");
    var fd = full[0].replace(".", "");
    if (fd.charAt(p) === "5" && /^0*$/.test(fd.slice(p + 1)) && +fd.charAt(p - 1) % 2 === 0) {
      out = { d: fd.slice(0, p), e: parseInt(full[1], 10) };
    }
    return out;
  }

  function superscript(n) {
    return String(n).split("").map(function (c) { return SUP[c]; }).join("");
  }

  /**
   * The book's number format, the rules of vibration.book.presentation.tables.fmt: `digits` significant
   * figures as Python's "g" format (fixed notation for exponents -4 to digits - 1), trailing zeros dropped
   * unless `zeros`, a power of ten as ×10ⁿ (never e-notation), a true minus sign everywhere, ∞, and "—"
   * for NaN.
   */
  function fmt(v, digits, zeros) {
    var p = Math.max(1, Math.round(digits === undefined ? 4 : digits));
    v = Number(v);
    if (isNaN(v)) { return "\u2014"; }
    if (!isFinite(v)) { return v > 0 ? "\u221e" : MINUS + "\u221e"; }
    if (v === 0) { return zeros && p > 1 ? "0." + new Array(p).join("0") : "0"; }
    var sign = v < 0 ? MINUS : "";
    var r = roundSig(Math.abs(v), p);
    var d = r.d, e = r.e, text;
    if (e >= -4 && e < p) {
      var intPart, frac;
      if (e >= 0) {
        intPart = d.slice(0, e + 1);
        frac = d.slice(e + 1);
      } else {
        intPart = "0";
        frac = new Array(-e).join("0") + d;
      }
      if (!zeros) { frac = frac.replace(/0+$/, ""); }
      text = frac ? intPart + "." + frac : intPart;
    } else {
      var mant = d.charAt(0), rest = d.slice(1);
      if (!zeros) { rest = rest.replace(/0+$/, ""); }
      if (rest) { mant += "." + rest; }
      var power = "10" + superscript(e);
      text = mant === "1" ? power : mant + "\u00d7" + power;
    }
    return sign + text;
  }

  /** v with `decimals` decimals (a slider's readout), a true minus sign, never "−0". */
  function fixed(v, decimals) {
    var t = Number(v).toFixed(decimals);
    if (/^-0\.?0*$/.test(t)) { t = t.slice(1); }
    return t.replace("-", MINUS);
  }

  /** Label of a tick at v on an axis whose ticks are `step` apart: plain decimals from 0.001 to 10⁵, else ×10ⁿ. */
  function tickText(v, step) {
    var lastDigit = Math.floor(Math.log10(Math.abs(step)) + 1e-9);
    if (v === 0 || Math.abs(v) < 1e-9 * Math.abs(step)) { return lastDigit >= -6 ? fixed(0, Math.max(0, -lastDigit)) : "0"; }
    var a = Math.abs(v);
    if (a >= 1e-3 && a < 1e5 && lastDigit >= -6) {
      return fixed(v, Math.max(0, -lastDigit));
    }
    var digits = Math.max(1, Math.floor(Math.log10(a) + 1e-9) - lastDigit + 1);
    return fmt(v, Math.min(digits, 15));
  }

  /* ---------------------------------------------------------------- ticks */

  /** A round step (1, 2 or 5 times a power of ten) giving about n intervals over span. */
  function niceStep(span, n) {
    var raw = Math.abs(span) / Math.max(1, n);
    if (!(raw > 0) || !isFinite(raw)) { return 1; }
    var mag = Math.pow(10, Math.floor(Math.log10(raw)));
    var r = raw / mag;
    return (r < 1.5 ? 1 : r < 3 ? 2 : r < 7 ? 5 : 10) * mag;
  }

  /** Multiples of a nice step inside [lo, hi] (about n intervals): every one in range, none missing. */
  function ticks(lo, hi, n) {
    if (!(hi > lo)) { return isFinite(lo) ? [lo] : []; }
    var st = niceStep(hi - lo, n || 5), out = [];
    var k0 = Math.ceil(lo / st - 1e-9), k1 = Math.floor(hi / st + 1e-9);
    for (var k = k0; k <= k1 && out.length < 1000; k++) {
      var v = k * st;
      out.push(Math.abs(v) < 1e-12 * st ? 0 : Number(v.toPrecision(12)));
    }
    return out;
  }

  /** Ticks of a logarithmic axis from lo to hi (values > 0): the decades, with 2 and 5 when fewer than three. */
  function logTicks(lo, hi) {
    var d0 = Math.ceil(Math.log10(lo) - 1e-9), d1 = Math.floor(Math.log10(hi) + 1e-9), out = [], d;
    for (d = d0; d <= d1 && out.length < 400; d++) { out.push(Number(Math.pow(10, d).toPrecision(12))); }
    if (out.length >= 3) {
      var every = Math.ceil(out.length / 8); // at most about eight labelled decades
      return out.filter(function (_, i) { return (d1 - d0 - i) % every === 0; });
    }
    out = [];
    for (d = d0 - 1; d <= d1 && out.length < 400; d++) {
      [1, 2, 5].forEach(function (m) {
        var v = Number((m * Math.pow(10, d)).toPrecision(12));
        if (v >= lo * (1 - 1e-9) && v <= hi * (1 + 1e-9)) { out.push(v); }
      });
    }
    return out.length >= 2 ? out : ticks(lo, hi, 3);
  }

  function logTickText(v) {
    var d = Math.round(Math.log10(v));
    if (Math.abs(v / Math.pow(10, d) - 1) < 1e-9) { // a decade
      return d >= -3 && d <= 4 ? fixed(v, Math.max(0, -d)) : "10" + superscript(d);
    }
    return tickText(v, Math.pow(10, Math.floor(Math.log10(v) + 1e-9)));
  }

  /* ---------------------------------------------------------------- SVG */

  /** A new SVG element in parent (the namespace is the parent's: the script names no URL). */
  function el(name, attrs, parent) {
    var e = document.createElementNS(parent.namespaceURI, name);
    for (var a in attrs) {
      if (attrs[a] !== undefined && attrs[a] !== null) { e.setAttribute(a, attrs[a]); }
    }
    parent.appendChild(e);
    return e;
  }

  /** Fill a text element with `label`, "_x" parts as subscripts (as the book's table headers). */
  function richText(node, label) {
    while (node.firstChild) { node.removeChild(node.firstChild); }
    var parts = String(label).split(/_([0-9A-Za-z\u00c0-\u024f\u0370-\u03ff\u221e]+)/);
    var size = parseFloat(node.getAttribute("font-size")) || FONT.label;
    var shift = Math.round(0.3 * size * 10) / 10;
    for (var i = 0; i < parts.length; i++) {
      if (!parts[i]) { continue; }
      if (i % 2 === 0) {
        node.appendChild(document.createTextNode(parts[i]));
      } else {
        el("tspan", { dy: shift, "font-size": (0.78 * size).toFixed(1) }, node).textContent = parts[i];
        // back to the baseline; a zero-width space carries the shift when the subscript ends the label
        el("tspan", { dy: -shift }, node).textContent = i + 1 < parts.length && parts[i + 1] ? "" : "\u200b";
      }
    }
    return node;
  }

  /** Width in px of a label at a font size: measured when the SVG is rendered, estimated otherwise. */
  function measure(svg, label, size) {
    var t = el("text", { x: -1000, y: -1000, "font-size": size, visibility: "hidden" }, svg);
    richText(t, label);
    var w = 0;
    try { w = t.getComputedTextLength(); } catch (err) { w = 0; }
    svg.removeChild(t);
    return w > 0 ? w : 0.6 * size * String(label).replace(/_/g, "").length;
  }

  /* ---------------------------------------------------------------- scales */

  function extent(values, log) {
    var lo = Infinity, hi = -Infinity;
    for (var i = 0; i < values.length; i++) {
      var v = values[i];
      if (isFinite(v) && (!log || v > 0)) {
        if (v < lo) { lo = v; }
        if (v > hi) { hi = v; }
      }
    }
    return [lo, hi];
  }

  /** The axis range [lo, hi] (data values) from the spec or from the data, padded. */
  function axisRange(ax, values) {
    var log = !!ax.log;
    var ext = extent(values, log);
    var lo = ax.min !== undefined ? ax.min : ext[0], hi = ax.max !== undefined ? ax.max : ext[1];
    if (!isFinite(lo) || !isFinite(hi)) { lo = log ? 0.1 : 0; hi = log ? 10 : 1; }
    var f = log ? Math.log10 : function (v) { return v; }, g = log ? function (v) { return Math.pow(10, v); } : f;
    var a = f(lo), b = f(hi);
    if (!(b > a)) { var mid = a; a = mid - (mid !== 0 && !log ? 0.5 * Math.abs(mid) : 0.5); b = 2 * mid - a; }
    var pad = ax.pad !== undefined ? ax.pad : 0.05;
    var span = b - a;
    if (ax.min === undefined) { a -= pad * span; }
    if (ax.max === undefined) { b += pad * span; }
    return [g(a), g(b)];
  }

  function scale(lo, hi, log, p0, p1) {
    var f = log ? Math.log10 : function (v) { return v; };
    var a = f(lo), b = f(hi), k = (p1 - p0) / (b - a);
    var s = function (v) { return p0 + (f(v) - a) * k; };
    s.lo = lo; s.hi = hi; s.log = log;
    return s;
  }

  /* ---------------------------------------------------------------- drawing */

  var uid = 0;

  function legendEntries(spec) {
    return spec.series.filter(function (s) { return s.label; });
  }

  /** Legend rows above the plot area: [{x, entry}] per row, wrapped at the SVG's width. */
  function layoutLegend(svg, entries, W) {
    var rows = [[]], x = 4, sample = 24;
    entries.forEach(function (s) {
      var w = sample + 5 + measure(svg, s.label, FONT.legend) + 14;
      if (x + w > W - 2 && rows[rows.length - 1].length) { rows.push([]); x = 4; }
      rows[rows.length - 1].push({ x: x, entry: s });
      x += w;
    });
    return entries.length ? rows : [];
  }

  function drawSample(g, s, x, y) {
    if (s.type === "points") {
      marker(g, s, x + 12, y);
    } else if (s.type === "band") {
      el("rect", { x: x, y: y - 5, width: 24, height: 10, fill: s.color || "#d9dde2", "fill-opacity": s.opacity || 0.7 }, g);
    } else {
      el("line", { x1: x, x2: x + 24, y1: y, y2: y, stroke: s.color || INK, "stroke-width": s.width || 1.6,
        "stroke-dasharray": s.dash || null }, g);
    }
  }

  function marker(g, s, x, y) {
    var r = s.r || 4, attrs;
    var m = s.marker || "circle";
    if (m === "cross") {
      attrs = { d: "M" + (x - r) + "," + (y - r) + "L" + (x + r) + "," + (y + r) + "M" + (x - r) + "," + (y + r) +
        "L" + (x + r) + "," + (y - r), stroke: s.color || INK, "stroke-width": s.width || 2, fill: "none" };
      return el("path", attrs, g);
    }
    var common = { fill: s.color || INK, stroke: s.stroke || "#fff", "stroke-width": s.stroke === "none" ? 0 : 1.2 };
    if (m === "square") {
      attrs = { x: (x - r).toFixed(2), y: (y - r).toFixed(2), width: 2 * r, height: 2 * r };
      for (var k in common) { attrs[k] = common[k]; }
      return el("rect", attrs, g);
    }
    attrs = { cx: x.toFixed(2), cy: y.toFixed(2), r: r };
    for (var c in common) { attrs[c] = common[c]; }
    return el("circle", attrs, g);
  }

  /** Pixel coordinates of a line's points, split where a value is not finite (or not positive on a log axis). */
  function pieces(xs, ys, sx, sy, box) {
    var out = [], cur = [], n = Math.min(xs.length, ys.length, MAX_SERIES_POINTS);
    var lim = 20 * (box.b - box.t + box.r - box.l); // far outside the area: clipped, nearly the true slope
    function clamp(p, lo, hi) { return Math.max(lo - lim, Math.min(hi + lim, p)); }
    for (var i = 0; i < n; i++) {
      var X = sx(xs[i]), Y = sy(ys[i]); // ±Infinity (or 0 on a log axis) leaves the area; NaN breaks the line
      if (isNaN(X) || isNaN(Y)) {
        if (cur.length > 1) { out.push(cur); }
        cur = [];
        continue;
      }
      cur.push(clamp(X, box.l, box.r).toFixed(2) + "," + clamp(Y, box.t, box.b).toFixed(2));
    }
    if (cur.length > 1) { out.push(cur); }
    return out;
  }

  function lineAttrs(s, cls) {
    return { "class": cls || null, fill: "none", stroke: s.color || INK, "stroke-width": s.width || 1.6,
      "stroke-dasharray": s.dash || null, "stroke-linejoin": "round" };
  }

  function drawSeries(gClip, gFree, s, sx, sy, box) {
    var i, a;
    if (s.type === "line") {
      pieces(s.x, s.y, sx, sy, box).forEach(function (pts) {
        a = lineAttrs(s, s.cls);
        a.points = pts.join(" ");
        el("polyline", a, gClip);
      });
    } else if (s.type === "segments") {
      s.segs.forEach(function (q) {
        a = lineAttrs(s, s.cls);
        a.x1 = sx(q[0]).toFixed(2); a.y1 = sy(q[1]).toFixed(2); a.x2 = sx(q[2]).toFixed(2); a.y2 = sy(q[3]).toFixed(2);
        el("line", a, gClip);
      });
    } else if (s.type === "vline" || s.type === "hline") {
      a = lineAttrs({ color: s.color || MUTED, width: s.width || 1, dash: s.dash }, s.cls);
      if (s.type === "vline") {
        var X = sx(s.x);
        if (!(X >= box.l - 0.5 && X <= box.r + 0.5)) { return; }
        a.x1 = a.x2 = X.toFixed(2); a.y1 = box.t; a.y2 = box.b;
      } else {
        var Y = sy(s.y);
        if (!(Y >= box.t - 0.5 && Y <= box.b + 0.5)) { return; }
        a.y1 = a.y2 = Y.toFixed(2); a.x1 = box.l; a.x2 = box.r;
      }
      el("line", a, gClip);
    } else if (s.type === "band") {
      var y0 = sy(s.y0), y1 = sy(s.y1);
      el("rect", { "class": s.cls || null, x: box.l, width: box.r - box.l, y: Math.min(y0, y1).toFixed(2),
        height: Math.abs(y1 - y0).toFixed(2), fill: s.color || "#d9dde2", "fill-opacity": s.opacity || 0.7 }, gClip);
    } else if (s.type === "points") {
      for (i = 0; i < Math.min(s.x.length, s.y.length, MAX_SERIES_POINTS); i++) {
        var px = sx(s.x[i]), py = sy(s.y[i]);
        if (!(px >= box.l - 1 && px <= box.r + 1 && py >= box.t - 1 && py <= box.b + 1)) { continue; }
        var m = marker(gFree, s, px, py);
        if (s.cls) { m.setAttribute("class", s.cls); }
        if (s.title) { el("title", {}, m).textContent = s.title; }
      }
    } else if (s.type === "text") {
      var tx = sx(s.x) + (s.dx || 0), ty = sy(s.y) + (s.dy || 0);
      if (!isFinite(tx) || !isFinite(ty)) { return; }
      var t = el("text", { "class": s.cls || null, x: tx.toFixed(2), y: ty.toFixed(2), "text-anchor": s.anchor || "start",
        "font-size": s.size || FONT.text, fill: s.color || INK, "font-weight": s.weight || null }, gFree);
      richText(t, s.text);
    }
  }

  function seriesValues(spec, key) {
    var out = [];
    spec.series.forEach(function (s) {
      if (s.type === "line" || s.type === "points") {
        var a = s[key];
        for (var i = 0; i < a.length; i++) { out.push(a[i]); }
      } else if (s.type === "segments") {
        s.segs.forEach(function (q) { out.push(key === "x" ? q[0] : q[1], key === "x" ? q[2] : q[3]); });
      }
    });
    return out;
  }

  function tickList(ax, lo, hi, n) {
    var list;
    if (Array.isArray(ax.ticks)) {
      var gap = Infinity;
      ax.ticks.forEach(function (t, i) {
        if (i > 0 && typeof t === "number") { gap = Math.min(gap, Math.abs(t - ax.ticks[i - 1])); }
      });
      list = ax.ticks.map(function (t) {
        if (typeof t === "object") { return t; }
        return { v: t, label: ax.format ? ax.format(t) : ax.log ? logTickText(t) : tickText(t, isFinite(gap) ? gap : t) };
      });
    } else {
      var vals = ax.log ? logTicks(lo, hi) : ticks(lo, hi, ax.ticks || n);
      var step = vals.length > 1 ? vals[1] - vals[0] : Math.abs(vals[0] || 1);
      list = vals.map(function (v) { return { v: v, label: ax.log ? logTickText(v) : tickText(v, step) }; });
    }
    return list.filter(function (t) {
      var f = ax.log ? Math.log10 : function (v) { return v; };
      var a = f(lo), b = f(hi), x = f(t.v), tol = 1e-9 * (b - a);
      return x >= a - tol && x <= b + tol;
    }).map(function (t) {
      return { v: t.v, label: ax.format && !Array.isArray(ax.ticks) ? ax.format(t.v) : t.label };
    });
  }

  /** Font size, colour and style of an axis's tick labels (axis option tickStyle: {size, color, italic}). */
  function tickStyle(ax) {
    var t = ax.tickStyle || {};
    return { size: t.size || FONT.tick, color: t.color || MUTED, style: t.italic ? "italic" : null };
  }

  /** Draw the plot `spec` into `svg` at the SVG's current width; returns {x, y, box, width, height}. */
  function draw(svg, spec) {
    svg.__vibPlot = spec;
    watch(svg);
    var width = Math.round(svg.getBoundingClientRect().width) || spec.width || 640;
    var W = Math.max(width, 200);
    var H = spec.height || 260;
    if (spec.aspect) { H = Math.min(H, Math.round(spec.aspect * W)); }
    svg.setAttribute("viewBox", "0 0 " + W + " " + H);  // for measuring; the legend's rows add to the height
    svg.setAttribute("font-family", "inherit");
    svg.style.display = "block";
    svg.style.width = "100%";
    svg.style.height = "auto";
    svg.style.overflow = "hidden";
    while (svg.firstChild) { svg.removeChild(svg.firstChild); }
    var xa = spec.x || {}, ya = spec.y || {};
    var entries = legendEntries(spec);
    var rows = layoutLegend(svg, entries, W);
    var legendH = rows.length ? rows.length * 17 + 6 : 0;
    H += legendH;
    svg.setAttribute("viewBox", "0 0 " + W + " " + H);
    var top = spec.top || 0; // room for notes above the plot area
    H += top;
    svg.setAttribute("viewBox", "0 0 " + W + " " + H);
    var box = { t: 8 + legendH + top, b: H - (xa.label ? 42 : 24), l: 0, r: W - 12 };
    var xr = axisRange(xa, seriesValues(spec, "x")), yr = axisRange(ya, seriesValues(spec, "y"));
    var yTicks = tickList(ya, yr[0], yr[1], Math.max(2, Math.round((box.b - box.t) / 45)));
    var labelW = 0;
    var xts = tickStyle(xa), yts = tickStyle(ya);
    yTicks.forEach(function (t) { labelW = Math.max(labelW, measure(svg, t.label, yts.size)); });
    box.l = Math.ceil(labelW + 8 + (ya.label ? 20 : 4));
    if (spec.equal) { // widen one range so that a unit is as long on both axes
      var kx = (box.r - box.l) / (xr[1] - xr[0]), ky = (box.b - box.t) / (yr[1] - yr[0]), mid, half;
      if (kx > ky) {
        mid = 0.5 * (xr[0] + xr[1]); half = 0.5 * (box.r - box.l) / ky; xr = [mid - half, mid + half];
      } else {
        mid = 0.5 * (yr[0] + yr[1]); half = 0.5 * (box.b - box.t) / kx; yr = [mid - half, mid + half];
        yTicks = tickList(ya, yr[0], yr[1], Math.max(2, Math.round((box.b - box.t) / 45)));
      }
    }
    var n = Math.max(2, Math.round((box.r - box.l) / 85)), xTicks;
    for (var tries = 0; tries < 8; tries++) { // fewer ticks until their labels leave room between them
      xTicks = tickList(xa, xr[0], xr[1], n);
      var widest = 0;
      xTicks.forEach(function (t) { widest = Math.max(widest, measure(svg, t.label, xts.size)); });
      var room = xTicks.length > 1 ? (box.r - box.l) / (xTicks.length - 1) : Infinity;
      if (widest + 10 <= room || n <= 2 || Array.isArray(xa.ticks)) { break; }
      n -= 1;
    }
    var last = xTicks.length ? measure(svg, xTicks[xTicks.length - 1].label, xts.size) : 0;
    box.r = Math.min(box.r, W - 2 - last / 2);
    var sx = scale(xr[0], xr[1], !!xa.log, box.l, box.r), sy = scale(yr[0], yr[1], !!ya.log, box.b, box.t);
    var id = "vibplot-" + (++uid);
    var defs = el("defs", {}, svg);
    el("rect", { x: box.l, y: box.t, width: box.r - box.l, height: box.b - box.t }, el("clipPath", { id: id }, defs));
    var axes = el("g", { "class": "vp-axes" }, svg);
    xTicks.forEach(function (t) {
      var X = sx(t.v).toFixed(2);
      if (xa.grid !== false) { el("line", { x1: X, x2: X, y1: box.t, y2: box.b, stroke: GRID }, axes); }
      el("text", { "class": "vp-tick", x: X, y: box.b + 6 + xts.size, "text-anchor": "middle", "font-size": xts.size,
        fill: xts.color, "font-style": xts.style }, axes).textContent = t.label;
    });
    yTicks.forEach(function (t) {
      var Y = sy(t.v).toFixed(2);
      if (ya.grid !== false) { el("line", { x1: box.l, x2: box.r, y1: Y, y2: Y, stroke: GRID }, axes); }
      el("text", { "class": "vp-tick", x: box.l - 5, y: Y, dy: "0.32em", "text-anchor": "end", "font-size": yts.size,
        fill: yts.color, "font-style": yts.style }, axes).textContent = t.label;
    });
    el("rect", { x: box.l, y: box.t, width: box.r - box.l, height: box.b - box.t, fill: "none", stroke: FRAME }, axes);
    if (xa.label) {
      richText(el("text", { "class": "vp-label", x: ((box.l + box.r) / 2).toFixed(1), y: H - 8, "text-anchor": "middle",
        "font-size": FONT.label, fill: INK }, axes), xa.label);
    }
    if (ya.label) {
      var cy = ((box.t + box.b) / 2).toFixed(1);
      richText(el("text", { "class": "vp-label", transform: "translate(14," + cy + ") rotate(-90)", "text-anchor": "middle",
        "font-size": FONT.label, fill: INK }, axes), ya.label);
    }
    var gClip = el("g", { "clip-path": "url(#" + id + ")" }, svg);
    var gFree = el("g", {}, svg);
    spec.series.forEach(function (s) { drawSeries(gClip, gFree, s, sx, sy, box); });
    if (rows.length) {
      var lg = el("g", { "class": "vp-legend" }, svg);
      rows.forEach(function (row, i) {
        var y = 8 + 17 * i + 6;
        row.forEach(function (item) {
          drawSample(lg, item.entry, item.x, y);
          richText(el("text", { x: item.x + 29, y: y, dy: "0.35em", "font-size": FONT.legend, fill: INK }, lg),
            item.entry.label);
        });
      });
    }
    return { x: sx, y: sy, box: box, width: W, height: H };
  }

  /* ---------------------------------------------------------------- resizing */

  var observer = null;
  function redraw(svg) {
    var w = Math.round(svg.getBoundingClientRect().width);
    if (w > 0 && w !== svg.__vibWidth && svg.__vibPlot) {
      svg.__vibWidth = w;
      draw(svg, svg.__vibPlot);
    }
  }
  function watch(svg) {
    if (svg.__vibWatched) {
      svg.__vibWidth = Math.round(svg.getBoundingClientRect().width);
      return;
    }
    svg.__vibWatched = true;
    svg.__vibWidth = Math.round(svg.getBoundingClientRect().width);
    if (window.ResizeObserver) {
      if (!observer) {
        var pending = [];
        observer = new ResizeObserver(function (list) {
          list.forEach(function (e) { if (pending.indexOf(e.target) < 0) { pending.push(e.target); } });
          window.requestAnimationFrame(function () {
            var todo = pending;
            pending = [];
            todo.forEach(redraw);
          });
        });
      }
      observer.observe(svg);
    } else {
      window.addEventListener("resize", function () { redraw(svg); });
    }
  }

  /* ---------------------------------------------------------------- panels */

  /** A panel's data-params and data-styles, parsed, the first time it is mounted (its dataset[flag] then set);
   *  null for no panel or one mounted already. */
  function claim(panel, flag) {
    if (!panel || panel.dataset[flag]) {
      return null;
    }
    panel.dataset[flag] = "1";
    return { cfg: JSON.parse(panel.dataset.params), styles: JSON.parse(panel.dataset.styles) };
  }

  window.VibPlot = {
    version: VERSION,
    claim: claim,
    fmt: fmt,
    fixed: fixed,
    tickText: tickText,
    niceStep: niceStep,
    ticks: ticks,
    logTicks: logTicks,
    richText: richText,
    draw: draw,
  };
})();
