// model.js: the page's data in typed arrays, and the steps of inflating and sculpting.
//
// A trace labels Delaunay triangles interior (1) or exterior (0); "step s" means the first
// s steps applied. Which edges are on the boundary is decided in Rust alone (sigdt's
// Trace::boundary_changes): the page gets the boundary before the first step, and for each
// step the edges it toggles in or out. Applying step k flips the label of its triangle and
// toggles those edges; doing it again undoes it, so stepping back applies the same step.
// The labels only orient the boundary edges, to fill the interior through them (`sides`).

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
  this.labels = Uint8Array.from(trace.initial_inside, (v) => (v ? 1 : 0));
  if (this.labels.length !== T) throw new Error("initial_inside must have one label per triangle");
  this.phases = trace.phases;
  // Every edge that is ever on the boundary gets an id; ends[2e], ends[2e + 1] are its points.
  const ids = new Map();
  const key = (i, j) => (i < j ? i * n + j : j * n + i);
  const ends = [];
  const id = ([i, j], where) => {
    if (!(i < n && j < n)) throw new Error(`${where}: edge (${i}, ${j}) names a missing point`);
    let e = ids.get(key(i, j));
    if (e === undefined) {
      e = ends.length / 2;
      ids.set(key(i, j), e);
      ends.push(i, j);
    }
    return e;
  };
  const initial = trace.initial_boundary.map((edge) => id(edge, "initial_boundary"));
  const S = trace.steps.length;
  this.stepTriangle = new Uint32Array(S);
  this.stepPhase = new Uint8Array(S);
  this.ordinal = new Uint32Array(S); // 1-based position among the steps of its phase
  this.totals = this.phases.map(() => 0);
  this.toggleStart = new Uint32Array(S + 1); // step k toggles toggles[toggleStart[k] ..]
  const toggles = [];
  trace.steps.forEach(([t, phase, edges], k) => {
    if (!(t < T)) throw new Error(`step ${k} names a missing triangle ${t}`);
    if (!(phase < this.phases.length)) throw new Error(`step ${k} has an unknown phase ${phase}`);
    this.stepTriangle[k] = t;
    this.stepPhase[k] = phase;
    this.ordinal[k] = ++this.totals[phase];
    for (const edge of edges) toggles.push(id(edge, `step ${k}`));
    this.toggleStart[k + 1] = toggles.length;
  });
  this.toggles = Uint32Array.from(toggles);
  this.ends = Uint32Array.from(ends);
  const E = ends.length / 2;
  this.on = new Uint8Array(E); // 1 for the edges on the boundary now
  for (const e of initial) this.on[e] = 1;
  // left[e], right[e]: the triangle with edge e's ends in counter-clockwise, clockwise order
  // (-1: none), to fill the interior (see `sides`).
  this.left = new Int32Array(E).fill(-1);
  this.right = new Int32Array(E).fill(-1);
  for (let h = 0; h < 3 * T; h++) {
    const [i, j] = [this.tri[h], this.tri[h % 3 === 2 ? h - 2 : h + 1]];
    const e = ids.get(key(i, j));
    if (e !== undefined) (this.ends[2 * e] === i ? this.left : this.right)[e] = (h / 3) | 0;
  }
  this.steps = S;
  this.inflatedAt = Math.min(Math.max(trace.inflated_at | 0, 0), S);
  this.current = 0;
}

/** Applies step k to the current state, or undoes it if it is the last one applied. */
Trace.prototype.flip = function (k) {
  this.labels[this.stepTriangle[k]] ^= 1;
  for (let a = this.toggleStart[k]; a < this.toggleStart[k + 1]; a++) this.on[this.toggles[a]] ^= 1;
};

/** Moves to step s (0 ≤ s ≤ steps), applying or undoing the steps between. */
Trace.prototype.seek = function (s) {
  s = Math.min(Math.max(s | 0, 0), this.steps);
  for (; this.current < s; this.current++) this.flip(this.current);
  for (; this.current > s; this.current--) this.flip(this.current - 1);
};

/** The number of interior triangles at the current step. */
Trace.prototype.insideCount = function () {
  let inside = 0;
  for (let t = 0; t < this.labels.length; t++) inside += this.labels[t];
  return inside;
};

/** The boundary at the current step, as a flat edge array. */
Trace.prototype.boundary = function () {
  let size = 0;
  for (let e = 0; e < this.on.length; e++) size += this.on[e];
  const out = new Uint32Array(2 * size);
  for (let e = 0, k = 0; e < this.on.length; e++) {
    if (!this.on[e]) continue;
    out[k++] = this.ends[2 * e];
    out[k++] = this.ends[2 * e + 1];
  }
  return out;
};

/**
 * The boundary edges at the current step that have an interior triangle on one side, as a
 * flat array directed with that triangle on their left: the outline the interior is filled
 * through. Which edges are on the boundary is the trace's; this only orients them, and
 * leaves out the dangling ones (exterior on both sides), which bound no area.
 */
Trace.prototype.sides = function () {
  const { on, ends, left, right, labels } = this;
  const out = [];
  for (let e = 0; e < on.length; e++) {
    if (!on[e]) continue;
    if (left[e] >= 0 && labels[left[e]]) out.push(ends[2 * e], ends[2 * e + 1]);
    else if (right[e] >= 0 && labels[right[e]]) out.push(ends[2 * e + 1], ends[2 * e]);
  }
  return Uint32Array.from(out);
};

/**
 * Directed sides split into closed cycles: cycle c visits loops[starts[c] .. starts[c + 1]).
 * The sides of a set of counter-clockwise triangles have as many sides in as out at every
 * vertex, so a walk can only end where it started, and however they are split, the nonzero
 * rule fills exactly the triangles.
 */
function cycles(edges, n) {
  const sides = edges.length / 2;
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

/** The name of the phase of step k ("inflate", "pocket", "sculpt"). */
Trace.prototype.phaseName = function (k) {
  return this.phases[this.stepPhase[k]];
};

/** What step s shows: "initial", "inflate 3/12", "pocket", "sculpt 2/5" or "final". */
Trace.prototype.label = function (s) {
  if (s >= this.steps) return "final";
  if (s <= 0) return "initial";
  const name = this.phaseName(s - 1);
  // A pocket fills several triangles at once: counting them one by one says nothing.
  if (name === "pocket") return name;
  return `${name} ${this.ordinal[s - 1]}/${this.totals[this.stepPhase[s - 1]]}`;
};
