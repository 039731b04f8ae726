// Runs the Khronos glTF-Validator (npm gltf-validator) on each file given and
// prints one line per file: its error, warning, info and hint counts, then each
// error and warning. Exits 1 when any file has an error or a warning.
//   node gltf_validator.mjs VALIDATOR_DIR FILE...
import { readFile } from "node:fs/promises";
import { createRequire } from "node:module";
import path from "node:path";

const [validatorDir, ...files] = process.argv.slice(2);
const validator = createRequire(path.join(validatorDir, "index.js"))(validatorDir);
let failed = false;
for (const file of files) {
    const bytes = new Uint8Array(await readFile(file));
    const report = await validator.validateBytes(bytes, {
        uri: file,
        maxIssues: 0,
        externalResourceFunction: (uri) => readFile(path.resolve(path.dirname(file), decodeURIComponent(uri))).then((b) => new Uint8Array(b)),
    });
    const i = report.issues;
    console.log(`${file}: ${i.numErrors} errors, ${i.numWarnings} warnings, ${i.numInfos} infos, ${i.numHints} hints`);
    for (const m of i.messages) {
        if (m.severity <= 1) console.log(`  ${m.severity === 0 ? "error" : "warning"} ${m.code} ${m.pointer ?? ""}: ${m.message}`);
    }
    failed ||= i.numErrors + i.numWarnings > 0;
}
process.exit(failed ? 1 : 0);
