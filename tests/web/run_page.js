// Opens one web sample's page in headless Chromium and waits, in real time, until the sample has
// exited (the page's #pbr-exit, web/shell.html), then leaves what the page holds in a folder:
// every file the run wrote, its log (page.log) and its exit code (exit.txt). The browser is
// driven over the DevTools protocol on a pipe (--remote-debugging-pipe), so nothing waits on a
// guess: not a virtual-time budget, which can end a page whose frame loop is still running.
//
//     node tests/web/run_page.js CHROMIUM URL DIR [TIMEOUT_S]
//
// Exit code 0 when the page reported an exit code (whatever it was), 1 otherwise (the reason on
// stderr). Node's standard library only.
"use strict";
const { spawn } = require("child_process");
const fs = require("fs");
const path = require("path");

const [chromium, url, dir, timeoutText] = process.argv.slice(2);
if (!chromium || !url || !dir) {
  console.error("usage: node run_page.js CHROMIUM URL DIR [TIMEOUT_S]");
  process.exit(2);
}
const timeoutMs = 1000 * Number(timeoutText || 120);

// Whole or absent: a temporary beside the file, renamed over it.
function writeWhole(file, data) {
  const temporary = path.join(path.dirname(file), `.${path.basename(file)}.${process.pid}.tmp`);
  fs.writeFileSync(temporary, data);
  fs.renameSync(temporary, file);
}

const profile = fs.mkdtempSync(path.join(dir, ".profile-"));
const browser = spawn(chromium, [
  "--headless", "--no-sandbox", `--user-data-dir=${profile}`, "--use-angle=swiftshader",
  "--enable-unsafe-swiftshader", "--disable-gpu", "--disable-background-networking",
  "--disable-component-update", "--disable-sync", "--no-first-run", "--remote-debugging-pipe",
  "about:blank",
], { stdio: ["ignore", "ignore", "pipe", "pipe", "pipe"] });
let browserErr = "";
browser.stderr.on("data", (d) => { browserErr += d; });

const toBrowser = browser.stdio[3], fromBrowser = browser.stdio[4];
let nextId = 1, buffered = Buffer.alloc(0);
const pending = new Map();
function send(method, params = {}, sessionId) {
  const id = nextId++;
  const message = { id, method, params };
  if (sessionId) message.sessionId = sessionId;
  toBrowser.write(JSON.stringify(message) + "\0");
  return new Promise((resolve, reject) => pending.set(id, { resolve, reject }));
}
fromBrowser.on("data", (chunk) => {
  buffered = Buffer.concat([buffered, chunk]);
  for (let end = buffered.indexOf(0); end >= 0; end = buffered.indexOf(0)) {
    const message = JSON.parse(buffered.subarray(0, end).toString("utf8"));
    buffered = buffered.subarray(end + 1);
    const waiting = message.id && pending.get(message.id);
    if (!waiting) continue;
    pending.delete(message.id);
    if (message.error) waiting.reject(new Error(message.error.message));
    else waiting.resolve(message.result);
  }
});

// What the page holds once the sample has exited, as one JSON text (null before).
const collect = `(function () {
  var exit = document.getElementById("pbr-exit");
  if (!exit) return null;
  var files = {};
  document.querySelectorAll("pre.pbr-file[data-name]").forEach(function (e) {
    files[e.getAttribute("data-name")] = e.textContent;
  });
  var log = document.getElementById("pbr-log");
  return JSON.stringify({ exit: exit.textContent, log: log ? log.textContent : "", files: files });
})()`;

function finish(code, why) {
  if (why) console.error(`run_page.js: ${why}${browserErr ? "\n" + browserErr.slice(-2000) : ""}`);
  browser.kill("SIGKILL");
  fs.rmSync(profile, { recursive: true, force: true });
  process.exit(code);
}

(async () => {
  const timer = setTimeout(() => finish(1, `no exit code from the page after ${timeoutMs / 1000} s`),
                           timeoutMs);
  const { targetId } = await send("Target.createTarget", { url });
  const { sessionId } = await send("Target.attachToTarget", { targetId, flatten: true });
  for (;;) {
    const { result } = await send("Runtime.evaluate", { expression: collect, returnByValue: true },
                                  sessionId);
    if (result && typeof result.value === "string") {
      const page = JSON.parse(result.value);
      for (const [name, base64] of Object.entries(page.files)) {
        writeWhole(path.join(dir, path.basename(name)), Buffer.from(base64, "base64"));
      }
      writeWhole(path.join(dir, "page.log"), page.log);
      writeWhole(path.join(dir, "exit.txt"), page.exit);
      clearTimeout(timer);
      finish(0);
    }
    await new Promise((resolve) => setTimeout(resolve, 100));
  }
})().catch((error) => finish(1, error.message));
