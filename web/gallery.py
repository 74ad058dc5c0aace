#!/usr/bin/python3
"""Writes the web build's gallery page: build/web/index.html, a link to every sample's page with
its picture and the first paragraph of its README (what the sample teaches, and from which text).

    web/gallery.py --source . --out build/web 01_lighting 02_lighting_textured ...

Standard library only; run by the web build (web/CMakeLists.txt).
"""
import argparse
import html
import pathlib
import re
import shutil
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from whole_file import write_whole  # noqa: E402

# pages worth a link of their own besides the default: (sample, query, what it shows, golden)
VARIANTS = [
    ("05_ibl_specular", "--textured", "the five material sets", "05_ibl_specular_textured"),
]


def first_paragraph(readme):
    """The README's first paragraph of prose: not a heading, a picture, a caption or a list."""
    paragraphs = readme.read_text(encoding="utf-8").split("\n\n")
    for paragraph in paragraphs:
        text = paragraph.strip()
        if not text or text.startswith(("#", "![", "*", "|", "```", "-", "<")):
            continue
        return " ".join(line.strip() for line in text.splitlines())
    return ""


def markdown_inline(text):
    """The little markdown a first paragraph has: bold, code, links."""
    out = html.escape(text, quote=False)
    out = re.sub(r"\*\*(.+?)\*\*", r"<b>\1</b>", out)
    out = re.sub(r"\*([^*]+)\*", r"<i>\1</i>", out)
    out = re.sub(r"`([^`]+)`", r"<code>\1</code>", out)
    out = re.sub(r"\[([^\]]+)\]\(([^)]+)\)", r"\1", out)  # relative links mean nothing here
    out = re.sub(r"&lt;(https?://[^&\s]+)&gt;", r'<a href="\1">\1</a>', out)
    return out


def picture(source, out, golden):
    """The golden picture beside the page (the web one where there is one)."""
    for candidate in (source / "tests/golden/web" / f"{golden}.png", source / "tests/golden" / f"{golden}.png"):
        if candidate.exists():
            (out / "img").mkdir(exist_ok=True)
            shutil.copyfile(candidate, out / "img" / f"{golden}.png")
            return f"img/{golden}.png"
    return None


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--source", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("samples", nargs="+")
    args = parser.parse_args()
    source, out = pathlib.Path(args.source), pathlib.Path(args.out)

    entries = []
    for sample in args.samples:
        number, title = sample.split("_", 1)
        links = [f'<a href="{sample}.html">{number} {html.escape(title)}</a>']
        for variant, query, what, _ in VARIANTS:
            if variant == sample:
                links.append(f'<a href="{sample}.html?{query}">{html.escape(query)}</a> ({what})')
        image = picture(source, out, sample)
        thumb = f'<a href="{sample}.html"><img src="{image}" alt="{sample}"></a>' if image else ""
        text = markdown_inline(first_paragraph(source / "samples" / sample / "README.md"))
        entries.append(f'<section>{thumb}<div><h2>{" &middot; ".join(links)}</h2>'
                       f"<p>{text}</p></div></section>")

    page = f"""<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>PBR samples in the browser</title>
<style>
body {{ font: 15px/1.45 sans-serif; margin: 1.5em auto; max-width: 70em; padding: 0 1em; color: #222; }}
section {{ display: flex; gap: 1.2em; margin: 1.2em 0; align-items: flex-start; }}
section img {{ width: 320px; border: 1px solid #999; }}
h2 {{ font-size: 1.1em; margin: 0 0 .3em; }}
code {{ background: #eee; padding: 0 .2em; }}
</style></head><body>
<h1>PBR samples in the browser (WebGL 2)</h1>
<p>The same C++ and GLSL as the native samples, built with emscripten; each page is one
self-contained file and computes its IBL maps itself. A page takes the sample's flags in its
address: <code>05_ibl_specular.html?--textured&amp;--camera=0,0,8</code>
(<code>?--help</code> lists them). Click a picture to look around: WASD moves, the mouse looks,
scroll zooms, Esc ends the run.</p>
{chr(10).join(entries)}
</body></html>
"""
    write_whole(out / "index.html", page)


if __name__ == "__main__":
    main()
