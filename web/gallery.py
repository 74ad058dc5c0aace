#!/usr/bin/python3
"""Writes the web build's gallery page: build/web/index.html, a link to every sample's page with
its picture and the opening of its README (what the sample teaches, and from which text).

    web/gallery.py --source . --out build/web 01_lighting 02_lighting_textured ...
    web/gallery.py --source . --check     # every sample's opening renders whole; exit 1 if not

Standard library only; run by the web build (web/CMakeLists.txt), and with --check by the docs
tests (tests/docs/check_docs.py links).
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

LIST_ITEM = re.compile(r"(\d+[.)]|[-*+])\s+")


def blocks(text):
    """The markdown's blocks in order, each (kind, body): "heading", "paragraph" (its lines
    joined), "caption" (a paragraph in italics), "picture", "code" (lines), "list" (items, each
    joined; body[0] is "ol" or "ul"), "table" or "html"."""
    lines, found, i = text.splitlines(), [], 0
    while i < len(lines):
        line = lines[i]
        if not line.strip():
            i += 1
        elif line.startswith("```"):
            end = next((j for j in range(i + 1, len(lines)) if lines[j].startswith("```")),
                       len(lines))
            found.append(("code", lines[i + 1:end]))
            i = end + 1
        elif line.startswith("    "):
            end = i
            while end < len(lines) and (lines[end].startswith("    ") or not lines[end].strip()):
                end += 1
            while not lines[end - 1].strip():
                end -= 1
            found.append(("code", [l[4:] for l in lines[i:end]]))
            i = end
        elif line.startswith("#"):
            found.append(("heading", line.lstrip("#").strip()))
            i += 1
        elif LIST_ITEM.match(line):
            kind = "ol" if line[0].isdigit() else "ul"
            items = []
            while i < len(lines) and lines[i].strip():
                m = LIST_ITEM.match(lines[i])
                if m:
                    items.append(lines[i][m.end():].strip())
                else:
                    items[-1] += " " + lines[i].strip()
                i += 1
            found.append(("list", [kind] + items))
        else:
            end = i
            while end < len(lines) and lines[end].strip() and not lines[end].startswith("```"):
                end += 1
            joined = " ".join(l.strip() for l in lines[i:end])
            if joined.startswith("|"):
                kind = "table"
            elif joined.startswith("!["):
                kind = "picture"
            elif joined.startswith("<"):
                kind = "html"
            elif re.fullmatch(r"\*[^*].*[^*]\*", joined):
                kind = "caption"
            else:
                kind = "paragraph"
            found.append((kind, joined))
            i = end
    return found


def finished(text):
    """Whether a piece of prose ends a sentence (not on a colon, a comma or mid-phrase)."""
    return re.search(r"[.!?][)\"'*`]*$", text.rstrip()) is not None


def first_sentence(text):
    """The first sentence of a paragraph, and what follows it ("" when it is one sentence).
    Full stops inside code spans and after abbreviations do not end a sentence."""
    masked = re.sub(r"`[^`]*`", lambda m: "x" * len(m.group(0)), text)
    for m in re.finditer(r"[.!?][)\"']*\s+(?=[A-Z0-9(\"'*`])", masked):
        if re.search(r"\b(e\.g|i\.e|cf|vs|ch|no|fig)$", masked[:m.start()], re.I):
            continue
        return text[:m.start() + len(m.group(0).rstrip())], text[m.end():]
    return text, ""


def opening(readme):
    """What the gallery shows of a sample: its README's first paragraph of prose, and, when that
    stops on a colon or mid-phrase, what completes the thought: the formula or list it
    introduces and the sentence that carries on after a formula (starting in lower case)."""
    found = blocks(readme.read_text(encoding="utf-8"))
    start = next((i for i, (kind, _) in enumerate(found) if kind == "paragraph"), None)
    if start is None:
        return []
    taken = [found[start]]
    for kind, body in found[start + 1:]:
        last_kind, last = taken[-1]
        open_ended = last_kind == "paragraph" and not finished(last)
        if kind in ("code", "list") and open_ended:
            taken.append((kind, body))
        elif kind == "paragraph" and body[:1].islower() and (open_ended or last_kind == "code"):
            sentence, rest = first_sentence(body)
            taken.append((kind, sentence))
            if rest:
                break
        else:
            break
    return taken


def markdown_inline(text):
    """A line of markdown as HTML: code spans first (kept literal: `a * b * c` stays so), then,
    on the rest, links, bold and italics; everything else HTML-escaped."""
    kept = []

    def keep(fragment):
        kept.append(fragment)
        return f"\0{len(kept) - 1}\0"

    def code(m):
        inner = m.group(2)
        if len(inner) > 2 and inner.startswith(" ") and inner.endswith(" "):
            inner = inner[1:-1]
        return keep("<code>" + html.escape(inner) + "</code>")

    def link(m):
        label, target = m.group(1), m.group(2)
        if not re.match(r"https?://", target):
            return label  # a file of the repository: not on the web page
        return f'<a href="{target.replace(chr(34), "&quot;")}">{label}</a>'

    out = re.sub(r"(`+)(.+?)(?<!`)\1(?!`)", code, text.replace("\0", ""))
    out = re.sub(r"<(https?://[^\s<>]+)>",
                 lambda m: keep(f'<a href="{html.escape(m.group(1))}">'
                                f"{html.escape(m.group(1))}</a>"), out)
    out = html.escape(out, quote=False)
    out = re.sub(r"\[([^\]]+)\]\(([^)\s]+)\)", link, out)
    # a delimiter touches the text it wraps: "a * b" is no emphasis
    out = re.sub(r"\*\*(?=\S)(.+?)(?<=\S)\*\*", r"<b>\1</b>", out)
    out = re.sub(r"\*(?=[^\s*])(.+?)(?<=[^\s*])\*", r"<i>\1</i>", out)
    return re.sub(r"\0(\d+)\0", lambda m: kept[int(m.group(1))], out)


def to_html(taken):
    """The opening's blocks as HTML."""
    out = []
    for kind, body in taken:
        if kind == "paragraph":
            out.append(f"<p>{markdown_inline(body)}</p>")
        elif kind == "code":
            out.append("<pre><code>" + html.escape("\n".join(body)) + "</code></pre>")
        elif kind == "list":
            items = "".join(f"<li>{markdown_inline(item)}</li>" for item in body[1:])
            out.append(f"<{body[0]}>{items}</{body[0]}>")
    return "".join(out)


