#!/usr/bin/python3
"""Runs every sample's --benchmark headless and prints a markdown table.

    scripts/bench.py [--build build/release] [--size 1280x720] [--msaa 4] [--frames 30]

Each sample draws one warm-up frame, then the measured frames; the table gives the median and
95th percentile frame time, the precompute time (IBL maps etc., cache off) and the start-up time
(App created -> first frame), and the GL renderer. Frame time depends on what is in view: each
sample runs at its default camera. Standard library only.
"""
import argparse
import json
import pathlib
import re
import subprocess
import sys


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

    rows = []
    for sample in samples:
        command = [str(sample), "--headless", "--benchmark", "--size", args.size, "--msaa", args.msaa,
                   "--frames", args.frames]
        if args.backend:
            command += ["--backend", args.backend]
        print(f"bench.py: {sample.name} ...", file=sys.stderr)
        run = subprocess.run(command, capture_output=True, text=True)
        lines = [line for line in run.stdout.splitlines() if line.startswith("{")]
        if run.returncode != 0 or not lines:
            print(f"bench.py: {sample.name} failed: {run.stderr.strip()}", file=sys.stderr)
            return 1
        rows.append(json.loads(lines[-1]))

    print(f"| sample | median ms | p95 ms | precompute s | start-up s | size | MSAA | backend | renderer |")
    print(f"| --- | ---: | ---: | ---: | ---: | --- | ---: | --- | --- |")
    for r in rows:
        print(f"| {r['sample']} | {r['median_ms']:.1f} | {r['p95_ms']:.1f} | {r['precompute_s']:.2f} "
              f"| {r['startup_s']:.2f} | {r['width']}x{r['height']} | {r['msaa']} | {r['backend']} | {r['renderer']} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
