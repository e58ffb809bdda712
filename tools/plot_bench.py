#!/usr/bin/python3
"""Plots a `sandbox bench` run: frame time against error, Pareto front marked.

Usage: tools/plot_bench.py bench.json bench.png
Uses Debian's python3-matplotlib (scripts/bootstrap installs it); nothing else.
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(source, target):
    run = json.load(open(source))
    rows = [r for r in run["results"] if r["rel_rmse"] is not None]
    fig, ax = plt.subplots(figsize=(8, 5), dpi=110)
    # Rows without a mode are the default mode's (the tiers and the budget's rungs).
    for mode, marker in (("particles", "o"), ("blocks", "s"), ("raymarch", "^"), ("sheets", "D"), ("billboards", "x")):
        pts = [r for r in rows if r["settings"].get("mode", "particles") == mode]
        ax.scatter([r["frame_ms"] for r in pts], [100 * r["rel_rmse"] for r in pts], marker=marker, label=mode,
                   alpha=0.8)
    front = sorted((r for r in rows if r["pareto"]), key=lambda r: r["frame_ms"])
    ax.plot([r["frame_ms"] for r in front], [100 * r["rel_rmse"] for r in front], "k--", lw=1, label="Pareto front")
    for r in rows:
        ax.annotate(r["setting"].replace("particles", "p").replace("blocks", "b"), (r["frame_ms"], 100 * r["rel_rmse"]),
                    fontsize=6, xytext=(3, 3), textcoords="offset points")
    ax.set_xscale("log")
    ax.set_xlabel("frame time, ms (median, GPU-synchronised)")
    ax.set_ylabel("rel-RMSE vs reference, %")
    ax.set_title("%s at %dx%d, t = %g s (%s)" % (run["scene"].split("/")[-1], run["width"], run["height"], run["time"],
                                                 run["gl_renderer"].split(" (")[0]))
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(target)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
