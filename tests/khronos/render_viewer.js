// Renders glTF files with the Khronos glTF Sample Viewer (npm @khronosgroup/gltf-viewer 1.1.0,
// WebGL 2) in ONE headless Chromium session, as a reference for samples 07, 08 and 10
// (tests/khronos/khronos_test.cpp). A tiny HTTP server on 127.0.0.1 (node's http module) serves
// the page, the viewer's bundle and its libraries, and the cases' files; the browser is driven
// over the DevTools protocol on a pipe (tests/support/chromium_pipe.js).
//
//     node tests/khronos/render_viewer.js CHROMIUM VIEWER_DIR JOB.json [TIMEOUT_S]
//
// VIEWER_DIR: the installed package (build/node-tools/node_modules/@khronosgroup/gltf-viewer).
// JOB.json:
//     { "environment": "/abs/tiny.hdr",
//       "cases": [ { "name": "...", "gltf": "/abs/file.gltf" (or .glb),
//                    "eye": [x,y,z], "target": [x,y,z], "yfov": radians, "near": n, "far": f,
//                    "width": w, "height": h, "output": "/abs/out.png",
//                    "clear": linear grey of the background,
//                    "defaultLight": { "direction": [x,y,z], "intensity": lux }  (optional: the
//                        light a renderer adds to a file without KHR_lights_punctual) } ],
//       "sheenTable": "/abs/lut_sheen_E.png"  (optional, below),
//       "imageBasedLight": true, "singleScattering": true, "cubeFaceSize": 64  (optional,
//       below) }
//
// The viewer 1.1.0 never applies its sheen albedo scaling: its package lacks the table it asks
// for (lut_sheen_E.png), and it marks that texture initialized before any upload, so even a
// served file would never reach the GL. With "sheenTable" the job serves that table (E of its
// Charlie sheen at x = NdotV, y = sheen roughness, in R) and the bundle is served with that one
// line changed (sheenELut.initialized = false), so that the viewer scales as it means to.
//
// The viewer 1.1.0 weighs transmitted light by 1 - F twice: inside its two transmission functions
// (the backdrop's, 1 - (F0 A + F90 B), and a light's, 1 - F), then again in the mix of the
// dielectric's base with its reflection by the Fresnel. Khronos took the inner ones out after 1.1.0
// (glTF-Sample-Renderer pull request 24, "Remove fresnel term from transmission formulas"). Its
// light through a surface also lacks the cosine every lobe is integrated with (D V NdotL, NdotL at
// the mirrored light, as its reflection has it), so a light in front of a thin pane sends light
// through it towards the front. The bundle is always served with those two returns changed
// (transmissionFixes; they touch nothing but KHR_materials_transmission's code): without the
// cosine, a rough pane lit from the front measured 29.4 dB (worst 16) against 54.4 dB with it.
//
// Every case: IBL off (the viewer still needs an environment: the job's tiny .hdr, filtered
// once), the file's own KHR_lights_punctual lights (no viewer default lights unless the case
// names one), tone mapping NONE with exposure 1 (the viewer then writes pow(linear, 1/2.2),
// clipped), no antialiasing, no anisotropic filtering, environmentRotation 0, the background the
// case's linear grey.
//
// With "imageBasedLight": the other way round, the job's environment lights every case alone
// (no punctual light) and is drawn behind it, unblurred. The viewer filters it with its own
// shaders and sample counts, at smaller sizes (iblSizes: "cubeFaceSize"^2 cube faces, 64^2 unless
// the job says, instead of 256^2, with the same five levels of roughness 0, 1/4 ... 1; 128^2
// lookup tables instead of 1024^2): seconds of SwiftShader instead of minutes. The environments
// the tests give it are smooth (linear in the direction, or constant). Its filtering converges
// with the face size: on the linear sky a rough metal sphere measured 42.2 dB against ours with
// 32^2 faces, 47.6 dB with 64^2 and 49.0 dB with 128^2 (which takes 25 s more).
// Its split sum is served with one change (exactSplitSum): the viewer weighs the LUT's scale by a
// roughness-dependent Fresnel of the view angle, F0 + (max(1 - roughness, F0) - F0) (1 - NdotV)^5,
// where the split sum's derivation has F0 alone (the LUT's bias already holds the Fresnel rise
// towards grazing angles; with both, a smooth dielectric seen at NdotV = 0.5 reflects 0.099 of the
// environment where Schlick's Fresnel and the exact integral give 0.070). With
// "singleScattering" its multiple-scattering share (FmsEms) is left out too, as the sample's
// --single-scattering leaves out its own. With a "sheenTable" too, its sheen's image-based light
// is weighed by the albedo in that table (sheenIblAlbedo), the albedo of the sheen it lights
// punctual lights with (D_Charlie, V_Sheen) and scales the base by, instead of the one with
// Ashikhmin's visibility in the B channel of its own table; and its sheen lobe prefilters the
// environment with 1024 samples a texel instead of 64 (a narrow sheen lobe's samples fall mostly
// below the horizon: with 64, the sheen spheres measured 43.3 dB against ours, 47.0 with 1024). The camera is set as a world transform (the inverse of
// lookAt(eye, target, +Y)); UserCamera.lookAt would store the view matrix itself there.
// Each PNG (8-bit RGB, the canvas's bytes as they are) is written whole or not at all.
// Exit code 0 when every case was written, 1 otherwise (the reasons on stderr). Node's standard
// library only, plus the viewer package.
"use strict";
const fs = require("fs");
const http = require("http");
const path = require("path");
const zlib = require("zlib");
const { launchChromium, writeWhole } = require("../support/chromium_pipe.js");

