// The fair-curves editor (doc/editor.md): points on an SVG canvas, every edit solved by the
// server (POST /api/solve answers the program's own JSON), the pieces drawn and their comb and
// kappa(s) plot evaluated here (curve.js), the certified extrema and inflections marked from
// POST /api/metrics. No framework, no build step, nothing fetched but the server's API.
import { sampleCurve, arcLengthAt } from './curve.js';
import { Channel, SolveSocket, postJSON, postForFile } from './api.js';
import { outcomeWords, fmt } from './status.js';
import { optionControl } from './options.js';
import { parsePointFile } from './pointfile.js';

const SVGNS = 'http://www.w3.org/2000/svg';
const $ = (id) => document.getElementById(id);

// The 9 methods of the API and their colours (the overlay legend uses the same).
const COLOURS = {
  kappa: '#2563eb', optimal: '#dc2626', cardinal: '#7c3aed', csr: '#059669', cubic: '#d97706',
  'catmull-rom': '#db2777', 'four-point': '#0891b2', quasi: '#65a30d', bspline: '#57534e',
};
const FALLBACK_METHODS = Object.keys(COLOURS).map((name) => ({ name, options: [] }));
// Options the page sets itself (closed) or the server refuses (outputs): never shown.
const HIDDEN_OPTIONS = new Set(['closed', 'output', 'svg', 'dxf', 'svg-path', 'plot', 'allow-unsolved', 'help', 'method']);
const MINIMUM_POINTS = { kappa: 3, csr: 3 };

const params = new URLSearchParams(location.search);
// The session id is a capability (whoever knows it can use the session): a CSPRNG's 122 bits
// (review s16 finding 13); 127.0.0.1 and localhost are secure contexts, where randomUUID exists.
const session = 'page-' + (globalThis.crypto && crypto.randomUUID ? crypto.randomUUID()
  : Array.from(crypto.getRandomValues(new Uint32Array(4)), (v) => v.toString(36)).join(''));

const state = {
  points: [],            // {x, y, corner: bool, tangent: bool, lambda: number|null}
  closed: false,
  method: 'kappa',
  overlay: new Set(),
  options: {},           // method -> {option name: value}
  perSegmentLambda: false,
  selected: -1,
  view: { scale: 60, ox: 60, oy: 420 },   // screen = (ox + scale x, oy - scale y)
  curves: {},            // method -> {curve, sampled, seq} | {error}
  metrics: null,         // {data, seq} of the primary curve
  methods: FALLBACK_METHODS,
  undo: [], redo: [],
  dragging: null,
};

// What the browser test reads: the round trips of the primary solves (edit -> answer drawn).
const stats = { roundTrips: [], phases: [], solves: 0, metrics: 0, lastExport: null, errors: 0 };
window.fairEditor = { state, stats };

// ---------------------------------------------------------------- coordinates
const canvas = $('canvas');
function toScreen(x, y) { return [state.view.ox + state.view.scale * x, state.view.oy - state.view.scale * y]; }
function toWorld(sx, sy) { return [(sx - state.view.ox) / state.view.scale, (state.view.oy - sy) / state.view.scale]; }
function eventPoint(ev) {
  const r = canvas.getBoundingClientRect();
  return [ev.clientX - r.left, ev.clientY - r.top];
}
// Clicked coordinates rounded to a tenth of a pixel's size, in a decimal step (short files).
function roundWorld(v) {
  const step = Math.pow(10, Math.floor(Math.log10(0.1 / state.view.scale)));
  return Math.round(v / step) * step;
}
// Screen coordinates in path data: a tenth of a pixel (faster than toFixed on thousands).
const n2 = (v) => String(Math.round(v * 10) / 10);

// The sizes of the canvas and the plot, read on start and on resize only: reading them while
// drawing would force a layout of the half-built SVG on every answer of a drag.
const sizes = { canvas: { w: 800, h: 500 }, plot: { w: 800, h: 150 } };
function measure() {
  sizes.canvas = { w: canvas.clientWidth || 800, h: canvas.clientHeight || 500 };
  sizes.plot = { w: $('plot').clientWidth || 800, h: $('plot').clientHeight || 150 };
}

function fitView() {
  const { w, h } = sizes.canvas;
  const pts = state.points;
  if (pts.length < 2) {
    state.view = { scale: w / 12, ox: w / 12, oy: h - h / 8 };
    return;
  }
  let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
  for (const p of pts) { x0 = Math.min(x0, p.x); x1 = Math.max(x1, p.x); y0 = Math.min(y0, p.y); y1 = Math.max(y1, p.y); }
  const dx = Math.max(x1 - x0, 1e-9), dy = Math.max(y1 - y0, 1e-9);
  const scale = Math.min((w * 0.7) / dx, (h * 0.6) / dy);
  state.view = { scale, ox: w / 2 - scale * (x0 + x1) / 2, oy: h / 2 + scale * (y0 + y1) / 2 };
}

// ---------------------------------------------------------------- requests
function methodInfo(name) { return state.methods.find((m) => m.name === name) || { name, options: [] }; }

function globalLambda() {
  const v = Number((state.options.optimal || {}).lambda);
  return Number.isFinite(v) && (state.options.optimal || {}).lambda !== '' ? v : 0.7;
}

