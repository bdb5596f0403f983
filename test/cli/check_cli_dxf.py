#!/usr/bin/env python3
# Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
#
# Issue 26: "every command writes the NURBS and DXF that ezdxf verifies", end to end through the
# program. For every curve command of fair-curves (kappa with w = 1 and automatic weights,
# cardinal, csr, optimal, every spline method, conic, shapes), open and closed where the command
# takes --closed, the program writes its JSON (-o) and a DXF (--dxf); then, independently of the
# library:
#   1. the JSON's "bspline" is evaluated here by the literal Cox-de Boor recursion (rational:
#      homogeneous coordinates), and at the parameters where piece j of "pieces" starts, ends and
#      has its middle (u = b_j + t (b_{j+1} - b_j), b the distinct knots of the domain) it is that
#      piece, evaluated by de Casteljau on its own control points and weights (1e-12 of the
#      extent): the two forms of one curve in the file agree;
#   2. ezdxf (a peer reader) opens the DXF, its audit reports no error and no fix, the drawing
#      holds one SPLINE per curve, with the planar flag, the rational flag iff the JSON has
#      weights, closed|periodic flags iff the JSON's curve is closed, and ezdxf's own evaluation
#      traces the Cox-de Boor curve of the JSON at 257 parameters to 1e-12 of the extent.
# Usage: check_cli_dxf.py FAIR_CURVES DATA_DIR (test/data). Exit 0 pass, 1 failure, 77 no ezdxf.
import json
import os
import subprocess
import sys
import tempfile

try:
    import ezdxf
except ImportError:
    print("SKIPPED: python3 has no ezdxf (Debian: apt-get install python3-ezdxf)")
    sys.exit(77)


def cox_de_boor(i, p, u, knots, end):
    """N_{i,p}(u), the literal recursion (0/0 = 0) on half-open spans [a, b), except at the
    domain's end u = end, where the span ending there is taken (the value is the limit from the
    left) and not the one starting there (a periodic knot vector continues beyond the domain)."""
    if p == 0:
        a, b = knots[i], knots[i + 1]
        if u == end:
            return 1.0 if a < b == end else 0.0
        return 1.0 if a <= u < b else 0.0
    left = right = 0.0
    d1 = knots[i + p] - knots[i]
    if d1 != 0:
        left = (u - knots[i]) / d1 * cox_de_boor(i, p - 1, u, knots, end)
    d2 = knots[i + p + 1] - knots[i + 1]
    if d2 != 0:
        right = (knots[i + p + 1] - u) / d2 * cox_de_boor(i + 1, p - 1, u, knots, end)
    return left + right


def nurbs_point(b, u):
    p, knots, cps = b["degree"], b["knots"], b["control_points"]
    w = b.get("weights", [1.0] * len(cps))
    end = knots[len(knots) - p - 1]
    x = y = s = 0.0
    for i in range(len(cps)):
        n = cox_de_boor(i, p, u, knots, end)
        x += n * w[i] * cps[i][0]
        y += n * w[i] * cps[i][1]
        s += n * w[i]
    return x / s, y / s


def bezier_point(piece, t):
    cps = piece["control_points"]
    w = piece.get("weights", [1.0] * len(cps))
    h = [(wi * c[0], wi * c[1], wi) for c, wi in zip(cps, w)]
    while len(h) > 1:
        h = [tuple((1 - t) * a + t * c for a, c in zip(h[k], h[k + 1])) for k in range(len(h) - 1)]
    return h[0][0] / h[0][2], h[0][1] / h[0][2]