const [chromium, viewerDir, jobFile, timeoutText] = process.argv.slice(2);
if (!chromium || !viewerDir || !jobFile) {
  console.error("usage: node render_viewer.js CHROMIUM VIEWER_DIR JOB.json [TIMEOUT_S]");
  process.exit(2);
}
const timeoutMs = 1000 * Number(timeoutText || 120);
const job = JSON.parse(fs.readFileSync(jobFile, "utf8"));

// --- PNG (8-bit RGB, no interlace), zlib from node ----------------------------------------------
const crcTable = Array.from({ length: 256 }, (_, n) => {
  let c = n;
  for (let k = 0; k < 8; ++k) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
  return c >>> 0;
});
function crc32(bytes) {
  let c = 0xffffffff;
  for (const b of bytes) c = crcTable[(c ^ b) & 255] ^ (c >>> 8);
  return (c ^ 0xffffffff) >>> 0;
}
function chunk(type, data) {
  const out = Buffer.alloc(12 + data.length);
  out.writeUInt32BE(data.length, 0);
  out.write(type, 4, "latin1");
  data.copy(out, 8);
  out.writeUInt32BE(crc32(out.subarray(4, 8 + data.length)), 8 + data.length);
  return out;
}
// rgb: width * height * 3 bytes, top row first.
function encodePng(width, height, rgb) {
  const header = Buffer.alloc(13);
  header.writeUInt32BE(width, 0);
  header.writeUInt32BE(height, 4);
  header[8] = 8;  // bit depth
  header[9] = 2;  // RGB
  const raw = Buffer.alloc(height * (1 + 3 * width));
  for (let y = 0; y < height; ++y) {
    raw[y * (1 + 3 * width)] = 0;  // filter: none
    rgb.copy(raw, y * (1 + 3 * width) + 1, y * 3 * width, (y + 1) * 3 * width);
  }
  return Buffer.concat([Buffer.from([137, 80, 78, 71, 13, 10, 26, 10]), chunk("IHDR", header),
                        chunk("IDAT", zlib.deflateSync(raw, { level: 6 })),
                        chunk("IEND", Buffer.alloc(0))]);
}

