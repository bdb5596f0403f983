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

// One kind of request (the primary solve, one overlay method, the metrics). submit(body, tag)
// sends at once when nothing is in flight, else replaces the pending body; an answer is handed
// to onAnswer(result, tag, seq, {sent, received}) only when no newer answer was applied and the channel was not
// reset since its request was sent (reset(): the method or the data changed in a way that makes
// every answer in flight stale).
export class Channel {
  constructor(url, onAnswer) {
    this.url = url;
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
    const result = await postJSON(this.url, job.body);
    const received = performance.now();
    this.inFlight = false;
    if (job.epoch === this.epoch && job.seq > this.applied) {
      this.applied = job.seq;
      this.onAnswer(result, job.tag, job.seq, { sent, received });
    }
    if (this.pending) this.pump();
  }
}
