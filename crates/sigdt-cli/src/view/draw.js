// draw.js: the camera (pan, zoom, fit), and drawing on the canvas or, for export, into SVG.
//
// Screen position of point i: (x * scale + tx, ty - y * scale), y pointing up. Coordinates
// are transformed here rather than by the canvas, so line widths stay in screen pixels.

/**
 * The layers, in legend order: `color` names a role of the palette (shared with `sigdt
 * render` and Python's plot), `on` says whether it is shown at start (with a trace / without).
 */
const LAYERS = [
  { id: "points", label: "points", color: "ink", on: [1, 1] },
  { id: "dt", label: "DT", color: "dt", width: 0.8, on: [0, 0] },
  { id: "sig", label: "SIG circles", color: "sig", width: 0.8, alpha: 0.8, on: [0, 0] },
  { id: "sigdt", label: "SIGDT", color: "sigdt", width: 1.3, on: [0, 0] },
  { id: "sigdt2", label: "SIGDT2 (leaf edges)", color: "sigdt2", width: 4, on: [0, 0] },
  { id: "boundary", label: "inflated boundary", color: "boundary", width: 2, dash: [7, 5], on: [0, 0] },
  { id: "result", label: "result", color: "result", width: 1.6, on: [1, 1] },
  { id: "gt", label: "ground truth", color: "truth", width: 8, alpha: 0.35, on: [0, 1] },
  { id: "interior", label: "interior (step)", color: "fill", fill: true, on: [1, 0] },
  { id: "current", label: "boundary (step)", color: "step_boundary", width: 1.6, on: [1, 0] },
  { id: "changed", label: "last step's triangle", color: "inflate", fill: true, on: [1, 0] },
  { id: "junctions", label: "junctions", color: "boundary", width: 2, on: [1, 1] },
];
// The step boundary is drawn under the result with the same width: at the end they coincide
// and the result shows as `sigdt render` draws it.
const DRAW_ORDER = ["interior", "gt", "dt", "sigdt2", "sigdt", "sig", "boundary", "current", "result", "changed", "points", "junctions"];
// A triangle thinner than this on screen (pixels) also gets a ring, so a sliver can be found.
const SLIVER_PX = 4;

const clamp = (x, lo, hi) => Math.min(Math.max(x, lo), hi);

function View(canvas, model) {
  this.canvas = canvas;
  this.ctx = canvas.getContext("2d");
  this.model = model;
  this.palette = model.palette;
  this.styles = Object.fromEntries(LAYERS.map((l) => [l.id, { ...l, color: model.palette[l.color] }]));
  this.scale = 1;
  this.tx = 0;
  this.ty = 0;
  this.sx = new Float64Array(model.n);
  this.sy = new Float64Array(model.n);
  this.width = 0;
  this.height = 0;
  this.pending = false;
  this.visible = {};
  this.step = 0;
  this.stepEdges = null; // boundary at this.step, computed once per step
  this.hover = -1;
}

/** Matches the canvas to its CSS size and the device pixel ratio. */
View.prototype.resize = function () {
  const dpr = window.devicePixelRatio || 1;
  const rect = this.canvas.getBoundingClientRect();
  this.width = Math.max(1, rect.width);
  this.height = Math.max(1, rect.height);
  this.canvas.width = Math.round(this.width * dpr);
  this.canvas.height = Math.round(this.height * dpr);
  this.ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
};

/** Centres the points with a margin of 24 screen pixels. */
View.prototype.fit = function () {
  const [x0, y0, x1, y1] = this.model.bounds();
  const margin = 24;
  const w = Math.max(x1 - x0, 1e-300);
  const h = Math.max(y1 - y0, 1e-300);
  this.scale = Math.min((this.width - 2 * margin) / w, (this.height - 2 * margin) / h);
  if (!Number.isFinite(this.scale) || this.scale <= 0) this.scale = 1;
  this.tx = this.width / 2 - ((x0 + x1) / 2) * this.scale;
  this.ty = this.height / 2 + ((y0 + y1) / 2) * this.scale;
  this.request();
};

