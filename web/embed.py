#!/usr/bin/python3
"""Puts a web sample's files (its shaders and assets) into its page, or into a bundle that
several pages share, as base64 text the page makes files of its own file system from before
main() runs. A file's bytes are decoded when the program first reads them (a page that shows one
material set of five decodes one), files with the same bytes are carried once, a PNG's image
data is deflated again by zlib (the same pixels in 31 % less: png_redeflated), and other large
files travel deflated, inflated by the browser before main() (the baked IBL maps).

    web/embed.py --page build/web/05_ibl_specular.html --shell web/shell.html
                 --program 05_ibl_specular --script assets/samples.js
                 [--bundle assets/materials.js[@FLAG]] SOURCE@/DESTINATION ...
    web/embed.py --write-bundle build/web/assets/materials.js SOURCE@/DESTINATION ...

--page writes a sample's page: the shell (web/shell.html) with, where it has its
<!-- pbr:files --> marker, a script with the files, the loader and the sample's name (argv[0],
which web/samples_main.cpp runs), and, at {{{ SCRIPT }}}, the program the pages
share (--script, the wasm inside, loaded with <script src>; one that cannot be loaded is the
page's one error line). --bundle names a bundle (a path relative to the page) the page loads
before main(), always, or only when its command line holds FLAG (05 reads the material sets
only with --textured). --write-bundle writes such a bundle: a script of its own, loaded with
<script src>, so that the pages open from file:// too and the gallery carries the material
sets once, not in every page that shows them.

A SOURCE folder is taken whole. The files travel as text beside the program, not inside the
wasm (browsers refuse to compile a module of more than 8 MB at once, and the page compiles its
module before main runs, so that a capture never races the start-up), and after emscripten
linked the page (which would otherwise parse and minify megabytes of base64). The output is
written whole, or removed when its files cannot be put in. Standard library only.
"""
import argparse
import base64
import html
import json
import pathlib
import struct
import sys
import zlib

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from whole_file import write_whole  # noqa: E402

# The page's side: Module.pbrFiles(data, files) makes each file of the page's file system: an
# empty file of the right size whose contents (MEMFS keeps them in node.contents) are decoded at
# their first use, then kept as a plain value. Bundles call it when they have loaded.
LOADER = """
Module["pbrFiles"] = function (data, files) {
  var FS = Module.FS;
  function decode(text) {
    // the browser's own decoder where it has one (Chromium 140 on): atob and the loop below
    // took 0.1 s of 09's start-up in a CPU profile
    if (Uint8Array.fromBase64) return Uint8Array.fromBase64(text);
    var binary = atob(text), bytes = new Uint8Array(binary.length);
    for (var i = 0; i < binary.length; ++i) bytes[i] = binary.charCodeAt(i);
    return bytes;
  }
  files.forEach(function (file) {
    var path = file[0], text = data[file[1]];
    FS.mkdirTree(path.substring(0, path.lastIndexOf("/")));
    if (file[2]) {  // deflated: inflated by the browser before main() runs
      Module.addRunDependency(path);
      new Response(new Blob([decode(text)]).stream().pipeThrough(new DecompressionStream("deflate")))
        .arrayBuffer().then(function (buffer) {
          FS.writeFile(path, new Uint8Array(buffer));
          Module.removeRunDependency(path);
        }, function () { Module["pbrFailed"]("error: " + path + ": its bytes in the page are damaged"); });
      return;
    }
    FS.writeFile(path, new Uint8Array(0));
    var node = FS.lookupPath(path).node;
    var padding = text.slice(-2) === "==" ? 2 : text.slice(-1) === "=" ? 1 : 0;
    node.usedBytes = text.length / 4 * 3 - padding;
    function keep(value) {
      Object.defineProperty(node, "contents", {value: value, writable: true, configurable: true,
                                               enumerable: true});
    }
    Object.defineProperty(node, "contents", {configurable: true, enumerable: true, set: keep,
      get: function () { var bytes = decode(text); keep(bytes); return bytes; }});
  });
};
"""


def files_of(source, destination):
    source = pathlib.Path(source)
    if source.is_file():
        yield source, destination
        return
    if not source.is_dir():
        raise SystemExit(f"embed.py: {source}: no such file or folder")
    for path in sorted(p for p in source.rglob("*") if p.is_file()):
        yield path, destination.rstrip("/") + "/" + path.relative_to(source).as_posix()


def png_redeflated(content):
    """A PNG's bytes with its image data deflated again by zlib at its default level (6): the
    same rows and filters, so the same pixels, 31 % smaller than what stb_image_write's
    fixed-Huffman deflate makes of the material sets (18.5 MB to 12.8 MB). Level 9 saves 4 %
    more of them in nine times the time (29 s against 3 s, 2026-12-04), on a core the build's
    compiler would use. Anything else (or a PNG that would not shrink) as it is."""
    signature = b"\x89PNG\r\n\x1a\n"
    if not content.startswith(signature):
        return content
    chunks, data, at = [], b"", len(signature)
    while at + 12 <= len(content):
        size, kind = struct.unpack(">I4s", content[at:at + 8])
        body = content[at + 8:at + 8 + size]
        at += 12 + size
        if kind == b"IDAT":
            if data == b"":
                chunks.append(None)  # where the image data goes
            data += body
        else:
            chunks.append((kind, body))
    if at != len(content) or data == b"":
        return content
    try:
        deflated = zlib.compress(zlib.decompress(data), 6)
    except zlib.error:
        return content
    out = [signature]
    for chunk in chunks:
        kind, body = chunk if chunk else (b"IDAT", deflated)
        out.append(struct.pack(">I4s", len(body), kind) + body +
                   struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF))
    smaller = b"".join(out)
    return smaller if len(smaller) < len(content) else content


