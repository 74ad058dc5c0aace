#!/usr/bin/env python3
"""Chooses the tests the sanitizer build runs: tests/sanitizers/release_only.txt.

The sanitizers find what is wrong in the lines of ours that run. This script builds the asan
preset with gcov's line counts added and every test registered (-DPBR_SANITIZER_SUBSET=OFF),
runs each test on its own (a test's sample runs write their counts into the test's own folder,
GCOV_PREFIX), and keeps, for each test, the lines of the project's code it ran (common/, samples/,
resources/; not tests/, which the sanitizer build does not instrument). Then it chooses:

  1. every test whose point is a variety of conditions that no fuzz target reaches (bad flags
     beside a GL context, full disks, values past what the sums carry), where the sanitizers find
     what a line count does not show; the variety of a reader's input (damaged and corrupt files,
     every model of a corpus) is the fuzz label's: each reader of ours runs under the same
     sanitizers there, on every kept input and new ones (tests/fuzz);
  2. then, greedily, the test that runs the most lines not yet run per second of its time, until
     the chosen tests run every line the whole suite runs, but for the tests named in
     LEFT_TO_RELEASE (chosen by hand, each with its reason);

and writes the others, sorted, to release_only.txt (with --write): the Release build runs every
test, the sanitizer build leaves those to it. Needs the Release build's baked assets
(./build.sh test, or cmake --build --preset default, first). Takes about 15 minutes on 2 cores.

usage: tests/sanitizers/measure_coverage.py [--build DIR] [--jobs N] [--write]
                                            [--reuse | --only REGEX]
"""
import argparse
import concurrent.futures
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

SOURCE = Path(__file__).resolve().parents[2]
LIST = SOURCE / "tests" / "sanitizers" / "release_only.txt"
# The tests of step 1, by suite: the variety of conditions, the sanitizers' best use. (Until
# 2026-12-08 the readers' suites were kept whole here too, Damage, ModelFile, HdrFile,
# MaterialDir and IblCache, about half of the sanitizer tests' time; the fuzz label now runs those
# readers under the same sanitizers on their corpora, Debian's glTF test models included.)
INPUT_VARIETY = re.compile(r"^([A-Za-z]+/)?(Output|Cli|HdrRange)\.")
OWN_CODE = ("common/", "samples/", "resources/")
# Left to the Release build by hand, for the 10 minutes, whatever lines they alone run (the
# sanitizers leave those lines unchecked): six panel tests whose own lines are a few of the panel's
# UI code each (exposure in stops, the moved camera's command line, copy, moving and folding, the
# scrolled field of view, Tab; about 40 test-seconds under the sanitizers), and the white furnaces
# of sample 10's layers (about 8 test-seconds there: quadratures of pure arithmetic, so the sheen's
# albedo quadrature, common/math/gltf_extensions.cpp's sheenAlbedoQuadrature, is Release's alone).
LEFT_TO_RELEASE = {
    "Panel.ExposureSlidesInStops",
    "Panel.AMovedCamerasCommandDrawsTheSamePicture",
    "Panel.CopySaysItCopied",
    "Panel.ThePanelMovesAndFolds",
    "Panel.AScrolledFieldOfViewIsOnTheCommandLine",
    "Panel.TabHidesThePanelWithoutTurningTheCamera",
    "GltfExtensions.AWhiteBaseUnderAWhiteSheenNeverReflectsMoreThanArrives",
    "GltfExtensions.AWhiteLayeredSurfaceInAWhiteFurnaceNeverReflectsMoreThanArrives",
    # (2026-12-08) three tests of 10-20 test-seconds each under the sanitizers for a few lines of
    # their own: the two notes of IblCache::load (a stale key, a damaged file: the KTX reader
    # before them is the fuzz label's), 09's moving lights for --point-lights (arithmetic and a
    # push_back a light), 04's `return reportFailure()` (every other sample's runs under them)
    "IblCache.DamagedOrStaleFilesAreRecomputedNotDrawn",
    "Every/LiveFlags.RaisedAndLoweredLiveEachDrawsWhatItsCommandDraws/light09",
    "HdrFile.BrokenFilesAreOneLineErrors",
}


def asan_environment():
    """The asan test preset's environment, as `ctest --preset asan` sets it."""
    presets = json.loads((SOURCE / "CMakePresets.json").read_text())
    preset = next(p for p in presets["testPresets"] if p["name"] == "asan")
    return {k: v.replace("${sourceDir}", str(SOURCE)) for k, v in preset["environment"].items()}


