#!/usr/bin/python3
"""Writes the script that puts a web sample's files (its shaders and assets) into the page's own
file system before main() runs: a --pre-js of the page, the bytes in base64.

    web/embed.py --out build/web/embed/05_ibl_specular.js SOURCE@/DESTINATION ...

A SOURCE folder is taken whole. The files travel as text beside the program, not inside the
wasm: browsers refuse to compile a module of more than 8 MB at once, and the page compiles its
module before main runs (so that a capture never races the start-up). Standard library only.
"""
import argparse
import base64
import json
import os
import pathlib
import tempfile


def files_of(source, destination):
    source = pathlib.Path(source)
    if source.is_file():
        yield source, destination
        return
    if not source.is_dir():
        raise SystemExit(f"embed.py: {source}: no such file or folder")
    for path in sorted(p for p in source.rglob("*") if p.is_file()):
        yield path, destination.rstrip("/") + "/" + path.relative_to(source).as_posix()


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", required=True)
    parser.add_argument("entries", nargs="+", help="SOURCE@/DESTINATION")
    args = parser.parse_args()

    lines = ["// Written by web/embed.py: this page's files, put into its file system before main().",
             'Module["preRun"] = Module["preRun"] || [];',
             'Module["preRun"].push(function () {',
             "  function put(path, text) {",
             "    var binary = atob(text), bytes = new Uint8Array(binary.length);",
             "    for (var i = 0; i < binary.length; ++i) bytes[i] = binary.charCodeAt(i);",
             '    FS.mkdirTree(path.substring(0, path.lastIndexOf("/")));',
             "    FS.writeFile(path, bytes);",
             "  }"]
    for entry in args.entries:
        source, _, destination = entry.partition("@")
        for path, target in files_of(source, destination):
            data = base64.b64encode(path.read_bytes()).decode("ascii")
            lines.append(f"  put({json.dumps(target)}, \"{data}\");")
    lines.append("});")

    out = pathlib.Path(args.out)
    out.parent.mkdir(parents=True, exist_ok=True)
    fd, temporary = tempfile.mkstemp(prefix="." + out.name + ".", suffix=".tmp", dir=out.parent)
    try:
        with os.fdopen(fd, "w", encoding="ascii") as f:
            f.write("\n".join(lines) + "\n")
            f.flush()
            os.fsync(f.fileno())
        os.chmod(temporary, 0o644)
        os.replace(temporary, out)
    except BaseException:
        os.unlink(temporary)
        raise


if __name__ == "__main__":
    main()
