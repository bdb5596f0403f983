# Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
#
# Batch work with fair and concurrent.futures (issue 28; doc/python.md, "Batch work"): every
# coastline of test/data/real/natural_earth_coastlines.ndjson (16 Natural Earth features, 3-131
# points) as an optimal curve, a csr spline and a kappa-curve, sequentially and then in a
# ThreadPoolExecutor (the solves release the GIL) and a ProcessPoolExecutor (the curves pickle).
# Prints the wall times and the speed-ups, and checks that every parallel answer is the
# sequential one. Usage: PYTHONPATH=<build>/python /usr/bin/python3 batch_coastlines.py [workers] [repeat]
import json
import os
import sys
import time
from concurrent.futures import ProcessPoolExecutor, ThreadPoolExecutor

import fair

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "..", "test", "data", "real", "natural_earth_coastlines.ndjson")


def coastlines():
    out = []
    with open(DATA) as f:
        for line in f:
            pts = json.loads(line)["geometry"]["coordinates"]
            closed = pts[0] == pts[-1]
            if closed:
                pts = pts[:-1]
            out.append((pts, closed))
    return out


def solve(job):
    family, pts, closed = job
    try:
        if family == "optimal":
            return fair.optimal_curve(pts, closed=closed).to_json()
        if family == "csr":
            return fair.csr_spline(pts, closed=closed).to_json()
        return fair.kappa_curve(pts, closed=closed, weights="auto").to_json()
    except fair.Error as e:  # too few points for a family: part of the answer
        return type(e).__name__ + ": " + str(e)


def main():
    workers = int(sys.argv[1]) if len(sys.argv) > 1 else os.cpu_count()
    repeat = int(sys.argv[2]) if len(sys.argv) > 2 else 1
    jobs = [(f, p, c) for _ in range(repeat) for p, c in coastlines() for f in ("optimal", "csr", "kappa")]
    t0 = time.perf_counter()
    sequential = [solve(j) for j in jobs]
    t1 = time.perf_counter()
    with ThreadPoolExecutor(max_workers=workers) as pool:
        threaded = list(pool.map(solve, jobs))
    t2 = time.perf_counter()
    with ProcessPoolExecutor(max_workers=workers) as pool:
        processes = list(pool.map(solve, jobs))
    t3 = time.perf_counter()
    assert threaded == sequential and processes == sequential
    print(f"{len(jobs)} solves, {workers} workers: sequential {t1 - t0:.2f} s, threads {t2 - t1:.2f} s "
          f"(x{(t1 - t0) / (t2 - t1):.2f}), processes {t3 - t2:.2f} s (x{(t1 - t0) / (t3 - t2):.2f}); "
          "parallel answers identical to the sequential ones")


if __name__ == "__main__":
    main()
