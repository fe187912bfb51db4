"""Call overhead of the Python bindings, measured with timeit (not a test: run it by hand).

    PYTHONPATH=build/python python3 bench/python_overhead.py [MOMENTA_CLI]

1. aba on the 7-link chain of bench/ (test::revolute_chain: links 0.1 m, 1 kg, axes alternating
   z, y) from Python, against the C++ call's own time from build/bench/dynamics_bench
   (BM_Aba/7) when it is built;
2. a 10⁴-step simulation of the double pendulum returned to numpy, against `momenta simulate`
   writing the same table as CSV to /dev/null.
"""

import json
import os
import pathlib
import subprocess
import sys
import tempfile
import time
import timeit

import numpy as np

import momenta
from momenta import inertia

ROOT = pathlib.Path(__file__).resolve().parents[1]


def chain(n):
    m, L, r = 1.0, 0.1, 0.01
    link = inertia.MassProperties(m, [L / 2, 0, 0],
                                  np.diag([0.5 * m * r * r, m * (3 * r * r + L * L) / 12,
                                           m * (3 * r * r + L * L) / 12]))
    b = momenta.ModelBuilder(f"chain{n}")
    for k in range(n):
        b.add_body(f"link{k}", link)
        b.add_joint(f"joint{k}", "revolute", parent="world" if k == 0 else f"link{k - 1}",
                    child=f"link{k}", axis=[0, 0, 1] if k % 2 == 0 else [0, 1, 0],
                    in_parent={"position": [0.0 if k == 0 else L, 0, 0]})
    return b.build()


def best_median(statement, number, repeat=15, **names):
    times = timeit.repeat(statement, number=number, repeat=repeat, globals=names)
    return float(np.median(times)) / number


def cpp_aba_seconds():
    exe = ROOT / "build" / "bench" / "dynamics_bench"
    if not exe.exists():
        return None
    out = subprocess.run([str(exe), "--benchmark_filter=BM_Aba/7$", "--benchmark_repetitions=10",
                          "--benchmark_report_aggregates_only=true", "--benchmark_format=json"],
                         capture_output=True, text=True, check=True).stdout
    runs = json.loads(out)["benchmarks"]
    median = next(r for r in runs if r.get("aggregate_name") == "median")
    return median["real_time"] * {"ns": 1e-9, "us": 1e-6}[median["time_unit"]]


def main():
    model = chain(7)
    ws = momenta.Workspace(model)
    rng = np.random.default_rng(42)
    q, v, tau = rng.uniform(-3.14, 3.14, 7), rng.uniform(-1, 1, 7), rng.uniform(-1, 1, 7)
    python = best_median("ws.aba(q, v, tau)", number=20000, ws=ws, q=q, v=v, tau=tau)
    cpp = cpp_aba_seconds()
    print(f"aba, 7-link chain, from Python: {python * 1e9:.0f} ns per call (median of 15 × 20000)")
    if cpp:
        print(f"  C++ call (dynamics_bench BM_Aba/7 median): {cpp * 1e9:.0f} ns; "
              f"Python adds {(python - cpp) * 1e9:.0f} ns")

    cli = sys.argv[1] if len(sys.argv) > 1 else str(ROOT / "build" / "apps" / "momenta" / "momenta")
    path = ROOT / "examples" / "double_pendulum.yaml"
    pendulum = momenta.load_model(path)
    # 10⁴ steps at the file's 0.5 ms: 5 s, every row kept.
    to_numpy = best_median(lambda: momenta.simulate(pendulum, duration=5.0, every=1), number=1, repeat=7)
    def run_cli():
        subprocess.run([cli, "simulate", str(path), "--duration", "5", "--every", "1", "--quiet",
                        "--output", os.devnull, "--force"], check=True, capture_output=True)
    to_csv = best_median(run_cli, number=1, repeat=7)
    print(f"10⁴-step double pendulum: to numpy {to_numpy * 1e3:.1f} ms, CLI to CSV {to_csv * 1e3:.1f} ms, "
          f"ratio {to_numpy / to_csv:.2f}")


if __name__ == "__main__":
    main()
