#!/usr/bin/env python3
"""The parallel efficiency a sweep's schedule allows, from its runs' own times (docs/sweeps.md,
"On many cores"): a model for machines with more cores than this one.

    python3 bench/sweep_schedule_model.py results.csv --threads 16 --mpi 2x8

Reads the `wall_s` column of a results file (each run timed on the thread that ran it; best from
a 1-thread sweep) and replays the runs, in list order, on N threads that each take the next run
as they free up — momenta's schedule on one process — and, with --mpi, on ranks whose threads
take runs from a queue the rank tops up to its threads' worth and a quarter more whenever fewer
than that quarter wait (an instant round trip) — momenta's schedule across MPI ranks. With --mpi it also replays the schedule momenta used before: every rank but 0 takes
a batch of as many runs as it has threads and asks for the next batch only once the slowest of
them is done. It prints E = (Σ run times) / (N × makespan) for each: what is lost to the run
times' spread (the last runs end unevenly, a batch waits for its slowest) and nothing else — no
clock slowdown, no writer, no messages. Only the standard library.
"""

import argparse
import csv
import heapq


def continuous(times, threads):
    """Makespan of `threads` threads each taking the next run when free."""
    free = [0.0] * threads
    for t in times:
        heapq.heappush(free, heapq.heappop(free) + t)
    return max(free)


def fed(times, ranks, threads):
    """Makespan when rank 0's threads take runs one at a time and every other rank keeps a queue:
    whenever fewer than `reserve` = max(1, threads // 4) runs wait in it, it is topped up to
    threads + reserve runs, queued and running (an instant round trip)."""
    reserve = max(1, threads // 4)
    queues = [[] for _ in range(ranks)]
    running = [0] * ranks
    i = 0

    def top_up(rank):
        nonlocal i
        wanted = threads + reserve - len(queues[rank]) - running[rank]
        while wanted > 0 and i < len(times):
            queues[rank].append(times[i])
            i += 1
            wanted -= 1

    for rank in range(1, ranks):
        top_up(rank)
    free = [(0.0, rank, False) for rank in range(ranks) for _ in range(threads)]
    heapq.heapify(free)  # a thread free at a time, of a rank, after a run or not
    end = 0.0
    while free:
        now, rank, ran = heapq.heappop(free)
        if ran:
            running[rank] -= 1
        if rank == 0:
            if i >= len(times):
                continue
            t = times[i]
            i += 1
        else:
            if not queues[rank]:
                continue
            t = queues[rank].pop(0)
            if len(queues[rank]) < reserve:
                top_up(rank)
        running[rank] += 1
        end = max(end, now + t)
        heapq.heappush(free, (now + t, rank, True))
    return end


def batched(times, ranks, threads):
    """Makespan when rank 0's threads take runs one at a time and every other rank takes a batch
    of `threads` runs and waits for the slowest before it takes the next."""
    free0 = [0.0] * threads  # rank 0's threads: when each is free
    others = [0.0] * (ranks - 1)  # the other ranks: when each finishes its batch
    heapq.heapify(others)
    end = 0.0
    i = 0
    while i < len(times):
        if others and others[0] <= free0[0]:
            start = heapq.heappop(others)
            batch = times[i:i + threads]
            i += len(batch)
            heapq.heappush(others, start + max(batch))
            end = max(end, start + max(batch))
        else:
            start = heapq.heappop(free0)
            heapq.heappush(free0, start + times[i])
            end = max(end, start + times[i])
            i += 1
    return max([end] + free0 + others)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("results", help="a sweep's results file, with its wall_s column")
    parser.add_argument("--threads", type=int, nargs="+", default=[4, 8, 16])
    parser.add_argument("--mpi", nargs="*", default=["2x8"], help="RANKSxTHREADS")
    args = parser.parse_args()
    with open(args.results, newline="") as f:
        times = [float(row["wall_s"]) for row in csv.DictReader(f) if row.get("wall_s")]
    if not times:
        raise SystemExit(f"{args.results}: no wall_s values (was it written with --no-timing?)")
    total = sum(times)
    mean = total / len(times)
    spread = (sum((t - mean) ** 2 for t in times) / len(times)) ** 0.5
    print(f"{len(times)} runs: mean {mean * 1e3:.1f} ms, sd {spread / mean:.1%}, "
          f"longest {max(times) / mean:.2f}× the mean")
    print("| schedule | N | E |")
    print("|---|---|---|")
    for n in args.threads:
        print(f"| one process, {n} threads | {n} | {total / (n * continuous(times, n)):.1%} |")
    for split in args.mpi:
        ranks, threads = (int(x) for x in split.split("x"))
        n = ranks * threads
        now = total / (n * fed(times, ranks, threads))
        old = total / (n * batched(times, ranks, threads))
        print(f"| {ranks} ranks × {threads}, each fed from a queue (now) | {n} | {now:.1%} |")
        print(f"| {ranks} ranks × {threads}, batch waits for its slowest (before) | {n} | {old:.1%} |")


if __name__ == "__main__":
    main()
