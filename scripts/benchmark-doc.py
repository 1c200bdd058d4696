#!/usr/bin/env python3
"""Writes docs/benchmark.md from the reports scripts/benchmark.sh made: REPORTS/<scene>/<light>/
report.json and report.html. A table per scene, the machine and GL renderer named, the best of
each light said in one line, and each report's two Pareto charts cut out of its page as
stand-alone SVG files under OUT/benchmark/."""
import argparse
import json
import os
import re


def standalone_charts(page):
    """The page's inline SVG charts, each with the page's style sheet and a white ground so that
    it reads on its own (an <img> of an SVG sees no style of the page around it)."""
    style = re.search(r"<style>(.*?)</style>", page, re.S).group(1)
    charts = []
    for svg in re.findall(r'<svg viewBox="0 0 (\d+) (\d+)" class="chart"[^>]*>(.*?)</svg>', page, re.S):
        width, height, body = svg
        charts.append('<svg xmlns="http://www.w3.org/2000/svg" width="%s" height="%s" viewBox="0 0 %s %s">'
                      '<style>text{font-family:DejaVu Sans,sans-serif}%s</style><rect width="100%%" height="100%%" fill="#fff"/>%s</svg>\n'
                      % (width, height, width, height, style, body))
    return charts


def percent(value, decimals=3):
    return "%.*f" % (decimals, value)


def count(value):
    """A count as the report's page writes it: 812, 12.4 k, 4.19 M; n/a where it was not taken."""
    if value is None:
        return "n/a"
    for unit, scale in (("G", 1e9), ("M", 1e6), ("k", 1e3)):
        if value >= scale:
            return "%.*f %s" % (2 if value < 10 * scale else 1, value / scale, unit)
    return "%d" % value


def front(row):
    marks = [name for name, key in (("misclassified", "pareto_front"), ("area", "area_pareto_front")) if row[key]]
    return ", ".join(marks)


def scene_table(reports):
    """One row a technique and light; with reports merged from several machines, a renderer
    column says whose each row is (their times are compared only with their own machine's)."""
    machines = {(row["renderer"], row["machine"]) for _, report in reports for row in report["rows"]}
    several = len(machines) > 1
    lines = ["| light | technique |" + (" renderer |" if several else "")
             + " misclassified % | false shadow % | false light % | area MAE % | DSSIM | frame ms (p10–p90) | shadow pass ms | lit pass ms"
             + " | shadow taps | shadow-pass samples | texels cleared | map | on the front |",
             "| --- | --- |" + (" --- |" if several else "") + " ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | --- |"]
    for light, report in reports:
        for row in report["rows"]:
            hard, frame = row["hard_reference"], row["frame_wall"]
            counts = row["counts"]
            lines.append("| %s | %s |%s %s | %s | %s | %s ± %s | %.5f | %.1f (%.1f–%.1f) | %.1f | %.1f | %s | %s | %s | %s | %s |" % (
                light, row["label"], (" %s, %s |" % (row["renderer"], row["machine"].split(", ")[0])) if several else "", percent(hard["misclassified_pct"]),
                percent(hard["false_shadow_pct"]), percent(hard["false_light_pct"]),
                percent(row["area_reference"]["mae_pct"]), percent(row["area_mae_noise_pct"]), row["dssim"], frame["median_ms"],
                frame["p10_ms"], frame["p90_ms"], row["shadow_pass_wall"]["median_ms"], row["lit_pass_wall"]["median_ms"],
                count(counts["taps"]), count(counts["shadow_pass"]["samples"]), count(counts["cleared_texels"]),
                "%.0f MiB" % (counts["map_bytes"] / 2**20), front(row)))
    return lines


def best_line(light, report):
    rows = report["rows"]
    fastest = min(rows, key=lambda r: r["frame_wall"]["median_ms"])
    hard = min(rows, key=lambda r: r["hard_reference"]["misclassified_pct"])
    area = min(rows, key=lambda r: r["area_reference"]["mae_pct"])
    ssim = min(rows, key=lambda r: r["dssim"])
    return ("- %s light: fastest %s (%.1f ms), fewest misclassified %s (%.3f %%), closest to the area light %s (MAE %.3f %%), "
            "best DSSIM %s (%.5f)." % (light, fastest["label"], fastest["frame_wall"]["median_ms"], hard["label"],
                                       hard["hard_reference"]["misclassified_pct"], area["label"], area["area_reference"]["mae_pct"],
                                       ssim["label"], ssim["dssim"]))