def data_and_files(entries):
    """The JavaScript lines that fill `data` (each distinct content once) and `files`."""
    lines, seen = ["var data = [], files = [];"], {}
    for entry in entries:
        source, _, destination = entry.partition("@")
        for path, target in files_of(source, destination):
            content = png_redeflated(path.read_bytes())
            # Other files of 64 KB or more travel deflated where that saves a tenth (the
            # environment cube's 16.8 MB of half floats are 2.3 MB deflated): the browser inflates
            # them before main() runs (DecompressionStream); the rest is decoded at its first read.
            deflated = zlib.compress(content, 9) if len(content) >= 65536 and not content.startswith(b"\x89PNG") else content
            packed = deflated if len(deflated) < 0.9 * len(content) else content
            key = (packed, packed is not content)
            if key not in seen:
                seen[key] = len(seen)
                lines.append(f"data.push(\"{base64.b64encode(packed).decode('ascii')}\");")
            lines.append(f"files.push([{json.dumps(target)}, {seen[key]}, {int(key[1])}]);")
    return lines


def page_script(program, entries, bundles):
    needs = [list(b.partition("@")[::2]) for b in bundles]  # [src, flag or ""]
    return "\n".join([
        "<script>",
        "// web/embed.py: the sample this page runs (argv[0]), its files, made files of its file",
        "// system before main(), each decoded at its first read, and the bundles it loads; the",
        "// script then leaves the page (its megabytes of text are not the page's content)",
        "(function (script) {",
        f'Module["thisProgram"] = {json.dumps(program)};',
        LOADER.strip(),
        *data_and_files(entries),
        f"var bundles = {json.dumps(needs)};",
        'Module["preRun"].push(function () {',
        '  Module["pbrFiles"](data, files);',
        "  bundles.forEach(function (bundle) {",
        "    if (bundle[1] && Module.arguments.indexOf(bundle[1]) < 0) return;",
        '    Module["pbrStatus"]("loading " + bundle[0]);',
        "    Module.addRunDependency(bundle[0]);",
        '    var element = document.createElement("script");',
        "    element.src = bundle[0];",
        "    element.onload = function () { element.remove(); Module.removeRunDependency(bundle[0]); };",
        "    element.onerror = function () {",
        '      Module["pbrFailed"]("error: " + bundle[0] + ": cannot be loaded (it belongs beside the page)");',
        "    };",
        "    document.body.appendChild(element);",
        "  });",
        "  script.remove();",
        "});",
        "})(document.currentScript);",
        "</script>"])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    target = parser.add_mutually_exclusive_group(required=True)
    target.add_argument("--page")
    target.add_argument("--write-bundle")
    parser.add_argument("--shell", help="the page's template (web/shell.html), with --page")
    parser.add_argument("--program", help="the sample the page runs, with --page")
    parser.add_argument("--script", help="the program's script, relative to the page, with --page")
    parser.add_argument("--bundle", action="append", default=[], help="SRC[@FLAG], with --page")
    parser.add_argument("entries", nargs="*", help="SOURCE@/DESTINATION")
    args = parser.parse_intermixed_args()

    if args.write_bundle:
        text = "\n".join(["// web/embed.py: files shared by several pages (Module.pbrFiles: the",
                          "// page's loader makes them files of its file system)",
                          "(function () {", *data_and_files(args.entries),
                          'Module["pbrFiles"](data, files);', "})();", ""])
        out = pathlib.Path(args.write_bundle)
        out.parent.mkdir(parents=True, exist_ok=True)
        write_whole(out, text)
        return
    if not (args.shell and args.program and args.script):
        raise SystemExit("embed.py: --page needs --shell, --program and --script")
    out = pathlib.Path(args.page)
    page = pathlib.Path(args.shell).read_text(encoding="utf-8")
    for marker in ("<!-- pbr:files -->", "{{{ SCRIPT }}}"):
        if page.count(marker) != 1:
            raise SystemExit(f"embed.py: {args.shell}: no single {marker} marker")
    src = html.escape(args.script)
    failed = html.escape(json.dumps(f"error: {args.script}: cannot be loaded (it belongs beside "
                                    "the page)"))
    # the script marker first: the files' names are the user's, the shell's markers are not
    page = page.replace("{{{ SCRIPT }}}",
                        f'<script src="{src}" onerror="Module.pbrFailed({failed})"></script>')
    page = page.replace("<!-- pbr:files -->", page_script(args.program, args.entries, args.bundle))
    write_whole(out, page)


if __name__ == "__main__":
    try:
        main()
    except BaseException:
        # a page without its files would fail at its first read: no page instead
        for i, arg in enumerate(sys.argv):
            if arg in ("--page", "--write-bundle") and i + 1 < len(sys.argv):
                pathlib.Path(sys.argv[i + 1]).unlink(missing_ok=True)
        raise
