// model.js: the page's data decoded into typed arrays, and the steps of inflating and sculpting.
//
// Arrays come as base64 of little-endian bytes, edge layers as one bit per edge of the edge
// list (the sides of the triangles and the extra edges, sorted; `EdgeList`), as the Rust side
// (src/view/mod.rs) documents. A trace labels Delaunay triangles interior (1) or exterior (0);
// "step s" means the first s steps applied. Which edges are on the boundary is decided in Rust
// alone (sigdt's Trace::boundary_change_sides): the page gets the boundary before the first
// step, and for each step which sides of its triangle it toggles in or out. Applying step k
// flips the label of its triangle and toggles those edges; doing it again undoes it, so
// stepping back applies the same step. The labels only orient the boundary edges, to fill the
// interior through them (`sides`).

/** The bytes of base64 `text`, which must be a multiple of `size` bytes long. */
function bytesOf(text, what, size) {
  if (typeof text !== "string") throw new Error(`${what} is missing`);
  const raw = atob(text);
  if (raw.length % size) throw new Error(`${what} has ${raw.length} bytes, not a multiple of ${size}`);
  const out = new Uint8Array(raw.length);
  for (let k = 0; k < raw.length; k++) out[k] = raw.charCodeAt(k);
  return out;
}

/** A typed array of `Type` from base64 `text` (the page assumes a little-endian machine). */
function typed(Type, text, what, multiple = 1) {
  const bytes = bytesOf(text, what, Type.BYTES_PER_ELEMENT * multiple);
  return new Type(bytes.buffer, 0, bytes.length / Type.BYTES_PER_ELEMENT);
}

/** `count` bits from base64 `text`, one byte (0 or 1) each. */
function bitsOf(text, count, what) {
  const bytes = bytesOf(text, what, 1);
  if (bytes.length !== Math.ceil(count / 8)) throw new Error(`${what} must have ${count} bits`);
  const out = new Uint8Array(count);
  for (let k = 0; k < count; k++) out[k] = (bytes[k >> 3] >> (k & 7)) & 1;
  return out;
}

/**
 * The sorted list of unique edges [i, j], i < j, of the triangles' sides and `extra` pairs,
 * grouped by i: edge e is (ei[e], ej[e]), and the edges from i are first[i] .. first[i + 1].
 */
function EdgeList(tri, extra, n) {
  const pairs = tri.length + extra.length / 2;
  const lo = new Uint32Array(pairs);
  const hi = new Uint32Array(pairs);
  for (let h = 0; h < tri.length; h++) {
    const [a, b] = [tri[h], tri[h % 3 === 2 ? h - 2 : h + 1]];
    [lo[h], hi[h]] = a < b ? [a, b] : [b, a];
  }
  for (let k = 0; k < extra.length / 2; k++) {
    const [a, b] = [extra[2 * k], extra[2 * k + 1]];
    if (!(a < b && b < n)) throw new Error(`extra edge ${k} (${a}, ${b}) is not a pair i < j of points`);
    [lo[tri.length + k], hi[tri.length + k]] = [a, b];
  }
  // Bucket by i, then sort and deduplicate each bucket (a few edges each) by j.
  const first = new Uint32Array(n + 1);
  for (let k = 0; k < pairs; k++) first[lo[k] + 1]++;
  for (let i = 0; i < n; i++) first[i + 1] += first[i];
  const at = first.slice(0, n);
  const js = new Uint32Array(pairs);
  for (let k = 0; k < pairs; k++) js[at[lo[k]]++] = hi[k];
  let size = 0;
  for (let i = 0; i < n; i++) {
    const [start, end] = [first[i], first[i + 1]];
    first[i] = size;
    for (let a = start; a < end; a++) {
      const j = js[a];
      let b = size;
      while (b > first[i] && js[b - 1] > j) b--;
      if (b > first[i] && js[b - 1] === j) continue;
      js.copyWithin(b + 1, b, size);
      js[b] = j;
      size++;
    }
  }
  first[n] = size;
  this.first = first;
  this.ej = js.slice(0, size);
  this.ei = new Uint32Array(size);
  for (let i = 0; i < n; i++) this.ei.fill(i, first[i], first[i + 1]);
  this.length = size;
}

/** The id of edge (a, b), or -1. */
EdgeList.prototype.find = function (a, b) {
  if (a > b) [a, b] = [b, a];
  for (let e = this.first[a]; e < this.first[a + 1]; e++) if (this.ej[e] === b) return e;
  return -1;
};

/** The edges whose bit is set, as a flat Uint32Array [i0, j0, i1, j1, ...]. */
EdgeList.prototype.select = function (bits) {
  let size = 0;
  for (let e = 0; e < this.length; e++) size += bits[e];
  const out = new Uint32Array(2 * size);
  for (let e = 0, k = 0; e < this.length; e++) {
    if (!bits[e]) continue;
    out[k++] = this.ei[e];
    out[k++] = this.ej[e];
  }
  return out;
};

