"""Ensembles of hard-disk runs on Dask: the equation of state Z(eta) with replicas.

    python -m circlecollide.ensemble eos --eta 0.2:0.7:6 --n 4096 --replicas 8
    python -m circlecollide.ensemble eos ... --scheduler tcp://host:8786   # an existing cluster
    python -m circlecollide.ensemble plot circlecollide-eos-.../eos.csv     # the figure again

Each (eta, replica) is one Dask task (``circlecollide.hard_disks.state_point``): a box of n
disks from its own seed (the run's ``--seed``, eta and the replica's number: the results do not
depend on how many workers there are or which runs what), equilibrated, then measured. Without
``--scheduler`` the run starts a ``distributed.LocalCluster`` on this machine (``--workers``
processes, one thread each, as many as it has cores by default) and stops it after. A bar
shows the tasks done and the collisions per second of the whole cluster (the tasks report as
they run). The results go to ``--out`` (default: a new folder ``circlecollide-eos-<time>`` in
the current directory): ``eos.csv`` (per eta: the mean Z over the replicas, its standard error
from their spread, Kolafa-Rottner's Z and the deviation in errors), ``tasks.csv`` (each task:
its Z, collisions, times, worker) and ``eos.png`` (Z(eta) with error bars against
Kolafa-Rottner, and the deviation); the table is printed.

Needs dask, distributed and matplotlib (``pip install circlecollide[science]``).
"""

from __future__ import annotations

import argparse
import csv
import datetime
import math
import os
import sys
import threading
import time
from typing import Any, Dict, List, Optional, Sequence, TextIO

from . import hard_disks
from ._extras import extra

#: the topic tasks report their progress on (Worker.log_event / Client.subscribe_topic)
PROGRESS_TOPIC = "circlecollide-progress"

#: eos.csv's columns, in order
EOS_COLUMNS = ["eta", "n", "replicas", "z", "z_err", "z_kr", "dev_percent", "dev_sigma", "collisions"]


def parse_etas(spec: str) -> List[float]:
    """'a:b:k' is k values from a to b evenly spaced (0.2:0.7:6 is 0.2, 0.3, ... 0.7); else a
    comma-separated list. Every eta must be in (0, pi / 4) (a square lattice start)."""
    if ":" in spec:
        parts = spec.split(":")
        if len(parts) != 3:
            raise ValueError(f"--eta {spec!r}: expected START:STOP:COUNT")
        a, b, k = float(parts[0]), float(parts[1]), int(parts[2])
        if k < 1:
            raise ValueError(f"--eta {spec!r}: COUNT must be >= 1")
        etas = [a] if k == 1 else [a + (b - a) * i / (k - 1) for i in range(k)]
    else:
        etas = [float(x) for x in spec.split(",") if x.strip()]
    etas = [round(e, 12) for e in etas]
    for e in etas:
        if not 0.0 < e < math.pi / 4:
            raise ValueError(f"--eta: {e} is not in (0, pi/4)")
    return etas


def eos_task(eta: float, n: int, replica: int, seed: int, equil: float, per_disk: float, blocks: int) -> Dict[str, Any]:
    """One (eta, replica) point, run on a worker; reports its collisions on PROGRESS_TOPIC
    about once a second."""
    key = f"{eta!r}/{replica}"
    report = _reporter(key)
    m = hard_disks.state_point(eta, n, replica, seed, equil, per_disk, blocks, report)
    report(m.collisions, force=True)
    z_err = m.z_error
    return {
        "eta": eta,
        "n": n,
        "replica": replica,
        "z": m.z,
        "z_blocks_err": z_err,
        "collisions": m.collisions,
        "sim_time": m.sim_time,
        "wall_s": m.wall_seconds,
        "worker": _worker_address(),
    }


def _worker_address() -> str:
    try:
        return str(extra("distributed").get_worker().address)
    except (ImportError, ValueError):
        return "-"


