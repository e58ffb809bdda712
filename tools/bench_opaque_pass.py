#!/usr/bin/env python3
"""The opaque pass's cost on the content scenes, two builds side by side in one run.

    tools/bench_opaque_pass.py BEFORE_SANDBOX BEFORE_SCENES AFTER_SANDBOX AFTER_SCENES [--size WxH] [--rounds N]

Each scene is rendered by the two builds in turn (A B A B ..., N rounds), each render timing 20
GPU-synchronised frames (`sandbox render --stats`, per-pass medians); a row is the median over the
rounds of each build's `passes_ms.opaque`, and their ratio. The scenes are each build's own files
(BEFORE_SCENES, AFTER_SCENES: a content/scenes folder), at make_scenes.py's times, balanced tier.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "scenegen"))
from make_scenes import TIMES  # noqa: E402


def opaque_ms(sandbox, scene, time, size):
    with tempfile.TemporaryDirectory() as folder:
        stats = os.path.join(folder, "stats.json")
        subprocess.run([sandbox, "render", scene, "--size", size, "--time", str(time), "--out", os.path.join(folder, "f.png"),
                        "--stats", stats], check=True, stdout=subprocess.DEVNULL)
        with open(stats) as f:
            return json.load(f)["passes_ms"]["opaque"]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("before_sandbox")
    parser.add_argument("before_scenes")
    parser.add_argument("after_sandbox")
    parser.add_argument("after_scenes")
    parser.add_argument("--size", default="1280x720")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--scenes", default="demo,smoke,campfire,cloud,cumulus,cumulus_aircraft,jet,explosion,fog_smoke")
    a = parser.parse_args()
    print("| scene | opaque before (ms) | opaque after (ms) | after / before |")
    print("|---|---|---|---|")
    for name in a.scenes.split(","):
        before, after = [], []
        time = TIMES.get(name, 0.0)
        for _ in range(a.rounds):
            before.append(opaque_ms(a.before_sandbox, os.path.join(a.before_scenes, name + ".gltf"), time, a.size))
            after.append(opaque_ms(a.after_sandbox, os.path.join(a.after_scenes, name + ".gltf"), time, a.size))
        b, n = statistics.median(before), statistics.median(after)
        print("| %s | %.2f | %.2f | %.2f |" % (name, b, n, n / b), flush=True)


if __name__ == "__main__":
    main()
