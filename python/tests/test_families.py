# Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
#
# The Python module against independent oracles (issue 28, "Tests"): scipy evaluates the NURBS of
# every polynomial curve; scipy's natural cubic spline on chordal parameters is the library's
# natural interpolating spline; the curve is the one the program fair-curves writes for the same
# input (its JSON, member for member); ezdxf reads the DXF with the program's own check.
import json
import os
import subprocess
import sys

import numpy as np
import pytest
from scipy.interpolate import BSpline, CubicSpline

import fair
from conftest import SOURCE_DIR, polygon, wave

# (family, call) of polynomial curves, open and closed: their NURBS has unit weights.
POLYNOMIAL = [
    ("kappa 1", lambda: fair.kappa_curve(wave(5))),
    ("kappa 1 closed", lambda: fair.kappa_curve(polygon(), closed=True)),
    ("cardinal", lambda: fair.cardinal_spline(wave())),
    ("cardinal closed alpha", lambda: fair.cardinal_spline(polygon(), closed=True, alpha=0.4)),
    ("csr", lambda: fair.csr_spline(wave())),
    ("csr closed centripetal", lambda: fair.csr_spline(polygon(), closed=True, knots="centripetal")),
    ("optimal", lambda: fair.optimal_curve(wave())),
    ("optimal closed", lambda: fair.optimal_curve(polygon(), closed=True, lam=0.5)),
    ("cubic natural", lambda: fair.interpolating_spline(wave())),
    ("cubic not-a-knot", lambda: fair.interpolating_spline(wave(), end="not-a-knot")),
    ("cubic closed", lambda: fair.interpolating_spline(polygon(), closed=True)),
    ("catmull-rom", lambda: fair.interpolating_spline(wave(), method="catmull-rom")),
    ("four-point", lambda: fair.interpolating_spline(wave(), method="four-point")),
    ("quasi closed", lambda: fair.interpolating_spline(polygon(), method="quasi", closed=True)),
    ("bspline", lambda: fair.interpolating_spline(wave(), method="bspline")),
]


@pytest.mark.parametrize("name,make", POLYNOMIAL, ids=[p[0] for p in POLYNOMIAL])
def test_scipy_bspline_evaluates_the_nurbs(name, make):
    curve = make()
    n = curve.nurbs()
    assert not n.rational and np.all(n.weights == 1)
    assert len(n.knots) == len(n.control_points) + n.degree + 1
    # extrapolate: a closed curve's periodic form has knots beyond the domain; u stays inside it
    spline = BSpline(n.knots, n.control_points, n.degree)
    a, b = curve.domain
    assert (a, b) == (n.knots[n.degree], n.knots[len(n.control_points)])
    u = np.linspace(a, b, 257)
    extent = np.ptp(curve.points, axis=0).max()
    if n.closed:
        # scipy evaluates u = u_n in the last span, empty when u_n is a multiple knot (the double
        # knots of a kappa-curve or a Cardinal spline): a closed curve's end is its start.
        assert np.allclose(curve(b), curve(a), rtol=0, atol=1e-13 * extent)
        u = u[:-1]
    assert np.max(np.abs(spline(u) - curve(u))) <= 1e-12 * extent
    # Derivatives: scipy differentiates the B-spline itself. Where a knot inside the domain is
    # repeated (the double knots of a kappa-curve, C1 only) scipy refuses the derivative of that
    # order; the pieces are then compared inside each knot span instead.
    inner = np.unique(n.knots[n.degree:len(n.control_points) + 1])
    u_in = np.concatenate([np.linspace(a_, b_, 9)[1:-1] for a_, b_ in zip(inner[:-1], inner[1:])])
    for nu in range(1, min(2, n.degree) + 1):
        try:
            d = spline.derivative(nu)(u_in)
        except ValueError:
            d = np.array([BSpline(n.knots, n.control_points, n.degree)(x, nu=nu) for x in u_in])
        scale = np.max(np.abs(d)) + 1
        assert np.max(np.abs(d - curve(u_in, nu=nu))) <= 1e-9 * scale
    if n.degree >= 2:
        # the curvature is det(c', c'') / |c'|^3 of scipy's derivatives
        d1, d2 = spline(u_in, nu=1), spline(u_in, nu=2)
        kappa = (d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]) / np.hypot(d1[:, 0], d1[:, 1]) ** 3
        assert np.allclose(curve.curvature(u_in), kappa, rtol=1e-8, atol=1e-10)


