// ui.js: the layer legend, the step controls, export, mouse and keyboard; `start` runs the
// page.

const $ = (id) => document.getElementById(id);
const count = (n) => n.toLocaleString("en-US");
const short = (x) => String(Number(x.toPrecision(6)));

/** Legend rows with checkboxes (ids as in LAYERS); a layer without data is disabled. */
function buildLayers(model, view) {
  for (const el of document.querySelectorAll("[data-phase]")) {
    el.style.setProperty("--c", model.palette[el.dataset.phase]);
  }
  const list = $("layers");
  const trace = model.trace;
  const sizes = {
    points: model.n,
    sig: model.n,
    interior: trace ? trace.labels.length : null,
    current: trace ? trace.steps : null,
    changed: trace ? trace.steps : null,
    junctions: model.junctions && model.junctions.length ? model.junctions.length : null,
  };
  const stepLayers = ["interior", "current", "changed"];
  for (const layer of LAYERS) {
    const edges = model.edges[layer.id];
    const size = layer.id in sizes ? sizes[layer.id] : edges ? edges.length / 2 : null;
    const row = document.createElement("label");
    row.className = "layer";
    const input = document.createElement("input");
    input.type = "checkbox";
    input.id = layer.id;
    input.disabled = size === null || (trace === null && stepLayers.includes(layer.id));
    input.checked = !input.disabled && Boolean(layer.on[trace ? 0 : 1]);
    const swatch = document.createElement("span");
    const ring = layer.id === "sig" || layer.id === "junctions";
    swatch.className = `swatch swatch-${layer.fill ? "fill" : layer.id === "points" ? "dot" : ring ? "ring" : "line"}`;
    swatch.style.setProperty("--c", view.styles[layer.id].color);
    swatch.style.setProperty("--w", `${Math.min(layer.width || 2, 6)}px`);
    if (layer.dash) swatch.classList.add("dashed");
    const name = document.createElement("span");
    name.className = "name";
    name.textContent = layer.label;
    const n = document.createElement("span");
    n.className = "count";
    n.textContent = size === null ? "—" : stepLayers.includes(layer.id) ? "" : count(size);
    if (layer.id === "interior") n.id = "interior-count";
    if (input.disabled) row.classList.add("missing");
    row.append(input, swatch, name, n);
    list.append(row);
    view.visible[layer.id] = input.checked;
    input.addEventListener("change", () => {
      view.visible[layer.id] = input.checked;
      view.request();
    });
  }
}

/** The step slider, its buttons, the phase bar and the status text. */
function Stepper(model, view) {
  this.view = view;
  this.trace = model.trace;
  this.slider = $("step");
  this.playing = false;
  const trace = this.trace;
  if (!trace) {
    $("stepper").classList.add("no-trace");
    $("step-legend").hidden = true;
    for (const id of ["step", "back", "forward", "play"]) $(id).disabled = true;
    $("status").textContent = "no trace (method has no inflating/sculpting)";
    return;
  }
  const N = trace.steps;
  this.slider.max = N;
  this.rate = Math.max(4, N / 12); // steps per second when playing: about 12 s in all
  const totals = trace.phases.map((name, p) => `${count(trace.totals[p])} ${name}`);
  $("steps-summary").textContent = totals.join(" · ");
  this.phases(trace, view);
  this.slider.addEventListener("input", () => this.go(Number(this.slider.value), true));
  $("back").addEventListener("click", () => this.go(view.step - 1));
  $("forward").addEventListener("click", () => this.go(view.step + 1));
  $("play").addEventListener("click", () => this.toggle());
}

/** Colours the bar under the slider by the phase of each step; marks the inflated state. */
Stepper.prototype.phases = function (trace, view) {
  const N = trace.steps;
  const stops = [];
  let k = 0;
  while (k < N) {
    let end = k;
    while (end < N && trace.stepPhase[end] === trace.stepPhase[k]) end++;
    const color = view.palette[trace.phaseName(k)] || "#999";
    stops.push(`${color} ${((100 * k) / N).toFixed(3)}%`, `${color} ${((100 * end) / N).toFixed(3)}%`);
    k = end;
  }
  $("phases").style.background = stops.length ? `linear-gradient(to right, ${stops.join(", ")})` : "#ddd";
  $("inflated-mark").style.left = N ? `${(100 * trace.inflatedAt) / N}%` : "0";
  $("inflated-mark").title = `inflating ends after step ${trace.inflatedAt}`;
};

/** Shows step s; `fromSlider` when the user moved the slider (which then keeps its value). */
Stepper.prototype.go = function (s, fromSlider) {
  const trace = this.trace;
  if (!trace) return;
  if (!fromSlider) this.slider.value = String(clamp(s, 0, trace.steps));
  if (fromSlider || !this.ticking) this.stop();
  this.view.setStep(s);
  s = this.view.step;
  $("status").textContent = trace.label(s);
  let info = `step ${count(s)} / ${count(trace.steps)}`;
  if (s > 0) {
    const k = s - 1;
    const t = trace.stepTriangle[k];
    info += ` · triangle ${t} → ${trace.labels[t] ? "interior" : "exterior"}`;
  }
  if (s === trace.inflatedAt) info += " · inflated";
  $("stepinfo").textContent = info;
  $("interior-count").textContent = count(trace.insideCount());
};

