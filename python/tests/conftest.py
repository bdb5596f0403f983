# Copyright (c) 2026 The fair authors. Distributed under the Boost Software License 1.0.
# Shared data of the tests of the Python module (issue 28; doc/python.md).
import math
import os

import numpy as np
import pytest

SOURCE_DIR = os.environ.get("FAIR_SOURCE_DIR",
                            os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..")))


def wave(n=7):
    """An open S-shaped polyline with turns of both signs (sparse, so every family solves)."""
    return np.array([(float(i), math.sin(1.1 * i) + 0.15 * i) for i in range(n)])


def polygon(n=8, seed=0):
    """A closed star-shaped polygon with seeded radii (convex-ish, no repeated points)."""
    rng = np.random.default_rng(seed)
    a = 2 * math.pi * np.arange(n) / n
    r = 1 + 0.25 * rng.random(n)
    return np.column_stack([r * np.cos(a), r * np.sin(a)])


def read_csv(path):
    rows = []
    with open(path) as f:
        for line in f:
            line = line.strip()
            if not line or line.startswith("#") or line[0].isalpha():
                continue
            rows.append(tuple(float(v) for v in line.split(",")))
    return np.array(rows)


@pytest.fixture
def csr_fig2():
    return read_csv(os.path.join(SOURCE_DIR, "test", "data", "csr", "fig2.csv"))
