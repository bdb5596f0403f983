// Unit tests of the page's modules in Node (no browser): the evaluation of the pieces (curve.js)
// against closed forms and finite differences, the point-file reader (pointfile.js), the outcome
// words (status.js) against the program's summary lines, and the request channel (api.js):
// one request in flight, coalescing, stale answers dropped; the drag steps' WebSocket (SolveSocket).
//   node page_units.mjs EDITOR_DIR
import path from 'node:path';
import { pathToFileURL } from 'node:url';

const dir = path.resolve(process.argv[2] || path.join(path.dirname(new URL(import.meta.url).pathname), "../../tools/fair-curves/editor"));
const load = (f) => import(pathToFileURL(path.join(dir, f)).href);
const { preparePiece, evaluate, curvature, sampleCurve, arcLengthAt } = await load('curve.js');
const { parsePointFile } = await load('pointfile.js');
const { outcomeWords } = await load('status.js');
const { Channel, SolveSocket } = await load('api.js');

let failures = 0;
function check(ok, what) { console.log((ok ? 'ok   ' : 'FAIL ') + what); if (!ok) failures++; }
const close = (a, b, tol) => Math.abs(a - b) <= tol;

// ---- curve.js
// A circle arc of radius 2 as a rational quadratic (weights 1, cos(θ/2), 1 for the angle θ = 90°):
// every point at distance 2 from the centre, curvature 1/2 (counter-clockwise: positive).
{
  const r = 2, c = Math.SQRT1_2;
  const arc = preparePiece({ degree: 2, control_points: [[r, 0], [r, r], [0, r]], weights: [1, c, 1] });
  let worst = 0, worstK = 0;
  for (let j = 0; j <= 20; ++j) {
    const e = evaluate(arc, j / 20);
    worst = Math.max(worst, Math.abs(Math.hypot(e.x, e.y) - r));
    worstK = Math.max(worstK, Math.abs(curvature(e) - 1 / r));
  }
  check(worst < 1e-14 && worstK < 1e-14, `rational quadratic circle arc: radius within ${worst.toExponential(1)}, curvature 1/2 within ${worstK.toExponential(1)}`);
  const s = sampleCurve([{ degree: 2, control_points: [[r, 0], [r, r], [0, r]], weights: [1, c, 1] }], 200);
  check(close(s.length, Math.PI * r / 2, 1e-4), `arc length of the quarter circle ${s.length.toFixed(6)} ~ pi (chords of 200 samples)`);
  check(close(arcLengthAt(s, 0, 0.5), s.length / 2, 1e-9), 'arcLengthAt(0, 1/2) is half the symmetric arc');
}
// A rational cubic: the derivatives against central differences of the evaluation itself.
{
  const p = preparePiece({ degree: 3, control_points: [[0, 0], [1, 2], [3, -1], [4, 1]], weights: [1, 0.5, 2, 1] });
  const h = 1e-5;
  let worst = 0;
  for (const t of [0, 0.1, 0.37, 0.5, 0.9, 1]) {
    const a = evaluate(p, t - h), b = evaluate(p, t + h), e = evaluate(p, t);
    worst = Math.max(worst, Math.abs((b.x - a.x) / (2 * h) - e.dx), Math.abs((b.y - a.y) / (2 * h) - e.dy),
      Math.abs((b.dx - a.dx) / (2 * h) - e.ddx), Math.abs((b.dy - a.dy) / (2 * h) - e.ddy));
  }
  check(worst < 1e-6, `rational cubic: first and second derivatives = central differences (${worst.toExponential(1)})`);
  const e0 = evaluate(p, 0), e1 = evaluate(p, 1);
  check(e0.x === 0 && e0.y === 0 && close(e1.x, 4, 1e-15) && close(e1.y, 1, 1e-15), 'end points interpolated');
  // c'(0) = d (w1 / w0) (P1 - P0) for a rational Bézier curve.
  check(close(e0.dx, 3 * 0.5 * 1, 1e-14) && close(e0.dy, 3 * 0.5 * 2, 1e-14), "c'(0) = 3 w1/w0 (P1 - P0)");
}
// A polynomial cubic (no weights) y = x^3 on [0, 1] with x = t: curvature 6t / (1 + 9t^4)^(3/2).
{
  const p = preparePiece({ degree: 3, control_points: [[0, 0], [1 / 3, 0], [2 / 3, 0], [1, 1]] });
  let worst = 0;
  for (const t of [0, 0.25, 0.5, 1]) worst = Math.max(worst, Math.abs(curvature(evaluate(p, t)) - 6 * t / Math.pow(1 + 9 * t ** 4, 1.5)));
  check(worst < 1e-13, `y = x^3: curvature 6t/(1+9t^4)^(3/2) within ${worst.toExponential(1)}`);
}
// A segment (degree 1, the four-point scheme's pieces): curvature 0, two samples.
{
  const s = sampleCurve([{ degree: 1, control_points: [[0, 0], [3, 4]] }], 24);
  check(s.samples.length === 2 && s.samples.every((q) => q.k === 0) && s.length === 5, 'a segment: two samples, curvature 0, length 5');
}