/** Zooms by `factor` keeping the point under screen position (mx, my) in place. */
View.prototype.zoom = function (factor, mx, my) {
  this.scale *= factor;
  this.tx = mx - (mx - this.tx) * factor;
  this.ty = my - (my - this.ty) * factor;
  this.request();
};

View.prototype.pan = function (dx, dy) {
  this.tx += dx;
  this.ty += dy;
  this.request();
};

/** The point within `radius` pixels of (mx, my) nearest to it, or -1. */
View.prototype.pick = function (mx, my, radius) {
  let best = -1;
  let bestD = radius * radius;
  for (let i = 0; i < this.model.n; i++) {
    const d = (this.sx[i] - mx) ** 2 + (this.sy[i] - my) ** 2;
    if (d < bestD) [best, bestD] = [i, d];
  }
  return best;
};

/** Schedules one redraw on the next animation frame. */
View.prototype.request = function () {
  if (this.pending) return;
  this.pending = true;
  requestAnimationFrame(() => {
    this.pending = false;
    this.draw();
  });
};

/** Draws the visible layers with `ctx` (the canvas's, or an SvgContext to export). */
View.prototype.draw = function (ctx = this.ctx, hover = true) {
  const { model, sx, sy } = this;
  for (let i = 0; i < model.n; i++) {
    sx[i] = model.xs[i] * this.scale + this.tx;
    sy[i] = this.ty - model.ys[i] * this.scale;
  }
  ctx.globalAlpha = 1;
  ctx.fillStyle = this.palette.background;
  ctx.fillRect(0, 0, this.width, this.height);
  ctx.lineCap = "round";
  ctx.lineJoin = "round";
  const trace = model.trace;
  for (const id of DRAW_ORDER) {
    if (!this.visible[id]) continue;
    const style = this.styles[id];
    ctx.globalAlpha = style.alpha || 1;
    if (id === "points") this.drawPoints(ctx, style);
    else if (id === "sig") this.drawCircles(ctx, style);
    else if (id === "interior" && trace) this.drawInterior(ctx, style);
    else if (id === "current" && trace) this.strokeEdges(ctx, this.currentBoundary().edges, style);
    else if (id === "changed" && trace) this.drawChanged(ctx);
    else if (id === "junctions") this.drawJunctions(ctx, style);
    else if (model.edges[id]) this.strokeEdges(ctx, model.edges[id], style);
  }
  ctx.globalAlpha = 1;
  if (hover && this.hover >= 0) {
    ctx.beginPath();
    ctx.arc(sx[this.hover], sy[this.hover], 7, 0, 2 * Math.PI);
    ctx.lineWidth = 2;
    ctx.strokeStyle = this.palette.missing;
    ctx.stroke();
  }
};

/** Whether segment (x0, y0)-(x1, y1), widened by `pad`, surely misses the canvas. */
View.prototype.off = function (x0, y0, x1, y1, pad) {
  const w = this.width + pad;
  const h = this.height + pad;
  return (x0 < -pad && x1 < -pad) || (x0 > w && x1 > w) || (y0 < -pad && y1 < -pad) || (y0 > h && y1 > h);
};

// Big paths are drawn in chunks: the rasteriser slows down more than linearly with size.
const CHUNK = 1024;

/** The edges of a flat edge array that cross the canvas and leave their pixel. */
View.prototype.visibleEdges = function (edges, pad) {
  const { sx, sy } = this;
  const shown = [];
  for (let k = 0; 2 * k < edges.length; k++) {
    const i = edges[2 * k];
    const j = edges[2 * k + 1];
    if (this.off(sx[i], sy[i], sx[j], sy[j], pad)) continue;
    // An edge inside one pixel: the edges that leave that pixel cover it.
    if (Math.round(sx[i]) === Math.round(sx[j]) && Math.round(sy[i]) === Math.round(sy[j])) continue;
    shown.push(k);
  }
  return shown;
};

