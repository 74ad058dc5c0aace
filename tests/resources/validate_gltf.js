// Runs Khronos' glTF validator (npm package gltf-validator) on one file:
//   node validate_gltf.js <path to the gltf-validator module> <file.gltf|.glb> [--strict]
//                         [--allow CODE@POINTER]...
// prints the counts, then every message (errors, warnings, infos, hints); exits 0 when there are
// no errors and, with --strict, no warnings either. --allow names one warning that is expected
// (its code at that JSON pointer): it is printed as expected and not counted against --strict,
// and its absence is a failure (so that an allowance cannot outlive its reason).
const fs = require('fs'), path = require('path');
const validator = require(process.argv[2]);
const file = process.argv[3];
let strict = false;
const allowed = new Set();
for (let i = 4; i < process.argv.length; ++i) {
  if (process.argv[i] === '--strict') strict = true;
  else if (process.argv[i] === '--allow' && i + 1 < process.argv.length) allowed.add(process.argv[++i]);
  else { console.error(`unknown argument: ${process.argv[i]}`); process.exit(2); }
}
const dir = path.dirname(file);
const severities = ['error', 'warning', 'info', 'hint'];
validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
  uri: path.basename(file),
  maxIssues: 0,  // all of them
  externalResourceFunction: (uri) => new Promise((resolve, reject) => {
    try { resolve(new Uint8Array(fs.readFileSync(path.join(dir, decodeURIComponent(uri))))); } catch (e) { reject(e.toString()); }
  })
}).then((report) => {
  const i = report.issues;
  console.log(`errors ${i.numErrors} warnings ${i.numWarnings} infos ${i.numInfos} hints ${i.numHints}`);
  let unexpected = 0;
  const seen = new Set();
  for (const m of i.messages) {
    const key = `${m.code}@${m.pointer || ''}`;
    const expected = m.severity === 1 && allowed.has(key);
    if (expected) seen.add(key);
    else if (m.severity === 1) ++unexpected;
    console.log(`${severities[m.severity]} ${m.code} ${m.pointer || ''}: ${m.message}${expected ? ' (expected: --allow)' : ''}`);
  }
  const missing = [...allowed].filter((key) => !seen.has(key));
  for (const key of missing) console.log(`missing: the allowed warning ${key} did not occur`);
  if (strict) console.log(`unexpected warnings ${unexpected}`);
  process.exit(i.numErrors === 0 && (!strict || unexpected === 0) && missing.length === 0 ? 0 : 1);
}, (error) => { console.error(error); process.exit(2); });
