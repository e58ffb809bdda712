#!/usr/bin/python3
"""Assembles docs/PERFORMANCE.md from the measurements scripts/bench just took.

Usage: tools/make_performance_md.py BENCH_DIR DOCS_DIR
       tools/make_performance_md.py --tiers|--sweeps|--multiple|--raymarch|--editor BENCH_DIR DOCS_DIR   (one section)
Every number in the page comes from BENCH_DIR; the prose around them only says what the numbers
show (which setting is on the Pareto front, how cost grows), so the page stays true to the code.
The sections this script does not generate (each names the script or test that measured it) are
kept as they are.
"""
import glob
import json
import statistics
import math
import os
import platform
import shutil
import sys


def cpu_model():
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown CPU"


def pct(v):
    return "–" if v is None else "%.2f%%" % (100 * v)


def table(run):
    rows = ["| setting | frame ms | media ms | frame / floor | rel-RMSE | PSNR dB | Pareto |",
            "|---|---:|---:|---:|---:|---:|:-:|"]
    for r in run["results"]:
        over = "–" if r["frame_over_floor"] is None else "%.1f×" % r["frame_over_floor"]
        rows.append("| %s | %.1f | %.1f | %s | %s | %s | %s |" % (
            r["setting"], r["frame_ms"], r["media_ms"], over, pct(r["rel_rmse"]),
            "–" if r["psnr"] is None else "%.1f" % r["psnr"], "●" if r["pareto"] else ""))
    return "\n".join(rows)


def pareto_advice(run):
    rows = [r for r in run["results"] if r["rel_rmse"] is not None]
    front = sorted((r for r in rows if r["pareto"]), key=lambda r: r["frame_ms"])
    best = min(rows, key=lambda r: r["rel_rmse"])
    fastest = front[0]
    default = next((r for r in rows if r["setting"] == "particles"), None)
    good = [r for r in front if r["rel_rmse"] <= 1.25 * best["rel_rmse"]]
    text = ["Pareto front, fastest first: " + ", ".join("`%s` (%.1f ms, %s)" % (r["setting"], r["frame_ms"], pct(r["rel_rmse"]))
                                                        for r in front) + "."]
    if good:
        g = good[0]
        line = "Best trade: `%s` — within 25%% of the lowest error (%s, `%s`) at %.1f ms" % (
            g["setting"], pct(best["rel_rmse"]), best["setting"], g["frame_ms"])
        if default:
            line += ", %.1f× faster than the default `particles` (%.1f ms, %s)" % (default["frame_ms"] / g["frame_ms"],
                                                                                 default["frame_ms"], pct(default["rel_rmse"]))
        text.append(line + ".")
    text.append("Fastest on the front: `%s` at %.1f ms with %s." % (fastest["setting"], fastest["frame_ms"], pct(fastest["rel_rmse"])))
    return " ".join(text)


def scaling_section(run):
    rows = run.get("scaling") or []
    if not rows:
        return ""
    out = ["| setting | particles | 320×180 ms | 640×360 ms | 1280×720 ms |", "|---|---:|---:|---:|---:|"]
    keys = sorted({(r["mode"], r["particles"]) for r in rows}, key=lambda k: (k[0], k[1]))
    cell = {(r["mode"], r["particles"], r["width"]): r.get("frame_ms") for r in rows}
    floor = {(r["mode"], r["particles"], r["width"]): r.get("splat_floor_ms") for r in rows}

    def entry(mode, n, w):
        ms = cell.get((mode, n, w))
        if ms is None:
            return "skipped"
        f = floor.get((mode, n, w))
        return "%.1f (%.1f× floor)" % (ms, ms / f) if f else "%.1f" % ms
    for mode, n in keys:
        out.append("| %s | %d | %s |" % (mode, n, " | ".join(entry(mode, n, w) for w in (320, 640, 1280))))
    growth = []
    for mode in sorted({k[0] for k in keys}):
        for w in (320, 640, 1280):
            pts = [(n, cell[(mode, n, w)]) for (m, n) in keys if m == mode and cell.get((mode, n, w))]
            if len(pts) >= 2:
                (n0, t0), (n1, t1) = pts[0], pts[-1]
                growth.append("`%s` at width %d: time ∝ N^%.2f from %d to %d particles" % (
                    mode, w, math.log(t1 / t0) / math.log(n1 / n0), n0, n1))
    return "\n".join(out) + "\n\nHow cost grows (log-log slope between the smallest and largest count measured): " + \
        "; ".join(growth) + ".\n"


