#!/usr/bin/env python3
"""Mutation runs: does the suite catch a real bug? Each mutation below changes one thing in the
code (a wrong exponent, a dropped term, a check removed), the Release build is rebuilt, and the
tests run (every label but docs, which read the READMEs) until the first failure. A mutation the
suite lets through "survives": a gap in the proof. The file is always restored, and the build
rebuilt at the end.

usage: scripts/mutate.py [--list] [--only NAME ...] [--build DIR] [--jobs N]
Prints one line per mutation as it goes, then a table. Takes a few minutes per mutation; run
by hand after a change to the tests, not in CI.
"""
import argparse
import os
import pathlib
import re
import subprocess
import sys
import time

# name, file, the text replaced (it must occur exactly once), its replacement, what it breaks
MUTATIONS = [
    ("fresnel-exponent-4", "shaders/include/brdf.glsl",
     "return F0 + (1.0 - F0) * pow(clamp(1.0 - cosTheta, 0.0, 1.0), 5.0);",
     "return F0 + (1.0 - F0) * pow(clamp(1.0 - cosTheta, 0.0, 1.0), 4.0);",
     "direct-light Fresnel with exponent 4 (the review: survived all 140 tests)"),
    ("normal-matrix-mat3", "common/gl/shader.cpp",
     'set("normalMatrix", glm::transpose(glm::inverse(glm::mat3(model))));',
     'set("normalMatrix", glm::mat3(model));',
     "normals by mat3(model), wrong under a non-uniform scale (the review: survived)"),
    ("seamless-cube-maps-off", "common/app/app.cpp",
     "    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);",
     "    glDisable(GL_TEXTURE_CUBE_MAP_SEAMLESS);",
     "seams along the cube's edges (the review: 416 pixels off, under the gate)"),
    ("ggx-alpha-linear", "shaders/include/brdf.glsl",
     "    float a = roughness * roughness;",
     "    float a = roughness;",
     "GGX with alpha = roughness instead of roughness^2"),
    ("light-falloff-linear", "shaders/01_lighting/pbr.frag",
     "vec3 radiance = lightColors[i] * attenuation;",
     "vec3 radiance = lightColors[i] * sqrt(attenuation);",
     "1/d light falloff instead of 1/d^2"),
    ("irradiance-no-cosine", "shaders/ibl/irradiance.frag",
     "* cos(theta) * sin(theta);",
     "* sin(theta);",
     "the irradiance convolution without its cosine"),
    ("lut-bias-dropped", "shaders/ibl/brdf_lut.frag",
     "            B += Fc * G_Vis;",
     "            B += 0.0 * G_Vis;",
     "the LUT's bias term dropped"),
    ("sheen-without-pdf", "shaders/ibl/brdf_lut.frag",
     "sum += V_Ashikhmin(NdotL, NdotV) * NdotL * 4.0 * VdotH / NdotH;",
     "sum += V_Ashikhmin(NdotL, NdotV) * NdotL * VdotH;",
     "the sheen estimate without its sampling density (the cookbook's form)"),
    ("split-sum-fresnel-twice", "shaders/include/ibl_ambient.glsl",
     "vec3 E = F0 * envBRDF.x + envBRDF.y;",
     "vec3 E = fresnelSchlickRoughness(NdotV, F0, roughness) * envBRDF.x + envBRDF.y;",
     "the exact split sum multiplying the scale by F instead of F0"),
    ("hdr-half-floats-only", "common/gl/texture.cpp",
     "internalFormat_(fitsHalfFloat(image) ? GL_RGB16F : GL_RGB32F)",
     "internalFormat_(GL_RGB16F)",
     "a bright sun overflowing half floats (the review: NaN in 06's maps, black spheres)"),
    ("ao-decoded-as-srgb", "common/gl/texture.cpp",
     "Texture2D::load(*files.ao, ColorSpace::Linear, filter)",
     "Texture2D::load(*files.ao, ColorSpace::Srgb, filter)",
     "occlusion decoded as sRGB"),
    ("ktx-level-count-unchecked", "common/files/ktx.cpp",
     "    if (levels > maxLevels) {",
     "    if (false) {",
     "a KTX level count of 0xFFFFFFFF read as -1 (the review: 05 segfaulted)"),
    ("gl-errors-dropped", "common/app/app.cpp",
     "        if (++flagged <= debugErrorsSinceCheck_) continue;",
     "        if (GLAD_GL_KHR_debug) continue;",
     "glGetError ignored where KHR_debug exists (the review: muted errors vanished)"),
    ("ibl-state-not-restored", "common/ibl/ibl.cpp",
     "    const SavedGlState saved;\n    const bool sheen = channels",
     "    const bool sheen = channels",
     "the BRDF LUT pass leaves framebuffer, viewport and depth state changed"),
    ("srgb-target-not-encoding", "common/gl/framebuffer.cpp",
     "    if (srgb_) srgbEncoding(true);",
     "    if (srgb_) srgbEncoding(false);",
     "03's sRGB target storing linear values unencoded (and blending them)"),
    ("output-temporaries-left", "common/base/output.cpp",
     "    } catch (...) {\n        removeTemporaries();\n        throw;\n    }",
     "    } catch (...) {\n        throw;\n    }",
     "a failed write leaves its temporary behind"),
    ("sample-flags-unchecked", "common/app/options.cpp",
     "            checkSampleFlag(*own, value);",
     "",
     "a sample's own flags not checked before the context"),
    ("directx-normals-not-flipped", "common/gl/texture.cpp",
     "normal.pixels[i] = std::uint8_t(255 - normal.pixels[i]);",
     "normal.pixels[i] = normal.pixels[i];",
     "DirectX normal maps used as OpenGL ones"),
    ("basecolor-name-unknown", "common/files/material_folder.cpp",
     '{"albedo", "basecolor", "base_color",',
     '{"albedo", "base_color",',
     "freepbr's *_basecolor.png not found"),
]


