// model.js: the page's data in typed arrays, and the replay of inflating and sculpting.
//
// A trace labels Delaunay triangles interior (1) or exterior (0). Step k sets triangle
// steps[k][0] to steps[k][1]; "step s" means steps[0..s] applied. The boundary at step s is
// every triangle edge with different labels on its two sides (beyond the convex hull is
// exterior), plus the initial dangling edges whose triangles are all still exterior.

const KIND_NAMES = { i: "inflate", p: "pocket", s: "sculpt" };

/** Flat Uint32Array [i0, j0, i1, j1, ...] of an edge list, or null. */
function flatEdges(edges, n) {
  if (!edges) return null;
  const flat = new Uint32Array(2 * edges.length);
  edges.forEach(([i, j], k) => {
    if (!(i < n && j < n)) throw new Error(`edge ${k} (${i}, ${j}) names a missing point`);
    flat[2 * k] = i;
    flat[2 * k + 1] = j;
  });
  return flat;
}

function Model(data) {
  const n = data.points.length;
  this.title = data.title || "";
  this.method = data.method || "";
  this.status = data.status || "";
  this.n = n;
  this.xs = new Float64Array(n);
  this.ys = new Float64Array(n);
  this.nn = new Float64Array(n);
  data.points.forEach(([x, y], i) => {
    this.xs[i] = x;
    this.ys[i] = y;
    this.nn[i] = Number.isFinite(data.nn && data.nn[i]) ? data.nn[i] : 0;
  });
  this.edges = {};
  const layers = data.layers || {};
  for (const name of Object.keys(layers)) this.edges[name] = flatEdges(layers[name], n);
  this.trace = data.trace ? new Trace(data.trace, n) : null;
  if (this.trace) this.edges.boundary = this.trace.boundaryAt(this.trace.inflatedAt).edges;
}

/** [minX, minY, maxX, maxY] of the points (a unit box around the origin if there are none). */
Model.prototype.bounds = function () {
  if (this.n === 0) return [-1, -1, 1, 1];
  let [x0, y0, x1, y1] = [Infinity, Infinity, -Infinity, -Infinity];
  for (let i = 0; i < this.n; i++) {
    x0 = Math.min(x0, this.xs[i]);
    y0 = Math.min(y0, this.ys[i]);
    x1 = Math.max(x1, this.xs[i]);
    y1 = Math.max(y1, this.ys[i]);
  }
  return [x0, y0, x1, y1];
};

function Trace(trace, n) {
  const T = trace.triangles.length;
  this.tri = new Uint32Array(3 * T);
  trace.triangles.forEach((t, k) => {
    if (!(t[0] < n && t[1] < n && t[2] < n)) throw new Error(`triangle ${k} names a missing point`);
    this.tri.set(t, 3 * k);
  });
  // across[3t + k]: the triangle across the edge from corner k to corner k + 1 of t, or -1.
  this.across = new Int32Array(3 * T).fill(-1);
  const seen = new Map();
  const key = (i, j) => (i < j ? i * n + j : j * n + i);
  for (let h = 0; h < 3 * T; h++) {
    const k = key(this.tri[h], this.tri[h % 3 === 2 ? h - 2 : h + 1]);
    const other = seen.get(k);
    if (other === undefined) {
      seen.set(k, h);
    } else {
      this.across[h] = Math.floor(other / 3);
      this.across[other] = Math.floor(h / 3);
    }
  }
  this.initial = Uint8Array.from(trace.initial_inside, (v) => (v ? 1 : 0));
  if (this.initial.length !== T) throw new Error("initial_inside must have one label per triangle");
  this.labels = this.initial.slice();
  this.dangling = flatEdges(trace.dangling, n);
  // danglingAt[2d], danglingAt[2d + 1]: the (up to two) triangles on dangling edge d, or -1.
  this.danglingAt = new Int32Array(this.dangling.length).fill(-1);
  for (let d = 0; 2 * d < this.dangling.length; d++) {
    const h = seen.get(key(this.dangling[2 * d], this.dangling[2 * d + 1]));
    if (h !== undefined) {
      this.danglingAt[2 * d] = Math.floor(h / 3);
      this.danglingAt[2 * d + 1] = this.across[h];
    }
  }
  const S = trace.steps.length;
  this.stepTriangle = new Uint32Array(S);
  this.stepInside = new Uint8Array(S);
  this.stepBefore = new Uint8Array(S); // the label the step replaced, to step back
  this.stepKind = new Array(S);
  this.ordinal = new Uint32Array(S); // 1-based position among the steps of its kind
  this.totals = { i: 0, p: 0, s: 0 };
  const labels = this.initial.slice();
  trace.steps.forEach(([t, inside, kind], k) => {
    if (!(t < T)) throw new Error(`step ${k} names a missing triangle ${t}`);
    this.stepTriangle[k] = t;
    this.stepInside[k] = inside ? 1 : 0;
    this.stepBefore[k] = labels[t];
    labels[t] = this.stepInside[k];
    this.stepKind[k] = kind;
    this.totals[kind] = (this.totals[kind] || 0) + 1;
    this.ordinal[k] = this.totals[kind];
  });
  this.steps = S;
  this.inflatedAt = Math.min(Math.max(trace.inflated_at | 0, 0), S);
  this.current = 0;
}