def test_rational_kappa_curve_nurbs_is_its_pieces():
    # weights="auto": rational pieces; the homogeneous B-spline (w P, w) evaluated by scipy and
    # divided by w is the curve (the definition of a NURBS).
    curve = fair.kappa_curve(polygon(), weights="auto")
    n = curve.nurbs()
    assert n.rational and n.degree == 2
    h = BSpline(n.knots, np.column_stack([n.control_points * n.weights[:, None], n.weights]), n.degree)
    u = np.linspace(*curve.domain, 101)
    hu = h(u)
    assert np.allclose(hu[:, :2] / hu[:, 2:], curve(u), rtol=0, atol=1e-12 * 10)
    report = curve.report
    assert report["status"] == curve.status and curve.status in ("interior", "on_joins")
    assert len(curve.pieces) == len(report["pieces"]) == 6  # open: one piece per interior point
    for piece, written in zip(curve.pieces, report["pieces"]):
        assert piece["weights"] is not None and piece["control_points"].shape == (3, 2)
        # each input point is on its piece, at the piece's parameter t (the "point" and "t" members)
        b, w, t = piece["control_points"], piece["weights"], written["t"]
        basis = np.array([(1 - t) ** 2, 2 * t * (1 - t), t ** 2]) * w
        assert np.allclose(basis @ b / basis.sum(), curve.points[written["point"]], rtol=0, atol=1e-12)


@pytest.mark.parametrize("knots", ["chordal", "uniform"])
def test_natural_cubic_equals_scipy_cubicspline(knots):
    # On chordal parameters (knots="chordal") and on 0, 1, ..., n (the default, as fair-curves).
    p = wave(9)
    if knots == "chordal":
        t = np.concatenate([[0], np.cumsum(np.hypot(*np.diff(p, axis=0).T))])
        curve = fair.interpolating_spline(p, end="natural", knots="chordal")
    else:
        t = np.arange(len(p), dtype=float)
        curve = fair.interpolating_spline(p, end="natural")
    assert curve.status is None and curve.report["end"] == "natural"
    a, b = curve.domain
    assert a == 0 and b == pytest.approx(t[-1], rel=1e-15)
    # the interior knots are the chordal parameters (the NURBS of a C2 cubic: single knots)
    assert np.allclose(np.unique(curve.nurbs().knots), t, rtol=0, atol=1e-13 * t[-1])
    u = np.linspace(0, t[-1], 301)
    ref = CubicSpline(t, p, bc_type="natural")
    assert np.max(np.abs(ref(u) - curve(u))) <= 1e-12 * np.ptp(p, axis=0).max()
    assert np.max(np.abs(ref(u, 1) - curve(u, nu=1))) <= 1e-10
    assert np.max(np.abs(ref(u[1:-1], 2) - curve(u[1:-1], nu=2))) <= 1e-9
    # through the points, and the natural ends c''(0) = c''(L) = 0
    assert np.allclose(curve(t), p, rtol=0, atol=1e-13)
    assert np.allclose(curve([0.0, t[-1]], nu=2), 0, atol=1e-10)


def test_vectorised_shapes_like_scipy():
    curve = fair.cardinal_spline(wave())
    a, b = curve.domain
    assert curve(a).shape == (2,)
    assert curve(np.full((3, 4), (a + b) / 2)).shape == (3, 4, 2)
    assert curve.curvature(np.linspace(a, b, 5).reshape(5, 1)).shape == (5, 1)
    s = curve.sample(50)
    assert s.shape == (50, 2)
    assert np.allclose(s[0], curve.points[0], atol=1e-14) and np.allclose(s[-1], curve.points[-1], atol=1e-13)


# ------------------------------------------------------------------ the program's JSON
FAIR_CURVES = os.environ.get("FAIR_CURVES")

PROGRAM_CASES = [
    ("kappa", [], lambda p: fair.kappa_curve(p), wave()),
    ("kappa", ["--weights", "auto"], lambda p: fair.kappa_curve(p, weights="auto"), wave()),
    ("kappa", ["--weights", "1.5", "--closed"], lambda p: fair.kappa_curve(p, closed=True, weights=1.5), polygon()),
    ("cardinal", [], lambda p: fair.cardinal_spline(p), wave()),
    ("cardinal", ["--alpha", "0.3", "--closed"], lambda p: fair.cardinal_spline(p, closed=True, alpha=0.3), polygon()),
    ("csr", ["--knots", "uniform"], lambda p: fair.csr_spline(p, knots="uniform"), wave()),
    ("optimal", [], lambda p: fair.optimal_curve(p), wave()),
    ("optimal", ["--lambda", "0.25", "--closed"], lambda p: fair.optimal_curve(p, closed=True, lam=0.25), polygon()),
    ("optimal", ["--derivative-weight", "2:1", "--derivative-weight", "1:0.5:3"],
     lambda p: fair.optimal_curve(p, derivative_weight={2: 1.0, 1: (0.5, 3.0)}), wave()),
    ("spline", ["--method", "cubic", "--end", "not-a-knot"],
     lambda p: fair.interpolating_spline(p, end="not-a-knot"), wave()),
    ("spline", ["--method", "catmull-rom", "--closed"],
     lambda p: fair.interpolating_spline(p, method="catmull-rom", closed=True), polygon()),
]


