#!/usr/bin/env python3
"""Checks that the READMEs tell the truth, one promise per check (ctest runs each as a test):

  test-names     every test a README names (`Suite.Name`, `Suite.*`) is a ctest test, and so
                 is every test tests/sanitizers/release_only.txt leaves to the Release build
  flags          every flag in a README's flag table, or in a command it shows, is in that
                 sample's --help; every flag a sample's --help lists is in its README
  links          every relative link and picture resolves, #anchors included, inside the repo;
                 no README cites a file outside the repository; the web gallery renders each
                 sample README's opening whole, code spans literal (web/gallery.py --check)
  golden-update  the one golden-update command the docs show selects the test of every golden
  runnable       every command in a code block marked <!-- runnable --> runs and exits 0
  environment    every environment variable the code reads is in README.md and in --help, and
                 every PBR_ variable the READMEs name is read by the code
  build-sh       ./build.sh -h and --help print the usage, a bad argument is named, and
                 `./build.sh run` takes relative paths from the caller's folder
  code-names     in each sample README's text-to-code table ("| the text | here |"), every code
                 name on our side is an identifier of the files its row links or names
                 (`pbr::FlyCamera` as FlyCamera), every number there a literal of them (on the
                 line of a name its clause gives, if any), and a row whose text names those
                 files lack gives a name of ours

usage: check_docs.py CHECK --source DIR --build DIR
Prints one line per broken promise and exits 1 when there is any.
"""
import argparse
import os
import re
import shlex
import subprocess
import sys
import tempfile
from pathlib import Path

FAILURES = []


def fail(message):
    FAILURES.append(message)
    print("FAIL: " + message)


def readmes(source):
    """Every page of the docs: README.md, each sample's README.md and the pages in docs/."""
    found = [source / "README.md"]
    found += sorted((source / "samples").glob("*/README.md"))
    found += sorted((source / "docs").glob("*.md"))
    return found


def rel(path, source):
    return str(path.relative_to(source))


def ctest_names(build, extra=()):
    out = subprocess.run(["ctest", "--test-dir", str(build), "-N", *extra], capture_output=True,
                         text=True, check=True).stdout
    return [m.group(1).strip() for m in re.finditer(r"Test\s+#\d+: (.+)", out)]


def sample_names(build):
    return sorted(p.name for p in (build / "bin").iterdir()
                  if re.fullmatch(r"\d\d_\w+", p.name) and os.access(p, os.X_OK))


HELP_CACHE = {}


def help_of(build, sample):
    if sample not in HELP_CACHE:
        run = subprocess.run([str(build / "bin" / sample), "--help"], capture_output=True,
                             text=True)
        if run.returncode != 0:
            fail(f"{sample} --help exits {run.returncode}")
        HELP_CACHE[sample] = run.stdout
    return HELP_CACHE[sample]


def help_flags(text, section=None):
    """The flags of --help, all of them or those of one section ("flags of 01_lighting:")."""
    flags, current = set(), None
    for line in text.splitlines():
        if line and not line.startswith(" "):
            current = line
            continue
        m = re.match(r"  (--[\w-]+)", line)
        if m and (section is None or current == section):
            flags.add(m.group(1))
    return flags


def code_spans(text):
    return re.findall(r"`([^`\n]+)`", text)


def code_blocks(text):
    """(marker line before the block, list of lines) for every fenced block."""
    blocks, lines = [], text.splitlines()
    i = 0
    while i < len(lines):
        if lines[i].startswith("```"):
            marker = lines[i - 1].strip() if i > 0 else ""
            body = []
            i += 1
            while i < len(lines) and not lines[i].startswith("```"):
                body.append(lines[i])
                i += 1
            blocks.append((marker, body))
        i += 1
    return blocks


def sample_of_readme(path):
    m = re.search(r"samples/(\d\d_\w+)/README\.md$", str(path))
    return m.group(1) if m else None


# --- checks -------------------------------------------------------------------------------