def disagreements(scene, light, report):
    """The rows the report itself left off its fronts as visibly wrong (report.json's visibly_wrong:
    a picture unlike both the hard and the area reference's, which misclassified pixels may miss,
    such as a moire of partial shadow), each with the report's reason."""
    return ["- %s, %s light: %s at %.3f %% misclassified, %s." % (
                scene, light, r["label"], r["hard_reference"]["misclassified_pct"], r["visibly_wrong"])
            for r in report["rows"] if r.get("visibly_wrong")]


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--reports", required=True)
    parser.add_argument("--out", required=True, help="folder for benchmark.md and benchmark/")
    parser.add_argument("--seconds", type=int, required=True, help="the whole run")
    parser.add_argument("--command", required=True, help="the command line, as the page names it")
    parser.add_argument("--scenes", nargs="+", required=True, help="scene folders of REPORTS in their order")
    parser.add_argument("--lights", nargs="+", required=True, help="light folders of each scene in their order")
    args = parser.parse_args()

    pictures = os.path.join(args.out, "benchmark")
    os.makedirs(pictures, exist_ok=True)
    for old in os.listdir(pictures):
        if old.endswith(".svg"):
            os.remove(os.path.join(pictures, old))

    first = None
    sections = []
    disagreeing = []
    for scene in args.scenes:
        reports = []
        for light in args.lights:
            folder = os.path.join(args.reports, scene, light)
            with open(os.path.join(folder, "report.json"), encoding="utf-8") as f:
                report = json.load(f)
            with open(os.path.join(folder, "report.html"), encoding="utf-8") as f:
                charts = standalone_charts(f.read())
            for kind, chart in zip(("misclassified", "area"), charts):
                with open(os.path.join(pictures, "%s-%s-%s.svg" % (scene, light, kind)), "w", encoding="utf-8") as f:
                    f.write(chart)
            reports.append((light, report))
            disagreeing += disagreements(scene, light, report)
            first = first or report
        seconds = sum(r["seconds"] for _, r in reports)
        section = ["## %s" % scene, "",
                   "Scene `%s`, %d light-facing pixels measured under the directional light; %.0f s for its %d reports." % (
                       os.path.basename(reports[0][1]["scene"]), reports[0][1]["rows"][0]["hard_reference"]["pixels"], seconds, len(reports)), ""]
        section += scene_table(reports) + [""]
        section += [best_line(light, report) for light, report in reports] + [""]
        for light, _ in reports:
            section.append("![%s, %s light: misclassified pixels against frame time](benchmark/%s-%s-misclassified.svg)" % (scene, light, scene, light))
            section.append("![%s, %s light: MAE against the area light, against frame time](benchmark/%s-%s-area.svg)" % (scene, light, scene, light))
            section.append("")
        sections += section

    minutes, seconds = divmod(args.seconds, 60)
    page = ["# Benchmark: every shadow technique under every light type", "",
            "Made by `%s` (`shadowlab report` of each technique at its defaults, one report per scene and light type); "
            "regenerate it with that command, not by hand." % args.command, "",
            "- Machine: %s" % first["machine"],
            "- GL renderer: %s" % first["renderer"],
            "- Image %s, %d timed frames per configuration after %d warm-up, the shadow pass redrawn every frame; "
            "times are wall-clock milliseconds around `glFinish` (CPU time on a software rasteriser), medians with p10–p90."
            % (first["size"], first["frames"], first["warmup"]),
            "- Errors against an Embree ray-traced reference of the same pixels: misclassified pixels (|V − V_ref| > 0.5) split "
            "into false shadow and false light against one shadow ray a pixel; MAE against a disk light of radius %g traced with "
            "%d rays a pixel (its noise floor is why no technique reaches 0); DSSIM = 1 − mean SSIM (Wang et al. 2004; 11 × 11 "
            "Gaussian window, σ 1.5, K1 0.01, K2 0.03, on luma) of the frame against the same frame shaded with the hard "
            "reference's visibility." % (first["light_radius"], first["area_samples_per_pixel"]),
            "- DSSIM compares with the hard reference, so a soft shadow (pcss, a wide kernel) scores worse by design there; "
            "how close a shadow comes to the soft one of a disk light is the area MAE.",
            "- **These times are a software rasteriser's.** On llvmpipe a pass costs about what its fragments and bytes cost the "
            "CPU, so bandwidth-heavy passes (a moments blur, a 2048² clear) rank far dearer than on a GPU. The counts beside them "
            "are the same on any GPU: shadow taps (the technique's texture reads per lookup times the fragments that looked up), "
            "the shadow pass's samples passed, the shadow-map texels it cleared, and the storage's memory.",
            "- A row is on the front when no other is both clearly faster and clearly more accurate (see the report's page).",
            "- The whole run took %d min %02d s." % (minutes, seconds), "",
            "## Rows left out as visibly wrong", "",
            "Each report leaves off its fronts, and never recommends, a row whose picture is unlike both the hard and the "
            "area reference's (DSSIM over 0.01 against each): acne, or a moiré of partial shadow that misclassified pixels "
            "miss. The test suite holds every hard-edged filter under that bar on the models of assimp-testmodels "
            "(tests/tst_RealModels.cpp).", ""]
    page += (disagreeing or ["- None."]) + [""]
    with open(os.path.join(args.out, "benchmark.md"), "w", encoding="utf-8") as f:
        f.write("\n".join(page + sections))


if __name__ == "__main__":
    main()
