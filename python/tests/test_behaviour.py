# Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
#
# Typed errors, threads, pickling and the install of the Python module (issue 28).
import math
import os
import pickle
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

import fair
from conftest import polygon, wave


def test_exception_hierarchy():
    assert issubclass(fair.InvalidInputError, ValueError) and issubclass(fair.InvalidInputError, fair.Error)
    assert issubclass(fair.PreconditionError, ValueError)
    assert issubclass(fair.SolveError, fair.Error) and issubclass(fair.Error, RuntimeError)


BAD = [
    ("nan", [(0, 0), (1, math.nan), (2, 0), (3, 1)], "point 1 is not finite"),
    ("inf", np.array([(0, 0), (1, 1), (2, math.inf), (3, 1)]), "point 2 is not finite"),
    ("too few", [(0, 0), (1, 1)], "needs at least"),
    ("wrong shape", np.zeros((5, 3)), "expected an (N, 2) array"),
    ("flat", np.zeros(8), "expected an (N, 2) array"),
    ("not numbers", [("a", "b"), ("c", "d"), ("e", "f")], "expected an (N, 2) array"),
    ("repeated", [(0, 0), (1, 1), (1, 1), (2, 0)], "repeats its neighbour"),
]
FAMILIES = [fair.kappa_curve, fair.optimal_curve, fair.cardinal_spline, fair.csr_spline, fair.interpolating_spline]


@pytest.mark.parametrize("family", FAMILIES, ids=[f.__name__ for f in FAMILIES])
@pytest.mark.parametrize("name,points,message", BAD, ids=[b[0] for b in BAD])
def test_bad_input_raises_typed_errors(family, name, points, message):
    if name == "too few" and family in (fair.optimal_curve, fair.interpolating_spline):
        points = [(0, 0)]  # an open optimal curve or cubic spline needs 2 points
    with pytest.raises(fair.InvalidInputError, match=message.replace("(", r"\(").replace(")", r"\)")):
        family(points)


def test_bad_options_raise_typed_errors():
    p = wave()
    cases = [
        (lambda: fair.kappa_curve(p, weights=-1), "weights"),
        (lambda: fair.kappa_curve(p, weights="heavy"), "weights"),
        (lambda: fair.kappa_curve(p, weights=[1, 2]), "weights: expected a number"),
        (lambda: fair.kappa_curve(p, max_iterations=2.5), "max_iterations: expected an integer"),
        (lambda: fair.kappa_curve(p, weights="auto", tension=[1, math.nan, 1, 1, 1, 1, 1]), "tension 1 = nan"),
        (lambda: fair.cardinal_spline(p, alpha="x"), "alpha: expected a number"),
        (lambda: fair.optimal_curve(p, resolution=math.nan), "resolution"),
        (lambda: fair.optimal_curve(p, tangents=[(9, 1, 0)]), "out of range"),
        (lambda: fair.optimal_curve(p, segment_lambda=[0.5] * 6, lam=0.5), "exclude each other"),
        (lambda: fair.kappa_curve([(0, 0), (1, 0), (2, 0)]), "collinear"),
        (lambda: fair.kappa_curve(p * 1e300), "beyond"),
        (lambda: fair.basic_shape_design('{"x": 1}'), "missing member"),
        (lambda: fair.kappa_curve(p, clamp=0.5), "apply to weights=\"auto\""),
        (lambda: fair.kappa_curve(p, weights="auto", tension=[1.0, 2.0]), "tension"),
        (lambda: fair.cardinal_spline(p, alpha=math.nan), "alpha"),
        (lambda: fair.csr_spline(p, knots="arc"), "knots"),
        (lambda: fair.optimal_curve(p, lam=2), "lam"),
        (lambda: fair.optimal_curve(p, lam=0.5, length_weight=1), "drop length_weight"),
        (lambda: fair.optimal_curve(p, solver="lbfgs"), "solver"),
        (lambda: fair.optimal_curve(p, tangents=[(0, 1)]), "constraints"),
        (lambda: fair.optimal_curve(p, derivative_weight={5: 1.0}), "order k must be 1, 2, 3 or 4"),
        (lambda: fair.optimal_curve(p, tangents=[(2.0**64, 1.0, 0.0)]), r"index must be an integer in \[0, 2\^53\)"),
        (lambda: fair.kappa_curve(p)([0.5], nu=1.5), "integer derivative order"),
        (lambda: fair.optimal_curve(p, derivative_weight={1: -1.0}), "beta_k"),
        (lambda: fair.optimal_curve(p, derivative_weight={1: (1.0, 0.5)}), "alpha_k"),
        (lambda: fair.optimal_curve(p, derivative_weight=[1.0]), "expected a dict"),
        (lambda: fair.interpolating_spline(p, end="periodic"), "end"),
        (lambda: fair.interpolating_spline(p, method="akima"), "method"),
        (lambda: fair.interpolating_spline(p, end="clamped"), "start_derivative"),
        (lambda: fair.interpolating_spline(p, knots="arc"), "knots"),
        (lambda: fair.interpolating_spline(p, method="bspline", knots="chordal"), "knots applies"),
    ]
    for make, message in cases:
        with pytest.raises(fair.InvalidInputError, match=message):
            make()
    # the solve's own checks of its options are fair::Precondition_error (a ValueError too)
    with pytest.raises(fair.PreconditionError, match="segment_lambda has 5 values, the curve has 6 segments"):
        fair.optimal_curve(p, segment_lambda=[0.5] * 5)
    with pytest.raises(fair.PreconditionError, match=r"segment_lambda\[1\] = 2"):
        fair.optimal_curve(p, segment_lambda=[0.5, 2, 0.5, 0.5, 0.5, 0.5])
    c = fair.interpolating_spline(p)
    with pytest.raises(fair.PreconditionError):
        c(c.domain[1] + 1)  # outside the domain
    # derivative orders are capped (O(nu^2) work, overflow of a rational curve's terms past ~150)
    k = fair.kappa_curve(p, weights="auto")
    assert np.all(np.isfinite(k([0.5], nu=32)))
    for nu in (33, 170, 10**6):
        with pytest.raises(fair.PreconditionError, match="derivative order in"):
            k([0.5], nu=nu)
    with pytest.raises(ValueError):
        c(math.nan)