def check_test_names(source, build):
    names = ctest_names(build)
    cores = {re.sub(r"^[^/]*/", "", re.sub(r"/[^/]*$", "", n)) if "/" in n else n for n in names}
    suites = {c.split(".")[0] for c in cores if "." in c}
    seen = 0
    for readme in readmes(source):
        for span in code_spans(readme.read_text()):
            m = re.fullmatch(r"([A-Z][A-Za-z0-9]*)\.([A-Z][A-Za-z0-9_]*|\*)", span)
            if not m:
                continue
            seen += 1
            suite, test = m.groups()
            if test == "*":
                if suite not in suites:
                    fail(f"{rel(readme, source)} names tests {span}, but no test suite {suite} exists")
            elif span not in cores:
                fail(f"{rel(readme, source)} names the test {span}, which ctest -N does not list")
    if seen == 0:
        fail("no README names any test: the check found nothing to check")
    # a name there that no longer exists would quietly put its test back under the sanitizers
    release_only = source / "tests" / "sanitizers" / "release_only.txt"
    listed = [l.strip() for l in release_only.read_text().splitlines()
              if l.strip() and not l.startswith("#")]
    for name in listed:
        backend = re.search(r"_(osmesa|egl_software|egl)$", name)
        if backend and not any(n.endswith(backend.group(0)) for n in names):
            continue  # a backend this build does not have (OSMesa is gone from Mesa 25.1 on)
        if name not in names:
            fail(f"tests/sanitizers/release_only.txt names {name}, which ctest -N does not list")


def check_flags(source, build):
    samples = sample_names(build)
    if not samples:
        fail("no sample executables in " + str(build / "bin"))
        return
    common = help_flags(help_of(build, samples[0]), "flags every sample takes:")
    for readme in readmes(source):
        text = readme.read_text()
        own = sample_of_readme(readme)
        targets = [own] if own else samples
        # Flag tables: rows whose first cell starts with a flag.
        for row in re.findall(r"^\|\s*`(--[\w-]+)", text, re.M):
            for sample in targets:
                if row not in help_flags(help_of(build, sample)):
                    fail(f"{rel(readme, source)}: the flag table lists {row}, which "
                         f"{sample} --help does not")
        # Commands shown: a sample's name (or path) followed by flags.
        commands = code_spans(text) + [l for _, body in code_blocks(text) for l in body]
        for command in commands:
            m = re.match(r"(?:\S*/)?(\d\d_\w+)\s+(.*)", command.split("#")[0].strip())
            if not m or m.group(1) not in samples:
                continue
            for flag in re.findall(r"(?<![\w-])(--[\w-]+)", m.group(2)):
                if flag not in help_flags(help_of(build, m.group(1))):
                    fail(f"{rel(readme, source)}: `{command.strip()}` uses {flag}, which "
                         f"{m.group(1)} --help does not list")
        # Every flag of the sample's own is explained in its README; every common flag in the
        # top README.
        if own:
            for flag in help_flags(help_of(build, own), f"flags of {own}:"):
                if f"`{flag}" not in text:
                    fail(f"{rel(readme, source)} does not explain {own}'s flag {flag}")
        elif readme == source / "README.md":
            for flag in common:
                if not re.search(r"^\|\s*`" + re.escape(flag) + r"[` ]", text, re.M):
                    fail(f"README.md's flag table lacks the common flag {flag}")


def slug(heading):
    heading = re.sub(r"[`*_]", lambda m: "_" if m.group(0) == "_" else "", heading.strip())
    return re.sub(r"[^\w\- ]", "", heading.lower()).replace(" ", "-")


def anchors(path):
    return {slug(m.group(1)) for m in re.finditer(r"^#+\s+(.*)$", path.read_text(), re.M)}


