// Evaluation of the pieces a solve returns (the "pieces" member of the program's curve JSON:
// {"degree", "control_points", "weights"?}): rational Bézier curves evaluated in homogeneous
// coordinates by de Casteljau's algorithm, with the first two derivatives for the curvature.
// Used for the curve and the comb while a point is dragged; the certified markers come from the
// server (/api/metrics), never from these samples.

// A piece prepared for repeated evaluation: its homogeneous control points (w x, w y, w) in a
// flat array, and a scratch array for de Casteljau (no allocation per evaluation: a drag
// evaluates thousands of points per answer).
export function preparePiece(piece) {
  const cp = piece.control_points, w = piece.weights;
  const n = cp.length;
  const h = new Float64Array(3 * n);
  for (let i = 0; i < n; ++i) {
    const wi = w ? w[i] : 1;
    h[3 * i] = wi * cp[i][0]; h[3 * i + 1] = wi * cp[i][1]; h[3 * i + 2] = wi;
  }
  return { degree: n - 1, h, b: new Float64Array(3 * n) };
}

// Point, first and second derivative at t. de Casteljau on the homogeneous points
// P = (X, Y, W); its intermediate levels give the derivatives of P (degree d):
// P'' = d (d - 1) (b_2 - 2 b_1 + b_0) at the level of three points, P' = d (b_1 - b_0) at the
// level of two, P = b_0 at the last. Then c = P/W, c' = (P' - W' c)/W,
// c'' = (P'' - 2 W' c' - W'' c)/W.
export function evaluate(prep, t) {
  const d = prep.degree, b = prep.b;
  b.set(prep.h);
  let X1 = 0, Y1 = 0, W1 = 0, X2 = 0, Y2 = 0, W2 = 0;
  const s = 1 - t;
  for (let r = 0; r <= d; ++r) {
    const m = d - r;  // points left: m + 1
    if (m === 2) {
      const f = d * (d - 1);
      X2 = f * (b[6] - 2 * b[3] + b[0]); Y2 = f * (b[7] - 2 * b[4] + b[1]); W2 = f * (b[8] - 2 * b[5] + b[2]);
    } else if (m === 1) {
      X1 = d * (b[3] - b[0]); Y1 = d * (b[4] - b[1]); W1 = d * (b[5] - b[2]);
    }
    if (m === 0) break;
    for (let i = 0; i < 3 * m; ++i) b[i] = s * b[i] + t * b[i + 3];
  }
  const W = b[2];
  const x = b[0] / W, y = b[1] / W;
  const dx = (X1 - W1 * x) / W, dy = (Y1 - W1 * y) / W;
  const ddx = (X2 - 2 * W1 * dx - W2 * x) / W, ddy = (Y2 - 2 * W1 * dy - W2 * y) / W;
  return { x, y, dx, dy, ddx, ddy };
}

// Signed curvature (x' y'' - y' x'') / |c'|^3; 0 where the speed vanishes.
export function curvature(e) {
  const s2 = e.dx * e.dx + e.dy * e.dy;
  if (!(s2 > 0)) return 0;
  return (e.dx * e.ddy - e.dy * e.ddx) / (s2 * Math.sqrt(s2));
}

// Samples of a curve: per piece `perPiece` + 1 samples {piece, t, x, y, nx, ny, k, s} with the
// left unit normal (nx, ny), the curvature k and the arc length s (chords of the samples);
// `starts[i]` is the index of the first sample of piece i.
export function sampleCurve(pieces, perPiece = 24) {
  const samples = [];
  const starts = [];
  let s = 0;
  let prev = null;
  pieces.forEach((piece, pi) => {
    const prep = preparePiece(piece);
    const m = piece.degree <= 1 ? 1 : perPiece;
    starts.push(samples.length);
    for (let j = 0; j <= m; ++j) {
      const t = j / m;
      const e = evaluate(prep, t);
      const speed = Math.hypot(e.dx, e.dy);
      const nx = speed > 0 ? -e.dy / speed : 0, ny = speed > 0 ? e.dx / speed : 0;
      if (prev) s += Math.hypot(e.x - prev.x, e.y - prev.y);
      const sample = { piece: pi, t, x: e.x, y: e.y, nx, ny, k: curvature(e), s };
      samples.push(sample);
      prev = sample;
    }
  });
  return { samples, starts, length: s };
}

// The arc length at (piece, t), interpolated in the samples of that piece.
export function arcLengthAt(sampled, piece, t) {
  const a = sampled.starts[piece];
  if (a === undefined) return NaN;
  const b = piece + 1 < sampled.starts.length ? sampled.starts[piece + 1] - 1 : sampled.samples.length - 1;
  const m = b - a;
  if (m <= 0) return sampled.samples[a].s;
  const f = Math.min(Math.max(t, 0), 1) * m;
  const j = Math.min(Math.floor(f), m - 1);
  const s0 = sampled.samples[a + j].s, s1 = sampled.samples[a + j + 1].s;
  return s0 + (f - j) * (s1 - s0);
}