def test_clamped_cubic_takes_the_end_derivatives():
    p = wave()
    c = fair.interpolating_spline(p, end="clamped", start_derivative=(1, 0), end_derivative=(0, 1))
    d = c([c.domain[0], c.domain[1]], nu=1)
    assert np.allclose(d, [(1, 0), (0, 1)], atol=1e-12)


def test_solve_error_with_throw_on_failure():
    # An iteration cap of 0 leaves the kappa solve unsolved: the status says it, and with
    # throw_on_failure the library's Solve_error becomes fair.SolveError with its message.
    c = fair.kappa_curve(wave(), max_iterations=0)
    assert c.status == "unsolved"
    with pytest.raises(fair.SolveError) as failure:
        fair.kappa_curve(wave(), max_iterations=0, throw_on_failure=True)
    # the library's message, and the report the curve would have had
    assert "unsolved" in str(failure.value)
    assert failure.value.report == c.report["report"]


def batch():
    """Curves of several families on seeded data: the work a batch engine runs."""
    jobs = []
    for seed in range(12):
        jobs.append((fair.kappa_curve, (polygon(9, seed),), dict(closed=True, weights="auto")))
        jobs.append((fair.optimal_curve, (polygon(7, seed),), dict(closed=True)))
        jobs.append((fair.cardinal_spline, (wave(6 + seed % 4),), {}))
    return jobs


def test_threads_give_exactly_the_sequential_answers():
    jobs = batch()
    sequential = [f(*a, **k).to_json() for f, a, k in jobs]
    with ThreadPoolExecutor(max_workers=4) as pool:
        threaded = list(pool.map(lambda job: job[0](*job[1], **job[2]).to_json(), jobs))
    assert threaded == sequential
    # evaluation of one shared curve from many threads
    c = fair.kappa_curve(polygon(), closed=True, weights="auto")
    u = np.linspace(*c.domain, 1000)
    ref = c(u)
    with ThreadPoolExecutor(max_workers=4) as pool:
        for r in pool.map(lambda _: c(u), range(16)):
            assert np.array_equal(r, ref)