def check(name, json_path, dxf_path):
    problems = []
    doc = json.load(open(json_path))
    b = doc["bspline"]
    p, knots = b["degree"], b["knots"]
    start, end = knots[p], knots[len(knots) - p - 1]
    xs = [c[0] for c in b["control_points"]]
    ys = [c[1] for c in b["control_points"]]
    extent = max(max(xs) - min(xs), max(ys) - min(ys))
    tolerance = 1e-12 * extent
    # 1. the JSON's NURBS against its pieces
    breaks = sorted(set(k for k in knots if start <= k <= end))
    pieces = doc["pieces"]
    if len(pieces) != len(breaks) - 1:
        problems.append(f"{len(pieces)} pieces but {len(breaks) - 1} knot spans in the domain")
    else:
        worst = 0.0
        for j, piece in enumerate(pieces):
            for t in (0.0, 0.5, 1.0):
                u = breaks[j] + t * (breaks[j + 1] - breaks[j])
                if t == 1.0 and j + 1 < len(pieces):
                    u = breaks[j + 1]  # the join, evaluated from the right: the next piece's start
                    q = bezier_point(pieces[j + 1], 0.0)
                else:
                    q = bezier_point(piece, t)
                c = nurbs_point(b, u)
                worst = max(worst, abs(c[0] - q[0]), abs(c[1] - q[1]))
        if worst > tolerance:
            problems.append(f"the bspline is {worst:.3g} from the pieces (extent {extent:.3g})")
    # 2. ezdxf
    dxf = ezdxf.readfile(dxf_path)
    auditor = dxf.audit()
    if auditor.has_errors or auditor.has_fixes:
        problems.append(f"audit: {len(auditor.errors)} errors, {len(auditor.fixes)} fixes")
    splines = dxf.modelspace().query("SPLINE")
    if len(splines) != 1:
        return problems + [f"{len(splines)} SPLINE entities, expected 1"]
    s = splines[0]
    flags = s.dxf.flags
    if not flags & 8:
        problems.append("planar flag 8 missing")
    if bool(flags & 4) != ("weights" in b):
        problems.append(f"rational flag {flags & 4}, JSON weights {'weights' in b}")
    if bool(flags & 3) != bool(b["closed"]) or (flags & 3) not in (0, 3):
        problems.append(f"closed flags {flags & 3}, JSON closed {b['closed']}")
    dknots = list(s.knots)
    if len(dknots) != len(knots) or max(abs(a - c) for a, c in zip(dknots, knots)) > 1e-15 * max(1.0, abs(knots[-1])):
        problems.append("the DXF's knots are not the JSON's")
    tool = s.construction_tool()
    u0, u1 = dknots[0], dknots[-1]
    worst = 0.0
    for k in range(257):
        u = start + (end - start) * k / 256
        if b["closed"] and k == 256:
            u = start  # ezdxf's find_span takes an empty span at a multiple end knot (check_dxf.py)
        t = (u - u0) / (u1 - u0) if u0 != 0.0 else u
        e = tool.point(t)
        c = nurbs_point(b, u)
        worst = max(worst, abs(e.x - c[0]), abs(e.y - c[1]))
    if worst > tolerance:
        problems.append(f"ezdxf's curve is {worst:.3g} from the JSON's NURBS (extent {extent:.3g})")
    kind = ("closed" if b["closed"] else "open") + (", rational" if "weights" in b else "")
    return problems, f"degree {p}, {len(pieces)} pieces, {kind}, ezdxf within {worst / extent:.2g} of the extent"


def main():
    if len(sys.argv) != 3:
        print("usage: check_cli_dxf.py FAIR_CURVES DATA_DIR")
        return 2
    program, data = sys.argv[1], sys.argv[2]
    points = os.path.join(data, "cli", "data_set_1.csv")
    runs = {
        "kappa": ["kappa", points],
        "kappa-closed-auto": ["kappa", points, "--closed", "--weights", "auto"],
        "cardinal": ["cardinal", points],
        "cardinal-closed": ["cardinal", points, "--closed"],
        "csr": ["csr", os.path.join(data, "csr", "fig2.csv")],
        "csr-closed": ["csr", os.path.join(data, "csr", "circle12.csv"), "--closed"],
        "optimal": ["optimal", os.path.join(data, "optimal", "arch.csv")],
        "optimal-closed": ["optimal", points, "--closed"],
        "conic": ["conic", "--p0", "0,0", "--p1", "1,2", "--p2", "4,0", "--w", "2"],
        "shapes": ["shapes", os.path.join(data, "shapes", "design.json")],
    }
    for method in ("cubic", "catmull-rom", "four-point", "quasi", "bspline"):
        runs["spline-" + method] = ["spline", points, "--method", method]
        runs["spline-" + method + "-closed"] = ["spline", points, "--method", method, "--closed"]
    failures = 0
    kinds = set()
    with tempfile.TemporaryDirectory(prefix="fair_cli_dxf_") as directory:
        for name, args in runs.items():
            j, d = os.path.join(directory, name + ".json"), os.path.join(directory, name + ".dxf")
            run = subprocess.run([program] + args + ["-o", j, "--dxf", d], stdout=subprocess.PIPE,
                                 stderr=subprocess.STDOUT, text=True)
            if run.returncode != 0 or not os.path.exists(j) or not os.path.exists(d):
                failures += 1
                print(f"{name}: FAILED: fair-curves {' '.join(args)} exited {run.returncode}: {run.stdout.strip()}")
                continue
            problems, summary = check(name, j, d)
            if problems:
                failures += 1
                print(f"{name}: FAILED: " + " | ".join(problems))
            else:
                kinds.add(summary.split(",")[2].strip())
                print(f"{name}: ok ({summary})")
    if not {"open", "closed"} <= kinds:
        failures += 1
        print(f"FAILED: expected open and closed curves, got {sorted(kinds)}")
    print(f"{len(runs)} commands, ezdxf {ezdxf.__version__}: {failures} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