// --- the server ---------------------------------------------------------------------------------
// What it may serve from the disk: the folders of the cases' files and of the environment.
const roots = new Set([path.dirname(path.resolve(job.environment))]);
for (const c of job.cases) roots.add(path.dirname(path.resolve(c.gltf)));
const types = {
  ".js": "text/javascript", ".wasm": "application/wasm", ".gltf": "model/gltf+json",
  ".json": "application/json", ".png": "image/png", ".jpg": "image/jpeg", ".jpeg": "image/jpeg",
  ".html": "text/html",
};
const page = `<!doctype html><html><head><meta charset="utf-8">
<script>window.LIBKTX = undefined; window.DracoDecoderModule = undefined;</script>
<script type="module">
import { GltfView, GltfState } from "/viewer/dist/gltf-viewer.module.js";
const canvas = document.createElement("canvas");
document.body.appendChild(canvas);
const gl = canvas.getContext("webgl2", { antialias: false, alpha: false, depth: true,
                                         premultipliedAlpha: false, preserveDrawingBuffer: true });
// No anisotropic filtering: the viewer asks for 16x wherever the extension is there.
const getExtension = gl.getExtension.bind(gl);
gl.getExtension = (name) => name === "EXT_texture_filter_anisotropic" ? null : getExtension(name);
const view = new GltfView(gl);
const getVisibleLights = view.renderer.getVisibleLights;
const loader = view.createResourceLoader(undefined, undefined, "/viewer/dist/libs/");
let environment;

function cameraToWorld(eye, target) {  // the inverse of lookAt(eye, target, +Y), column-major
  const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
  const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                           a[0] * b[1] - a[1] * b[0]];
  const unit = (a) => { const l = Math.hypot(a[0], a[1], a[2]); return [a[0] / l, a[1] / l, a[2] / l]; };
  const f = unit(sub(target, eye)), s = unit(cross(f, [0, 1, 0])), u = cross(s, f);
  return new Float32Array([s[0], s[1], s[2], 0, u[0], u[1], u[2], 0, -f[0], -f[1], -f[2], 0,
                           eye[0], eye[1], eye[2], 1]);
}

window.pbrRender = async (c) => {
  if (!environment && c.imageBasedLight) {
    environment = await loader.loadEnvironment(c.environment,
                                               { lut_sheen_E_file: "/lut_sheen_E.png" });
  }
  if (!environment) {
    // The viewer filters the environment with fixed sizes and sample counts whatever the image
    // (256^2 cube faces, 2048 Lambertian and 1024 GGX samples a texel, two 1024^2 LUTs): minutes
    // of SwiftShader, queued on the GPU, that the first read-back would wait for. With IBL off
    // nothing reads those maps, so the filter passes (its only draws) are skipped.
    const drawArrays = gl.drawArrays;
    gl.drawArrays = () => {};
    try {
      environment = await loader.loadEnvironment(c.environment,
                                                 { lut_sheen_E_file: "/lut_sheen_E.png" });
    } finally {
      gl.drawArrays = drawArrays;
    }
  }
  const state = view.createState();
  state.gltf = await loader.loadGltf(c.gltf);
  state.environment = environment;
  state.sceneIndex = state.gltf.scene ?? 0;
  state.cameraIndex = undefined;
  const p = state.renderingParameters;
  p.useIBL = c.imageBasedLight;
  p.usePunctual = !c.imageBasedLight;
  p.renderEnvironmentMap = c.imageBasedLight;
  p.blurEnvironmentMap = false;
  p.toneMap = GltfState.ToneMaps.NONE;
  p.exposure = 1.0;
  p.environmentRotation = 0.0;
  // gl.clearColor takes it as it is (documented as 0-255, used as 0-1); the viewer's display
  // encoding is pow(1/2.2), so the linear grey goes in so encoded.
  const clear = Math.pow(c.clear, 1 / 2.2);
  p.clearColor = [clear, clear, clear, 1.0];
  // A file without lights: the one directional light the case names, as the renderer under test
  // adds it. The viewer's own fallback (useDirectionalLightsWithDisabledIBL: two lights) stays
  // off; its light object (lightKey) is reused with a node of its own, since without a node
  // toUniform gives it a NaN position, and SwiftShader's shader then draws black.
  p.useDirectionalLightsWithDisabledIBL = false;
  // getVisibleLights recurses into children through this same property: only the outermost
  // call (the scene's nodes) gets the light.
  let depth = 0;
  view.renderer.getVisibleLights = (gltf, nodes) => {
    let lights;
    ++depth;
    try {
      lights = getVisibleLights.call(view.renderer, gltf, nodes);
    } finally {
      --depth;
    }
    if (c.defaultLight && depth === 0 && lights.length === 0) {
      const light = view.renderer.lightKey;
      light.direction = new Float32Array(c.defaultLight.direction);  // a plain array: no light
      light.color = [1, 1, 1];
      light.intensity = c.defaultLight.intensity;
      lights.push([{ worldTransform: new Float32Array([1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]) },
                   light]);
    }
    return lights;
  };
  const camera = state.userCamera;
  camera.transform = cameraToWorld(c.eye, c.target);
  camera.perspective.yfov = c.yfov;
  camera.perspective.znear = c.near;
  camera.perspective.zfar = c.far;
  canvas.width = c.width;
  canvas.height = c.height;
  // Two frames: whatever the first one sets up lazily is in place for the second.
  view.renderFrame(state, c.width, c.height);
  view.renderFrame(state, c.width, c.height);
  gl.bindFramebuffer(gl.FRAMEBUFFER, null);
  const pixels = new Uint8Array(c.width * c.height * 4);
  gl.readPixels(0, 0, c.width, c.height, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
  let text = "";
  for (let i = 0; i < pixels.length; i += 0x8000) {
    text += String.fromCharCode.apply(null, pixels.subarray(i, i + 0x8000));
  }
  return btoa(text);
};
window.pbrReady = true;
</script></head><body style="margin:0"></body></html>`;

