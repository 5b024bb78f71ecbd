// The TextMate grammar, tokenised the way VS Code does it (vscode-textmate + vscode-oniguruma):
// run with `npm test` after `npm ci` in editors/vscode.
"use strict";

const test = require("node:test");
const assert = require("node:assert");
const fs = require("node:fs");
const path = require("node:path");
const oniguruma = require("vscode-oniguruma");
const textmate = require("vscode-textmate");

const GRAMMAR = path.join(__dirname, "..", "syntaxes", "eds.tmLanguage.json");

async function loadGrammar() {
  const wasm = fs.readFileSync(require.resolve("vscode-oniguruma/release/onig.wasm"));
  await oniguruma.loadWASM(wasm.buffer.slice(wasm.byteOffset, wasm.byteOffset + wasm.byteLength));
  const registry = new textmate.Registry({
    onigLib: Promise.resolve({
      createOnigScanner: (patterns) => new oniguruma.OnigScanner(patterns),
      createOnigString: (text) => new oniguruma.OnigString(text),
    }),
    loadGrammar: async () => textmate.parseRawGrammar(fs.readFileSync(GRAMMAR, "utf8"), GRAMMAR),
  });
  return registry.loadGrammar("source.eds");
}

/** Each token of `text` as [its text, its innermost scope]. */
function tokens(grammar, text) {
  let state = textmate.INITIAL;
  const found = [];
  for (const line of text.split("\n")) {
    const result = grammar.tokenizeLine(line, state);
    for (const token of result.tokens) {
      const piece = line.slice(token.startIndex, token.endIndex);
      if (piece.trim()) found.push([piece.trim(), token.scopes[token.scopes.length - 1]]);
    }
    state = result.ruleStack;
  }
  return found;
}

function scopeOf(found, piece) {
  const match = found.find(([text]) => text === piece);
  assert.ok(match, `no token ${piece} in ${JSON.stringify(found)}`);
  return match[1];
}

const SAMPLE = [
  "$ a comment with \"quotes\"",
  "[Connection Manager]",
  "    Connection1 =",
  "        0x04010002,             $ trigger & transport",
  "        Param1,2,Assem150,",
  "        \"say \\\"$ not a comment\\\"\",",
  "        \"20 04 24 01 2C [Param2]\";",
  "[File]",
  "    CreateDate = 11-22-2026; CreateTime = 09:30:00;",
  "    Revision = 1.1;",
  "    ProxyAssem1 = Module, -40, 0b0101;",
].join("\n");

test("sections, entries, values, references and comments get their scopes", async () => {
  const found = tokens(await loadGrammar(), SAMPLE);
  assert.strictEqual(scopeOf(found, "$"), "punctuation.definition.comment.eds");
  assert.strictEqual(scopeOf(found, "Connection Manager"), "entity.name.section.eds");
  assert.strictEqual(scopeOf(found, "Connection1"), "keyword.other.entry.eds");
  assert.strictEqual(scopeOf(found, "="), "keyword.operator.assignment.eds");
  assert.strictEqual(scopeOf(found, "0x04010002"), "constant.numeric.hex.eds");
  assert.strictEqual(scopeOf(found, "trigger & transport"), "comment.line.dollar.eds");
  assert.strictEqual(scopeOf(found, "Param1"), "variable.other.reference.eds");
  assert.strictEqual(scopeOf(found, "Assem150"), "variable.other.reference.eds");
  assert.strictEqual(scopeOf(found, "[Param2]"), "variable.other.reference.eds");
  assert.strictEqual(scopeOf(found, "11-22-2026"), "constant.numeric.date.eds");
  assert.strictEqual(scopeOf(found, "09:30:00"), "constant.numeric.time.eds");
  assert.strictEqual(scopeOf(found, "1.1"), "constant.numeric.decimal.eds");
  assert.strictEqual(scopeOf(found, "Module"), "constant.language.eds");
  assert.strictEqual(scopeOf(found, "-40"), "constant.numeric.decimal.eds");
  assert.strictEqual(scopeOf(found, "0b0101"), "constant.numeric.binary.eds");
  assert.strictEqual(scopeOf(found, ";"), "punctuation.terminator.entry.eds");
});

test("a $ inside a string is not a comment, and escapes are marked", async () => {
  const found = tokens(await loadGrammar(), SAMPLE);
  assert.strictEqual(scopeOf(found, "$ not a comment"), "string.quoted.double.eds");
  assert.strictEqual(scopeOf(found, "\\\""), "constant.character.escape.eds");
  assert.ok(!found.some(([text, scope]) => text.includes("not a comment") && scope.startsWith("comment")));
});