// ---- pointfile.js
{
  const a = parsePointFile('# a wave\n0,0\n1, 0.5\n\n2 1 # comment\n3;1e-1\n');
  check(JSON.stringify(a) === JSON.stringify({ points: [[0, 0], [1, 0.5], [2, 1], [3, 0.1]], closed: false }), 'CSV: commas, spaces, semicolons, comments, blank lines');
  const b = parsePointFile('{"points": [[0, 0], [1, 2.5]], "closed": true}');
  check(b.closed === true && b.points[1][1] === 2.5, 'JSON with "closed"');
  for (const [bad, why] of [['1,\n', 'an empty field'], ['0x10,1\n', 'hex'], ['a,b\n', 'letters'], ['1,2,3\n', 'three fields'],
    ['{"points": [[0, 0, 1]]}', 'a triple'], ['{"points": [[0, "1"]]}', 'a string'], ['{"pts": []}', 'no points'], ['1e400,0\n', '1e400']]) {
    let threw = false;
    try { parsePointFile(bad); } catch (e) { threw = true; }
    check(threw, `refused: ${why}`);
  }
}

// ---- status.js: the program's words (kappa_command.cpp, optimal_command.cpp, cardinal_command.cpp)
{
  const kappa = (report, extra = {}) => ({ pieces: [{}, {}, {}], closed: false, weights: '1', points: [[0, 0], [1, 1], [2, 0], [3, 1], [4, 0]],
    report: Object.assign({ refinement_passes: 2, iterations: 1, residuals: { max: 1e-15 }, warm_started: false }, report), ...extra });
  let w = outcomeWords('kappa', kappa({ status: 'interior' }));
  check(w.level === 'ok' && w.text.endsWith('; interior: every point at a curvature maximum of its piece') && w.text.startsWith('kappa: 3 pieces, open, weights 1, 2 passes and 1 iterations'), `interior: "${w.text}"`);
  w = outcomeWords('kappa', kappa({ status: 'on_joins', points_on_joins: [1, 3], warm_started: true }));
  check(w.level === 'warn' && w.text.includes(', warm; on joins: points 1 3 on a join (t or lambda at 0 or 1), not at a curvature maximum; the rest interior'), `on joins: "${w.text}"`);
  w = outcomeWords('kappa', kappa({ status: 'unsolved', reason: 'beyond_density_limit', points_beyond_density_limit: [1, 2, 3, 4, 5, 6, 7, 8, 9] }));
  check(w.level === 'bad' && w.text.includes('unsolved (beyond_density_limit): no kappa-curve exists for this data: 9 of 5 points are beyond the density limit') && w.text.includes('points 1 2 3 4 5 6 7 8 ...'), `beyond the density limit: "${w.text}"`);
  w = outcomeWords('kappa', kappa({ status: 'unsolved', reason: 'points_at_minima', points_at_minima: [2] }));
  check(w.text.endsWith('unsolved (points_at_minima): at a curvature minimum, not a maximum: point 2'), `at minima: "${w.text}"`);
  w = outcomeWords('kappa', kappa({ status: 'unsolved', reason: 'no_convergence', residuals: { max: 0.25 }, worst_points: [{ point: 3, residual: 0.25 }] }));
  check(w.text.endsWith('unsolved (no_convergence): residual 0.25 above the tolerance, worst 3 (0.25)'), `no convergence: "${w.text}"`);
  const opt = (status, extra = {}) => ({ closed: true, points: [[0, 0], [1, 1], [2, 0]], polygon: new Array(40), fit_max_distance: 0.0123,
    report: Object.assign({ status, levels: [1, 2, 3], iterations: 12, energy: 4321.5, extent_ratio: 1, self_intersections: 0, input_self_intersections: 0 }, extra) });
  w = outcomeWords('optimal', opt('converged'));
  check(w.level === 'ok' && w.text === 'optimal: closed, 3 points -> 40 vertices in 3 levels, 12 iterations, energy 4321.5, spline fit within 0.0123; converged', `converged: "${w.text}"`);
  w = outcomeWords('optimal', opt('capped'));
  check(w.level === 'bad' && w.text.includes('; capped'), `capped: "${w.text}"`);
  w = outcomeWords('optimal', opt('converged', { extent_ratio: 3.2, self_intersections: 2 }));
  check(w.level === 'bad' && w.text.includes('warning: the curve reaches 3.2 times the extent of its points and has 2 self-intersections (the input polygon 0)'), `balloon: "${w.text}"`);
  w = outcomeWords('cardinal', { points: [[0, 0], [1, 1], [2, 0]], closed: false, pieces: [{}, {}], report: { status: 'no_optimum', alpha: 0.5, energy: 1 } });
  check(w.level === 'warn' && w.text.includes('no_optimum: alpha = 0.5 (eq. 18 has no positive optimum: Catmull-Rom)'), `cardinal no optimum: "${w.text}"`);
}

