#!/usr/bin/env python3
"""The speed guard's runner (scripts/bench.sh builds the two binaries and calls this).

Runs a fixed suite of `shadowlab bench --json` cases, a model load and a small report on a BASE
and a HEAD binary, interleaved round by round in alternating order, and prints for every figure
the median of each side, the median HEAD/BASE ratio over the rounds and the p10-p90 of those
ratios. A figure whose median ratio is above 1.05 is flagged. The table is also written to a
Markdown file (docs/performance.md)."""
import argparse
import datetime
import json
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time

# Where the hand-written part of docs/performance.md begins; everything from it on is kept.
KEPT_FROM = "## Why the software profile's optimisations exist"

SLOWER = 1.05
NOISE_MS = 0.05
OUTSIDE = "outside the passes ms"


def cases(mesh, quick):
    frames = ["--frames", "20" if quick else "60", "--warmup", "5"]
    hd = ["--size", "1280x720"]
    suite = [
        ("seed, still", ["bench", "--scene", "seed", "--phase", "steady"] + hd + frames, ["steady"]),
        ("seed, moving light", ["bench", "--scene", "seed", "--phase", "moving-light"] + hd + frames, ["moving-light"]),
        ("seed, moving camera", ["bench", "--scene", "seed", "--phase", "moving-camera"] + hd + frames, ["moving-camera"]),
        ("seed, spot light, moving", ["bench", "--scene", "seed", "--phase", "moving-light", "--set", "light.type=spot"] + hd + frames,
         ["moving-light"]),
        ("seed, point light, moving", ["bench", "--scene", "seed", "--phase", "moving-light", "--set", "light.type=point"] + hd + frames,
         ["moving-light"]),
        ("seed, vsm, moving light", ["bench", "--scene", "seed", "--phase", "moving-light", "--set", "filter.mode=vsm"] + hd + frames,
         ["moving-light"]),
        ("seed, msm, moving light", ["bench", "--scene", "seed", "--phase", "moving-light", "--set", "filter.mode=msm"] + hd + frames,
         ["moving-light"]),
        ("seed, pcss, moving light", ["bench", "--scene", "seed", "--phase", "moving-light", "--set", "filter.mode=pcss"] + hd + frames,
         ["moving-light"]),
        ("city, still", ["bench", "--scene", "city", "--phase", "steady"] + hd + frames, ["steady"]),
        ("city, moving camera", ["bench", "--scene", "city", "--phase", "moving-camera"] + hd + frames, ["moving-camera"]),
        ("city, 50 vehicles moving", ["bench", "--scene", "city+50", "--phase", "moving-casters"] + hd + frames, ["moving-casters"]),
        ("10^6 triangles, still", ["bench", "--scene", mesh, "--phase", "steady", "--size", "960x540"] + frames, ["steady"]),
    ]
    whole = [
        ("10^6 triangles, load", ["settings", "--scene", mesh]),
        ("report, seed 160x90", ["report", "--scene", "seed", "--size", "160x90", "--frames", "5", "--area-samples", "2",
                                 "--sweep", "filters", "--out", None]),
    ]
    return suite, whole


def run_bench(binary, arguments):
    out = subprocess.run([binary] + arguments + ["--json"], check=True, capture_output=True, text=True).stdout
    return json.loads(out)


def phase_figures(report, phases):
    figures = {}
    for phase in report["phases"]:
        if phase["phase"] not in phases:
            continue
        for name in ("frame_wall", "shadow_pass_wall", "lit_pass_wall"):
            stats = phase.get(name, {})
            if stats.get("count", 0) > 0:
                figures[f'{name.replace("_wall", "")} ms'] = stats["median_ms"]
        # The frame less its passes (the CPU's own work: the fit, the reach), per frame on average:
        # from the means, which add up where medians do not, so that a build without bench's own
        # row of it is measured the same way.
        frame, lit, shadow = (phase.get(name, {}) for name in ("frame_wall", "lit_pass_wall", "shadow_pass_wall"))
        if frame.get("count", 0) > 0 and lit.get("count", 0) > 0:
            shadow_ms = shadow.get("mean_ms", 0.0) * shadow.get("count", 0) / frame["count"]
            figures[OUTSIDE] = max(frame["mean_ms"] - lit["mean_ms"] - shadow_ms, 0.0)
    return figures