/**
 * Strokes the edges of a flat edge array. Wide and dashed lines are slow to
 * rasterise, so beyond 20,000 visible edges they are drawn as plain hairlines.
 */
View.prototype.strokeEdges = function (ctx, edges, style) {
  if (!edges) return;
  const { sx, sy } = this;
  const shown = this.visibleEdges(edges, style.width);
  const many = shown.length > 20000;
  ctx.setLineDash(many ? [] : style.dash || []);
  ctx.lineWidth = many ? Math.min(style.width, 1) : style.width;
  ctx.lineCap = many ? "butt" : "round";
  ctx.strokeStyle = style.color;
  for (let c = 0; c < shown.length; c += CHUNK) {
    ctx.beginPath();
    for (const k of shown.slice(c, c + CHUNK)) {
      ctx.moveTo(sx[edges[2 * k]], sy[edges[2 * k]]);
      ctx.lineTo(sx[edges[2 * k + 1]], sy[edges[2 * k + 1]]);
    }
    ctx.stroke();
  }
  ctx.setLineDash([]);
  ctx.lineCap = "round";
};

View.prototype.drawPoints = function (ctx, style) {
  const { sx, sy } = this;
  const n = this.model.n;
  const r = n > 20000 ? 1.2 : n > 2000 ? 1.8 : 2.6;
  // With many points, one dot per pixel is enough.
  const [w, h] = [Math.ceil(this.width), Math.ceil(this.height)];
  const seen = n > 5000 ? new Uint8Array(w * h) : null;
  ctx.fillStyle = style.color;
  ctx.beginPath();
  let size = 0;
  for (let i = 0; i < n; i++) {
    if (this.off(sx[i], sy[i], sx[i], sy[i], r)) continue;
    if (seen) {
      const p = clamp(Math.floor(sy[i]), 0, h - 1) * w + clamp(Math.floor(sx[i]), 0, w - 1);
      if (seen[p]) continue;
      seen[p] = 1;
    }
    if (n > 20000) {
      ctx.rect(sx[i] - r, sy[i] - r, 2 * r, 2 * r);
    } else {
      ctx.moveTo(sx[i] + r, sy[i]);
      ctx.arc(sx[i], sy[i], r, 0, 2 * Math.PI);
    }
    if (++size === CHUNK) {
      ctx.fill();
      ctx.beginPath();
      size = 0;
    }
  }
  ctx.fill();
};

/** A ring around every junction of the result (a point with three edges or more). */
View.prototype.drawJunctions = function (ctx, style) {
  const { sx, sy } = this;
  ctx.beginPath();
  for (const j of this.model.junctions || []) {
    ctx.moveTo(sx[j] + 8, sy[j]);
    ctx.arc(sx[j], sy[j], 8, 0, 2 * Math.PI);
  }
  ctx.lineWidth = style.width;
  ctx.strokeStyle = style.color;
  ctx.stroke();
};

View.prototype.drawCircles = function (ctx, style) {
  const { sx, sy } = this;
  const nn = this.model.nn;
  ctx.lineWidth = style.width;
  ctx.strokeStyle = style.color;
  ctx.beginPath();
  let size = 0;
  for (let i = 0; i < this.model.n; i++) {
    const r = nn[i] * this.scale;
    if (r < 0.5 || this.off(sx[i], sy[i], sx[i], sy[i], r)) continue;
    ctx.moveTo(sx[i] + r, sy[i]);
    ctx.arc(sx[i], sy[i], r, 0, 2 * Math.PI);
    if (++size === CHUNK) {
      ctx.stroke();
      ctx.beginPath();
      size = 0;
    }
  }
  ctx.stroke();
};

/**
 * The interior at the current step, filled through its boundary cycles (nonzero rule), or
 * triangle by triangle when there are many small cycles (which the rasteriser handles
 * slowly).
 */
