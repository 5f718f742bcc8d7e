"""Writes docs/BENCHMARKS.md and its plots from the results of bench/run.sh.

Usage: python report.py RESULTS_DIR DOCS_DIR COMMAND
       python report.py --splice RESULTS_DIR DOCS_DIR COMMAND
RESULTS_DIR holds machine.txt, pair.csv, matrix.csv, headline.txt, scaling.csv, features.csv, idle.csv and
peers.txt; every number in the page comes from there.
--splice writes only section 10 (the 1.2 calls: bulk.txt, filter.txt, python_bulk.txt and the run's
bulk_machine.txt) into the page as it stands, in place of its section 10 or before "How to
reproduce": for a run of those benchmarks alone, which the section then dates and describes.
--splice-uses writes section 11 (worlds that reserve only what they use: uses.txt, from
`bench_world uses`, and uses_machine.txt) the same way.
"""
import csv
import math
import os
import re
import sys



def pyplot():
    # imported only where a plot is drawn: --splice needs no matplotlib
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def rows(path):
    if not os.path.exists(path):
        return []
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def figures(text):
    return {m.group(1): float(m.group(2)) for m in re.finditer(r"^figure (\S+) (\S+)$", text, re.M)}


def read(path):
    return open(path).read() if os.path.exists(path) else ""


def g(x, digits=3):
    x = float(x)
    if x == 0:
        return "0"
    if math.isnan(x):
        return "-"
    if abs(x) >= 1e5 or abs(x) < 1e-3:
        return "%.*e" % (digits - 1, x)
    return "%.*g" % (digits, x)


def peers_table(text):
    out = {}
    for line in text.splitlines():
        if not line.startswith("peer ") or "skipped" in line:
            continue
        parts = line.split()
        kv = dict(p.split("=", 1) for p in parts[2:] if "=" in p)
        out.setdefault(parts[1], []).append(kv)
    return out


