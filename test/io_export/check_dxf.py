#!/usr/bin/env python3
# Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
#
# ezdxf, an independent DXF reader, reads the drawings fair::io::write_dxf writes (issue 26):
# every case of test/io_export/nurbs_cases.h (every family, open and closed, polynomial and
# rational) is written by test_io_export (Dxf_export.every_case*, FAIR_DXF_CASES_DIR) with the
# library's own points c(u) (Nurbs_curve_2::point); then, for each drawing:
#   - ezdxf.readfile opens it and doc.audit() reports no error and no fix;
#   - ezdxf.recover.readfile (the tolerant loader, which reports what it had to repair) too;
#   - its one SPLINE has the flags of the curve (planar 8, rational 4, closed|periodic 1|2) and
#     ezdxf's own evaluation (Spline.construction_tool().point) traces the library's points to
#     1e-12 of the extent. ezdxf normalises a knot vector not starting at 0 to [0, 1]: the
#     parameter u of the library is (u - u_0) / (u_last - u_0) there.
# Exit 0: all pass; 1: a failure (listed); 77: ezdxf is not installed (ctest: skipped).
import os
import subprocess
import sys
import tempfile

try:
    import ezdxf
    from ezdxf import recover
except ImportError:
    print("SKIPPED: python3 has no ezdxf (Debian: apt-get install python3-ezdxf; tools/bootstrap.sh installs it)")
    sys.exit(77)


def check_case(path, samples_path):
    problems = []
    doc = ezdxf.readfile(path)
    auditor = doc.audit()
    if auditor.has_errors or auditor.has_fixes:
        problems.append(f"audit: {len(auditor.errors)} errors, {len(auditor.fixes)} fixes: "
                        + "; ".join(str(e.message) for e in list(auditor.errors) + list(auditor.fixes)))
    doc2, auditor2 = recover.readfile(path)
    if auditor2.has_errors or auditor2.has_fixes:
        problems.append(f"recover: {len(auditor2.errors)} errors, {len(auditor2.fixes)} fixes: "
                        + "; ".join(str(e.message) for e in list(auditor2.errors) + list(auditor2.fixes)))
    splines = doc.modelspace().query("SPLINE")
    if len(splines) != 1:
        return problems + [f"{len(splines)} SPLINE entities, expected 1"]
    spline = splines[0]
    knots = list(spline.knots)
    closed = spline.dxf.flags & 3
    if not spline.dxf.flags & 8:
        problems.append("planar flag 8 missing")
    if bool(spline.dxf.flags & 4) != bool(len(spline.weights)):
        problems.append(f"rational flag {spline.dxf.flags & 4} but {len(spline.weights)} weights")
    if closed not in (0, 3):
        problems.append(f"closed flags {closed}, expected 0 or 3")
    tool = spline.construction_tool()
    u0, u1 = knots[0], knots[-1]
    rows = [tuple(map(float, line.split())) for line in open(samples_path)]
    xs = [r[1] for r in rows]
    ys = [r[2] for r in rows]
    extent = max(max(xs) - min(xs), max(ys) - min(ys))
    degree = spline.dxf.degree
    domain_start, domain_end = knots[degree], knots[len(knots) - degree - 1]
    worst = 0.0
    for u, x, y in rows:
        if closed and u == domain_end:
            # ezdxf's find_span takes span n-1 at u >= u_n, an empty span when u_n is a multiple
            # knot (the double knots of a kappa-curve): a closed curve's end is its start.
            u = domain_start
        t = (u - u0) / (u1 - u0) if u0 != 0.0 else u
        p = tool.point(t)
        worst = max(worst, abs(p.x - x), abs(p.y - y))
    if worst > 1e-12 * extent:
        problems.append(f"ezdxf's curve is {worst:.3g} from the library's (extent {extent:.3g}; allowed 1e-12 of it)")
    return problems, worst / extent, closed, bool(spline.weights)


def main():
    if len(sys.argv) != 2:
        print("usage: check_dxf.py TEST_IO_EXPORT_EXECUTABLE")
        return 2
    with tempfile.TemporaryDirectory(prefix="fair_dxf_") as directory:
        env = dict(os.environ, FAIR_DXF_CASES_DIR=directory)
        run = subprocess.run([sys.argv[1], "--gtest_filter=Dxf_export.every_case*"], env=env,
                             stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        if run.returncode != 0:
            # A crash (negative: killed by that signal) prints nothing of its own: say so.
            print(run.stdout)
            how = (f"was killed by signal {-run.returncode}" if run.returncode < 0
                   else f"exited with status {run.returncode}")
            print(f"FAILED: the generator {sys.argv[1]} --gtest_filter=Dxf_export.every_case* {how}")
            return 1
        names = sorted(f[:-4] for f in os.listdir(directory) if f.endswith(".dxf") and f != "all.dxf")
        failures = 0
        kinds = set()
        for name in names:
            result = check_case(os.path.join(directory, name + ".dxf"), os.path.join(directory, name + ".samples"))
            problems = result[0]
            if problems:
                failures += 1
                print(f"{name}: FAILED: " + " | ".join(problems))
            else:
                kinds.add((result[2] != 0, result[3]))
                print(f"{name}: ok (max distance {result[1]:.2g} of the extent, "
                      f"{'closed' if result[2] else 'open'}, {'rational' if result[3] else 'polynomial'})")
        # the drawing of all curves together
        doc = ezdxf.readfile(os.path.join(directory, "all.dxf"))
        auditor = doc.audit()
        count = len(doc.modelspace().query("SPLINE"))
        if auditor.has_errors or auditor.has_fixes or count != len(names):
            failures += 1
            print(f"all.dxf: FAILED: {len(auditor.errors)} errors, {len(auditor.fixes)} fixes, {count} splines")
        if len(kinds) != 4:
            failures += 1
            print(f"FAILED: expected open/closed x polynomial/rational cases, got {sorted(kinds)}")
        if len(names) < 20:
            failures += 1
            print(f"FAILED: only {len(names)} cases")
        print(f"{len(names)} drawings, ezdxf {ezdxf.__version__}: {failures} failures")
        return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