def _reporter(key: str) -> Any:
    """progress(collisions) for a task: sends (key, collisions) to the client at most once a
    second (a no-op outside a Dask worker)."""
    try:
        worker = extra("distributed").get_worker()
    except (ImportError, ValueError):
        worker = None
    last = [0.0]

    def report(collisions: int, force: bool = False) -> None:
        now = time.monotonic()
        if worker is not None and (force or now - last[0] >= 1.0):
            last[0] = now
            worker.log_event(PROGRESS_TOPIC, {"task": key, "collisions": int(collisions)})

    return report


class Progress:
    """The bar: tasks done of all, collisions per second (the tasks' reported collisions over
    the time since the start), elapsed time. On a terminal it redraws one line; elsewhere it
    writes a line per finished task."""

    def __init__(self, total: int, stream: Optional[TextIO] = None, enabled: bool = True) -> None:
        self.total, self.enabled = total, enabled
        self.stream: TextIO = stream or sys.stderr
        self.done = 0
        self.collisions: Dict[str, int] = {}
        self.start = time.monotonic()
        self.tty = hasattr(self.stream, "isatty") and self.stream.isatty()
        self._lock = threading.Lock()

    def event(self, event: Any) -> None:
        """A task's report (what Client.subscribe_topic hands over: (time, message))."""
        msg = event[1] if isinstance(event, tuple) else event
        with self._lock:
            self.collisions[msg["task"]] = max(self.collisions.get(msg["task"], 0), int(msg["collisions"]))
        if self.tty:
            self.draw()

    def finished(self, key: str, collisions: int) -> None:
        with self._lock:
            self.done += 1
            self.collisions[key] = collisions
        self.draw(final=not self.tty)

    def rate(self) -> float:
        elapsed = max(time.monotonic() - self.start, 1e-9)
        return sum(self.collisions.values()) / elapsed

    def line(self) -> str:
        width = 30
        fill = int(round(width * self.done / self.total)) if self.total else width
        elapsed = time.monotonic() - self.start
        return (
            f"[{'#' * fill}{'-' * (width - fill)}] {self.done}/{self.total} tasks, "
            f"{self.rate():.3g} collisions/s, {elapsed:.1f} s"
        )

    def draw(self, final: bool = False) -> None:
        if not self.enabled:
            return
        with self._lock:
            text = self.line()
        if self.tty:
            self.stream.write("\r" + text + ("\n" if self.done == self.total else ""))
        elif final:
            self.stream.write(text + "\n")
        self.stream.flush()


def summarize(results: Sequence[Dict[str, Any]]) -> List[Dict[str, Any]]:
    """Per eta: the mean Z over the replicas and its standard error from their spread (with
    one replica, from its blocks), Kolafa-Rottner's Z and the deviation, in per cent and in
    errors. Rows in increasing eta; deterministic given the tasks' results."""
    by_eta: Dict[float, List[Dict[str, Any]]] = {}
    for r in results:
        by_eta.setdefault(r["eta"], []).append(r)
    rows = []
    for eta in sorted(by_eta):
        rs = sorted(by_eta[eta], key=lambda r: r["replica"])
        z, err = hard_disks.mean_and_error([r["z"] for r in rs])
        if len(rs) == 1:
            err = rs[0]["z_blocks_err"]
        z_kr = hard_disks.z_kolafa_rottner(eta)
        rows.append(
            {
                "eta": eta,
                "n": rs[0]["n"],
                "replicas": len(rs),
                "z": z,
                "z_err": err,
                "z_kr": z_kr,
                "dev_percent": 100.0 * (z / z_kr - 1.0) if not math.isnan(z_kr) else math.nan,
                "dev_sigma": (z - z_kr) / err if err > 0 and not math.isnan(z_kr) else math.nan,
                "collisions": sum(r["collisions"] for r in rs),
            }
        )
    return rows


def _cell(v: Any) -> str:
    if isinstance(v, float):
        return "nan" if math.isnan(v) else repr(v)
    return str(v)