def build(build_dir, jobs):
    flags = "--coverage"
    subprocess.run(["cmake", "--preset", "asan", "-B", str(build_dir),
                    "-DPBR_SANITIZER_SUBSET=OFF", f"-DCMAKE_C_FLAGS={flags}",
                    f"-DCMAKE_CXX_FLAGS={flags}", f"-DCMAKE_EXE_LINKER_FLAGS={flags}",
                    f"-DCMAKE_SHARED_LINKER_FLAGS={flags}"],
                   cwd=SOURCE, check=True, stdout=subprocess.DEVNULL)
    subprocess.run(["cmake", "--build", str(build_dir), "-j", str(jobs)], check=True,
                   stdout=subprocess.DEVNULL)


def registered_tests(build_dir):
    listing = json.loads(subprocess.run(
        ["ctest", "--test-dir", str(build_dir), "--show-only=json-v1"], check=True,
        capture_output=True, text=True).stdout)
    tests = []
    for test in listing["tests"]:
        props = {p["name"]: p["value"] for p in test.get("properties", [])}
        env = dict(kv.split("=", 1) for kv in props.get("ENVIRONMENT", []))
        tests.append({"name": test["name"], "command": test["command"], "env": env,
                      "cwd": props.get("WORKING_DIRECTORY", str(build_dir)),
                      "gtest": any(a.startswith("--gtest_filter=") for a in test["command"])})
    return tests


def lines_run(counts_dir, notes):
    """The lines of our code with a count above zero in the .gcda files under counts_dir."""
    gcdas = sorted(counts_dir.rglob("*.gcda"))
    for gcda in gcdas:  # gcov wants each .gcno beside its .gcda
        note = notes.get(gcda.relative_to(counts_dir).with_suffix(".gcno"))
        if note and not gcda.with_suffix(".gcno").exists():
            gcda.with_suffix(".gcno").symlink_to(note)
    if not gcdas:
        return set()
    out = subprocess.run(["gcov", "--json-format", "--stdout"] + [str(g) for g in gcdas],
                         cwd=counts_dir, capture_output=True, text=True).stdout
    lines = set()
    for doc in (json.loads(l) for l in out.splitlines() if l.startswith("{")):
        for f in doc.get("files", []):
            path = Path(f["file"])
            if not path.is_absolute() or SOURCE not in path.parents:
                continue
            rel = path.relative_to(SOURCE).as_posix()
            if rel.startswith(OWN_CODE):
                lines.update(f"{rel}:{l['line_number']}" for l in f["lines"] if l["count"] > 0)
    return lines


def measure(tests, build_dir, jobs, scratch):
    notes = {p.relative_to("/"): p for p in build_dir.rglob("*.gcno")}
    environment = dict(os.environ, **asan_environment())

    def run(index):
        test = tests[index]
        counts = scratch / f"test{index:04d}"
        env = dict(environment, **test["env"], GCOV_PREFIX=str(counts), GCOV_PREFIX_STRIP="0")
        start = time.monotonic()
        status = subprocess.run(test["command"], cwd=test["cwd"], env=env,
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL).returncode
        test["seconds"] = time.monotonic() - start
        test["lines"] = lines_run(counts, notes)
        shutil.rmtree(counts, ignore_errors=True)
        # gcov's own files can make a test of full disks or exact output fail here; the lines it
        # ran still count
        mark = "" if status == 0 else f" (exit {status} under gcov)"
        print(f"{test['seconds']:6.1f} s {len(test['lines']):5d} lines  {test['name']}{mark}",
              flush=True)

    with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
        list(pool.map(run, range(len(tests))))


def choose(tests):
    everything = set().union(*(t["lines"] for t in tests))
    chosen = [t for t in tests if not t["gtest"] or INPUT_VARIETY.search(t["name"])]
    mandatory = len(chosen)
    left = everything - set().union(*(t["lines"] for t in chosen))
    rest = [t for t in tests if t not in chosen and t["name"] not in LEFT_TO_RELEASE]
    while left and rest:
        best = max(rest, key=lambda t: len(left & t["lines"]) / max(t["seconds"], 0.05))
        if not left & best["lines"]:
            break
        left -= best["lines"]
        chosen.append(best)
        rest.remove(best)
    # then, dearest first, each test the greedy choice took goes back to Release where the lines
    # only it runs among those chosen are run, greedily again, by tests that take less time in all
    # (none where the others chosen run them all: a test taken early for its many lines can have
    # been covered since)
    for t in sorted(chosen[mandatory:], key=lambda t: -t["seconds"]):
        others = [u for u in chosen if u is not t]
        need = t["lines"] - set().union(*(u["lines"] for u in others))
        pool = [u for u in rest if u is not t]
        added = []
        while need:
            best = max(pool, key=lambda u: len(need & u["lines"]) / max(u["seconds"], 0.05),
                       default=None)
            if best is None or not need & best["lines"]:
                break
            need -= best["lines"]
            added.append(best)
            pool.remove(best)
        if not need and sum(u["seconds"] for u in added) < t["seconds"]:
            chosen[:] = others + added
            rest[:] = [u for u in rest if u not in added] + [t]
    return everything, left, chosen, [t for t in tests if t not in chosen]


