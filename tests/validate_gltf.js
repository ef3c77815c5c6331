// Prints the Khronos glTF validator's report of one .glb/.gltf file as JSON.
// Usage: NODE_PATH=<folder holding gltf-validator> node validate_gltf.js FILE
const fs = require("fs");
const validator = require("gltf-validator");

const path = process.argv[2];
validator.validateBytes(new Uint8Array(fs.readFileSync(path)), { maxIssues: 100 })
  .then((report) => process.stdout.write(JSON.stringify(report)))
  .catch((error) => { process.stderr.write(String(error) + "\n"); process.exit(1); });