def write_csv(path: str, rows: Sequence[Dict[str, Any]], columns: Sequence[str]) -> None:
    with open(path, "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(columns)
        for r in rows:
            out.writerow([_cell(r[c]) for c in columns])


def read_eos_csv(path: str) -> List[Dict[str, Any]]:
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    ints = {"n", "replicas", "collisions"}
    return [{k: (int(v) if k in ints else float(v)) for k, v in r.items()} for r in rows]


def table(rows: Sequence[Dict[str, Any]]) -> str:
    """The printed table."""
    lines = [
        f"{'eta':>6} {'N':>7} {'R':>3} {'Z':>10} {'+-':>8} {'Z_KR':>10} {'dev %':>8} {'dev/err':>8} {'collisions':>12}"
    ]
    for r in rows:
        kr = "-" if math.isnan(r["z_kr"]) else f"{r['z_kr']:10.5f}"
        dev = "-" if math.isnan(r["dev_percent"]) else f"{r['dev_percent']:+8.3f}"
        sig = "-" if math.isnan(r["dev_sigma"]) else f"{r['dev_sigma']:+8.2f}"
        lines.append(
            f"{r['eta']:6.3f} {r['n']:7d} {r['replicas']:3d} {r['z']:10.5f} {r['z_err']:8.5f} {kr:>10} {dev:>8} {sig:>8} {r['collisions']:12d}"
        )
    return "\n".join(lines)


def plot(rows: Sequence[Dict[str, Any]], path: str) -> str:
    """eos.png: Z(eta) with error bars over Kolafa-Rottner's curve (and Henderson's), and
    below it the deviation from Kolafa-Rottner in per cent. matplotlib's Agg backend: no
    display needed."""
    import numpy as np

    extra("matplotlib").use("Agg")
    plt = extra("matplotlib.pyplot")

    etas = np.array([r["eta"] for r in rows])
    z = np.array([r["z"] for r in rows])
    err = np.array([r["z_err"] for r in rows])
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 7), sharex=True, gridspec_kw={"height_ratios": [3, 2]})
    lo, hi = min(0.0, etas.min() - 0.02), min(hard_disks.KOLAFA_ROTTNER_ETA_MAX, max(etas.max() + 0.02, 0.1))
    grid = np.linspace(lo, hi, 300)
    top.plot(grid, [hard_disks.z_kolafa_rottner(e) for e in grid], "k-", lw=1, label="Kolafa & Rottner 2006")
    top.plot(grid, [hard_disks.z_henderson(e) for e in grid], "k:", lw=1, label="Henderson 1975")
    top.errorbar(etas, z, yerr=err, fmt="o", ms=4, capsize=3, color="C0", label=f"circlecollide, N = {rows[0]['n']}")
    top.set_ylabel("Z = PA / NkT")
    top.legend(loc="upper left")
    top.set_title(f"hard-disk equation of state, {rows[0]['replicas']} replicas per point")
    dev = np.array([r["dev_percent"] for r in rows])
    dev_err = 100.0 * err / np.array([r["z_kr"] for r in rows])
    bottom.axhline(0.0, color="k", lw=1)
    bottom.errorbar(etas, dev, yerr=dev_err, fmt="o", ms=4, capsize=3, color="C0")
    bottom.set_xlabel("area fraction eta")
    bottom.set_ylabel("Z / Z_KR - 1 (%)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def default_out() -> str:
    return os.path.abspath(datetime.datetime.now().strftime("circlecollide-eos-%Y%m%d-%H%M%S"))


def run_eos(args: argparse.Namespace, stdout: Optional[TextIO] = None, stderr: Optional[TextIO] = None) -> List[Dict[str, Any]]:
    stdout = stdout or sys.stdout
    stderr = stderr or sys.stderr
    distributed = extra("distributed")
    Client, LocalCluster, as_completed = distributed.Client, distributed.LocalCluster, distributed.as_completed

    # by its module's name, also when this file runs as __main__ (python -m): the workers
    # import it rather than receive a copy of __main__'s
    from circlecollide.ensemble import eos_task

    etas = parse_etas(args.eta)
    out = os.path.abspath(args.out) if args.out else default_out()
    os.makedirs(out, exist_ok=True)
    cluster = None
    if args.scheduler:
        client = Client(args.scheduler)
        where = f"the scheduler at {args.scheduler}"
    else:
        workers = args.workers or os.cpu_count() or 1
        cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None)
        client = Client(cluster)
        where = f"a LocalCluster of {workers} worker processes"
    try:
        ntasks = len(etas) * args.replicas
        stderr.write(f"eos: {ntasks} tasks ({len(etas)} eta x {args.replicas} replicas, N = {args.n}) on {where}\n")
        progress = Progress(ntasks, stderr, enabled=not args.quiet)
        client.subscribe_topic(PROGRESS_TOPIC, progress.event)
        futures = {}
        for eta in etas:
            equil = args.equil * (3 if eta >= 0.6 else 1)  # the dense fluid relaxes more slowly
            for rep in range(args.replicas):
                f = client.submit(
                    eos_task, eta, args.n, rep, args.seed, equil, args.collisions, args.blocks, pure=False
                )
                futures[f] = f"{eta!r}/{rep}"
        results = []
        for f in as_completed(list(futures)):
            r = f.result()
            results.append(r)
            progress.finished(futures[f], r["collisions"])
        client.unsubscribe_topic(PROGRESS_TOPIC)
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    results.sort(key=lambda r: (r["eta"], r["replica"]))
    rows = summarize(results)
    write_csv(os.path.join(out, "eos.csv"), rows, EOS_COLUMNS)
    write_csv(
        os.path.join(out, "tasks.csv"),
        results,
        ["eta", "n", "replica", "z", "z_blocks_err", "collisions", "sim_time", "wall_s", "worker"],
    )
    stdout.write(table(rows) + "\n")
    if not args.no_plot:
        plot(rows, os.path.join(out, "eos.png"))
    stdout.write(f"wrote {out}{os.sep}eos.csv, tasks.csv" + ("" if args.no_plot else ", eos.png") + "\n")
    return rows


def parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="python -m circlecollide.ensemble", description=__doc__.split("\n\n")[0])
    sub = p.add_subparsers(dest="command", required=True)
    e = sub.add_parser("eos", help="the hard-disk equation of state, one Dask task per (eta, replica)")
    e.add_argument("--eta", default="0.2:0.7:6", help="START:STOP:COUNT or a comma list (default 0.2:0.7:6)")
    e.add_argument("--n", type=int, default=4096, help="disks per box (default 4096)")
    e.add_argument("--replicas", type=int, default=8, help="independent runs per eta (default 8)")
    e.add_argument("--seed", type=int, default=1, help="the run's seed (default 1)")
    e.add_argument("--equil", type=float, default=100.0, help="collisions per disk to equilibrate (3x at eta >= 0.6)")
    e.add_argument("--collisions", type=float, default=1000.0, help="collisions per disk measured (default 1000)")
    e.add_argument("--blocks", type=int, default=10, help="blocks of the measurement (default 10)")
    e.add_argument("--scheduler", help="address of a running Dask scheduler (default: start a LocalCluster)")
    e.add_argument("--workers", type=int, default=0, help="LocalCluster worker processes (default: the cores)")
    e.add_argument("--out", help="folder for eos.csv, tasks.csv, eos.png (default: ./circlecollide-eos-<time>)")
    e.add_argument("--no-plot", action="store_true", help="write no PNG (no matplotlib needed)")
    e.add_argument("--quiet", action="store_true", help="no progress bar")
    pl = sub.add_parser("plot", help="eos.png again from an eos.csv")
    pl.add_argument("csv", help="an eos.csv written by the eos command")
    pl.add_argument("--out", help="the PNG (default: eos.png beside the CSV)")
    return p


def main(argv: Optional[Sequence[str]] = None) -> int:
    args = parser().parse_args(argv)
    if args.command == "eos":
        if args.n < 1 or args.replicas < 1 or args.blocks < 1:
            raise SystemExit("eos: --n, --replicas and --blocks must be >= 1")
        run_eos(args)
    else:
        rows = read_eos_csv(args.csv)
        path = args.out or os.path.join(os.path.dirname(os.path.abspath(args.csv)), "eos.png")
        sys.stdout.write(table(rows) + "\n")
        sys.stdout.write(f"wrote {plot(rows, path)}\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
