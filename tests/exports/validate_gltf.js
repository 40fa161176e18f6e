// Validate a .gltf or .glb with the Khronos glTF validator (npm package gltf-validator) and print
// its report as JSON. Usage: node validate_gltf.js VALIDATOR_DIR FILE
const path = require("path");
const fs = require("fs");
const validator = require(path.resolve(process.argv[2]));
const file = process.argv[3];
validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
  uri: file,
  externalResourceFunction: (uri) => new Promise((resolve, reject) => {
    fs.readFile(path.resolve(path.dirname(file), decodeURIComponent(uri)), (err, data) => err ? reject(err) : resolve(new Uint8Array(data)));
  }),
}).then((report) => {
  console.log(JSON.stringify(report));
}).catch((error) => { console.error(String(error)); process.exit(1); });