function Model(data) {
  if (data.format !== 2) throw new Error(`this page reads data format 2, not ${data.format}`);
  const n = data.n;
  this.title = data.title || "";
  this.method = data.method || "";
  this.status = data.status || "";
  this.palette = data.palette;
  this.n = n;
  const xy = typed(Float64Array, data.points, "points", 2);
  if (xy.length !== 2 * n) throw new Error(`points must hold ${n} points`);
  this.xs = new Float64Array(n);
  this.ys = new Float64Array(n);
  for (let i = 0; i < n; i++) [this.xs[i], this.ys[i]] = [xy[2 * i], xy[2 * i + 1]];
  const nn = typed(Float32Array, data.nn, "nn");
  if (nn.length !== n) throw new Error(`nn must hold ${n} radii`);
  this.nn = Float64Array.from(nn, (r) => (Number.isFinite(r) ? r : 0));
  this.tri = typed(Uint32Array, data.triangles, "triangles", 3);
  for (let h = 0; h < this.tri.length; h++) {
    if (!(this.tri[h] < n)) throw new Error(`triangle ${(h / 3) | 0} names a missing point`);
  }
  this.list = new EdgeList(this.tri, typed(Uint32Array, data.extra_edges, "extra_edges", 2), n);
  this.edges = {};
  const layers = data.layers || {};
  for (const name of Object.keys(layers)) {
    this.edges[name] = layers[name] === null ? null : this.list.select(bitsOf(layers[name], this.list.length, name));
  }
  this.trace = data.trace ? new Trace(data.trace, this.tri, this.list) : null;
  this.junctions = this.edges.result ? junctionsOf(this.edges.result, n) : null;
}

/** The points with three edges or more in a flat edge array [i0, j0, i1, j1, ...]. */
function junctionsOf(edges, n) {
  const degree = new Uint32Array(n);
  for (let k = 0; k < edges.length; k++) degree[edges[k]]++;
  const out = [];
  for (let v = 0; v < n; v++) if (degree[v] >= 3) out.push(v);
  return out;
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

function Trace(trace, tri, list) {
  const T = tri.length / 3;
  this.tri = tri;
  this.list = list;
  this.phases = trace.phases;
  this.labels = bitsOf(trace.initial_inside, T, "initial_inside");
  this.on = bitsOf(trace.initial_boundary, list.length, "initial_boundary"); // 1: on the boundary now
  // sideEdge[3t + k]: the edge of side k of triangle t, from its corner k to corner k + 1.
  this.sideEdge = new Uint32Array(3 * T);
  // left[e], right[e]: the triangle with edge e's ends in counter-clockwise, clockwise order
  // (-1: none), to fill the interior (see `sides`).
  this.left = new Int32Array(list.length).fill(-1);
  this.right = new Int32Array(list.length).fill(-1);
  for (let h = 0; h < 3 * T; h++) {
    const i = tri[h];
    const e = list.find(i, tri[h % 3 === 2 ? h - 2 : h + 1]);
    this.sideEdge[h] = e;
    (list.ei[e] === i ? this.left : this.right)[e] = (h / 3) | 0;
  }
  this.stepTriangle = typed(Uint32Array, trace.step_triangles, "step_triangles");
  const changes = typed(Uint8Array, trace.step_changes, "step_changes");
  const S = this.stepTriangle.length;
  if (changes.length !== S) throw new Error("step_changes must have one byte per step");
  this.stepSides = new Uint8Array(S); // bit k: side k of the step's triangle is toggled
  this.stepPhase = new Uint8Array(S);
  this.ordinal = new Uint32Array(S); // 1-based position among the steps of its phase
  this.totals = this.phases.map(() => 0);
  for (let k = 0; k < S; k++) {
    const phase = changes[k] >> 3;
    if (!(this.stepTriangle[k] < T)) throw new Error(`step ${k} names a missing triangle ${this.stepTriangle[k]}`);
    if (!(phase < this.phases.length)) throw new Error(`step ${k} has an unknown phase ${phase}`);
    this.stepSides[k] = changes[k] & 7;
    this.stepPhase[k] = phase;
    this.ordinal[k] = ++this.totals[phase];
  }
  this.steps = S;
  this.inflatedAt = Math.min(Math.max(trace.inflated_at | 0, 0), S);
  this.current = 0;
}

/** Applies step k to the current state, or undoes it if it is the last one applied. */
Trace.prototype.flip = function (k) {
  const t = this.stepTriangle[k];
  this.labels[t] ^= 1;
  for (let side = 0; side < 3; side++) {
    if ((this.stepSides[k] >> side) & 1) this.on[this.sideEdge[3 * t + side]] ^= 1;
  }
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
  return this.list.select(this.on);
};

/**
 * The boundary edges at the current step that have an interior triangle on one side, as a
 * flat array directed with that triangle on their left: the outline the interior is filled
 * through. Which edges are on the boundary is the trace's; this only orients them, and
 * leaves out the dangling ones (exterior on both sides), which bound no area.
 */
Trace.prototype.sides = function () {
  const { on, left, right, labels } = this;
  const { ei, ej } = this.list;
  const out = [];
  for (let e = 0; e < on.length; e++) {
    if (!on[e]) continue;
    if (left[e] >= 0 && labels[left[e]]) out.push(ei[e], ej[e]);
    else if (right[e] >= 0 && labels[right[e]]) out.push(ej[e], ei[e]);
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