// The "options" of a solve request of `method`: the panel's values, the corners and the
// per-segment lambdas (file options as rows, doc/editor_api.md).
function requestOptions(method) {
  const out = {};
  const values = state.options[method] || {};
  for (const [name, value] of Object.entries(values)) {
    if (value === '' || value === false || value === null || value === undefined) continue;
    if (method === 'optimal' && state.perSegmentLambda && name === 'lambda') continue;
    out[name] = value;
  }
  if (method === 'optimal') {
    const n = state.points.length;
    const rows = [];
    state.points.forEach((p, i) => {
      if (!p.corner) return;
      if (!state.closed && (i === 0 || i === n - 1)) return;
      const a = state.points[(i - 1 + n) % n], b = state.points[(i + 1) % n];
      rows.push([i, p.x - a.x, p.y - a.y, b.x - p.x, b.y - p.y]);
    });
    if (rows.length) out.corners = rows;
    // Tangent constraints: the direction of the chord of the neighbours (at an open end: of the
    // end segment), after the rows typed into the tangents field.
    const tangents = [];
    state.points.forEach((p, i) => {
      if (!p.tangent || n < 2) return;
      const a = state.points[!state.closed && i === 0 ? 0 : (i - 1 + n) % n];
      const b = state.points[!state.closed && i === n - 1 ? n - 1 : (i + 1) % n];
      tangents.push([i, b.x - a.x, b.y - a.y]);
    });
    if (tangents.length) out.tangents = [...(Array.isArray(out.tangents) ? out.tangents : []), ...tangents];
    if (state.perSegmentLambda) {
      const segments = state.closed ? n : n - 1;
      const g = globalLambda();
      out['lambda-file'] = Array.from({ length: Math.max(segments, 0) }, (_, i) => state.points[i].lambda ?? g);
    }
  }
  return out;
}

function solveBody(method, withSession) {
  const body = { method, points: state.points.map((p) => [p.x, p.y]), closed: state.closed, options: requestOptions(method) };
  if (withSession && method === 'kappa') body.session = session;
  return body;
}

// Samples per piece for the curve, the comb and the plot: 24, fewer on long curves (about 1500
// in all, at least 3 a piece), so that an answer is drawn within a frame.
function samplesPerPiece(pieces) { return Math.max(3, Math.min(24, Math.ceil(1500 / Math.max(pieces, 1)))); }

function enoughPoints(method) { return state.points.length >= (MINIMUM_POINTS[method] || 2); }

// The drag steps (kappa session) go over the WebSocket while it is open (doc/editor_api.md).
const solveSocket = new SolveSocket('/api/ws');
const primary = new Channel('/api/solve', onPrimaryAnswer, solveSocket);
const overlayChannels = {};
const metricsChannel = new Channel('/api/metrics', onMetricsAnswer);
let metricsTimer = 0;

function overlayChannel(method) {
  if (!overlayChannels[method]) overlayChannels[method] = new Channel('/api/solve', (r, tag) => onOverlayAnswer(method, r, tag));
  return overlayChannels[method];
}

// Every edit ends here: draw the points now, ask the server for the curves.
function changed(t0 = performance.now()) {
  renderPoints();
  renderPointPanel();
  requestSolves(t0);
}

function requestSolves(t0 = performance.now()) {
  if (enoughPoints(state.method)) {
    // Warm (a kappa session) only while a point is dragged: a warm start may settle on another root
    // of the kappa system than a fresh solve (the review of the server measured up to 0.56 on a
    // curve 2.5 across), so every other edit, and the end of a drag, is solved fresh: what stays on
    // the screen is what the program and the export give.
    const dragging = Boolean(state.dragging && state.dragging.moved && !state.dragging.pan);
    primary.submit(solveBody(state.method, dragging), { method: state.method, t0 });
  } else {
    primary.reset();
    delete state.curves[state.method];
    state.metrics = null;
    setStatus('muted', state.points.length === 0 ? 'Click on the canvas to add points.'
      : `${state.method}: needs at least ${MINIMUM_POINTS[state.method] || 2} points`);
    renderCurve();
  }
  for (const m of state.overlay) {
    if (m === state.method) continue;
    if (enoughPoints(m)) overlayChannel(m).submit(solveBody(m, false), { method: m });
    else { overlayChannel(m).reset(); state.curves[m] = { error: 'too few points' }; }
  }
  renderOverlays();
}

function onPrimaryAnswer(result, tag, seq, timing) {
  if (tag.method !== state.method) return;
  stats.solves++;
  if (result.ok) {
    const curve = result.data;
    state.curves[tag.method] = { curve, sampled: sampleCurve(curve.pieces, samplesPerPiece(curve.pieces.length)), seq };
    const w = outcomeWords(tag.method, curve);
    setStatus(w.level, w.text, curve);
  } else {
    stats.errors++;
    state.curves[tag.method] = { error: result.data.error, status: result.status };
    setStatus('bad', `${tag.method}: ${result.data.error}` + (result.status ? ` (HTTP ${result.status})` : ''));
  }
  state.metrics = null;
  renderCurve();
  renderOverlays();
  const dt = performance.now() - tag.t0;
  stats.roundTrips.push(dt);
  // Where the time went: before the request left, the request (server and transfer, answer
  // parsed), the drawing.
  stats.phases.push({ queued: timing.sent - tag.t0, request: timing.received - timing.sent, server: result.serverMs,
    draw: performance.now() - timing.received, via: result.via });
  $('timing').textContent = `round trip ${dt.toFixed(1)} ms`;
  scheduleMetrics();
}

