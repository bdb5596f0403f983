#!/usr/bin/python3
"""The load test of `fair-curves serve` (issue 27): 8 clients x 40 requests on loopback, mixed
methods, every answer identical (byte for byte) to the program's own output on the same points;
prints the latency percentiles (recorded in doc/benchmarks.md).

   /usr/bin/python3 editor_load.py PROGRAM [CLIENTS [REQUESTS]]
Python 3 standard library only. Exit 0 when every answer is right, 1 otherwise.
"""
import http.client
import json
import math
import os
import random
import subprocess
import sys
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import editor_api  # noqa: E402  (the server and the program runner of the API test)

_numbers = [int(a) for a in sys.argv[2:] if a.isdigit()]
CLIENTS = _numbers[0] if len(_numbers) > 0 else 8
REQUESTS = _numbers[1] if len(_numbers) > 1 else 40


def requests():
    """Twelve distinct solves: the 9 methods on 6 to 40 points, some closed, some with options."""
    rnd = random.Random(27)

    def wave(n, closed=False):
        if closed:
            return [[round(3 * math.cos(2 * math.pi * i / n) * (1 + 0.2 * (i % 2)), 6),
                     round(2 * math.sin(2 * math.pi * i / n) * (1 + 0.2 * (i % 2)), 6)] for i in range(n)]
        return [[round(i * 0.8, 6), round((i % 2) * (1.2 + 0.3 * rnd.random()), 6)] for i in range(n)]

    out = []
    for k, m in enumerate(editor_api.METHODS):
        closed = k % 3 == 1 and m != "csr"
        out.append({"method": m, "points": wave(6 + 4 * k, closed), "closed": closed, "options": {}})
    out.append({"method": "kappa", "points": wave(40), "closed": False, "options": {"weights": "auto"}})
    out.append({"method": "optimal", "points": wave(8), "closed": False, "options": {"lambda": 0.5}})
    out.append({"method": "cubic", "points": wave(12), "closed": False, "options": {"end": "not-a-knot"}})
    return out


def main():
    program = editor_api.PROGRAM
    reqs = requests()
    expected = []
    for r in reqs:
        code, out, err, _ = editor_api.run_program(r)
        if code not in (0, 3):
            print(f"FAIL the program refused {r['method']}: {err}")
            return 1
        expected.append(out)
    bodies = [json.dumps(r).encode() for r in reqs]

    server = editor_api.Server()
    latencies = []
    wrong = []
    lock = threading.Lock()

    def client(k):
        rnd = random.Random(1000 + k)
        conn = http.client.HTTPConnection(server.host, server.port, timeout=60)
        mine = []
        for j in range(REQUESTS):
            i = rnd.randrange(len(reqs))
            t0 = time.perf_counter()
            try:
                conn.request("POST", "/api/solve", body=bodies[i], headers={"Content-Type": "application/json"})
                resp = conn.getresponse()
                body = resp.read()
                status = resp.status
                if resp.getheader("Connection", "").lower() == "close":
                    conn.close()
                    conn = http.client.HTTPConnection(server.host, server.port, timeout=60)
            except (OSError, http.client.HTTPException) as e:
                conn.close()
                conn = http.client.HTTPConnection(server.host, server.port, timeout=60)
                status, body = 0, str(e).encode()
            dt = time.perf_counter() - t0
            mine.append(dt)
            if status != 200 or body != expected[i]:
                with lock:
                    wrong.append((k, j, reqs[i]["method"], status, body[:200]))
        conn.close()
        with lock:
            latencies.extend(mine)

    t0 = time.perf_counter()
    threads = [threading.Thread(target=client, args=(k,)) for k in range(CLIENTS)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    wall = time.perf_counter() - t0
    code, _, _ = server.stop()

    latencies.sort()

    def pct(p):
        return 1000 * latencies[min(len(latencies) - 1, max(0, math.ceil(p / 100 * len(latencies)) - 1))]

    n = len(latencies)
    print(f"{CLIENTS} clients x {REQUESTS} requests = {n} solves of {len(reqs)} distinct requests "
          f"({', '.join(sorted(set(r['method'] for r in reqs)))}) in {wall:.2f} s ({n / wall:.1f} requests/s), {os.cpu_count()} cores")
    print(f"latency ms: p50 {pct(50):.1f}  p90 {pct(90):.1f}  p99 {pct(99):.1f}  max {1000 * latencies[-1]:.1f}")
    for w in wrong[:10]:
        print(f"FAIL client {w[0]} request {w[1]} ({w[2]}): HTTP {w[3]} {w[4]!r}")
    ok = not wrong and n == CLIENTS * REQUESTS and code == 0
    print(f"{'ok  ' if not wrong else 'FAIL'} every answer identical to the program's ({n - len(wrong)} of {n})")
    print("all checks passed" if ok and not editor_api.failures else "FAILED")
    return 0 if ok and not editor_api.failures else 1


if __name__ == "__main__":
    sys.exit(main())
