// The browser test of the editor (issue 27, doc/editor.md): Debian's chromium, headless, driven
// by puppeteer-core (pinned by package-lock.json; it never downloads a browser), against
// `fair-curves serve --port 0`. It adds points by clicks, drags one, checks that the curve's
// path and the comb change and that the status line reads the report, removes, nudges and
// undoes, loads a point file, switches the method and the overlay, toggles closed, exports DXF
// and checks it, measures the drag round trip on a 100-point kappa-curve and saves a screenshot.
//
//   node browser_test.mjs PROGRAM OUT_DIR [--editor-dir DIR] [--figure PNG]
// Exit 0: passed; 1: failed; 77: skipped (no /usr/bin/chromium or no node_modules: npm ci).
import { spawn, spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { createInterface } from 'node:readline';
import { fileURLToPath } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
const CHROMIUM = process.env.FAIR_CHROMIUM || '/usr/bin/chromium';
const SKIP = 77;

const args = process.argv.slice(2);
const option = (name) => { const i = args.indexOf(name); if (i < 0) return null; const v = args[i + 1]; args.splice(i, 2); return v; };
const editorDir = option('--editor-dir');
const figure = option('--figure');
const [program, outDir] = args;
if (!program || !outDir) { console.error('usage: node browser_test.mjs PROGRAM OUT_DIR [--editor-dir DIR] [--figure PNG]'); process.exit(2); }

// Missing tools skip the test (77), unless FAIR_EDITOR_REQUIRE_BROWSER=1 (bootstrap's test
// command, hence CI): then they fail it.
const required = process.env.FAIR_EDITOR_REQUIRE_BROWSER === '1';
function missing(what) {
  console.log(`${required ? 'FAIL' : 'SKIP'}: ${what}`);
  process.exit(required ? 1 : SKIP);
}
if (!fs.existsSync(CHROMIUM)) missing(`no ${CHROMIUM} (apt-get install chromium)`);
let puppeteer;
try {
  puppeteer = (await import('puppeteer-core')).default;
} catch (e) {
  missing(`puppeteer-core is not installed (npm ci in ${here}): ${e.message}`);
}

let failures = 0;
function check(ok, what) {
  if (ok) console.log(`ok   ${what}`);
  else { console.log(`FAIL ${what}`); failures++; }
  return ok;
}
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));
const median = (v) => { const s = [...v].sort((a, b) => a - b); return s.length % 2 ? s[(s.length - 1) / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2; };

// ---------------------------------------------------------------- the server
fs.mkdirSync(outDir, { recursive: true });
const serverArgs = ['serve', '--port', '0'];
if (editorDir) serverArgs.push('--editor-dir', editorDir);
const server = spawn(program, serverArgs, { stdio: ['ignore', 'pipe', 'pipe'] });
let serverLog = '';
server.stderr.on('data', (d) => { serverLog += d; });
const baseUrl = await new Promise((resolve, reject) => {
  const timer = setTimeout(() => reject(new Error('the server wrote no first line within 20 s')), 20000);
  const rl = createInterface({ input: server.stdout });
  rl.once('line', (line) => {
    clearTimeout(timer);
    const m = /^fair-curves serve: listening on (http:\/\/[^ ]+\/)$/.exec(line);
    m ? resolve(m[1]) : reject(new Error(`unexpected first line: ${line}`));
  });
  server.once('exit', (code) => reject(new Error(`the server exited (${code}): ${serverLog}`)));
});
console.log(`server: ${baseUrl}`);
// Killed by ctest's timeout or ^C: do not leave the server running.
for (const sig of ['SIGINT', 'SIGTERM']) process.on(sig, () => { server.kill('SIGTERM'); process.exit(1); });

const userDataDir = fs.mkdtempSync(path.join(os.tmpdir(), 'fair-editor-chromium-'));
const downloads = fs.mkdtempSync(path.join(os.tmpdir(), 'fair-editor-downloads-'));
let browser;
async function cleanup() {
  if (browser) await browser.close().catch(() => {});
  server.kill('SIGTERM');
  fs.rmSync(userDataDir, { recursive: true, force: true });
  fs.rmSync(downloads, { recursive: true, force: true });
}

try {
  browser = await puppeteer.launch({
    executablePath: CHROMIUM,
    headless: true,
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
      '--disable-component-update', '--disable-sync', `--user-data-dir=${userDataDir}`],
  });
  const page = await browser.newPage();
  await page.setViewport({ width: 1280, height: 800 });
  const pageErrors = [];
  const foreign = [];
  page.on('pageerror', (e) => pageErrors.push(e.message));
  page.on('console', (m) => { if (m.type() === 'error') pageErrors.push(m.text()); });
  // Nothing fetched at run time but the server's own files and API.
  page.on('request', (r) => { if (!r.url().startsWith(baseUrl) && !r.url().startsWith('data:') && !r.url().startsWith('blob:')) foreign.push(r.url()); });
  const cdp = await page.createCDPSession();
  await cdp.send('Browser.setDownloadBehavior', { behavior: 'allow', downloadPath: downloads });

  await page.goto(baseUrl + '?empty', { waitUntil: 'load' });
  await page.evaluate(() => window.fairEditor.ready);
  const settle = async () => {
    await page.waitForFunction(() => !window.fairEditor.busy(), { timeout: 30000, polling: 20 });
  };
  const status = () => page.$eval('#status', (e) => e.textContent);
  const dataStatus = () => page.$eval('#statusbar', (e) => e.dataset.status);
  const attr = (sel, a) => page.$eval(sel, (e, a) => e.getAttribute(a), a);
  const rect = await page.$eval('#canvas', (e) => { const r = e.getBoundingClientRect(); return { x: r.left, y: r.top, w: r.width, h: r.height }; });
  const at = (fx, fy) => [rect.x + fx * rect.w, rect.y + fy * rect.h];
  const pointCount = () => page.$$eval('#points circle.point', (c) => c.length);
  const points = () => page.evaluate(() => window.fairEditor.state.points.map((p) => [p.x, p.y]));
  const solveDirect = (body) => page.evaluate(async (b) => (await fetch('/api/solve', { method: 'POST', headers: { 'Content-Type': 'application/json' }, body: JSON.stringify(b) })).json(), body);

  // ---- add points by clicks: a wave of six
  const clicks = [[0.1, 0.75], [0.25, 0.35], [0.42, 0.6], [0.58, 0.3], [0.74, 0.55], [0.9, 0.25]];
  for (const [fx, fy] of clicks) { const [x, y] = at(fx, fy); await page.mouse.click(x, y); }
  await settle();
  check(await pointCount() === 6, 'six clicks add six points');
  const pts = await points();
  const direct = await solveDirect({ method: 'kappa', points: pts, closed: false, options: {} });
  const words = { interior: 'interior: every point at a curvature maximum of its piece', on_joins: 'on joins:', unsolved: 'unsolved (' }[direct.status];
  const s1 = await status();
  check(s1.startsWith(`kappa: ${direct.pieces.length} pieces, open, weights 1,`) && s1.includes(words),
    `status line reads the report (${direct.status}): "${s1}"`);
  check(await dataStatus() === direct.status, 'status line carries the report status');
  const curve1 = await attr('#curve', 'd'), comb1 = await attr('#comb', 'd');
  check(curve1 && curve1.length > 100 && comb1 && comb1.length > 100, 'curve and comb drawn');
  // The certified markers: with an interior kappa-curve every interior point is a curvature
  // maximum, so an extremum marker lies on each of them.
  await page.waitForFunction(() => document.querySelectorAll('#markers .marker-extremum').length > 0, { timeout: 20000 });
  if (direct.status === 'interior') {
    const near = await page.evaluate(() => {
      const ms = [...document.querySelectorAll('#markers .marker-extremum')].map((m) => {
        const d = m.getAttribute('d').match(/M([-\d.]+) ([-\d.]+)/); return [Number(d[1]), Number(d[2]) + 5];
      });
      const e = window.fairEditor;
      return e.state.points.slice(1, -1).map((_, k) => { const [x, y] = e.screenOf(k + 1); return Math.min(...ms.map(([mx, my]) => Math.hypot(mx - x, my - y))); });
    });
    check(near.every((d) => d < 1.5), `an extremum marker on each interior point (distances ${near.map((d) => d.toFixed(2)).join(' ')} px)`);
  }
  check((await page.$$eval('#plot-markers .marker-extremum', (m) => m.length)) > 0, 'extrema marked in the kappa(s) plot');
  check((await attr('#plot-curve', 'd') || '').length > 100, 'kappa(s) plot drawn');

  // ---- drag point 2
  const [px, py] = await page.evaluate(() => window.fairEditor.screenOf(2));
  await page.mouse.move(rect.x + px, rect.y + py);
  await page.mouse.down();
  for (let k = 1; k <= 10; ++k) await page.mouse.move(rect.x + px + 3 * k, rect.y + py - 4 * k);
  await page.mouse.up();
  await settle();
  const [qx, qy] = await page.evaluate(() => window.fairEditor.screenOf(2));
  check(Math.abs(qx - px - 30) < 1 && Math.abs(qy - py + 40) < 1, `the drag moved point 2 by (30, -40) px (got ${(qx - px).toFixed(1)}, ${(qy - py).toFixed(1)})`);
  check(await pointCount() === 6, 'a drag adds no point');
  const curve2 = await attr('#curve', 'd'), comb2 = await attr('#comb', 'd');
  check(curve2 !== curve1, 'the curve path changed after the drag');
  check(comb2 !== comb1, 'the comb changed after the drag');
  const moved = await solveDirect({ method: 'kappa', points: await points(), closed: false, options: {} });
  check((await dataStatus()) === moved.status && (await status()).startsWith(`kappa: ${moved.pieces.length} pieces`), `status after the drag: "${await status()}"`);

  // ---- remove (Delete, double-click), nudge, undo
  const before = await points();
  await page.mouse.click(rect.x + qx, rect.y + qy);            // select point 2
  await page.keyboard.press('ArrowRight');
  await settle();
  const nudged = await points();
  const scale = await page.evaluate(() => window.fairEditor.state.view.scale);
  check(Math.abs(nudged[2][0] - before[2][0] - 1 / scale) < 0.2 / scale && nudged[2][1] === before[2][1], 'ArrowRight nudges the selected point one pixel');
  await page.keyboard.press('Delete');
  await settle();
  check(await pointCount() === 5, 'Delete removes the selected point');
  const [dx, dy] = await page.evaluate(() => window.fairEditor.screenOf(3));
  await page.mouse.click(rect.x + dx, rect.y + dy, { clickCount: 1 });
  await page.mouse.click(rect.x + dx, rect.y + dy, { clickCount: 2 });
  await settle();
  check(await pointCount() === 4, 'double-click removes a point');
  await page.keyboard.down('Control'); await page.keyboard.press('z'); await page.keyboard.up('Control');
  await settle();
  check(await pointCount() === 5, 'Ctrl+Z undoes the removal');
  await page.click('#undo'); await settle();
  await page.click('#undo'); await settle();
  check(JSON.stringify(await points()) === JSON.stringify(before), 'the Undo button walks back to the dragged curve');

  // ---- an option from the panel (built from /api/methods): kappa weights auto
  await page.select('#options [data-option="weights"] select', 'auto');
  await settle();
  const autoDirect = await solveDirect({ method: 'kappa', points: before, closed: false, options: { weights: 'auto' } });
  const sAuto = await status();
  check(sAuto.includes(', weights auto,') && (await dataStatus()) === autoDirect.status, `weights auto from the options panel: "${sAuto}"`);
  check(await page.evaluate((d) => JSON.stringify(window.fairEditor.state.curves.kappa.curve) === JSON.stringify(d), autoDirect),
    'the page holds the answer of a direct solve with weights auto');
  await page.select('#options [data-option="weights"] select', '1');
  await settle();

  // ---- load a point file (CSV) through the file input
  const csv = path.join(downloads, 'wave.csv');
  fs.writeFileSync(csv, '# a wave\n0,0\n1,0.8\n2,0.2\n3,1.1\n4,0.4\n');
  const input = await page.$('#load');
  await input.uploadFile(csv);
  await page.waitForFunction(() => window.fairEditor.state.points.length === 5 && window.fairEditor.state.points[3].y === 1.1, { timeout: 10000 });
  await settle();
  check((await status()).startsWith('kappa: 3 pieces, open'), `a loaded CSV is solved: "${await status()}"`);
  await page.click('#undo'); await settle();
  check(JSON.stringify(await points()) === JSON.stringify(before), 'undo after a load restores the points');
  check(await page.evaluate(() => window.fairEditor.state.points.every((_, i) => {
    const [x, y] = window.fairEditor.screenOf(i); const c = document.getElementById('canvas');
    return x >= 0 && y >= 0 && x <= c.clientWidth && y <= c.clientHeight;
  })), 'the restored points are in view (the view was fitted to the loaded file)');

  // ---- switch the method
  await page.select('#method', 'optimal');
  await settle();
  const optimalDirect = await solveDirect({ method: 'optimal', points: before, closed: false, options: {} });
  const s3 = await status();
  check(s3.startsWith('optimal: open, 6 points') && s3.includes(`; ${optimalDirect.report.status}`), `optimal status reads the report: "${s3}"`);
  check(await attr('#curve', 'd') !== curve2, 'the optimal curve differs from the kappa-curve');
  check((await page.$$eval('#options [data-option]', (o) => o.map((x) => x.dataset.option))).includes('lambda'), 'the options panel of optimal has lambda');
  // A corner on point 2 (the C key): the request carries the corners row from its neighbours.
  const [cx2, cy2] = await page.evaluate(() => window.fairEditor.screenOf(2));
  await page.mouse.click(rect.x + cx2, rect.y + cy2);
  await page.keyboard.press('c');
  await settle();
  const row = [2, before[2][0] - before[1][0], before[2][1] - before[1][1], before[3][0] - before[2][0], before[3][1] - before[2][1]];
  const cornerDirect = await solveDirect({ method: 'optimal', points: before, closed: false, options: { corners: [row] } });
  check((await page.$$eval('#points circle.corner', (c) => c.length)) === 1, 'C marks point 2 a corner');
  check(await page.evaluate((d) => JSON.stringify(window.fairEditor.state.curves.optimal.curve) === JSON.stringify(d), cornerDirect),
    `the page holds the answer of a direct solve with the corner row (${(await status()).split('; ').pop()})`);
  await page.keyboard.press('c');
  await settle();
  check((await page.$$eval('#points circle.corner', (c) => c.length)) === 0 && (await status()) === s3, 'C again removes the corner');
  // A tangent at point 2 (the T key): the row "2 tx ty" along the chord of its neighbours.
  await page.keyboard.press('t');
  await settle();
  const tangentDirect = await solveDirect({ method: 'optimal', points: before, closed: false,
    options: { tangents: [[2, before[3][0] - before[1][0], before[3][1] - before[1][1]]] } });
  check((await page.$$eval('#points circle.tangent', (c) => c.length)) === 1 &&
    await page.evaluate((d) => JSON.stringify(window.fairEditor.state.curves.optimal.curve) === JSON.stringify(d), tangentDirect),
    'T fixes the tangent of point 2: the answer of a direct solve with its row');
  await page.keyboard.press('t');
  await settle();

  // ---- the overlay: kappa and cardinal beside optimal
  for (const m of ['kappa', 'cardinal']) await page.click(`#overlay-list input[data-overlay="${m}"]`);
  await settle();
  const overlays = await page.$$eval('#overlays path', (ps) => ps.map((p) => [p.dataset.method, p.getAttribute('stroke'), p.getAttribute('d').length]));
  check(overlays.length === 2 && overlays.every(([, , n]) => n > 100), `two overlays drawn (${overlays.map((o) => o[0]).join(', ')})`);
  check(new Set(overlays.map((o) => o[1])).size === 2 && !overlays.some((o) => o[1] === '#dc2626'), 'the overlays have their own colours');

  // ---- closed
  await page.click('#closed');
  await settle();
  const s4 = await status();
  check(s4.startsWith('optimal: closed, 6 points'), `closed toggled: "${s4}"`);
  const closedPath = await attr('#curve', 'd');
  const nums = closedPath.match(/-?[\d.]+/g).map(Number);
  check(Math.hypot(nums[0] - nums[nums.length - 2], nums[1] - nums[nums.length - 1]) < 0.05, 'the closed curve ends where it starts');
  check((await page.$$eval('#overlays path', (p) => p.length)) === 2, 'the overlays follow the closed toggle');

  // ---- export DXF (a download)
  await page.click('#export-dxf');
  let dxfFile = null;
  for (let k = 0; k < 100 && !dxfFile; ++k) {
    await sleep(100);
    dxfFile = fs.readdirSync(downloads).find((f) => f.endsWith('.dxf'));
  }
  if (check(!!dxfFile, `the DXF button downloads a file (${dxfFile})`)) {
    await sleep(200);
    const dxf = fs.readFileSync(path.join(downloads, dxfFile), 'utf8');
    const lines = dxf.split(/\r?\n/).map((l) => l.trim());
    // Group code / value pairs; the flags (code 70) of the SPLINE's AcDbSpline subclass.
    let closedFlag;
    for (let k = lines.indexOf('AcDbSpline') + 1; k > 0 && k + 1 < lines.length; k += 2)
      if (lines[k] === '70') { closedFlag = lines[k + 1]; break; }
    check(lines.includes('SPLINE') && lines.includes('AcDbSpline') && lines[lines.length - 2] === 'EOF' || lines[lines.length - 1] === 'EOF',
      `the DXF has a SPLINE and ends with EOF (${dxf.length} bytes)`);
    check(lines.includes('AC1015'), 'the DXF is R2000 (AC1015)');
    check(closedFlag !== undefined && (Number(closedFlag) & 1) === 1, `the DXF spline of the closed curve has the closed flag (70: ${closedFlag})`);
  }
  // ---- save the points (JSON): the file is read back by the page's own reader's rules
  await page.click('#save-json');
  let saved = null;
  for (let k = 0; k < 100 && !saved; ++k) {
    await sleep(100);
    if (fs.existsSync(path.join(downloads, 'points.json'))) saved = fs.readFileSync(path.join(downloads, 'points.json'), 'utf8');
  }
  check(saved !== null && JSON.stringify(JSON.parse(saved)) === JSON.stringify({ points: before, closed: true }),
    'Save .json writes {"points": ..., "closed": true} of the points on the canvas');
  if (saved !== null) {
    // The program reads the saved file (fair-curves points validates a point file).
    const r = spawnSync(program, ['points', path.join(downloads, 'points.json')], { encoding: 'utf8' });
    check(r.status === 0, `fair-curves points reads the saved file (exit ${r.status} ${(r.stderr || '').trim()})`);
  }
  await page.click('#closed'); await settle();

  // ---- the drag round trip on a 100-point kappa-curve
  for (const m of ['kappa', 'cardinal']) await page.click(`#overlay-list input[data-overlay="${m}"]`);
  await page.select('#method', 'kappa');
  // A zigzag: every point a turning point, an interior kappa-curve (a sine as dense as this is
  // beyond the density limit of kappa-curves, doc/kappa_existence.md).
  const hundred = Array.from({ length: 100 }, (_, i) => [Number((i * 0.4).toFixed(3)), Number(((i % 2) * (1.5 + 0.4 * Math.sin(i * 0.1))).toFixed(3))]);
  await page.evaluate((p) => window.fairEditor.loadPoints(p, false), hundred);
  await settle();
  const s5 = await status();
  check(s5.startsWith('kappa: 98 pieces, open') && s5.includes('interior'), `the 100-point kappa-curve is solved: "${s5}"`);
  const [hx, hy] = await page.evaluate(() => window.fairEditor.screenOf(50));
  await page.mouse.move(rect.x + hx, rect.y + hy);
  await page.mouse.down();
  // Past the 3-pixel drag threshold first (not measured), then moves around a circle of 6 pixels:
  // each moves the point by about 1.8 pixels and waits for its answer to be drawn (the metrics
  // wait for the drag to pause: they are not part of the round trip).
  await page.mouse.move(rect.x + hx + 6, rect.y + hy);
  await page.waitForFunction(() => !window.fairEditor.primaryBusy(), { timeout: 20000, polling: 'raf' });
  // The first drag step opened the WebSocket (lazily; that step went by fetch).
  await page.waitForFunction(() => window.fairEditor.socketOpen(), { timeout: 20000, polling: 'raf' });
  const trips = [];
  const phases = [];
  const socket0 = await page.evaluate(() => window.fairEditor.socketSent());
  let warm = 0;
  const moves = 40;
  for (let k = 1; k <= moves; ++k) {
    const n0 = await page.evaluate(() => window.fairEditor.stats.roundTrips.length);
    await page.mouse.move(rect.x + hx + 6 * Math.cos(0.3 * k), rect.y + hy + 6 * Math.sin(0.3 * k));
    await page.waitForFunction((n) => window.fairEditor.stats.roundTrips.length > n && !window.fairEditor.primaryBusy(),
      { timeout: 20000, polling: 'raf' }, n0);
    const [t, ph] = await page.evaluate(() => { const s = window.fairEditor.stats; return [s.roundTrips.at(-1), s.phases.at(-1)]; });
    trips.push(t);
    phases.push(ph);
    if ((await status()).includes(', warm;')) warm++;
  }
  await page.mouse.up();
  await settle();
  const med = median(trips);
  // The drag steps go over the WebSocket /api/ws (doc/editor_api.md): the page's count of
  // messages sent and the channel of every measured answer.
  const socketSent = (await page.evaluate(() => window.fairEditor.socketSent())) - socket0;
  const overSocket = phases.filter((p) => p.via === 'ws').length;
  const serverTimes = phases.map((p) => p.server).filter((v) => Number.isFinite(v));
  const sorted = [...trips].sort((a, b) => a - b);
  console.log(`drag round trip, 100-point kappa-curve, ${moves} moves: median ${med.toFixed(2)} ms, ` +
    `p90 ${sorted[Math.floor(0.9 * (sorted.length - 1))].toFixed(2)} ms, max ${sorted[sorted.length - 1].toFixed(2)} ms; ` +
    `${warm} of ${moves} answers warm-started; target median <= 16 ms: ${med <= 16 ? 'met' : 'NOT met'}`);
  console.log(`  of which (medians): before the request ${median(phases.map((p) => p.queued)).toFixed(2)} ms, ` +
    `request (server, transfer, JSON parsed) ${median(phases.map((p) => p.request)).toFixed(2)} ms ` +
    `of which the server's own ${serverTimes.length ? median(serverTimes).toFixed(2) + ' ms (Server-Timing of ' + serverTimes.length + ' fetches)' : 'not measured (no Server-Timing over the WebSocket)'}, ` +
    `drawing ${median(phases.map((p) => p.draw)).toFixed(2)} ms; load average ${os.loadavg().map((l) => l.toFixed(2)).join(' ')}`);
  console.log(`  ${overSocket} of ${moves} measured answers came over the WebSocket (${socketSent} messages sent)`);
  check(overSocket === moves && socketSent >= moves, `the drag steps went over the WebSocket: ${overSocket} of ${moves} answers, ${socketSent} messages`);
  check(trips.length >= 30, 'at least 30 moves measured');
  check(warm >= moves / 2, `the drag re-solves warm (session): ${warm} of ${moves}`);
  // The target (16 ms, a frame) is printed with the load average; the assertion is the 100 ms
  // within which an answer to input still reads as immediate (the RAIL model's response budget),
  // because this machine's two cores are shared with compilers (doc/editor.md, "Measured").
  check(med <= 100, `median drag round trip ${med.toFixed(2)} ms <= 100 ms`);

  // ---- the screenshot: the six-point curve, kappa with optimal and cardinal overlaid
  await page.evaluate((p) => window.fairEditor.loadPoints(p, false), before);
  for (const m of ['optimal', 'cardinal']) await page.click(`#overlay-list input[data-overlay="${m}"]`);
  await page.click('#show-controls');
  await settle();
  await page.waitForFunction(() => document.querySelectorAll('#markers .marker-extremum').length > 0, { timeout: 20000 });
  const [sx, sy] = await page.evaluate(() => window.fairEditor.screenOf(3));
  await page.mouse.click(rect.x + sx, rect.y + sy);
  await settle();
  const shot = path.join(outDir, 'editor.png');
  await page.screenshot({ path: shot });
  console.log(`screenshot: ${shot}`);
  if (figure) { fs.copyFileSync(shot, figure); console.log(`copied to ${figure}`); }

  check(pageErrors.length === 0, `no errors in the page${pageErrors.length ? ': ' + pageErrors.join(' | ') : ''}`);
  check(foreign.length === 0, `nothing fetched but the server's own URLs${foreign.length ? ': ' + foreign.join(' ') : ''}`);
} catch (e) {
  console.log(`FAIL ${e.stack || e}`);
  failures++;
} finally {
  await cleanup();
}
if (serverLog.trim()) console.log(`server stderr:\n${serverLog.trim()}`);
console.log(failures ? `${failures} check(s) failed` : 'all checks passed');
process.exit(failures ? 1 : 0);
