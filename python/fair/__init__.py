# Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
"""fair: fair interpolating planar curves (issue 28; doc/python.md).

Every family of the C++ library with numpy in and out. The curves are solved by the library in
double precision (CGAL::Simple_cartesian<double>, the kernel of the program fair-curves) without
the GIL, and reported by the library's own writers: ``curve.to_json()`` is the JSON of
``fair-curves <command> -o`` for the same input and options, ``curve.to_dxf(path)`` its DXF.
"""

import json as _json
import os as _os
import tempfile as _tempfile

import numpy as _np

from . import _fair
from ._fair import (Error, InvalidInputError, PreconditionError, SolveError,  # noqa: F401
                    NonConvergenceError, InternalError)

__all__ = ["kappa_curve", "basic_shape_design", "optimal_curve", "cardinal_spline", "csr_spline", "interpolating_spline",
           "Curve", "Nurbs", "Error", "InvalidInputError", "PreconditionError", "SolveError",
           "NonConvergenceError", "InternalError"]


class Nurbs:
    """The curve's exchange form (the "bspline" member of its JSON): ``degree``, ``knots`` (the
    full vector), ``control_points`` (M, 2), ``weights`` (M,), ``closed`` (periodic form: the last
    ``degree`` control points repeat the first), ``rational``."""

    __slots__ = ("degree", "knots", "control_points", "weights", "closed", "rational")

    def __init__(self, degree, knots, control_points, weights, closed, rational):
        self.degree, self.knots, self.control_points = degree, knots, control_points
        self.weights, self.closed, self.rational = weights, closed, rational

    def __repr__(self):
        return "Nurbs(degree=%d, %d control points, %s%s)" % (
            self.degree, len(self.control_points), "closed" if self.closed else "open",
            ", rational" if self.rational else "")


def _rebuild(family, args, kwargs):
    return _FAMILIES[family](*args, **kwargs)