def test_pickle_round_trip_resolves_the_same_curve():
    curves = [fair.kappa_curve(wave(), weights="auto", clamp=0.25), fair.optimal_curve(polygon(), closed=True, lam=0.3),
              fair.cardinal_spline(wave(), alpha=0.7), fair.csr_spline(polygon(), closed=True, knots="uniform"),
              fair.interpolating_spline(wave(), end="clamped", start_derivative=(1, 0), end_derivative=(1, 1)),
              fair.optimal_curve(wave(), tangents=np.array([(0, 1.0, 0.0)])),
              fair.basic_shape_design(os.path.join(os.environ.get("FAIR_SOURCE_DIR", "."), "test", "data", "shapes",
                                                   "design.json"))]
    for c in curves:
        d = pickle.loads(pickle.dumps(c))
        assert type(d) is fair.Curve and d.to_json() == c.to_json() and repr(d) == repr(c)
        u = np.linspace(*c.domain, 33)
        assert np.array_equal(d(u), c(u))


def test_repr_names_family_and_status():
    assert repr(fair.kappa_curve(wave(5))) == "<fair.kappa_curve open, 5 points, 3 pieces, status 'interior'>"
    assert repr(fair.csr_spline(wave())).startswith("<fair.csr_spline open, 7 points")


def test_install_tree_imports(tmp_path):
    cmake, build = os.environ.get("FAIR_CMAKE"), os.environ.get("FAIR_BUILD_DIR")
    if not cmake or not build:
        pytest.skip("FAIR_CMAKE/FAIR_BUILD_DIR unset (run through ctest)")
    run = subprocess.run([cmake, "--install", build, "--prefix", str(tmp_path), "--component", "Python"],
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stdout + run.stderr
    site = tmp_path / "lib" / f"python{sys.version_info.major}.{sys.version_info.minor}" / "site-packages"
    code = "import fair; print(fair.__file__); print(fair.interpolating_spline([(0, 0), (1, 1), (2, 0)]).status)"
    env = dict(os.environ, PYTHONPATH=str(site))
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, cwd=str(tmp_path))
    assert out.returncode == 0, out.stderr
    assert out.stdout.splitlines() == [str(site / "fair" / "__init__.py"), "None"]


def test_solves_release_the_gil():
    # While a solve runs in a worker thread, the main thread keeps running Python: with the GIL
    # held through the C++ call, no main-thread step could fall inside the call's time window
    # (beyond one switch interval at its start). Data: the largest coastline of the real data
    # (131 points, Natural Earth), whose optimal curve takes ~0.4 s on this machine.
    import json
    import threading
    import time
    path = os.path.join(os.environ.get("FAIR_SOURCE_DIR", "."), "test", "data", "real",
                        "natural_earth_coastlines.ndjson")
    with open(path) as f:
        lines = [json.loads(line)["geometry"]["coordinates"] for line in f]
    pts = max(lines, key=len)[:-1]  # closed: the first point repeats at the end
    window = {}

    def work():
        window["start"] = time.perf_counter()
        fair._fair.optimal_curve(pts, closed=True)
        window["end"] = time.perf_counter()

    thread = threading.Thread(target=work)
    stamps = []
    thread.start()
    while thread.is_alive():
        stamps.append(time.perf_counter())
    thread.join()
    inside = [t for t in stamps if window["start"] + 2 * sys.getswitchinterval() < t < window["end"]]
    assert window["end"] - window["start"] > 4 * sys.getswitchinterval()
    assert len(inside) > 100, (len(inside), window)


def _solve_in_worker(seed):
    # module-level, so that a ProcessPoolExecutor can pickle the call
    return fair.kappa_curve(polygon(9, seed), closed=True, weights="auto")


def test_curves_cross_process_boundaries():
    # The worker returns Curve objects: they are pickled by input and options and solved again
    # in this process, to the same JSON as a solve here.
    from concurrent.futures import ProcessPoolExecutor
    with ProcessPoolExecutor(max_workers=2) as pool:
        curves = list(pool.map(_solve_in_worker, range(4)))
    assert [c.to_json() for c in curves] == [_solve_in_worker(s).to_json() for s in range(4)]