function onOverlayAnswer(method, result) {
  if (!state.overlay.has(method)) return;
  state.curves[method] = result.ok ? { curve: result.data, sampled: sampleCurve(result.data.pieces, samplesPerPiece(result.data.pieces.length) >> 1) }
    : { error: result.data.error };
  renderOverlays();
}

// The certified markers: asked for 250 ms after the last primary answer, so a drag never
// waits for them (they are hidden while the curve moves).
function scheduleMetrics() {
  clearTimeout(metricsTimer);
  metricsTimer = 0;
  renderMetrics();
  const c = state.curves[state.method];
  if (!c || !c.curve) return;
  metricsTimer = setTimeout(() => {
    metricsTimer = 0;
    const now = state.curves[state.method];
    if (now !== c) return;
    metricsChannel.submit({ curve: c.curve, samples: 8 }, { seq: c.seq, method: state.method });
  }, 250);
}

function onMetricsAnswer(result, tag) {
  const c = state.curves[state.method];
  if (!c || c.seq !== tag.seq || tag.method !== state.method) return;  // the curve moved on
  stats.metrics++;
  state.metrics = result.ok ? { data: result.data, seq: tag.seq } : { error: result.data.error };
  renderMarkers();
  renderMetrics();
}

// ---------------------------------------------------------------- status line
function setStatus(level, text, curve) {
  const bar = $('statusbar');
  bar.className = level;
  $('status').textContent = text;
  $('status').title = text;
  const s = curve && (curve.report && curve.report.status || curve.status);
  bar.dataset.status = s || (level === 'bad' ? 'error' : '');
}