def check_links(source, build):
    del build
    checked = 0
    for readme in readmes(source):
        text = readme.read_text()
        if "shared/seeds" in text or "../shared" in text:
            fail(f"{rel(readme, source)} cites a file outside the repository (shared/...)")
        for target in re.findall(r"\]\(([^)\s]+)\)", text):
            if re.match(r"[a-z]+:", target):
                continue  # a URL
            checked += 1
            path_part, _, anchor = target.partition("#")
            path = (readme.parent / path_part).resolve() if path_part else readme
            if source.resolve() not in path.parents and path != source.resolve():
                fail(f"{rel(readme, source)}: link {target} leaves the repository")
                continue
            if not path.exists():
                fail(f"{rel(readme, source)}: link {target} points at nothing")
                continue
            if anchor and path.suffix == ".md" and anchor not in anchors(path):
                fail(f"{rel(readme, source)}: link {target}: no heading #{anchor} in {path.name}")
    if checked == 0:
        fail("no relative link found: the check found nothing to check")
    gallery = subprocess.run([sys.executable, str(source / "web" / "gallery.py"), "--check",
                              "--source", str(source)], capture_output=True, text=True)
    for line in gallery.stdout.splitlines():
        fail(line.removeprefix("FAIL: "))
    if gallery.returncode != 0 and not gallery.stdout.strip():
        fail(f"web/gallery.py --check exits {gallery.returncode}: {gallery.stderr.strip()}")


def check_golden_update(source, build):
    lines = [l.split("#")[0].strip() for readme in readmes(source)
             for _, body in code_blocks(readme.read_text()) for l in body
             if "PBR_UPDATE_GOLDENS=1" in l]
    if len(lines) != 1:
        fail(f"the docs should show one golden-update command (PBR_UPDATE_GOLDENS=1 ...) in a "
             f"code block; they show {len(lines)}")
        return
    words = shlex.split(lines[0])
    if words[:2] != ["PBR_UPDATE_GOLDENS=1", "ctest"]:
        fail(f"the golden-update command is not 'PBR_UPDATE_GOLDENS=1 ctest ...': {lines[0]}")
        return
    args, i = [], 2
    while i < len(words):  # the preset names the build folder; the check names it directly
        if words[i] == "--preset":
            i += 2
            continue
        args.append(words[i])
        i += 1
    selected = ctest_names(build, args)
    goldens = sorted(p.stem for p in (source / "tests" / "golden").glob("*.png"))
    if not goldens:
        fail("no golden pictures found")
    for golden in goldens:
        if not any(re.search(r"^[A-Za-z]+/GoldenImage\.MatchesGolden/" + re.escape(golden) +
                             r"_[a-z_]+$", name) for name in selected):
            fail(f"the golden-update command ({lines[0]}) runs no test that rewrites "
                 f"tests/golden/{golden}.png")
    web_goldens = sorted(p.stem for p in (source / "tests" / "golden" / "web").glob("*.png"))
    for golden in web_goldens:  # the browser's (tests/web), named <golden>_webgl
        if not any(re.search(r"WebGolden\.MatchesGolden/" + re.escape(golden) + r"_webgl$", name)
                   for name in selected):
            fail(f"the golden-update command ({lines[0]}) runs no test that rewrites "
                 f"tests/golden/web/{golden}.png")
    if "PBR_UPDATE_GOLDENS" not in (source / "tests" / "support" / "golden.cpp").read_text():
        fail("tests/support/golden.cpp does not read PBR_UPDATE_GOLDENS")


def scratch_dir(source, build):
    """A folder that looks like the repository root to a README command, writes landing in it."""
    scratch = Path(tempfile.mkdtemp(prefix="docs-", dir=build / "test-output"))
    (scratch / "build").mkdir()
    (scratch / "build" / "release").symlink_to(build)
    (scratch / "scripts").symlink_to(source / "scripts")
    return scratch