def pareto_plot(matrix, path):
    plt = pyplot()
    scenes = list(dict.fromkeys(r["scene"] for r in matrix))
    cols = 3
    rows_n = (len(scenes) + cols - 1) // cols
    fig, grid = plt.subplots(rows_n, cols, figsize=(4.2 * cols, 3.4 * rows_n), squeeze=False)
    axes = [[ax for row in grid for ax in row]]
    for ax in axes[0][len(scenes):]:
        ax.set_visible(False)
    style = {"EXACT": ("o", "tab:green"), "SWEPT": ("s", "tab:blue"), "DISCRETE": ("^", "tab:red")}
    for ax, scene in zip(axes[0], scenes):
        for mode, (marker, color) in style.items():
            pts = [r for r in matrix if r["scene"] == scene and r["mode"] == mode]
            # an error of 0 (the reference itself) is drawn at the plot's floor
            xs = [max(float(r["traj_err_r"]), 1e-16) for r in pts]
            ys = [float(r["sec_per_sim_s"]) for r in pts]
            ax.scatter(xs, ys, marker=marker, color=color, label=mode)
            for r, x, y in zip(pts, xs, ys):
                ax.annotate("1/%d" % round(1 / float(r["dt"])), (x, y), fontsize=6, xytext=(2, 2),
                            textcoords="offset points")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_title(scene, fontsize=9)
        ax.set_xlabel("trajectory error / radius")
        ax.grid(True, which="major", alpha=0.3)
    axes[0][0].set_ylabel("wall s per simulated s")
    axes[0][0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def scaling_plot(scaling, path):
    plt = pyplot()
    ns = [float(r["n"]) for r in scaling]
    cost = [float(r["cost_ns"]) for r in scaling]
    fig, ax = plt.subplots(figsize=(5, 3.6))
    ax.loglog(ns, cost, "o-", label="EXACT, gas phi = 0.3")
    if ns:
        ref = [cost[0] * math.log(n) / math.log(ns[0]) for n in ns]
        ax.loglog(ns, ref, "--", color="gray", label="proportional to log N")
    ax.set_xlabel("circles N")
    ax.set_ylabel("ns per collision")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


SECTION_12 = "## 10. The 1.2 calls: the batch add and the query filter"


def bench_block(w, text):
    """A benchmark's printout as a code block, without its figure lines."""
    w("```")
    w("\n".join(l for l in text.strip("\n").splitlines() if not l.startswith("figure ")))
    w("```")
    w("")


def measured_apart(w, res, machine_file, command):
    """The line naming a section's own run (its command and the machine's state then), when the
    section was measured apart from bench/run.sh."""
    machine = read(os.path.join(res, machine_file)).strip().splitlines()
    if command and machine:
        w("Measured apart from the sections above (`%s`), in one session: %s." % (command, "; ".join(machine)))
        w("")


def section_12(res, w, command=None):
    """Section 10 from bulk.txt, filter.txt and python_bulk.txt (bench_bulk add, bench_queries
    filter, bench/python_bulk.py); with command, the separate run it came from is named."""
    bulk, filt, pyb, absent = (read(os.path.join(res, n)) for n in ("bulk.txt", "filter.txt", "python_bulk.txt",
                                                                     "filter_absent.txt"))
    if not (bulk or filt or pyb):
        return

    w(SECTION_12)
    w("")
    measured_apart(w, res, "bulk_machine.txt", command)
    if bulk:
        w("`bench_bulk add`: N circles (the gas of section 4 at area fraction 0.3, EXACT, its four walls) "
          "added to an empty world by one `cc_world_add_circles` call and by N `cc_world_add_circle` calls, "
          "each into fresh memory touched before the clock starts, the two alternating which goes first; "
          "ns per circle, medians over rounds [spread], the ratio per round. Both end with the same "
          "`cc_world_hash`. The batch checks every circle before it adds any (the header's Batches), so "
          "it reads its input twice: in C it is no faster than the single adds (it pays for that second "
          "pass); what it saves is a binding's crossing of its FFI for every circle (below).")
        w("")
        bench_block(w, bulk)
    if pyb:
        w("`bench/python_bulk.py`: the same from Python, `World.add_circles(pos, vel, radius, mass)` from "
          "numpy arrays (one C call per chunk) against a loop of `World.add_circle` over `Circle` values "
          "made before the clock starts (the loop's floor), us per circle; the ratio per round, and of "
          "the minima. Both end with the same `World.hash`. Unlike the C rows, a `World`'s memory (numpy "
          "zeros: pages mapped at their first write) is first written by the adds, in both rows: at "
          "N = 1e6 that is part of what `add_circles` costs, as it is for a user.")
        w("")
        bench_block(w, pyb)
    if filt:
        w("`bench_queries filter`: casts and disc queries from random points of the gas of 10,000 "
          "(section 6's calls), each as the 1.1 call (a mask), as its `_filtered` twin with "
          "`CC_QUERY_FILTER_DEFAULT` (passes everything), with `ignore` a circle far from every path "
          "(the one farthest from the box's centre: the same answers, so what the filter itself costs), and with `ignore` "
          "the circle nearest the start (a cue ball's own cast: the cast goes on past that circle to the "
          "next one, a longer search and another answer), the same points in every variant, the "
          "variants' order rotated each round; ratios to the 1.1 call per round. The 1.1 calls are the "
          "`_filtered` ones with {mask, -1}, so a program that sets no filter pays nothing for it.")
        w("")
        bench_block(w, filt)
    if absent:
        w("`bench/filter_absent.sh` (by hand: it needs a build from before the filter): the 1.1 calls "
          "(`bench_queries casts --quick`, the same points) of main before the filter's merge (73eb23c) "
          "against this build's, the two programs alternating, the ratio per round: what the filter "
          "costs a program that sets none.")
        w("")
        bench_block(w, absent)


SECTION_USES = "## 11. Worlds that reserve only what they use"


def section_uses(res, w, command=None):
    """Section 11 from uses.txt (bench_world uses); with command, the separate run named."""
    text = read(os.path.join(res, "uses.txt"))
    if not text:
        return
    w(SECTION_USES)
    w("")
    measured_apart(w, res, "uses_machine.txt", command)
    w("`bench_world uses`: the bytes per circle `cc_world_size` asks for (EXACT; SWEPT and DISCRETE "
      "need 9 to 11 fewer) with `cc_world_def.uses` = 0, `CC_USES_PROPS` and `CC_USES_ALL` (the "
      "default, and what a 1.0 or 1.1 def gets), open and periodic; then the plain periodic gas "
      "(hard disks at area fraction 0.3 from a lattice, nothing of 1.1 used) in a world of uses = 0 "
      "and one of ALL, in the same rounds, the two alternating which goes first: ns per "
      "collision after 5 time units, medians over rounds [spread], the ratio per round (uses = 0 / "
      "ALL). Both run the same collisions (the count is the first round's). The properties' "
      "48 bytes a circle are what uses = 0 saves: no path of a plain scene reads them, so what it "
      "changes in time is the memory a large world spreads over, and the noise of a shared machine. "
      "Where uses.txt holds more than one run, each is shown: their ratios scatter around 1 (at "
      "N = 1e6 the per-round ratios of one run lie all below 1 and of another all above), the "
      "machine's (memory and its pages, the other jobs) rather than the world's, which reads the "
      "same memory either way.")
    w("")
    bench_block(w, text)


def how_to(w):
    w("## How to reproduce")
    w("")
    w("```sh")
    w("bench/run.sh            # everything, writes this page (several minutes)")
    w("bench/run.sh --quick    # the headline figures only, under a minute once built")
    w("build-bench/bench/bench_pair --help; build-bench/bench/bench_world matrix|headline|scaling|features")
    w("build-bench/bench/bench_pair_rolling dump|time; bench/pooltool_rolling.py (section 8)")
    w("build-bench/bench/bench_queries casts|walls|filter")
    w("build-bench/bench/bench_bulk add [--quick]   # section 10, the batch add")
    w("build-bench/bench/bench_world uses [--quick]   # section 11, worlds that reserve only what they use")
    w("bench/filter_absent.sh 73eb23c build-bench/bench/bench_queries   # section 10, by hand")
    w("build-bench/bench/bench_idle [--quick]   # section 5, a step with nothing to do")
    w("build-bench/bench/bench_exact [--quick] [--max-n N] [--only disks|scaling|scenes|d3|d7|gas|big]   # section 9")
    w("CIRCLECOLLIDE_LIBRARY=build-bench/src/libcirclecollide.so PYTHONPATH=bindings/python/src \\")
    w("  build-bench/venv/bin/python bench/python_path.py build-bench/bench   # section 7")
    w("CIRCLECOLLIDE_LIBRARY=build-bench/src/libcirclecollide.so PYTHONPATH=bindings/python/src \\")
    w("  build-bench/venv/bin/python bench/python_bulk.py   # section 10")
    w("```")
    w("")


def splice(res, docs, command, title=SECTION_12, section=None):
    path = os.path.join(docs, "BENCHMARKS.md")
    page = read(path)
    L = []
    (section or section_12)(res, L.append, command)
    text = "\n".join(L) + "\n"
    start = page.find(title)
    if start >= 0:
        end = page.find("\n## ", start + len(title))
        page = page[:start] + text + page[end + 1:]
    else:
        at = page.find("## How to reproduce")
        page = page[:at] + text + page[at:]
    H = []
    how_to(H.append)
    page = page[:page.find("## How to reproduce")] + "\n".join(H)
    with open(path, "w") as f:
        f.write(page)


def main():
    if sys.argv[1] == "--splice":
        splice(*sys.argv[2:5])
        return
    if sys.argv[1] == "--splice-uses":
        splice(*sys.argv[2:5], title=SECTION_USES, section=section_uses)
        return
    res, docs, command = sys.argv[1:4]
    machine = read(os.path.join(res, "machine.txt")).strip().splitlines()
    pair = rows(os.path.join(res, "pair.csv"))
    matrix = rows(os.path.join(res, "matrix.csv"))
    scaling = rows(os.path.join(res, "scaling.csv"))
    features = rows(os.path.join(res, "features.csv"))
    idle = rows(os.path.join(res, "idle.csv"))
    figs = {}
    for name in ("pair.txt", "headline.txt", "features.txt", "idle.txt", "scaling.txt", "matrix.txt", "casts.txt",
                 "walls.txt", "periodic_casts.txt", "exact.txt", "rolling.txt"):
        figs.update(figures(read(os.path.join(res, name))))
    peers = peers_table(read(os.path.join(res, "peers.txt")))
    if matrix:
        pareto_plot(matrix, os.path.join(docs, "bench_pareto.png"))
    if scaling:
        scaling_plot(scaling, os.path.join(docs, "bench_scaling.png"))

    L = []
    w = L.append

    def notes(name):
        # a hand-kept account (bench/NAME) after a section's measured block: a rerun keeps it
        text = read(os.path.join(os.path.dirname(os.path.abspath(__file__)), name))
        if text:
            w(text.rstrip())
            w("")
    w("# Benchmarks: what exactness costs")
    w("")
    w("Generated by `%s` (do not edit by hand; rerun it). Every number below was measured in that one "
      "run, on this machine, side by side; the machine is shared and noisy, so each time is the median "
      "of several repetitions with its spread (min - max), and ratios are medians of per-round ratios "
      "where the methods ran in the same round. `bench/run.sh --quick` prints the headline figures in "
      "under a minute." % command)
    w("")
    for m in machine:
        w("- " + m)
    w("")

    # ---- headline
    exact_tunnel = sum(int(r["tunnelling"]) + int(r["escaped"]) for r in matrix if r["mode"] == "EXACT")
    ours_peer = peers.get("circlecollide", [])
    bil = peers.get("billiards", [])
    bil_ratio = None
    if bil and ours_peer:
        ours_rate = float(ours_peer[-1]["collisions_per_s"])
        bil_ratio = ours_rate / float(bil[0]["collisions_per_s"])
    growth = None
    if len(scaling) >= 2:
        c0, c1 = float(scaling[0]["cost_ns"]), float(scaling[-1]["cost_ns"])
        n0, n1 = float(scaling[0]["n"]), float(scaling[-1]["n"])
        growth = (c1 / c0, math.log(n1) / math.log(n0), n0, n1)
    w("## Headline figures and targets")
    w("")
    w("| figure | value | target | met |")
    w("|---|---|---|---|")

    def target(name, value, text, ok):
        w("| %s | %s | %s | %s |" % (name, value, text, "yes" if ok else "**no**"))

    if "sweep_speedup_vs_box2d" in figs:
        v = figs["sweep_speedup_vs_box2d"]
        target("`sweep_speedup_vs_box2d` (b2TimeOfImpact time / cc_sweep time)", g(v), ">= 20", v >= 20)
    if "sweep_cost_vs_textbook" in figs:
        v = figs["sweep_cost_vs_textbook"]
        target("`sweep_cost_vs_textbook` (cc_sweep time / textbook time)", g(v), "<= 1.3", v <= 1.3)
    if "world_collisions_per_s_n10000" in figs:
        v = figs["world_collisions_per_s_n10000"]
        target("`world_collisions_per_s_n10000` (EXACT, gas phi = 0.3, one core)", g(v), ">= 3e6", v >= 3e6)
    if growth:
        target("EXACT cost per collision, N = %s vs %s" % (g(growth[3]), g(growth[2])), "x %s" % g(growth[0]),
               "<= x %s (log N / log N0)" % g(growth[1]), growth[0] <= growth[1])
    if matrix:
        target("tunnelling + escapes in EXACT (all scenes, steps)", str(exact_tunnel), "0", exact_tunnel == 0)
    if bil_ratio is not None:
        target("collisions/s, ours / billiards (N = 1000)", g(bil_ratio), ">= 1000", bil_ratio >= 1000)
    if "rolling_pair_over_sweep" in figs:  # issue 12's target (section 8: it moves with the machine's state)
        v = figs["rolling_pair_over_sweep"]
        target("`rolling_pair_over_sweep` (cc_sweep_rolling time / cc_sweep time, pool pairs)", g(v), "<= 3", v <= 3)
    w("")

    # ---- pair
    if pair:
        w("## 1. Pair level: time of impact of two moving circles")
        w("")
        w("The same random pairs for every method (radii 0.05-0.5, gaps up to 3, speeds up to ~6, t_max = 1; "
          "no pair overlapping at t = 0), one thread. *Cache-resident*: blocks of 1024 pairs swept twice, "
          "the second pass timed (the compute cost, as inside a world). *Streamed*: every pair once from "
          "main memory (a batch query). Accuracy against the exact reference (GMP/MPFR, "
          "tests/reference/) on the very inputs each method saw (float methods: the float roundings): "
          "*disagreements* = hit/miss differs from the exact answer; *error* = |t - t_exact| for pairs "
          "both call a hit (t in [0, 1]).")
        w("")
        w("| method | ns/pair cache-resident | spread | ns/pair streamed | spread | hits | disagreements | "
          "median error | max error | note |")
        w("|---|---|---|---|---|---|---|---|---|---|")
        for r in pair:
            dis = r["disagreements"] if int(r["disagreements"]) >= 0 else "-"
            w("| %s | %s | %s - %s | %s | %s - %s | %s | %s | %s | %s | %s |" % (
                r["method"], g(r["ns_hot_median"]), g(r["ns_hot_min"]), g(r["ns_hot_max"]),
                g(r["ns_stream_median"]), g(r["ns_stream_min"]), g(r["ns_stream_max"]), r["hits"], dis,
                g(r["err_median"]), g(r["err_max"]), r["note"]))
        w("")
        w("Box2D's b2TimeOfImpact is a conservative-advancement solver in float that stops at a separation "
          "of R minus its linear slop (5 mm) within a tolerance: its 'errors' are mostly that designed "
          "offset, and its disagreements are grazing pairs inside the slop band; it is the speed "
          "comparison that matters there. `cc_sweep_many` is bit-identical to cc_sweep per pair (it returns "
          "time and code only, no point or normal).")
        w("")

    # ---- world matrix
    if matrix:
        w("## 2. World level: scenes x modes x step sizes")
        w("")
        w("Scenes: a gas of equal discs (r = 0.5, Gaussian velocities, four walls) at area fractions "
          "0.05, 0.3 and 0.6; a pool break (15 racked balls 1 um apart, cue ball at 10 m/s, four cushions); "
          "air hockey (a 30 m/s puck, 8 puck radii per 1/60 s step, two immovable mallets). Restitution 1. "
          "Each run simulates the scene's time (gas 1 s, pool and hockey 2 s). *s/sim s* = wall seconds "
          "per simulated second (median of repetitions, spread min - max); *tunnelling* = pairs or wall "
          "contacts that the pre-step motion makes within a step but that end the step apart with "
          "unchanged velocities (they passed through); *escaped* = centres that left the table; "
          "*overlap* = deepest overlap after any step, in radii; *dE/E* = relative energy change over "
          "the run; *error* = RMS distance of the final positions from EXACT at a step of 1/7680, in radii "
          "(the plot draws that reference itself, error 0, at 1e-16).")
        w("")
        w("![cost against error](bench_pareto.png)")
        w("")
        w("| scene | mode | step | s/sim s | spread | collisions/s | tunnelling | escaped | overlap/r | dE/E | "
          "error/r |")
        w("|---|---|---|---|---|---|---|---|---|---|---|")
        for r in matrix:
            w("| %s | %s | 1/%d | %s | %s - %s | %s | %s | %s | %s | %s | %s |" % (
                r["scene"], r["mode"], round(1 / float(r["dt"])), g(r["sec_per_sim_s"]), g(r["sec_min"]),
                g(r["sec_max"]), g(r["collisions_per_s"]), r["tunnelling"], r["escaped"], g(r["max_overlap_r"]),
                g(r["energy_drift"]), g(r["traj_err_r"])))
        w("")
        head = read(os.path.join(res, "headline.txt")).strip()
        if head:
            w("EXACT on the gas at N = 10000, phi = 0.3 (steps of 1/60 after a warm-up of about half a collision "
              "per circle; the world's own counters per collision, since its creation):")
            w("")
            w("```")
            w(head)
            w("```")
            w("")

    notes("walls_notes.md")  # the hand-kept table of escapes against speed and the jam, after section 2

    # ---- scaling
    if scaling:
        w("## 3. Scaling of EXACT with N")
        w("")
        w("The gas at phi = 0.3, N circles, timed after a warm-up of about half a collision per circle (the "
          "first step makes every initial prediction; the lattice start needs a few collisions to become a "
          "gas), steps of 1/60, median of 3 runs; memory = cc_world_size / N for a world of "
          "capacity N with four walls.")
        w("")
        w("![cost per collision against N](bench_scaling.png)")
        w("")
        w("| N | collisions/s | ns per collision | rate spread | bytes per circle |")
        w("|---|---|---|---|---|")
        for r in scaling:
            w("| %s | %s | %s | %s - %s | %s |" % (r["n"], g(r["collisions_per_s"]), g(r["cost_ns"]),
                                                  g(r["rate_min"]), g(r["rate_max"]),
                                                  g(r["bytes_per_circle"])))
        w("")

    # ---- peers
    if peers:
        w("## 4. Peers on the same gas (N = 1000, phi = 0.3, steps of 1/60)")
        w("")
        w("All engines start from the state of `bench_world dump-gas 1000 0.3`; only their own stepping is "
          "timed; tunnelling, escapes, overlap and energy drift are judged from the recorded steps by the "
          "same checker (bench/bench_check.c). Box2D: every body a bullet, restitution 1, restitution "
          "threshold 0, no friction, 4 substeps; its collisions are begin-touch events. pymunk: "
          "elasticity 1, no friction, begin callbacks. billiards is exact and event-driven but pure "
          "Python, so it runs 1 simulated second; our rate at the same length is its comparison row.")
        w("")
        w("| engine | simulated s | collisions | collisions/s | ours / theirs | tunnelling | escaped | "
          "overlap/r | dE/E |")
        w("|---|---|---|---|---|---|---|---|---|")
        ours_rates = [float(p["collisions_per_s"]) for p in peers.get("circlecollide", [])]
        for name, lst in peers.items():
            for i, p in enumerate(lst):
                rate = float(p["collisions_per_s"])
                sim_s = float(p["collisions"]) / rate / float(p["sec_per_sim_s"]) if rate > 0 else float("nan")
                if name == "circlecollide":
                    ratio = "1"
                else:
                    ref = ours_rates[-1] if name == "billiards" else ours_rates[0]
                    ratio = g(ref / rate) if rate > 0 else "-"
                w("| %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
                    name, g(sim_s, 2), p["collisions"], g(rate), ratio, p["tunnelling"], p["escaped"],
                    g(p["max_overlap_r"]), g(p["energy_drift"])))
        w("")

    # ---- features
    if features:
        w("## 5. Model only what a scene requires: absent features cost nothing")
        w("")
        w("The same freely expanding gas (no wall is ever reached within the run; N = 10000, phi = 0.3, EXACT, "
          "5 simulated seconds), with features absent, allowed but unused, or present far away. Every "
          "variant but the last processes exactly the same collisions (the column shows it): filters that "
          "admit every pair and sensors change no impulse; half the pairs filtered is other physics, shown "
          "for the cost per collision of a filtered world. The variants run in rotating "
          "order within each round. *Ratio* = median over rounds of the per-round cost ratio to the first row; "
          "*ratio of minima* = fastest run over fastest baseline run, the steadier estimate on a noisy "
          "machine (noise only adds time), and the one the `feature_cost_*` figures report.")
        w("")
        w("| variant | ns per collision | spread | collisions | ratio to baseline | ratio of minima |")
        w("|---|---|---|---|---|---|")
        for r in features:
            w("| %s | %s | %s - %s | %s | %s | %s |" % (r["variant"], g(r["ns_per_collision"]), g(r["ns_min"]),
                                                        g(r["ns_max"]), r["collisions"], g(r["ratio_to_base"]),
                                                        g(r["ratio_of_minima"])))
        w("")
    if idle:
        w("A step with nothing to do (`bench_idle`, EXACT, steps of 1 ms): a world of 10,000 circles at rest, "
          "and the same circles moving at up to 1e-3 (about 0.01 cell crossings per step, no collisions), "
          "against an empty world of the same capacity, in rotating order within each round. What a step costs "
          "beyond its events is `cc_world_step`'s own check of what the step may reach (2^1017, and half a "
          "period in periodic SWEPT), decided from bounds the world keeps (src/world/step.c), not by a pass "
          "over every circle. *Ratio* = median over rounds of the per-round ratio to the empty world.")
        w("")
        w("| variant | N | ns per step | spread | ratio to empty | events per step |")
        w("|---|---|---|---|---|---|")
        for r in idle:
            w("| %s | %s | %s | %s - %s | %s | %s |" % (r["variant"], r["n"], g(r["ns_per_step"]), g(r["ns_min"]),
                                                     g(r["ns_max"]), g(r["ratio_to_empty"]), g(r["events_per_step"])))
        w("")
    if features or idle:
        notes("features_notes.md")  # the hand-kept account of those rows' history, after the measured tables

    # ---- queries and walls (bench_queries)
    casts, walls = read(os.path.join(res, "casts.txt")), read(os.path.join(res, "walls.txt"))
    periodic = read(os.path.join(res, "periodic_casts.txt"))
    if casts or walls or periodic:
        w("## 6. Queries and walls at scale")
        w("")
        w("Casts (a ray, and a circle of radius 0.5, over 10 units) and disc queries (radius 1.5) from random "
          "points of the gas at area fraction 0.3, in worlds of growing N at the same density: the cost "
          "follows the region a query covers, not the world (ratios to N = 1000). Then the gas of 10,000 "
          "circles with its 4 walls, and with 10,000 short walls on rings outside the box that no circle "
          "reaches (the same collisions): the walls' tree keeps the cost per collision close. Last, ray casts "
          "in that gas (10,000 circles) made periodic, in each mode after one step, against the walled gas's EXACT "
          "cast of the same length (10 radii, and three periods): a periodic cast sees every image along its "
          "path, through the grid in EXACT, and in SWEPT and DISCRETE (no grid between steps) by every "
          "circle's images in each half period of the path.")
        w("")
        for text in (casts, walls, periodic):
            if text:
                w("```")
                w("\n".join(l for l in text.splitlines() if not l.startswith("figure ")))
                w("```")
                w("")

    # ---- the Python path (bench/python_path.py)
    py = read(os.path.join(res, "python_path.txt"))
    if py:
        w("## 7. The Python path")
        w("")
        w("`bench/python_path.py`: the gas of section 4 at N = 10,000 stepped from Python (one `World.step` "
          "call a frame, then also reading `World.positions` every frame) against `bench_world peer` in C, "
          "and one pair-function call from Python against the C function and the Python peers' "
          "equivalents (billiards' `time_of_impact` answers what `sweep` does; pymunk's "
          "`shapes_collide` what `detect_static` does). Each round measures every row; ratios are per "
          "round, median [min, max]. Python runs the same library build (CIRCLECOLLIDE_LIBRARY).")
        w("")
        w("```")
        w("\n".join(l for l in py.splitlines() if not l.startswith("figure ")))
        w("```")
        w("")
        notes("python_notes.md")  # the hand-kept reading of an earlier run, after the measured block

    # ---- rolling pair (bench_pair_rolling + pooltool_rolling.py, issue 12)
    rolling = read(os.path.join(res, "rolling.txt"))
    if rolling:
        w("## 8. Rolling pair: cc_sweep_rolling beside cc_sweep, the textbook quartic and pooltool")
        w("")
        w("20,000 pool-like pairs (balls of radius 0.028575 m on a 2.54 x 1.27 m table, speeds 0.05..3 m/s, "
          "rolling resistance mu g = 0.0981 m/s^2, a third of the second balls at rest), all methods on the "
          "same pairs in the same run: cc_sweep_rolling; cc_sweep on the same pairs without friction; the "
          "textbook quartic (Ferrari, tests/reference/textbook_quartic.c); pooltool's ball-ball collision "
          "time (ball_ball_collision_coeffs + ptmath.roots.quartic.solve + min_real_root), one pair at a "
          "time from Python as its event loop calls it, and its batched numba solver (quartic.solve_many) "
          "alone. Accuracy on the same pairs and on the rolling corpus: docs/NUMERICS.md.")
        w("")
        w("```")
        w("\n".join(l for l in rolling.splitlines() if not l.startswith("figure ") and not l.startswith("csv ")))
        w("```")
        w("")
        notes("rolling_notes.md")  # the hand-kept account of issue 12's changes, after the measured block

    # ---- issue 16 (bench_exact): the measured run, then the hand-kept account (bench/exact_notes.md)
    exact = read(os.path.join(res, "exact.txt"))
    if exact:
        w("## 9. EXACT at research speed (issue 16)")
        w("")
        w("`bench_exact`: EXACT's cost per collision divided by `cc_sweep`'s cache-resident time per pair, both "
          "measured in the same round of the same process (CPU time, so that the waits of a shared machine stay "
          "out); periodic hard disks of diameter 1 (N = 10,000 at area fractions 0.3 and 0.7), the walled gas of "
          "the headline, N = 10,000 against a large N at 0.3, the pool break and the air-hockey rally. Medians "
          "over rounds, [min - max].")
        w("")
        w("```")
        w("\n".join(l for l in exact.splitlines() if not l.startswith("figure ")))
        w("```")
        w("")
    notes("exact_notes.md")

    section_12(res, w)
    section_uses(res, w)

    how_to(w)
    with open(os.path.join(docs, "BENCHMARKS.md"), "w") as f:
        f.write("\n".join(L))


if __name__ == "__main__":
    main()