/** Moves the labels to step s (0 ≤ s ≤ steps), applying or undoing the steps between. */
Trace.prototype.seek = function (s) {
  s = Math.min(Math.max(s | 0, 0), this.steps);
  for (; this.current < s; this.current++) {
    this.labels[this.stepTriangle[this.current]] = this.stepInside[this.current];
  }
  for (; this.current > s; this.current--) {
    this.labels[this.stepTriangle[this.current - 1]] = this.stepBefore[this.current - 1];
  }
};

/** The number of interior triangles at the current step. */
Trace.prototype.insideCount = function () {
  let inside = 0;
  for (let t = 0; t < this.labels.length; t++) inside += this.labels[t];
  return inside;
};

/**
 * The boundary of the current labels: `edges`, a flat edge array, starts with `sides`
 * edges directed with the interior on their left (they form closed cycles), followed by
 * the dangling edges still on the boundary.
 */
Trace.prototype.boundary = function () {
  const out = [];
  const { tri, across, labels } = this;
  for (let h = 0; h < tri.length; h++) {
    // Each boundary edge once: from its interior side, counter-clockwise.
    const other = across[h];
    if (labels[(h / 3) | 0] && (other < 0 || !labels[other])) {
      out.push(tri[h], tri[h % 3 === 2 ? h - 2 : h + 1]);
    }
  }
  const sides = out.length / 2;
  for (let d = 0; 2 * d < this.dangling.length; d++) {
    const a = this.danglingAt[2 * d];
    const b = this.danglingAt[2 * d + 1];
    if ((a < 0 || !labels[a]) && (b < 0 || !labels[b])) {
      out.push(this.dangling[2 * d], this.dangling[2 * d + 1]);
    }
  }
  return { edges: Uint32Array.from(out), sides };
};

/**
 * The directed sides edges[0 .. 2 * sides) split into closed cycles: cycle c visits
 * loops[starts[c] .. starts[c + 1]). The sides of a set of counter-clockwise triangles
 * have as many sides in as out at every vertex, so a walk can only end where it started,
 * and however they are split, the nonzero rule fills exactly the triangles.
 */
function cycles(edges, sides, n) {
  const first = new Int32Array(n + 1); // sides out of v: at[first[v] .. first[v + 1])
  for (let k = 0; k < sides; k++) first[edges[2 * k] + 1]++;
  for (let v = 0; v < n; v++) first[v + 1] += first[v];
  const next = first.slice(0, n);
  const at = new Int32Array(sides);
  for (let k = 0; k < sides; k++) at[next[edges[2 * k]]++] = k;
  next.set(first.subarray(0, n)); // per vertex: the next side not yet used
  const used = new Uint8Array(sides);
  const loops = new Uint32Array(sides);
  const starts = [0];
  let size = 0;
  for (let k0 = 0; k0 < sides; k0++) {
    if (used[k0]) continue;
    const v0 = edges[2 * k0];
    for (let k = k0; k >= 0; ) {
      used[k] = 1;
      loops[size++] = edges[2 * k];
      const v = edges[2 * k + 1];
      while (next[v] < first[v + 1] && used[at[next[v]]]) next[v]++;
      k = v === v0 || next[v] === first[v + 1] ? -1 : at[next[v]];
    }
    starts.push(size);
  }
  return { loops, starts };
}

/** The boundary at step s (the labels are left at step s). */
Trace.prototype.boundaryAt = function (s) {
  this.seek(s);
  return this.boundary();
};

/** What step s shows: "initial", "inflate 3/12", "pocket", "sculpt 2/5" or "final". */
Trace.prototype.label = function (s) {
  if (s >= this.steps) return "final";
  if (s <= 0) return "initial";
  const kind = this.stepKind[s - 1];
  if (kind === "p") return "pocket";
  return `${KIND_NAMES[kind] || kind} ${this.ordinal[s - 1]}/${this.totals[kind]}`;
};