def check_runnable(source, build):
    env = dict(os.environ)
    for variable in ("DISPLAY", "WAYLAND_DISPLAY"):
        env.pop(variable, None)
    env["PBR_CACHE_DIR"] = str(build / "test-output" / "ibl-cache")
    ran = 0
    for readme in readmes(source):
        for marker, body in code_blocks(readme.read_text()):
            if marker != "<!-- runnable -->":
                continue
            for line in body:
                command = re.sub(r"\s+#.*$", "", line).strip()
                if not command:
                    continue
                ran += 1
                scratch = scratch_dir(source, build)
                run = subprocess.run(["bash", "-c", command], cwd=scratch, env=env,
                                     capture_output=True, text=True, timeout=600)
                problems = [l for l in run.stderr.splitlines()
                            if l.startswith("error") or "GL error" in l]
                if run.returncode != 0 or problems:
                    last = (problems or run.stderr.splitlines() or ["(no output)"])[-1]
                    fail(f"{rel(readme, source)}: `{command}` exits {run.returncode}: {last}")
                else:
                    print(f"ok: {rel(readme, source)}: {command}")
    if ran == 0:
        fail("no README command is marked <!-- runnable -->: the check found nothing to run")


def variables_read(source, folders):
    names = set()
    for folder in folders:
        for path in (source / folder).rglob("*"):
            if path.suffix not in (".cpp", ".h", ".py", ".sh"):
                continue
            text = path.read_text(errors="replace")
            names |= set(re.findall(r"(?:getenv|variable|fromEnvOr|environ(?:\.get)?)\s*[(\[]\s*\"([A-Z_]+)\"",
                                    text))
            if path.suffix == ".sh":  # a shell script's ${NAME:-default}
                names |= set(re.findall(r"\$\{([A-Z_]+):-", text))
    return names


def cmake_options(source):
    """The build's own settings (option() and CACHE variables), which READMEs name as -D flags,
    and the switches common/'s headers define."""
    names = set()
    for path in [source / "CMakeLists.txt", *source.glob("*/**/CMakeLists.txt"), *source.glob("cmake/*.cmake")]:
        if "build" in path.relative_to(source).parts[:1]:
            continue
        text = path.read_text(errors="replace")
        names |= set(re.findall(r"option\(\s*(PBR_[A-Z_]+)", text))
        names |= set(re.findall(r"set\(\s*(PBR_[A-Z_]+)[^)]*\bCACHE\b", text))
    for path in (source / "common").rglob("*.h"):  # the code's own switches (PBR_WEBGL)
        names |= set(re.findall(r"#define (PBR_[A-Z_]+)", path.read_text(errors="replace")))
    return names


def check_environment(source, build):
    samples = sample_names(build)
    usage = help_of(build, samples[0]) if samples else ""
    top = (source / "README.md").read_text()
    read_by_samples = variables_read(source, ["common"])
    if not read_by_samples:
        fail("found no environment variable read in common/: the check is broken")
    for name in sorted(read_by_samples):
        if name not in usage:
            fail(f"common/ reads ${name}, which --help does not list")
        if name not in top:
            fail(f"common/ reads ${name}, which README.md does not mention")
    read_anywhere = variables_read(source, ["common", "tests", "scripts", "tools", "resources"])
    options = cmake_options(source)
    if "PBR_SANITIZE" not in options:
        fail("found no PBR_ option in the CMakeLists: the check is broken")
    for readme in readmes(source):
        for name in sorted(set(re.findall(r"\b(PBR_[A-Z_]+)\b", readme.read_text()))):
            if name not in read_anywhere and name not in options:
                fail(f"{rel(readme, source)} names ${name}, which no code reads and no CMake option is")
    for name in sorted(set(re.findall(r"\b(PBR_[A-Z_]+)\b", usage))):
        if name not in read_by_samples:
            fail(f"--help names ${name}, which the samples do not read")


