#!/usr/bin/python3
"""Puts a web sample's files (its shaders and assets) into its page: a script, where the shell
(web/shell.html) has its <!-- pbr:files --> marker, that writes them into the page's own file
system before main() runs, the bytes in base64.

    web/embed.py --page build/web/05_ibl_specular.html SOURCE@/DESTINATION ...

A SOURCE folder is taken whole. The files travel as text beside the program, not inside the
wasm (browsers refuse to compile a module of more than 8 MB at once, and the page compiles its
module before main runs, so that a capture never races the start-up), and after emscripten
linked the page (which would otherwise parse and minify megabytes of base64). The page is
rewritten whole, or removed when its files cannot be put in. Standard library only.
"""
import argparse
import base64
import json
import pathlib
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from whole_file import write_whole  # noqa: E402


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
    parser.add_argument("--page", required=True)
    parser.add_argument("entries", nargs="+", help="SOURCE@/DESTINATION")
    args = parser.parse_args()

    lines = ["<script>",
             "// web/embed.py: this page's files, written into its file system before main(); the",
             "// script then leaves the page (its megabytes of text are not the page's content)",
             "(function (script) {",
             'Module["preRun"].push(function () {',
             "  function put(path, text) {",
             "    var binary = atob(text), bytes = new Uint8Array(binary.length);",
             "    for (var i = 0; i < binary.length; ++i) bytes[i] = binary.charCodeAt(i);",
             '    Module.FS.mkdirTree(path.substring(0, path.lastIndexOf("/")));',
             "    Module.FS.writeFile(path, bytes);",
             "  }"]
    for entry in args.entries:
        source, _, destination = entry.partition("@")
        for path, target in files_of(source, destination):
            data = base64.b64encode(path.read_bytes()).decode("ascii")
            lines.append(f"  put({json.dumps(target)}, \"{data}\");")
    lines += ["  script.remove();", "});", "})(document.currentScript);", "</script>"]

    out = pathlib.Path(args.page)
    page = out.read_text(encoding="utf-8")
    marker = "<!-- pbr:files -->"
    if page.count(marker) != 1:
        raise SystemExit(f"embed.py: {out}: no single {marker} marker (already packed, or not "
                         "made from web/shell.html)")
    page = page.replace(marker, "\n".join(lines))
    write_whole(out, page)

if __name__ == "__main__":
    try:
        main()
    except BaseException:
        # a page without its files would fail at its first read: no page instead
        page = [a for a in sys.argv if a.endswith(".html")]
        for path in page:
            pathlib.Path(path).unlink(missing_ok=True)
        raise
