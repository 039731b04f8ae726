// Runs the Khronos glTF-Validator (npm gltf-validator) on each file given and
// prints one line per file: its error, warning, info and hint counts, then each
// error, warning and unused object. Exits 1 when any file has an error, a
// warning or an unused object (texture coordinates, tangents, textures), except
// the height textures boxlod's materials name in extras.boxlod.height_texture
// (glTF has no slot for them: docs/design.md, Files) and the levels MSFT_lod names;
// in an MSFT_lod chain, the level buffers' data URIs are warned of and allowed
// (Babylon.js loads the levels in order only through them: docs/cost.md).
// --allow CODE also allows that warning (a source's own, kept as it was).
//   node gltf_validator.mjs VALIDATOR_DIR [--allow CODE] FILE...
import { readFile } from "node:fs/promises";
import { createRequire } from "node:module";
import path from "node:path";

const [validatorDir, ...rest] = process.argv.slice(2);
const allowed = rest[0] === "--allow" ? rest[1] : undefined;
const files = allowed ? rest.slice(2) : rest;
const validator = createRequire(path.join(validatorDir, "index.js"))(validatorDir);
// The JSON of a .gltf, or of a .glb's first chunk (glTF 2.0, GLB File Format Specification).
function gltfJson(bytes) {
    const glb = bytes.length >= 20 && new TextDecoder().decode(bytes.subarray(0, 4)) === "glTF";
    const text = glb ? bytes.subarray(20, 20 + new DataView(bytes.buffer, bytes.byteOffset).getUint32(12, true)) : bytes;
    return JSON.parse(new TextDecoder().decode(text));
}

// The pointers of what only an extension the validator does not follow names:
// the textures (and their images) of boxlod's extras, and the roots of an
// MSFT_lod chain's coarser levels.
function namedElsewhere(gltf) {
    const pointers = new Set();
    for (const node of gltf.nodes ?? [])
        for (const id of node?.extensions?.MSFT_lod?.ids ?? []) pointers.add(`/nodes/${id}`);
    for (const material of gltf.materials ?? []) {
        const texture = material.extras?.boxlod?.height_texture;
        if (texture === undefined) continue;
        pointers.add(`/textures/${texture}`);
        pointers.add(`/images/${gltf.textures[texture].source}`);
    }
    return pointers;
}

let failed = false;
for (const file of files) {
    const bytes = new Uint8Array(await readFile(file));
    const report = await validator.validateBytes(bytes, {
        uri: file,
        maxIssues: 0,
        externalResourceFunction: (uri) => readFile(path.resolve(path.dirname(file), decodeURIComponent(uri))).then((b) => new Uint8Array(b)),
    });
    const i = report.issues;
    const gltf = gltfJson(bytes), elsewhere = namedElsewhere(gltf);
    // A chain's level buffers are data URIs by design, also in a GLB (toolkit/formats/gltf_document.cpp: sequence_levels).
    const chain = (gltf.extensionsUsed ?? []).includes("MSFT_lod");
    const unused = i.messages.filter((m) => (m.code === "UNUSED_OBJECT" || m.code === "UNUSED_MESH_TANGENT") && !elsewhere.has(m.pointer));
    console.log(`${file}: ${i.numErrors} errors, ${i.numWarnings} warnings, ${i.numInfos} infos (${unused.length} unused), ${i.numHints} hints`);
    for (const m of i.messages) {
        if (m.severity <= 1 || unused.includes(m))
            console.log(`  ${["error", "warning", "info"][m.severity]} ${m.code} ${m.pointer ?? ""}: ${m.message}`);
    }
    const warnings = i.messages.filter((m) => m.severity === 1 && m.code !== allowed &&
        !(chain && m.code === "DATA_URI_GLB" && m.pointer.startsWith("/buffers/")));
    failed ||= i.numErrors + warnings.length + unused.length > 0;
}
process.exit(failed ? 1 : 0);