// ---------------------------------------------------------------- drawing
function el(tag, attrs, parent) {
  const e = document.createElementNS(SVGNS, tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  if (parent) parent.appendChild(e);
  return e;
}

function pathOfSamples(samples) {
  let d = '';
  for (let i = 0; i < samples.length; ++i) {
    const [x, y] = toScreen(samples[i].x, samples[i].y);
    d += (i ? 'L' : 'M') + n2(x) + ' ' + n2(y);
  }
  return d;
}

function renderGrid() {
  const g = $('grid');
  g.replaceChildren();
  const { w, h } = sizes.canvas;
  const [wx0, wy1] = toWorld(0, 0), [wx1, wy0] = toWorld(w, h);
  // A minor step of 15-75 pixels in a 1-2-5 decade, majors every 5.
  let step = Math.pow(10, Math.floor(Math.log10(15 / state.view.scale)));
  for (const f of [1, 2, 5, 10]) if (f * step * state.view.scale >= 15) { step *= f; break; }
  let d1 = '', d2 = '';
  for (let i = Math.ceil(wx0 / step); i * step <= wx1; ++i) {
    const [x] = toScreen(i * step, 0);
    if (i % 5 === 0) d2 += `M${n2(x)} 0V${h}`; else d1 += `M${n2(x)} 0V${h}`;
  }
  for (let j = Math.ceil(wy0 / step); j * step <= wy1; ++j) {
    const [, y] = toScreen(0, j * step);
    if (j % 5 === 0) d2 += `M0 ${n2(y)}H${w}`; else d1 += `M0 ${n2(y)}H${w}`;
  }
  el('path', { d: d1, class: 'grid-minor' }, g);
  el('path', { d: d2, class: 'grid-major' }, g);
  const [ax, ay] = toScreen(0, 0);
  el('path', { d: `M${n2(ax)} 0V${h}M0 ${n2(ay)}H${w}`, class: 'grid-axis' }, g);
}

function renderPoints() {
  const g = $('points');
  const pts = state.points;
  while (g.childNodes.length > 2 * pts.length) g.lastChild.remove();
  while (g.childNodes.length < 2 * pts.length) {
    const i = g.childNodes.length / 2;
    el('circle', { r: 5, class: 'point', 'data-index': i }, g);
    el('text', { class: 'point-label' }, g);
  }
  const corners = state.method === 'optimal';
  pts.forEach((p, i) => {
    const [x, y] = toScreen(p.x, p.y);
    const c = g.childNodes[2 * i], t = g.childNodes[2 * i + 1];
    // Only what changed is written (a drag moves one point of a hundred: one style recalculation).
    const key = `${n2(x)} ${n2(y)} ${i === state.selected} ${corners && p.corner} ${corners && p.tangent} ${i} ${pts.length <= 60}`;
    if (c.__drawn === key) return;
    c.__drawn = key;
    c.setAttribute('cx', n2(x)); c.setAttribute('cy', n2(y));
    c.setAttribute('data-index', i);
    c.setAttribute('r', i === state.selected ? 6 : 5);
    c.setAttribute('class', 'point' + (i === state.selected ? ' selected' : '') + (corners && p.corner ? ' corner' : '') +
      (corners && p.tangent ? ' tangent' : ''));
    t.setAttribute('x', n2(x + 7)); t.setAttribute('y', n2(y - 7));
    // Index labels while they can be read (a dense sample set would be a smudge of digits).
    t.textContent = pts.length <= 60 ? String(i) : '';
  });
  let d = '';
  pts.forEach((p, i) => { const [x, y] = toScreen(p.x, p.y); d += (i ? 'L' : 'M') + n2(x) + ' ' + n2(y); });
  if (state.closed && pts.length > 2) d += 'Z';
  $('polygon').setAttribute('d', $('show-polygon').checked ? d : '');
}

function combScale(sampled) {
  // |kappa| at the 95th percentile drawn as 12% of the smaller side of the canvas, times the slider.
  const ks = sampled.samples.map((s) => Math.abs(s.k)).filter(Number.isFinite).sort((a, b) => a - b);
  const k95 = ks.length ? ks[Math.floor(0.95 * (ks.length - 1))] : 0;
  if (!(k95 > 0)) return 0;
  const px = 0.12 * Math.min(sizes.canvas.w, sizes.canvas.h) * Math.pow(10, Number($('comb-scale').value));
  return px / state.view.scale / k95;   // world units per unit of curvature
}

function renderCurve() {
  const c = state.curves[state.method];
  const colour = COLOURS[state.method] || '#2563eb';
  const curve = $('curve'), comb = $('comb'), env = $('comb-envelope');
  curve.style.stroke = colour; comb.style.stroke = colour; env.style.stroke = colour;
  if (!c || !c.curve) {
    curve.setAttribute('d', ''); comb.setAttribute('d', ''); env.setAttribute('d', ''); $('controls').setAttribute('d', '');
    renderPlot(); renderMarkers();
    return;
  }
  const samples = c.sampled.samples;
  curve.setAttribute('d', pathOfSamples(samples));
  if ($('show-comb').checked) {
    const k = combScale(c.sampled);
    let teeth = '', hull = '';
    // Every sample on the envelope, at most about 400 teeth (a dense fan hides the curve).
    const stride = Math.max(1, Math.round(samples.length / 400));
    samples.forEach((s, i) => {
      // The tooth points away from the centre of curvature: -kappa times the left normal.
      const [x1, y1] = toScreen(s.x - k * s.k * s.nx, s.y - k * s.k * s.ny);
      if (i % stride === 0) {
        const [x0, y0] = toScreen(s.x, s.y);
        teeth += `M${n2(x0)} ${n2(y0)}L${n2(x1)} ${n2(y1)}`;
      }
      hull += (i ? 'L' : 'M') + n2(x1) + ' ' + n2(y1);
    });
    comb.setAttribute('d', teeth); env.setAttribute('d', hull);
  } else { comb.setAttribute('d', ''); env.setAttribute('d', ''); }
  if ($('show-controls').checked) {
    let d = '';
    for (const piece of c.curve.pieces)
      piece.control_points.forEach((p, i) => { const [x, y] = toScreen(p[0], p[1]); d += (i ? 'L' : 'M') + n2(x) + ' ' + n2(y); });
    $('controls').setAttribute('d', d);
  } else $('controls').setAttribute('d', '');
  renderPlot();
  renderMarkers();
}

// The legend over the canvas: the method drawn with its comb, then the overlaid ones.
function renderLegend() {
  const box = $('legend');
  box.replaceChildren();
  const shown = [state.method, ...[...state.overlay].filter((m) => m !== state.method)];
  if (shown.length < 2) return;
  for (const m of shown) {
    const row = document.createElement('div');
    row.innerHTML = `<span class="swatch"></span> ${m}${m === state.method ? ' <span class="muted">(comb, plot)</span>' : ''}`;
    row.querySelector('.swatch').style.background = COLOURS[m];  // CSSOM: no inline style for the CSP
    box.appendChild(row);
  }
}

function renderOverlays() {
  renderLegend();
  const g = $('overlays');
  g.replaceChildren();
  for (const m of state.overlay) {
    if (m === state.method) continue;
    const c = state.curves[m];
    if (c && c.curve) el('path', { d: pathOfSamples(c.sampled.samples), class: 'overlay', stroke: COLOURS[m], 'data-method': m }, g);
  }
  for (const m of Object.keys(COLOURS)) {
    const e = document.querySelector(`#overlay-list [data-error="${m}"]`);
    if (!e) continue;
    const c = state.curves[m];
    e.textContent = state.overlay.has(m) && m !== state.method && c && c.error ? c.error : '';
  }
}

function renderMarkers() {
  const g = $('markers');
  g.replaceChildren();
  $('plot-markers').replaceChildren();
  const c = state.curves[state.method];
  if (!$('show-markers').checked || !state.metrics || !state.metrics.data || !c || c.seq !== state.metrics.seq) return;
  const m = state.metrics.data;
  for (const e of m.curvature_extrema || []) {
    const [x, y] = toScreen(e.x, e.y);
    el('path', { d: `M${n2(x)} ${n2(y - 5)}l5 5l-5 5l-5 -5z`, class: 'marker-extremum' }, g)
      .appendChild(document.createElementNS(SVGNS, 'title')).textContent = `curvature extremum ${fmt(e.curvature, 6)} (piece ${e.piece}, t ${fmt(e.t, 6)})`;
  }
  for (const e of m.inflections || []) {
    const [x, y] = toScreen(e.x, e.y);
    el('circle', { cx: n2(x), cy: n2(y), r: 4, class: 'marker-inflection' }, g)
      .appendChild(document.createElementNS(SVGNS, 'title')).textContent = `inflection (piece ${e.piece}, t ${fmt(e.t, 6)})`;
  }
  if (plotMap) {
    const pg = $('plot-markers');
    for (const e of m.curvature_extrema || []) {
      const [x, y] = plotMap(arcLengthAt(c.sampled, e.piece, e.t), e.curvature);
      el('path', { d: `M${n2(x)} ${n2(y - 4)}l4 4l-4 4l-4 -4z`, class: 'marker-extremum' }, pg);
    }
    for (const e of m.inflections || []) {
      const [x, y] = plotMap(arcLengthAt(c.sampled, e.piece, e.t), 0);
      el('circle', { cx: n2(x), cy: n2(y), r: 3.5, class: 'marker-inflection' }, pg);
    }
  }
}

let plotMap = null;
function renderPlot() {
  const plot = $('plot');
  const { w, h } = sizes.plot;
  const c = state.curves[state.method];
  $('plot-joins').replaceChildren();
  $('plot-axes').replaceChildren();
  $('plot-curve').style.stroke = COLOURS[state.method];
  if (!c || !c.curve || !(c.sampled.length > 0)) {
    $('plot-curve').setAttribute('d', ''); $('plot-zero').setAttribute('d', ''); plotMap = null;
    return;
  }
  const samples = c.sampled.samples;
  let kmax = 0;
  for (const s of samples) if (Number.isFinite(s.k)) kmax = Math.max(kmax, Math.abs(s.k));
  kmax = kmax > 0 ? kmax : 1;
  const left = 44, right = 12, L = c.sampled.length;
  plotMap = (s, k) => [left + (w - left - right) * s / L, h / 2 - (h / 2 - 14) * k / kmax];
  let d = '';
  samples.forEach((s, i) => { const [x, y] = plotMap(s.s, s.k); d += (i ? 'L' : 'M') + n2(x) + ' ' + n2(y); });
  $('plot-curve').setAttribute('d', d);
  const [zx0, zy] = plotMap(0, 0), [zx1] = plotMap(L, 0);
  $('plot-zero').setAttribute('d', `M${n2(zx0)} ${n2(zy)}H${n2(zx1)}`);
  let joins = '';
  // The joins of the pieces, when they are few enough to read (an optimal curve has hundreds).
  if (c.sampled.starts.length <= 40) for (const a of c.sampled.starts.slice(1)) { const [x] = plotMap(samples[a].s, 0); joins += `M${n2(x)} 8V${h - 8}`; }
  el('path', { d: joins, class: 'plot-join' }, $('plot-joins'));
  const axes = $('plot-axes');
  for (const k of [kmax, -kmax]) {
    const [, y] = plotMap(0, k);
    el('text', { x: 4, y: n2(y + 4), class: 'plot-tick' }, axes).textContent = fmt(k, 3);
  }
  el('text', { x: n2(w - right), y: h - 4, class: 'plot-tick', 'text-anchor': 'end' }, axes).textContent = `s = ${fmt(L, 4)}`;
}

function renderAll() {
  renderGrid();
  renderPoints();
  renderCurve();
  renderOverlays();
}

function renderMetrics() {
  const box = $('metrics');
  const m = state.metrics;
  if (!m) { box.textContent = state.curves[state.method] && state.curves[state.method].curve ? 'measuring…' : '—'; box.className = 'muted'; return; }
  if (m.error) { box.textContent = m.error; box.className = 'overlay-error'; return; }
  const d = m.data;
  const rows = [
    ['arc length', fmt(d.arc_length, 6)], ['bending energy ∫κ² ds', fmt(d.bending_energy, 6)],
    ['curvature variation ∫κ\'² ds', fmt(d.curvature_variation_arc_length, 6)],
    ['κ range', `${fmt(d.min_curvature, 4)} … ${fmt(d.max_curvature, 4)}`],
    ['curvature extrema', String((d.curvature_extrema || []).length)], ['inflections', String((d.inflections || []).length)],
    ['certified', d.certified ? 'yes' : 'no'],
  ];
  box.className = '';
  box.replaceChildren();
  const table = document.createElement('table');
  for (const [k, v] of rows) {
    const tr = table.insertRow();
    tr.insertCell().textContent = k;
    tr.insertCell().textContent = v;
  }
  box.appendChild(table);
}

// ---------------------------------------------------------------- side panel
function buildMethodSelect() {
  const sel = $('method');
  sel.replaceChildren();
  for (const m of state.methods) {
    const o = document.createElement('option');
    o.value = m.name;
    o.textContent = m.name;
    sel.appendChild(o);
  }
  sel.value = state.method;
}

function buildOverlayList() {
  const box = $('overlay-list');
  box.replaceChildren();
  for (const m of state.methods) {
    const label = document.createElement('label');
    label.className = 'toggle';
    label.innerHTML = `<input type="checkbox" data-overlay="${m.name}"> <span class="swatch"></span> ${m.name} <span class="overlay-error" data-error="${m.name}"></span>`;
    label.querySelector('.swatch').style.background = COLOURS[m.name];
    const box2 = label.querySelector('input');
    box2.checked = state.overlay.has(m.name);
    box2.addEventListener('change', () => {
      if (box2.checked) state.overlay.add(m.name); else { state.overlay.delete(m.name); overlayChannel(m.name).reset(); }
      requestSolves();
    });
    box.appendChild(label);
  }
}

function buildOptions() {
  const box = $('options');
  box.replaceChildren();
  $('options-method').textContent = '· ' + state.method;
  const info = methodInfo(state.method);
  const values = state.options[state.method] || (state.options[state.method] = {});
  const opts = (info.options || []).filter((o) => !HIDDEN_OPTIONS.has(o.name));
  if (!opts.length) { box.innerHTML = '<span class="muted">none</span>'; return; }
  for (const opt of opts) {
    const div = document.createElement('div');
    div.className = 'opt';
    div.dataset.option = opt.name;
    const name = document.createElement('div');
    name.className = 'name';
    name.textContent = opt.name;
    const help = document.createElement('div');
    help.className = 'help';
    help.textContent = opt.help || '';
    const set = (v) => { values[opt.name] = v; primary.reset(); requestSolves(); };
    const perSegment = { get: () => state.perSegmentLambda, set: (v) => { state.perSegmentLambda = v; renderPointPanel(); requestSolves(); } };
    div.append(name, optionControl(opt, values[opt.name], set, perSegment), help);
    box.appendChild(div);
  }
}

function renderPointPanel() {
  const box = $('point-panel');
  const i = state.selected;
  if (i < 0 || i >= state.points.length) { box.innerHTML = '<span class="muted">none: click a point</span>'; return; }
  const p = state.points[i];
  box.replaceChildren();
  const line = document.createElement('div');
  line.textContent = `point ${i}: (${fmt(p.x, 6)}, ${fmt(p.y, 6)})`;
  box.appendChild(line);
  if (state.method === 'optimal') {
    const n = state.points.length;
    const endpoint = !state.closed && (i === 0 || i === n - 1);
    const c = document.createElement('label');
    c.innerHTML = '<input type="checkbox" id="corner-toggle"> corner (tangents from the neighbours)';
    const cb = c.querySelector('input');
    cb.checked = p.corner; cb.disabled = endpoint;
    cb.addEventListener('change', () => { pushUndo(); p.corner = cb.checked; changed(); });
    box.appendChild(c);
    const t = document.createElement('label');
    t.innerHTML = '<input type="checkbox" id="tangent-toggle"> tangent along the neighbours\' chord (T)';
    const tb = t.querySelector('input');
    tb.checked = !!p.tangent;
    tb.addEventListener('change', () => { pushUndo(); p.tangent = tb.checked; changed(); });
    box.appendChild(t);
    if (state.perSegmentLambda && (state.closed || i < n - 1)) {
      const l = document.createElement('label');
      const v = p.lambda ?? globalLambda();
      l.innerHTML = `λ of segment ${i}→${(i + 1) % n} <input type="range" min="0" max="1" step="0.01"> <span></span>`;
      const r = l.querySelector('input'), out = l.querySelector('span');
      r.value = v; out.textContent = Number(v).toFixed(2);
      r.addEventListener('input', () => { p.lambda = Number(r.value); out.textContent = Number(r.value).toFixed(2); requestSolves(); });
      box.appendChild(l);
    }
  }
}

// ---------------------------------------------------------------- editing
function snapshot() { return JSON.stringify({ points: state.points, closed: state.closed }); }
function pushUndo() { state.undo.push(snapshot()); if (state.undo.length > 500) state.undo.shift(); state.redo = []; }
function restore(s) {
  const o = JSON.parse(s);
  state.points = o.points; state.closed = o.closed;
  $('closed').checked = state.closed;
  if (state.selected >= state.points.length) state.selected = -1;
  // Undoing a load brings back points the view may no longer show: fit when one is outside.
  const outside = state.points.some((p) => {
    const [x, y] = toScreen(p.x, p.y);
    return x < 0 || y < 0 || x > sizes.canvas.w || y > sizes.canvas.h;
  });
  if (outside) { fitView(); renderAll(); }
  primary.reset();
  changed();
}
function undo() { if (state.undo.length) { state.redo.push(snapshot()); restore(state.undo.pop()); } }
function redo() { if (state.redo.length) { state.undo.push(snapshot()); restore(state.redo.pop()); } }

function removePoint(i) {
  if (i < 0 || i >= state.points.length) return;
  pushUndo();
  state.points.splice(i, 1);
  state.selected = -1;
  changed();
}

// Where a click adds its point: into the nearest edge of the point polygon when within 8 pixels
// of it, else after the last point.
function insertionIndex(sx, sy) {
  const pts = state.points.map((p) => toScreen(p.x, p.y));
  const n = pts.length;
  let best = -1, bestD = 8;
  const edges = state.closed ? n : n - 1;
  for (let i = 0; i < edges; ++i) {
    const [ax, ay] = pts[i], [bx, by] = pts[(i + 1) % n];
    const vx = bx - ax, vy = by - ay, l2 = vx * vx + vy * vy;
    const u = l2 > 0 ? Math.max(0, Math.min(1, ((sx - ax) * vx + (sy - ay) * vy) / l2)) : 0;
    const d = Math.hypot(ax + u * vx - sx, ay + u * vy - sy);
    if (d < bestD && u > 0 && u < 1) { bestD = d; best = i + 1; }
  }
  return best < 0 ? n : best;
}

canvas.addEventListener('pointerdown', (ev) => {
  canvas.focus();
  const [sx, sy] = eventPoint(ev);
  const t = ev.target;
  if (ev.button === 1 || (ev.button === 0 && ev.shiftKey && !(t.classList && t.classList.contains('point')))) {
    state.dragging = { pan: true, sx, sy, ox: state.view.ox, oy: state.view.oy };
  } else if (ev.button !== 0) {
    return;
  } else if (t.classList && t.classList.contains('point')) {
    const i = Number(t.getAttribute('data-index'));
    state.selected = i;
    state.dragging = { index: i, sx, sy, moved: false };
    renderPoints(); renderPointPanel();
  } else {
    pushUndo();
    const i = insertionIndex(sx, sy);
    const [x, y] = toWorld(sx, sy);
    state.points.splice(i, 0, { x: roundWorld(x), y: roundWorld(y), corner: false, tangent: false, lambda: null });
    state.selected = i;
    state.dragging = { index: i, sx, sy, moved: true, added: true };
    changed();
  }
  canvas.setPointerCapture(ev.pointerId);
  ev.preventDefault();
});

canvas.addEventListener('pointermove', (ev) => {
  const d = state.dragging;
  if (!d) return;
  const t0 = performance.now();
  const [sx, sy] = eventPoint(ev);
  if (d.pan) {
    state.view.ox = d.ox + sx - d.sx; state.view.oy = d.oy + sy - d.sy;
    renderAll();
    return;
  }
  if (!d.moved) {
    if (Math.hypot(sx - d.sx, sy - d.sy) < 3) return;
    pushUndo();
    d.moved = true;
  }
  const [x, y] = toWorld(sx, sy);
  const p = state.points[d.index];
  p.x = roundWorld(x); p.y = roundWorld(y);
  changed(t0);
});

function endDrag(ev) {
  if (!state.dragging) return;
  const moved = state.dragging.moved && !state.dragging.pan;
  state.dragging = null;
  if (canvas.hasPointerCapture(ev.pointerId)) canvas.releasePointerCapture(ev.pointerId);
  if (moved) requestSolves();  // the fresh solve of the final position (see requestSolves)
}
canvas.addEventListener('pointerup', endDrag);
canvas.addEventListener('pointercancel', endDrag);

// The point within 8 pixels of (sx, sy), the nearest; -1 if none. (A double-click's target is the
// canvas, which captured the pointer, not the point's circle.)
function pointAt(sx, sy) {
  let best = -1, bestD = 8;
  state.points.forEach((p, i) => {
    const [x, y] = toScreen(p.x, p.y);
    const d = Math.hypot(x - sx, y - sy);
    if (d <= bestD) { bestD = d; best = i; }
  });
  return best;
}

canvas.addEventListener('dblclick', (ev) => {
  const i = pointAt(...eventPoint(ev));
  if (i >= 0) removePoint(i);
});

canvas.addEventListener('wheel', (ev) => {
  ev.preventDefault();
  const [sx, sy] = eventPoint(ev);
  const f = Math.exp(-ev.deltaY * 0.0015);
  const v = state.view;
  v.ox = sx - (sx - v.ox) * f; v.oy = sy - (sy - v.oy) * f; v.scale *= f;
  renderAll();
}, { passive: false });

window.addEventListener('keydown', (ev) => {
  const tag = (ev.target.tagName || '').toLowerCase();
  if (tag === 'input' || tag === 'textarea' || tag === 'select') return;
  const ctrl = ev.ctrlKey || ev.metaKey;
  if (ctrl && (ev.key === 'z' || ev.key === 'Z')) { ev.shiftKey ? redo() : undo(); ev.preventDefault(); return; }
  if (ctrl && ev.key === 'y') { redo(); ev.preventDefault(); return; }
  const i = state.selected;
  if ((ev.key === 'Delete' || ev.key === 'Backspace') && i >= 0) { removePoint(i); ev.preventDefault(); return; }
  if (ev.key === 'Escape') { state.selected = -1; renderPoints(); renderPointPanel(); return; }
  if (ev.key === 'f' || ev.key === 'F') { fitView(); renderAll(); return; }
  if ((ev.key === 'c' || ev.key === 'C') && i >= 0 && state.method === 'optimal') {
    const n = state.points.length;
    if (state.closed || (i > 0 && i < n - 1)) { pushUndo(); state.points[i].corner = !state.points[i].corner; changed(); }
    return;
  }
  if ((ev.key === 't' || ev.key === 'T') && i >= 0 && state.method === 'optimal') {
    pushUndo(); state.points[i].tangent = !state.points[i].tangent; changed();
    return;
  }
  const arrows = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, 1], ArrowDown: [0, -1] };
  if (arrows[ev.key] && i >= 0) {
    // One pixel (ten with Shift) in world units.
    const step = (ev.shiftKey ? 10 : 1) / state.view.scale;
    pushUndo();
    const p = state.points[i];
    p.x = roundWorld(p.x + arrows[ev.key][0] * step); p.y = roundWorld(p.y + arrows[ev.key][1] * step);
    changed();
    ev.preventDefault();
  }
});

