// The server's API (doc/editor_api.md): POST JSON, and a channel per kind of request that keeps
// at most one request in flight, coalesces the newer ones into one pending request, and drops
// stale answers by their sequence numbers, so a drag never queues work at the server and never
// shows an older curve after a newer one.

// POST `body` as JSON to `url`; resolves to {ok, status, data, serverMs} (data: the parsed JSON
// answer, or {error} for an error answer or a network failure; serverMs: Server-Timing, or NaN).
export async function postJSON(url, body) {
  let response;
  try {
    response = await fetch(url, { method: 'POST', headers: { 'Content-Type': 'application/json' }, body: JSON.stringify(body) });
  } catch (e) {
    return { ok: false, status: 0, data: { error: `the server did not answer (${e.message})` } };
  }
  const text = await response.text();
  let data;
  try {
    data = JSON.parse(text);
  } catch (e) {
    data = { error: text.slice(0, 300) || `HTTP ${response.status}` };
  }
  // The server's own time for the answer, from its "Server-Timing: app;dur=<ms>" header.
  const timing = /dur=([0-9.]+)/.exec(response.headers.get('Server-Timing') || '');
  return { ok: response.ok, status: response.status, data, serverMs: timing ? Number(timing[1]) : NaN };
}

// POST a body and receive a file (export): {ok, status, blob, filename} or {ok: false, error}.
export async function postForFile(url, body) {
  let response;
  try {
    response = await fetch(url, { method: 'POST', headers: { 'Content-Type': 'application/json' }, body: JSON.stringify(body) });
  } catch (e) {
    return { ok: false, status: 0, error: `the server did not answer (${e.message})` };
  }
  if (!response.ok) {
    const text = await response.text();
    let error = text;
    try { error = JSON.parse(text).error; } catch (e) { /* not JSON: the text */ }
    return { ok: false, status: response.status, error };
  }
  const disposition = response.headers.get('Content-Disposition') || '';
  const m = /filename="([^"]+)"/.exec(disposition);
  return { ok: true, status: response.status, blob: await response.blob(), filename: m ? m[1] : 'curve' };
}

// The WebSocket /api/ws of the kappa session's drag steps (doc/editor_api.md, "WebSocket"):
// chromium's fetch() costs 13-17 ms a round trip on loopback, a WebSocket message 2.4-7 ms.
// Opened lazily (connect() on a drag step), opened again on the next drag step after a close.
// One message in flight per socket (the Channel keeps one request in flight): answers are matched
// to requests by their order.
export class SolveSocket {
  constructor(path) {
    this.path = path;
    this.ws = null;
    this.waiting = [];  // resolve functions of the messages sent, in order
    this.sent = 0;      // messages sent (the browser test's evidence that the drag used the socket)
  }
  get open() { return this.ws !== null && this.ws.readyState === WebSocket.OPEN; }
  connect() {
    if (typeof WebSocket === 'undefined' || (this.ws && this.ws.readyState <= WebSocket.OPEN)) return;
    let ws;
    try {
      ws = new WebSocket((location.protocol === 'https:' ? 'wss://' : 'ws://') + location.host + this.path);
    } catch (e) {
      return;
    }
    this.ws = ws;
    ws.onmessage = (event) => {
      const resolve = this.waiting.shift();
      if (resolve) resolve(socketResult(event.data));
    };
    ws.onclose = () => {
      if (this.ws === ws) this.ws = null;
      for (const resolve of this.waiting.splice(0)) resolve(null);  // null: send it by fetch instead
    };
  }
  // Resolves to a result as postJSON's (serverMs NaN: a message has no Server-Timing), or to null
  // when the socket closed before the answer.
  solve(body) {
    return new Promise((resolve) => {
      this.waiting.push(resolve);
      this.ws.send(JSON.stringify(body));
      this.sent++;
    });
  }
}

// An answer message: the bytes /api/solve answers, or {error, status[, id]} on an error.
function socketResult(text) {
  let data;
  try {
    data = JSON.parse(text);
  } catch (e) {
    return { ok: false, status: 0, data: { error: String(text).slice(0, 300) }, serverMs: NaN, via: 'ws' };
  }
  const isError = data && typeof data.error === 'string' && typeof data.status === 'number' &&
    Object.keys(data).every((k) => k === 'error' || k === 'status' || k === 'id');
  if (isError) return { ok: false, status: data.status, data: { error: data.error }, serverMs: NaN, via: 'ws' };
  return { ok: true, status: 200, data, serverMs: NaN, via: 'ws' };
}

// One kind of request (the primary solve, one overlay method, the metrics). submit(body, tag)
// sends at once when nothing is in flight, else replaces the pending body; an answer is handed
// to onAnswer(result, tag, seq, {sent, received}) only when no newer answer was applied and the channel was not
// reset since its request was sent (reset(): the method or the data changed in a way that makes
// every answer in flight stale).
export class Channel {
  // socket (optional, a SolveSocket): carries the bodies with a session (drag steps) while open.
  constructor(url, onAnswer, socket = null) {
    this.url = url;
    this.socket = socket;
    this.onAnswer = onAnswer;
    this.seq = 0;          // sequence number of the last request built
    this.applied = 0;      // sequence number of the last answer applied
    this.epoch = 0;        // bumped by reset()
    this.inFlight = false;
    this.pending = null;
  }
  submit(body, tag) {
    this.pending = { body, tag, seq: ++this.seq, epoch: this.epoch };
    if (!this.inFlight) this.pump();
  }
  reset() {
    this.epoch++;
    this.pending = null;
  }
  get busy() { return this.inFlight || this.pending !== null; }
  async pump() {
    const job = this.pending;
    if (!job) return;
    this.pending = null;
    this.inFlight = true;
    const sent = performance.now();
    let result = null;
    if (this.socket && job.body.session) {
      if (this.socket.open) result = await this.socket.solve(job.body);
      else this.socket.connect();  // this step by fetch; the next ones by the socket
    }
    if (result === null) result = { ...(await postJSON(this.url, job.body)), via: 'fetch' };
    const received = performance.now();
    this.inFlight = false;
    if (job.epoch === this.epoch && job.seq > this.applied) {
      this.applied = job.seq;
      this.onAnswer(result, job.tag, job.seq, { sent, received });
    }
    if (this.pending) this.pump();
  }
}