INLINE_CASES = [  # (markdown, HTML)
    ("the constant `vec3(0.03) * albedo * ao` of 01", "the constant "
     "<code>vec3(0.03) * albedo * ao</code> of 01"),
    ("*3D Graphics*, **PBR**, `a<b` & a < b", "<i>3D Graphics</i>, <b>PBR</b>, "
     "<code>a&lt;b</code> &amp; a &lt; b"),
    ("x * y * z, ``a ` b``", "x * y * z, <code>a ` b</code>"),
    ("[`brdf.glsl`](../brdf.glsl), [site](https://e.org/?a&b), <https://e.org/x>",
     '<code>brdf.glsl</code>, <a href="https://e.org/?a&amp;b">site</a>, '
     '<a href="https://e.org/x">https://e.org/x</a>'),
]


def check(source):
    """What the gallery would get wrong: the inline cases, and every sample's opening (found,
    whole, and not ending mid-sentence)."""
    problems = []
    for markdown, expected in INLINE_CASES:
        if markdown_inline(markdown) != expected:
            problems.append(f"web/gallery.py renders {markdown!r} as "
                            f"{markdown_inline(markdown)!r}, not {expected!r}")
    readmes = sorted((source / "samples").glob("[0-9][0-9]_*/README.md"))
    if not readmes:
        problems.append(f"no samples/*/README.md under {source}")
    for readme in readmes:
        taken = opening(readme)
        where = readme.relative_to(source)
        if not taken:
            problems.append(f"{where}: no paragraph of prose for the gallery")
            continue
        kind, last = taken[-1]
        if kind == "paragraph" and not finished(last):
            problems.append(f"{where}: the gallery's summary ends mid-sentence: ...{last[-40:]}")
        if kind == "list" and not finished(last[-1]):
            problems.append(f"{where}: the gallery's summary ends mid-list: ...{last[-1][-40:]}")
    return problems


