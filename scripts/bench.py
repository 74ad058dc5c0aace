#!/usr/bin/python3
"""Runs every sample's --benchmark headless and prints a markdown table.

    scripts/bench.py [--build build/release] [--size 1280x720] [--msaa 4] [--frames 30]

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
    args = parser.parse_args()

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


if __name__ == "__main__":
    sys.exit(main())