View.prototype.drawInterior = function (ctx, style) {
  const { sx, sy } = this;
  const { loops, starts } = this.currentBoundary();
  ctx.fillStyle = style.color;
  ctx.beginPath();
  if (starts.length <= 2000) {
    for (let c = 0; c + 1 < starts.length; c++) {
      let [px, py] = [NaN, NaN];
      for (let k = starts[c]; k < starts[c + 1]; k++) {
        const v = loops[k];
        if (Math.round(sx[v]) === px && Math.round(sy[v]) === py) continue; // in the same pixel
        [px, py] = [Math.round(sx[v]), Math.round(sy[v])];
        if (k === starts[c]) ctx.moveTo(sx[v], sy[v]);
        else ctx.lineTo(sx[v], sy[v]);
      }
      ctx.closePath();
    }
  } else {
    const { tri, labels } = this.model.trace;
    for (let t = 0, size = 0; t < labels.length; t++) {
      if (!labels[t]) continue;
      const [a, b, c] = [tri[3 * t], tri[3 * t + 1], tri[3 * t + 2]];
      ctx.moveTo(sx[a], sy[a]);
      ctx.lineTo(sx[b], sy[b]);
      ctx.lineTo(sx[c], sy[c]);
      ctx.closePath();
      if (++size === 64) {
        ctx.fill();
        ctx.beginPath();
        size = 0;
      }
    }
  }
  ctx.fill("nonzero");
};

/** The triangle changed by the last step and its colour, or null at step 0. */
View.prototype.changed = function () {
  const trace = this.model.trace;
  if (!trace || this.step <= 0) return null;
  const k = this.step - 1;
  const t = trace.stepTriangle[k];
  const corners = [0, 1, 2].map((c) => trace.tri[3 * t + c]);
  return { corners, color: this.palette[trace.phaseName(k)] || this.palette.inflate };
};

/**
 * The triangle changed by the last step: filled and outlined in its phase's colour, so that
 * a sliver still shows as a line, and ringed when it is thinner or smaller than a few
 * pixels.
 */
View.prototype.drawChanged = function (ctx) {
  const changed = this.changed();
  if (!changed) return;
  const { sx, sy } = this;
  const [a, b, c] = changed.corners;
  ctx.beginPath();
  ctx.moveTo(sx[a], sy[a]);
  ctx.lineTo(sx[b], sy[b]);
  ctx.lineTo(sx[c], sy[c]);
  ctx.closePath();
  ctx.fillStyle = ctx.strokeStyle = changed.color;
  ctx.fill();
  ctx.lineWidth = 2.5;
  ctx.stroke();
  // Thickness: twice the area over the longest side.
  const area2 = Math.abs((sx[b] - sx[a]) * (sy[c] - sy[a]) - (sy[b] - sy[a]) * (sx[c] - sx[a]));
  const side = Math.max(Math.hypot(sx[b] - sx[a], sy[b] - sy[a]), Math.hypot(sx[c] - sx[b], sy[c] - sy[b]), Math.hypot(sx[a] - sx[c], sy[a] - sy[c]));
  if (side < 2 * SLIVER_PX || area2 < SLIVER_PX * side) {
    const [cx, cy] = [(sx[a] + sx[b] + sx[c]) / 3, (sy[a] + sy[b] + sy[c]) / 3];
    ctx.beginPath();
    ctx.arc(cx, cy, Math.max(9, side / 2 + 4), 0, 2 * Math.PI);
    ctx.lineWidth = 2.5;
    ctx.stroke();
  }
};

/** The boundary at the current step and the cycles of its interior, once per step. */
View.prototype.currentBoundary = function () {
  if (!this.stepEdges) {
    const trace = this.model.trace;
    const { loops, starts } = cycles(trace.sides(), this.model.n);
    this.stepEdges = { edges: trace.boundary(), loops, starts };
  }
  return this.stepEdges;
};

/** Moves the replay to step s. */
View.prototype.setStep = function (s) {
  const trace = this.model.trace;
  if (!trace) return;
  this.step = clamp(s | 0, 0, trace.steps);
  trace.seek(this.step);
  this.stepEdges = null; // recomputed by the next frame, however often the slider moves
  this.request();
};