def picture(source, out, golden):
    """The golden picture beside the page (the web one where there is one)."""
    for candidate in (source / "tests/golden/web" / f"{golden}.png",
                      source / "tests/golden" / f"{golden}.png"):
        if candidate.exists():
            (out / "img").mkdir(exist_ok=True)
            shutil.copyfile(candidate, out / "img" / f"{golden}.png")
            return f"img/{golden}.png"
    return None


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--source", required=True)
    parser.add_argument("--out")
    parser.add_argument("--check", action="store_true",
                        help="check the rendering and every sample's opening; write nothing")
    parser.add_argument("samples", nargs="*")
    args = parser.parse_args()
    source = pathlib.Path(args.source)
    if args.check:
        problems = check(source)
        for problem in problems:
            print("FAIL: " + problem)
        return 1 if problems else 0
    if not args.out or not args.samples:
        parser.error("--out and the samples are needed, unless --check")
    out = pathlib.Path(args.out)

    entries = []
    for sample in args.samples:
        number, title = sample.split("_", 1)
        links = [f'<a href="{sample}.html">{number} {html.escape(title)}</a>']
        for variant, query, what, _ in VARIANTS:
            if variant == sample:
                links.append(f'<a href="{sample}.html?{query}">{html.escape(query)}</a> ({what})')
        image = picture(source, out, sample)
        thumb = f'<a href="{sample}.html"><img src="{image}" alt="{sample}"></a>' if image else ""
        text = to_html(opening(source / "samples" / sample / "README.md"))
        entries.append(f'<section>{thumb}<div><h2>{" &middot; ".join(links)}</h2>'
                       f"{text}</div></section>")

    page = f"""<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>PBR samples in the browser</title>
<style>
body {{ font: 15px/1.45 sans-serif; margin: 1.5em auto; max-width: 70em; padding: 0 1em;
       color: #222; }}
section {{ display: flex; gap: 1.2em; margin: 1.2em 0; align-items: flex-start; }}
section img {{ width: 320px; border: 1px solid #999; }}
section p {{ margin: 0 0 .5em; }}
h2 {{ font-size: 1.1em; margin: 0 0 .3em; }}
code {{ background: #eee; padding: 0 .2em; }}
pre {{ background: #eee; padding: .3em .6em; margin: 0 0 .5em; overflow-x: auto; }}
pre code {{ padding: 0; }}
</style></head><body>
<h1>PBR samples in the browser (WebGL 2)</h1>
<p>The same C++ and GLSL as the native samples, built with emscripten; each page opens from
the disk as well as from a server. The glTF samples draw the models the native loader read,
packed by the build, and the IBL maps of the project's environment come baked by the build; the
material sets are one file beside the pages (<code>assets/materials.js</code>), loaded by the
pages that show them, and the pages of each layer of the helper library share one program. A page takes the sample's flags in its
address: <code>05_ibl_specular.html?--textured&amp;--camera=0,0,8</code>
(<code>?--help</code> lists them). Click a picture to look around: WASD moves, the mouse looks,
scroll zooms, Esc ends the run; in the glTF viewers (07, 08) a drag orbits the model instead.
Each page's header says which.</p>
{chr(10).join(entries)}
</body></html>
"""
    write_whole(out / "index.html", page)
    return 0


if __name__ == "__main__":
    sys.exit(main())