@pytest.mark.parametrize("command,args,make,points", PROGRAM_CASES,
                         ids=[c[0] + " " + " ".join(c[1]) for c in PROGRAM_CASES])
def test_equals_the_program_json(tmp_path, command, args, make, points):
    if not FAIR_CURVES or not os.path.exists(FAIR_CURVES):
        pytest.skip("fair-curves is not built (FAIR_CURVES unset): build it to compare with the program")
    pts = tmp_path / "points.json"
    # JSON numbers of Python's repr read back to the same doubles: the program sees these points.
    pts.write_text(json.dumps({"points": points.tolist()}))
    out = tmp_path / "curve.json"
    run = subprocess.run([FAIR_CURVES, command, str(pts), "-o", str(out)] + args, capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    program = json.loads(out.read_text())
    curve = make(points)
    mine = json.loads(curve.to_json())
    assert mine == program
    assert curve.report == program and curve.status == program.get("status")


def test_optimal_constraints_and_segment_lambdas_equal_the_program(tmp_path):
    # The program reads constraints and lambdas from files ("i x y" lines, one lambda per line);
    # the module takes the same numbers as arrays.
    if not FAIR_CURVES or not os.path.exists(FAIR_CURVES):
        pytest.skip("fair-curves is not built (FAIR_CURVES unset): build it to compare with the program")
    p = wave()
    lambdas = [0.2, 0.4, 0.6, 0.8, 0.5, 0.3]
    tangents = [(0, 1.0, 0.0), (6, 0.0, 1.0)]
    corners = [(3, 1.0, 1.0, 1.0, -1.0)]
    (tmp_path / "p.json").write_text(json.dumps({"points": p.tolist()}))
    (tmp_path / "l.txt").write_text("".join(f"{v!r}\n" for v in lambdas))
    (tmp_path / "t.txt").write_text("".join(f"{int(i)} {x!r} {y!r}\n" for i, x, y in tangents))
    (tmp_path / "c.txt").write_text("".join(" ".join([str(int(r[0]))] + [repr(v) for v in r[1:]]) + "\n"
                                            for r in corners))
    out = tmp_path / "o.json"
    run = subprocess.run([FAIR_CURVES, "optimal", str(tmp_path / "p.json"), "-o", str(out), "--lambda-file",
                          str(tmp_path / "l.txt"), "--tangents", str(tmp_path / "t.txt"), "--corners",
                          str(tmp_path / "c.txt")], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    curve = fair.optimal_curve(p, segment_lambda=lambdas, tangents=np.array(tangents), corners=np.array(corners))
    assert curve.report == json.loads(out.read_text())


# ------------------------------------------------------------------ DXF
def test_dxf_passes_the_program_ezdxf_check(tmp_path):
    pytest.importorskip("ezdxf")
    sys.path.insert(0, os.path.join(SOURCE_DIR, "test", "io_export"))
    try:
        import check_dxf
    finally:
        sys.path.pop(0)
    for i, curve in enumerate([fair.kappa_curve(wave(), weights="auto"), fair.kappa_curve(polygon(), closed=True),
                               fair.csr_spline(polygon(), closed=True), fair.optimal_curve(wave())]):
        dxf = tmp_path / f"c{i}.dxf"
        curve.to_dxf(dxf)
        u = np.linspace(*curve.domain, 64)
        xy = curve(u)
        samples = tmp_path / f"c{i}.txt"
        samples.write_text("".join(f"{a!r} {x!r} {y!r}\n" for a, (x, y) in zip(u, xy)))
        problems, relative, closed, rational = check_dxf.check_case(str(dxf), str(samples))
        assert problems == [], problems
        assert bool(closed) == curve.closed and rational == curve.nurbs().rational


# ------------------------------------------------------------------ certificate
def test_certify_is_the_exact_certificate():
    # A cubic interpolating spline of integer points: C0 and interpolation hold exactly even in
    # the doubles written; the certificate names every property the method claims.
    cert = fair.interpolating_spline([(0, 0), (1, 2), (3, 3), (4, 1)]).certify()
    assert list(cert) == ["C0", "G1", "|kappa|", "interpolation", "Proposition 1"]
    assert cert["C0"]["holds"] and cert["C0"]["defect"] == 0
    assert cert["interpolation"]["defect"] <= 1e-15 and cert["G1"]["defect"] <= 1e-15
    assert cert["Proposition 1"]["holds"]
    # a kappa-curve (interior: every point at a curvature maximum): each property within rounding
    # of the double solve (doc/fair_curves_program.md, "certify")
    k = fair.kappa_curve(wave(5), closed=True).certify(tolerance=1e-9)
    kc = k.pop("kappa_certificate")
    assert set(k) == {"C0", "G1", "|kappa|", "interpolation", "kappa maxima"}
    assert all(p["holds"] for p in k.values()), k
    assert all(p["defect"] <= 1e-9 for p in k.values())
    # fair::certify: the exact curve of the solver's state proves the outcome "interior": every
    # point exactly on its piece, C0 and G1 exactly, one certified maximum per piece near t_i
    assert kc["status"] == "interior" and kc["proves_outcome"] and kc["valid"]
    assert kc["all_points_on_pieces"] and kc["all_g1"] and kc["all_maxima_at_points"]
    assert len(kc["pieces"]) == 5 and len(kc["joins"]) == 5
    for p in kc["pieces"]:
        lo, hi = p["root_interval"]
        assert p["unique_maximum"] and p["maxima"] == 1 and lo <= hi and p["root_distance"] <= 1e-9
    assert kc["max_kappa_mismatch"] <= 1e-9
    # on joins: proved as that outcome (valid_on_joins), not as interior; unsolved: nothing proved
    j = fair.kappa_curve(wave()).certify(tolerance=1e-9)["kappa_certificate"]
    assert (j["status"], j["proves_outcome"], j["valid"]) == ("on_joins", True, False)
    u = fair.kappa_curve(wave(), max_iterations=0).certify(tolerance=1e-9)["kappa_certificate"]
    assert (u["status"], u["proves_outcome"]) == ("unsolved", False)


# ------------------------------------------------------------------ basic shapes
DESIGN = os.path.join(SOURCE_DIR, "test", "data", "shapes", "design.json")


def test_basic_shape_design_is_a_c2_cubic_and_equals_the_program(tmp_path):
    with open(DESIGN) as f:
        design = json.load(f)
    curve = fair.basic_shape_design(design)
    n = curve.nurbs()
    assert curve.status is None and n.degree == 3 and curve.method == "shapes"
    report = curve.report
    assert report["design"] == "design" and report["convexity"]["proposition_holds"] in (True, False)
    assert len(report["shapes"]) == len(design["shapes"])
    # scipy: the same curve from the knots and control points (rational: homogeneous form)
    w = n.weights if n.rational else np.ones(len(n.control_points))
    h = BSpline(n.knots, np.column_stack([n.control_points * w[:, None], w]), 3)
    u = np.linspace(*curve.domain, 200)[:-1]
    hu = h(u)
    assert np.max(np.abs(hu[:, :2] / hu[:, 2:] - curve(u))) <= 1e-12 * np.ptp(n.control_points, axis=0).max()
    # the certificate of its method: C2 cubic with Proposition 1
    cert = curve.certify(tolerance=1e-9)
    assert list(cert) == ["C0", "G1", "|kappa|", "Proposition 1"] and cert["C0"]["holds"]
    # a path gives the program's "design" member: the program's JSON for the same file
    by_path = fair.basic_shape_design(DESIGN)
    assert by_path.report["design"] == DESIGN and by_path.report["pieces"] == report["pieces"]
    if FAIR_CURVES and os.path.exists(FAIR_CURVES):
        out = tmp_path / "shapes.json"
        run = subprocess.run([FAIR_CURVES, "shapes", DESIGN, "-o", str(out)], capture_output=True, text=True)
        assert run.returncode == 0, run.stderr
        assert json.loads(out.read_text()) == by_path.report


def test_basic_shape_design_errors_name_the_json_path():
    with open(os.path.join(SOURCE_DIR, "test", "data", "shapes", "bad_radius.json")) as f:
        bad = json.load(f)
    with pytest.raises(fair.InvalidInputError, match="design"):
        fair.basic_shape_design(bad)
