// Runs the Khronos glTF validator (npm gltf-validator) over the given .gltf/.glb files.
// Prints one line per file with its error/warning counts and every error; exits 1 if any file has
// an error. Used by scripts/test (through ctest) for every scene in content/scenes.
import { readFile } from 'node:fs/promises';
import path from 'node:path';
import validator from 'gltf-validator';

let failed = false;
for (const file of process.argv.slice(2)) {
  const data = new Uint8Array(await readFile(file));
  const report = await validator.validateBytes(data, {
    uri: path.basename(file),
    maxIssues: 100,
    externalResourceFunction: (uri) =>
      readFile(path.join(path.dirname(file), decodeURIComponent(uri))).then((b) => new Uint8Array(b)),
  });
  const { numErrors, numWarnings } = report.issues;
  console.log(`${file}: ${numErrors} errors, ${numWarnings} warnings`);
  for (const m of report.issues.messages) {
    if (m.severity === 0) console.log(`  error ${m.code} at ${m.pointer ?? ''}: ${m.message}`);
    else if (m.severity === 1) console.log(`  warning ${m.code} at ${m.pointer ?? ''}: ${m.message}`);
  }
  if (numErrors > 0) failed = true;
}
process.exit(failed ? 1 : 0);
