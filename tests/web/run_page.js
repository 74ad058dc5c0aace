// Opens one web sample's page in headless Chromium and waits, in real time, until the sample has
// exited (the page's #pbr-exit, web/shell.html), then leaves what the page holds in a folder:
// every file the run wrote, its log (page.log), its exit code (exit.txt), the page's query
// string at the end (address.txt: the page's controls keep it current), every text its
// header showed, one a line (said.txt), its line on the mouse and keys (hint.txt), the bar's
// command line and frame time under a shown picture (command.txt, frame.txt), a view's caption
// (caption.txt) and its scale bar's ticks ("at value;...", scale.txt), how many labels over the
// picture are still shown (labels.txt), and, when the address
// asks for one with shot=N after '#' (web/shell.html), the canvas as the browser showed frame N for a person to see, cut from a
// screenshot of the page (canvas-screenshot.png): not the program's own read-back, so what WebGL
// does to a picture on its way to the screen is in it. The browser is driven over the DevTools protocol on a
// pipe (tests/support/chromium_pipe.js), so nothing waits on a guess: not a virtual-time budget,
// which can end a page whose frame loop is still running.
//
//     node tests/web/run_page.js CHROMIUM URL DIR [TIMEOUT_S]
//
// Exit code 0 when the page reported an exit code (whatever it was), 1 otherwise (the reason on
// stderr). Node's standard library only.
"use strict";
const path = require("path");
const { launchChromium, writeWhole } = require("../support/chromium_pipe.js");

const [chromium, url, dir, timeoutText] = process.argv.slice(2);
if (!chromium || !url || !dir) {
  console.error("usage: node run_page.js CHROMIUM URL DIR [TIMEOUT_S]");
  process.exit(2);
}
const timeoutMs = 1000 * Number(timeoutText || 120);
const browser = launchChromium(chromium, dir);

// What the page holds once the sample has exited, as one JSON text (null before).
const collect = `(function () {
  var exit = document.getElementById("pbr-exit");
  if (!exit) return null;
  var files = {};
  document.querySelectorAll("pre.pbr-file[data-name]").forEach(function (e) {
    files[e.getAttribute("data-name")] = e.textContent;
  });
  var log = document.getElementById("pbr-log");
  var status = document.getElementById("pbr-status");
  return JSON.stringify({ exit: exit.textContent, log: log ? log.textContent : "", files: files,
                         address: location.search,
                         said: (status && status.getAttribute("data-said")) || "",
                         hint: (document.getElementById("pbr-hint") || {}).textContent || "",
                         command: (document.getElementById("pbr-command") || {}).textContent || "",
                         frame: (document.getElementById("pbr-frame") || {}).textContent || "",
                         caption: (document.getElementById("pbr-caption-text") || {}).textContent || "",
                         labels: Array.from(document.querySelectorAll("#pbr-labels > div"))
                             .filter(function (e) { return e.offsetParent !== null; }).length,
                         scale: Array.from(document.querySelectorAll("#pbr-caption-scale span"))
                             .map(function (e) { return e.getAttribute("data-at") + " " + e.textContent; })
                             .join(";") });
})()`;

// The canvas's place in the page, once the page holds a frame for its screenshot (null before).
const shotReady = `(function () {
  var status = document.getElementById("pbr-status");
  if (!status || status.getAttribute("data-shot") !== "ready") return null;
  var box = document.getElementById("canvas").getBoundingClientRect();
  return JSON.stringify({ x: box.left + scrollX, y: box.top + scrollY, width: box.width,
                         height: box.height });
})()`;

function finish(code, why) {
  const browserErr = browser.stderr();
  if (why) console.error(`run_page.js: ${why}${browserErr ? "\n" + browserErr.slice(-2000) : ""}`);
  browser.close();
  process.exit(code);
}

(async () => {
  const timer = setTimeout(() => finish(1, `no exit code from the page after ${timeoutMs / 1000} s`),
                           timeoutMs);
  const sessionId = await browser.open(url);
  for (;;) {
    const shot = await browser.evaluate(sessionId, shotReady);
    if (typeof shot === "string") {
      // the page's pixels 1:1 (a canvas of W x H pixels is W x H CSS pixels at scale 1)
      const { data } = await browser.send("Page.captureScreenshot", {
        format: "png", captureBeyondViewport: true, clip: { ...JSON.parse(shot), scale: 1 },
      }, sessionId);
      writeWhole(path.join(dir, "canvas-screenshot.png"), Buffer.from(data, "base64"));
      await browser.evaluate(sessionId, `document.getElementById("pbr-status")
          .setAttribute("data-shot", "taken"), Module.pbrShotTaken(), true`);
    }
    const value = await browser.evaluate(sessionId, collect);
    if (typeof value === "string") {
      const page = JSON.parse(value);
      for (const [name, base64] of Object.entries(page.files)) {
        writeWhole(path.join(dir, path.basename(name)), Buffer.from(base64, "base64"));
      }
      writeWhole(path.join(dir, "page.log"), page.log);
      writeWhole(path.join(dir, "exit.txt"), page.exit);
      writeWhole(path.join(dir, "address.txt"), page.address);
      writeWhole(path.join(dir, "said.txt"), page.said);
      writeWhole(path.join(dir, "hint.txt"), page.hint);
      writeWhole(path.join(dir, "command.txt"), page.command);
      writeWhole(path.join(dir, "frame.txt"), page.frame);
      writeWhole(path.join(dir, "caption.txt"), page.caption);
      writeWhole(path.join(dir, "scale.txt"), page.scale);
      writeWhole(path.join(dir, "labels.txt"), String(page.labels));
      clearTimeout(timer);
      finish(0);
    }
    await new Promise((resolve) => setTimeout(resolve, 100));
  }
})().catch((error) => finish(1, error.message));