const transmissionFixes = [
  ["return(1.0-specularColor)*attenuatedColor*baseColor;", "return attenuatedColor*baseColor;"],
  ["return(1.0-F)*baseColor*D*Vis;", "return baseColor*D*Vis*clamp(dot(n,l_mirror),0.0,1.0);"],
];
// faces of `size`^2 (a power of two, 16 or more), five levels of roughness as the viewer's own
const iblSizes = (size) => [
  ["this.textureSize = 256;", `this.textureSize = ${size};`],
  ["this.lowestMipLevel = 4;", `this.lowestMipLevel = ${Math.log2(size) - 4};`],
  ["this.lutResolution = 1024;", "this.lutResolution = 128;"],
  ["this.sheenSamplCount = 64;", "this.sheenSamplCount = 1024;"],
];
const sheenIblAlbedo = ["float brdf=texture(u_CharlieLUT,brdfSamplePoint).b;",
                        "float brdf=texture(u_SheenELUT,brdfSamplePoint).r;"];
const exactSplitSum = ["vec3 Fr=max(vec3(1.0-roughness),F0)-F0;", "vec3 Fr=vec3(0.0);"];
const singleScattering = ["return FssEss+FmsEms;}", "return FssEss;}"];
const server = http.createServer((request, response) => {
  const url = decodeURIComponent(new URL(request.url, "http://localhost").pathname);
  let file;
  if (url === "/") {
    response.writeHead(200, { "Content-Type": "text/html" });
    response.end(page);
    return;
  }
  if (url === "/lut_sheen_E.png" && !job.sheenTable) {  // fetched; the job draws no sheen
    response.writeHead(200, { "Content-Type": "image/png" });
    response.end(encodePng(1, 1, Buffer.from([255, 255, 255])));
    return;
  }
  if (url === "/lut_sheen_E.png") {
    file = path.resolve(job.sheenTable);
  }
  const bundle = "/viewer/dist/gltf-viewer.module.js";
  if (url === bundle) {  // served with the lines below changed
    let text = fs.readFileSync(path.join(viewerDir, "dist", "gltf-viewer.module.js"), "utf8");
    const changes = [...transmissionFixes];
    if (job.imageBasedLight) changes.push(...iblSizes(job.cubeFaceSize ?? 64), exactSplitSum);
    if (job.singleScattering) changes.push(singleScattering);
    if (job.sheenTable) changes.push(["sheenELut.initialized = true;", "sheenELut.initialized = false;"]);
    if (job.sheenTable && job.imageBasedLight) changes.push(sheenIblAlbedo);
    for (const [line, replacement] of changes) {
      if (!text.includes(line)) {
        finish(1, `the viewer's bundle has no '${line}' to change: another version?`);
        return;
      }
      text = text.replace(line, replacement);
    }
    response.writeHead(200, { "Content-Type": "text/javascript" });
    response.end(text);
    return;
  }
  if (file) {
    // the table above
  } else if (url.startsWith("/viewer/")) {
    file = path.join(viewerDir, path.normalize(url.slice("/viewer/".length)));
    if (!file.startsWith(path.resolve(viewerDir) + path.sep)) file = undefined;
  } else if (url.startsWith("/fs/")) {
    file = path.normalize(url.slice("/fs".length));
    if (![...roots].some((root) => file.startsWith(root + path.sep))) file = undefined;
  }
  fs.readFile(file || "", (error, data) => {
    if (!file || error) {
      response.writeHead(404);
      response.end();
      return;
    }
    response.writeHead(200, {
      "Content-Type": types[path.extname(file).toLowerCase()] || "application/octet-stream",
    });
    response.end(data);
  });
});