class Curve:
    """A solved curve of one family. Made by the family functions, never directly."""

    def __init__(self, family, solved, args, kwargs):
        self._family, self._solved, self._args, self._kwargs = family, solved, args, kwargs
        self._json = _json.loads(solved.json_text())

    # --- the report
    @property
    def method(self):
        """The method name of the JSON ("kappa", "optimal", "cardinal", "csr", "cubic", ...)."""
        return self._json["method"]

    @property
    def status(self):
        """The report's status ("interior", "converged", "optimal", ...); None for constructive methods."""
        return self._json.get("status")

    @property
    def report(self):
        """The program's curve JSON as a dict (the same members as ``fair-curves ... -o``): the
        solver's own report is ``report["report"]``, its status ``report["status"]``."""
        return _json.loads(self._solved.json_text())

    @property
    def closed(self):
        return self._json["closed"]

    @property
    def points(self):
        """The input points, (N, 2)."""
        return _np.array(self._json["points"], dtype=float).reshape(-1, 2)

    @property
    def pieces(self):
        """The pieces: a list of dicts {"degree", "control_points" (n+1, 2), "weights" or None}."""
        return [{"degree": p["degree"],
                 "control_points": _np.array(p["control_points"], dtype=float),
                 "weights": _np.array(p["weights"], dtype=float) if "weights" in p else None}
                for p in self._json["pieces"]]

    def nurbs(self):
        """The curve as one NURBS (Nurbs)."""
        degree, knots, cps, weights, closed, rational = self._solved.nurbs_data()
        return Nurbs(degree, knots, cps, weights, closed, rational)

    @property
    def domain(self):
        """The parameter interval (u_min, u_max) of the NURBS."""
        return self._solved.domain()

    # --- evaluation, vectorised like scipy.interpolate
    def __call__(self, u, nu=0):
        """c(u) (nu = 0) or its derivative of order nu: shape u.shape + (2,)."""
        u = _np.asarray(u, dtype=float)
        if isinstance(nu, bool) or int(nu) != nu:
            raise InvalidInputError(f"nu: expected an integer derivative order, got {nu!r}")
        out = self._solved.evaluate(_np.ascontiguousarray(u.ravel()), int(nu))
        return out.reshape(u.shape + (2,))

    def curvature(self, u):
        """The signed curvature at u: shape u.shape."""
        u = _np.asarray(u, dtype=float)
        return self._solved.curvature(_np.ascontiguousarray(u.ravel())).reshape(u.shape)

    def sample(self, n):
        """n points at equally spaced parameters over the domain, ends included: (n, 2)."""
        n = int(n)
        if n < 2:
            raise InvalidInputError("sample: n must be at least 2, got %d" % n)
        a, b = self.domain
        return self(_np.linspace(a, b, n))

    # --- exchange
    def to_json(self):
        """The curve JSON, exactly as ``fair-curves <command> -o`` writes it."""
        return self._solved.json_pretty()

    def to_dxf(self, path):
        """Writes the curve as an R2000 DXF drawing with one SPLINE (fair/io/write_dxf.h)."""
        text = self._solved.dxf_text()
        with open(_os.fspath(path), "w", encoding="ascii", newline="") as f:
            f.write(text)

    def certify(self, tolerance=0.0):
        """The library's exact certificate (fair/io/certify_curve.h, as ``fair-curves certify``):
        every number of the curve JSON is read as the exact rational it denotes and each property
        its method claims (C0, G1, |kappa|, interpolation of the input points, ...) is decided in
        exact arithmetic. Returns {name: {"holds", "defect", "detail"}}; a kappa-curve's also has
        "kappa_certificate": fair::certify (fair/Kappa_certificate.h), the exact curve of the
        solver's state certified fraction-free ("proves_outcome", per piece and per join)."""
        with _tempfile.TemporaryDirectory(prefix="fair-certify-") as d:
            curve_file = _os.path.join(d, "curve.json")
            points_file = _os.path.join(d, "points.json")
            with open(curve_file, "w") as f:
                f.write(self.to_json())
            with open(points_file, "w") as f:
                _json.dump({"points": self._json["points"], "closed": self.closed}, f)
            props = _fair.certify_file(curve_file, points_file, float(tolerance))
        out = {p["name"]: {"holds": p["holds"], "defect": p["defect"], "detail": p["detail"]} for p in props}
        if self._family == "kappa_curve":
            out["kappa_certificate"] = self._solved.kappa_certificate()
        return out

    # --- pickling: by the input and the options, re-solved on load
    def __reduce__(self):
        return (_rebuild, (self._family, self._args, self._kwargs))

    def __repr__(self):
        st = self.status
        return "<fair.%s %s, %d points, %d pieces%s>" % (
            self._family, "closed" if self.closed else "open", len(self._json["points"]),
            len(self._json["pieces"]), "" if st is None else ", status " + repr(st))


def _points_arg(points):
    # Keep the input exactly as given (as float64 when it converts), so that a pickle re-solves
    # the same data; the binding validates it (shape, finiteness) and raises InvalidInputError.
    try:
        return _np.array(points, dtype=float)
    except (TypeError, ValueError):
        return points


def kappa_curve(points, closed=False, weights=1.0, *, tension=None, clamp=None, max_iterations=None,
                throw_on_failure=False):
    """The (rational) kappa-curve (fair::Kappa_curve_2; fair-curves kappa). ``weights``: 1
    (polynomial), "auto" (minimum-eccentricity weights, eq. 16, with ``tension`` per point and
    ``clamp``) or a weight W > 0 for every point."""
    args = (_points_arg(points),)
    kwargs = dict(closed=closed, weights=weights, tension=tension, clamp=clamp, max_iterations=max_iterations,
                  throw_on_failure=throw_on_failure)
    return Curve("kappa_curve", _fair.kappa_curve(*args, **kwargs), args, kwargs)


