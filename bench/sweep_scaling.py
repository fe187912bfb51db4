#!/usr/bin/env python3
"""How a sweep scales over threads and MPI ranks, and where the time goes (docs/sweeps.md, "On many
cores").

    python3 bench/sweep_scaling.py build/apps/momenta/momenta                  # 1, 2, 4 … cores
    python3 bench/sweep_scaling.py build/apps/momenta/momenta --threads 1 8 16 --mpi 2x8
    python3 bench/sweep_scaling.py build/apps/momenta/momenta --trajectories csv

Runs `momenta sweep` on the sweep file (default bench/sweeps/quarter_car_scaling.yaml: 256 runs of
about 50 ms) once per configuration and prints, for each:

- wall: the command's wall-clock time, and `wall − start`, less the process's start (reading and
  checking the sweep, measured once as a one-run shard's wall time less that run's own);
- efficiency E = T(1) / (N T(N)) on those times, N the threads (ranks × threads under MPI);
- run slowdown s: the mean of the results' wall_s (each run's own time, measured on the thread
  that ran it) over that at 1 thread — how much slower a run is when N cores are busy (clock
  frequency, shared caches, memory), which no scheduling can win back: E ≤ 1/s;
- E·s: the rest, what the sweep's own organisation (taking runs, the writer thread, waiting for
  the run order) keeps of the cores;
- CPU s per run: user + system time of the whole command per run; it stays put as threads are
  added when nothing spins or contends (also on a machine with fewer cores than threads);
- whether the results are those of 1 thread, every column but wall_s compared as text;
- schedule: the E the schedule alone allows N threads with the 1-thread run times (the last runs
  end unevenly; sweep_schedule_model.py), the bound E·s approaches when nothing else is lost.

Only the standard library: it runs wherever momenta does.
"""

import argparse
import csv
import os
import pathlib
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

from sweep_schedule_model import continuous

ROOT = pathlib.Path(__file__).resolve().parent.parent


def sweep_copy(sweep, folder, trajectories):
    """The sweep file with its model path made absolute (so the copy can live elsewhere) and,
    if asked, trajectories to a CSV folder or an HDF5 file in `folder`."""
    lines = []
    for line in sweep.read_text().splitlines():
        if line.startswith(("model:", "part:")):
            key, value = line.split(":", 1)
            value = value.split("#", 1)[0].strip()
            line = f"{key}: {(sweep.parent / value).resolve()}"
        lines.append(line)
    if trajectories == "csv":
        lines.append(f"trajectories: {folder / 'traj'}/")
    elif trajectories == "h5":
        lines.append(f"trajectories: {folder / 'traj.h5'}")
    copy = folder / "sweep.yaml"
    copy.write_text("\n".join(lines) + "\n")
    return copy


def run_sweep(command, folder):
    """Wall seconds, CPU seconds (user + system of the children) and the results' rows."""
    for old in ("traj", "traj.h5", "out.csv"):
        path = folder / old
        if path.is_dir():
            shutil.rmtree(path)
        elif path.exists():
            path.unlink()
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.monotonic()
    done = subprocess.run(command, cwd=folder, stdout=subprocess.DEVNULL,
                          stderr=subprocess.PIPE, text=True)
    wall = time.monotonic() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if done.returncode != 0:
        sys.exit(f"sweep_scaling: {' '.join(map(str, command))} failed:\n{done.stderr}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    with open(folder / "out.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    return wall, cpu, rows


def without_timing(rows):
    return [{k: v for k, v in row.items() if k != "wall_s"} for row in rows]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("momenta", type=pathlib.Path, help="the momenta executable")
    parser.add_argument("sweep", type=pathlib.Path, nargs="?",
                        default=ROOT / "bench" / "sweeps" / "quarter_car_scaling.yaml")
    cores = os.cpu_count() or 1
    default_threads = sorted({1, *[n for n in (2, 4, 8, 16, 32, 64) if n <= cores], cores})
    parser.add_argument("--threads", type=int, nargs="+", default=default_threads)
    parser.add_argument("--mpi", nargs="*", default=[],
                        help="RANKSxTHREADS configurations, e.g. 2x8 (needs mpirun)")
    parser.add_argument("--trajectories", choices=("none", "csv", "h5"), default="none")
    args = parser.parse_args()

    momenta = args.momenta.resolve()
    with tempfile.TemporaryDirectory(prefix="momenta-scaling-") as tmp:
        folder = pathlib.Path(tmp)
        sweep = sweep_copy(args.sweep.resolve(), folder, args.trajectories)
        base = [str(momenta), "sweep", str(sweep), "-o", "out.csv", "--force", "--quiet"]

        configurations = [(1, n) for n in args.threads]
        for spec in args.mpi:
            ranks, threads = (int(x) for x in spec.lower().split("x"))
            configurations.append((ranks, threads))
        results = []
        for ranks, threads in configurations:
            command = base + ["--threads", str(threads)]
            if ranks > 1:
                command = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-n", str(ranks),
                           *command]
            wall, cpu, rows = run_sweep(command, folder)
            results.append((ranks, threads, wall, cpu, rows))

        # The process's start: a one-run shard's wall less that run's own time.
        runs = len(results[0][4])
        wall, _, rows = run_sweep(base + ["--threads", "1", "--shard", f"1/{runs}"], folder)
        start = max(0.0, wall - float(rows[0]["wall_s"]))

    reference = next((r for r in results if r[0] == 1 and r[1] == 1), None)
    if reference is None:
        sys.exit("sweep_scaling: --threads must include 1 (the reference)")
    t1 = reference[2] - start
    times1 = [float(r["wall_s"]) for r in reference[4]]
    run1 = statistics.fmean(times1)
    print(f"{args.sweep.name}: {runs} runs, trajectories: {args.trajectories}; "
          f"{cores} cores here; process start {start:.3f} s")
    print("| ranks × threads | wall (s) | wall − start (s) | E | run slowdown s | E·s "
          "| schedule | CPU s per run | same results |")
    print("|---|---|---|---|---|---|---|---|---|")
    for ranks, threads, wall, cpu, rows in results:
        n = ranks * threads
        efficiency = t1 / (n * (wall - start))
        slowdown = statistics.fmean(float(r["wall_s"]) for r in rows) / run1
        same = without_timing(rows) == without_timing(reference[4])
        schedule = sum(times1) / (n * continuous(times1, n))
        print(f"| {ranks} × {threads} | {wall:.2f} | {wall - start:.2f} | {efficiency:.0%} "
              f"| {slowdown:.2f} | {efficiency * slowdown:.0%} | {schedule:.0%} "
              f"| {1000 * cpu / runs:.1f} ms | {'yes' if same else 'NO'} |")


if __name__ == "__main__":
    main()