def run(command, cwd, log):
    with open(log, "a") as out:
        return subprocess.run(command, cwd=cwd, stdout=out, stderr=subprocess.STDOUT).returncode


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--list", action="store_true", help="list the mutations and stop")
    parser.add_argument("--only", nargs="+", default=[], help="run only these mutations")
    parser.add_argument("--build", default="build/release", help="the Release build folder")
    parser.add_argument("--jobs", default=str(os.cpu_count() or 2))
    args = parser.parse_args()
    source = pathlib.Path(__file__).resolve().parent.parent
    build = (source / args.build).resolve()
    if args.list:
        for name, path, _, _, why in MUTATIONS:
            print(f"{name:30} {path:36} {why}")
        return 0
    chosen = [m for m in MUTATIONS if not args.only or m[0] in args.only]
    unknown = set(args.only) - {m[0] for m in MUTATIONS}
    if unknown:
        print(f"mutate.py: unknown mutation(s): {', '.join(sorted(unknown))}", file=sys.stderr)
        return 2
    log = build / "test-output" / "mutations.log"
    log.parent.mkdir(parents=True, exist_ok=True)
    log.write_text("")
    results = []
    for name, path, old, new, why in chosen:
        file = source / path
        original = file.read_text()
        if original.count(old) != 1:
            print(f"mutate.py: {name}: the text to replace occurs {original.count(old)} times in "
                  f"{path}; the mutation list is stale", file=sys.stderr)
            return 1
        started = time.time()
        try:
            file.write_text(original.replace(old, new))
            with open(log, "a") as out:
                out.write(f"\n===== {name}: {why}\n")
            if run(["cmake", "--build", str(build), "-j", args.jobs], source, log) != 0:
                verdict, caught_by = "caught", "the build"
            else:
                before = log.stat().st_size
                code = run(["ctest", "--test-dir", str(build), "-j", args.jobs,
                            "--stop-on-failure", "-LE", "docs"], source, log)
                text = log.read_text()[before:]
                failed = re.findall(r"^\s*\d+ - (\S+) \((?:Failed|Timeout|SEGFAULT|Subprocess)",
                                    text, re.M)
                verdict = "caught" if code != 0 else "SURVIVED"
                caught_by = ", ".join(failed[:3]) if failed else ("-" if code == 0 else "?")
        finally:
            file.write_text(original)
        seconds = time.time() - started
        results.append((name, verdict, caught_by, seconds, why))
        print(f"{name}: {verdict} ({caught_by}) in {seconds:.0f} s", flush=True)
    run(["cmake", "--build", str(build), "-j", args.jobs], source, log)

    print("\n| mutation | what it breaks | verdict | first test to fail |")
    print("| --- | --- | --- | --- |")
    for name, verdict, caught_by, _, why in results:
        print(f"| {name} | {why} | {verdict} | {caught_by} |")
    survived = [r for r in results if r[1] != "caught"]
    print(f"\n{len(results) - len(survived)} of {len(results)} caught; log: {log}")
    return 1 if survived else 0


if __name__ == "__main__":
    sys.exit(main())
