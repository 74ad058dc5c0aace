// Runs Khronos' glTF validator (npm package gltf-validator) on one file:
//   node validate_gltf.js <path to the gltf-validator module> <file.gltf|.glb>
// prints the counts and every error and warning; exits 0 when there are no errors.
const fs = require('fs'), path = require('path');
const validator = require(process.argv[2]);
const file = process.argv[3];
const dir = path.dirname(file);
validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
  uri: path.basename(file),
  externalResourceFunction: (uri) => new Promise((resolve, reject) => {
    try { resolve(new Uint8Array(fs.readFileSync(path.join(dir, decodeURIComponent(uri))))); } catch (e) { reject(e.toString()); }
  })
}).then((report) => {
  const i = report.issues;
  console.log(`errors ${i.numErrors} warnings ${i.numWarnings} infos ${i.numInfos} hints ${i.numHints}`);
  for (const m of i.messages) if (m.severity <= 1) console.log(`${m.severity === 0 ? 'error' : 'warning'} ${m.code} ${m.pointer || ''}: ${m.message}`);
  process.exit(i.numErrors === 0 ? 0 : 1);
}, (error) => { console.error(error); process.exit(2); });