def check_build_sh(source, build):
    script = source / "build.sh"
    for flag in ("-h", "--help"):
        run = subprocess.run([str(script), flag], capture_output=True, text=True)
        if run.returncode != 0 or not run.stdout.startswith("usage: ./build.sh run"):
            fail(f"./build.sh {flag} exits {run.returncode} with: {run.stdout[:60]!r}")
    run = subprocess.run([str(script), "--bogus"], capture_output=True, text=True)
    last = (run.stderr.strip().splitlines() or [""])[-1]
    if run.returncode != 2 or "'--bogus'" not in last:
        fail(f"./build.sh --bogus exits {run.returncode}, last line {last!r}")
    if build.resolve() != (source / "build" / "release").resolve():
        print(f"skipped: ./build.sh run builds {source / 'build/release'}, not this build ({build})")
        return
    caller = Path(tempfile.mkdtemp(prefix="build-sh-", dir=build / "test-output"))
    env = dict(os.environ)
    env.pop("DISPLAY", None)
    env.pop("WAYLAND_DISPLAY", None)
    run = subprocess.run([str(script), "run", "--headless", "--size", "32x18", "--output",
                          "relative.png"], cwd=caller, env=env, capture_output=True, text=True,
                         timeout=600)
    if run.returncode != 0 or not (caller / "relative.png").exists():
        fail(f"./build.sh run --output relative.png in {caller} exits {run.returncode} and "
             f"leaves {sorted(p.name for p in caller.iterdir())}: "
             f"{(run.stderr.strip().splitlines() or [''])[-1]}")


CODE_SUFFIXES = (".cpp", ".h", ".glsl", ".frag", ".vert", ".py", ".cmake", ".txt")


def text_to_code_rows(text):
    """The rows of a sample README's text-to-code tables (header "| the text | <ours> |"), as
    (line number, the text's cell, our cell)."""
    rows, lines = [], text.splitlines()
    for i, line in enumerate(lines):
        if not re.match(r"\|\s*the text\s*\|", line, re.I):
            continue
        for j in range(i + 2, len(lines)):
            if not lines[j].startswith("|"):
                break
            cells = [c.strip() for c in re.split(r"(?<!\\)\|", lines[j].strip())[1:-1]]
            if len(cells) >= 2:
                rows.append((j + 1, cells[0], cells[1]))
    return rows


def named_file(name, readme, linked, source):
    """The file a bare `name.glsl` in a table means: one the table links with that name, else
    one in the sample's own folders, else the only one in the repository with that name."""
    for path in linked:
        if path.as_posix().endswith("/" + name):
            return path
    sample = readme.parent.name
    for folder in (readme.parent, source / "shaders" / sample):
        if (folder / name).is_file():
            return folder / name
    found = [p for folder in ("common", "shaders", "samples", "tests", "tools", "resources")
             for p in (source / folder).rglob(name.split("/")[-1])
             if p.as_posix().endswith("/" + name)]
    return found[0] if len(found) == 1 else None


def literal_in(number, text):
    """Whether `number` (as the README writes it) is a numeric literal of `text`: 256 matches
    256, 256u, 256.0f; 0.5 matches 0.5 and 0.50."""
    body = re.escape(number) + (r"0*" if "." in number else r"(?:\.0*)?")
    return re.search(r"(?<![\w.])" + body + r"(?![\d.])", text) is not None


def code_links(cell, readme):
    """The code files a table cell links (not READMEs, not URLs), resolved."""
    return {(readme.parent / t).resolve() for t in re.findall(r"\]\(([^)\s#]+)[^)]*\)", cell)
            if not re.match(r"[a-z]+:", t) and t.endswith(CODE_SUFFIXES)}


def read_all(files):
    return "\n".join(p.read_text(errors="replace") for p in sorted(files) if p.is_file())


def has_name(name, code):
    return re.search(r"\b" + re.escape(name) + r"\b", code) is not None