/** The current view as a standalone SVG document (what the canvas shows, without hover). */
View.prototype.svg = function () {
  const svg = new SvgContext(this.width, this.height);
  this.draw(svg, false);
  return svg.document(this.model.title);
};

/**
 * The subset of the canvas 2D context that View draws with, recording SVG paths: each
 * fill or stroke becomes one <path> with the current style.
 */
function SvgContext(width, height) {
  this.width = width;
  this.height = height;
  this.parts = [];
  this.d = [];
  this.dash = [];
  this.globalAlpha = 1;
  this.fillStyle = "#000000";
  this.strokeStyle = "#000000";
  this.lineWidth = 1;
  this.lineCap = "butt";
  this.lineJoin = "miter";
}

const svgNumber = (x) => String(Math.round(x * 100) / 100);

SvgContext.prototype.beginPath = function () {
  this.d = [];
};
SvgContext.prototype.moveTo = function (x, y) {
  this.d.push(`M${svgNumber(x)} ${svgNumber(y)}`);
};
SvgContext.prototype.lineTo = function (x, y) {
  this.d.push(`L${svgNumber(x)} ${svgNumber(y)}`);
};
SvgContext.prototype.closePath = function () {
  this.d.push("Z");
};
SvgContext.prototype.rect = function (x, y, w, h) {
  this.d.push(`M${svgNumber(x)} ${svgNumber(y)}h${svgNumber(w)}v${svgNumber(h)}h${svgNumber(-w)}Z`);
};
/** Full circles only (the only arcs View draws). */
SvgContext.prototype.arc = function (cx, cy, r) {
  const [x0, x1, y, R] = [svgNumber(cx + r), svgNumber(cx - r), svgNumber(cy), svgNumber(r)];
  this.d.push(`M${x0} ${y}A${R} ${R} 0 1 0 ${x1} ${y}A${R} ${R} 0 1 0 ${x0} ${y}Z`);
};
SvgContext.prototype.setLineDash = function (dash) {
  this.dash = dash;
};
SvgContext.prototype.setTransform = function () {};
SvgContext.prototype.opacity = function (attribute) {
  return this.globalAlpha < 1 ? ` ${attribute}="${this.globalAlpha}"` : "";
};
SvgContext.prototype.fill = function (rule = "nonzero") {
  if (!this.d.length) return;
  this.parts.push(`<path fill="${this.fillStyle}" fill-rule="${rule}"${this.opacity("fill-opacity")} d="${this.d.join("")}"/>`);
};
SvgContext.prototype.stroke = function () {
  if (!this.d.length) return;
  const dash = this.dash.length ? ` stroke-dasharray="${this.dash.join(" ")}"` : "";
  this.parts.push(
    `<path fill="none" stroke="${this.strokeStyle}" stroke-width="${svgNumber(this.lineWidth)}" ` +
      `stroke-linecap="${this.lineCap}" stroke-linejoin="${this.lineJoin}"${dash}${this.opacity("stroke-opacity")} d="${this.d.join("")}"/>`,
  );
};
SvgContext.prototype.fillRect = function (x, y, w, h) {
  this.parts.push(`<rect x="${svgNumber(x)}" y="${svgNumber(y)}" width="${svgNumber(w)}" height="${svgNumber(h)}" fill="${this.fillStyle}"/>`);
};
SvgContext.prototype.document = function (title) {
  const [w, h] = [svgNumber(this.width), svgNumber(this.height)];
  const escaped = title.replace(/&/g, "&amp;").replace(/</g, "&lt;").replace(/>/g, "&gt;");
  return (
    `<svg xmlns="http://www.w3.org/2000/svg" width="${w}" height="${h}" viewBox="0 0 ${w} ${h}">\n` +
    `<title>${escaped}</title>\n${this.parts.join("\n")}\n</svg>\n`
  );
};