def run_whole(binary, arguments):
    with tempfile.TemporaryDirectory() as folder:
        arguments = [folder if a is None else a for a in arguments]
        start = time.monotonic()
        subprocess.run([binary] + arguments, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        return {"whole process ms": (time.monotonic() - start) * 1000.0}


def anchor_ratios(binary, quick):
    """HEAD's ratios of the issue's table, each within one process or one round: the lit pass
    with shadows against without, the still city's frame against its lit pass, and the moving-
    light frame against the tutorial's own program (bench --anchor), at the default map, at the
    tutorial's 1024, and from the tutorial's own camera (close to a cube, most pixels looked up)."""
    frames = ["--frames", "20" if quick else "60", "--warmup", "5", "--size", "1280x720"]

    def phases(arguments):
        return {p["phase"]: p for p in run_bench(binary, ["bench"] + arguments + frames)["phases"]}

    def median(phase, figure):
        return phase[figure]["median_ms"]

    def shadow_cost(arguments):
        """The still lit pass with shadows over without, frame by frame in one process (bench
        --without-shadows): the median of the round-by-round ratios."""
        report = run_bench(binary, ["bench", "--phase", "steady", "--without-shadows"] + arguments + frames)
        return report["still_lit_pass_shadows_over_none"]["round_median"]

    seed = phases(["--scene", "seed", "--phase", "moving-light", "--anchor"])
    small = phases(["--scene", "seed", "--phase", "moving-light", "--anchor", "--set", "map.size=1024"])
    close = phases(["--scene", "seed", "--phase", "moving-light", "--anchor", "--set", "camera.position=0,0,3", "--set", "camera.target=0,0,-1"])
    city = phases(["--scene", "city", "--phase", "steady"])
    walk = phases(["--scene", "city", "--phase", "moving-camera"])

    def profiles(arguments, phase):
        """The frame under the hardware profile (the plain path) over the software one (every
        software rasteriser's optimisation on), in one process each, on this machine."""
        plain = phases(arguments + ["--phase", phase, "--set", "rasteriser.profile=hardware"])
        tuned = phases(arguments + ["--phase", phase, "--set", "rasteriser.profile=software"])
        return median(plain[phase], "frame_wall") / median(tuned[phase], "frame_wall")

    def cache(arguments):
        """shadow.cache with casters moving (bench's cache phases, interleaved in one process): the
        shadow pass per frame over shadow.cache=off's, and the frame over the casters standing."""
        report = run_bench(binary, ["bench", "--phase", "moving-casters"] + arguments + frames)["cache"]
        return report["shadow_pass_per_frame_over_uncached"], report["frame_over_standing"]["round_median"]

    city_static = cache(["--scene", "city+50", "--set", "shadow.cache=static"])
    city_pages = cache(["--scene", "city+50", "--set", "shadow.virtual=true", "--set", "shadow.cache=pages"])
    return {
        "city+50, vehicles moving, shadow.cache=static: shadow pass / shadow.cache=off": city_static[0],
        "the same: frame / vehicles standing": city_static[1],
        "city+50, virtual map, shadow.cache=pages: shadow pass / shadow.cache=off": city_pages[0],
        "the same, pages: frame / vehicles standing": city_pages[1],
        "seed, still: lit pass with shadows / without": shadow_cost(["--scene", "seed"]),
        "the same at a 1024 map (the issue's table)": shadow_cost(["--scene", "seed", "--set", "map.size=1024"]),
        "torus, still: lit pass with shadows / without (a third of the frame looked up)": shadow_cost(["--scene", "torus"]),
        "seed, moving light: frame / the tutorial's program": median(seed["moving-light"], "frame_wall") / median(seed["tutorial-program"], "frame_wall"),
        "the same at the tutorial's 1024 map": median(small["moving-light"], "frame_wall") / median(small["tutorial-program"], "frame_wall"),
        "the same from the tutorial's camera, (0, 0, 3) towards -z": median(close["moving-light"], "frame_wall") / median(close["tutorial-program"], "frame_wall"),
        "city, still: frame / lit pass": median(city["steady"], "frame_wall") / median(city["steady"], "lit_pass_wall"),
        "city, moving camera: frame with shadows / without": median(walk["moving-camera"], "frame_wall") / median(walk["moving-camera-no-shadows"], "frame_wall"),
        "the same: ms a frame outside the passes, with shadows": walk["moving-camera"].get("outside_passes_wall", {}).get("median_ms", float("nan")),
        "seed, moving light: frame, hardware profile / software profile": profiles(["--scene", "seed"], "moving-light"),
        "city, moving camera: frame, hardware profile / software profile": profiles(["--scene", "city"], "moving-camera"),
    }


def percentile(values, q):
    ordered = sorted(values)
    index = (len(ordered) - 1) * q
    low, high = int(index), min(int(index) + 1, len(ordered) - 1)
    return ordered[low] + (ordered[high] - ordered[low]) * (index - low)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--base", required=True)
    parser.add_argument("--head", required=True)
    parser.add_argument("--base-name", default="BASE")
    parser.add_argument("--head-name", default="HEAD")
    parser.add_argument("--mesh", required=True)
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--quick", action="store_true", help="fewer frames per case (a rough look, not for notes)")
    parser.add_argument("--out")
    options = parser.parse_args()

    suite, whole = cases(options.mesh, options.quick)
    # samples[case][figure][side] -> list over rounds
    samples = {}
    binaries = {"base": options.base, "head": options.head}
    # HEAD's own ratios against the tutorial's program, where HEAD has bench --anchor.
    help_text = subprocess.run([options.head, "bench", "--help"], capture_output=True, text=True).stdout
    anchored = "--anchor" in help_text
    anchor = {}
    for round_index in range(options.rounds):
        order = ["base", "head"] if round_index % 2 == 0 else ["head", "base"]
        for name, arguments, phases in suite:
            for side in order:
                figures = phase_figures(run_bench(binaries[side], arguments), phases)
                for figure, value in figures.items():
                    samples.setdefault(name, {}).setdefault(figure, {"base": [], "head": []})[side].append(value)
        for name, arguments in whole:
            for side in order:
                for figure, value in run_whole(binaries[side], arguments).items():
                    samples.setdefault(name, {}).setdefault(figure, {"base": [], "head": []})[side].append(value)
        if anchored:
            for figure, value in anchor_ratios(options.head, options.quick).items():
                anchor.setdefault(figure, []).append(value)
        print(f"round {round_index + 1}/{options.rounds} done", file=sys.stderr, flush=True)

    rows = []
    flagged = 0
    for name, figures in samples.items():
        for figure, sides in figures.items():
            base, head = sides["base"], sides["head"]
            if not base or len(base) != len(head):
                continue
            ratios = [h / b for h, b in zip(head, base) if b > 0]
            if not ratios:
                continue
            ratio = statistics.median(ratios)
            # The frame outside its passes is a few hundredths of a millisecond where nothing is
            # refitted, and moves by more than 5 % with the clock alone: flagged only where it
            # also moved by more than NOISE_MS.
            slower = ratio > SLOWER and (figure != OUTSIDE or statistics.median(head) - statistics.median(base) > NOISE_MS)
            flagged += slower
            rows.append((name, figure, statistics.median(base), statistics.median(head), ratio,
                         percentile(ratios, 0.1), percentile(ratios, 0.9), slower))

    machine = f"{platform.machine()}, {os.cpu_count()} cores"
    header = (f"HEAD {options.head_name} against BASE {options.base_name}, {options.rounds} interleaved rounds, "
              f"{datetime.date.today().isoformat()}, {machine}; wall-clock medians (CPU time on a software renderer)")
    lines = [header, "",
             "| case | figure | BASE | HEAD | HEAD/BASE | p10–p90 of the ratio | |",
             "| --- | --- | ---: | ---: | ---: | ---: | --- |"]
    for name, figure, base, head, ratio, p10, p90, slower in rows:
        lines.append(f"| {name} | {figure} | {base:.2f} | {head:.2f} | {ratio:.3f} | {p10:.3f}–{p90:.3f} | {'**slower**' if slower else ''} |")
    lines.append("")
    lines.append(f"{flagged} figure(s) more than {round((SLOWER - 1) * 100)} % slower." if flagged else
                 f"No figure more than {round((SLOWER - 1) * 100)} % slower.")
    if anchor:
        lines += ["", f"HEAD's own ratios, each within one round (median and p10–p90 over {options.rounds}):", "",
                  "| ratio | median | p10–p90 |", "| --- | ---: | ---: |"]
        for figure, values in anchor.items():
            lines.append(f"| {figure} | {statistics.median(values):.3f} | {percentile(values, 0.1):.3f}–{percentile(values, 0.9):.3f} |")
    print("\n".join(lines))
    if options.out:
        # The page's closing sections (why each optimisation exists, with its figures) are
        # written by hand and kept.
        kept = ""
        if os.path.exists(options.out):
            with open(options.out, encoding="utf-8") as old:
                text = old.read()
            at = text.find(KEPT_FROM)
            kept = text[at:] if at >= 0 else ""
        with open(options.out, "w", encoding="utf-8") as out:
            out.write("# Performance: the speed guard's last table\n\n")
            out.write("Made by `scripts/bench.sh` (see its header); run it before merging a change to a pass, and quote it.\n\n")
            out.write("\n".join(lines) + "\n")
            if kept:
                out.write("\n" + kept)
        print(f"wrote {options.out}", file=sys.stderr)
    return 1 if flagged else 0


if __name__ == "__main__":
    sys.exit(main())