// ---------------------------------------------------------------- files
function download(blob, filename) {
  const a = document.createElement('a');
  a.href = URL.createObjectURL(blob);
  a.download = filename;
  document.body.appendChild(a);
  a.click();
  setTimeout(() => { URL.revokeObjectURL(a.href); a.remove(); }, 1000);
}

function loadPoints(points, closed) {
  pushUndo();
  state.points = points.map(([x, y]) => ({ x, y, corner: false, tangent: false, lambda: null }));
  state.closed = closed;
  $('closed').checked = closed;
  state.selected = -1;
  primary.reset();
  fitView();
  renderAll();
  changed();
}

$('load').addEventListener('change', async (ev) => {
  const f = ev.target.files[0];
  if (!f) return;
  try {
    const { points, closed } = parsePointFile(await f.text());
    loadPoints(points, closed);
  } catch (e) {
    setStatus('bad', `${f.name}: ${e.message}`);
  }
  ev.target.value = '';
});
$('save-json').addEventListener('click', () => {
  const text = JSON.stringify({ points: state.points.map((p) => [p.x, p.y]), closed: state.closed }) + '\n';
  download(new Blob([text], { type: 'application/json' }), 'points.json');
});
$('save-csv').addEventListener('click', () => {
  const text = state.points.map((p) => `${p.x},${p.y}`).join('\n') + '\n';
  download(new Blob([text], { type: 'text/csv' }), 'points.csv');
});
for (const b of document.querySelectorAll('button.export')) {
  b.addEventListener('click', async () => {
    if (!enoughPoints(state.method)) { setStatus('bad', 'export: too few points'); return; }
    const body = solveBody(state.method, false);
    body.format = b.dataset.format;
    const r = await postForFile('/api/export', body);
    if (!r.ok) { setStatus('bad', `export ${b.dataset.format}: ${r.error} (HTTP ${r.status})`); return; }
    stats.lastExport = { format: b.dataset.format, filename: r.filename, size: r.blob.size };
    download(r.blob, r.filename);
  });
}

