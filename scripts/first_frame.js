// Opens a web sample's page as a user does (a fresh headless Chromium on its software WebGL 2,
// SwiftShader, the page's own default view in its canvas) and prints, as one JSON line, how long
// after the page was opened its first frame was drawn: the page's own marks
// (#pbr-status[data-first-frame-ms], web/shell.html: performance.now() once the first frame's GL
// work has finished; data-first-frame-submitted-ms once its commands were all given), real time,
// no virtual time budget. Run by scripts/bench.py --web.
//
//     node scripts/first_frame.js CHROMIUM URL [TIMEOUT_S]
//
// Node's standard library only.
"use strict";
const fs = require("fs");
const os = require("os");
const path = require("path");
const { launchChromium } = require("../tests/support/chromium_pipe.js");

const [chromium, url, timeoutText] = process.argv.slice(2);
if (!chromium || !url) {
  console.error("usage: node first_frame.js CHROMIUM URL [TIMEOUT_S]");
  process.exit(2);
}
const dir = fs.mkdtempSync(path.join(os.tmpdir(), "pbr-first-frame-"));
const browser = launchChromium(chromium, dir);
function finish(code, text) {
  if (text) (code === 0 ? process.stdout : process.stderr).write(text + "\n");
  browser.close();
  fs.rmSync(dir, { recursive: true, force: true });
  process.exit(code);
}
const mark = `(function () {
  var status = document.getElementById("pbr-status");
  var exit = document.getElementById("pbr-exit");
  if (exit) return JSON.stringify({ failed: status ? status.textContent : "exit" });
  var ms = status && status.getAttribute("data-first-frame-ms");
  return ms ? JSON.stringify({ first_frame_ms: Number(ms), submitted_ms:
                               Number(status.getAttribute("data-first-frame-submitted-ms")) })
            : null;
})()`;
(async () => {
  setTimeout(() => finish(1, `first_frame.js: no first frame after ${timeoutText || 60} s`),
             1000 * Number(timeoutText || 60));
  const sessionId = await browser.open(url);
  for (;;) {
    const value = await browser.evaluate(sessionId, mark);
    if (typeof value === "string") {
      const result = JSON.parse(value);
      if (result.failed) finish(1, `first_frame.js: the page ended: ${result.failed}`);
      finish(0, value);
    }
    await new Promise((resolve) => setTimeout(resolve, 20));
  }
})().catch((error) => finish(1, `first_frame.js: ${error.message}`));