def optimal_curve(points, closed=False, lam=None, *, length_weight=None, curvature_weight=None,
                  curvature_exponent=None, resolution=None, solver="newton", tangents=None, normals=None,
                  corners=None, segment_lambda=None, derivative_weight=None, throw_on_failure=False):
    """The optimal curve (fair::Optimal_curve_2; fair-curves optimal). ``lam`` in [0, 1] designs
    the weights (eq. 10); ``tangents``/``normals`` are (k, 3) rows (index, dx, dy), ``corners``
    (k, 5) rows (index, in dx, in dy, out dx, out dy); ``segment_lambda`` one lambda per segment
    (N - 1 open, N closed; the program's --lambda-file); ``derivative_weight`` {k: beta_k} or
    {k: (beta_k, alpha_k)}, k in 1..4 (the program's --derivative-weight K:BK[:AK]; the report then
    holds the C4 quintic smoothing spline under "quintic")."""
    args = (_points_arg(points),)
    kwargs = dict(closed=closed, lam=lam, length_weight=length_weight, curvature_weight=curvature_weight,
                  curvature_exponent=curvature_exponent, resolution=resolution, solver=solver,
                  tangents=tangents, normals=normals, corners=corners, segment_lambda=segment_lambda,
                  derivative_weight=derivative_weight, throw_on_failure=throw_on_failure)
    return Curve("optimal_curve", _fair.optimal_curve(*args, **kwargs), args, kwargs)


def cardinal_spline(points, closed=False, alpha=None, *, throw_on_failure=False):
    """The Cardinal spline (fair::Cardinal_spline_2; fair-curves cardinal): ``alpha`` None for the
    curvature-variation-minimising tension (eq. 18), else the given tension."""
    args = (_points_arg(points),)
    kwargs = dict(closed=closed, alpha=alpha, throw_on_failure=throw_on_failure)
    return Curve("cardinal_spline", _fair.cardinal_spline(*args, **kwargs), args, kwargs)


def csr_spline(samples, closed=False, knots="chordal"):
    """The curvature-sensitive relaxed spline of samples (fair::Csr_spline_2; fair-curves csr):
    ``knots`` "chordal", "uniform" or "centripetal"."""
    args = (_points_arg(samples),)
    kwargs = dict(closed=closed, knots=knots)
    return Curve("csr_spline", _fair.csr_spline(*args, **kwargs), args, kwargs)


def interpolating_spline(points, method="cubic", closed=False, end="natural", *, knots="uniform",
                         start_derivative=None, end_derivative=None):
    """The classic curves of fair-curves spline: ``method`` "cubic" (the C2 interpolating spline
    on ``knots`` "uniform" (the library's default, parameters 0, 1, ..., n), "chordal" or
    "centripetal"; ``end`` "natural", "not-a-knot" or "clamped" with both derivatives d/du),
    "catmull-rom", "four-point", "quasi" or "bspline"."""
    args = (_points_arg(points),)
    kwargs = dict(method=method, closed=closed, end=end, knots=knots, start_derivative=start_derivative,
                  end_derivative=end_derivative)
    return Curve("interpolating_spline", _fair.interpolating_spline(*args, **kwargs), args, kwargs)


def basic_shape_design(design):
    """Design with basic shapes (fair::basic_shape_design; fair-curves shapes): ``design`` is the
    JSON design description of doc/basic_shapes.md, as a dict, a JSON string, or the path of a
    design file (os.PathLike). The result is one C2 cubic spline; its report has the joins, the
    shapes' parts and the Proposition 1 convexity report of the program."""
    if isinstance(design, dict):
        text, name = _json.dumps(design), "design"
    elif isinstance(design, str) and design.lstrip().startswith("{"):
        text, name = design, "design"
    else:
        name = _os.fspath(design)
        with open(name) as f:
            text = f.read()
    return _shapes(text, name)


def _shapes(text, name):
    # pickled by the design's text and name (the name is the report's "design" member)
    return Curve("basic_shape_design", _fair.basic_shape_design(text, name), (text, name), {})


_FAMILIES = {"basic_shape_design": _shapes, "kappa_curve": kappa_curve, "optimal_curve": optimal_curve, "cardinal_spline": cardinal_spline,
             "csr_spline": csr_spline, "interpolating_spline": interpolating_spline}