// ---- api.js: a channel with a fetch whose answers the test releases by hand
{
  const pending = [];
  globalThis.fetch = (url, init) => new Promise((resolve) => pending.push({ body: JSON.parse(init.body), resolve }));
  const answer = (i, value) => pending[i].resolve({ ok: true, status: 200, text: async () => JSON.stringify(value),
    headers: new Map([['Server-Timing', `app;dur=${value.v}.25`]]) });
  const applied = [];
  const ch = new Channel('/api/solve', (r, tag, seq) => applied.push([r.data.v, tag, seq, r.serverMs]));
  ch.submit({ n: 1 }, 'a');
  ch.submit({ n: 2 }, 'b');
  ch.submit({ n: 3 }, 'c');
  check(pending.length === 1 && pending[0].body.n === 1, 'one request in flight; the others wait');
  answer(0, { v: 1 });
  await new Promise((r) => setTimeout(r, 10));
  check(pending.length === 2 && pending[1].body.n === 3, 'the pending requests coalesce into the newest one (2 is never sent)');
  check(applied.length === 1 && applied[0][0] === 1 && applied[0][2] === 1, 'the first answer applied');
  check(applied[0][3] === 1.25, `the server's time read from Server-Timing (${applied[0][3]} ms)`);
  ch.reset();
  answer(1, { v: 3 });
  await new Promise((r) => setTimeout(r, 10));
  check(applied.length === 1, 'an answer sent before reset() is dropped');
  ch.submit({ n: 4 }, 'd');
  answer(2, { v: 4 });
  await new Promise((r) => setTimeout(r, 10));
  check(applied.length === 2 && applied[1][0] === 4 && applied[1][2] === 4 && !ch.busy, 'the next answer applied, seq 4, channel idle');
}

// ---- api.js: the drag steps' WebSocket (a fake WebSocket; fetch answers at once)
{
  const sockets = [];
  class FakeSocket {
    static CONNECTING = 0; static OPEN = 1; static CLOSING = 2; static CLOSED = 3;
    constructor(url) { this.url = url; this.readyState = 0; this.sent = []; sockets.push(this); }
    send(text) { this.sent.push(JSON.parse(text)); }
    open() { this.readyState = 1; }
    answer(text) { this.onmessage({ data: text }); }
    close() { this.readyState = 3; this.onclose({}); }
  }
  globalThis.WebSocket = FakeSocket;
  globalThis.location = { protocol: 'http:', host: '127.0.0.1:8080' };
  const fetched = [];
  globalThis.fetch = async (url, init) => {
    fetched.push(JSON.parse(init.body));
    return { ok: true, status: 200, headers: { get: () => null }, text: async () => '{"v": "fetch"}' };
  };
  const tick = () => new Promise((r) => setTimeout(r, 5));
  const socket = new SolveSocket('/api/ws');
  const applied = [];
  const ch = new Channel('/api/solve', (r) => applied.push(r), socket);
  ch.submit({ n: 1 }, 't');  // no session: fetch, no socket opened
  await tick();
  check(fetched.length === 1 && sockets.length === 0 && applied[0].via === 'fetch', 'a request without a session goes by fetch and opens no socket');
  ch.submit({ n: 2, session: 's' }, 't');  // the first drag step: fetch, and the socket opened
  await tick();
  check(fetched.length === 2 && sockets.length === 1 && sockets[0].url === 'ws://127.0.0.1:8080/api/ws',
    'the first drag step goes by fetch and opens the socket lazily');
  sockets[0].open();
  ch.submit({ n: 3, session: 's' }, 't');
  await tick();
  check(sockets[0].sent.length === 1 && sockets[0].sent[0].n === 3 && ch.busy, 'a drag step over the open socket, in flight');
  ch.submit({ n: 4, session: 's' }, 't');
  ch.submit({ n: 5, session: 's' }, 't');
  check(sockets[0].sent.length === 1, 'one message in flight: newer steps wait and coalesce');
  sockets[0].answer('{"pieces": [], "v": "ws"}');
  await tick();
  check(applied.at(-1).via === 'ws' && applied.at(-1).ok && applied.at(-1).data.v === 'ws', 'the answer matched by order and applied');
  check(sockets[0].sent.length === 2 && sockets[0].sent[1].n === 5, 'then the newest pending step (5; 4 never sent)');
  sockets[0].answer('{"error": "points: bad", "status": 400, "id": 5}');
  await tick();
  check(!applied.at(-1).ok && applied.at(-1).status === 400 && applied.at(-1).data.error === 'points: bad', 'an error message: its status and error');
  ch.submit({ n: 6, session: 's' }, 't');
  await tick();
  sockets[0].close();  // closed with the step in flight: sent again by fetch
  await tick();
  check(fetched.at(-1).n === 6 && applied.at(-1).via === 'fetch' && !ch.busy, 'a step whose socket closed goes by fetch');
  ch.submit({ n: 7, session: 's' }, 't');
  await tick();
  check(sockets.length === 2 && fetched.at(-1).n === 7, 'the next drag step opens the socket again (and goes by fetch)');
  check(socket.sent === 3, `the socket counted its messages (${socket.sent})`);
}

console.log(failures ? `${failures} check(s) failed` : 'all checks passed');
process.exit(failures ? 1 : 0);