let browser;
function finish(code, why) {
  if (why) {
    const err = browser ? browser.stderr() : "";
    console.error(`render_viewer.js: ${why}${err ? "\n" + err.slice(-2000) : ""}`);
  }
  if (browser) browser.close();
  server.close();
  process.exit(code);
}

server.listen(0, "127.0.0.1", async () => {
  const timer = setTimeout(() => finish(1, `not done after ${timeoutMs / 1000} s`), timeoutMs);
  try {
    const origin = `http://127.0.0.1:${server.address().port}`;
    browser = launchChromium(chromium, path.dirname(path.resolve(jobFile)));
    browser.onEvent((message) => {  // the page's errors, for the reader of a failure
      if (message.method === "Runtime.exceptionThrown") {
        console.error(`page: ${message.params.exceptionDetails.exception?.description ?? ""}`);
      } else if (message.method === "Runtime.consoleAPICalled" &&
                 (message.params.type === "error" || message.params.type === "warning")) {
        console.error(`page ${message.params.type}: ` +
                      message.params.args.map((a) => a.value ?? a.description).join(" "));
      }
    });
    const session = await browser.open(`${origin}/`);
    await browser.send("Runtime.enable", {}, session);
    const started = Date.now();
    while (!(await browser.evaluate(session, "window.pbrReady === true"))) {
      if (Date.now() - started > 30000) throw new Error("the page never loaded the viewer");
      await new Promise((resolve) => setTimeout(resolve, 50));
    }
    const failed = [];
    for (const c of job.cases) {
      const begin = Date.now();
      const request = {
        ...c, gltf: `/fs${path.resolve(c.gltf)}`, environment: `/fs${path.resolve(job.environment)}`,
        imageBasedLight: job.imageBasedLight === true,
      };
      try {
        const base64 = await browser.evaluate(session, `pbrRender(${JSON.stringify(request)})`);
        const rgba = Buffer.from(base64, "base64"), rgb = Buffer.alloc(c.width * c.height * 3);
        for (let y = 0; y < c.height; ++y) {  // GL's rows bottom first; PNG's top first
          for (let x = 0; x < c.width; ++x) {
            const from = 4 * ((c.height - 1 - y) * c.width + x), to = 3 * (y * c.width + x);
            rgb[to] = rgba[from];
            rgb[to + 1] = rgba[from + 1];
            rgb[to + 2] = rgba[from + 2];
          }
        }
        writeWhole(c.output, encodePng(c.width, c.height, rgb));
        console.log(`${c.name}: ${((Date.now() - begin) / 1000).toFixed(2)} s`);
      } catch (error) {
        failed.push(`${c.name}: ${error.message}`);
      }
    }
    clearTimeout(timer);
    finish(failed.length ? 1 : 0, failed.length ? failed.join("\n") : "");
  } catch (error) {
    finish(1, error.message);
  }
});