def check_code_names(source, build):
    """Our side of a row is read clause by clause (split at ';'): a clause's names and numbers
    are looked up in the files that clause links or names, or else in those of the whole row; a
    number in a clause that names code must stand on a line with one of those names (256 on the
    line of kPrefilterSamples), or anywhere in the files when the clause names none."""
    del build
    checked = 0
    for readme in sorted((source / "samples").glob("*/README.md")):
        where = rel(readme, source)
        rows = text_to_code_rows(readme.read_text())
        table_links = set().union(*(code_links(ours, readme) for _, _, ours in rows))
        for line, theirs, ours in rows:
            label = theirs.replace("`", "")
            row = f'{where}:{line}, row "{label[:40]}{"..." if len(label) > 40 else ""}"'
            clauses = []  # (files, names, numbers) of each clause
            for clause in re.split(r";(?=(?:[^`]*`[^`]*`)*[^`]*$)", ours):
                files = code_links(clause, readme)
                prose = re.sub(r"\[[^\]]*\]\([^)]*\)", " ", clause)  # link texts: paths, "02"
                prose = re.sub(r"(?<=\d),(?=\d{3}\b)", "", prose)  # 1,024 is 1024
                names, numbers = [], []
                for span in code_spans(prose):
                    if span.startswith("-"):
                        continue  # a flag: the flags check's
                    if re.fullmatch(r"[\w./-]+\.(?:cpp|h|glsl|frag|vert)", span):
                        path = named_file(span, readme, table_links, source)
                        if path is None:
                            fail(f"{row} names the file {span}, which is not one file of the repo")
                        else:
                            files.add(path.resolve())
                    else:
                        names.append(span)
                for number in re.findall(r"(?<![\w.^])(\d+(?:\.\d+)?)(?![\w.])",
                                         re.sub(r"`[^`\n]+`", " ", prose)):
                    if not re.fullmatch(r"0\d", number):  # 04, 05: a sample, not a number
                        numbers.append(number)
                clauses.append((files, names, numbers))
            row_files = set().union(*(files for files, _, _ in clauses))
            for files, names, numbers in clauses:
                files = files or row_files
                if (names or numbers) and not files:
                    fail(f"{row}: our side names {', '.join(names + numbers)} but links no file")
                    continue
                code = read_all(files)
                shown = ", ".join(sorted(str(p.relative_to(source)) for p in files))
                idents = []
                for span in names:
                    checked += 1
                    m = re.fullmatch(r"(?:[A-Za-z_]\w*::)*([A-Za-z_]\w*)(?:\(\))?", span)
                    if m:
                        idents.append(m.group(1))
                    if (m and not has_name(m.group(1), code)) or (not m and span not in code):
                        fail(f"{row}: `{span}` is not in {shown}")
                lines = [l for l in code.splitlines() if any(has_name(i, l) for i in idents)]
                for number in numbers:
                    checked += 1
                    if idents and not any(literal_in(number, l) for l in lines):
                        fail(f"{row}: the number {number} is on no line of {shown} that names "
                             f"{' or '.join(idents)}")
                    elif not idents and not literal_in(number, code):
                        fail(f"{row}: the number {number} is not a literal of {shown}")
            # A name of the text's that our files lack must be mapped to a name of ours.
            code = read_all(row_files)
            absent = [s.rstrip("()") for s in code_spans(theirs)
                      if re.fullmatch(r"[A-Za-z_]\w*(?:\(\))?", s)
                      and not has_name(s.rstrip("()"), code)]
            if absent and not any(names for _, names, _ in clauses):
                shown = ", ".join(sorted(str(p.relative_to(source)) for p in row_files))
                fail(f"{row}: the text's {', '.join(absent)} "
                     f"{'is' if len(absent) == 1 else 'are'} not in {shown or 'any file'}, "
                     f"and the row names no code of ours for it")
    if checked == 0:
        fail("no text-to-code table names any code: the check found nothing to check")


CHECKS = {
    "test-names": check_test_names,
    "flags": check_flags,
    "links": check_links,
    "golden-update": check_golden_update,
    "runnable": check_runnable,
    "environment": check_environment,
    "build-sh": check_build_sh,
    "code-names": check_code_names,
}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("check", choices=sorted(CHECKS))
    parser.add_argument("--source", type=Path, required=True)
    parser.add_argument("--build", type=Path, required=True)
    args = parser.parse_args()
    (args.build / "test-output").mkdir(parents=True, exist_ok=True)
    CHECKS[args.check](args.source.resolve(), args.build.resolve())
    if FAILURES:
        print(f"{len(FAILURES)} broken promise(s)")
        return 1
    print("ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