Stepper.prototype.toggle = function () {
  if (this.playing) return this.stop();
  if (this.view.step >= this.trace.steps) this.go(0);
  this.playing = true;
  $("play").textContent = "❚❚ pause";
  let last = performance.now();
  let due = 0;
  const tick = (now) => {
    if (!this.playing) return;
    due += ((now - last) / 1000) * this.rate;
    last = now;
    if (due >= 1) {
      const k = Math.floor(due);
      due -= k;
      this.ticking = true;
      this.go(this.view.step + k);
      this.ticking = false;
    }
    if (this.view.step >= this.trace.steps) this.stop();
    else requestAnimationFrame(tick);
  };
  requestAnimationFrame(tick);
};

Stepper.prototype.stop = function () {
  this.playing = false;
  $("play").textContent = "▶ play";
};

/** A file name for an export of the current view: the title's first word and the step. */
function exportName(model, step, extension) {
  const base = model.title.replace(/\s*\(.*$/, "").replace(/[^\w.-]+/g, "_") || "sigdt-view";
  return model.trace ? `${base}-step-${step}.${extension}` : `${base}.${extension}`;
}

/** Saves `blob` as a download named `name`. */
function download(name, blob) {
  const link = document.createElement("a");
  link.href = URL.createObjectURL(blob);
  link.download = name;
  document.body.append(link);
  link.click();
  link.remove();
  setTimeout(() => URL.revokeObjectURL(link.href), 10000);
}

/** The PNG and SVG buttons: the current view, as drawn, without the hover ring. */
function bindExport(view) {
  $("export-png").addEventListener("click", () => {
    view.draw(view.ctx, false);
    view.canvas.toBlob((blob) => {
      download(exportName(view.model, view.step, "png"), blob);
      view.request();
    }, "image/png");
  });
  $("export-svg").addEventListener("click", () => {
    const blob = new Blob([view.svg()], { type: "image/svg+xml" });
    download(exportName(view.model, view.step, "svg"), blob);
  });
}

/** Drag to pan, wheel to zoom around the cursor, double-click to zoom in; hover names points. */
function bindCanvas(view) {
  const canvas = view.canvas;
  let drag = null;
  const at = (e) => {
    const r = canvas.getBoundingClientRect();
    return [e.clientX - r.left, e.clientY - r.top];
  };
  canvas.addEventListener("pointerdown", (e) => {
    if (e.button !== 0) return;
    drag = at(e);
    canvas.setPointerCapture(e.pointerId);
    canvas.classList.add("dragging");
  });
  canvas.addEventListener("pointermove", (e) => {
    const [x, y] = at(e);
    if (drag) {
      view.pan(x - drag[0], y - drag[1]);
      drag = [x, y];
      return;
    }
    const i = view.pick(x, y, 10);
    if (i !== view.hover) {
      view.hover = i;
      view.request();
      const m = view.model;
      $("hover").textContent =
        i < 0 ? "" : `point ${i} · (${short(m.xs[i])}, ${short(m.ys[i])}) · nn ${short(m.nn[i])}`;
    }
  });
  const end = () => {
    drag = null;
    canvas.classList.remove("dragging");
  };
  canvas.addEventListener("pointerup", end);
  canvas.addEventListener("pointercancel", end);
  canvas.addEventListener("pointerleave", () => {
    if (drag || view.hover < 0) return;
    view.hover = -1;
    $("hover").textContent = "";
    view.request();
  });
  canvas.addEventListener(
    "wheel",
    (e) => {
      e.preventDefault();
      const unit = e.deltaMode === 1 ? 32 : e.deltaMode === 2 ? 400 : 1;
      view.zoom(Math.exp(-e.deltaY * unit * 0.0015), ...at(e));
    },
    { passive: false },
  );
  canvas.addEventListener("dblclick", (e) => view.zoom(2, ...at(e)));
  $("fit").addEventListener("click", () => view.fit());
}

/** ←/→ step (with Shift: 10 steps), Home/End, space plays, F fits. */
function bindKeys(view, stepper) {
  document.addEventListener("keydown", (e) => {
    if (e.altKey || e.ctrlKey || e.metaKey) return;
    const onSlider = e.target === stepper.slider; // the slider handles its own keys
    const onControl = e.target instanceof HTMLButtonElement || e.target instanceof HTMLInputElement;
    const by = e.shiftKey ? 10 : 1;
    if (e.key === "ArrowLeft" && !onSlider) stepper.go(view.step - by);
    else if (e.key === "ArrowRight" && !onSlider) stepper.go(view.step + by);
    else if (e.key === "Home" && !onSlider) stepper.go(0);
    else if (e.key === "End" && !onSlider && stepper.trace) stepper.go(stepper.trace.steps);
    else if (e.key === " " && !onControl && stepper.trace) stepper.toggle();
    else if (e.key === "f" || e.key === "F") view.fit();
    else return;
    e.preventDefault();
  });
}

function start() {
  const model = new Model(JSON.parse($("data").textContent));
  const view = new View($("canvas"), model);
  document.title = model.title ? `${model.title} · sigdt view` : "sigdt view";
  $("title").textContent = model.title || "sigdt view";
  $("meta").textContent = [model.method, model.status].filter(Boolean).join(" · ");
  buildLayers(model, view);
  const stepper = new Stepper(model, view);
  bindCanvas(view);
  bindExport(view);
  bindKeys(view, stepper);
  view.resize();
  view.fit();
  // Open on the result; the slider goes back through the steps.
  stepper.go(model.trace ? model.trace.steps : 0);
  new ResizeObserver(() => {
    view.resize();
    view.draw();
  }).observe(view.canvas);
  window.sigdtView = { model, view, stepper };
}

try {
  start();
} catch (err) {
  $("error").textContent = `cannot show this data: ${err.message}`;
  $("error").hidden = false;
  throw err;
}