// ---------------------------------------------------------------- toolbar
$('method').addEventListener('change', () => {
  state.method = $('method').value;
  primary.reset();
  state.metrics = null;
  buildOptions();
  renderPoints();
  renderPointPanel();
  renderCurve();
  requestSolves();
});
$('closed').addEventListener('change', () => {
  pushUndo();
  state.closed = $('closed').checked;
  changed();
});
$('undo').addEventListener('click', undo);
$('redo').addEventListener('click', redo);
$('clear').addEventListener('click', () => { pushUndo(); state.points = []; state.selected = -1; changed(); });
$('fit').addEventListener('click', () => { fitView(); renderAll(); });
for (const id of ['show-comb', 'show-controls', 'show-markers', 'comb-scale']) $(id).addEventListener('input', () => renderCurve());
$('show-polygon').addEventListener('input', () => renderPoints());
window.addEventListener('resize', () => { measure(); renderAll(); });

// ---------------------------------------------------------------- start
async function start() {
  try {
    const r = await fetch('/api/methods');
    const data = await r.json();
    if (Array.isArray(data.methods) && data.methods.length) state.methods = data.methods;
  } catch (e) {
    setStatus('bad', `GET /api/methods failed (${e.message}): options unavailable`);
  }
  if (params.get('method') && COLOURS[params.get('method')]) state.method = params.get('method');
  buildMethodSelect();
  buildOverlayList();
  buildOptions();
  measure();
  if (!params.has('empty')) {
    // A first curve to play with: a wave of five points.
    state.points = [[0, 0], [2, 2.2], [4.5, 1.2], [6.5, 3.6], [9.5, 2.4]].map(([x, y]) => ({ x, y, corner: false, tangent: false, lambda: null }));
  }
  fitView();
  renderAll();
  changed();
}
// Hooks of the browser test (test/editor/browser_test.mjs): whether any request is pending, the
// screen position of a point, and loading points without the file dialog.
window.fairEditor.busy = () => primary.busy || metricsChannel.busy || metricsTimer !== 0 ||
  Object.entries(overlayChannels).some(([m, c]) => state.overlay.has(m) && c.busy);
window.fairEditor.primaryBusy = () => primary.busy;
// The drag steps sent over the WebSocket (the browser test checks that the drag used it).
window.fairEditor.socketSent = () => solveSocket.sent;
window.fairEditor.socketOpen = () => solveSocket.open;
window.fairEditor.screenOf = (i) => toScreen(state.points[i].x, state.points[i].y);
window.fairEditor.loadPoints = loadPoints;
window.fairEditor.ready = start();
