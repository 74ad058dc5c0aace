#!/usr/bin/python3
"""Runs every sample's --benchmark headless and prints a markdown table.

    scripts/bench.py [--build build/release] [--size 1280x720] [--msaa 4] [--frames 30]
    scripts/bench.py --web [--runs 5]

--web instead opens every page of the browser build (build/web, ./build.sh web) as a user does,
each --runs times in a fresh headless Chromium (software WebGL 2), and gives each page's weight
(the page and the bundles it loads) and how long after opening its first frame was drawn (real
time: the page's own mark, scripts/first_frame.js), the median and the range, and when the
frame's commands had all been given (the rest is the GL's drawing).

Each sample draws one warm-up frame, then the measured frames; the table gives the median and
95th percentile frame time, the precompute time and the start-up time (App created -> first
frame), and the GL renderer. Samples with IBL maps (those taking --no-cache) run three times in a
cache folder of the script's own: once to fill the cache, once with --no-cache (its precompute
time: every map computed) and once more with the cache warm (its start-up time and frame times).
Frame time depends on what is in view: each sample runs at its default camera. Standard library
only.
"""
import argparse
import json
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile


def main() -> int:
    root = pathlib.Path(__file__).resolve().parent.parent
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=str(root / "build" / "release"))
    parser.add_argument("--size", default="1280x720")
    parser.add_argument("--msaa", default="4")
    parser.add_argument("--frames", default="30")
    parser.add_argument("--backend", default=None, help="osmesa or egl (default: automatic)")
    parser.add_argument("--web", action="store_true", help="time the pages of build/web instead")
    parser.add_argument("--runs", type=int, default=5, help="with --web: openings of each page")
    args = parser.parse_args()
    if args.web:
        return bench_web(root, args.runs)

    bin_dir = pathlib.Path(args.build) / "bin"
    samples = sorted(p for p in bin_dir.glob("*") if re.fullmatch(r"\d\d_\w+", p.name))
    if not samples:
        print(f"bench.py: no samples in {bin_dir}; build first (./build.sh test or cmake --build --preset default)",
              file=sys.stderr)
        return 1

    cache = tempfile.TemporaryDirectory(prefix="pbr-bench-cache-")
    environment = dict(os.environ, PBR_CACHE_DIR=cache.name)

    def bench(sample, extra, frames=args.frames):
        command = [str(sample), "--headless", "--benchmark", "--size", args.size, "--msaa", args.msaa,
                   "--frames", frames] + extra
        if args.backend:
            command += ["--backend", args.backend]
        # in the scratch folder: 06 writes its .ktx files into the working directory
        run = subprocess.run(command, capture_output=True, text=True, env=environment, cwd=cache.name)
        lines = [line for line in run.stdout.splitlines() if line.startswith("{")]
        if run.returncode != 0 or not lines:
            raise RuntimeError(f"{sample.name} failed: {run.stderr.strip()}")
        return json.loads(lines[-1])

    rows = []
    for sample in samples:
        print(f"bench.py: {sample.name} ...", file=sys.stderr)
        try:
            usage = subprocess.run([str(sample), "--help"], capture_output=True, text=True).stdout
            if "--no-cache" in usage:
                bench(sample, [], frames="1")  # fills the cache
                cold = bench(sample, ["--no-cache"], frames="1")
                row = bench(sample, [])
                row["precompute_s"] = cold["precompute_s"]
            else:
                row = bench(sample, [])
        except RuntimeError as error:
            print(f"bench.py: {error}", file=sys.stderr)
            return 1
        rows.append(row)

    print(f"| sample | median ms | p95 ms | precompute s (cache off) | start-up s (cache warm) | size | MSAA | backend | renderer |")
    print(f"| --- | ---: | ---: | ---: | ---: | --- | ---: | --- | --- |")
    for r in rows:
        print(f"| {r['sample']} | {r['median_ms']:.1f} | {r['p95_ms']:.1f} | {r['precompute_s']:.2f} "
              f"| {r['startup_s']:.2f} | {r['width']}x{r['height']} | {r['msaa']} | {r['backend']} | {r['renderer']} |")
    return 0


def page_weight(page):
    """The page's bytes with the bundles it always loads (web/embed.py), in MB, and the bundles:
    ["assets/materials.js", ""] always, ["assets/materials.js", "--textured"] with that flag."""
    text = page.read_text(encoding="utf-8", errors="replace")
    bundles = sorted(set(re.findall(r'\["(assets/[^"]+\.js)", "([^"]*)"\]', text)))
    # and the program (<script src="assets/samples.js">, always loaded)
    bundles += [(src, "") for src in sorted(set(re.findall(r'<script src="(assets/[^"]+\.js)"', text)))]
    size = lambda bundle: (page.parent / bundle).stat().st_size
    always = page.stat().st_size + sum(size(b) for b, flag in bundles if not flag)
    with_all = page.stat().st_size + sum(size(b) for b, _ in bundles)
    return always / 1e6, with_all / 1e6, bundles


def bench_web(root, runs):
    web = root / "build" / "web"
    pages = sorted(p for p in web.glob("*.html") if re.fullmatch(r"\d\d_\w+\.html", p.name))
    chromium = shutil.which("chromium-headless-shell") or shutil.which("chromium")
    if not pages or not chromium or not shutil.which("node"):
        print("bench.py: --web needs build/web (./build.sh web), node and Chromium", file=sys.stderr)
        return 1
    print("| page | weight MB | with every bundle MB | bundles | first frame drawn s (median) "
          "| range s | its commands given s |")
    print("| --- | ---: | ---: | --- | ---: | --- | ---: |")
    for page in pages:
        print(f"bench.py: {page.name} ...", file=sys.stderr)
        times, submitted = [], []
        for _ in range(runs):
            run = subprocess.run(["node", str(root / "scripts" / "first_frame.js"), chromium,
                                  page.resolve().as_uri()], capture_output=True, text=True)
            if run.returncode != 0:
                print(f"bench.py: {page.name}: {run.stderr.strip()}", file=sys.stderr)
                return 1
            result = json.loads(run.stdout)
            times.append(result["first_frame_ms"] / 1000)
            submitted.append(result["submitted_ms"] / 1000)
        times.sort()
        submitted.sort()
        weight, with_all, bundles = page_weight(page)
        names = ", ".join(b + (f" (with {flag})" if flag else "") for b, flag in bundles)
        print(f"| {page.stem} | {weight:.1f} | {with_all:.1f} | {names or '-'} | "
              f"{times[len(times) // 2]:.2f} | {times[0]:.2f}-{times[-1]:.2f} | "
              f"{submitted[len(submitted) // 2]:.2f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