def write_list(dropped, summary):
    header = [
        "# The tests the sanitizer build leaves to the Release build, one name a line, written",
        "# by tests/sanitizers/measure_coverage.py --write (see there and docs/testing.md): the",
        "# sanitizer build's other tests run every line of ours the whole suite runs, but those",
        "# that only the tests its LEFT_TO_RELEASE names run. Measure again after adding tests",
        "# that run new code (a new test not named here runs under the sanitizers too).",
        f"# {summary}",
    ]
    write_atomically(LIST, "\n".join(header + sorted(t["name"] for t in dropped)) + "\n")


def write_atomically(path, text):
    """Whole or absent: a temporary file beside `path`, renamed after the last byte."""
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.")
    try:
        with os.fdopen(fd, "w") as f:
            f.write(text)
            f.flush()
            os.fsync(f.fileno())
        os.replace(tmp, path)
    except BaseException:
        os.unlink(tmp)
        raise


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", type=Path, default=SOURCE / "build" / "asan-coverage")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    parser.add_argument("--write", action="store_true", help="write release_only.txt")
    which = parser.add_mutually_exclusive_group()
    which.add_argument("--reuse", action="store_true",
                       help="choose again from the last measurement in the build folder")
    which.add_argument("--only", metavar="REGEX",
                       help="measure only the tests whose names match (a test added since), "
                            "the others taken from the last measurement")
    args = parser.parse_args()
    if not args.reuse and not (SOURCE / "build" / "release" / "resources").is_dir():
        sys.exit("measure_coverage.py: error: no build/release/resources: build the Release "
                 "preset first (cmake --build --preset default)")
    build_dir = args.build.resolve()
    saved = build_dir / "coverage.json"  # each test's seconds and lines, for --reuse
    if args.reuse:
        tests = json.loads(saved.read_text())
        for t in tests:
            t["lines"] = set(t["lines"])
    else:
        build(build_dir, args.jobs)
        tests = registered_tests(build_dir)
        if args.only:
            only = re.compile(args.only)
            last = {t["name"]: t for t in json.loads(saved.read_text())}
            for t in last.values():
                t["lines"] = set(t["lines"])
            measured = [t for t in tests if only.search(t["name"])]
            missing = [t["name"] for t in tests if t not in measured and t["name"] not in last]
            if missing:
                sys.exit(f"measure_coverage.py: error: not in the last measurement ({saved}), "
                         f"so --only must name them too: {', '.join(missing)}")
            tests = [t if only.search(t["name"]) else last[t["name"]] for t in tests]
        else:
            measured = tests
        with tempfile.TemporaryDirectory(prefix="counts-", dir=build_dir) as scratch:
            measure(measured, build_dir, args.jobs, Path(scratch))
        write_atomically(saved, json.dumps([dict(t, lines=sorted(t["lines"])) for t in tests]))
    everything, unrun, chosen, dropped = choose(tests)
    total = sum(t["seconds"] for t in tests)
    kept = sum(t["seconds"] for t in chosen)
    summary = (f"measured {time.strftime('%Y-%m-%d')}: {len(chosen)} of {len(tests)} tests, "
               f"{kept:.0f} of {total:.0f} test-seconds, run {len(everything) - len(unrun)} of "
               f"the {len(everything)} lines the suite runs (the others only by LEFT_TO_RELEASE)")
    print(summary)
    for t in sorted(chosen, key=lambda t: -t["seconds"]):
        print(f"  kept {t['seconds']:6.1f} s  {t['name']}")
    if args.write:
        write_list(dropped, summary)
        print(f"wrote {LIST.relative_to(SOURCE)}: {len(dropped)} tests")


if __name__ == "__main__":
    main()
