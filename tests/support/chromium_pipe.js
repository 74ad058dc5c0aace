// Headless Chromium driven over the DevTools protocol on a pipe (--remote-debugging-pipe): one
// browser, its messages in order, nothing waited for by guess. Shared by tests/web/run_page.js
// (a web sample's page) and tests/khronos/render_viewer.js (the Khronos glTF Sample Viewer).
// Node's standard library only.
"use strict";
const { spawn } = require("child_process");
const fs = require("fs");
const path = require("path");

// Whole or absent: a temporary beside the file, renamed over it.
function writeWhole(file, data) {
  const temporary = path.join(path.dirname(file), `.${path.basename(file)}.${process.pid}.tmp`);
  fs.writeFileSync(temporary, data);
  fs.renameSync(temporary, file);
}

// Starts the browser with a fresh profile folder inside `dir`, on SwiftShader's WebGL 2.
// Returns { send(method, params, sessionId) -> Promise of the result, open(url) -> Promise of a
// session id, evaluate(sessionId, expression) -> Promise of the value (promises awaited),
// onEvent(listener) (every protocol event: { method, params, sessionId }), close(), stderr() }.
function launchChromium(chromium, dir) {
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
  const listeners = [];
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
      if (message.method) listeners.forEach((listener) => listener(message));
      const waiting = message.id && pending.get(message.id);
      if (!waiting) continue;
      pending.delete(message.id);
      if (message.error) waiting.reject(new Error(message.error.message));
      else waiting.resolve(message.result);
    }
  });

  async function open(url) {
    const { targetId } = await send("Target.createTarget", { url });
    const { sessionId } = await send("Target.attachToTarget", { targetId, flatten: true });
    return sessionId;
  }
  async function evaluate(sessionId, expression) {
    const { result, exceptionDetails } = await send(
      "Runtime.evaluate", { expression, returnByValue: true, awaitPromise: true }, sessionId);
    if (exceptionDetails) {
      const e = exceptionDetails.exception;
      throw new Error((e && (e.description || e.value)) || exceptionDetails.text);
    }
    return result ? result.value : undefined;
  }
  // The browser's helper processes can still be writing to the profile for a moment after the
  // kill (seen: ENOTEMPTY on its Default folder, failing a run whose pictures were all written):
  // the removal retries, and a profile that still will not go is left behind, said, not fatal.
  function close() {
    browser.kill("SIGKILL");
    try {
      fs.rmSync(profile, { recursive: true, force: true, maxRetries: 20, retryDelay: 50 });
    } catch (e) {
      process.stderr.write(`chromium_pipe.js: left ${profile} behind: ${e.message}\n`);
    }
  }
  return {
    send, open, evaluate, close, stderr: () => browserErr,
    onEvent: (listener) => listeners.push(listener),
  };
}

module.exports = { launchChromium, writeWhole };