TIER_SCENES = [("cloud", "tiers_cloud"), ("smoke", "tiers_smoke"), ("campfire", "tiers_campfire"), ("jet", "tiers_jet"),
               ("explosion", "tiers_explosion"), ("cumulus", "cumulus_1280"), ("cumulus_aircraft", "aircraft_1280")]
TIERS = [("fast", "fast"), ("balanced", "balanced"), ("exact", "particles"), ("billboards", "billboards")]


def tiers_section(runs, bench_dir):
    present = [(scene, runs[name]) for scene, name in TIER_SCENES if name in runs]
    if not present:
        return []
    out = ["## Quality tiers", "",
           "`--quality` (or a scene's `render.quality`) picks each setting's value for the tier; anything set explicitly "
           "wins. The settings a tier changes, as `sandbox settings` declares them:", "", "```"]
    settings_txt = os.path.join(bench_dir, "settings.txt")
    if os.path.exists(settings_txt):
        for line in open(settings_txt).read().splitlines():
            key, _, rest = line.partition(" ")
            default = rest[rest.find("; default ") + len("; default "):] if "; default " in rest else ""
            default = default.split("; in ")[0]
            if "balanced" in default or "fast" in default:
                out.append("%-20s %s" % (key, default))
    out += ["```", "",
            "- `exact`: every correction per fragment (light integrated over each particle, exact chord integrals, "
            "neighbour order). The library's default.",
            "- `balanced` (the default of `sandbox render` and `scripts/demo`): light evaluated once per particle at nine rays "
            "with the exact chord integrals and fitted across the billboard, the sun's phase function and nearby lamps per "
            "fragment (a lamp's near field with the exact tier's quadrature and, around its peak, neighbour order); per "
            "fragment otherwise one kernel-table fetch.",
            "- `fast`: as balanced with cheaper light (one table fetch per ray), slices deposited in O(N) fill, automatic "
            "slice resolution, media at ¼ to ½ resolution where particles cover the image more than 2.5 times over "
            "and a typical billboard keeps 8 texels across its half size at ½ (drawn again at full resolution at the "
            "edges where a mesh enters the medium: `mixed_resolution`), and cheaper mesh shadows.",
            "- `billboards`: not a tier but the yardstick of what a typical engine ships: sorted sprites lit once per "
            "particle, no volumetric or mesh shadows, a soft-particle fade, one fetch per fragment.", "",
            "### Every content scene at 1280×720", "",
            "One `sandbox bench` run per scene (scripts/bench-tiers), the rows side by side, in single scattering: error is "
            "rel-RMSE against the single-scattering reference of the same frame. "
            "Each row's multiple is of the floor measured right after its own frames; the floor column is the median of "
            "the rows' (llvmpipe's timings move by up to ±30% between runs on this shared machine).", "",
            "| scene | particles | splat floor ms | " + " | ".join("%s ms (× floor, error)" % t for t, _ in TIERS) +
            " | exact / balanced | exact / fast |",
            "|---|---:|---:|" + "---:|" * len(TIERS) + "---:|---:|"]
    for scene, run in present:
        res = {r["setting"]: r for r in run["results"]}
        floors = sorted(r["splat_floor_ms"] for r in run["results"] if r.get("splat_floor_ms"))
        floor_ms = floors[len(floors) // 2] if floors else None
        cells = []
        for _, setting in TIERS:
            r = res.get(setting)
            if not r:
                cells.append("–")
                continue
            over = "" if r["frame_over_floor"] is None else "%.1f×, " % r["frame_over_floor"]
            cells.append("%.1f (%s%s)" % (r["frame_ms"], over, pct(r["rel_rmse"])))

        def ratio(a, b):
            return "%.1f×" % (res[a]["frame_ms"] / res[b]["frame_ms"]) if a in res and b in res else "–"
        out.append("| %s | %d | %s | %s | %s | %s |" % (scene, run["particles"], "–" if floor_ms is None else "%.1f" % floor_ms,
                                                        " | ".join(cells), ratio("particles", "balanced"), ratio("particles", "fast")))
    fast = [(scene, {r["setting"]: r for r in run["results"]}.get("fast")) for scene, run in present]
    fast = [(scene, r) for scene, r in fast if r and r["frame_over_floor"] is not None]
    if fast:
        worst = max(fast, key=lambda sr: sr[1]["frame_over_floor"])
        best = min(fast, key=lambda sr: sr[1]["frame_over_floor"])
        out += ["", "The fast tier runs at %.1f× (%s) to %.1f× (%s) the splat floor. Where the floor is a millisecond or two "
                "(a few hundred small particles), the frame's fixed full-screen work (shadow maps, the opaque pass, compose) "
                "dominates; see each scene's passes in its sweep below." % (
                    best[1]["frame_over_floor"], best[0], worst[1]["frame_over_floor"], worst[0])]
    out.append("")
    return out


def main(bench_dir, docs_dir):
    runs = {}
    for path in sorted(glob.glob(os.path.join(bench_dir, "*", "bench.json"))):
        runs[os.path.basename(os.path.dirname(path))] = json.load(open(path))
    perf_dir = os.path.join(docs_dir, "perf")
    os.makedirs(perf_dir, exist_ok=True)
    any_run = next(iter(runs.values()))
    lines = ["# Performance: speed against error", "",
             "Generated by `scripts/bench` (which runs `sandbox bench` and the reference benchmark) on %s." % any_run["date"][:10],
             "Do not edit the generated sections by hand: rerun the script. The sections it does not generate name the "
             "script or test that measured them and are kept as they are. Every speed claim is a ratio measured side by "
             "side in one run.", "",
             "- Machine: %s, %d cores (%s)" % (cpu_model(), os.cpu_count() or 0, platform.platform()),
             "- GL renderer: %s" % any_run["gl_renderer"],
             "- Frame time: median of %s GPU-synchronised frames after warm-up; per-pass medians from a second run." %
             ("20" if True else ""),
             "- Error: `sandbox compare` metrics of the real-time frame against `sandbox reference` of the same scene, time and size.",
             "- Splat floor (`splat_floor_ms`, `sandbox render --floor`): the time this GL implementation takes to blend every "
             "particle's full-resolution billboard once with a trivial shader, measured in the same process right after the "
             "timed frames. It is the scene's fixed yardstick whatever a mode writes; `frame / floor` is the frame time as a "
             "multiple of it.",
             ""]
    lines += tiers_section(runs, bench_dir)
    cum = runs.get("cumulus_1280")
    if cum:
        res = {r["setting"]: r for r in cum["results"]}
        p = res.get("particles")
        lines += ["## Blocks against particles: 8000 particles at 1280×720", "",
                  "content/scenes/cumulus.gltf, %d particles, one run:" % cum["particles"], "", table(cum), ""]
        if p:
            for name in ("blocks", "blocks instancing"):
                if name in res:
                    b = res[name]
                    lines.append("- `%s`: %.1f× faster than `particles` (%.0f ms vs %.0f ms), rel-RMSE %s vs %s." % (
                        name, p["frame_ms"] / b["frame_ms"], b["frame_ms"], p["frame_ms"], pct(b["rel_rmse"]), pct(p["rel_rmse"])))
            best = min((r for r in cum["results"] if r["setting"].startswith("blocks")), key=lambda r: r["frame_ms"])
            lines.append("- Fastest block setting measured: `%s`, %.1f× faster than `particles`." % (
                best["setting"], p["frame_ms"] / best["frame_ms"]))
        lines += ["", "The seed (seed 000, an NV6800GT) reports 25× (8 → 200 FPS) for 8000 particles. Its speed-up comes from "
                  "replacing per-particle work that a GPU of 2005 paid per fragment *and* per particle (read-backs in the light "
                  "pass, one draw per particle) with per-block work. Here the light pass never read back (optical depth is "
                  "additive), particles are drawn instanced in one call, and the rasteriser is llvmpipe on %d CPU cores: "
                  "time follows the number of shaded fragments, so the gain is the ratio of fragments the heavy shader runs on "
                  "— one per covered pixel per particle against one per covered pixel per block, plus the cheap impostor "
                  "fragments — which the `media ms` column shows. The fast tier takes the other route: the heavy work moves off the "
                  "fragments altogether (lighting once per particle, one table fetch per fragment)." % (os.cpu_count() or 0), ""]
    air = runs.get("aircraft_1280")
    if air:
        res = {r["setting"]: r for r in air["results"]}
        p = res.get("particles")
        lines += ["## With a mesh inside the cloud: the same 8000 particles and an aircraft, at 1280×720", "",
                  "content/scenes/cumulus_aircraft.gltf (cumulus.gltf with an airliner-sized aircraft flying through it), one run. "
                  "`blocks` (block_shading=seam, the default) shades blocks exactly near the texels where the aircraft lies "
                  "among their particles and smoothly elsewhere; `block_shading=smooth` shades every block smoothly:", "", table(air), ""]
        if p:
            for name in ("blocks", "blocks block_shading=smooth", "blocks block_shading=exact"):
                if name in res:
                    b = res[name]
                    lines.append("- `%s`: %.2f× the speed of `particles` (%.0f ms vs %.0f ms), rel-RMSE %s vs %s." % (
                        name, p["frame_ms"] / b["frame_ms"], b["frame_ms"], p["frame_ms"], pct(b["rel_rmse"]), pct(p["rel_rmse"])))
        lines.append("")
    lines += sweeps_section(bench_dir, docs_dir)
    if "scaling" in runs:
        lines += ["## Scaling with particle count and resolution", "",
                  "A synthetic cloud in content/scenes/cumulus.gltf's media bounds, constant optical depth, 5 timed frames each "
                  "(a setting is skipped when the 10× smaller cloud already took over 0.8 s). `particles` is the exact tier, "
                  "`fast` the fast tier; each cell gives the frame time and its multiple of the splat floor.", "",
                  scaling_section(runs["scaling"])]
    budget_path = os.path.join(bench_dir, "budget.json")
    if os.path.exists(budget_path):
        b = json.load(open(budget_path))
        lines += ["## Frame budget", "",
                  "`sandbox render %s --size %dx%d --budget-ms %g`: the controller walked the quality ladder (tiers and media "
                  "resolutions, ordered by the error the sweeps measure) on this machine and kept **%s**; its frames then took "
                  "a median of %.1f ms (%.2f× the budget) over %d frames." % (
                      b["scene"], b["width"], b["height"], b["budget_ms"], b["chosen"], b["frame_ms"], b["frame_ms"] / b["budget_ms"],
                      b["frames"]), ""]
    ref_path = os.path.join(bench_dir, "reference.json")
    if os.path.exists(ref_path):
        ref = json.load(open(ref_path))
        for b in ref.get("benchmarks", []):
            lines += ["## Reference renderer", "",
                      "`nimbus_reference_benchmark` (tests/benchmarks): 640×360, %d particles, tolerance 1e-4: **%.1f s** on %d cores "
                      "(goal ≤ 60 s), %.1f source evaluations per pixel, %d unconverged pixels." % (
                          b.get("particles", 0), b.get("seconds", 0), os.cpu_count() or 0, b.get("evaluations_per_pixel", 0),
                          b.get("unconverged_pixels", 0)), ""]
    lines += raymarch_section(bench_dir)
    lines += animated_section(bench_dir)
    lines += editor_section(bench_dir)
    lines += kept_sections(docs_dir, lines)
    open(os.path.join(docs_dir, "PERFORMANCE.md"), "w").write("\n".join(lines))


def sections(lines):
    """The page's `## ` sections as (heading, lines), in order."""
    out = []
    for line in lines:
        if line.startswith("## "):
            out.append((line, []))
        if out:
            out[-1][1].append(line)
    return out


def kept_sections(docs_dir, generated):
    """The existing page's sections that this run did not generate, unchanged."""
    path = os.path.join(docs_dir, "PERFORMANCE.md")
    if not os.path.exists(path):
        return []
    made = {heading for heading, _ in sections(generated)}
    kept = []
    for heading, body in sections(open(path).read().split("\n")):
        if heading not in made:
            kept += body
    return kept


SWEEPS_HEADING = "## Settings sweeps per content scene"
SWEEP_SKIP = ("cumulus_1280", "aircraft_1280", "scaling", "raymarch")


def sweep_runs(bench_dir):
    runs = {}
    for path in sorted(glob.glob(os.path.join(bench_dir, "*", "bench.json"))):
        name = os.path.basename(os.path.dirname(path))
        if name not in SWEEP_SKIP and not name.startswith("tiers_"):
            runs[name] = json.load(open(path))
    return runs


# Errors within 2% of each other (1.03% against 1.05%) count as equal in the sweeps' summary: a
# slower row does not reach the front by a difference no image shows.
TIE = 0.02


def beats(s, r):
    return s is not r and s["frame_ms"] < r["frame_ms"] and s["rel_rmse"] <= r["rel_rmse"] * (1 + TIE)


def family_place(run, family):
    """Where a mode's rows sit against the scene's front (ties as TIE says): its rows on the front,
    else its own best trade and the fastest row of another mode that beats it."""
    rows = [r for r in run["results"] if r["rel_rmse"] is not None]
    mine = [r for r in rows if r["setting"].split()[0] == family]
    if not mine:
        return "–"
    on = sorted((r for r in mine if not any(beats(s, r) for s in rows)), key=lambda r: r["frame_ms"])
    if on:
        return "on the front: " + ", ".join("`%s` (%.1f ms, %s)" % (r["setting"], r["frame_ms"], pct(r["rel_rmse"])) for r in on)
    # The mode's own best trade: its lowest error among its rows that no row of its own beats.
    best = min((r for r in mine if not any(beats(s, r) for s in mine)), key=lambda r: (r["rel_rmse"], r["frame_ms"]))
    b = min((s for s in rows if beats(s, best)), key=lambda s: s["frame_ms"])
    return "off: its best `%s` (%.1f ms, %s), beaten by `%s` (%.1f ms, %s)" % (
        best["setting"], best["frame_ms"], pct(best["rel_rmse"]), b["setting"], b["frame_ms"], pct(b["rel_rmse"]))


def sweeps_section(bench_dir, docs_dir=None):
    """`sandbox bench` per content scene: the table, the chart, the front; then where the sheets and
    raymarch modes sit on each scene's front."""
    runs = sweep_runs(bench_dir)
    if not runs:
        return []
    models = sorted({run.get("scattering", "the scene's") for run in runs.values()})
    lines = [SWEEPS_HEADING, "",
             "`scripts/bench-sweeps` (measured %s): `sandbox bench` on every content scene with media, %s scattering for the frames and "
             "the reference alike. The sweeps rank each setting's own error; the multiple model's Monte Carlo reference would "
             "add its noise to every row (the multiple model's sweeps are in \"Multiple scattering: sweeps against the "
             "multiple judge\"). Rows "
             "without a quality are the exact tier's; a scene whose table holds fewer rows swept the subset scripts/bench-sweeps "
             "gives it (its exact rows take seconds a frame). The table below says where the sheets and raymarch modes sit on each "
             "scene's front, counting errors within %d%% of each other as equal (so a slower row does not reach the front by "
             "a difference no image shows); the ● in the scenes' tables is the strict front." % (
                 max(run["date"][:10] for run in runs.values()), " and ".join(models), round(100 * TIE)), "",
             "| scene | sheets | raymarch |", "|---|---|---|"]
    for name, run in runs.items():
        lines.append("| %s | %s | %s |" % (name, family_place(run, "sheets"), family_place(run, "raymarch")))
    lines.append("")
    return lines + scene_blocks(runs, bench_dir, docs_dir, "", lambda run: "%s scattering, reference %.1f s" % (
        run.get("scattering", "single"), run["reference_seconds"]))


def scene_blocks(runs, bench_dir, docs_dir, chart_prefix, reference_text):
    """Per scene: a heading (its frame, and `reference_text(run)`), its chart copied into
    DOCS_DIR/perf as CHART_PREFIX + name, its table and its front."""
    lines = []
    perf_dir = os.path.join(docs_dir, "perf") if docs_dir else None
    for name, run in runs.items():
        src = os.path.join(bench_dir, name, "bench.png")
        chart = perf_dir is not None and os.path.exists(src)
        if chart:
            os.makedirs(perf_dir, exist_ok=True)
            shutil.copy(src, os.path.join(perf_dir, chart_prefix + name + ".png"))
        lines += ["### %s (t = %g s, %d×%d, %d particles, %s)" % (
            os.path.basename(run["scene"]), run["time"], run["width"], run["height"], run["particles"], reference_text(run)), ""]
        if chart:
            lines += ["![time against error](perf/%s%s.png)" % (chart_prefix, name), ""]
        lines += [table(run), "", pareto_advice(run), ""]
    return lines


MULTIPLE_HEADING = "## Multiple scattering: sweeps against the multiple judge"


def multiple_section(bench_dir, docs_dir):
    """scripts/bench-multiple's runs: per scene the judge's paths and noise, the table, the chart
    and the front, each row's error against the Monte Carlo reference of the multiple model."""
    runs = {name: run for name, run in sweep_runs(bench_dir).items() if run.get("scattering") == "multiple"}
    if not runs:
        return []
    lines = [MULTIPLE_HEADING, "",
             "`scripts/bench-multiple` (measured %s): `sandbox bench --scattering multiple` on the content scenes whose judge "
             "takes seconds, the frames and the reference both in the multiple model. The reference is Monte Carlo: its noise "
             "(the RMS of its per-pixel standard error over its mean luminance, stated per scene) is in every row's error in "
             "quadrature, so rows within it of each other are as good as the judge can tell. `scattering_voxels` and "
             "`scattering_sweeps` are the model's own settings (the diffusion grid's resolution and relaxation sweeps per "
             "frame); `billboards` stays the single-scattering yardstick." % max(run["date"][:10] for run in runs.values()), ""]
    return lines + scene_blocks(runs, bench_dir, docs_dir, "multiple_", lambda run: "reference %.1f s: %d paths per pixel, noise %s" % (
        run["reference_seconds"], run.get("reference_spp", 0), pct(run.get("reference_noise_rel_rmse"))))


EDITOR_HEADING = "## Editor viewport"


def editor_section(bench_dir):
    """The editor's frame rate from scripts/bench-editor's editor_fps.txt (also written as JSON)."""
    path = os.path.join(bench_dir, "editor_fps.txt")
    if not os.path.exists(path):
        return []
    rows = {}
    for line in open(path):
        # "smoke 8 640x360 frames 20: 29.0 ms per frame (34.49 fps) at 640x360"
        parts = line.split()
        if len(parts) < 8 or parts[3] != "frames":
            continue
        rows.setdefault(parts[0], {"time": float(parts[1])})[parts[2]] = float(parts[5])
    json.dump(rows, open(os.path.join(bench_dir, "editor_fps.json"), "w"), indent=2)
    sizes = ["1280x720", "640x360"]
    lines = [EDITOR_HEADING, "",
             "`scripts/bench-editor`: `sandbox edit SCENE --viewport-size WxH --script` under xvfb-run, fast tier (the "
             "editor's default), mean wall time of 20 editor frames after 3 warm-up frames. An editor frame is its "
             "whole loop: the viewport render, the ImGui panels and the swap. The goal is 10 fps at the preview size (640×360).", "",
             "| scene | t (s) | " + " | ".join("%s ms (fps)" % s for s in sizes) + " |",
             "|---|---|" + "---|" * len(sizes)]
    for scene, row in rows.items():
        cells = ["%.0f (%.1f)" % (row[s], 1000.0 / row[s]) if s in row else "–" for s in sizes]
        lines.append("| %s | %g | %s |" % (scene, row["time"], " | ".join(cells)))
    return lines + [""]


RAYMARCH_HEADING = "## Raymarch against particles and blocks"


def raymarch_section(bench_dir):
    """scripts/bench-raymarch's runs: frame, splat floor and error per mode, per cumulus-sized scene."""
    folder = os.path.join(bench_dir, "raymarch")
    if not os.path.isdir(folder):
        return []
    labels = [("raymarch", "raymarch"), ("raymarch_half", "raymarch, media_scale 0.5"), ("fast", "particles, fast tier"),
              ("blocks", "blocks")]
    lines = [RAYMARCH_HEADING, "",
             "`scripts/bench-raymarch`: each mode at 1280×720 in one run, median of 20 GPU-synchronised frames, the splat "
             "floor measured in the same process, rel-RMSE against `sandbox reference` of the same frame. Raymarch's cost "
             "follows the media target's pixels × the voxels each ray crosses, not the particle count, and the medium is "
             "smooth at the voxel scale, so halving `media_scale` costs it little error. Its error grows where the grid is "
             "coarse against small particles: tests/scenes/media/raymarch_test.cpp states every content scene's (campfire's "
             "small flames are the worst).", "",
             "| scene | mode | frame ms | splat floor ms | frame / floor | rel-RMSE |", "|---|---|---|---|---|---|"]
    for scene in ("cumulus", "cumulus_aircraft"):
        for key, label in labels:
            stats_path = os.path.join(folder, "%s_%s.json" % (scene, key))
            error_path = os.path.join(folder, "%s_%s_error.json" % (scene, key))
            if not os.path.exists(stats_path) or not os.path.exists(error_path):
                continue
            s, e = json.load(open(stats_path)), json.load(open(error_path))
            lines.append("| %s | %s | %.0f | %.1f | %.1f | %.4f |" % (scene, label, s["frame_ms"], s["splat_floor_ms"],
                                                                  s["frame_ms"] / s["splat_floor_ms"], e["rel_rmse"]))
    return lines + [""]


ANIMATED_HEADING = "## An animated frame"


def animated_section(bench_dir):
    """scripts/bench-animated's runs: the fast tier's frame with the medium moving, per model, and still."""
    folder = os.path.join(bench_dir, "animated")
    if not os.path.isdir(folder):
        return []
    lines = [ANIMATED_HEADING, "",
             "`scripts/bench-animated`: the content scenes whose medium moves, fast tier at 1280×720, `sandbox render --stats "
             "--animate` (the simulation steps 1/60 s before each frame), in turn with the single model and the still frame, 3 "
             "rounds, medians. A moving medium pays its simulation step and upload, and in the multiple model its grid solved "
             "again on the CPU (`media_scattering_solve_ms`, inside the frame; a still medium keeps the first frame's), from "
             "scratch by default and, with `scattering_warm_sweeps=16`, from the last frame's answer (docs/design-notes.md has "
             "its error). The benchmarks above time still frames.", "",
             "| scene | multiple, moving (ms) | of it, the grid's solve (ms) | warm-started, moving (ms) | its solve (ms) | "
             "single, moving (ms) | multiple, still (ms) | moving multiple / moving single (warm) |",
             "|---|---:|---:|---:|---:|---:|---:|---:|"]
    for scene in ("smoke", "steam", "explosion", "campfire", "jet"):
        runs = {}
        for name in ("multiple", "warm", "single", "still"):
            paths = sorted(glob.glob(os.path.join(folder, "%s_%s_*.json" % (scene, name))))
            if paths:
                runs[name] = [json.load(open(p)) for p in paths]
        if len(runs) < 4:
            continue
        med = lambda name, key: statistics.median(r.get(key, 0.0) for r in runs[name])
        lines.append("| %s | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.2f× (%.2f×) |" % (
            scene, med("multiple", "frame_ms"), med("multiple", "media_scattering_solve_ms"), med("warm", "frame_ms"),
            med("warm", "media_scattering_solve_ms"), med("single", "frame_ms"), med("still", "frame_ms"),
            med("multiple", "frame_ms") / med("single", "frame_ms"), med("warm", "frame_ms") / med("single", "frame_ms")))
    return lines + [""]


def replace_section(docs_dir, heading, section):
    """Rewrites one section of an existing PERFORMANCE.md in place (appended if it is new)."""
    path = os.path.join(docs_dir, "PERFORMANCE.md")
    text = open(path).read().split("\n")
    start = end = len(text)
    if heading in text:
        start = text.index(heading)
        end = next((i for i in range(start + 1, len(text)) if text[i].startswith("## ")), len(text))
    open(path, "w").write("\n".join(text[:start] + section + text[end:]))


if __name__ == "__main__":
    if sys.argv[1] == "--tiers":  # the tiers' runs alone (tiers_<scene>, cumulus_1280, aircraft_1280)
        runs = {os.path.basename(os.path.dirname(p)): json.load(open(p)) for p in sorted(glob.glob(os.path.join(sys.argv[2], "*", "bench.json")))}
        replace_section(sys.argv[3], "## Quality tiers", tiers_section(runs, sys.argv[2]))
    elif sys.argv[1] == "--editor":
        replace_section(sys.argv[3], EDITOR_HEADING, editor_section(sys.argv[2]))
    elif sys.argv[1] == "--raymarch":
        replace_section(sys.argv[3], RAYMARCH_HEADING, raymarch_section(sys.argv[2]))
    elif sys.argv[1] == "--animated":
        replace_section(sys.argv[3], ANIMATED_HEADING, animated_section(sys.argv[2]))
    elif sys.argv[1] == "--multiple":
        replace_section(sys.argv[3], MULTIPLE_HEADING, multiple_section(sys.argv[2], sys.argv[3]))
    elif sys.argv[1] == "--sweeps":
        replace_section(sys.argv[3], SWEEPS_HEADING, sweeps_section(sys.argv[2], sys.argv[3]))
    else:
        main(sys.argv[1], sys.argv[2])
