#!/usr/bin/env python3
# Draws doc/figures/optimal_defaults.svg (doc/optimal_curves.md, "Defaults"): the optimal curve
# through one hand-drawn Quick, Draw! stroke (test/data/optimal/quickdraw_stroke.csv) at the old
# defaults (beta = beta_0 = 1) and at lambda = 0.3, 0.5, 0.7 (the defaults now), 0.9, from the
# polygons that `fair-curves optimal -o` writes. Usage: optimal_defaults.py FAIR_CURVES > out.svg,
# or optimal_defaults.py --json OLD L03 L05 L07 L09 > out.svg with those five JSON files (any file
# with the "polygon" member; the extent ratio is computed here as in the report).
import json, subprocess, sys, tempfile, os

tool = sys.argv[1]
here = os.path.dirname(os.path.abspath(__file__))
points_file = os.path.join(here, '..', '..', 'test', 'data', 'optimal', 'quickdraw_stroke.csv')
runs = [('old defaults: beta = beta0 = 1', ['--length-weight', '1', '--curvature-weight', '1']),
        ('lambda = 0.3', ['--lambda', '0.3']), ('lambda = 0.5', ['--lambda', '0.5']),
        ('lambda = 0.7 (defaults)', []), ('lambda = 0.9', ['--lambda', '0.9'])]
points = [tuple(map(float, l.split(','))) for l in open(points_file) if l.strip()]
def extent_ratio(poly):
    gx = sum(p[0] for p in points) / len(points); gy = sum(p[1] for p in points) / len(points)
    r = lambda q: ((q[0] - gx) ** 2 + (q[1] - gy) ** 2) ** 0.5
    return max(1.0, max(map(r, poly)) / max(map(r, points)))
panels = []
if tool == '--json':
    for (title, _), f in zip(runs, sys.argv[2:]):
        poly = [tuple(p) for p in json.load(open(f))['polygon']]
        panels.append((title, poly, {'extent_ratio': extent_ratio(poly), 'status': 'converged'}))
for title, args in ([] if tool == '--json' else runs):
    with tempfile.TemporaryDirectory() as d:
        out = os.path.join(d, 'c.json')
        subprocess.run([tool, 'optimal', points_file, '-o', out] + args, check=False, capture_output=True)
        j = json.load(open(out))
        panels.append((title, [tuple(p) for p in j['polygon']], j['report']))
# each panel at its own scale (the bounding box of its curve and the points): the extent ratio in
# the caption says how large the curve is against its points
size, pad = 260.0, 20.0
def frame(poly):
    xs = [p[0] for p in poly + points]; ys = [p[1] for p in poly + points]
    x0, y1 = min(xs), max(ys)
    s = (size - 2 * pad) / max(max(xs) - x0, y1 - min(ys))
    return lambda p, k: (k * size + pad + (p[0] - x0) * s, 40 + pad + (y1 - p[1]) * s)
w = size * len(panels)
svg = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" font-size="11">' % (w, size + 50),
       '<rect width="100%" height="100%" fill="white"/>']
for k, (title, poly, report) in enumerate(panels):
    xy = frame(poly)
    svg.append('<text x="%.1f" y="16">%s</text>' % (k * size + 8, title))
    svg.append('<text x="%.1f" y="31" fill="#555">extent ratio %.2f, %s</text>' % (k * size + 8, report['extent_ratio'], report['status']))
    inp = ' '.join('%.2f,%.2f' % xy(p, k) for p in points)
    svg.append('<polyline points="%s" fill="none" stroke="#bbb" stroke-width="1"/>' % inp)
    cur = ' '.join('%.2f,%.2f' % xy(p, k) for p in poly)
    svg.append('<polyline points="%s" fill="none" stroke="#1f5fbf" stroke-width="1.6"/>' % cur)
    for p in points:
        svg.append('<circle cx="%.2f" cy="%.2f" r="2.5" fill="#d03030"/>' % xy(p, k))
    if k: svg.append('<line x1="%.1f" y1="0" x2="%.1f" y2="%d" stroke="#ddd"/>' % (k * size, k * size, size + 50))
svg.append('</svg>')
print('\n'.join(svg))
