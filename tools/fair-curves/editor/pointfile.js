// Reading a point file in the page (the Load button): the two forms the program reads
// (fair::io::read_point_file, doc/io.md).

// A point file: JSON {"points": [[x, y], ...], "closed"?} (or a bare array), or CSV/text with
// one "x,y" (or "x y") a line; '#' comments and blank lines skipped.
const DECIMAL = /^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/;

export function parsePointFile(text) {
  const t = text.trim();
  if (t.startsWith('{') || t.startsWith('[')) {
    const o = JSON.parse(t);
    const pts = Array.isArray(o) ? o : o.points;
    if (!Array.isArray(pts)) throw new Error('no "points" array');
    return { points: pts.map((p, i) => {
      if (!Array.isArray(p) || p.length !== 2 || !p.every(Number.isFinite)) throw new Error(`points[${i}]: not [x, y]`);
      return p;
    }), closed: !Array.isArray(o) && o.closed === true };
  }
  const points = [];
  t.split(/\r?\n/).forEach((line, n) => {
    const l = line.replace(/#.*/, '').trim();
    if (!l) return;
    // Decimal numbers only, as the program reads them (no hex, no empty field: "1," is an error).
    const fields = l.split(/\s*[,;]\s*|\s+/);
    if (fields.length !== 2 || !fields.every((f) => DECIMAL.test(f)) || !fields.map(Number).every(Number.isFinite))
      throw new Error(`line ${n + 1}: not "x,y"`);
    points.push(fields.map(Number));
  });
  return { points, closed: false };
}
